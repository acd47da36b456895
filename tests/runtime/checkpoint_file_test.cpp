// Single-file and in-memory checkpoints: round trips, every truncation and bit flip of a file
// refused with the state untouched, and file safety (mode 0600, no symlink followed, exclusive
// temp files, the previous checkpoint intact after a failed write).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "file_io.hpp"
#include "file_test_schemas.hpp"
#include "file_test_util.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/symcr.hpp"

namespace file_tests {
namespace {

using symcr::Error;

class CheckpointFile : public ::testing::Test {
 protected:
  TempDir dir;
  std::string path = dir.file("copter.ckpt");
};

TEST_F(CheckpointFile, RoundTrip) {
  fill_a(5);
  const symcr::Status saved = symcr::checkpoint(schema_a, path.c_str());
  ASSERT_TRUE(saved.ok()) << saved.message();
  scramble_a();
  const symcr::Report report = symcr::restore(schema_a, path.c_str());
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 0u);
  expect_a(5);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"copter.ckpt"});  // no temp file left
}

TEST_F(CheckpointFile, RoundTripWithFdatasync) {
  fill_a(6);
  symcr::CheckpointOptions options;
  options.durability = symcr::Durability::Fdatasync;
  ASSERT_TRUE(symcr::checkpoint(schema_a, path.c_str(), options).ok());
  scramble_a();
  ASSERT_TRUE(symcr::restore(schema_a, path.c_str()).ok());
  expect_a(6);
}

TEST_F(CheckpointFile, OverwritesThePreviousCheckpoint) {
  fill_a(1);
  ASSERT_TRUE(symcr::checkpoint(schema_a, path.c_str()).ok());
  fill_a(2);
  ASSERT_TRUE(symcr::checkpoint(schema_a, path.c_str()).ok());
  scramble_a();
  ASSERT_TRUE(symcr::restore(schema_a, path.c_str()).ok());
  expect_a(2);
}

TEST_F(CheckpointFile, BufferRoundTripAndSameBytesAsTheFile) {
  fill_a(7);
  std::vector<std::uint8_t> buffer;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(schema_a, buffer, 99).ok());
  ASSERT_TRUE(symcr::checkpoint(schema_a, path.c_str()).ok());
  scramble_a();
  const symcr::Report report = symcr::restore_from_buffer(schema_a, buffer.data(), buffer.size());
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 99u);
  expect_a(7);

  // The file is the same record: identical but for sequence, timestamp and checksum.
  std::vector<std::uint8_t> file = read_file(path);
  ASSERT_EQ(file.size(), buffer.size());
  for (std::vector<std::uint8_t>* record : {&file, &buffer}) {
    std::memset(record->data() + 16, 0, 16);  // sequence, timestamp_ns
    std::memset(record->data() + 48, 0, 4);   // checksum
  }
  EXPECT_EQ(file, buffer);
}

TEST_F(CheckpointFile, BufferKeepsItsCapacity) {
  fill_a(1);
  std::vector<std::uint8_t> buffer;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(schema_a, buffer).ok());
  const std::uint8_t* storage = buffer.data();
  const std::size_t size = buffer.size();
  fill_a(2);
  ASSERT_TRUE(symcr::checkpoint_to_buffer(schema_a, buffer).ok());
  EXPECT_EQ(buffer.data(), storage);
  EXPECT_EQ(buffer.size(), size);
}

// A buffer reused for checkpoints is written over in place (large values copied over the
// previous record with their checksum): whatever it held before, longer or shorter, it then
// holds exactly the new record, the one a fresh buffer gets.
TEST_F(CheckpointFile, AReusedBufferHoldsExactlyTheNewRecord) {
  constexpr std::size_t kCount = (std::size_t{3} << 20) / sizeof(std::uint64_t);  // 3 MiB
  static std::vector<std::uint64_t> samples(kCount);
  static const symcr::TypeInfo types[] = {
      schema_tables::scalar("uint64", symcr::Kind::UInt, 8),
      schema_tables::array("uint64[393216]", 0, kCount,
                           static_cast<std::uint32_t>(kCount * sizeof(std::uint64_t)), 8),
  };
  static const symcr::RootInfo roots[] = {{"samples", 1, samples.data(), 0, nullptr}};
  static const symcr::Schema big{types, 2, roots, 1, nullptr};
  auto fill = [](std::uint64_t seed) {
    for (std::size_t i = 0; i < kCount; ++i) samples[i] = seed * 1000003u + i;
  };
  auto expect_restores = [&](const std::vector<std::uint8_t>& record, std::uint64_t seed) {
    std::fill(samples.begin(), samples.end(), 0);
    const symcr::Report report = symcr::restore_from_buffer(big, record.data(), record.size());
    ASSERT_TRUE(report.ok()) << report.status().message();
    for (std::size_t i = 0; i < kCount; i += 4099) ASSERT_EQ(samples[i], seed * 1000003u + i);
    ASSERT_EQ(samples[kCount - 1], seed * 1000003u + kCount - 1);
  };
  auto without_time = [](std::vector<std::uint8_t> record) {
    if (record.size() < 56) return record;  // no header: compared as it is
    std::memset(record.data() + 24, 0, 8);  // timestamp_ns
    std::memset(record.data() + 48, 0, 4);  // checksum (covers the timestamp)
    return record;
  };

  fill(1);
  std::vector<std::uint8_t> reused;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(big, reused).ok());
  expect_restores(reused, 1);
  const std::size_t size = reused.size();
  for (const std::size_t before : {size, size + 5000, size / 2, std::size_t{10}}) {
    reused.assign(before, 0xEE);  // a longer, shorter or foreign earlier content
    fill(before);
    ASSERT_TRUE(symcr::checkpoint_to_buffer(big, reused).ok());
    std::vector<std::uint8_t> fresh;
    ASSERT_TRUE(symcr::checkpoint_to_buffer(big, fresh).ok());
    ASSERT_EQ(reused.size(), size) << before;
    EXPECT_TRUE(without_time(reused) == without_time(fresh)) << before;
    expect_restores(reused, before);
  }
  // The steady state: the same size every time, overwritten in place.
  fill(2);
  ASSERT_TRUE(symcr::checkpoint_to_buffer(big, reused).ok());
  fill(3);
  ASSERT_TRUE(symcr::checkpoint_to_buffer(big, reused).ok());
  EXPECT_EQ(reused.size(), size);
  expect_restores(reused, 3);
}

TEST_F(CheckpointFile, ANewBuildRestoresByNamesFromTheInlineSchema) {
  fill_a(8);
  ASSERT_TRUE(symcr::checkpoint(schema_a, path.c_str()).ok());
  copter_b = CopterB{};
  telemetry_b = Telemetry{};
  const symcr::Report report = symcr::restore(schema_b, path.c_str());
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(copter_b.ticks, 1008);
  EXPECT_EQ(copter_b.mode, FlightMode::Land);
  EXPECT_EQ(copter_b.mission.items[3].lat, 42.0 + 8 + 3 * 0.25);
  EXPECT_EQ(copter_b.battery, 15.5f - 8 * 0.125f);
  EXPECT_EQ(copter_b.geofence, 77);
  EXPECT_EQ(telemetry_b.frames, 56u);
  EXPECT_EQ(report.count(symcr::Decision::Dropped), 1u);  // armed_ms
  // Strict mode refuses the dropped field and writes nothing.
  copter_b.ticks = 0;
  symcr::RestoreOptions strict;
  strict.strict = true;
  EXPECT_EQ(symcr::restore(schema_b, path.c_str(), strict).status().error(), Error::Strict);
  EXPECT_EQ(copter_b.ticks, 0);
}

TEST_F(CheckpointFile, EveryTruncationIsRefusedAndChangesNothing) {
  fill_a(4);
  ASSERT_TRUE(symcr::checkpoint(schema_a, path.c_str()).ok());
  const std::vector<std::uint8_t> full = read_file(path);
  scramble_a();
  const std::vector<std::uint8_t> before = state_a();
  const std::string cut = dir.file("cut.ckpt");
  for (std::size_t length = 0; length < full.size(); ++length) {
    write_file(cut, std::vector<std::uint8_t>(full.begin(), full.begin() + length));
    const symcr::Report report = symcr::restore(schema_a, cut.c_str());
    ASSERT_FALSE(report.ok()) << "restored a file cut at " << length;
    ASSERT_EQ(report.status().error(), Error::Truncated) << length << ": "
                                                         << report.status().message();
    ASSERT_EQ(state_a(), before) << "state changed by a file cut at " << length;
  }
}

TEST_F(CheckpointFile, EveryBitFlipIsRefusedAndChangesNothing) {
  fill_a(4);
  ASSERT_TRUE(symcr::checkpoint(schema_a, path.c_str()).ok());
  const std::vector<std::uint8_t> clean = read_file(path);
  scramble_a();
  const std::vector<std::uint8_t> before = state_a();
  const std::set<Error> clean_errors = {Error::NotACheckpoint, Error::FutureVersion,
                                        Error::Truncated, Error::Checksum, Error::Corrupt};
  const std::string flipped_path = dir.file("flipped.ckpt");
  std::vector<std::uint8_t> flipped = clean;
  for (std::size_t bit = 0; bit < clean.size() * 8; ++bit) {
    flipped[bit / 8] ^= static_cast<std::uint8_t>(1u << (bit % 8));
    write_file(flipped_path, flipped);
    flipped[bit / 8] = clean[bit / 8];
    const symcr::Report report = symcr::restore(schema_a, flipped_path.c_str());
    ASSERT_FALSE(report.ok()) << "restored a file with bit " << bit << " flipped";
    ASSERT_EQ(clean_errors.count(report.status().error()), 1u)
        << bit << ": " << report.status().message();
    ASSERT_EQ(state_a(), before) << "state changed by bit flip " << bit;
  }
}

TEST_F(CheckpointFile, FutureFormatVersionIsRefusedCleanly) {
  fill_a(1);
  ASSERT_TRUE(symcr::checkpoint(schema_a, path.c_str()).ok());
  std::vector<std::uint8_t> bytes = read_file(path);
  symcr::format::store16(bytes.data() + 8, 2);
  write_file(path, bytes);
  scramble_a();
  const auto before = state_a();
  const symcr::Report report = symcr::restore(schema_a, path.c_str());
  EXPECT_EQ(report.status().error(), Error::FutureVersion);
  const std::string message = report.status().message();
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find("version 2"), std::string::npos) << message;
  EXPECT_NE(message.find("version 1"), std::string::npos) << message;
  EXPECT_EQ(state_a(), before);
}

TEST_F(CheckpointFile, NotACheckpoint) {
  write_text(path, "this is a text file, not a checkpoint; it is long enough for a header\n");
  const symcr::Report report = symcr::restore(schema_a, path.c_str());
  EXPECT_EQ(report.status().error(), Error::NotACheckpoint);
}

TEST_F(CheckpointFile, MissingFileIsAnIoErrorNamingThePath) {
  const symcr::Report report = symcr::restore(schema_a, path.c_str());
  EXPECT_EQ(report.status().error(), Error::Io);
  EXPECT_NE(std::string(report.status().message()).find(path), std::string::npos);
}

TEST_F(CheckpointFile, DirectoriesAndFifosAreRefusedWithoutBlocking) {
  EXPECT_EQ(symcr::restore(schema_a, dir.path().c_str()).status().error(), Error::Io);
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  EXPECT_EQ(symcr::restore(schema_a, path.c_str()).status().error(), Error::Io);
}

TEST_F(CheckpointFile, ProgramSchemaFormsNeedGeneratedCode) {
  // This test binary links no generated code, so symcr_program_schema is null.
  const auto generated = &symcr_program_schema;
  ASSERT_TRUE(generated == nullptr);
  EXPECT_EQ(symcr::checkpoint(path.c_str()).error(), Error::NoSchema);
  EXPECT_EQ(symcr::restore(path.c_str()).status().error(), Error::NoSchema);
  symcr::Store store;
  EXPECT_EQ(symcr::Store::open(dir.file("s.store").c_str(), {}, store).error(), Error::NoSchema);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{});
}

TEST_F(CheckpointFile, CreatedWithMode0600) {
  ScopedUmask no_mask(0);
  fill_a(1);
  ASSERT_TRUE(symcr::checkpoint(schema_a, path.c_str()).ok());
  EXPECT_EQ(permission_bits(path), 0600u);
  // Replacing a file that had wider permissions does not inherit them.
  ASSERT_EQ(::chmod(path.c_str(), 0666), 0);
  ASSERT_TRUE(symcr::checkpoint(schema_a, path.c_str()).ok());
  EXPECT_EQ(permission_bits(path), 0600u);
}

TEST_F(CheckpointFile, SymlinkAtThePathIsNeitherFollowedNorReplaced) {
  const std::string victim = dir.file("victim");
  write_text(victim, "precious");
  ASSERT_EQ(::symlink(victim.c_str(), path.c_str()), 0);
  fill_a(1);
  const symcr::Status saved = symcr::checkpoint(schema_a, path.c_str());
  EXPECT_EQ(saved.error(), Error::Io);
  EXPECT_NE(std::string(saved.message()).find("symbolic link"), std::string::npos);
  EXPECT_TRUE(is_symlink(path));
  EXPECT_EQ(read_file(victim), std::vector<std::uint8_t>({'p', 'r', 'e', 'c', 'i', 'o', 'u', 's'}));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"copter.ckpt", "victim"}));

  // Nor is one followed on restore, even to a valid checkpoint.
  const std::string real = dir.file("real.ckpt");
  ASSERT_TRUE(symcr::checkpoint(schema_a, real.c_str()).ok());
  const std::string link = dir.file("link.ckpt");
  ASSERT_EQ(::symlink(real.c_str(), link.c_str()), 0);
  const symcr::Report report = symcr::restore(schema_a, link.c_str());
  EXPECT_EQ(report.status().error(), Error::Io);
  EXPECT_NE(std::string(report.status().message()).find("symbolic link"), std::string::npos);
}

TEST_F(CheckpointFile, ExistingTempNamesAreNeverReusedOrFollowed) {
  char taken[4096];
  ASSERT_TRUE(symcr::detail::temp_path_for(path.c_str(), 0, taken, sizeof taken));
  write_text(taken, "someone else's file");
  const std::string victim = dir.file("victim");
  write_text(victim, "precious");
  char trap[4096];
  ASSERT_TRUE(symcr::detail::temp_path_for(path.c_str(), 1, trap, sizeof trap));
  ASSERT_EQ(::symlink(victim.c_str(), trap), 0);

  fill_a(3);
  const symcr::Status saved = symcr::checkpoint(schema_a, path.c_str());
  ASSERT_TRUE(saved.ok()) << saved.message();
  const std::vector<std::uint8_t> someone = read_file(taken);
  EXPECT_EQ(std::string(someone.begin(), someone.end()), "someone else's file");
  EXPECT_TRUE(is_symlink(trap));
  const std::vector<std::uint8_t> precious = read_file(victim);
  EXPECT_EQ(std::string(precious.begin(), precious.end()), "precious");
  scramble_a();
  ASSERT_TRUE(symcr::restore(schema_a, path.c_str()).ok());
  expect_a(3);
  EXPECT_EQ(dir.entries().size(), 4u);  // checkpoint, the two squatters, the victim
}

TEST_F(CheckpointFile, FailedWriteKeepsThePreviousCheckpointAndRemovesTheTempFile) {
  fill_a(1);
  ASSERT_TRUE(symcr::checkpoint(schema_a, path.c_str()).ok());
  const std::vector<std::uint8_t> previous = read_file(path);

  // A file-size limit below the record makes the temp file's write fail (EFBIG).
  struct sigaction ignore {}, old_action {};
  ignore.sa_handler = SIG_IGN;
  ASSERT_EQ(::sigaction(SIGXFSZ, &ignore, &old_action), 0);
  rlimit old_limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  rlimit small = old_limit;
  small.rlim_cur = 16;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  fill_a(2);
  const symcr::Status saved = symcr::checkpoint(schema_a, path.c_str());
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  ::sigaction(SIGXFSZ, &old_action, nullptr);

  EXPECT_EQ(saved.error(), Error::Io);
  EXPECT_EQ(read_file(path), previous);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"copter.ckpt"});
  scramble_a();
  ASSERT_TRUE(symcr::restore(schema_a, path.c_str()).ok());
  expect_a(1);
}

TEST_F(CheckpointFile, ADirectoryAtThePathIsLeftAlone) {
  ASSERT_EQ(::mkdir(path.c_str(), 0700), 0);
  write_text(path + "/inside", "x");
  fill_a(1);
  EXPECT_EQ(symcr::checkpoint(schema_a, path.c_str()).error(), Error::Io);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"copter.ckpt"});  // temp file removed
  EXPECT_EQ(read_file(path + "/inside"), std::vector<std::uint8_t>{'x'});
}

}  // namespace
}  // namespace file_tests
