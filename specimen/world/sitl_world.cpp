// sitl_world: one flight of the experiment. The world (physics, sensors, ground station) runs
// here, in the parent; the autopilot runs as a child process that can be killed and replaced
// by a patched build without the world noticing anything but silence on the links. The
// vehicle's true physical state therefore survives every autopilot restart, as it would in
// reality: only the autopilot's memory is lost, and what it gets back is what the checkpoint
// method restores.
//
// The simulation is lock-step (the world waits for each autopilot loop), so it runs as fast
// as the processes allow; --speedup N paces it at N times real time instead.
//
// Prints one JSON object describing the flight; writes the flown track as CSV with --track.
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "autopilot_process.hpp"
#include "criu_checkpointer.hpp"
#include "flight_judge.hpp"
#include "geo.hpp"
#include "ground_station.hpp"
#include "messages.hpp"
#include "mission_file.hpp"
#include "physics.hpp"
#include "sensors.hpp"

namespace {

using world::AutopilotProcess;
using world::BodyState;

struct Options {
  std::string autopilot;         // the build that starts the mission (V0)
  std::string resume_autopilot;  // the build restarted after the checkpoint (Vk)
  std::string mission_path;
  // none | raw-image | symcr | symcr-points | criu | criu-unchecked (CRIU with its file
  // validation reduced to sizes, which the world makes equal: the old memory under the new code)
  // | symcr-live (the autopilot is the live host flying V0's vehicle module, told to switch to
  // Vk's in flight: --autopilot and --resume-autopilot are the modules)
  std::string method = "none";
  std::string live_host;         // symcr-live: the host executable (copter_live)
  bool live_strict = false;      // symcr-live: refuse a transfer with a lossy decision
  std::string criu = "criu";     // the criu binary
  double criu_every_s = 2;       // red team: seconds between CRIU's dumps
  std::string workdir = ".";
  std::string track_path;
  unsigned seed = 1;
  double checkpoint_at_s = -1;   // seconds after arming; < 0: never stop the autopilot
  double exploit_at_s = -1;      // red team: seconds after arming to send the exploit
  double exploit_again_s = -1;   // red team: seconds after the restart to send it again
  double pause_at_s = -1;        // seconds after arming: the operator pauses (LOITER) ...
  double pause_s = 1.0;          // ... and resumes the mission (AUTO) this much later
  int restarts = 0;              // watchdog: restarts of a restarted autopilot that stops
  int fallback_depth = 0;        // symcr: the store's crash-loop fallback (0: off)
  int checkpoint_every = 10;     // autopilot loops between checkpoints
  double outage_s = 0.2;         // world time while no autopilot runs (motors hold)
  double time_limit_s = 0;       // 0: from the route length
  double speedup = 0;            // 0: as fast as possible
  double wind_max_ms = 3.0;
  double visit_radius_m = 3.5;
};

struct Point {
  double t = -1, north = 0, east = 0, alt = 0;
};

struct Result {
  bool success = false;
  std::string reason;
  double mission_time_s = 0;
  double sim_time_s = 0;
  int checkpoints_saved = 0;
  std::uint32_t checkpoint_bytes = 0;
  double checkpoint_us_sum = 0;
  bool restarted = false;
  int restarts = 0;  // how often the autopilot was restarted (the first restart included)
  bool restored = false;
  double restore_us = -1;
  std::string autopilot_exit;
  Point checkpoint_point, resume_point, exploit_point;
};

[[noreturn]] void usage(const char* message) {
  std::fprintf(stderr,
               "sitl_world: %s\n"
               "usage: sitl_world --autopilot EXE --mission FILE [--resume-autopilot EXE]\n"
               "  [--method none|raw-image|symcr|symcr-points|criu|criu-unchecked|symcr-live]\n"
               "  [--checkpoint-at S] [--exploit-at S] [--exploit-again S]\n"
               "  [--pause-at S] [--pause S] [--restarts N] [--fallback-depth N]\n"
               "  [--live-host EXE] [--live-strict 0|1] (symcr-live)\n"
               "  [--checkpoint-every LOOPS]"
               " [--criu EXE] [--criu-every S] [--outage S] [--seed N] [--time-limit S]\n"
               "  [--speedup X] [--wind M/S] [--workdir DIR] [--track FILE]\n",
               message);
  std::exit(2);
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) usage(("missing value for " + arg).c_str());
    const std::string value = argv[++i];
    if (arg == "--autopilot") o.autopilot = value;
    else if (arg == "--resume-autopilot") o.resume_autopilot = value;
    else if (arg == "--mission") o.mission_path = value;
    else if (arg == "--method") o.method = value;
    else if (arg == "--workdir") o.workdir = value;
    else if (arg == "--track") o.track_path = value;
    else if (arg == "--seed") o.seed = static_cast<unsigned>(std::stoul(value));
    else if (arg == "--checkpoint-at") o.checkpoint_at_s = std::stod(value);
    else if (arg == "--exploit-at") o.exploit_at_s = std::stod(value);
    else if (arg == "--exploit-again") o.exploit_again_s = std::stod(value);
    else if (arg == "--pause-at") o.pause_at_s = std::stod(value);
    else if (arg == "--pause") o.pause_s = std::stod(value);
    else if (arg == "--restarts") o.restarts = std::stoi(value);
    else if (arg == "--fallback-depth") o.fallback_depth = std::stoi(value);
    else if (arg == "--live-host") o.live_host = value;
    else if (arg == "--live-strict") o.live_strict = value == "1";
    else if (arg == "--checkpoint-every") o.checkpoint_every = std::stoi(value);
    else if (arg == "--outage") o.outage_s = std::stod(value);
    else if (arg == "--time-limit") o.time_limit_s = std::stod(value);
    else if (arg == "--speedup") o.speedup = std::stod(value);
    else if (arg == "--wind") o.wind_max_ms = std::stod(value);
    else if (arg == "--visit-radius") o.visit_radius_m = std::stod(value);
    else if (arg == "--criu") o.criu = value;
    else if (arg == "--criu-every") o.criu_every_s = std::stod(value);
    else usage(("unknown option " + arg).c_str());
  }
  if (o.autopilot.empty() || o.mission_path.empty()) usage("--autopilot and --mission are required");
  if (o.method != "none" && o.method != "raw-image" && o.method != "symcr" &&
      o.method != "symcr-points" && o.method != "criu" && o.method != "criu-unchecked" &&
      o.method != "symcr-live")
    usage("unknown method");
  if (o.method == "symcr-live" && o.live_host.empty()) usage("symcr-live needs --live-host");
  if (o.resume_autopilot.empty()) o.resume_autopilot = o.autopilot;
  return o;
}

bool is_criu(const std::string& method) { return method == "criu" || method == "criu-unchecked"; }

std::string json_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) < 0x20) continue;
    out += c;
  }
  return out;
}

std::string point_json(const Point& p) {
  if (p.t < 0) return "null";
  char buf[160];
  std::snprintf(buf, sizeof(buf), "{\"t\":%.2f,\"north\":%.2f,\"east\":%.2f,\"alt\":%.2f}", p.t,
                p.north, p.east, p.alt);
  return buf;
}

class World {
 public:
  World(const Options& options, const world::Mission& mission, const world::Home& home)
      : options_(options),
        mission_(mission),
        physics_(world::Airframe{}, make_wind(options), options.seed),
        sensors_(home, options.seed * 7919u + 1u),
        station_(mission),
        judge_(mission, home, options.visit_radius_m) {
    if (!options.track_path.empty()) track_.open(options.track_path);
    if (track_) track_ << "t,north,east,alt,segment\n";
    if (is_criu(options.method)) {
      // Absolute: criu resolves relative paths against its own working directory.
      const std::filesystem::path workdir = std::filesystem::absolute(options.workdir);
      criu_ = std::make_unique<world::CriuCheckpointer>(
          options.criu, (workdir / "criu-images").string(), workdir.string(),
          /*build_id=*/options.method == "criu");
    }
  }

  Result run();

 private:
  static world::WindModel make_wind(const Options& options) {
    std::mt19937_64 rng(options.seed * 104729u + 17u);
    std::uniform_real_distribution<double> speed(0.0, options.wind_max_ms), dir(0.0, 2 * M_PI);
    const double s = speed(rng), d = dir(rng);
    world::WindModel wind;
    wind.mean = {s * std::cos(d), s * std::sin(d), 0};
    return wind;
  }

  std::vector<std::string> autopilot_args() const {
    std::vector<std::string> args;
    if (live()) {
      return {"--module", options_.autopilot, "--update-module", options_.resume_autopilot,
              "--strict", options_.live_strict ? "1" : "0"};
    }
    if (options_.method != "none" && !criu_) {
      args = {"--checkpoint", options_.method, "--checkpoint-path",
              options_.workdir + "/checkpoint." + (options_.method == "raw-image" ? "img" : "store"),
              "--checkpoint-every", std::to_string(options_.checkpoint_every)};
      if (options_.fallback_depth > 0) {
        args.insert(args.end(), {"--fallback-depth", std::to_string(options_.fallback_depth)});
      }
    }
    return args;
  }
  std::string log_path() const { return options_.workdir + "/autopilot.log"; }
  bool live() const { return options_.method == "symcr-live"; }
  // Where the criu methods run the autopilot from: V0, then Vk put in its place.
  std::string installed_executable() const {
    return (std::filesystem::absolute(options_.workdir) / "autopilot").lexically_normal().string();
  }

  Point here() const {
    const BodyState& s = physics_.state();
    return {time_s(), s.position.x, s.position.y, -s.position.z};
  }
  double time_s() const { return static_cast<double>(time_us_) * 1e-6; }
  void step_world(const std::array<double, 4>& motors, int segment);
  // One autopilot loop; false when the autopilot is gone (`gone_how` says how).
  bool autopilot_loop(std::array<double, 4>& motors, bool& saved_this_loop, std::string& gone_how);
  bool restart_autopilot(Result& result, int& segment);
  bool install_executable(const std::string& source, std::string& error) const;
  bool criu_dump(Result& result, bool leave_running);
  bool criu_restore(Result& result);
  void pace();

  const Options& options_;
  const world::Mission& mission_;
  world::Physics physics_;
  world::Sensors sensors_;
  world::GroundStation station_;
  world::FlightJudge judge_;
  AutopilotProcess autopilot_;
  std::ofstream track_;
  std::uint64_t time_us_ = 0;
  // When the running autopilot process started: its clock (SIM_SENSORS' time_us) counts from
  // there, as a flight controller's does from its boot. A CRIU restore resumes the dumped
  // process, whose clock goes on.
  std::uint64_t autopilot_boot_us_ = 0;
  std::uint64_t next_track_us_ = 0;
  std::chrono::steady_clock::time_point wall_start_ = std::chrono::steady_clock::now();
  Result* result_ = nullptr;
  std::unique_ptr<world::CriuCheckpointer> criu_;
  std::vector<world::ExternalLink> dumped_links_;  // of the process the newest dump holds
  double next_dump_s_ = 0;                         // red team: mission time of the next dump
};

constexpr std::uint64_t kLoopUs = 10000;   // autopilot loop: 100 Hz
constexpr int kPhysicsSubsteps = 4;         // physics: 400 Hz
constexpr int kReplyTimeoutMs = 20000;

void World::step_world(const std::array<double, 4>& motors, int segment) {
  const double dt = kLoopUs * 1e-6 / kPhysicsSubsteps;
  for (int i = 0; i < kPhysicsSubsteps; ++i) {
    physics_.step(motors, dt);
    sensors_.accumulate_imu(physics_.state());
  }
  time_us_ += kLoopUs;
  judge_.update(physics_.state(), time_s());
  // Every loop while the autopilot is down (it is short), every 0.2 s otherwise.
  if (track_ && (time_us_ >= next_track_us_ || segment == 1)) {
    next_track_us_ = time_us_ + 200000;
    const Point p = here();
    track_ << p.t << ',' << p.north << ',' << p.east << ',' << p.alt << ',' << segment << '\n';
  }
}

void World::pace() {
  if (options_.speedup <= 0) return;
  const auto target = wall_start_ + std::chrono::microseconds(
                                        static_cast<std::int64_t>(time_us_ / options_.speedup));
  std::this_thread::sleep_until(target);
}

bool World::autopilot_loop(std::array<double, 4>& motors, bool& saved_this_loop,
                           std::string& gone_how) {
  saved_this_loop = false;
  mav::SimSensors sample = sensors_.sample(physics_.state(), time_us_);
  sample.time_us = time_us_ - autopilot_boot_us_;
  if (!autopilot_.sim().send(mav::make_frame(mav::SIM_SENSORS, sample))) {
    gone_how = autopilot_.reap();
    return false;
  }
  mav::Frame frame;
  for (;;) {
    if (!autopilot_.sim().receive(frame, kReplyTimeoutMs)) {
      if (autopilot_.sim().closed()) {
        gone_how = autopilot_.reap();
      } else {
        autopilot_.kill_now();
        gone_how = "hung (no reply)";
      }
      return false;
    }
    if (frame.msgid == mav::SIM_CHECKPOINT) {
      const auto msg = mav::read_payload<mav::SimCheckpoint>(frame);
      if (msg.event == mav::CKPT_SAVED) {
        ++result_->checkpoints_saved;
        result_->checkpoint_us_sum += msg.nanos * 1e-3;
        // The checkpoint that counts is the one the first build wrote and the second restored.
        if (!result_->restarted) {
          result_->checkpoint_bytes = msg.bytes;
          result_->checkpoint_point = here();
        }
        saved_this_loop = true;
      } else if (msg.event == mav::CKPT_RESTORED) {
        result_->restored = true;
        result_->restore_us = msg.nanos * 1e-3;
        if (live()) result_->resume_point = here();  // Vk's code flies from here
      } else {
        result_->restored = false;
      }
      continue;
    }
    if (frame.msgid == mav::SIM_MOTORS) {
      const auto out = mav::read_payload<mav::SimMotors>(frame);
      for (int i = 0; i < 4; ++i) motors[i] = out.motor[i];
      return true;
    }
  }
}

bool World::restart_autopilot(Result& result, int& segment) {
  // The world goes on while the flight computer is down: the motor controllers hold their
  // last command (as an IO co-processor does), the vehicle keeps flying open-loop.
  std::array<double, 4> held{};
  for (int i = 0; i < 4; ++i) held[i] = physics_.state().motor[i];
  segment = 1;
  for (double t = 0; t < options_.outage_s; t += kLoopUs * 1e-6) step_world(held, segment);
  result.restarted = true;
  ++result.restarts;
  result.restored = false;  // until this start reports its restore
  result.restore_us = -1;
  if (criu_) {
    if (!criu_restore(result)) return false;
  } else {
    std::vector<std::string> args = autopilot_args();
    args.push_back("--restore");
    autopilot_boot_us_ = time_us_;
    if (!autopilot_.start(options_.resume_autopilot, args, log_path())) {
      result.reason = "could not start " + options_.resume_autopilot;
      return false;
    }
  }
  station_.on_autopilot_restarted();
  result.resume_point = here();
  segment = 2;
  return true;
}

// A copy of `source` at installed_executable(), replacing what was there as a whole (a new
// file, renamed over the old path). For criu-unchecked both builds are padded with zeros (which
// an ELF file ignores) to the larger one's size, so that CRIU's size check lets the new code in.
bool World::install_executable(const std::string& source, std::string& error) const {
  namespace fs = std::filesystem;
  const std::string target = installed_executable();
  const std::string staged = target + ".new";
  std::error_code code;
  fs::copy_file(source, staged, fs::copy_options::overwrite_existing, code);
  if (!code && options_.method == "criu-unchecked") {
    const std::uintmax_t size = std::max(fs::file_size(options_.autopilot, code),
                                         fs::file_size(options_.resume_autopilot, code));
    if (!code) fs::resize_file(staged, size, code);
  }
  if (!code) fs::permissions(staged, fs::perms::owner_all | fs::perms::group_read |
                                         fs::perms::group_exec | fs::perms::others_read |
                                         fs::perms::others_exec, code);
  if (!code) fs::rename(staged, target, code);
  if (code) error = "cannot install " + source + " at " + target + ": " + code.message();
  return !code;
}

// CRIU dumps the running autopilot; without `leave_running` that is also its end.
bool World::criu_dump(Result& result, bool leave_running) {
  const world::CriuOutcome dumped =
      criu_->dump(autopilot_.pid(), autopilot_.external_links(), leave_running);
  if (!dumped.ok) {
    result.reason = "criu dump failed: " + dumped.error;
    return false;
  }
  dumped_links_ = autopilot_.external_links();
  ++result.checkpoints_saved;
  result.checkpoint_us_sum += dumped.seconds * 1e6;
  result.checkpoint_bytes = static_cast<std::uint32_t>(dumped.image_bytes);
  result.checkpoint_point = here();
  if (!leave_running) {
    autopilot_.forget_killed();
    result.autopilot_exit = "killed by criu dump";
  }
  return true;
}

// Vk put where the dumped executable was, then CRIU restores the newest dump, unmodified in
// what it checks: a refusal is the outcome.
bool World::criu_restore(Result& result) {
  if (!criu_->has_dump()) {
    result.reason = "criu: no dump was taken before the autopilot stopped";
    return false;
  }
  std::string error;
  if (!install_executable(options_.resume_autopilot, error)) {
    result.reason = error;
    return false;
  }
  world::ChildEnds ends;
  if (!autopilot_.open_links(log_path(), ends)) {
    result.reason = "cannot open the restored autopilot's links";
    return false;
  }
  const world::CriuOutcome restored = criu_->restore(dumped_links_, ends);
  result.restore_us = restored.seconds * 1e6;
  if (!restored.ok) {
    // CRIU names the executable by its path without the leading '/': the same reason reads
    // the same in every flight's directory.
    std::string why = restored.error;
    const std::string path = installed_executable().substr(1);
    for (std::size_t at = why.find(path); at != std::string::npos; at = why.find(path, at)) {
      why.replace(at, path.size(), "<workdir>/autopilot");
    }
    result.reason = "criu refused the restore: " + why;
    return false;
  }
  autopilot_.adopt(restored.pid);
  result.restored = true;
  return true;
}

Result World::run() {
  Result result;
  result_ = &result;
  const double route_m = mission_.route_length_m();
  const double limit_s = options_.time_limit_s > 0
                             ? options_.time_limit_s
                             : 2.5 * route_m / mission_.cruise_speed_ms() + 120.0;
  std::string first = live() ? options_.live_host : options_.autopilot;
  if (criu_) {
    if (!install_executable(options_.autopilot, result.reason)) return result;
    first = installed_executable();
  }
  autopilot_boot_us_ = time_us_;
  if (!autopilot_.start(first, autopilot_args(), log_path())) {
    result.reason = "could not start " + first;
    return result;
  }
  std::array<double, 4> motors{};
  int segment = 0;
  bool exploit_sent = false;
  bool exploit_resent = false;
  bool pause_sent = false, resume_sent = false;
  bool airborne = false;
  double landed_since = -1;
  for (;;) {
    bool saved = false;
    std::string gone_how;
    if (!autopilot_loop(motors, saved, gone_how)) {
      result.autopilot_exit = gone_how;
      if (exploit_sent && !result.restarted && options_.method != "none") {
        // The attack crashed the flight software: the watchdog restarts the repaired build
        // from the latest checkpoint taken before the exploit.
        if (!restart_autopilot(result, segment)) return result;
        continue;
      }
      if (result.restarted && result.restarts <= options_.restarts && !criu_) {
        // The watchdog restarts a restarted build that stopped again (a crash loop).
        if (!restart_autopilot(result, segment)) return result;
        continue;
      }
      result.reason = "autopilot stopped (" + gone_how + ")";
      if (exploit_resent) result.reason += " when the exploit was sent again";
      if (result.restarted && !result.restored) result.reason += ": restore failed";
      break;
    }
    station_.update(autopilot_.gcs(), time_s());
    step_world(motors, segment);
    pace();

    const BodyState& s = physics_.state();
    if (!s.on_ground) airborne = true;
    if (physics_.crashed()) {
      result.reason = std::string("crashed: ") + physics_.crash_reason();
      break;
    }
    if (judge_.max_distance_from_route() > 300.0) {
      result.reason = "flew away from the route";
      break;
    }
    const double mission_s = station_.mission_started() ? time_s() - station_.arm_time_s() : 0;
    if (time_s() > limit_s + 60.0) {
      result.reason = "time limit";
      break;
    }
    const bool disarmed = motors[0] == 0 && motors[1] == 0 && motors[2] == 0 && motors[3] == 0;
    if (airborne && s.on_ground && disarmed) {
      if (landed_since < 0) landed_since = time_s();
      if (time_s() - landed_since >= 1.0) {
        result.mission_time_s = landed_since - station_.arm_time_s();
        break;
      }
    } else {
      landed_since = -1;
    }

    if (criu_ && station_.mission_started() && options_.exploit_at_s >= 0 && !exploit_sent &&
        mission_s >= next_dump_s_) {
      // Red team: CRIU dumps the vulnerable build periodically, leaving it running.
      next_dump_s_ = mission_s + options_.criu_every_s;
      if (!criu_dump(result, /*leave_running=*/true)) break;
    }
    if (result.restarted && options_.exploit_again_s >= 0 && !exploit_resent &&
        time_s() >= result.resume_point.t + options_.exploit_again_s) {
      // The attacker tries again: a restored build that is still vulnerable falls again.
      station_.send_exploit(autopilot_.gcs());
      exploit_resent = true;
    }
    if (station_.mission_started() && options_.pause_at_s >= 0 && !pause_sent &&
        mission_s >= options_.pause_at_s) {
      station_.send_mode(autopilot_.gcs(), mav::MODE_LOITER);
      pause_sent = true;
    }
    if (pause_sent && !resume_sent && mission_s >= options_.pause_at_s + options_.pause_s) {
      station_.send_mode(autopilot_.gcs(), mav::MODE_AUTO);
      resume_sent = true;
    }
    if (station_.mission_started() && options_.exploit_at_s >= 0 && !exploit_sent &&
        mission_s >= options_.exploit_at_s) {
      station_.send_exploit(autopilot_.gcs());
      exploit_sent = true;
      result.exploit_point = here();
    }
    const bool at_checkpoint_point = station_.mission_started() && options_.method != "none" &&
                                     options_.exploit_at_s < 0 && options_.checkpoint_at_s >= 0 &&
                                     !result.restarted && mission_s >= options_.checkpoint_at_s;
    if (at_checkpoint_point && live()) {
      // No checkpoint, no kill: the running autopilot switches to Vk's code in flight.
      mav::Frame update;
      update.msgid = mav::SIM_UPDATE;
      autopilot_.sim().send(update);
      result.restarted = true;
      result.checkpoint_point = here();
    } else if (at_checkpoint_point && criu_) {
      // CRIU's dump stops the flight computer: the checkpoint and the crash in one.
      if (!criu_dump(result, /*leave_running=*/false)) break;
      if (!restart_autopilot(result, segment)) return result;
    } else if (at_checkpoint_point && saved) {
      // Stop the flight computer right after a checkpoint, as a crash would.
      autopilot_.kill_now();
      result.autopilot_exit = "killed (SIGKILL)";
      if (!restart_autopilot(result, segment)) return result;
    }
  }
  result.sim_time_s = time_s();
  autopilot_.kill_now();
  if (!result.reason.empty()) return result;

  std::string why;
  if (!judge_.route_flown_in_order(why)) {
    result.reason = why;
  } else if (judge_.distance_to_end(physics_.state()) > 5.0) {
    result.reason = "landed away from the end of the route";
  } else if (result.mission_time_s > limit_s) {
    result.reason = "over the time bound";
  } else if (options_.checkpoint_at_s >= 0 && options_.method != "none" && !result.restarted) {
    result.reason = "mission ended before the checkpoint point";
  } else if (options_.exploit_at_s >= 0 && !exploit_sent) {
    result.reason = "mission ended before the exploit";
  } else if (options_.exploit_at_s >= 0 && options_.method != "none" && !result.restarted) {
    // A red-team flight with a checkpoint method measures the restore after the crash: an
    // exploit that did not stop the autopilot tested nothing.
    result.reason = "the exploit did not stop the autopilot: nothing was restored";
  } else if (live() && result.restarted && !result.restored) {
    result.reason = "no update (refused, or Vk could not be loaded): V0's code flew on";
  } else if (result.restarted && !result.restored) {
    result.reason = "the restarted autopilot did not report a restore";
  } else {
    result.success = true;
    result.reason = "ok";
  }
  return result;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);
  // An autopilot that died mid-flight is seen as a failed write, not as this process's death
  // (children get the default back before they exec).
  std::signal(SIGPIPE, SIG_IGN);
  world::Mission mission;
  std::string error;
  if (!world::load_mission(options.mission_path, mission, error)) {
    std::fprintf(stderr, "sitl_world: %s\n", error.c_str());
    return 2;
  }
  std::error_code mkdir_error;
  std::filesystem::create_directories(options.workdir, mkdir_error);
  if (mkdir_error) {
    std::fprintf(stderr, "sitl_world: %s: %s\n", options.workdir.c_str(), mkdir_error.message().c_str());
    return 2;
  }
  world::Home home;
  home.lat = static_cast<std::int32_t>(std::lround(mission.items[0].lat * 1e7));
  home.lng = static_cast<std::int32_t>(std::lround(mission.items[0].lng * 1e7));

  const auto wall_start = std::chrono::steady_clock::now();
  World world(options, mission, home);
  const Result r = world.run();
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();

  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(3);
  out << "{\"success\":" << (r.success ? "true" : "false") << ",\"reason\":\""
      << json_escape(r.reason) << "\",\"mission\":\"" << json_escape(mission.name)
      << "\",\"method\":\"" << options.method << "\",\"seed\":" << options.seed
      << ",\"mission_time_s\":" << r.mission_time_s << ",\"sim_time_s\":" << r.sim_time_s
      << ",\"wall_time_s\":" << wall_s << ",\"checkpoints_saved\":" << r.checkpoints_saved
      << ",\"checkpoint_bytes\":" << r.checkpoint_bytes << ",\"checkpoint_us_mean\":"
      << (r.checkpoints_saved > 0 ? r.checkpoint_us_sum / r.checkpoints_saved : 0.0)
      << ",\"restarted\":" << (r.restarted ? "true" : "false")
      << ",\"restarts\":" << r.restarts
      << ",\"restored\":" << (r.restored ? "true" : "false") << ",\"restore_us\":" << r.restore_us
      << ",\"autopilot_exit\":\"" << json_escape(r.autopilot_exit) << "\""
      << ",\"route_points\":" << mission.route_points().size() << ",\"checkpoint_point\":"
      << (r.restarted ? point_json(r.checkpoint_point) : "null")
      << ",\"resume_point\":" << point_json(r.resume_point)
      << ",\"exploit_point\":" << point_json(r.exploit_point) << "}";
  std::printf("%s\n", out.str().c_str());
  return r.success ? 0 : 1;
}
