#include "criu_checkpointer.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <utility>

namespace world {
namespace {

namespace fs = std::filesystem;

// Where criu's inherited descriptors go in its process (above anything it opens first).
constexpr int kFirstInheritedFd = 10;

// Why criu failed, from its log: the first error a task being dumped or restored hit (those
// lines start with its pid), else criu's last error; without timestamp and source location.
std::string criu_error(const std::string& log_path) {
  std::ifstream log(log_path);
  std::string line, last;
  while (std::getline(log, line)) {
    const std::size_t at = line.find("Error (");
    if (at == std::string::npos) continue;
    const std::size_t text = line.find("): ", at);
    const std::string message = text == std::string::npos ? line.substr(at) : line.substr(text + 3);
    const std::size_t first = line.find_first_not_of(' ');
    if (first != std::string::npos && std::isdigit(static_cast<unsigned char>(line[first])) &&
        line.compare(line.find_first_not_of("0123456789", first), 2, ": ") == 0) {
      return message;
    }
    last = message;
  }
  return last.empty() ? "criu failed (no error line in " + log_path + ")" : last;
}

std::uint64_t directory_bytes(const std::string& dir) {
  std::uint64_t total = 0;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir, error)) {
    if (entry.is_regular_file(error)) total += entry.file_size(error);
  }
  return total;
}

}  // namespace

CriuCheckpointer::CriuCheckpointer(std::string criu, std::string images_dir, std::string log_dir,
                                   bool build_id)
    : criu_(std::move(criu)),
      images_dir_(std::move(images_dir)),
      log_dir_(std::move(log_dir)),
      build_id_(build_id) {}

CriuOutcome CriuCheckpointer::run(const std::vector<std::string>& args,
                                  const std::vector<int>& inherited, const std::string& log) {
  std::vector<std::string> argv_storage{criu_};
  argv_storage.insert(argv_storage.end(), args.begin(), args.end());
  argv_storage.push_back("--log-file");
  argv_storage.push_back(log);
  if (!build_id_) {
    argv_storage.push_back("--file-validation");
    argv_storage.push_back("filesize");
  }
  std::vector<char*> argv;
  for (std::string& s : argv_storage) argv.push_back(s.data());
  argv.push_back(nullptr);

  CriuOutcome outcome;
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = ::fork();
  if (pid < 0) {
    outcome.error = "cannot fork criu";
    return outcome;
  }
  if (pid == 0) {
    std::signal(SIGPIPE, SIG_DFL);
    for (std::size_t i = 0; i < inherited.size(); ++i) {
      ::dup2(inherited[i], kFirstInheritedFd + static_cast<int>(i));  // without close-on-exec
    }
    const int null_fd = ::open("/dev/null", O_RDWR);
    if (null_fd >= 0) {
      ::dup2(null_fd, 0);
      ::dup2(null_fd, 1);
      ::dup2(null_fd, 2);
    }
    ::execv(criu_.c_str(), argv.data());
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  outcome.ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!outcome.ok) {
    outcome.error =
        WIFEXITED(status) && WEXITSTATUS(status) == 127 ? "cannot run " + criu_ : criu_error(log);
  }
  return outcome;
}

CriuOutcome CriuCheckpointer::dump(pid_t pid, const std::vector<ExternalLink>& links,
                                   bool leave_running) {
  // Into a fresh directory, which replaces the previous dump only once complete.
  const std::string next = images_dir_ + ".next";
  std::error_code error;
  fs::remove_all(next, error);
  fs::create_directories(next, error);
  std::vector<std::string> args{"dump",         "--tree", std::to_string(pid),
                                "--images-dir", next,     "--shell-job"};
  for (const ExternalLink& link : links) {
    args.push_back("--external");
    args.push_back(link.dump_id);
  }
  if (leave_running) args.push_back("--leave-running");
  CriuOutcome outcome = run(args, {}, log_dir_ + "/criu-dump.log");
  if (!outcome.ok) {
    fs::remove_all(next, error);
    return outcome;
  }
  fs::remove_all(images_dir_, error);
  fs::rename(next, images_dir_, error);
  if (error) {
    outcome.ok = false;
    outcome.error = "cannot keep the dump: " + error.message();
    return outcome;
  }
  outcome.image_bytes = directory_bytes(images_dir_);
  ++dumps_;
  return outcome;
}

CriuOutcome CriuCheckpointer::restore(const std::vector<ExternalLink>& links,
                                      const ChildEnds& ends) {
  const std::string pidfile = log_dir_ + "/criu-restore.pid";
  std::error_code error;
  fs::remove(pidfile, error);
  // Detached, as a sibling of criu: the restored autopilot is this process's child again.
  std::vector<std::string> args{
      "restore",           "--images-dir", images_dir_, "--shell-job", "--restore-detached",
      "--restore-sibling", "--pidfile",    pidfile};
  std::vector<int> inherited;
  for (const ExternalLink& link : links) {
    args.push_back("--inherit-fd");
    args.push_back("fd[" + std::to_string(kFirstInheritedFd + static_cast<int>(inherited.size())) +
                   "]:" + link.restore_key);
    inherited.push_back(ends.at(link.child_fd));
  }
  CriuOutcome outcome = run(args, inherited, log_dir_ + "/criu-restore.log");
  if (!outcome.ok) return outcome;
  std::ifstream in(pidfile);
  long pid = -1;
  if (!(in >> pid) || pid <= 0) {
    outcome.ok = false;
    outcome.error = "criu restored no process (no pid in " + pidfile + ")";
    return outcome;
  }
  outcome.pid = static_cast<pid_t>(pid);
  return outcome;
}

}  // namespace world
