// The checkpoint store (docs/format.md §4): the ring, fallback past torn and corrupt slots,
// a new build reading the previous build's checkpoints, geometry, durability and file safety.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <new>
#include <string>
#include <vector>

#include "crc32c.hpp"
#include "file_test_schemas.hpp"
#include "file_test_util.hpp"
#include "plan.hpp"
#include "schema_blob.hpp"
#include "store_fixture.hpp"
#include "symcr/device.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/symcr.hpp"

// Counts every allocation through operator new in this test binary: the store's save() must
// not allocate once warmed up.
// GCC cannot see that the replaced new and delete below are a matching pair.
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
static std::atomic<std::uint64_t> g_allocations{0};
void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace file_tests {
namespace {

using symcr::Error;

// Raw access to a store file, read through its header, to corrupt what a crash could.
struct StoreFile {
  std::string path;
  std::vector<std::uint8_t> bytes;
  explicit StoreFile(std::string p) : path(std::move(p)), bytes(read_file(path)) {}
  std::uint32_t slot_count() const { return symcr::format::load32(bytes.data() + 12); }
  std::uint32_t slot_size() const { return symcr::format::load32(bytes.data() + 16); }
  std::uint32_t schema_area_size() const { return symcr::format::load32(bytes.data() + 20); }
  std::uint64_t slots_offset() const { return symcr::format::load64(bytes.data() + 24); }
  std::uint8_t* slot(std::uint32_t i) { return bytes.data() + slots_offset() + i * slot_size(); }
  std::uint64_t sequence(std::uint32_t i) { return symcr::format::load64(slot(i) + 16); }
  std::size_t record_size(std::uint32_t i) {
    return 56 + symcr::format::load32(slot(i) + 40) + symcr::format::load32(slot(i) + 44);
  }
  std::uint32_t slot_with_sequence(std::uint64_t sequence) {
    for (std::uint32_t i = 0; i < slot_count(); ++i) {
      if (std::memcmp(slot(i), "SYMCRCKP", 8) == 0 && this->sequence(i) == sequence) return i;
    }
    ADD_FAILURE() << "no slot holds sequence " << sequence;
    return 0;
  }
  void reseal(std::uint32_t i) {
    symcr::format::store32(slot(i) + 48, 0);
    symcr::format::store32(slot(i) + 48, symcr::detail::crc32c(slot(i), record_size(i)));
  }
  void write() const { write_file(path, bytes); }
};

class StoreTest : public StoreFixture {
 protected:
  symcr::Report restore_latest(const symcr::Schema& schema = schema_a) {
    symcr::Store store;
    open(store, schema);
    return store.restore_latest();
  }
  // Scrambles the live state, reopens the store and restores: the checkpoint of `sequence`,
  // which saved seed `sequence`, must come back.
  void expect_restores_sequence(int sequence);
  // Scrambles the live state and restores the newest slot of the open `store`, which must
  // hold seed `seed`.
  void expect_store_restores(symcr::Store& store, int seed);
};

void StoreTest::expect_store_restores(symcr::Store& store, int seed) {
  scramble_a();
  const symcr::Report report = store.restore_latest();
  ASSERT_TRUE(report.ok()) << report.status().message();
  expect_a(seed);
}

void StoreTest::expect_restores_sequence(int sequence) {
  scramble_a();
  const symcr::Report report = restore_latest();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), static_cast<std::uint64_t>(sequence));
  expect_a(sequence);
}

TEST_F(StoreTest, CreatesAPreallocatedFileWithMode0600) {
  ScopedUmask no_mask(0);
  symcr::Store store;
  open(store);
  EXPECT_TRUE(store.is_open());
  EXPECT_EQ(store.last_sequence(), 0u);
  EXPECT_EQ(permission_bits(path), 0600u);
  const StoreFile file(path);
  EXPECT_EQ(std::memcmp(file.bytes.data(), "SYMCRSTO", 8), 0);
  EXPECT_EQ(symcr::format::load16(file.bytes.data() + 8), 1u);
  EXPECT_EQ(file.slot_count(), 4u);
  EXPECT_EQ(file.slot_size(), 65536u);
  EXPECT_EQ(file.slots_offset() % 4096, 0u);
  EXPECT_EQ(file.slots_offset(), 4096u + 2u * file.schema_area_size());
  EXPECT_EQ(symcr::format::load32(file.bytes.data() + 32),
            symcr::detail::crc32c(file.bytes.data(), 32));
  EXPECT_EQ(file.bytes.size(), file.slots_offset() + 4u * 65536u);
  struct stat info {};
  ASSERT_EQ(::stat(path.c_str(), &info), 0);
  EXPECT_GE(static_cast<std::uint64_t>(info.st_blocks) * 512, file.bytes.size());  // allocated
}

// Only the store file (and its counter) is never followed as a symlink: a folder on its path
// may be one.
TEST_F(StoreTest, AStoreInAFolderReachedThroughASymlinkSavesAndRestores) {
  const std::string real = dir.file("real");
  const std::string linked = dir.file("linked");
  ASSERT_EQ(::mkdir(real.c_str(), 0700), 0);
  ASSERT_EQ(::symlink(real.c_str(), linked.c_str()), 0);
  path = linked + "/copter.store";
  save_seeds(1, 3);
  expect_restores_sequence(3);
  symcr::Store store;
  ASSERT_TRUE(symcr::Store::open_readonly(path.c_str(), schema_a, store).ok());
  EXPECT_TRUE(store.restore_latest().ok());
  ::unlink((real + "/copter.store").c_str());
  ::unlink(linked.c_str());
  ::rmdir(real.c_str());
}

TEST_F(StoreTest, EmptyStoreHasNoValidSlot) {
  fill_a(1);
  const auto before = state_a();
  const symcr::Report report = restore_latest();
  EXPECT_EQ(report.status().error(), Error::NoValidSlot);
  EXPECT_EQ(state_a(), before);
}

// A restore point tells a first start (nothing saved yet) from a store whose checkpoints are
// all damaged: only the second is a failed restore.
TEST_F(StoreTest, HoldsCheckpointsIsFalseOnlyWhileEverySlotIsEmpty) {
  {
    symcr::Store store;
    open(store);
    EXPECT_FALSE(store.holds_checkpoints());
    fill_a(1);
    ASSERT_TRUE(store.save().ok());
    EXPECT_TRUE(store.holds_checkpoints());
  }
  StoreFile file(path);
  file.slot(file.slot_with_sequence(1))[60] ^= 0x04;  // the only checkpoint, damaged
  file.write();
  symcr::Store reopened;
  open(reopened);
  EXPECT_TRUE(reopened.holds_checkpoints());
  EXPECT_EQ(reopened.restore_latest().status().error(), Error::NoValidSlot);
}

TEST_F(StoreTest, SavesWrapTheRingAndRestoreTheNewest) {
  {
    symcr::Store store;
    open(store);
    for (int seed = 1; seed <= 10; ++seed) {
      fill_a(seed);
      ASSERT_TRUE(store.save().ok());
      EXPECT_EQ(store.last_sequence(), static_cast<std::uint64_t>(seed));
    }
    scramble_a();
    const symcr::Report report = store.restore_latest();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_EQ(report.sequence(), 10u);
    expect_a(10);
  }
  // The ring holds the last four, one per slot.
  StoreFile file(path);
  std::vector<std::uint64_t> sequences;
  for (std::uint32_t i = 0; i < 4; ++i) sequences.push_back(file.sequence(i));
  std::sort(sequences.begin(), sequences.end());
  EXPECT_EQ(sequences, (std::vector<std::uint64_t>{7, 8, 9, 10}));
  // Each slot costs the payload plus the 56-byte header: the schema is shared.
  EXPECT_LT(file.record_size(file.slot_with_sequence(10)), 56u + 200u);

  // A reopened store continues the sequence.
  symcr::Store store;
  open(store);
  EXPECT_EQ(store.last_sequence(), 10u);
  fill_a(11);
  ASSERT_TRUE(store.save().ok());
  EXPECT_EQ(store.last_sequence(), 11u);
  scramble_a();
  const symcr::Report report = store.restore_latest();
  ASSERT_TRUE(report.ok());
  EXPECT_EQ(report.sequence(), 11u);
  expect_a(11);
}

TEST_F(StoreTest, FallsBackPastABitFlipInTheNewestSlot) {
  save_seeds(1, 6);
  StoreFile file(path);
  const std::uint32_t newest = file.slot_with_sequence(6);
  file.slot(newest)[60] ^= 0x04;
  file.write();
  expect_restores_sequence(5);
}

TEST_F(StoreTest, TheReportListsTheSlotsPassedOverAndWhy) {
  save_seeds(1, 4);
  StoreFile file(path);
  const std::uint32_t torn = file.slot_with_sequence(4);
  file.slot(torn)[60] ^= 0x04;
  const std::uint32_t rejected = file.slot_with_sequence(3);
  file.slot(rejected)[56 + kPayloadOffsetOfActiveA] = 7;
  file.reseal(rejected);
  file.write();
  scramble_a();
  const symcr::Report report = restore_latest();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 2u);
  ASSERT_EQ(report.skipped().size(), 2u) << report.to_text();
  EXPECT_EQ(report.skipped()[0].slot, rejected);
  EXPECT_EQ(report.skipped()[0].sequence, 3u);
  EXPECT_NE(report.skipped()[0].reason.find("rejected by the restore"), std::string::npos);
  EXPECT_EQ(report.skipped()[1].slot, torn);
  EXPECT_NE(report.skipped()[1].reason.find("torn or corrupt"), std::string::npos);
  // A restore that passed nothing over lists nothing: the next save (sequence 4, after the
  // rejected 3 that still validates) goes into the torn slot.
  save_seeds(5, 5);
  const symcr::Report clean = restore_latest();
  EXPECT_EQ(clean.sequence(), 4u);
  expect_a(5);
  EXPECT_TRUE(clean.skipped().empty()) << clean.to_text();
}

TEST_F(StoreTest, FallsBackPastATornNewestSlot) {
  save_seeds(1, 6);
  {
    // Torn write: the second half of the record never reached the disk.
    StoreFile file(path);
    const std::uint32_t newest = file.slot_with_sequence(6);
    const std::size_t half = file.record_size(newest) / 2;
    std::memset(file.slot(newest) + half, 0, file.slot_size() - half);
    file.write();
  }
  expect_restores_sequence(5);
  {
    // Torn the other way: the first half of the slot zeroed, header included.
    StoreFile file(path);
    const std::uint32_t slot5 = file.slot_with_sequence(5);
    std::memset(file.slot(slot5), 0, file.slot_size() / 2);
    file.write();
  }
  expect_restores_sequence(4);
}

TEST_F(StoreTest, SaveAfterFallbackContinuesPastTheHighestValidSequence) {
  save_seeds(1, 3);
  StoreFile file(path);
  file.slot(file.slot_with_sequence(3))[70] ^= 1;
  file.write();
  symcr::Store store;
  open(store);
  EXPECT_EQ(store.last_sequence(), 2u);
  fill_a(9);
  ASSERT_TRUE(store.save().ok());
  EXPECT_EQ(store.last_sequence(), 3u);
  // The corrupt slot was reused first: sequences 1, 2, 3 (new) remain.
  StoreFile after(path);
  EXPECT_EQ(after.slot_with_sequence(3), file.slot_with_sequence(3));
  scramble_a();
  const symcr::Report report = store.restore_latest();
  ASSERT_TRUE(report.ok());
  EXPECT_EQ(report.sequence(), 3u);
  expect_a(9);
}

TEST_F(StoreTest, AllSlotsCorruptIsNoValidSlotAndChangesNothing) {
  save_seeds(1, 4);
  StoreFile file(path);
  for (std::uint32_t i = 0; i < 4; ++i) file.slot(i)[56 + i] ^= 0x80;
  file.write();
  scramble_a();
  const auto before = state_a();
  const symcr::Report report = restore_latest();
  EXPECT_EQ(report.status().error(), Error::NoValidSlot);
  EXPECT_NE(std::string(report.status().message()).find("4 corrupt"), std::string::npos)
      << report.status().message();
  EXPECT_EQ(state_a(), before);
}

TEST_F(StoreTest, AValidSlotThatRestoreRejectsFallsBackToTheNextOne) {
  save_seeds(1, 3);
  StoreFile file(path);
  const std::uint32_t newest = file.slot_with_sequence(3);
  // A bool of 7 passes the CRC once resealed, but no writer produces it: the engine's full
  // decode rejects it as corrupt before writing anything.
  file.slot(newest)[56 + kPayloadOffsetOfActiveA] = 7;
  file.reseal(newest);
  file.write();
  expect_restores_sequence(2);
}

TEST_F(StoreTest, AFutureVersionSlotIsSkipped) {
  save_seeds(1, 3);
  StoreFile file(path);
  const std::uint32_t newest = file.slot_with_sequence(3);
  symcr::format::store16(file.slot(newest) + 8, 2);
  file.reseal(newest);
  file.write();
  scramble_a();
  const symcr::Report report = restore_latest();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 2u);
}

TEST_F(StoreTest, SaveTooLargeForASlotWritesNothing) {
  options.slot_size = 1024;
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), blob_schema, options, store).ok());
    const std::vector<std::uint8_t> before = read_file(path);
    const symcr::Status status = store.save();
    EXPECT_EQ(status.error(), Error::TooLarge);
    EXPECT_NE(std::string(status.message()).find("1024"), std::string::npos);
    EXPECT_EQ(read_file(path), before);
    EXPECT_EQ(store.last_sequence(), 0u);
  }
}

TEST_F(StoreTest, NewBuildRestoresThePreviousBuildsCheckpointAndKeepsItUntilItSaves) {
  save_seeds(1, 3);  // build A: sequences 1..3
  {
    // Build B starts: the newest checkpoint is A's, restored by names into B's layout.
    copter_b = CopterB{};
    copter_b.geofence = 77;
    symcr::Store store;
    open(store, schema_b);
    EXPECT_EQ(store.last_sequence(), 3u);
    const symcr::Report report = store.restore_latest();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_EQ(report.sequence(), 3u);
    EXPECT_EQ(copter_b.ticks, 1003);  // int32 -> int64
    EXPECT_EQ(copter_b.mode, FlightMode::Auto);
    EXPECT_EQ(copter_b.mission.items[2].speed, 32);
    EXPECT_EQ(copter_b.battery, 15.5f - 3 * 0.125f);
    EXPECT_EQ(copter_b.geofence, 77);  // added: kept
    EXPECT_EQ(telemetry_b.frames, 21u);

    // B's first save must not destroy A's schema: A's checkpoints stay restorable.
    copter_b.ticks = 5000;
    ASSERT_TRUE(store.save().ok());
    EXPECT_EQ(store.last_sequence(), 4u);
  }
  {
    StoreFile file(path);
    file.slot(file.slot_with_sequence(4))[60] ^= 1;  // B's only checkpoint torn
    file.write();
  }
  copter_b.ticks = 0;
  symcr::Report report = restore_latest(schema_b);
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 3u);  // A's, through A's schema area
  EXPECT_EQ(copter_b.ticks, 1003);

  // B keeps saving; reopened, B's newest is what comes back.
  {
    symcr::Store store;
    open(store, schema_b);
    copter_b.ticks = 6000;
    ASSERT_TRUE(store.save().ok());
    EXPECT_EQ(store.last_sequence(), 4u);
  }
  copter_b.ticks = 0;
  report = restore_latest(schema_b);
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 4u);
  EXPECT_EQ(copter_b.ticks, 6000);
}

// A fresh process restoring its own build's checkpoint parses no schema, copies none and plans
// nothing: the store's area is recognised as this build's by its bytes, and the same build's
// decoder restores it. The report's entries are planned when read, the schema into itself.
TEST_F(StoreTest, TheBuildsOwnCheckpointIsRestoredWithoutParsingOrPlanning) {
  save_seeds(1, 2);
  static const symcr::Schema reader = schema_a;  // its own plans, whatever ran before
  ASSERT_EQ(symcr::device::check_schema(reader), symcr::device::Result::Ok);
  symcr::Store store;
  open(store, reader);
  scramble_a();
  const symcr::Report report = store.restore_latest();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 2u);
  expect_a(2);
  const std::uint64_t hash = symcr::detail::schema_blob(reader).hash;
  EXPECT_FALSE(symcr::detail::cached_plan(hash, reader));
  ASSERT_FALSE(report.entries().empty());
  EXPECT_EQ(report.count(symcr::Decision::Restored), report.entries().size());
  const auto plan = symcr::detail::cached_plan(hash, reader);
  ASSERT_TRUE(plan);
  EXPECT_EQ(plan->writer, &reader);
  EXPECT_FALSE(plan->writer_owner);
}

// Strict mode decides from the plan: the same build's restore is planned then, with the same
// values.
TEST_F(StoreTest, StrictRestoresOfTheSameBuildArePlanned) {
  save_seeds(1, 1);
  static const symcr::Schema reader = schema_a;
  symcr::Store store;
  open(store, reader);
  scramble_a();
  symcr::RestoreOptions strict;
  strict.strict = true;
  const symcr::Report report = store.restore_latest(strict);
  ASSERT_TRUE(report.ok()) << report.status().message();
  expect_a(1);
  EXPECT_TRUE(symcr::detail::cached_plan(symcr::detail::schema_blob(reader).hash, reader));
}

// The plan for an earlier build's area shares the store's parsed schema instead of copying it,
// and must outlive the store: closed and deleted, the cached plan still restores that build's
// checkpoints (the sanitizer build would see any use of the freed area).
TEST_F(StoreTest, APlanOutlivesTheStoreWhoseSchemaAreaItWasBuiltFrom) {
  save_seeds(1, 3);
  static const symcr::Schema reader = schema_b;
  std::uint64_t writer_hash = 0;
  {
    symcr::Store store;
    open(store, reader);
    copter_b = CopterB{};
    const symcr::Report report = store.restore_latest();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_EQ(copter_b.ticks, 1003);
    writer_hash = symcr::detail::schema_blob(schema_a).hash;
    const auto plan = symcr::detail::cached_plan(writer_hash, reader);
    ASSERT_TRUE(plan);
    EXPECT_TRUE(plan->writer_owner);
    EXPECT_EQ(plan->writer, &plan->writer_owner->schema());
  }
  ASSERT_EQ(::unlink(path.c_str()), 0);
  fill_a(8);
  std::vector<std::uint8_t> checkpoint;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(schema_a, checkpoint).ok());
  copter_b = CopterB{};
  const symcr::Report report =
      symcr::restore_from_buffer(reader, checkpoint.data(), checkpoint.size());
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(copter_b.ticks, 1008);
  EXPECT_EQ(copter_b.mission.items[2].speed, 82);
  const auto plan = symcr::detail::cached_plan(writer_hash, reader);
  ASSERT_TRUE(plan);
  EXPECT_STREQ(plan->writer->roots[0].name, schema_a.roots[0].name);
  EXPECT_FALSE(report.entries().empty());
}

// A build opens its store while it initialises and restores where time counts: open() resolves
// the plan of the newest checkpoint's schema, so that restore_latest() only decodes and writes.
// An empty store plans nothing.
TEST_F(StoreTest, OpenResolvesThePlanOfTheNewestCheckpoint) {
  static const symcr::Schema reader = schema_b;  // its own plans, whatever ran before
  const std::uint64_t writer_hash = symcr::detail::schema_blob(schema_a).hash;
  {
    symcr::Store empty;
    open(empty, schema_a);
  }
  {
    symcr::Store store;
    open(store, reader);
    EXPECT_FALSE(symcr::detail::cached_plan(writer_hash, reader));
  }
  save_seeds(1, 2);
  symcr::Store store;
  open(store, reader);
  const auto planned = symcr::detail::cached_plan(writer_hash, reader);
  ASSERT_TRUE(planned);
  copter_b = CopterB{};
  const symcr::Report report = store.restore_latest();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(copter_b.ticks, 1002);
  EXPECT_EQ(symcr::detail::cached_plan(writer_hash, reader), planned);  // the restore's plan
}

TEST_F(StoreTest, AThirdBuildReplacesOnlyTheOlderSchemaArea) {
  // Build C: B's types with only the "copter" root, so its schema (and hash) differ.
  const symcr::Schema schema_c{tables::types_b, tables::kTypeCount, tables::roots_b, 1, nullptr};
  save_seeds(1, 2);  // A: 1, 2
  {
    symcr::Store store;
    open(store, schema_b);
    copter_b.ticks = 3333;
    ASSERT_TRUE(store.save().ok());  // B: 3, its schema beside A's
  }
  {
    symcr::Store store;
    open(store, schema_c);
    copter_b.ticks = 4444;
    ASSERT_TRUE(store.save().ok());  // C: 4, its schema replaces A's, not B's (the newest)
  }
  StoreFile file(path);
  file.slot(file.slot_with_sequence(4))[60] ^= 1;
  file.write();
  copter_b.ticks = 0;
  symcr::Report report = restore_latest(schema_c);
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 3u);  // B's checkpoint survived C's first save
  EXPECT_EQ(copter_b.ticks, 3333);

  // A's checkpoints went with A's schema area: C's save reused the first of them (an invalid
  // slot is the oldest), the other is left with an unknown schema.
  file.slot(file.slot_with_sequence(3))[60] ^= 1;
  file.write();
  report = restore_latest(schema_c);
  EXPECT_EQ(report.status().error(), Error::NoValidSlot);
  EXPECT_NE(std::string(report.status().message())
                .find("1 empty, 2 corrupt or torn, 1 with an unknown schema"),
            std::string::npos)
      << report.status().message();
}

TEST_F(StoreTest, FdatasyncDurability) {
  options.durability = symcr::Durability::Fdatasync;
  save_seeds(1, 3);
  scramble_a();
  const symcr::Report report = restore_latest();
  ASSERT_TRUE(report.ok());
  EXPECT_EQ(report.sequence(), 3u);
  expect_a(3);
}

TEST_F(StoreTest, SaveAllocatesNothingAfterTheFirstCall) {
  symcr::Store store;
  open(store);
  fill_a(1);
  ASSERT_TRUE(store.save().ok());
  ASSERT_TRUE(store.save().ok());
  const std::uint64_t before = g_allocations.load();
  for (int seed = 2; seed < 20; ++seed) {
    fill_a(seed);
    ASSERT_TRUE(store.save().ok());
  }
  EXPECT_EQ(g_allocations.load(), before);
}

TEST_F(StoreTest, DifferentGeometryWithCheckpointsRestoresThemAndRewritesTheStoreAtTheFirstSave) {
  save_seeds(1, 3);
  const std::vector<std::uint8_t> before = read_file(path);
  options.slots = 8;
  options.slot_size = 2 * options.slot_size;  // the patched build's state grew
  {
    symcr::Store store;
    open(store);
    EXPECT_EQ(read_file(path), before) << "opening wrote into the store";
    EXPECT_EQ(store.options().slots, 4u) << "reads with the file's own geometry";
    expect_store_restores(store, 3);
    fill_a(4);
    const symcr::Status saved = store.save();
    ASSERT_TRUE(saved.ok()) << saved.message();
    EXPECT_EQ(store.options().slots, 8u);
  }
  const StoreFile file(path);
  EXPECT_EQ(file.slot_count(), 8u);
  EXPECT_EQ(file.slot_size(), options.slot_size);
  EXPECT_EQ(file.bytes.size(), file.slots_offset() + 8u * options.slot_size);
  expect_restores_sequence(4);
  // The earlier checkpoints came along: damage the newest and the one before restores.
  StoreFile damaged(path);
  damaged.slot(damaged.slot_with_sequence(4))[60] ^= 1;
  damaged.write();
  expect_restores_sequence(3);
}

TEST_F(StoreTest, ANewGeometryTooSmallForTheNewestCheckpointKeepsTheOldOne) {
  save_seeds(1, 2);
  const std::uint32_t old_slot_size = options.slot_size;
  options.slot_size = 112;  // holds no checkpoint at all
  symcr::Store store;
  open(store);
  fill_a(3);
  const symcr::Status saved = store.save();  // into the old geometry, which still holds it
  ASSERT_TRUE(saved.ok()) << saved.message();
  const StoreFile file(path);
  EXPECT_EQ(file.slot_size(), old_slot_size);
  store.close();
  options.slot_size = old_slot_size;
  expect_restores_sequence(3);
}

TEST_F(StoreTest, AZeroedHeaderIsRebuiltFromTheSlotsAndNothingIsLost) {
  save_seeds(1, 6);
  StoreFile file(path);
  std::memset(file.bytes.data(), 0, 36);  // a torn or zeroed first page
  file.write();
  expect_restores_sequence(6);
  const StoreFile rebuilt(path);
  EXPECT_EQ(rebuilt.slot_count(), 4u);
  EXPECT_EQ(rebuilt.slot_size(), options.slot_size);
  EXPECT_EQ(std::vector<std::uint8_t>(rebuilt.bytes.begin() + 4096, rebuilt.bytes.end()),
            std::vector<std::uint8_t>(file.bytes.begin() + 4096, file.bytes.end()))
      << "recovery changed more than the header";
  save_seeds(7, 7);
  expect_restores_sequence(7);
}

TEST_F(StoreTest, ACorruptHeaderWithAnotherGeometryRequestedOpensRestoreOnly) {
  save_seeds(1, 3);
  StoreFile file(path);
  file.bytes[13] ^= 1;  // slot_count, under the header CRC
  file.write();
  options.slots = 6;  // the geometry cannot be confirmed against this
  symcr::Store store;
  open(store);
  EXPECT_TRUE(store.read_only());
  expect_store_restores(store, 3);
  fill_a(4);
  const symcr::Status saved = store.save();
  EXPECT_EQ(saved.error(), Error::Io);
  EXPECT_NE(std::string(saved.message()).find("damaged header"), std::string::npos)
      << saved.message();
  EXPECT_EQ(std::string(saved.message()).find("remove"), std::string::npos) << saved.message();
  EXPECT_EQ(read_file(path), file.bytes) << "a restore-only store was written";
}

TEST_F(StoreTest, AHeaderThatIsNotAStoreAndNoCheckpointsIsRefusedAndLeftAlone) {
  std::vector<std::uint8_t> text(300 * 1024, 'x');
  write_file(path, text);
  symcr::Store store;
  EXPECT_EQ(symcr::Store::open(path.c_str(), schema_a, options, store).error(),
            Error::NotACheckpoint);
  EXPECT_EQ(read_file(path), text);
}

TEST_F(StoreTest, ATruncatedStoreRestoresItsWholeSlotsAndGrowsBackForWriting) {
  save_seeds(1, 4);  // sequences 1-4 in slots 0-3
  StoreFile file(path);
  ASSERT_GT(file.record_size(2), 100u);
  const std::uint64_t cut = file.slots_offset() + 2 * file.slot_size() + 100;  // inside slot 2
  ASSERT_EQ(::truncate(path.c_str(), static_cast<off_t>(cut)), 0);
  expect_restores_sequence(2);
  EXPECT_EQ(read_file(path).size(), file.bytes.size()) << "not grown back to its geometry";
  save_seeds(5, 5);  // sequence 3: the slots past the cut are gone
  scramble_a();
  const symcr::Report report = restore_latest();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 3u);
  expect_a(5);
}

// A truncation that takes only zero bytes off the newest record: the file grows back to its
// geometry zero-filled, which makes that record whole again. The first restore after open()
// (which follows open()'s scan) and every later one must read the file as grown back.
TEST_F(StoreTest, ATruncationOfTrailingZerosIsReadAsGrownBackByTheFirstRestoreToo) {
  save_seeds(1, 3);  // sequences 1-3 in slots 0-2
  StoreFile file(path);
  const std::uint64_t start = file.slots_offset() + 2 * file.slot_size();
  const std::uint64_t end = start + file.record_size(2);
  std::uint64_t cut = end;
  while (cut > start && file.bytes[cut - 1] == 0) --cut;
  ASSERT_LT(cut, end) << "the newest record ends in no zero byte";
  ASSERT_EQ(::truncate(path.c_str(), static_cast<off_t>(cut)), 0);
  symcr::Store store;
  open(store);
  for (int round = 0; round < 2; ++round) {
    scramble_a();
    const symcr::Report report = store.restore_latest();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_EQ(report.sequence(), 3u) << "round " << round;
    EXPECT_TRUE(report.skipped().empty()) << "round " << round;
    expect_a(3);
  }
}

TEST_F(StoreTest, AReadOnlyStoreFileOpensForRestoring) {
  save_seeds(1, 2);
  ASSERT_EQ(::chmod(path.c_str(), 0400), 0);
  const std::vector<std::uint8_t> before = read_file(path);
  // root ignores file permissions: open_readonly() is the same path without relying on them.
  for (const bool explicit_readonly : {false, true}) {
    symcr::Store store;
    const symcr::Status status = explicit_readonly
                                     ? symcr::Store::open_readonly(path.c_str(), schema_a, store)
                                     : symcr::Store::open(path.c_str(), schema_a, options, store);
    ASSERT_TRUE(status.ok()) << status.message();
    if (!explicit_readonly && ::geteuid() == 0) continue;
    EXPECT_TRUE(store.read_only());
    scramble_a();
    ASSERT_TRUE(store.restore_latest().ok());
    expect_a(2);
    EXPECT_EQ(store.save().error(), Error::Io);
  }
  EXPECT_EQ(read_file(path), before);
}

TEST_F(StoreTest, OpenReadonlyTakesTheGeometryFromTheFile) {
  options.slots = 3;
  options.slot_size = 12288;
  save_seeds(1, 5);
  symcr::Store store;
  const symcr::Status status = symcr::Store::open_readonly(path.c_str(), schema_a, store);
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(store.options().slots, 3u);
  EXPECT_EQ(store.options().slot_size, 12288u);
  scramble_a();
  ASSERT_TRUE(store.restore_latest().ok());
  expect_a(5);
}

// The first restore after open() follows the slots open() read, without reading them again;
// a store opened for restoring only holds no lock, so its owner may save meanwhile, and its
// restore reads the slots again and finds that checkpoint.
TEST_F(StoreTest, ARestoreOnlyStoreRestoresWhatItsOwnerSavedAfterItWasOpened) {
  save_seeds(1, 2);
  symcr::Store reader;
  ASSERT_TRUE(symcr::Store::open_readonly(path.c_str(), schema_a, reader).ok());
  {
    symcr::Store owner;
    open(owner);
    fill_a(3);
    ASSERT_TRUE(owner.save().ok());
  }
  expect_store_restores(reader, 3);
}

TEST_F(StoreTest, RestoreLatestAfterOpenAndAfterASaveRestoresTheNewest) {
  save_seeds(1, 2);
  symcr::Store store;
  open(store);
  expect_store_restores(store, 2);
  fill_a(3);
  ASSERT_TRUE(store.save().ok());
  expect_store_restores(store, 3);
  expect_store_restores(store, 3);
}

TEST_F(StoreTest, OpenReadonlyNeverCreatesAFile) {
  symcr::Store store;
  EXPECT_EQ(symcr::Store::open_readonly(path.c_str(), schema_a, store).error(), Error::Io);
  struct stat info {};
  EXPECT_NE(::stat(path.c_str(), &info), 0);
}

TEST_F(StoreTest, DifferentGeometryWithoutCheckpointsIsRewrittenAtTheFirstSave) {
  {
    symcr::Store store;
    open(store);
  }
  options.slots = 3;
  options.slot_size = 8192;
  symcr::Store store;
  open(store);
  EXPECT_EQ(StoreFile(path).slot_count(), 4u) << "open() rewrote the store";
  fill_a(1);
  ASSERT_TRUE(store.save().ok());
  const StoreFile file(path);
  EXPECT_EQ(file.slot_count(), 3u);
  EXPECT_EQ(file.slot_size(), 8192u);
  EXPECT_EQ(file.bytes.size(), file.slots_offset() + 3u * 8192u);
}

// A damaged schema area makes every slot unrestorable for a while; the next save rewrites the
// area, which revives them. That save must still be the newest: numbered above every intact
// record, restorable or not.
TEST_F(StoreTest, ASaveAfterASchemaAreaWasDamagedIsNumberedAboveTheRevivedSlots) {
  save_seeds(3, 6);  // sequences 1..4
  StoreFile file(path);
  file.bytes[4096 + 16 + 3] ^= 0x40;  // a byte of schema area 0's schema
  file.write();
  {
    symcr::Store store;
    open(store);
    EXPECT_EQ(store.restore_latest().status().error(), Error::NoValidSlot);
    fill_a(100);
    ASSERT_TRUE(store.save().ok());
    EXPECT_EQ(store.last_sequence(), 5u);
  }
  const symcr::Report report = restore_latest();
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(report.sequence(), 5u);
  expect_a(100);
}

// A rewrite for another geometry killed before its rename leaves its new file: the next open
// removes it (its process is gone), and the store keeps its checkpoints.
TEST_F(StoreTest, OpenRemovesTheTempFileOfARewriteWhoseProcessDied) {
  save_seeds(1, 2);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) ::_exit(0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  const std::string stale = path + ".tmp." + std::to_string(child) + ".0";
  write_file(stale, std::vector<std::uint8_t>(300000, 0));
  {
    symcr::Store store;
    open(store);
  }
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"copter.store"}));
  const symcr::Report report = restore_latest();
  EXPECT_EQ(report.sequence(), 2u);
}

TEST_F(StoreTest, InvalidOptionsAreRefused) {
  symcr::Store store;
  options.slots = 1;
  EXPECT_FALSE(symcr::Store::open(path.c_str(), schema_a, options, store).ok());
  options.slots = 4;
  options.slot_size = 16;
  EXPECT_FALSE(symcr::Store::open(path.c_str(), schema_a, options, store).ok());
  EXPECT_EQ(dir.entries(), std::vector<std::string>{});
}

TEST_F(StoreTest, AFileThatIsNotAStoreIsLeftAlone) {
  write_text(path, std::string(5000, 'x'));
  symcr::Store store;
  const symcr::Status status = symcr::Store::open(path.c_str(), schema_a, options, store);
  EXPECT_EQ(status.error(), Error::NotACheckpoint);
  EXPECT_EQ(read_file(path), std::vector<std::uint8_t>(5000, 'x'));
}

TEST_F(StoreTest, AnotherProgramsCheckpointIsRefusedUnlessAccepted) {
  static symcr::Schema rover = schema_a;
  static symcr::Schema copter = schema_a;
  rover.program = "rover";
  copter.program = "copter";
  {
    symcr::Store store;
    open(store, rover);
    fill_a(4);
    ASSERT_TRUE(store.save().ok());
  }
  scramble_a();
  const std::vector<std::uint8_t> scrambled = state_a();
  symcr::Store store;
  open(store, copter);
  const symcr::Report refused = store.restore_latest();
  EXPECT_EQ(refused.status().error(), Error::Incompatible);
  EXPECT_NE(std::string(refused.status().message()).find("another program"), std::string::npos)
      << refused.status().message();
  EXPECT_EQ(state_a(), scrambled) << "a refused restore wrote into the state";
  symcr::RestoreOptions accept;
  accept.accept_other_program = true;
  ASSERT_TRUE(store.restore_latest(accept).ok());
  expect_a(4);
  // An anonymous program (no name) accepts it, as before programs were named.
  store.close();
  scramble_a();
  ASSERT_TRUE(restore_latest(schema_a).ok());
  expect_a(4);
}

TEST_F(StoreTest, ACorruptStoreHeaderIsRecoveredFromTheSlots) {
  save_seeds(1, 2);
  StoreFile file(path);
  file.bytes[13] ^= 1;  // slot_count, under the header CRC
  file.write();
  expect_restores_sequence(2);
  EXPECT_EQ(StoreFile(path).slot_count(), 4u);
}

TEST_F(StoreTest, AFutureStoreVersionIsRefusedAndLeftAlone) {
  save_seeds(1, 1);
  StoreFile file(path);
  symcr::format::store16(file.bytes.data() + 8, 2);
  symcr::format::store32(file.bytes.data() + 32, symcr::detail::crc32c(file.bytes.data(), 32));
  file.write();
  symcr::Store store;
  const symcr::Status status = symcr::Store::open(path.c_str(), schema_a, options, store);
  EXPECT_EQ(status.error(), Error::FutureVersion);
  EXPECT_NE(std::string(status.message()).find("version 2"), std::string::npos) << status.message();
  EXPECT_EQ(read_file(path), file.bytes);
}

TEST_F(StoreTest, AnEmptyFileIsInitialised) {
  write_text(path, "");  // e.g. a crash between creating and initialising
  symcr::Store store;
  open(store);
  fill_a(2);
  ASSERT_TRUE(store.save().ok());
  scramble_a();
  ASSERT_TRUE(store.restore_latest().ok());
  expect_a(2);
}

TEST_F(StoreTest, ASymlinkAtThePathIsNotFollowed) {
  const std::string victim = dir.file("victim");
  write_text(victim, "precious");
  ASSERT_EQ(::symlink(victim.c_str(), path.c_str()), 0);
  symcr::Store store;
  const symcr::Status status = symcr::Store::open(path.c_str(), schema_a, options, store);
  EXPECT_EQ(status.error(), Error::Io);
  EXPECT_NE(std::string(status.message()).find("symbolic link"), std::string::npos);
  const std::vector<std::uint8_t> precious = read_file(victim);
  EXPECT_EQ(std::string(precious.begin(), precious.end()), "precious");
  EXPECT_TRUE(is_symlink(path));
}

TEST_F(StoreTest, OneOpenStorePerFile) {
  symcr::Store first;
  open(first);
  symcr::Store second;
  const symcr::Status status = symcr::Store::open(path.c_str(), schema_a, options, second);
  EXPECT_EQ(status.error(), Error::Io);
  EXPECT_FALSE(second.is_open());
  first.close();
  open(second);
  EXPECT_TRUE(second.is_open());
}

TEST_F(StoreTest, MovedStoreKeepsWorking) {
  symcr::Store store;
  open(store);
  symcr::Store moved(std::move(store));
  EXPECT_FALSE(store.is_open());  // NOLINT(bugprone-use-after-move): defined as closed
  fill_a(4);
  ASSERT_TRUE(moved.save().ok());
  symcr::Store assigned;
  assigned = std::move(moved);
  scramble_a();
  const symcr::Report report = assigned.restore_latest();
  ASSERT_TRUE(report.ok());
  expect_a(4);
  EXPECT_EQ(store.save().error(), Error::Io);  // closed stores refuse cleanly
}

}  // namespace
}  // namespace file_tests
