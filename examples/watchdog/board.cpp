#include "board.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <symcr/device.hpp>
#include <vector>

namespace board {
namespace {

using symcr::device::Result;

constexpr std::size_t kBackupRamSize = 4096;  // what the board keeps across a reset
constexpr std::size_t kSlotSize = 512;        // four slots
constexpr std::uint64_t kCheckpointEvery = 50;

std::uint8_t record[kSlotSize];
std::uint8_t scratch[kSlotSize];

// The backup RAM: a file of kBackupRamSize bytes, mapped shared so that what the firmware
// writes is there at the next boot (zeroes at the first, as after a power cut).
std::uint8_t* map_backup_ram(const char* path) {
  const int fd = ::open(path, O_RDWR | O_CREAT, 0600);
  if (fd < 0 || ::ftruncate(fd, kBackupRamSize) != 0) return nullptr;
  void* memory = ::mmap(nullptr, kBackupRamSize, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  ::close(fd);
  return memory == MAP_FAILED ? nullptr : static_cast<std::uint8_t*>(memory);
}

[[noreturn]] void watchdog_reset() {
  std::printf("watchdog reset\n");
  std::fflush(stdout);
  std::_Exit(0);  // no destructors, no clean-up: the board simply restarts
}

bool read_file(const char* path, std::vector<std::uint8_t>& out) {
  std::FILE* file = std::fopen(path, "rb");
  if (file == nullptr) return false;
  std::uint8_t buffer[512];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) != 0;) {
    out.insert(out.end(), buffer, buffer + n);
  }
  std::fclose(file);
  return true;
}

bool write_file(const char* path, const std::uint8_t* data, std::size_t size) {
  std::FILE* file = std::fopen(path, "wb");
  if (file == nullptr) return false;
  const bool written = std::fwrite(data, 1, size, file) == size;
  return std::fclose(file) == 0 && written;
}

// --save-initial and --export: what the update tool asks of a firmware over its link.
int save_record(const symcr::device::Build& build, std::uint64_t sequence, const char* path) {
  std::size_t size = 0;
  const Result saved = symcr::device::save(build, sequence, record, sizeof record, &size);
  if (saved != Result::Ok || !write_file(path, record, size)) {
    std::fprintf(stderr, "cannot save %s: %s\n", path, symcr::device::result_text(saved));
    return 1;
  }
  std::printf("%s: saved %s (%zu bytes)\n", kVersion, path, size);
  return 0;
}

}  // namespace

int run(int argc, char** argv) {
  const char* backup = nullptr;
  const char* restore_from = nullptr;
  const char* export_to = nullptr;
  const char* save_initial = nullptr;
  unsigned long loops = 0;
  for (int i = 1; i + 1 < argc; i += 2) {
    const char* value = argv[i + 1];
    if (std::strcmp(argv[i], "--backup") == 0)
      backup = value;
    else if (std::strcmp(argv[i], "--loops") == 0)
      loops = std::strtoul(value, nullptr, 10);
    else if (std::strcmp(argv[i], "--restore-from") == 0)
      restore_from = value;
    else if (std::strcmp(argv[i], "--export") == 0)
      export_to = value;
    else if (std::strcmp(argv[i], "--save-initial") == 0)
      save_initial = value;
  }
  const symcr::device::Build build = symcr::device::program_build();
  if (save_initial != nullptr) return save_record(build, 0, save_initial);
  std::uint8_t* ram = backup != nullptr ? map_backup_ram(backup) : nullptr;
  symcr::device::Ring ring;
  if (ram == nullptr ||
      ring.open(symcr::device::memory_storage(ram, kBackupRamSize), kSlotSize) != Result::Ok) {
    std::fprintf(stderr,
                 "usage: %s --backup <file> [--loops N] [--restore-from <record>] "
                 "[--export <record>] [--save-initial <record>]\n",
                 argv[0]);
    return 2;
  }

  // Boot: the state of the newest checkpoint this build can restore.
  std::uint64_t sequence = 0;
  std::size_t skipped = 0;
  Result restored;
  if (restore_from != nullptr) {  // the first boot after an update: the converted record
    std::vector<std::uint8_t> bytes;
    restored = read_file(restore_from, bytes)
                   ? symcr::device::restore(build, bytes.data(), bytes.size(), scratch,
                                            sizeof scratch, &sequence)
                   : Result::Truncated;
  } else {
    restored = ring.restore_latest(build, record, sizeof record, scratch, sizeof scratch, &sequence,
                                   nullptr, &skipped);
  }
  if (restored == Result::Ok) {
    std::printf("%s: boot: restored checkpoint #%llu\n", kVersion,
                static_cast<unsigned long long>(sequence));
  } else if (restored == Result::Empty) {
    std::printf("%s: boot: no checkpoint yet: initial state\n", kVersion);
  } else {
    std::printf("%s: boot: nothing restored (%s): initial state\n", kVersion,
                symcr::device::result_text(restored));
  }
  print_state();
  if (export_to != nullptr) {
    return restored == Result::Ok ? save_record(build, sequence, export_to) : 1;
  }

  for (unsigned long i = 0; i < loops; ++i) {
    fly_one_loop();
    if (loop_count() % kCheckpointEvery == 0) {
      const Result saved = ring.save(build, record, sizeof record);
      std::printf("%s: checkpoint #%llu at loop %llu%s%s\n", kVersion,
                  static_cast<unsigned long long>(ring.last_sequence()),
                  static_cast<unsigned long long>(loop_count()), saved == Result::Ok ? "" : ": ",
                  saved == Result::Ok ? "" : symcr::device::result_text(saved));
      print_state();
    }
  }
  print_state();
  watchdog_reset();
}

}  // namespace board
