// The specimen's critical state through cereal's and Boost.Serialization's binary archives,
// with the hand-written serialize functions of serializers.hpp: save and load each, to and
// from a preallocated memory buffer (as checkpoint_to_buffer does), so the comparison is the
// serialisation itself, not I/O. Boost in its fastest configuration: no archive header, no
// tracking, no class information. Same method as critical_compare.cpp for the stand-in.
//
// This translation unit needs exceptions and RTTI (both libraries use them); the runtime is
// still built with -fno-exceptions -fno-rtti.
#include <cstddef>
#include <istream>
#include <ostream>
#include <streambuf>
#include <vector>

#include <benchmark/benchmark.h>

#include "serializers.hpp"
#include "initial_state.hpp"
#include "state.hpp"

namespace specimen_bench {
namespace {

// A streambuf over a fixed buffer: the libraries write into and read from memory.
class FixedBuffer : public std::streambuf {
 public:
  FixedBuffer() : bytes_(64 * 1024) {}
  void rewind_output() { setp(bytes_.data(), bytes_.data() + bytes_.size()); }
  void rewind_input(std::size_t size) { setg(bytes_.data(), bytes_.data(), bytes_.data() + size); }
  std::size_t written() const { return static_cast<std::size_t>(pptr() - pbase()); }

 private:
  std::vector<char> bytes_;
};

constexpr unsigned kBoostFlags = boost::archive::no_header | boost::archive::no_codecvt;

std::size_t cereal_save_once(FixedBuffer& buffer) {
  std::ostream stream(&buffer);
  buffer.rewind_output();
  cereal::BinaryOutputArchive archive(stream);
  archive(copter);
  return buffer.written();
}

std::size_t boost_save_once(FixedBuffer& buffer, unsigned flags) {
  buffer.rewind_output();
  {
    boost::archive::binary_oarchive archive(buffer, flags);
    archive << copter;
  }
  return buffer.written();
}

// ---- cereal ------------------------------------------------------------------------------------
void BM_CerealSave(benchmark::State& state) {
  reset_to_flight_state();
  FixedBuffer buffer;
  std::ostream stream(&buffer);
  for (auto _ : state) {
    buffer.rewind_output();
    cereal::BinaryOutputArchive archive(stream);
    archive(copter);
    benchmark::ClobberMemory();
  }
  state.counters["bytes"] = static_cast<double>(buffer.written());
}
BENCHMARK(BM_CerealSave)->Apply(measured_iterations);

void BM_CerealLoad(benchmark::State& state) {
  reset_to_flight_state();
  FixedBuffer buffer;
  const std::size_t size = cereal_save_once(buffer);
  reset_copter();  // the loads must bring every value back
  std::istream stream(&buffer);
  for (auto _ : state) {
    buffer.rewind_input(size);
    cereal::BinaryInputArchive archive(stream);
    archive(copter);
    benchmark::ClobberMemory();
  }
  if (!matches_flight_state()) fail(state, "cereal", "the loaded state differs");
  state.counters["bytes"] = static_cast<double>(size);
}
BENCHMARK(BM_CerealLoad)->Apply(measured_iterations);

// ---- Boost.Serialization ---------------------------------------------------------------------
void BM_BoostSave(benchmark::State& state) {
  reset_to_flight_state();
  FixedBuffer buffer;
  for (auto _ : state) {
    buffer.rewind_output();
    boost::archive::binary_oarchive archive(buffer, kBoostFlags);
    archive << copter;
    benchmark::ClobberMemory();
  }
  state.counters["bytes"] = static_cast<double>(buffer.written());
  FixedBuffer with_header;
  state.counters["bytes_with_header"] = static_cast<double>(boost_save_once(with_header, 0));
}
BENCHMARK(BM_BoostSave)->Apply(measured_iterations);

void BM_BoostLoad(benchmark::State& state) {
  reset_to_flight_state();
  FixedBuffer buffer;
  const std::size_t size = boost_save_once(buffer, kBoostFlags);
  reset_copter();
  for (auto _ : state) {
    buffer.rewind_input(size);
    boost::archive::binary_iarchive archive(buffer, kBoostFlags);
    archive >> copter;
    benchmark::ClobberMemory();
  }
  if (!matches_flight_state()) fail(state, "boost", "the loaded state differs");
  state.counters["bytes"] = static_cast<double>(size);
}
BENCHMARK(BM_BoostLoad)->Apply(measured_iterations);

}  // namespace
}  // namespace specimen_bench
