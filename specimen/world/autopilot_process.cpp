#include "autopilot_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <fstream>

namespace world {
namespace {

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

// A socket end as CRIU names it: by its inode.
bool socket_link(int child_fd, int fd, ExternalLink& out) {
  struct stat info;
  if (::fstat(fd, &info) != 0) return false;
  const std::string inode = std::to_string(static_cast<unsigned long long>(info.st_ino));
  out = ExternalLink{child_fd, "unix[" + inode + "]", "socket:[" + inode + "]"};
  return true;
}

// A regular file as CRIU names it: by the mount it is on and its inode.
bool file_link(int child_fd, int fd, ExternalLink& out) {
  struct stat info;
  if (::fstat(fd, &info) != 0) return false;
  std::ifstream fdinfo("/proc/self/fdinfo/" + std::to_string(fd));
  std::string key;
  unsigned mount_id = 0;
  bool found = false;
  while (fdinfo >> key) {
    if (key == "mnt_id:" && fdinfo >> mount_id) {
      found = true;
      break;
    }
  }
  if (!found) return false;
  char id[96];
  std::snprintf(id, sizeof id, "file[%x:%llx]", mount_id,
                static_cast<unsigned long long>(info.st_ino));
  out = ExternalLink{child_fd, id, id};
  return true;
}

}  // namespace

ChildEnds::~ChildEnds() {
  close_fd(log);
  close_fd(sim);
  close_fd(gcs);
}

int ChildEnds::at(int child_fd) const {
  switch (child_fd) {
    case 2:
      return log;
    case 3:
      return sim;
    case 4:
      return gcs;
    default:
      return -1;
  }
}

AutopilotProcess::~AutopilotProcess() { kill_now(); }

bool AutopilotProcess::open_links(const std::string& log_path, ChildEnds& ends) {
  close_links();
  int sim_pair[2], gcs_pair[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sim_pair) != 0) return false;
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, gcs_pair) != 0) {
    ::close(sim_pair[0]);
    ::close(sim_pair[1]);
    return false;
  }
  sim_fd_ = sim_pair[0];
  gcs_fd_ = gcs_pair[0];
  ends.sim = sim_pair[1];
  ends.gcs = gcs_pair[1];
  ends.log = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (ends.log < 0) return false;
  sim_ = mav::Channel(sim_fd_);
  gcs_ = mav::Channel(gcs_fd_);
  links_.assign(3, ExternalLink{});
  return file_link(2, ends.log, links_[0]) && socket_link(3, ends.sim, links_[1]) &&
         socket_link(4, ends.gcs, links_[2]);
}

bool AutopilotProcess::start(const std::string& executable, const std::vector<std::string>& args,
                             const std::string& log_path) {
  ChildEnds ends;
  if (!open_links(log_path, ends)) return false;
  std::vector<std::string> argv_storage{executable, "--sim-fd", "3", "--gcs-fd", "4"};
  argv_storage.insert(argv_storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& s : argv_storage) argv.push_back(s.data());
  argv.push_back(nullptr);

  const pid_t pid = ::fork();
  if (pid < 0) return false;
  if (pid == 0) {
    // Child: links on fds 3 and 4, the log on 2 (dup2 clears close-on-exec); nothing on 0 and
    // 1, so that a dump of the process holds nothing of the world's but its links.
    std::signal(SIGPIPE, SIG_DFL);
    // Moved above 4 first, so that placing one cannot overwrite another.
    const int log = ::fcntl(ends.log, F_DUPFD_CLOEXEC, 10);
    const int sim = ::fcntl(ends.sim, F_DUPFD_CLOEXEC, 10);
    const int gcs = ::fcntl(ends.gcs, F_DUPFD_CLOEXEC, 10);
    const int null_fd = ::open("/dev/null", O_RDWR | O_CLOEXEC);
    if (null_fd >= 0) {
      ::dup2(null_fd, 0);
      ::dup2(null_fd, 1);
    }
    ::dup2(log, 2);
    ::dup2(sim, 3);
    ::dup2(gcs, 4);
    ::execv(executable.c_str(), argv.data());
    std::perror(executable.c_str());
    ::_exit(127);
  }
  pid_ = pid;
  return true;
}

void AutopilotProcess::adopt(pid_t pid) { pid_ = pid; }

void AutopilotProcess::close_links() {
  close_fd(sim_fd_);
  close_fd(gcs_fd_);
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

void AutopilotProcess::forget_killed() {
  if (pid_ > 0) {
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
