// The live autopilot (method symcr-live): a host process that flies one vehicle module
// (vehicle_module.hpp) and, on the world's SIM_UPDATE, switches to the patched build's module
// without stopping: a thread loads the new module and prepares the transfer while the old one
// keeps flying; at the next loop boundary (the quiescent point: no vehicle code runs between
// two loops) symcr::transfer moves the state, the links are handed over, the new module
// resumes and flies that loop. A refused transfer leaves the old module flying, untouched.
//
//   copter_live --sim-fd N --gcs-fd N --module V0.so --update-module Vk.so [--strict 1]
//
// --strict 1 refuses a transfer with any lossy decision (RestoreOptions::strict).
//
// The gap reported to the world (SIM_CHECKPOINT, CKPT_RESTORED) is the time from the loop
// boundary to the new module's first motor outputs: transfer, hand-over, resume and one loop.
#include <dlfcn.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>

#include <symcr/symcr.hpp>

#include "vehicle_module.hpp"

namespace {

constexpr int kSensorTimeoutMs = 30000;

std::uint64_t now_ns() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                        std::chrono::steady_clock::now().time_since_epoch())
                                        .count());
}

struct Module {
  void* handle = nullptr;
  const symcr::Schema* schema = nullptr;
  decltype(&specimen_vehicle_setup) setup = nullptr;
  decltype(&specimen_vehicle_link) link = nullptr;
  decltype(&specimen_vehicle_step) step = nullptr;
  decltype(&specimen_vehicle_resume) resume = nullptr;
};

template <typename Function>
bool resolve(void* handle, const char* name, Function& out) {
  out = reinterpret_cast<Function>(::dlsym(handle, name));
  if (out == nullptr) std::fprintf(stderr, "copter_live: no %s: %s\n", name, ::dlerror());
  return out != nullptr;
}

// Loads a module (RTLD_LOCAL: its globals, runtime and schema are its own) and sets it up.
// A file already loaded would give the loaded copy back: the same build as an update (V0 -> V0)
// is loaded from a copy of its file, a module of its own.
bool load(const char* path, Module& out, const char* loaded = nullptr) {
  namespace fs = std::filesystem;
  std::error_code error;
  std::string copy;
  if (loaded != nullptr && fs::equivalent(path, loaded, error)) {
    copy = (fs::temp_directory_path() / ("copter_live_" + std::to_string(::getpid()) + ".so"))
               .string();
    fs::copy_file(path, copy, fs::copy_options::overwrite_existing, error);
    if (error) {
      std::fprintf(stderr, "copter_live: cannot copy %s: %s\n", path, error.message().c_str());
      return false;
    }
  }
  out.handle = ::dlopen(copy.empty() ? path : copy.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!copy.empty()) fs::remove(copy, error);  // mapped: the file is no longer needed
  if (out.handle == nullptr) {
    std::fprintf(stderr, "copter_live: cannot load %s: %s\n", path, ::dlerror());
    return false;
  }
  decltype(&symcr_program_schema) schema = nullptr;
  if (!resolve(out.handle, "symcr_program_schema", schema) ||
      !resolve(out.handle, "specimen_vehicle_setup", out.setup) ||
      !resolve(out.handle, "specimen_vehicle_link", out.link) ||
      !resolve(out.handle, "specimen_vehicle_step", out.step) ||
      !resolve(out.handle, "specimen_vehicle_resume", out.resume)) {
    return false;
  }
  out.schema = schema();
  if (out.schema == nullptr) {
    std::fprintf(stderr, "copter_live: %s has no generated schema\n", path);
    return false;
  }
  out.setup();
  return true;
}

void report(mav::Channel& sim, mav::CheckpointEvent event, std::uint64_t nanos) {
  mav::SimCheckpoint msg{};
  msg.event = event;
  msg.nanos = nanos > 0xFFFFFFFFu ? 0xFFFFFFFFu : static_cast<std::uint32_t>(nanos);
  msg.micros = static_cast<std::uint32_t>(nanos / 1000);
  sim.send(mav::make_frame(mav::SIM_CHECKPOINT, msg));
}

void usage() {
  std::fprintf(stderr,
               "usage: copter_live --sim-fd N --gcs-fd N --module V0.so --update-module Vk.so "
               "[--strict 1]\n");
}

}  // namespace

int main(int argc, char** argv) {
  int sim_fd = -1, gcs_fd = -1;
  const char* module_path = nullptr;
  const char* update_path = nullptr;
  symcr::RestoreOptions options;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string arg = argv[i];
    if (arg == "--sim-fd") {
      sim_fd = std::atoi(argv[i + 1]);
    } else if (arg == "--gcs-fd") {
      gcs_fd = std::atoi(argv[i + 1]);
    } else if (arg == "--module") {
      module_path = argv[i + 1];
    } else if (arg == "--update-module") {
      update_path = argv[i + 1];
    } else if (arg == "--strict") {
      options.strict = std::atoi(argv[i + 1]) != 0;
    } else {
      usage();
      return 2;
    }
  }
  if (sim_fd < 0 || gcs_fd < 0 || module_path == nullptr || update_path == nullptr) {
    usage();
    return 2;
  }

  Module flying;
  if (!load(module_path, flying)) return 3;
  *flying.link(0) = mav::Channel(sim_fd);
  *flying.link(1) = mav::Channel(gcs_fd);
  mav::Channel world(sim_fd);  // the host receives; the flying module sends on its own end

  // The update: loaded and prepared on a thread while the old module flies on.
  Module next;
  std::atomic<int> next_state{0};  // 0 none, 1 loading, 2 ready, 3 failed
  std::thread loader;
  mav::Frame frame;
  while (world.receive(frame, kSensorTimeoutMs)) {
    if (frame.msgid == mav::SIM_UPDATE && next_state.load() == 0) {
      next_state = 1;
      loader = std::thread([&] {
        const bool ok = load(update_path, next, module_path) &&
                        symcr::prepare_transfer(*flying.schema, *next.schema).ok();
        next_state = ok ? 2 : 3;
      });
      continue;
    }
    if (frame.msgid != mav::SIM_SENSORS) continue;
    const mav::SimSensors sensors = mav::read_payload<mav::SimSensors>(frame);
    if (next_state.load() == 3) {
      loader.join();
      next_state = 4;  // reported once; the old module flies on
      report(*flying.link(0), mav::CKPT_RESTORE_FAILED, 0);
    }
    if (next_state.load() == 2) {
      loader.join();
      next_state = 4;
      // The loop boundary: nothing of the old module runs until this is decided.
      const std::uint64_t start = now_ns();
      const symcr::Report moved = symcr::transfer(*flying.schema, *next.schema, options);
      const std::uint64_t transferred = now_ns();
      if (moved.ok()) {
        *next.link(0) = *flying.link(0);
        *next.link(1) = *flying.link(1);
        next.resume(&sensors);
        flying = next;
        if (!flying.step(&sensors)) break;
        const std::uint64_t gap = now_ns() - start;
        report(*flying.link(0), mav::CKPT_RESTORED, gap);
        std::fprintf(stderr,
                     "copter_live: switched to %s: transfer %.1f us, gap to its first motor "
                     "outputs %.1f us\n%s",
                     update_path, (transferred - start) * 1e-3, gap * 1e-3,
                     moved.to_text().c_str());
        continue;
      }
      std::fprintf(stderr, "copter_live: transfer refused; %s flies on:\n%s", module_path,
                   moved.to_text().c_str());
      report(*flying.link(0), mav::CKPT_RESTORE_FAILED, transferred - start);
    }
    if (!flying.step(&sensors)) break;
  }
  if (loader.joinable()) loader.join();
  // The modules stay loaded: the process ends here.
  return 0;
}
