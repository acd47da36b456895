// Times of clocks (docs/resolution.md, "Clocks"): a restore in the process that wrote the
// checkpoint moves no time; the device profile, which restores only after a reset, moves every
// time by its clock's advance in the member's own arithmetic and keeps the never value; the
// host's and the device's payloads end with the same clock readings.
#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "device_format.hpp"
#include "record.hpp"
#include "schema_blob.hpp"
#include "schema_tables.hpp"
#include "symcr/device.hpp"
#include "symcr/symcr.hpp"

namespace {

using namespace schema_tables;

std::uint32_t g_millis = 0;
std::int64_t read_millis() { return g_millis; }

struct Timers {
  std::uint32_t last_ms;
  std::uint32_t never_ms;       // 0: "no time yet"
  std::int16_t short_ms;        // a 16-bit time wraps at 2^16
  std::uint32_t duration_ms;    // not a time
  std::uint32_t seen_ms[2];
};
Timers timers;

const symcr::ClockInfo kClock{"millis", read_millis, 0};
const symcr::FieldTime kTime{&kClock, 0};
const TypeInfo kTypes[] = {
    scalar("uint32", Kind::UInt, 4),
    scalar("int16", Kind::Int, 2),
    array("uint32[2]", 0, 2, 8, 4),
    record("Timers", sizeof(Timers), alignof(Timers), nullptr, 0),
};
const FieldInfo kFields[] = {timed("last_ms", 0, offsetof(Timers, last_ms), kTime),
                             timed("never_ms", 0, offsetof(Timers, never_ms), kTime),
                             timed("short_ms", 1, offsetof(Timers, short_ms), kTime),
                             field("duration_ms", 0, offsetof(Timers, duration_ms)),
                             timed("seen_ms", 2, offsetof(Timers, seen_ms), kTime)};
const TypeInfo* types() {
  static TypeInfo table[4] = {kTypes[0], kTypes[1], kTypes[2], kTypes[3]};
  table[3].fields = kFields;
  table[3].field_count = 5;
  return table;
}
const symcr::Schema& schema() {
  static const symcr::RootInfo roots[] = {{"timers", 3, &timers, 0, nullptr}};
  static const symcr::Schema s{types(), 4, roots, 1, nullptr};
  return s;
}

void set_timers() {
  timers = Timers{4800, 0, 30000, 1500, {4999, 0}};
}

TEST(Clocks, ARestoreInTheWritingProcessMovesNoTime) {
  g_millis = 5000;
  set_timers();
  std::vector<std::uint8_t> record;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(schema(), record).ok());
  g_millis = 9000;
  timers = Timers{};
  const symcr::Report report = symcr::restore_from_buffer(schema(), record.data(), record.size());
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(timers.last_ms, 4800u);
  EXPECT_EQ(timers.short_ms, 30000);
  EXPECT_EQ(timers.seen_ms[0], 4999u);
  EXPECT_EQ(report.count(symcr::Decision::Rebased), 0u) << report.to_text();
}

TEST(Clocks, TheHostsPayloadEndsWithTheEpochAndEachReading) {
  g_millis = 5000;
  set_timers();
  std::vector<std::uint8_t> record;
  ASSERT_TRUE(symcr::checkpoint_to_buffer(schema(), record).ok());
  ASSERT_GE(record.size(), 16u);
  std::uint64_t epoch = 0;
  std::int64_t reading = 0;
  std::memcpy(&epoch, record.data() + record.size() - 16, 8);
  std::memcpy(&reading, record.data() + record.size() - 8, 8);
  EXPECT_NE(epoch, 0u);
  EXPECT_EQ(reading, 5000);
}

TEST(Clocks, TheDeviceMovesEveryTimeByItsClocksAdvanceAndKeepsNever) {
  const symcr::device::Build build{&schema(), symcr::detail::schema_blob(schema()).hash};
  g_millis = 5000;
  set_timers();
  std::vector<std::uint8_t> record(symcr::device::record_size(schema()));
  std::size_t size = 0;
  ASSERT_EQ(symcr::device::save(build, 1, record.data(), record.size(), &size),
            symcr::device::Result::Ok);
  g_millis = 10;  // a restart: the clock began again
  timers = Timers{};
  std::vector<std::uint8_t> scratch(symcr::device::scratch_size(schema()));
  ASSERT_EQ(symcr::device::restore(build, record.data(), size, scratch.data(), scratch.size()),
            symcr::device::Result::Ok);
  EXPECT_EQ(timers.last_ms, 4800u - 4990u);  // wraps as uint32 arithmetic does
  EXPECT_EQ(g_millis - timers.last_ms, 200u);
  EXPECT_EQ(timers.never_ms, 0u);
  EXPECT_EQ(timers.short_ms, static_cast<std::int16_t>(30000 - 4990));
  EXPECT_EQ(timers.duration_ms, 1500u);
  EXPECT_EQ(timers.seen_ms[0], 4999u - 4990u);
  EXPECT_EQ(timers.seen_ms[1], 0u);
}

TEST(Clocks, TheHostMovesTheTimesOfADeviceCheckpoint) {
  // A device writes epoch 0 (no process to tell apart): any host restore moves its times.
  const symcr::device::Build build{&schema(), symcr::detail::schema_blob(schema()).hash};
  g_millis = 5000;
  set_timers();
  std::vector<std::uint8_t> record(symcr::device::record_size(schema()));
  std::size_t size = 0;
  ASSERT_EQ(symcr::device::save(build, 1, record.data(), record.size(), &size),
            symcr::device::Result::Ok);
  g_millis = 6000;
  timers = Timers{};
  symcr::detail::RecordView view;
  ASSERT_TRUE(symcr::detail::parse_record(record.data(), size, view, nullptr).ok());
  const symcr::Report report =
      symcr::detail::restore_record(view, schema(), symcr::detail::schema_blob(schema()).hash,
                                    schema(), symcr::RestoreOptions{});
  ASSERT_TRUE(report.ok()) << report.status().message();
  EXPECT_EQ(timers.last_ms, 5800u);
  EXPECT_EQ(timers.never_ms, 0u);
  EXPECT_EQ(timers.seen_ms[0], 5999u);
  EXPECT_EQ(timers.duration_ms, 1500u);
  EXPECT_EQ(report.count(symcr::Decision::Rebased), 5u) << report.to_text();  // 4 fields, 1 clock
}

TEST(Clocks, RebaseTimeWrapsInTheIntegersWidthAndSkipsNever) {
  std::uint8_t bytes[8] = {0xFF, 0xFF, 0, 0, 0, 0, 0, 0};
  symcr::format::rebase_time(bytes, 2, 0, 1);  // 0xFFFF + 1 wraps to 0 in 16 bits
  EXPECT_EQ(bytes[0], 0);
  EXPECT_EQ(bytes[1], 0);
  EXPECT_EQ(bytes[2], 0);
  std::uint32_t never = 0xFFFFFFFFu;
  symcr::format::rebase_time(reinterpret_cast<std::uint8_t*>(&never), 4, -1, 5);
  EXPECT_EQ(never, 0xFFFFFFFFu);  // -1 is 0xFFFFFFFF in 32 bits
}

}  // namespace
