#include "state.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include <benchmark/benchmark.h>

#include "flight.hpp"
#include "symcr/symcr.hpp"

#ifndef SPECIMEN_BENCH_MISSION
#error "SPECIMEN_BENCH_MISSION (the mission file to fly) must be defined by the build"
#endif

namespace specimen_bench {
namespace {

// The mission item the copter is flying towards when the state is taken: mid-route, with the
// whole command list loaded and the take-off behind it.
constexpr int kUntilItem = 8;

std::vector<std::uint8_t>& checkpoint_bytes() {
  static std::vector<std::uint8_t> bytes;
  return bytes;
}

std::string& description() {
  static std::string text;
  return text;
}

void fly_once() {
  std::vector<std::uint8_t>& bytes = checkpoint_bytes();
  if (!bytes.empty()) return;
  const char* mission = std::getenv("SPECIMEN_BENCH_MISSION");
  const std::string file = mission && *mission ? mission : SPECIMEN_BENCH_MISSION;
  const FlightResult flight = fly(file, kUntilItem);
  if (!flight.ok) die("flight", flight.error);
  const std::size_t slash = file.find_last_of('/');
  char text[256];
  std::snprintf(text, sizeof text, "%s: %.1f s simulated, heading for item %d of %d commands",
                file.c_str() + (slash == std::string::npos ? 0 : slash + 1), flight.seconds,
                flight.current_item, flight.mission_items);
  description() = text;
  const symcr::Status status = symcr::checkpoint_to_buffer(program_schema(), bytes);
  if (!status.ok()) die("checkpoint_to_buffer", status.message());
}

}  // namespace

void reset_to_flight_state() {
  fly_once();
  const std::vector<std::uint8_t>& bytes = checkpoint_bytes();
  const symcr::Report report = symcr::restore_from_buffer(program_schema(), bytes.data(),
                                                          bytes.size());
  if (!report.ok()) die("restore_from_buffer", report.status().message());
}

const std::string& flight_description() {
  fly_once();
  return description();
}

const std::vector<std::uint8_t>& flight_checkpoint() {
  fly_once();
  return checkpoint_bytes();
}

bool matches_flight_state() {
  const std::vector<std::uint8_t>& expected = flight_checkpoint();
  std::vector<std::uint8_t> now;
  if (!symcr::checkpoint_to_buffer(program_schema(), now).ok()) return false;
  // The payloads end the records (whatever their headers: an authenticated one is longer).
  const std::size_t payload = payload_size(now);
  return payload == payload_size(expected) && payload <= now.size() &&
         payload <= expected.size() &&
         std::memcmp(now.data() + now.size() - payload,
                     expected.data() + expected.size() - payload, payload) == 0;
}

std::size_t store_record_bytes() {
  const std::vector<std::uint8_t>& record = flight_checkpoint();
  return record.size() - schema_size(record);
}

}  // namespace specimen_bench
