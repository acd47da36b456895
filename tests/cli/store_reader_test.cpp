// StoreReader (runtime/src/store_reader.hpp): a store's slots as restore_latest() sees them,
// read without a Schema and without the store's lock.
#include "store_reader.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include "fixture_tables.hpp"
#include "symcr/symcr.hpp"

namespace {

using symcr::detail::StoreReader;
using symcr::detail::StoreSlotState;

class StoreReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    path_ = std::string(::testing::TempDir()) + "symcr_cli_unit_" +
            std::to_string(::getpid()) + ".store";
    ::unlink(path_.c_str());
  }
  void TearDown() override { ::unlink(path_.c_str()); }

  // Four slots after `saves` saves; the Store stays open (and locked) while it is read.
  void save(symcr::Store& store, int saves) {
    symcr::StoreOptions options;
    options.slots = 4;
    options.slot_size = 4096;
    ASSERT_TRUE(symcr::Store::open(path_.c_str(), cli_fixture::schema(), options, store).ok());
    for (int seed = 1; seed <= saves; ++seed) {
      cli_fixture::fill_state(seed);
      ASSERT_TRUE(store.save().ok());
    }
  }

  void flip_byte(long offset) {
    std::FILE* file = std::fopen(path_.c_str(), "r+b");
    ASSERT_NE(file, nullptr);
    std::fseek(file, offset, SEEK_SET);
    const int byte = std::fgetc(file);
    std::fseek(file, offset, SEEK_SET);
    std::fputc(~byte & 0xFF, file);
    std::fclose(file);
  }

  std::string path_;
};

TEST_F(StoreReaderTest, ListsSlotsNewestFirstWhileTheStoreIsOpen) {
  symcr::Store store;
  save(store, 6);  // sequences by slot: 5, 6, 3, 4
  StoreReader reader;
  const symcr::Status status = reader.open(path_.c_str());
  ASSERT_TRUE(status.ok()) << status.message();
  EXPECT_EQ(reader.geometry().slot_count, 4u);
  EXPECT_TRUE(reader.area(0).valid);
  EXPECT_FALSE(reader.area(1).valid);
  EXPECT_EQ(reader.valid_slots_newest_first(), (std::vector<std::uint32_t>{1, 0, 3, 2}));
  EXPECT_EQ(reader.slots()[1].header.sequence, 6u);

  std::vector<std::uint8_t> bytes;
  symcr::detail::RecordView view;
  int area = -1;
  ASSERT_TRUE(reader.read_record(1, bytes, view, area).ok());
  EXPECT_EQ(area, 0);
  EXPECT_EQ(view.header.sequence, 6u);
  EXPECT_GT(view.payload_size, 0u);
}

TEST_F(StoreReaderTest, ClassifiesEmptyAndCorruptSlots) {
  {
    symcr::Store store;
    save(store, 2);
  }
  StoreReader before;
  ASSERT_TRUE(before.open(path_.c_str()).ok());
  const std::uint64_t slot1 = before.geometry().slots_offset + before.geometry().slot_size;
  flip_byte(static_cast<long>(slot1 + 60));

  StoreReader reader;
  ASSERT_TRUE(reader.open(path_.c_str()).ok());
  EXPECT_EQ(reader.slots()[0].state, StoreSlotState::Valid);
  EXPECT_EQ(reader.slots()[1].state, StoreSlotState::Corrupt);
  EXPECT_EQ(reader.slots()[1].problem.error(), symcr::Error::Checksum);
  EXPECT_EQ(reader.slots()[2].state, StoreSlotState::Empty);
  EXPECT_EQ(reader.valid_slots_newest_first(), (std::vector<std::uint32_t>{0}));
  std::vector<std::uint8_t> bytes;
  symcr::detail::RecordView view;
  int area = -1;
  EXPECT_EQ(reader.read_record(1, bytes, view, area).error(), symcr::Error::Checksum);
  EXPECT_EQ(reader.read_record(2, bytes, view, area).error(), symcr::Error::NoValidSlot);
  EXPECT_EQ(reader.read_record(9, bytes, view, area).error(), symcr::Error::Io);
}

TEST_F(StoreReaderTest, RefusesDamagedStoreFiles) {
  {
    symcr::Store store;
    save(store, 1);
  }
  ASSERT_EQ(::truncate(path_.c_str(), 8192), 0);
  StoreReader truncated;
  EXPECT_EQ(truncated.open(path_.c_str()).error(), symcr::Error::Truncated);

  flip_byte(14);  // slot_count, under the header CRC
  StoreReader bad_header;
  EXPECT_EQ(bad_header.open(path_.c_str()).error(), symcr::Error::Checksum);

  flip_byte(0);
  StoreReader not_a_store;
  EXPECT_EQ(not_a_store.open(path_.c_str()).error(), symcr::Error::NotACheckpoint);
}

}  // namespace
