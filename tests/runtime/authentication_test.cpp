// Authenticated checkpoints: with keys set, checkpoints carry an HMAC-SHA-256 naming their key,
// and a restore refuses one that lacks a MAC, names a key the program does not hold, or was
// changed after it was written (even with its CRC made good again), leaving the state untouched.
// A store passes over such a slot to an older authentic one. Keys rotate by id.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "authentication.hpp"
#include "crc32c.hpp"
#include "file_test_schemas.hpp"
#include "file_test_util.hpp"
#include "record.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/symcr.hpp"

namespace {

using namespace file_tests;

const std::vector<std::uint8_t> kOldKey(32, 0x11);
const std::vector<std::uint8_t> kNewKey = {'r', 'o', 't', 'a', 't', 'e', 'd'};

class AuthenticationTest : public ::testing::Test {
 protected:
  void TearDown() override { EXPECT_TRUE(symcr::set_checkpoint_keys(nullptr, 0).ok()); }

  static void use_keys(std::vector<symcr::CheckpointKey> keys) {
    const symcr::Status status = symcr::set_checkpoint_keys(keys.data(), keys.size());
    ASSERT_TRUE(status.ok()) << status.message();
  }
  static symcr::CheckpointKey old_key() { return {1, kOldKey.data(), kOldKey.size()}; }
  static symcr::CheckpointKey new_key() { return {2, kNewKey.data(), kNewKey.size()}; }

  // A checkpoint of seed `seed`, written with the keys in force.
  static std::vector<std::uint8_t> checkpoint(int seed) {
    fill_a(seed);
    std::vector<std::uint8_t> bytes;
    const symcr::Status status = symcr::checkpoint_to_buffer(schema_a, bytes);
    EXPECT_TRUE(status.ok()) << status.message();
    return bytes;
  }
  static symcr::Report restore(const std::vector<std::uint8_t>& bytes) {
    return symcr::restore_from_buffer(schema_a, bytes.data(), bytes.size());
  }
  // The CRC made good again after a change: what an attacker who can write the file does.
  static void reseal(std::vector<std::uint8_t>& bytes) {
    symcr::format::store32(bytes.data() + symcr::format::kRecordChecksumOffset, 0);
    symcr::format::store32(bytes.data() + symcr::format::kRecordChecksumOffset,
                           symcr::detail::crc32c(bytes.data(), bytes.size()));
  }
  static void expect_refused(const symcr::Report& report, const char* why) {
    EXPECT_EQ(report.status().error(), symcr::Error::Unauthenticated);
    EXPECT_NE(std::string(report.status().message()).find(why), std::string::npos)
        << report.status().message();
    EXPECT_EQ(copter_a.ticks, -1);  // scrambled, and still so: nothing was written
    EXPECT_EQ(telemetry_a.frames, 0xFFFFFFFFu);
  }
};

TEST_F(AuthenticationTest, AnAuthenticatedCheckpointNamesItsKeyAndRestores) {
  use_keys({old_key()});
  const std::vector<std::uint8_t> bytes = checkpoint(3);
  EXPECT_EQ(symcr::format::load16(bytes.data() + 10),
            112u);  // header with key id, MAC version and MAC
  EXPECT_EQ(symcr::format::load32(bytes.data() + 60), symcr::format::kRecordMacVersion);
  EXPECT_EQ(symcr::format::load32(bytes.data() + 12) & 2u, 2u);
  EXPECT_EQ(symcr::format::load32(bytes.data() + 56), 1u);
  scramble_a();
  const symcr::Report report = restore(bytes);
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(copter_a.ticks, 1003);
}

TEST_F(AuthenticationTest, AChangeWithTheCrcMadeGoodIsRefused) {
  use_keys({old_key()});
  std::vector<std::uint8_t> bytes = checkpoint(3);
  const std::size_t payload = 112 + symcr::format::load32(bytes.data() + 40);
  bytes[payload] ^= 0x40;  // copter.ticks
  reseal(bytes);
  scramble_a();
  expect_refused(restore(bytes), "MAC does not verify with key id 1");
}

TEST_F(AuthenticationTest, AnotherKeyIdTheProgramDoesNotHoldIsRefused) {
  use_keys({new_key()});
  const std::vector<std::uint8_t> bytes = checkpoint(3);
  use_keys({old_key()});
  scramble_a();
  expect_refused(restore(bytes), "key id 2, which this program does not hold");
}

TEST_F(AuthenticationTest, ACheckpointWithoutAMacIsRefusedWhenKeysAreSet) {
  const std::vector<std::uint8_t> bytes = checkpoint(3);  // no keys: no MAC
  EXPECT_EQ(symcr::format::load16(bytes.data() + 10), 56u);
  use_keys({old_key()});
  scramble_a();
  expect_refused(restore(bytes), "carries no MAC");
}

TEST_F(AuthenticationTest, TheSameIdWithAnotherKeyDoesNotVerify) {
  use_keys({old_key()});
  const std::vector<std::uint8_t> bytes = checkpoint(3);
  const std::vector<std::uint8_t> guessed(32, 0x12);
  use_keys({{1, guessed.data(), guessed.size()}});
  scramble_a();
  expect_refused(restore(bytes), "MAC does not verify");
}

TEST_F(AuthenticationTest, RotatedKeysStillVerifyTheOldKeysCheckpoints) {
  use_keys({old_key()});
  const std::vector<std::uint8_t> before = checkpoint(3);
  use_keys({new_key(), old_key()});  // the new key signs, the old one still verifies
  const std::vector<std::uint8_t> after = checkpoint(4);
  EXPECT_EQ(symcr::format::load32(after.data() + 56), 2u);
  scramble_a();
  symcr::Report report = restore(before);
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(copter_a.ticks, 1003);
  report = restore(after);
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(copter_a.ticks, 1004);
}

TEST_F(AuthenticationTest, WithoutKeysAnAuthenticatedCheckpointRestoresUnverified) {
  use_keys({old_key()});
  const std::vector<std::uint8_t> bytes = checkpoint(5);
  ASSERT_TRUE(symcr::set_checkpoint_keys(nullptr, 0).ok());
  scramble_a();
  const symcr::Report report = restore(bytes);
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(copter_a.ticks, 1005);
}

TEST_F(AuthenticationTest, KeysMustBeNonEmptyAndTheirIdsDistinct) {
  const std::vector<std::uint8_t> empty;
  const symcr::CheckpointKey no_bytes{7, empty.data(), 0};
  EXPECT_FALSE(symcr::set_checkpoint_keys(&no_bytes, 1).ok());
  const symcr::CheckpointKey twice[] = {old_key(), {1, kNewKey.data(), kNewKey.size()}};
  const symcr::Status status = symcr::set_checkpoint_keys(twice, 2);
  EXPECT_FALSE(status.ok());
  EXPECT_NE(std::string(status.message()).find("two checkpoint keys have id 1"), std::string::npos);
}

// The newest slot changed: the store does not fall back to an older authentic slot (that would
// be a rollback an attacker chooses), it refuses, because the freshness counter says a newer
// one was saved.
TEST_F(AuthenticationTest, AStoreWhoseNewestSlotWasTamperedWithRestoresNothing) {
  TempDir dir;
  const std::string path = dir.file("auth.store");
  use_keys({old_key()});
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, symcr::StoreOptions{}, store).ok());
    for (int seed = 1; seed <= 3; ++seed) {
      fill_a(seed);
      ASSERT_TRUE(store.save().ok());
    }
  }
  // The newest slot (sequence 3) changed and resealed, as by someone who can write the file.
  std::vector<std::uint8_t> bytes = read_file(path);
  const std::uint64_t slots = symcr::format::load64(bytes.data() + 24);
  const std::uint32_t slot_size = symcr::format::load32(bytes.data() + 16);
  bool tampered = false;
  for (std::uint32_t i = 0; i < 4 && !tampered; ++i) {
    std::uint8_t* slot = bytes.data() + slots + std::uint64_t{i} * slot_size;
    if (std::memcmp(slot, "SYMCRCKP", 8) != 0 || symcr::format::load64(slot + 16) != 3) continue;
    const std::size_t size =
        112 + symcr::format::load32(slot + 40) + symcr::format::load32(slot + 44);
    slot[112] ^= 0x40;
    symcr::format::store32(slot + 48, 0);
    symcr::format::store32(slot + 48, symcr::detail::crc32c(slot, size));
    tampered = true;
  }
  ASSERT_TRUE(tampered);
  write_file(path, bytes);

  symcr::Store store;
  ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, symcr::StoreOptions{}, store).ok());
  scramble_a();
  symcr::Report report = store.restore_latest();
  EXPECT_EQ(report.status().error(), symcr::Error::RolledBack) << report.status().message();
  EXPECT_NE(std::string(report.status().message()).find("newest authenticated checkpoint is "
                                                        "sequence 2"),
            std::string::npos)
      << report.status().message();
  EXPECT_EQ(copter_a.ticks, -1);

  // Under another key nothing in the store is authentic: nothing restored, the state untouched.
  const std::vector<std::uint8_t> other(16, 0x99);
  use_keys({{1, other.data(), other.size()}});
  scramble_a();
  report = store.restore_latest();
  EXPECT_EQ(report.status().error(), symcr::Error::NoValidSlot);
  EXPECT_NE(std::string(report.status().message()).find("3 unauthenticated"), std::string::npos)
      << report.status().message();
  EXPECT_EQ(copter_a.ticks, -1);
}

// Keys set after a store was opened apply to its next restore: its slots are checked again.
TEST_F(AuthenticationTest, KeysSetAfterOpeningAStoreApplyToItsFirstRestore) {
  TempDir dir;
  const std::string path = dir.file("late-keys.store");
  symcr::Store store;
  ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, symcr::StoreOptions{}, store).ok());
  fill_a(4);
  ASSERT_TRUE(store.save().ok());  // without keys: no MAC
  store.close();
  ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, symcr::StoreOptions{}, store).ok());
  use_keys({old_key()});
  scramble_a();
  const symcr::Report report = store.restore_latest();
  EXPECT_EQ(report.status().error(), symcr::Error::NoValidSlot);
  EXPECT_NE(std::string(report.status().message()).find("1 unauthenticated"), std::string::npos)
      << report.status().message();
  EXPECT_EQ(copter_a.ticks, -1);
}

// A schema's digest is what a record's MAC binds; only keys make a store compute one. Without
// keys, opening a store (this build's, or another build's: a schema area parsed) and restoring
// from it hash no schema.
TEST_F(AuthenticationTest, AStoreUsedWithoutKeysHashesNoSchema) {
  TempDir dir;
  const std::string path = dir.file("no-keys.store");
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, symcr::StoreOptions{}, store).ok());
    fill_a(5);
    ASSERT_TRUE(store.save().ok());
  }
  const std::uint64_t before = symcr::detail::schema_digest_count();
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, symcr::StoreOptions{}, store).ok());
    scramble_a();
    const symcr::Report report = store.restore_latest();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_EQ(copter_a.ticks, 1005);
  }
  {
    symcr::Store store;  // another build: the area of build A's schema is parsed
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_b, symcr::StoreOptions{}, store).ok());
    copter_b = CopterB{};
    const symcr::Report report = store.restore_latest();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_EQ(copter_b.ticks, 1005);
  }
  EXPECT_EQ(symcr::detail::schema_digest_count(), before);
}

// The digests computed when first needed bind what they did when open computed them: a save
// signed under keys set after the open verifies when reopened, by this build and by another
// (whose schema area holds build A's schema), and a slot moved elsewhere does not.
TEST_F(AuthenticationTest, KeysSetAfterOpeningAStoreSignItsSavesForEveryBuild) {
  TempDir dir;
  const std::string path = dir.file("late-keys-save.store");
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, symcr::StoreOptions{}, store).ok());
    use_keys({old_key()});
    fill_a(6);
    ASSERT_TRUE(store.save().ok());
    fill_a(7);
    ASSERT_TRUE(store.save().ok());
  }
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_a, symcr::StoreOptions{}, store).ok());
    scramble_a();
    const symcr::Report report = store.restore_latest();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_EQ(report.sequence(), 2u);
    EXPECT_EQ(copter_a.ticks, 1007);
  }
  {
    symcr::Store store;
    ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_b, symcr::StoreOptions{}, store).ok());
    copter_b = CopterB{};
    const symcr::Report report = store.restore_latest();
    ASSERT_TRUE(report.ok()) << report.status().message();
    EXPECT_EQ(report.sequence(), 2u);
    EXPECT_EQ(copter_b.ticks, 1007);
  }
  // The newest record moved into the older one's slot (its CRC intact), its own slot cleared:
  // bound to the slot it was written to, it does not verify where it lies now, and the
  // freshness counter knows a checkpoint numbered 2 was written.
  std::vector<std::uint8_t> bytes = read_file(path);
  const std::uint64_t slots = symcr::format::load64(bytes.data() + 24);
  const std::uint32_t slot_size = symcr::format::load32(bytes.data() + 16);
  int newest = -1, older = -1;
  for (std::uint32_t i = 0; i < 4; ++i) {
    const std::uint8_t* slot = bytes.data() + slots + std::uint64_t{i} * slot_size;
    if (std::memcmp(slot, "SYMCRCKP", 8) != 0) continue;
    (symcr::format::load64(slot + 16) == 2 ? newest : older) = static_cast<int>(i);
  }
  ASSERT_GE(newest, 0);
  ASSERT_GE(older, 0);
  std::memcpy(bytes.data() + slots + std::uint64_t(older) * slot_size,
              bytes.data() + slots + std::uint64_t(newest) * slot_size, slot_size);
  std::memset(bytes.data() + slots + std::uint64_t(newest) * slot_size, 0, slot_size);
  write_file(path, bytes);
  symcr::Store store;
  ASSERT_TRUE(symcr::Store::open(path.c_str(), schema_b, symcr::StoreOptions{}, store).ok());
  copter_b = CopterB{};
  const symcr::Report report = store.restore_latest();
  EXPECT_EQ(report.status().error(), symcr::Error::RolledBack) << report.status().message();
  EXPECT_NE(std::string(report.status().message())
                .find("newest authenticated checkpoint is sequence 0"),
            std::string::npos)
      << report.status().message();
  EXPECT_EQ(copter_b.ticks, 0);
}

}  // namespace
