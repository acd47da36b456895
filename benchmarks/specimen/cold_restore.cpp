#include "cold_restore.hpp"

#include <fcntl.h>
#include <linux/perf_event.h>
#include <sys/ioctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "Copter.hpp"
#include "common.hpp"
#include "symcr/symcr.hpp"

namespace specimen_bench {
namespace {

std::uint64_t now_ns() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                        std::chrono::steady_clock::now().time_since_epoch())
                                        .count());
}

std::vector<char> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) die("read", path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const std::string& path, const void* data, std::size_t size) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) die("write", path);
}

// Page faults of this process so far (minor: a first touch of a page of code, data or heap).
std::uint64_t page_faults() {
  rusage usage{};
  ::getrusage(RUSAGE_SELF, &usage);
  return static_cast<std::uint64_t>(usage.ru_minflt + usage.ru_majflt);
}

// Hardware counters of this thread's user-mode execution around the timed part, to see where a
// cold restore's time goes: work (instructions), stalls (cycles), first touches of code and data
// pages the TLBs do not hold, code fetched from beyond the first-level cache. Only with
// SYMCR_COLD_COUNTERS=1 in the environment: switching counters on and off costs system calls
// that would be timed too. A counter the machine or its permissions refuse reads as 0.
class Counters {
 public:
  static constexpr int kCount = 5;
  Counters() {
    const char* wanted = std::getenv("SYMCR_COLD_COUNTERS");
    if (wanted == nullptr || std::strcmp(wanted, "1") != 0) return;
    static const std::uint64_t kCache =
        PERF_COUNT_HW_CACHE_OP_READ << 8 | PERF_COUNT_HW_CACHE_RESULT_MISS << 16;
    const std::pair<std::uint32_t, std::uint64_t> events[kCount] = {
        {PERF_TYPE_HARDWARE, PERF_COUNT_HW_INSTRUCTIONS},
        {PERF_TYPE_HARDWARE, PERF_COUNT_HW_CPU_CYCLES},
        {PERF_TYPE_HW_CACHE, PERF_COUNT_HW_CACHE_ITLB | kCache},
        {PERF_TYPE_HW_CACHE, PERF_COUNT_HW_CACHE_DTLB | kCache},
        {PERF_TYPE_HW_CACHE, PERF_COUNT_HW_CACHE_L1I | kCache}};
    for (int i = 0; i < kCount; ++i) {
      perf_event_attr attr{};
      attr.size = sizeof attr;
      attr.type = events[i].first;
      attr.config = events[i].second;
      attr.disabled = i == 0 ? 1 : 0;  // the group follows its leader
      attr.exclude_kernel = 1;
      attr.exclude_hv = 1;
      fds_[i] =
          static_cast<int>(::syscall(SYS_perf_event_open, &attr, 0, -1, i == 0 ? -1 : fds_[0], 0));
      if (fds_[0] < 0) return;
    }
  }
  ~Counters() {
    for (int fd : fds_) {
      if (fd >= 0) ::close(fd);
    }
  }
  void start() {
    if (fds_[0] >= 0) ::ioctl(fds_[0], PERF_EVENT_IOC_ENABLE, PERF_IOC_FLAG_GROUP);
  }
  void stop() {
    if (fds_[0] < 0) return;
    ::ioctl(fds_[0], PERF_EVENT_IOC_DISABLE, PERF_IOC_FLAG_GROUP);
    for (int i = 0; i < kCount; ++i) {
      std::uint64_t value = 0;
      if (fds_[i] >= 0 &&
          ::read(fds_[i], &value, sizeof value) == static_cast<ssize_t>(sizeof value)) {
        values_[i] = value;
      }
    }
  }
  // "instructions cycles itlb_misses dtlb_misses l1i_misses"
  void print() const {
    for (int i = 0; i < kCount; ++i) {
      std::printf(" %llu", static_cast<unsigned long long>(values_[i]));
    }
  }

 private:
  int fds_[kCount] = {-1, -1, -1, -1, -1};
  std::uint64_t values_[kCount] = {};
};

// --- the child: one restore in a fresh process --------------------------------------------

// The experiment's symcr method: the store is opened when the autopilot starts; the timed part
// is restore_latest(), from the call to the state written. Prints "open_ns restore_ns
// open_faults restore_faults" and the restore's counters.
int child_symcr(const char* store_path, bool (*restored)()) {
  Counters counters;
  const std::uint64_t f0 = page_faults();
  const std::uint64_t t0 = now_ns();
  symcr::Store store;
  const symcr::Status opened = symcr::Store::open(store_path, symcr::StoreOptions{}, store);
  const std::uint64_t t1 = now_ns();
  const std::uint64_t f1 = page_faults();
  if (!opened.ok()) die("open", opened.message());
  counters.start();
  const symcr::Report report = store.restore_latest();
  counters.stop();
  const std::uint64_t t2 = now_ns();
  const std::uint64_t f2 = page_faults();
  if (!report.ok()) die("restore_latest", report.status().message());
  if (!restored()) die("restore_latest", "wrong values restored");
  std::printf("%llu %llu %llu %llu", static_cast<unsigned long long>(t1 - t0),
              static_cast<unsigned long long>(t2 - t1), static_cast<unsigned long long>(f1 - f0),
              static_cast<unsigned long long>(f2 - f1));
  counters.print();
  std::printf("\n");
  return 0;
}

// The experiment's raw-image method: the file is opened when the autopilot starts; the timed
// part reads the image and copies it over `copter`. Only the time is of interest: the image's
// heap and code addresses are the parent's, meaningless here, so the process ends at once,
// running no destructor over them.
int child_raw(const char* image_path) {
  Counters counters;
  const std::uint64_t f0 = page_faults();
  const std::uint64_t t0 = now_ns();
  const int fd = ::open(image_path, O_RDONLY | O_CLOEXEC);
  const std::uint64_t t1 = now_ns();
  const std::uint64_t f1 = page_faults();
  if (fd < 0) die("open", image_path);
  counters.start();
  std::vector<std::uint8_t> image(sizeof(Copter));
  if (::pread(fd, image.data(), image.size(), 0) != static_cast<ssize_t>(image.size())) {
    die("read", image_path);
  }
  std::memcpy(static_cast<void*>(&copter), image.data(), image.size());
  counters.stop();
  const std::uint64_t t2 = now_ns();
  const std::uint64_t f2 = page_faults();
  std::printf("%llu %llu %llu %llu", static_cast<unsigned long long>(t1 - t0),
              static_cast<unsigned long long>(t2 - t1), static_cast<unsigned long long>(f1 - f0),
              static_cast<unsigned long long>(f2 - f1));
  counters.print();
  std::printf("\n");
  std::fflush(stdout);
  std::_Exit(0);
}

// --- the parent ---------------------------------------------------------------------------

struct Timing {
  std::uint64_t open_ns = 0;
  std::uint64_t restore_ns = 0;
  std::uint64_t open_faults = 0;
  std::uint64_t restore_faults = 0;
  std::uint64_t counters[Counters::kCount] = {};
};

// Runs this program again as `--cold-restore-child method path` and reads its timing line.
Timing run_child(const char* method, const std::string& path) {
  const char* self = "/proc/self/exe";
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) die("pipe", std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) die("fork", std::strerror(errno));
  if (pid == 0) {
    ::dup2(pipe_fds[1], STDOUT_FILENO);
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    const char* args[] = {self, "--cold-restore-child", method, path.c_str(), nullptr};
    ::execv(self, const_cast<char* const*>(args));
    std::_Exit(127);
  }
  ::close(pipe_fds[1]);
  std::string text;
  char buffer[256];
  ssize_t got;
  while ((got = ::read(pipe_fds[0], buffer, sizeof buffer)) > 0) text.append(buffer, got);
  ::close(pipe_fds[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  Timing timing;
  unsigned long long open_ns = 0, restore_ns = 0, open_faults = 0, restore_faults = 0;
  unsigned long long c[Counters::kCount] = {};
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 ||
      std::sscanf(text.c_str(), "%llu %llu %llu %llu %llu %llu %llu %llu %llu", &open_ns,
                  &restore_ns, &open_faults, &restore_faults, &c[0], &c[1], &c[2], &c[3],
                  &c[4]) != 4 + Counters::kCount) {
    die("cold restore", std::string("the ") + method + " child failed");
  }
  timing.open_ns = open_ns;
  timing.restore_ns = restore_ns;
  timing.open_faults = open_faults;
  timing.restore_faults = restore_faults;
  for (int i = 0; i < Counters::kCount; ++i) timing.counters[i] = c[i];
  return timing;
}

std::uint64_t median(std::vector<std::uint64_t> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

void print_row(const char* method, const std::vector<Timing>& timings) {
  std::vector<std::uint64_t> restore, open, open_faults, restore_faults;
  std::vector<std::uint64_t> counters[Counters::kCount];
  for (const Timing& t : timings) {
    restore.push_back(t.restore_ns);
    open.push_back(t.open_ns);
    open_faults.push_back(t.open_faults);
    restore_faults.push_back(t.restore_faults);
    for (int i = 0; i < Counters::kCount; ++i) counters[i].push_back(t.counters[i]);
  }
  std::printf(
      "cold-restore %s: runs %zu, restore median %.1f us (min %.1f, max %.1f), "
      "open median %.1f us, page faults median: open %llu, restore %llu\n",
      method, timings.size(), median(restore) / 1000.0,
      *std::min_element(restore.begin(), restore.end()) / 1000.0,
      *std::max_element(restore.begin(), restore.end()) / 1000.0, median(open) / 1000.0,
      static_cast<unsigned long long>(median(open_faults)),
      static_cast<unsigned long long>(median(restore_faults)));
  if (std::getenv("SYMCR_COLD_COUNTERS") == nullptr) return;
  std::printf(
      "cold-restore %s counters median: instructions %llu, cycles %llu, iTLB misses %llu, "
      "dTLB misses %llu, L1i misses %llu\n",
      method, static_cast<unsigned long long>(median(counters[0])),
      static_cast<unsigned long long>(median(counters[1])),
      static_cast<unsigned long long>(median(counters[2])),
      static_cast<unsigned long long>(median(counters[3])),
      static_cast<unsigned long long>(median(counters[4])));
}

int parent(int runs, const std::string& fixture_store, bool (*restored)()) {
  // The raw image of the state a restore brings back, this build's layout.
  {
    const std::string warm = scratch_path("cold-warm.store");
    const std::vector<char> image = read_bytes(fixture_store);
    write_bytes(warm, image.data(), image.size());
    symcr::Store store;
    symcr::Status status = symcr::Store::open(warm.c_str(), symcr::StoreOptions{}, store);
    const symcr::Report report = status.ok() ? store.restore_latest() : symcr::Report();
    if (!status.ok() || !report.ok() || !restored()) die("cold restore", "the warm restore failed");
    store.close();
    ::unlink(warm.c_str());
  }
  const std::string raw_path = scratch_path("cold.raw");
  write_bytes(raw_path, static_cast<const void*>(&copter), sizeof(Copter));
  const std::vector<char> store_image = read_bytes(fixture_store);
  const std::string store_path = scratch_path("cold.store");

  std::vector<Timing> symcr_timings, raw_timings;
  for (int i = 0; i < runs; ++i) {  // interleaved, so that drift hits both alike
    write_bytes(store_path, store_image.data(), store_image.size());  // open may prepare it
    symcr_timings.push_back(run_child("symcr", store_path));
    raw_timings.push_back(run_child("raw-image", raw_path));
  }
  ::unlink(store_path.c_str());
  ::unlink(raw_path.c_str());
  print_row("symcr", symcr_timings);
  print_row("raw-image", raw_timings);
  return 0;
}

}  // namespace

int run_cold_restore_mode(int argc, char** argv, bool (*restored)()) {
  if (argc == 4 && std::strcmp(argv[1], "--cold-restore-child") == 0) {
    if (std::strcmp(argv[2], "symcr") == 0) return child_symcr(argv[3], restored);
    if (std::strcmp(argv[2], "raw-image") == 0) return child_raw(argv[3]);
    die("cold restore", std::string("unknown method ") + argv[2]);
  }
  if (argc == 4 && std::strcmp(argv[1], "--cold-restore") == 0) {
    const int runs = std::atoi(argv[2]);
    if (runs <= 0) die("cold restore", "the number of runs must be positive");
    return parent(runs, argv[3], restored);
  }
  return -1;
}

}  // namespace specimen_bench
