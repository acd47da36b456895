// The specimen-sized critical state (critical_state.hpp) beside the two serialisation libraries
// a C++ user would otherwise reach for, cereal's and Boost.Serialization's binary archives, with
// hand-written serialize functions for the same structs, save and load each (benchmarks/README.md:
// "faster than cereal's and Boost.Serialization's binary archives ... side by side in one
// run"); and restore across a schema change (V0 checkpoint into the V1 build), with the
// resolution plan cached and not cached.
//
// Both libraries serialise into / out of a preallocated memory buffer (a fixed streambuf), as
// checkpoint_to_buffer does, so the comparison is the serialisation itself, not I/O. Boost is
// given its fastest configuration (no archive header, no tracking, no class versions): that is
// what a performance-minded user would do, and a fair opponent.
//
// This translation unit needs exceptions and RTTI (both libraries use them); the runtime itself
// is still built with -fno-exceptions -fno-rtti. Linked with runtime_latency.cpp into
// symcr_bench_latency.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <istream>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

// Without cereal or Boost (CMake found them missing: SYMCR_BENCH_NO_SERIALIZERS) the program
// still builds and measures everything else; benchmarks/run installs both.
#if !defined(SYMCR_BENCH_NO_SERIALIZERS)
#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/level.hpp>
#include <boost/serialization/tracking.hpp>
#include <cereal/archives/binary.hpp>
#include <cereal/types/common.hpp>
#endif

#include "critical_state.hpp"
#include "symcr/symcr.hpp"

#if !defined(SYMCR_BENCH_NO_SERIALIZERS)
// ---- hand-written serialize functions -----------------------------------------------------------
// cereal: found by ADL in the types' namespace.
namespace critical {

// cereal: serialize(archive, value)
template <class A> void serialize(A& ar, Vec3& v) { ar(v.x, v.y, v.z); }
template <class A> void serialize(A& ar, Ahrs& a) {
  ar(a.position, a.velocity, a.euler, a.gyro_bias, a.quaternion);
}
template <class A> void serialize(A& ar, Waypoint& w) {
  ar(w.lat, w.lon, w.alt, w.command, w.flags);
}
template <class A> void serialize(A& ar, Mission& m) { ar(m.items, m.current, m.count, m.state); }
template <class A> void serialize(A& ar, Copter& c) {
  ar(c.mode, c.armed, c.ticks, c.throttle, c.pid_gains, c.failsafe_flags, c.home_lat,
     c.home_lon, c.armed_ms, c.battery_mah, c.battery_volts);
}
template <class A> void serialize(A& ar, Telemetry& t) {
  ar(t.frames, t.drops, t.rssi, t.link_quality, t.rates, t.sequence, t.system_id,
     t.component_id);
}

}  // namespace critical

// Boost: serialize(archive, value, version), where Boost looks (and cereal, which would also
// accept a versioned serialize, does not).
namespace boost::serialization {
using namespace critical;
template <class A> void serialize(A& ar, Vec3& v, unsigned) { ar & v.x & v.y & v.z; }
template <class A> void serialize(A& ar, Ahrs& a, unsigned) {
  ar & a.position & a.velocity & a.euler & a.gyro_bias & a.quaternion;
}
template <class A> void serialize(A& ar, Waypoint& w, unsigned) {
  ar & w.lat & w.lon & w.alt & w.command & w.flags;
}
template <class A> void serialize(A& ar, Mission& m, unsigned) {
  ar & m.items & m.current & m.count & m.state;
}
template <class A> void serialize(A& ar, Copter& c, unsigned) {
  ar & c.mode & c.armed & c.ticks & c.throttle & c.pid_gains & c.failsafe_flags & c.home_lat &
      c.home_lon & c.armed_ms & c.battery_mah & c.battery_volts;
}
template <class A> void serialize(A& ar, Telemetry& t, unsigned) {
  ar & t.frames & t.drops & t.rssi & t.link_quality & t.rates & t.sequence & t.system_id &
      t.component_id;
}

}  // namespace boost::serialization

// Boost's fastest setting for plain structs: no class information, no object tracking.
#define CRITICAL_BOOST_PLAIN(T)                                                   \
  BOOST_CLASS_IMPLEMENTATION(critical::T, boost::serialization::object_serializable) \
  BOOST_CLASS_TRACKING(critical::T, boost::serialization::track_never)
CRITICAL_BOOST_PLAIN(Vec3)
CRITICAL_BOOST_PLAIN(Ahrs)
CRITICAL_BOOST_PLAIN(Waypoint)
CRITICAL_BOOST_PLAIN(Mission)
CRITICAL_BOOST_PLAIN(Copter)
CRITICAL_BOOST_PLAIN(Telemetry)
#endif  // !SYMCR_BENCH_NO_SERIALIZERS

namespace {

using namespace critical;

void fail(benchmark::State& state, const char* what, const char* message) {
  const std::string text = std::string(what) + ": " + message;
  state.SkipWithError(text.c_str());
}

#if !defined(SYMCR_BENCH_NO_SERIALIZERS)
// A streambuf over a fixed buffer: the libraries write into and read from memory, no allocation.
class FixedBuffer : public std::streambuf {
 public:
  FixedBuffer() : bytes_(64 * 1024) {}
  void rewind_output() { setp(bytes_.data(), bytes_.data() + bytes_.size()); }
  void rewind_input(std::size_t size) { setg(bytes_.data(), bytes_.data(), bytes_.data() + size); }
  std::size_t written() const { return static_cast<std::size_t>(pptr() - pbase()); }

 private:
  std::vector<char> bytes_;
};

// ---- cereal ------------------------------------------------------------------------------------
void BM_CerealSave(benchmark::State& state) {
  fill_state(1);
  FixedBuffer buffer;
  std::ostream stream(&buffer);
  for (auto _ : state) {
    buffer.rewind_output();
    cereal::BinaryOutputArchive archive(stream);
    archive(copter, ahrs, mission, telemetry);
    benchmark::ClobberMemory();
  }
  state.counters["bytes"] = static_cast<double>(buffer.written());
}
BENCHMARK(BM_CerealSave);

void BM_CerealLoad(benchmark::State& state) {
  fill_state(1);
  FixedBuffer buffer;
  std::size_t size = 0;
  {
    std::ostream out(&buffer);
    buffer.rewind_output();
    cereal::BinaryOutputArchive archive(out);
    archive(copter, ahrs, mission, telemetry);
    size = buffer.written();
  }
  std::istream stream(&buffer);
  for (auto _ : state) {
    buffer.rewind_input(size);
    cereal::BinaryInputArchive archive(stream);
    archive(copter, ahrs, mission, telemetry);
    benchmark::ClobberMemory();
  }
  if (copter.ticks != 1 || mission.count != 8) fail(state, "cereal", "wrong values loaded");
  state.counters["bytes"] = static_cast<double>(size);
}
BENCHMARK(BM_CerealLoad);

// ---- Boost.Serialization ---------------------------------------------------------------------
constexpr unsigned kBoostFlags = boost::archive::no_header | boost::archive::no_codecvt;

std::size_t boost_size(unsigned flags) {
  FixedBuffer buffer;
  buffer.rewind_output();
  {
    boost::archive::binary_oarchive archive(buffer, flags);
    archive << copter << ahrs << mission << telemetry;
  }
  return buffer.written();
}

void BM_BoostSave(benchmark::State& state) {
  fill_state(1);
  FixedBuffer buffer;
  for (auto _ : state) {
    buffer.rewind_output();
    boost::archive::binary_oarchive archive(buffer, kBoostFlags);
    archive << copter << ahrs << mission << telemetry;
    benchmark::ClobberMemory();
  }
  state.counters["bytes"] = static_cast<double>(buffer.written());
  state.counters["bytes_with_header"] = static_cast<double>(boost_size(0));
}
BENCHMARK(BM_BoostSave);

void BM_BoostLoad(benchmark::State& state) {
  fill_state(1);
  FixedBuffer buffer;
  buffer.rewind_output();
  {
    boost::archive::binary_oarchive archive(buffer, kBoostFlags);
    archive << copter << ahrs << mission << telemetry;
  }
  const std::size_t size = buffer.written();
  for (auto _ : state) {
    buffer.rewind_input(size);
    boost::archive::binary_iarchive archive(buffer, kBoostFlags);
    archive >> copter >> ahrs >> mission >> telemetry;
    benchmark::ClobberMemory();
  }
  if (copter.ticks != 1 || mission.count != 8) fail(state, "boost", "wrong values loaded");
  state.counters["bytes"] = static_cast<double>(size);
}
BENCHMARK(BM_BoostLoad);
#endif  // !SYMCR_BENCH_NO_SERIALIZERS

// ---- restore across a schema change: a V0 checkpoint into the V1 build ------------------------
// Checks that the V0 -> V1 restore did what the rules say (so a broken resolution cannot pass
// for a fast one).
bool v1_restored() {
  return v1::copter.mode == v1::FlightMode::Auto && v1::copter.throttle_out == 1500 &&
         v1::copter.battery_volts > 15.3 && v1::ahrs.attitude.z == 1.57f &&
         v1::mission.items[7].lat == 422808000 + 7000 && v1::mission.items[7].alt == 37.0 &&
         v1::telemetry.rssi == -60;
}

std::vector<std::uint8_t> v0_checkpoint() {
  fill_state(1);
  std::vector<std::uint8_t> bytes;
  symcr::checkpoint_to_buffer(schema, bytes);
  return bytes;
}

// The resolution plan of (V0 schema, V1 schema) is built once and cached
// (runtime/src/plan/plan.hpp).
// Single-file form: the inline V0 schema is parsed on every restore, the plan is not rebuilt.
void BM_SchemaChangeRestoreCached(benchmark::State& state) {
  const std::vector<std::uint8_t> bytes = v0_checkpoint();
  std::size_t entries = 0;
  for (auto _ : state) {
    const symcr::Report report = symcr::restore_from_buffer(v1::schema, bytes.data(), bytes.size());
    if (!report.ok()) {
      fail(state, "restore_from_buffer", report.status().message());
      break;
    }
    entries = report.entries().size();
  }
  if (!v1_restored()) fail(state, "V0 -> V1", "wrong values restored");
  state.counters["bytes"] = static_cast<double>(bytes.size());
  state.counters["report_entries"] = static_cast<double>(entries);
}
BENCHMARK(BM_SchemaChangeRestoreCached);

// Live update: V0's roots moved into V1's in this process (symcr::transfer), plan prepared.
void BM_SchemaChangeTransfer(benchmark::State& state) {
  fill_state(1);
  const symcr::Status prepared = symcr::prepare_transfer(schema, v1::schema);
  if (!prepared.ok()) return fail(state, "prepare_transfer", prepared.message());
  for (auto _ : state) {
    const symcr::Report report = symcr::transfer(schema, v1::schema);
    if (!report.ok()) {
      fail(state, "transfer", report.status().message());
      break;
    }
  }
  if (!v1_restored()) fail(state, "V0 -> V1", "wrong values transferred");
}
BENCHMARK(BM_SchemaChangeTransfer);

// Not cached: the runtime keeps a few plans keyed by the reader Schema object, so restoring in
// turn into more distinct (identical) reader Schema objects than it keeps makes every restore
// build its plan from scratch — what the first restore after a patch costs, with no engine hook.
void BM_SchemaChangeRestoreUncached(benchmark::State& state) {
  const std::vector<std::uint8_t> bytes = v0_checkpoint();
  constexpr std::size_t kReaders = 32;  // well above the plan cache's capacity
  std::vector<symcr::Schema> readers(kReaders, v1::schema);
  for (const symcr::Schema& reader : readers) {  // warm everything but the plans
    symcr::restore_from_buffer(reader, bytes.data(), bytes.size());
  }
  std::size_t next = 0;
  for (auto _ : state) {
    const symcr::Report report =
        symcr::restore_from_buffer(readers[next], bytes.data(), bytes.size());
    next = (next + 1) % kReaders;
    if (!report.ok()) {
      fail(state, "restore_from_buffer", report.status().message());
      break;
    }
  }
  if (!v1_restored()) fail(state, "V0 -> V1", "wrong values restored");
  state.counters["bytes"] = static_cast<double>(bytes.size());
}
BENCHMARK(BM_SchemaChangeRestoreUncached);

// The store written by V0, opened by V1: restore_latest with the store's parsed schema and the
// cached plan — the periodic-checkpoint deployment after a patch.
void BM_SchemaChangeStoreRestoreLatest(benchmark::State& state) {
  const std::string path = scratch_path("store-v1");
  ::unlink(path.c_str());
  symcr::StoreOptions options;
  options.slot_size = 4096;
  {
    symcr::Store writer;
    symcr::Status status = symcr::Store::open(path.c_str(), schema, options, writer);
    if (!status.ok()) return fail(state, "open", status.message());
    fill_state(1);
    status = writer.save();
    if (!status.ok()) return fail(state, "save", status.message());
  }
  symcr::Store reader;
  symcr::Status status = symcr::Store::open(path.c_str(), v1::schema, options, reader);
  if (!status.ok()) return fail(state, "open v1", status.message());
  for (auto _ : state) {
    const symcr::Report report = reader.restore_latest();
    if (!report.ok()) {
      fail(state, "restore_latest", report.status().message());
      break;
    }
  }
  if (!v1_restored()) fail(state, "V0 -> V1", "wrong values restored");
  reader.close();
  ::unlink(path.c_str());
}
BENCHMARK(BM_SchemaChangeStoreRestoreLatest);

}  // namespace

BENCHMARK_MAIN();
