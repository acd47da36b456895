// The "test program" the fuzzers restore into: the hand-written schemas of the engine tests
// (tests/runtime/handwritten_schemas.hpp, in the form symcr-gen emits), each world in its old
// (writer) and patched (reader) build. A fuzz input picks the reader; the writer schema comes
// from the input's bytes, so the same checkpoint meets both an unchanged and a different build.
//
// Every world can be reset to its initial state, with every heap object a restore may have
// created freed again (raw-pointer graphs included), so iterations do not leak into each
// other and LeakSanitizer only reports real leaks.
#ifndef SYMCR_FUZZING_FUZZ_WORLDS_HPP
#define SYMCR_FUZZING_FUZZ_WORLDS_HPP

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "authentication.hpp"
#include "crc32c.hpp"
#include "encode.hpp"
#include "handwritten_schemas.hpp"
#include "record.hpp"
#include "schema_blob.hpp"
#include "symcr/format/bytes.hpp"
#include "symcr/format/hashes.hpp"
#include "symcr/symcr.hpp"

namespace fuzz {

namespace w = engine_tests;

// Heap objects restore creates for raw pointers (through a type's Lifecycle) belong to nobody
// the harness can find reliably (an int32* may hold the only reference, into a node), so the
// pointer worlds' schemas wrap every Lifecycle with a registry: reset_world frees whatever
// restore created and nothing deleted.
struct Registry {
  std::unordered_map<void*, void (*)(void*)> live;
  void free_all() {
    auto objects = std::move(live);
    live.clear();
    for (auto& [object, destroy] : objects) destroy(object);
  }
};
inline Registry registry;

template <typename T>
struct Tracked {
  static void destroy_now(void* object) { delete static_cast<T*>(object); }
  static void* create() {
    T* object = new T();
    registry.live.emplace(object, &destroy_now);
    return object;
  }
  static void destroy(void* object) {
    registry.live.erase(object);
    delete static_cast<T*>(object);
  }
  static constexpr symcr::Lifecycle table{&create, &destroy, nullptr};
};

template <typename... Types>
const symcr::Schema& with_tracked_lifecycles(const symcr::Schema& original) {
  static std::vector<symcr::TypeInfo> types;
  static symcr::Schema schema{};
  if (types.empty()) {
    types.assign(original.types, original.types + original.type_count);
    for (symcr::TypeInfo& type : types) {
      ((type.lifecycle == &symcr::ops::lifecycle<Types>::table
            ? (void)(type.lifecycle = &Tracked<Types>::table)
            : (void)0),
       ...);
    }
    schema = symcr::Schema{types.data(), original.type_count, original.roots, original.root_count,
                           original.program};
  }
  return schema;
}

enum World : std::uint8_t {
  kA0, kA1, kB0, kB1, kC0, kC1, kD0, kD1, kE0, kE1, kT0, kT1, kP, kG, kWorldCount
};

inline const symcr::Schema& world_schema(unsigned world) {
  switch (world % kWorldCount) {
    case kA0: return w::a0::schema();
    case kA1: return w::a1::schema();
    case kB0: return w::b0::schema();
    case kB1: return w::b1::schema();
    case kC0:
      return with_tracked_lifecycles<w::c0::Node, w::c0::Nav, w::c0::Leaf>(w::c0::schema());
    case kC1:
      return with_tracked_lifecycles<w::c1::Node, w::c1::Nav, w::c1::Leaf>(w::c1::schema());
    case kD0: return w::d0::schema();
    case kD1: return w::d1::schema();
    case kE0: return w::e0::schema();
    case kE1: return w::e1::schema();
    case kT0: return w::t0::schema();
    case kT1: return w::t1::schema();
    case kP: return w::p::schema();
    default: return with_tracked_lifecycles<w::g::Node>(w::g::schema());
  }
}

inline const char* world_name(unsigned world) {
  static const char* const kNames[] = {"a0", "a1", "b0", "b1", "c0", "c1", "d0",
                                       "d1", "e0", "e1", "t0", "t1", "p",  "g"};
  return kNames[world % kWorldCount];
}

inline void reset_world(unsigned world) {
  switch (world % kWorldCount) {
    case kA0:
      w::a0::basic = w::a0::Basic{};
      w::a0::old_counter = 0;
      w::a0::gone_root = 0;
      break;
    case kA1:
      w::a1::basic = w::a1::Basic{};
      w::a1::counter = -1;
      w::a1::new_root = 99;
      break;
    case kB0: w::b0::bag = w::b0::Bag{}; break;
    case kB1: w::b1::bag = w::b1::Bag{}; break;
    case kC0: w::c0::world = w::c0::World{}; registry.free_all(); break;
    case kC1: w::c1::world = w::c1::World{}; registry.free_all(); break;
    case kD0: w::d0::derived = w::d0::Derived{}; break;
    case kD1: w::d1::derived = w::d1::Derived{}; break;
    case kE0:
      w::e0::small = w::e0::Small{};
      w::e0::good = w::e0::Checked{};
      w::e0::bad = w::e0::Checked{};
      break;
    case kE1:
      w::e1::small = w::e1::Small{};
      w::e1::good = w::e1::Checked{};
      w::e1::bad = w::e1::Checked{};
      break;
    case kT0: w::t0::tree = w::t0::Tree{}; w::t0::many.clear(); break;
    case kT1: w::t1::tree = w::t1::Tree{}; w::t1::many.clear(); break;
    case kP: w::p::state = w::p::State{}; break;
    default: w::g::graph = w::g::Graph{}; registry.free_all(); break;
  }
}

// Gives the pointer worlds a live object of the new build for restore to fill.
inline void preset_live_objects(unsigned world) {
  switch (world % kWorldCount) {
    case kC0: w::c0::world.head = static_cast<w::c0::Node*>(Tracked<w::c0::Node>::create()); break;
    case kC1: w::c1::world.head = static_cast<w::c1::Node*>(Tracked<w::c1::Node>::create()); break;
    case kG: w::g::graph.first = static_cast<w::g::Node*>(Tracked<w::g::Node>::create()); break;
    case kB1: w::b1::bag.up.reset(new w::b1::Item()); break;
    default: break;
  }
}

// The user's rules in the reader builds (the range on a1's basic.speed, e1's validator on
// Checked): whatever a restore did, no live value may break them.
inline bool world_rules_hold(unsigned world) {
  switch (world % kWorldCount) {
    case kA1: {
      const std::int32_t speed = w::a1::basic.speed;
      return speed == -1 || (speed >= 0 && speed <= 100);
    }
    case kE1: return w::e1::validate_checked(&w::e1::good) && w::e1::validate_checked(&w::e1::bad);
    default: return true;
  }
}

// The live state of a world as bytes (its own checkpoint payload): how the fuzzers check that
// a refused restore changed nothing.
inline std::vector<std::uint8_t> world_snapshot(unsigned world) {
  std::vector<std::uint8_t> out;
  const symcr::Status status = symcr::detail::encode_payload(world_schema(world), out);
  if (!status.ok()) {
    out.assign(status.message(), status.message() + std::strlen(status.message()));
    out.push_back(static_cast<std::uint8_t>(status.error()));
  }
  return out;
}

// Makes a mutated record's integrity fields consistent again (the inline schema's FNV-1a hash
// and the CRC-32C), so the fuzzer reaches the schema parser and the payload decoder instead of
// stopping at the checksum. Sizes are left as they are: only fields that fit are fixed. With
// keys set, an authenticated record is signed again for `binding` (a store slot's), or as a
// standalone checkpoint when null.
inline void fix_record_integrity(std::uint8_t* p, std::size_t size,
                                 const symcr::detail::RecordBinding* binding = nullptr) {
  if (size < symcr::format::kRecordHeaderSize) return;
  const std::uint64_t header_size =
      symcr::format::load16(p + symcr::format::kRecordHeaderSizeOffset);
  const std::uint32_t flags = symcr::format::load32(p + symcr::format::kRecordFlagsOffset);
  const std::uint64_t schema_size =
      symcr::format::load32(p + symcr::format::kRecordSchemaSizeOffset);
  const std::uint64_t payload_size =
      symcr::format::load32(p + symcr::format::kRecordPayloadSizeOffset);
  if ((flags & symcr::format::kRecordSchemaInline) && header_size + schema_size <= size) {
    symcr::format::store64(p + symcr::format::kRecordSchemaHashOffset,
                           symcr::format::fnv1a64(p + header_size, schema_size));
  }
  const std::uint64_t total = header_size + schema_size + payload_size;
  // With keys set, an authenticated record is signed again, so that mutations get past the MAC
  // (its MAC version and journal freshness stay as mutated: the reader checks them).
  const symcr::detail::KeySnapshot keys = symcr::detail::current_keys();
  if (keys && (flags & symcr::format::kRecordAuthenticated) &&
      header_size >= symcr::format::kRecordAuthenticatedHeaderSize && total <= size) {
    symcr::detail::RecordBinding standalone;
    if (binding == nullptr) {
      if ((flags & symcr::format::kRecordSchemaInline) && header_size + schema_size <= size) {
        symcr::detail::schema_digest(p + header_size, schema_size, standalone.schema_digest);
      }
      binding = &standalone;
    }
    symcr::format::store32(p + symcr::format::kRecordKeyIdOffset, keys->signing().id);
    symcr::detail::sign_record(*keys, p, total, *binding);
  }
  if (header_size >= symcr::format::kRecordHeaderSize && total <= size) {
    symcr::format::store32(p + symcr::format::kRecordChecksumOffset, 0);
    symcr::format::store32(p + symcr::format::kRecordChecksumOffset,
                           symcr::detail::crc32c(p, total));
  }
}

// The key the fuzzers authenticate with (control bit 7 of the record target).
inline void use_fuzz_key(bool on) {
  static const std::uint8_t kKey[] = {'f', 'u', 'z', 'z', '-', 'k', 'e', 'y'};
  const symcr::CheckpointKey fuzz_key{9, kKey, sizeof kKey};
  (void)symcr::set_checkpoint_keys(&fuzz_key, on ? 1 : 0);
}

}  // namespace fuzz

#endif  // SYMCR_FUZZING_FUZZ_WORLDS_HPP
