// The device profile (runtime/device) on the host: round trips of every kind it holds, the same
// payload bytes as the host runtime's for the same state (so each restores the other's
// records), and every refusal leaving the roots untouched.
#include "symcr/device.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <vector>

#include "crc32c.hpp"
#include "device_format.hpp"
#include "encode.hpp"
#include "parsed_schema.hpp"
#include "record.hpp"
#include "schema_blob.hpp"
#include "symcr/symcr.hpp"
#include "vehicle.hpp"

namespace device_tests {
namespace {

using symcr::device::Result;

symcr::device::Build build() { return {&kSchema, symcr::detail::schema_blob(kSchema).hash}; }

void expect_filled(int seed) {
  EXPECT_TRUE(holds(seed));
  EXPECT_EQ(vehicle.flying, seed % 2 == 1);
  EXPECT_EQ(vehicle.mode, Mode::Auto);
  EXPECT_EQ(vehicle.altitude, 100 + seed);
  EXPECT_EQ(vehicle.ticks, 5000000000ull + static_cast<std::uint64_t>(seed));
  EXPECT_EQ(vehicle.battery, 15.5f - seed * 0.25f);
  EXPECT_EQ(vehicle.raw.word, 0xA5A50000u + static_cast<std::uint32_t>(seed));
  EXPECT_EQ(vehicle.flags.armed, 1u);
  EXPECT_EQ(vehicle.flags.trim, -3 - seed % 5);
  EXPECT_EQ(vehicle.flags.count, 700u + static_cast<std::uint32_t>(seed));
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(vehicle.route[i].x, seed * 10 + i);
    EXPECT_EQ(vehicle.route[i].y, seed + i * 0.5);
  }
  EXPECT_EQ(vehicle.target, &vehicle.route[2]);
  EXPECT_EQ(vehicle.nothing, nullptr);
}

std::vector<std::uint8_t> device_save() {
  std::vector<std::uint8_t> record(symcr::device::record_size(kSchema));
  std::size_t size = 0;
  EXPECT_EQ(symcr::device::save(build(), 42, record.data(), record.size(), &size), Result::Ok);
  record.resize(size);
  return record;
}

Result device_restore(const std::vector<std::uint8_t>& record, std::uint64_t* sequence = nullptr) {
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(kSchema));
  return symcr::device::restore(build(), record.data(), record.size(), scratch.data(),
                                scratch.size(), sequence);
}

// Recomputes the record's CRC after a test changed a byte on purpose.
void reseal(std::vector<std::uint8_t>& record) {
  std::memset(record.data() + 48, 0, 4);
  const std::uint32_t crc = symcr::detail::crc32c(record.data(), record.size());
  std::memcpy(record.data() + 48, &crc, 4);
}

std::vector<std::uint8_t> snapshot() {
  const auto* bytes = reinterpret_cast<const std::uint8_t*>(&vehicle);
  return std::vector<std::uint8_t>(bytes, bytes + sizeof vehicle);
}

TEST(DeviceProfile, HoldsEveryKindOfItsSchema) {
  std::uint32_t unheld = 0;
  EXPECT_EQ(symcr::device::check_schema(kSchema, &unheld), Result::Ok);
  EXPECT_EQ(unheld, symcr::kNoType);
}

TEST(DeviceProfile, RoundTripsEveryKindAndPointersByPath) {
  fill(3);
  const std::vector<std::uint8_t> record = device_save();
  scramble();
  const int* before_constant = vehicle.constant;
  std::uint64_t sequence = 0;
  ASSERT_EQ(device_restore(record, &sequence), Result::Ok);
  EXPECT_EQ(sequence, 42u);
  expect_filled(3);
  EXPECT_EQ(vehicle.constant, before_constant);  // outside the roots: this build's value
}

TEST(DeviceProfile, WritesTheHostRuntimesPayloadByteForByte) {
  fill(5);
  const std::vector<std::uint8_t> record = device_save();
  std::vector<std::uint8_t> host;
  ASSERT_TRUE(symcr::detail::encode_payload(kSchema, host).ok());
  ASSERT_EQ(record.size(), 56 + host.size());
  EXPECT_TRUE(std::memcmp(record.data() + 56, host.data(), host.size()) == 0);
}

TEST(DeviceProfile, TheHostRestoresADeviceRecord) {
  fill(6);
  const std::vector<std::uint8_t> record = device_save();
  scramble();
  symcr::detail::RecordView view;
  ASSERT_TRUE(symcr::detail::parse_record(record.data(), record.size(), view, nullptr).ok());
  const symcr::Report report = symcr::detail::restore_record(
      view, kSchema, symcr::detail::schema_blob(kSchema).hash, kSchema, symcr::RestoreOptions{});
  ASSERT_TRUE(report.ok()) << report.status().message();
  expect_filled(6);
}

TEST(DeviceProfile, RestoresAHostCheckpointWithItsInlineSchema) {
  fill(7);
  std::vector<std::uint8_t> host;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(kSchema, host, 9).ok());
  scramble();
  std::uint64_t sequence = 0;
  ASSERT_EQ(device_restore(host, &sequence), Result::Ok);
  EXPECT_EQ(sequence, 9u);
  expect_filled(7);
}

TEST(DeviceProfile, RefusalsLeaveTheRootsUntouched) {
  fill(2);
  const std::vector<std::uint8_t> good = device_save();
  scramble();
  const std::vector<std::uint8_t> before = snapshot();
  struct Case {
    const char* what;
    std::vector<std::uint8_t> record;
    Result expected;
  };
  std::vector<Case> cases;
  {
    std::vector<std::uint8_t> r = good;
    r[70] ^= 0x10;  // a payload bit, CRC not updated
    cases.push_back({"bit flip", r, Result::Corrupt});
  }
  cases.push_back(
      {"truncated", std::vector<std::uint8_t>(good.begin(), good.end() - 3), Result::Truncated});
  {
    std::vector<std::uint8_t> r = good;
    r[32] ^= 1;  // schema hash
    reseal(r);
    cases.push_back({"other schema", r, Result::OtherSchema});
  }
  {
    std::vector<std::uint8_t> r = good;
    r[52] ^= 1;  // program id
    reseal(r);
    cases.push_back({"other program", r, Result::OtherProgram});
  }
  {
    std::vector<std::uint8_t> r = good;
    r[8] = 2;  // format version
    cases.push_back({"future version", r, Result::FutureVersion});
  }
  {
    std::vector<std::uint8_t> r = good;
    r[56] = 2;  // `flying`, a bool
    reseal(r);
    cases.push_back({"bool 2", r, Result::Corrupt});
  }
  {
    std::vector<std::uint8_t> r = good;
    const std::int16_t altitude = 6000;  // beyond SYMCR_RANGE's 5000
    std::memcpy(r.data() + 58, &altitude, 2);
    reseal(r);
    cases.push_back({"out of range", r, Result::Rejected});
  }
  {
    std::vector<std::uint8_t> r = good;
    const std::int32_t trim = -13;  // fits the 5-bit field, beyond its range [-12, 12]
    std::memcpy(r.data() + 80, &trim, 4);
    reseal(r);
    cases.push_back({"bit-field out of range", r, Result::Rejected});
  }
  {
    std::vector<std::uint8_t> r = good;
    const std::int32_t trim = 40;  // does not fit 5 signed bits
    std::memcpy(r.data() + 80, &trim, 4);
    reseal(r);
    cases.push_back({"bit-field value beyond its width", r, Result::Corrupt});
  }
  {
    std::vector<std::uint8_t> r = good;
    const std::uint64_t ticks = 666;  // valid_vehicle() refuses it
    std::memcpy(r.data() + 60, &ticks, 8);
    reseal(r);
    cases.push_back({"validator", r, Result::Rejected});
  }
  {
    std::vector<std::uint8_t> r = good;
    r.push_back(0);  // a byte after the reference table, inside the payload
    std::uint32_t payload;
    std::memcpy(&payload, r.data() + 44, 4);
    ++payload;
    std::memcpy(r.data() + 44, &payload, 4);
    reseal(r);
    cases.push_back({"trailing byte", r, Result::Corrupt});
  }
  {
    std::vector<std::uint8_t> r = good;
    const std::uint32_t step = 9;  // the last step of the reference: element 9 of Point[4]
    std::memcpy(r.data() + r.size() - 8, &step, 4);
    reseal(r);
    cases.push_back({"reference step out of its array", r, Result::Corrupt});
  }
  for (const Case& c : cases) {
    EXPECT_EQ(device_restore(c.record), c.expected) << c.what;
    EXPECT_EQ(snapshot(), before) << c.what;
  }
  ASSERT_EQ(device_restore(good), Result::Ok);  // and the good one still restores
  expect_filled(2);
}

TEST(DeviceProfile, TooSmallBuffersAreRefused) {
  fill(1);
  std::vector<std::uint8_t> record(100);
  std::size_t size = 0;
  EXPECT_EQ(symcr::device::save(build(), 1, record.data(), record.size(), &size), Result::NoSpace);
  const std::vector<std::uint8_t> good = device_save();
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(kSchema) - 1);
  EXPECT_EQ(
      symcr::device::restore(build(), good.data(), good.size(), scratch.data(), scratch.size()),
      Result::NoSpace);
}

// A schema with a kind only the host runtime holds is refused, naming the type.
TEST(DeviceProfile, AContainerIsNotHeld) {
  static std::vector<int> values;
  static const symcr::TypeInfo types[] = {scalar("int", Kind::Int, 4),
                                          holder("std::vector<int>", Kind::Container, sizeof values,
                                                 alignof(std::vector<int>), 0, nullptr)};
  static const symcr::RootInfo roots[] = {{"values", 1, &values, 0, nullptr}};
  static const symcr::Schema schema{types, 2, roots, 1, nullptr};
  std::uint32_t unheld = 0;
  EXPECT_EQ(symcr::device::check_schema(schema, &unheld), Result::Unsupported);
  EXPECT_EQ(unheld, 1u);
  std::uint8_t buffer[256];
  std::size_t size = 0;
  EXPECT_EQ(symcr::device::save({&schema, 1}, 0, buffer, sizeof buffer, &size),
            Result::Unsupported);
}

// A hand-written table may set kFieldHasRange and give no bounds: both runtimes read that as no
// range (the host's serialised schema drops the flag) instead of following a null pointer.
TEST(DeviceProfile, ARangeFlagWithoutBoundsIsNoRange) {
  struct Gauge {
    std::int32_t level;
  };
  static Gauge gauge;
  static const symcr::FieldInfo fields[] = {
      {"level", 0, 0, 0, 0, symcr::kFieldHasRange, nullptr, nullptr, nullptr}};
  static const symcr::TypeInfo types[] = {
      scalar("int32", Kind::Int, 4), record("Gauge", sizeof(Gauge), alignof(Gauge), fields, 1)};
  static const symcr::RootInfo roots[] = {{"gauge", 1, &gauge, 0, nullptr}};
  static const symcr::Schema schema{types, 2, roots, 1, nullptr};
  const symcr::device::Build build{&schema, 0x5EED0002DEC0DE02ull};

  gauge.level = 1000000;
  std::uint8_t record_bytes[256];
  std::size_t size = 0;
  ASSERT_EQ(symcr::device::save(build, 1, record_bytes, sizeof record_bytes, &size), Result::Ok);
  gauge.level = 0;
  std::uint8_t scratch[64];
  ASSERT_EQ(symcr::device::restore(build, record_bytes, size, scratch, sizeof scratch), Result::Ok);
  EXPECT_EQ(gauge.level, 1000000);

  symcr::detail::SchemaBlob blob;
  symcr::detail::serialise_blob(schema, blob);
  symcr::detail::ParsedSchema parsed;
  ASSERT_TRUE(symcr::detail::parse_schema(blob.data, blob.size, parsed).ok());
  EXPECT_EQ(parsed.schema().types[1].fields[0].flags & symcr::kFieldHasRange, 0u);
  EXPECT_EQ(parsed.schema().types[1].fields[0].range, nullptr);
}

// ---- the ring -------------------------------------------------------------------------------

// Flash as a block device: erased bytes are 0xFF, a write may only clear bits of erased ones.
struct Flash {
  std::vector<std::uint8_t> bytes;
  std::size_t unit;
  std::size_t erases = 0;
  std::size_t torn_after = SIZE_MAX;  // a write stops after this many bytes (a reset)
  Flash(std::size_t size, std::size_t erase_unit) : bytes(size, 0xFF), unit(erase_unit) {}

  symcr::device::Storage storage() { return {bytes.size(), unit, read, write, erase, this}; }
  static bool read(void* self, std::size_t offset, void* out, std::size_t n) {
    std::memcpy(out, static_cast<Flash*>(self)->bytes.data() + offset, n);
    return true;
  }
  static bool write(void* self, std::size_t offset, const void* data, std::size_t n) {
    Flash& flash = *static_cast<Flash*>(self);
    const auto* in = static_cast<const std::uint8_t*>(data);
    for (std::size_t i = 0; i < n && i < flash.torn_after; ++i) {
      if ((flash.bytes[offset + i] & in[i]) != in[i]) return false;  // not erased
      flash.bytes[offset + i] = in[i];
    }
    return flash.torn_after >= n;
  }
  static bool erase(void* self, std::size_t offset, std::size_t n) {
    Flash& flash = *static_cast<Flash*>(self);
    if (offset % flash.unit != 0 || n % flash.unit != 0) return false;
    std::fill(flash.bytes.begin() + offset, flash.bytes.begin() + offset + n, 0xFF);
    ++flash.erases;
    return true;
  }
};

// Backup SRAM whose writes a reset can cut short: the bytes before the cut are new, the rest old.
struct BackupSram {
  std::vector<std::uint8_t> bytes;
  std::size_t torn_after = SIZE_MAX;
  explicit BackupSram(std::size_t size) : bytes(size, 0) {}

  symcr::device::Storage storage() { return {bytes.size(), 1, read, write, nullptr, this}; }
  static bool read(void* self, std::size_t offset, void* out, std::size_t n) {
    std::memcpy(out, static_cast<BackupSram*>(self)->bytes.data() + offset, n);
    return true;
  }
  static bool write(void* self, std::size_t offset, const void* data, std::size_t n) {
    BackupSram& sram = *static_cast<BackupSram*>(self);
    const std::size_t written = std::min(n, sram.torn_after);
    std::memcpy(sram.bytes.data() + offset, data, written);
    sram.torn_after -= sram.torn_after == SIZE_MAX ? 0 : written;
    return written == n;
  }
};

struct RingBuffers {
  std::vector<std::uint8_t> record = std::vector<std::uint8_t>(1024);
  std::vector<std::uint8_t> scratch =
      std::vector<std::uint8_t>(symcr::device::scratch_size(kSchema));
};

Result ring_restore(symcr::device::Ring& ring, RingBuffers& b, std::uint64_t* sequence,
                    std::size_t* skipped) {
  return ring.restore_latest(build(), b.record.data(), b.record.size(), b.scratch.data(),
                             b.scratch.size(), sequence, nullptr, skipped);
}

TEST(DeviceRing, SavesRoundTheSlotsAndRestoresTheNewestAfterAReset) {
  std::vector<std::uint8_t> sram(4 * 1024, 0);
  RingBuffers b;
  {
    symcr::device::Ring ring;
    ASSERT_EQ(ring.open(symcr::device::memory_storage(sram.data(), sram.size()), 1024), Result::Ok);
    EXPECT_EQ(ring.slot_count(), 4u);
    for (int seed = 1; seed <= 6; ++seed) {  // wraps: slots hold 3..6
      fill(seed);
      ASSERT_EQ(ring.save(build(), b.record.data(), b.record.size()), Result::Ok) << seed;
    }
    EXPECT_EQ(ring.last_sequence(), 6u);
  }
  scramble();  // the watchdog reset: RAM is gone, the backup SRAM is not
  symcr::device::Ring ring;
  ASSERT_EQ(ring.open(symcr::device::memory_storage(sram.data(), sram.size()), 1024), Result::Ok);
  EXPECT_EQ(ring.last_sequence(), 6u);
  std::uint64_t sequence = 0;
  std::size_t skipped = 9;
  ASSERT_EQ(ring_restore(ring, b, &sequence, &skipped), Result::Ok);
  EXPECT_EQ(sequence, 6u);
  EXPECT_EQ(skipped, 0u);
  expect_filled(6);
}

TEST(DeviceRing, FallsBackPastACorruptNewestSlot) {
  std::vector<std::uint8_t> sram(3 * 1024, 0);
  RingBuffers b;
  symcr::device::Ring ring;
  ASSERT_EQ(ring.open(symcr::device::memory_storage(sram.data(), sram.size()), 1024), Result::Ok);
  for (int seed = 1; seed <= 2; ++seed) {
    fill(seed);
    ASSERT_EQ(ring.save(build(), b.record.data(), b.record.size()), Result::Ok);
  }
  sram[1024 + 100] ^= 0x04;  // slot 1 holds sequence 2
  scramble();
  std::uint64_t sequence = 0;
  std::size_t skipped = 0;
  ASSERT_EQ(ring_restore(ring, b, &sequence, &skipped), Result::Ok);
  EXPECT_EQ(sequence, 1u);
  EXPECT_EQ(skipped, 1u);
  expect_filled(1);
}

TEST(DeviceRing, OnFlashErasesBeforeWritingAndSurvivesATornWrite) {
  Flash flash(4 * 512, 512);
  RingBuffers b;
  symcr::device::Ring ring;
  ASSERT_EQ(ring.open(flash.storage(), 512), Result::Ok);
  fill(1);
  ASSERT_EQ(ring.save(build(), b.record.data(), b.record.size()), Result::Ok);
  fill(2);
  ASSERT_EQ(ring.save(build(), b.record.data(), b.record.size()), Result::Ok);
  EXPECT_EQ(flash.erases, 2u);
  fill(3);
  flash.torn_after = 100;  // the reset comes in the middle of the third save
  EXPECT_EQ(ring.save(build(), b.record.data(), b.record.size()), Result::Corrupt);
  flash.torn_after = SIZE_MAX;
  scramble();
  symcr::device::Ring after_reset;
  ASSERT_EQ(after_reset.open(flash.storage(), 512), Result::Ok);
  std::uint64_t sequence = 0;
  std::size_t skipped = 0;
  ASSERT_EQ(ring_restore(after_reset, b, &sequence, &skipped), Result::Ok);
  EXPECT_EQ(sequence, 2u);
  expect_filled(2);
  // Saving goes on after the newest whole record: into the torn slot, with the torn save's
  // sequence, rewriting nothing older.
  fill(4);
  ASSERT_EQ(after_reset.save(build(), b.record.data(), b.record.size()), Result::Ok);
  ASSERT_EQ(ring_restore(after_reset, b, &sequence, &skipped), Result::Ok);
  EXPECT_EQ(sequence, 3u);
  EXPECT_EQ(skipped, 0u);
  expect_filled(4);
  EXPECT_EQ(flash.erases, 4u);  // the torn save's and this one's, both of the same slot
}

// On flash a reset while a save programs its slot can leave the magic written and the sequence
// still erased (all ones): that slot must not be taken for the newest, nor its sequence + 1
// (wrapped to 0) for the next one. Every point of the save's writes is tried.
TEST(DeviceRing, OnFlashAResetAtAnyByteOfASaveNeverPinsTheRing) {
  RingBuffers b;
  const std::size_t record = symcr::device::record_size(kSchema);
  for (std::size_t cut = 0; cut <= record; ++cut) {
    Flash flash(4 * 512, 512);
    {
      symcr::device::Ring ring;
      ASSERT_EQ(ring.open(flash.storage(), 512), Result::Ok);
      for (int seed = 1; seed <= 6; ++seed) {
        fill(seed);
        ASSERT_EQ(ring.save(build(), b.record.data(), b.record.size()), Result::Ok);
      }
      fill(7);
      flash.torn_after = cut;  // the reset comes in the middle of save 7
      ring.save(build(), b.record.data(), b.record.size());
      flash.torn_after = SIZE_MAX;
    }
    std::uint64_t sequence = 0;
    {
      symcr::device::Ring ring;
      ASSERT_EQ(ring.open(flash.storage(), 512), Result::Ok);
      scramble();
      ASSERT_EQ(ring_restore(ring, b, &sequence, nullptr), Result::Ok) << "cut after " << cut;
      const int restored = holds(7) ? 7 : 6;
      EXPECT_TRUE(holds(restored)) << "cut after " << cut;
      EXPECT_EQ(sequence, static_cast<std::uint64_t>(restored)) << "cut after " << cut;
      for (int seed = 8; seed <= 17; ++seed) {
        fill(seed);
        ASSERT_EQ(ring.save(build(), b.record.data(), b.record.size()), Result::Ok);
      }
      EXPECT_EQ(ring.last_sequence(), static_cast<std::uint64_t>(restored + 10)) << cut;
    }
    symcr::device::Ring ring;
    ASSERT_EQ(ring.open(flash.storage(), 512), Result::Ok);
    scramble();
    ASSERT_EQ(ring_restore(ring, b, &sequence, nullptr), Result::Ok) << "cut after " << cut;
    EXPECT_TRUE(holds(17)) << "cut after " << cut << ": the newest save is not restored";
  }
}

// In backup SRAM a save rewrites its slot in place. When the record there had been damaged and
// the new one takes its sequence, a reset after the new header's first bytes must not bring the
// old record back as the newest, in front of a later save.
TEST(DeviceRing, OnBackupSramATornRewriteNeverRevivesADamagedOlderRecord) {
  RingBuffers b;
  const std::size_t record = symcr::device::record_size(kSchema);
  for (std::size_t cut = 0; cut <= 64 + record; ++cut) {
    BackupSram sram(3 * 512);
    symcr::device::Ring ring;
    ASSERT_EQ(ring.open(sram.storage(), 512), Result::Ok);
    for (int seed = 1; seed <= 3; ++seed) {  // sequences 1, 2, 3 in slots 0, 1, 2
      fill(seed);
      ASSERT_EQ(ring.save(build(), b.record.data(), b.record.size()), Result::Ok);
    }
    sram.bytes[512] ^= 0x01;   // save 2's magic
    sram.bytes[1024] ^= 0x01;  // save 3's magic
    fill(4);                   // goes after save 1, as sequence 2, into slot 1
    ASSERT_EQ(ring.save(build(), b.record.data(), b.record.size()), Result::Ok);
    fill(5);  // goes into slot 2, as sequence 3: save 3's
    sram.torn_after = cut;
    ring.save(build(), b.record.data(), b.record.size());
    sram.torn_after = SIZE_MAX;
    symcr::device::Ring after_reset;
    ASSERT_EQ(after_reset.open(sram.storage(), 512), Result::Ok);
    scramble();
    ASSERT_EQ(ring_restore(after_reset, b, nullptr, nullptr), Result::Ok) << "cut after " << cut;
    EXPECT_TRUE(holds(4) || holds(5)) << "cut after " << cut << ": an older save came back";
  }
}

// Sequences run from 1 to kLastRingSequence. A record with any other (here all ones, erased
// flash's) is not the ring's, and the next save never wraps to 0; at the last one, save refuses
// and changes nothing.
TEST(DeviceRing, SequencesNeverWrapAndTheLastOneRefusesFurtherSaves) {
  RingBuffers b;
  std::vector<std::uint8_t> sram(3 * 1024, 0);
  const symcr::device::Storage storage = symcr::device::memory_storage(sram.data(), sram.size());
  auto plant = [&](std::uint64_t sequence, std::size_t slot) {
    std::size_t size = 0;
    ASSERT_EQ(symcr::device::save(build(), sequence, b.record.data(), b.record.size(), &size),
              Result::Ok);
    std::memcpy(sram.data() + slot * 1024, b.record.data(), size);
  };
  fill(1);
  plant(1, 0);
  fill(2);
  plant(~std::uint64_t{0}, 1);
  symcr::device::Ring ring;
  ASSERT_EQ(ring.open(storage, 1024), Result::Ok);
  EXPECT_EQ(ring.last_sequence(), 1u);
  std::uint64_t sequence = 0;
  ASSERT_EQ(ring_restore(ring, b, &sequence, nullptr), Result::Ok);
  EXPECT_EQ(sequence, 1u);
  expect_filled(1);
  fill(3);
  ASSERT_EQ(ring.save(build(), b.record.data(), b.record.size()), Result::Ok);
  EXPECT_EQ(ring.last_sequence(), 2u);
  ASSERT_EQ(ring_restore(ring, b, &sequence, nullptr), Result::Ok);
  EXPECT_EQ(sequence, 2u);
  expect_filled(3);

  fill(4);
  plant(symcr::device::kLastRingSequence, 2);
  ASSERT_EQ(ring.open(storage, 1024), Result::Ok);
  EXPECT_EQ(ring.last_sequence(), symcr::device::kLastRingSequence);
  const std::vector<std::uint8_t> before = sram;
  fill(5);
  EXPECT_EQ(ring.save(build(), b.record.data(), b.record.size()), Result::SequenceExhausted);
  EXPECT_EQ(sram, before);
  ASSERT_EQ(ring_restore(ring, b, &sequence, nullptr), Result::Ok);
  EXPECT_EQ(sequence, symcr::device::kLastRingSequence);
  expect_filled(4);
}

TEST(DeviceRing, AnEmptyRingRestoresNothingAndChangesNothing) {
  std::vector<std::uint8_t> sram(2 * 1024, 0);
  RingBuffers b;
  symcr::device::Ring ring;
  ASSERT_EQ(ring.open(symcr::device::memory_storage(sram.data(), sram.size()), 1024), Result::Ok);
  fill(5);
  const std::vector<std::uint8_t> before = snapshot();
  EXPECT_EQ(ring_restore(ring, b, nullptr, nullptr), Result::Empty);
  EXPECT_EQ(snapshot(), before);
}

TEST(DeviceRing, BadGeometriesAreRefused) {
  std::vector<std::uint8_t> sram(1024, 0);
  symcr::device::Ring ring;
  EXPECT_EQ(ring.open(symcr::device::memory_storage(sram.data(), sram.size()), 1024),
            Result::NoSpace);  // one slot: no fallback possible
  Flash flash(4 * 512, 512);
  EXPECT_EQ(ring.open(flash.storage(), 300), Result::Unsupported);  // not whole erase units
}

// Arrays of values that are their bytes (numbers, enums, unions) restore element for element
// whatever path the decoder takes for them; an array of bools is still checked element by
// element, and a bad one refuses the record with the roots untouched.
struct Series {
  std::int16_t samples[5];
  Raw raws[2];
  bool seen[3];
  Mode modes[2];
  double levels[2];
};
Series series;

const symcr::Schema& series_schema() {
  enum : std::uint32_t {
    kI16,
    kSamples,
    kRawT,
    kRaws,
    kBoolT,
    kSeen,
    kU8T,
    kModeT,
    kModes2,
    kF64T,
    kLevels,
    kSeries,
    kCount
  };
  static const symcr::FieldInfo fields[] = {field("samples", kSamples, offsetof(Series, samples)),
                                            field("raws", kRaws, offsetof(Series, raws)),
                                            field("seen", kSeen, offsetof(Series, seen)),
                                            field("modes", kModes2, offsetof(Series, modes)),
                                            field("levels", kLevels, offsetof(Series, levels))};
  static const symcr::TypeInfo types[kCount] = {
      scalar("int16", Kind::Int, 2),
      array("int16[5]", kI16, 5, sizeof(Series::samples), alignof(std::int16_t)),
      union_of("Raw", sizeof(Raw), alignof(Raw)),
      array("Raw[2]", kRawT, 2, sizeof(Series::raws), alignof(Raw)),
      scalar("bool", Kind::Bool, 1),
      array("bool[3]", kBoolT, 3, sizeof(Series::seen), alignof(bool)),
      scalar("uint8", Kind::UInt, 1),
      enumeration("Mode", 1, kU8T, kModes, 2),
      array("Mode[2]", kModeT, 2, sizeof(Series::modes), alignof(Mode)),
      scalar("float64", Kind::Float, 8),
      array("float64[2]", kF64T, 2, sizeof(Series::levels), alignof(double)),
      record("Series", sizeof(Series), alignof(Series), fields, 5)};
  static const symcr::RootInfo roots[] = {{"series", kSeries, &series, 0, nullptr}};
  static const symcr::Schema schema{types, kCount, roots, 1, "device-series"};
  return schema;
}

void fill_series() {
  series = Series{{-7, 300, 0, 32767, -32768},
                  {},
                  {true, false, true},
                  {Mode::Auto, Mode::Stabilize},
                  {2.5, -1e300}};
  series.raws[0].word = 0xDEADBEEFu;
  series.raws[1].real = 0.125f;
}

TEST(DeviceProfile, ArraysOfNumbersEnumsUnionsAndBoolsRestoreEachElement) {
  const symcr::Schema& schema = series_schema();
  const symcr::device::Build series_build{&schema, symcr::detail::schema_blob(schema).hash};
  fill_series();
  std::vector<std::uint8_t> record(symcr::device::record_size(schema));
  std::size_t size = 0;
  ASSERT_EQ(symcr::device::save(series_build, 1, record.data(), record.size(), &size), Result::Ok);
  record.resize(size);
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(schema));
  std::memset(static_cast<void*>(&series), 0x5A, sizeof series);
  ASSERT_EQ(symcr::device::restore(series_build, record.data(), record.size(), scratch.data(),
                                   scratch.size()),
            Result::Ok);
  const std::int16_t samples[] = {-7, 300, 0, 32767, -32768};
  for (int i = 0; i < 5; ++i) EXPECT_EQ(series.samples[i], samples[i]) << i;
  EXPECT_EQ(series.raws[0].word, 0xDEADBEEFu);
  EXPECT_EQ(series.raws[1].real, 0.125f);
  EXPECT_TRUE(series.seen[0]);
  EXPECT_FALSE(series.seen[1]);
  EXPECT_TRUE(series.seen[2]);
  EXPECT_EQ(series.modes[0], Mode::Auto);
  EXPECT_EQ(series.modes[1], Mode::Stabilize);
  EXPECT_EQ(series.levels[0], 2.5);
  EXPECT_EQ(series.levels[1], -1e300);

  // The payload follows the header: samples (10 bytes), raws (8), then seen[1].
  constexpr std::size_t kSecondBool = 56 + 10 + 8 + 1;
  record[kSecondBool] = 2;
  reseal(record);
  std::memset(static_cast<void*>(&series), 0x33, sizeof series);
  std::vector<std::uint8_t> before(sizeof series);
  std::memcpy(before.data(), &series, sizeof series);
  EXPECT_EQ(symcr::device::restore(series_build, record.data(), record.size(), scratch.data(),
                                   scratch.size()),
            Result::Corrupt);
  EXPECT_EQ(std::memcmp(before.data(), &series, sizeof series), 0);
  // The host's first restore of its own checkpoint in a process takes the same decoder.
  std::vector<std::uint8_t> host;
  fill_series();
  ASSERT_TRUE(symcr::checkpoint_to_buffer(schema, host).ok());
  std::memset(static_cast<void*>(&series), 0x5A, sizeof series);
  const symcr::Report restored = symcr::restore_from_buffer(schema, host.data(), host.size());
  ASSERT_TRUE(restored.ok()) << restored.status().message();
  for (int i = 0; i < 5; ++i) EXPECT_EQ(series.samples[i], samples[i]) << i;
  EXPECT_EQ(series.raws[0].word, 0xDEADBEEFu);
  EXPECT_EQ(series.modes[0], Mode::Auto);
  EXPECT_EQ(series.levels[1], -1e300);
}

// Structs whose fields are all plain numbers, in arrays, restore by the same few copies per
// element when the decoder is built for speed: what lies between their fields (padding, bytes
// no field names) keeps its live value, and a range, a validator or a bool among the fields
// still decides the record. A struct of more separate runs than the decoder copies at once goes
// field by field, to the same values.
struct Sample {
  std::uint16_t a, b, c;  // then two bytes of padding
  std::uint32_t d;
  float level;  // ranged [0, 1]
};
struct Pair {  // validated: x <= y
  std::int32_t x, y;
};
struct Switch {
  std::uint8_t u;
  bool on;
  std::int16_t v;
};
struct Gappy {  // ten fields at the even offsets: ten runs
  std::uint8_t bytes[20];
};
struct Table {
  Sample samples[3];
  Pair pairs[2];
  Switch switches[2];
  Gappy gappy[2];
};
Table table;

const symcr::FieldRange kUnit{0.0, 1.0};
bool ordered_pair(const void* object) {
  const Pair& pair = *static_cast<const Pair*>(object);
  return pair.x <= pair.y;
}

const symcr::Schema& table_schema() {
  enum : std::uint32_t {
    kU16,
    kU32,
    kF32,
    kSample,
    kSamples,
    kI32,
    kPair,
    kPairs,
    kU8,
    kBool,
    kI16,
    kSwitch,
    kSwitches,
    kGappy,
    kGappies,
    kTable,
    kCount
  };
  static const symcr::FieldInfo sample_fields[] = {
      field("a", kU16, offsetof(Sample, a)), field("b", kU16, offsetof(Sample, b)),
      field("c", kU16, offsetof(Sample, c)), field("d", kU32, offsetof(Sample, d)),
      ranged("level", kF32, offsetof(Sample, level), kUnit)};
  static const symcr::FieldInfo pair_fields[] = {field("x", kI32, offsetof(Pair, x)),
                                                 field("y", kI32, offsetof(Pair, y))};
  static const symcr::FieldInfo switch_fields[] = {field("u", kU8, offsetof(Switch, u)),
                                                   field("on", kBool, offsetof(Switch, on)),
                                                   field("v", kI16, offsetof(Switch, v))};
  static const symcr::FieldInfo gappy_fields[] = {
      field("b0", kU8, 0),   field("b2", kU8, 2),   field("b4", kU8, 4),   field("b6", kU8, 6),
      field("b8", kU8, 8),   field("b10", kU8, 10), field("b12", kU8, 12), field("b14", kU8, 14),
      field("b16", kU8, 16), field("b18", kU8, 18)};
  static const symcr::FieldInfo table_fields[] = {
      field("samples", kSamples, offsetof(Table, samples)),
      field("pairs", kPairs, offsetof(Table, pairs)),
      field("switches", kSwitches, offsetof(Table, switches)),
      field("gappy", kGappies, offsetof(Table, gappy))};
  static const symcr::TypeInfo types[kCount] = {
      scalar("uint16", Kind::UInt, 2),
      scalar("uint32", Kind::UInt, 4),
      scalar("float32", Kind::Float, 4),
      record("Sample", sizeof(Sample), alignof(Sample), sample_fields, 5),
      array("Sample[3]", kSample, 3, sizeof(Table::samples), alignof(Sample)),
      scalar("int32", Kind::Int, 4),
      record("Pair", sizeof(Pair), alignof(Pair), pair_fields, 2, nullptr, ordered_pair),
      array("Pair[2]", kPair, 2, sizeof(Table::pairs), alignof(Pair)),
      scalar("uint8", Kind::UInt, 1),
      scalar("bool", Kind::Bool, 1),
      scalar("int16", Kind::Int, 2),
      record("Switch", sizeof(Switch), alignof(Switch), switch_fields, 3),
      array("Switch[2]", kSwitch, 2, sizeof(Table::switches), alignof(Switch)),
      record("Gappy", sizeof(Gappy), alignof(Gappy), gappy_fields, 10),
      array("Gappy[2]", kGappy, 2, sizeof(Table::gappy), alignof(Gappy)),
      record("Table", sizeof(Table), alignof(Table), table_fields, 4)};
  static const symcr::RootInfo roots[] = {{"table", kTable, &table, 0, nullptr}};
  static const symcr::Schema schema{types, kCount, roots, 1, "device-table"};
  return schema;
}

void fill_table() {
  std::memset(static_cast<void*>(&table), 0, sizeof table);
  for (int i = 0; i < 3; ++i) {
    table.samples[i] =
        Sample{static_cast<std::uint16_t>(100 + i), static_cast<std::uint16_t>(200 + i),
               static_cast<std::uint16_t>(300 + i), 70000u + static_cast<std::uint32_t>(i),
               0.25f * static_cast<float>(i)};
  }
  table.pairs[0] = Pair{-5, 5};
  table.pairs[1] = Pair{7, 7};
  table.switches[0] = Switch{9, true, -300};
  table.switches[1] = Switch{250, false, 12345};
  for (int g = 0; g < 2; ++g) {
    for (int b = 0; b < 20; ++b) table.gappy[g].bytes[b] = static_cast<std::uint8_t>(g * 20 + b);
  }
}

// The restored table: fill_table()'s values where a field is, `live` in the bytes between them.
void expect_table(std::uint8_t live) {
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(table.samples[i].a, 100 + i) << i;
    EXPECT_EQ(table.samples[i].b, 200 + i) << i;
    EXPECT_EQ(table.samples[i].c, 300 + i) << i;
    EXPECT_EQ(table.samples[i].d, 70000u + static_cast<std::uint32_t>(i)) << i;
    EXPECT_EQ(table.samples[i].level, 0.25f * static_cast<float>(i)) << i;
    const auto* padding = reinterpret_cast<const std::uint8_t*>(&table.samples[i]) + 6;
    EXPECT_EQ(padding[0], live) << i;
    EXPECT_EQ(padding[1], live) << i;
  }
  EXPECT_EQ(table.pairs[0].x, -5);
  EXPECT_EQ(table.pairs[1].y, 7);
  EXPECT_EQ(table.switches[0].u, 9);
  EXPECT_TRUE(table.switches[0].on);
  EXPECT_EQ(table.switches[0].v, -300);
  EXPECT_EQ(table.switches[1].u, 250);
  EXPECT_FALSE(table.switches[1].on);
  EXPECT_EQ(table.switches[1].v, 12345);
  for (int g = 0; g < 2; ++g) {
    for (int b = 0; b < 20; ++b) {
      EXPECT_EQ(table.gappy[g].bytes[b], b % 2 == 0 ? g * 20 + b : live) << g << " " << b;
    }
  }
}

TEST(DeviceProfile, StructsOfNumbersInArraysRestoreByRunsAndKeepTheirChecks) {
  static_assert(offsetof(Sample, d) == 8, "two bytes of padding after Sample::c");
  const symcr::Schema& schema = table_schema();
  const symcr::device::Build table_build{&schema, symcr::detail::schema_blob(schema).hash};
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(schema));
  const auto save = [&] {
    std::vector<std::uint8_t> record(symcr::device::record_size(schema));
    std::size_t size = 0;
    EXPECT_EQ(symcr::device::save(table_build, 1, record.data(), record.size(), &size), Result::Ok);
    record.resize(size);
    return record;
  };
  const auto restore = [&](const std::vector<std::uint8_t>& record) {
    return symcr::device::restore(table_build, record.data(), record.size(), scratch.data(),
                                  scratch.size());
  };
  const auto refused = [&](const std::vector<std::uint8_t>& record, Result expected) {
    std::memset(static_cast<void*>(&table), 0x33, sizeof table);
    std::vector<std::uint8_t> before(sizeof table);
    std::memcpy(before.data(), &table, sizeof table);
    EXPECT_EQ(restore(record), expected);
    EXPECT_EQ(std::memcmp(before.data(), &table, sizeof table), 0);
  };
  fill_table();
  const std::vector<std::uint8_t> good = save();
  std::memset(static_cast<void*>(&table), 0x5A, sizeof table);
  ASSERT_EQ(restore(good), Result::Ok);
  expect_table(0x5A);

  fill_table();
  table.samples[2].level = 1.5f;  // out of its range
  refused(save(), Result::Rejected);
  fill_table();
  table.pairs[1] = Pair{8, 7};  // refused by its validator
  refused(save(), Result::Rejected);
  // The payload follows the header: samples (3 x 14 bytes), pairs (2 x 8), then switches[1].on.
  constexpr std::size_t kSecondSwitchOn = 56 + 3 * 14 + 2 * 8 + 4 + 1;
  std::vector<std::uint8_t> bad_bool = good;
  ASSERT_EQ(bad_bool[kSecondSwitchOn], 0);
  bad_bool[kSecondSwitchOn] = 2;
  reseal(bad_bool);
  refused(bad_bool, Result::Corrupt);

  // The host's first restore of its own checkpoint in a process takes the same decoder.
  std::vector<std::uint8_t> host;
  fill_table();
  ASSERT_TRUE(symcr::checkpoint_to_buffer(schema, host).ok());
  std::memset(static_cast<void*>(&table), 0x6B, sizeof table);
  const symcr::Report restored = symcr::restore_from_buffer(schema, host.data(), host.size());
  ASSERT_TRUE(restored.ok()) << restored.status().message();
  expect_table(0x6B);
}

// A 64-bit integer just past its range is refused: as a double, 2^53 + 1 rounds onto a bound
// of 2^53. The device refuses the record; a host's first restore (the same decoder) then goes
// the general way, which rejects that value alone.
struct Odometer {
  std::uint64_t total;  // ranged [0, 2^53]
  std::int64_t debt;    // ranged [-2^53, 0]
};
Odometer odometer;
const symcr::FieldRange kUpTo2To53{0, 9007199254740992.0};
const symcr::FieldRange kDownTo2To53{-9007199254740992.0, 0};

const symcr::Schema& odometer_schema() {
  static const symcr::FieldInfo fields[] = {
      ranged("total", 0, offsetof(Odometer, total), kUpTo2To53),
      ranged("debt", 1, offsetof(Odometer, debt), kDownTo2To53)};
  static const symcr::TypeInfo types[] = {
      scalar("uint64", Kind::UInt, 8), scalar("int64", Kind::Int, 8),
      record("Odometer", sizeof(Odometer), alignof(Odometer), fields, 2)};
  static const symcr::RootInfo roots[] = {{"odometer", 2, &odometer, 0, nullptr}};
  static const symcr::Schema schema{types, 3, roots, 1, "device-odometer"};
  return schema;
}

TEST(DeviceProfile, ASixtyFourBitIntegerJustPastItsRangeIsRefused) {
  const symcr::Schema& schema = odometer_schema();
  const symcr::device::Build odometer_build{&schema, symcr::detail::schema_blob(schema).hash};
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(schema));
  const std::uint64_t two53 = std::uint64_t{1} << 53;
  const auto restored = [&](std::uint64_t total, std::int64_t debt) {
    odometer = Odometer{total, debt};
    std::vector<std::uint8_t> record(symcr::device::record_size(schema));
    std::size_t size = 0;
    EXPECT_EQ(symcr::device::save(odometer_build, 1, record.data(), record.size(), &size),
              Result::Ok);
    odometer = Odometer{7, -7};
    return symcr::device::restore(odometer_build, record.data(), size, scratch.data(),
                                  scratch.size());
  };
  EXPECT_EQ(restored(two53, -static_cast<std::int64_t>(two53)), Result::Ok);
  EXPECT_EQ(odometer.total, two53);
  EXPECT_EQ(restored(two53 + 1, 0), Result::Rejected);
  EXPECT_EQ(odometer.total, 7u);
  EXPECT_EQ(restored(0, -static_cast<std::int64_t>(two53) - 1), Result::Rejected);
  EXPECT_EQ(odometer.debt, -7);

  // The host's first restore of its own checkpoint in this process.
  odometer = Odometer{two53 + 1, -5};
  std::vector<std::uint8_t> host;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(schema, host).ok());
  odometer = Odometer{7, -7};
  const symcr::Report report = symcr::restore_from_buffer(schema, host.data(), host.size());
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(odometer.total, 7u);
  EXPECT_EQ(odometer.debt, -5);
  EXPECT_EQ(report.count(symcr::Decision::Rejected), 1u);
}

// A host's first restore in a fresh process runs the walk of the decoder as the steps a store's
// open wrote (held_steps()): runs of bytes in one copy, every other value decoded as the walk
// decodes it. Over the test vehicle without its validator (which the steps do not take), every
// payload byte damaged four ways must be decided, and staged, as the walk decides it.
TEST(DeviceProfile, TheStepsOfTheWalkDecodeEveryPayloadAsTheWalkDoes) {
  using symcr::device::detail::HeldStep;
  EXPECT_EQ(symcr::device::detail::held_steps(kSchema, nullptr, 0, 1000), 0u);  // a validator
  symcr::TypeInfo types[kTypeCount];
  std::copy(std::begin(kTypes), std::end(kTypes), types);
  types[kVehicle].validate = nullptr;
  const symcr::Schema schema{types, kTypeCount, kRoots, 1, "device-test"};

  std::vector<HeldStep> steps(symcr::device::detail::held_steps(schema, nullptr, 0, 1000));
  ASSERT_EQ(symcr::device::detail::held_steps(schema, steps.data(), steps.size(), 1000),
            steps.size());
  constexpr std::uint32_t kCopy = symcr::kNoType;
  std::vector<HeldStep> expected = {
      {offsetof(Vehicle, flying), 0, kBool, kCopy},
      {offsetof(Vehicle, mode), 1, kCopy, kCopy},
      {0, 0, kVehicle, 2},  // altitude: ranged
      // ticks, battery and raw: one run
      {offsetof(Vehicle, ticks), offsetof(Vehicle, flags) - offsetof(Vehicle, ticks), kCopy, kCopy},
      {offsetof(Vehicle, flags), 0, kFlags, 0},  // bit-fields
      {offsetof(Vehicle, flags), 0, kFlags, 1},
      {offsetof(Vehicle, flags), 0, kFlags, 2}};
  // The route: the first point's x; each y with the next point's x, which follows it; the last y.
  static_assert(offsetof(Point, x) == 0 && offsetof(Point, y) == 8 && sizeof(Point) == 16, "");
  const std::size_t route = offsetof(Vehicle, route);
  expected.push_back({route, 4, kCopy, kCopy});
  for (std::size_t i = 0; i < 3; ++i) expected.push_back({route + i * 16 + 8, 12, kCopy, kCopy});
  expected.push_back({route + 3 * 16 + 8, 8, kCopy, kCopy});
  expected.push_back({offsetof(Vehicle, target), 0, kPointPtr, kCopy});
  expected.push_back({offsetof(Vehicle, constant), 0, kIntPtr, kCopy});
  expected.push_back({offsetof(Vehicle, nothing), 0, kPointPtr, kCopy});
  ASSERT_EQ(steps.size(), expected.size());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    EXPECT_EQ(steps[i].stage, expected[i].stage) << i;
    EXPECT_EQ(steps[i].size, expected[i].size) << i;
    EXPECT_EQ(steps[i].type, expected[i].type) << i;
    EXPECT_EQ(steps[i].field, expected[i].field) << i;
  }
  // Past the limit, the count stops: a caller keeping no more than that many knows to walk.
  EXPECT_GT(symcr::device::detail::held_steps(schema, nullptr, 0, 3), 3u);

  fill(4);
  std::vector<std::uint8_t> record(symcr::device::record_size(schema));
  std::size_t size = 0;
  const symcr::device::Build schema_build{&schema, symcr::detail::schema_blob(schema).hash};
  ASSERT_EQ(symcr::device::save(schema_build, 1, record.data(), record.size(), &size), Result::Ok);
  const std::vector<std::uint8_t> payload(record.begin() + 56, record.begin() + size);
  const symcr::device::detail::PayloadShape walked = symcr::device::detail::payload_shape(schema);
  symcr::device::detail::PayloadShape stepped = walked;
  stepped.steps = steps.data();
  stepped.step_count = steps.size();
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(schema));
  const auto restore_as = [&](const std::vector<std::uint8_t>& bytes,
                              const symcr::device::detail::PayloadShape& shape,
                              std::vector<std::uint8_t>& state) {
    scramble();
    const Result result = symcr::device::detail::restore_held_payload(
        schema, bytes.data(), bytes.size(), scratch.data(), scratch.size(), &shape);
    state = snapshot();
    return result;
  };
  std::vector<std::uint8_t> by_walk, by_steps;
  ASSERT_EQ(restore_as(payload, stepped, by_steps), Result::Ok);
  expect_filled(4);
  int refused = 0;
  for (std::size_t at = 0; at < payload.size(); ++at) {
    for (const std::uint8_t value : {0x00, 0x01, 0x80, 0xFF}) {
      std::vector<std::uint8_t> damaged = payload;
      damaged[at] = value;
      const Result walk_result = restore_as(damaged, walked, by_walk);
      EXPECT_EQ(restore_as(damaged, stepped, by_steps), walk_result) << at << " " << int{value};
      EXPECT_TRUE(by_steps == by_walk) << at << " " << int{value};
      refused += walk_result != Result::Ok;
    }
  }
  EXPECT_GT(refused, 20);  // bools, bit-fields, ranges and references among them
}

TEST(DeviceProfile, ResultsHaveTexts) {
  EXPECT_STREQ(symcr::device::result_text(Result::Ok), "ok");
  EXPECT_STREQ(symcr::device::result_text(Result::OtherSchema), "record of another build's schema");
  EXPECT_STREQ(symcr::device::result_text(Result::Empty), "no checkpoint saved yet");
  EXPECT_STREQ(symcr::device::result_text(Result::SequenceExhausted), "sequence numbers used up");
  // The texts are one string in Result's order: each result has its own, none runs into the next.
  const struct {
    Result result;
    const char* text;
  } kAll[] = {{Result::NoSpace, "buffer too small"},
              {Result::Unsupported, "a type the device profile cannot hold"},
              {Result::Truncated, "record truncated"},
              {Result::Corrupt, "record corrupt"},
              {Result::FutureVersion, "record from a newer format"},
              {Result::OtherProgram, "record of another program"},
              {Result::Rejected, "a value refused by its range or validator"},
              {Result::TooManyPointers, "more pointer targets than kMaxReferences"}};
  for (const auto& expected : kAll) {
    EXPECT_STREQ(symcr::device::result_text(expected.result), expected.text);
  }
  EXPECT_STREQ(symcr::device::result_text(static_cast<Result>(200)), "?");
}

}  // namespace
}  // namespace device_tests
