// A program including a broad slice of the standard library and C headers. Its roots reach
// only a handful of types; the generator must parse everything and walk only what they reach.
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <fstream>
#include <functional>
#include <iostream>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <numeric>
#include <optional>
#include <random>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <variant>
#include <vector>

#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <symcr/symcr.hpp>

struct Sample {
  double value;
  std::int64_t stamp_ns;
};

struct Telemetry {
  std::string station;
  std::vector<Sample> samples;
  std::map<std::string, std::uint32_t> counters;
  std::optional<double> calibration;
  std::mutex lock SYMCR_SKIP;                  // process state: not checkpointed
  std::function<void(const Sample&)> sink SYMCR_SKIP;
  std::thread worker SYMCR_SKIP;
  std::mt19937 rng SYMCR_SKIP;                 // re-seeded after restore
};

SYMCR_CHECKPOINT Telemetry telemetry;

int main(int argc, char** argv) {
  std::regex pattern("[a-z]+");
  telemetry.station = argc > 1 ? argv[1] : "home";
  if (std::regex_match(telemetry.station, pattern)) telemetry.counters["matches"] += 1;
  telemetry.samples.push_back({std::sqrt(2.0), static_cast<std::int64_t>(time(nullptr))});
  std::sort(telemetry.samples.begin(), telemetry.samples.end(),
            [](const Sample& a, const Sample& b) { return a.value < b.value; });
  printf("%zu samples\n", telemetry.samples.size());
  return 0;
}
