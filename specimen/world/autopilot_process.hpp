// The autopilot as a child process: started with its two links as file descriptors 3 (sensors
// and motors) and 4 (ground control) and its log as 2, stopped with SIGKILL like a crashed flight
// computer. A process CRIU restored is adopted with new links in place of the dumped ones.
#ifndef WORLD_AUTOPILOT_PROCESS_HPP
#define WORLD_AUTOPILOT_PROCESS_HPP

#include <sys/types.h>

#include <string>
#include <vector>

#include "channel.hpp"

namespace world {

// What the world hands an autopilot process, as CRIU names it: the dumped process's descriptor
// `child_fd` is external to the dump (`dump_id`, for --external) and is given back at restore
// in place of the resource `restore_key` (for --inherit-fd).
struct ExternalLink {
  int child_fd;
  std::string dump_id;
  std::string restore_key;
};

// The child's ends of fresh links, before they are handed over (closed by the destructor).
struct ChildEnds {
  ChildEnds() = default;
  ~ChildEnds();
  ChildEnds(const ChildEnds&) = delete;
  ChildEnds& operator=(const ChildEnds&) = delete;
  int log = -1, sim = -1, gcs = -1;
  // By the descriptor the child has them at (2, 3, 4).
  int at(int child_fd) const;
};

class AutopilotProcess {
 public:
  AutopilotProcess() = default;
  ~AutopilotProcess();
  AutopilotProcess(const AutopilotProcess&) = delete;
  AutopilotProcess& operator=(const AutopilotProcess&) = delete;

  // Starts `executable` with `args` (after the fd arguments); its stderr goes to `log_path`.
  bool start(const std::string& executable, const std::vector<std::string>& args,
             const std::string& log_path);
  // New links for a process started by someone else (CRIU): the world keeps its ends here.
  bool open_links(const std::string& log_path, ChildEnds& ends);
  // Takes `pid` (a child of this process) as the autopilot, on the links open_links() made.
  void adopt(pid_t pid);
  void kill_now();  // SIGKILL and reap
  // Reaps a process that exited by itself; describes how ("exit 3", "signal 11").
  std::string reap();
  // Reaps a process another program (CRIU's dump) killed, keeping the links' description.
  void forget_killed();
  bool running() const { return pid_ > 0; }
  pid_t pid() const { return pid_; }
  // The links of the running process, for a dump.
  const std::vector<ExternalLink>& external_links() const { return links_; }

  mav::Channel& sim() { return sim_; }
  mav::Channel& gcs() { return gcs_; }

 private:
  void close_links();

  pid_t pid_ = -1;
  int sim_fd_ = -1, gcs_fd_ = -1;
  mav::Channel sim_, gcs_;
  std::vector<ExternalLink> links_;
};

}  // namespace world

#endif  // WORLD_AUTOPILOT_PROCESS_HPP
