// Saving: the region index (encoder.hpp), which saved object or container run holds an
// address; regions may not overlap unless one contains the other by type.
#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <vector>

#include "encoder.hpp"

namespace symcr::detail::encoding {

// ---- the region index ----------------------------------------------------------------
// Small regions are chained from every 64-byte bucket they touch; large ones sit in a list.
std::uint32_t Encoder::find_region(std::uintptr_t address) {
  if (std::uint32_t* head = s_.buckets.find(address >> kBucketShift, 0)) {
    for (std::uint32_t link = *head; link != kNoRegion; link = s_.chain[link].next) {
      const ChainLink& entry = s_.chain[link];
      if (address >= entry.start && address < entry.end) return entry.region;
    }
  }
  for (std::uint32_t index : s_.large_regions) {
    const Region& region = s_.regions[index];
    if (address >= region.start && address < region.end) return index;
  }
  return kNoRegion;
}

std::uint32_t Encoder::overlapping(const Region& candidate) {
  for (std::uint32_t index : s_.large_regions) {
    const Region& region = s_.regions[index];
    if (candidate.start < region.end && region.start < candidate.end) return index;
  }
  const std::uintptr_t first = candidate.start >> kBucketShift;
  const std::uintptr_t last = (candidate.end - 1) >> kBucketShift;
  for (std::uintptr_t bucket = first; bucket <= last; ++bucket) {
    std::uint32_t* head = s_.buckets.find(bucket, 0);
    if (!head) continue;
    for (std::uint32_t link = *head; link != kNoRegion; link = s_.chain[link].next) {
      const ChainLink& entry = s_.chain[link];
      if (candidate.start < entry.end && entry.start < candidate.end) return entry.region;
    }
  }
  return kNoRegion;
}

std::uint32_t Encoder::add_region(const Region& region, bool heap_object) {
  const auto index = static_cast<std::uint32_t>(s_.regions.size());
  if (!track_regions_ || (heap_object && !exact_)) {
    s_.regions.push_back(region);
    return index;
  }
  const std::uint32_t other = overlapping(region);
  if (other != kNoRegion) {
    fail_overlap(region, s_.regions[other]);
    return index;
  }
  s_.regions.push_back(region);
  if (region.end - region.start >= kLargeRegion) {
    s_.large_regions.push_back(index);
    return index;
  }
  const std::uintptr_t first = region.start >> kBucketShift;
  const std::uintptr_t last = (region.end - 1) >> kBucketShift;
  for (std::uintptr_t bucket = first; bucket <= last; ++bucket) {
    bool inserted = false;
    std::uint32_t& head = s_.buckets.find_or_insert(bucket, 0, kNoRegion, inserted);
    const std::uint32_t link = static_cast<std::uint32_t>(s_.chain.size());
    s_.chain.push_back(ChainLink{region.start, region.end, index, head});
    head = link;
  }
  return index;
}

void Encoder::describe(const Region& region, char* buffer, std::size_t size) const {
  const char* type = types_[region.type].name;
  switch (region.kind) {
    case RegionKind::Object:
      if (region.object < schema_.root_count) {
        std::snprintf(buffer, size, "root '%s'", schema_.roots[region.object].name);
      } else {
        std::snprintf(buffer, size, "heap object #%u (%s)", region.object - schema_.root_count,
                      type);
      }
      return;
    case RegionKind::ContainerRun:
      std::snprintf(buffer, size, "elements of container #%u (%s)", region.object, type);
      return;
    case RegionKind::Owned:
      std::snprintf(buffer, size, "a unique_ptr's %s", type);
      return;
    case RegionKind::StringChars:
      std::snprintf(buffer, size, "the characters (%s) of a string", type);
      return;
  }
}

void Encoder::fail_overlap(const Region& added, const Region& existing) {
  char a[120], b[120];
  describe(added, a, sizeof a);
  describe(existing, b, sizeof b);
  error_ = Status(Error::Unsupported,
                  "cannot save: %s at %p overlaps %s at %p; a pointer to the inside of an "
                  "object was met before any pointer to the object itself",
                  a, reinterpret_cast<const void*>(added.start), b,
                  reinterpret_cast<const void*>(existing.start));
}

}  // namespace symcr::detail::encoding
