#include "autopilot_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>

namespace world {

AutopilotProcess::~AutopilotProcess() { kill_now(); }

bool AutopilotProcess::start(const std::string& executable, const std::vector<std::string>& args,
                             const std::string& log_path) {
  int sim_pair[2], gcs_pair[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sim_pair) != 0) return false;
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, gcs_pair) != 0) {
    ::close(sim_pair[0]);
    ::close(sim_pair[1]);
    return false;
  }
  std::vector<std::string> argv_storage{executable, "--sim-fd", "3", "--gcs-fd", "4"};
  argv_storage.insert(argv_storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& s : argv_storage) argv.push_back(s.data());
  argv.push_back(nullptr);

  const pid_t pid = ::fork();
  if (pid < 0) return false;
  if (pid == 0) {
    // Child: links on fds 3 and 4 (dup2 clears close-on-exec), stderr to the log.
    ::dup2(sim_pair[1], 3);
    ::dup2(gcs_pair[1], 4);
    const int log = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (log >= 0) ::dup2(log, 2);
    const int null_fd = ::open("/dev/null", O_WRONLY);
    if (null_fd >= 0) ::dup2(null_fd, 1);
    ::execv(executable.c_str(), argv.data());
    std::perror(executable.c_str());
    ::_exit(127);
  }
  ::close(sim_pair[1]);
  ::close(gcs_pair[1]);
  pid_ = pid;
  sim_fd_ = sim_pair[0];
  gcs_fd_ = gcs_pair[0];
  sim_ = mav::Channel(sim_fd_);
  gcs_ = mav::Channel(gcs_fd_);
  return true;
}

void AutopilotProcess::close_links() {
  if (sim_fd_ >= 0) ::close(sim_fd_);
  if (gcs_fd_ >= 0) ::close(gcs_fd_);
  sim_fd_ = gcs_fd_ = -1;
}

void AutopilotProcess::kill_now() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
  }
  close_links();
}

std::string AutopilotProcess::reap() {
  std::string how = "not running";
  if (pid_ > 0) {
    int status = 0;
    close_links();  // unblocks a child still writing
    ::waitpid(pid_, &status, 0);
    pid_ = -1;
    if (WIFSIGNALED(status)) {
      how = "signal " + std::to_string(WTERMSIG(status));
    } else {
      how = "exit " + std::to_string(WEXITSTATUS(status));
    }
  }
  close_links();
  return how;
}

}  // namespace world
