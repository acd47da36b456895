// The autopilot as a child process: started with its two links as file descriptors 3 (sensors
// and motors) and 4 (ground control), stopped with SIGKILL like a crashed flight computer.
#ifndef WORLD_AUTOPILOT_PROCESS_HPP
#define WORLD_AUTOPILOT_PROCESS_HPP

#include <string>
#include <sys/types.h>
#include <vector>

#include "channel.hpp"

namespace world {

class AutopilotProcess {
 public:
  AutopilotProcess() = default;
  ~AutopilotProcess();
  AutopilotProcess(const AutopilotProcess&) = delete;
  AutopilotProcess& operator=(const AutopilotProcess&) = delete;

  // Starts `executable` with `args` (after the fd arguments); its stderr goes to `log_path`.
  bool start(const std::string& executable, const std::vector<std::string>& args,
             const std::string& log_path);
  void kill_now();  // SIGKILL and reap
  // Reaps a process that exited by itself; describes how ("exit 3", "signal 11").
  std::string reap();
  bool running() const { return pid_ > 0; }

  mav::Channel& sim() { return sim_; }
  mav::Channel& gcs() { return gcs_; }

 private:
  void close_links();

  pid_t pid_ = -1;
  int sim_fd_ = -1, gcs_fd_ = -1;
  mav::Channel sim_, gcs_;
};

}  // namespace world

#endif  // WORLD_AUTOPILOT_PROCESS_HPP
