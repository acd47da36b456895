// Another build's schema laid out in this machine's memory, with its roots allocated: what
// `symcr convert` restores a checkpoint into and saves the result from. A payload depends on
// kinds, member order, scalar sizes and bit-field widths, never on offsets, so a layout of our
// own (pointers this machine's size, everything else as the build had it) writes exactly the
// payload the build itself would. Only the kinds that need no code of the build's are laid out:
// the device profile's (bool, integers, floating point, enums, structs, unions, fixed arrays,
// raw pointers).
#ifndef SYMCR_CLI_HOST_LAYOUT_HPP
#define SYMCR_CLI_HOST_LAYOUT_HPP

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"

namespace symcr::cli {

class HostLayout {
 public:
  // Lays `build` out and allocates its roots, zero-filled. `build` must outlive this object (its
  // names, enumerators and ranges are shared). Unsupported names the first kind that needs the
  // build's code. A schema file's sizes are not trusted with memory: roots larger in all than
  // kAlwaysAllowed, or than kBytesPerInputByte per byte of `input_size` (the files the
  // conversion reads), are refused (TooLarge) before anything is allocated.
  static constexpr std::uint64_t kAlwaysAllowed = std::uint64_t{64} << 20;
  static constexpr std::uint64_t kBytesPerInputByte = 16;
  Status lay_out(const Schema& build, std::uint64_t input_size);
  const Schema& schema() const { return schema_; }
  // After lay_out: a restore into the layout moves the times of each clock named in `now` as
  // the build's own restore would in a process whose clock reads now[name]; the times of
  // other clocks stay as saved. Each call replaces the last one's readings. Process-wide: one
  // layout's clocks are read at a time.
  static constexpr std::uint32_t kMaxClocks = 64;
  Status read_clocks_as(const std::map<std::string, std::int64_t>& now);

 private:
  struct Extent {
    std::uint32_t size = 0, align = 0;
    bool done = false;
  };
  Status extent_of(std::uint32_t type, int depth);

  const Schema* build_ = nullptr;
  std::vector<TypeInfo> types_;
  std::vector<std::vector<FieldInfo>> fields_;
  std::vector<Extent> extents_;
  std::vector<RootInfo> roots_;
  std::vector<ClockInfo> clocks_;  // the build's, reading the conversion's "now"
  std::vector<FieldTime> times_;   // the time fields', naming clocks_
  bool clocks_copied_ = false;
  std::vector<std::unique_ptr<std::max_align_t[]>> memory_;
  Schema schema_{};
};

}  // namespace symcr::cli

#endif  // SYMCR_CLI_HOST_LAYOUT_HPP
