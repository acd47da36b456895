// Saving: what each pointer points to (encoder.hpp). A target is classified once: inside a
// saved region, outside the state, or a new heap object (saved as its dynamic type when its
// class is polymorphic); at the end it is resolved into a base object or container element
// plus symbolic steps (docs/format.md §3).
#include <algorithm>
#include <cstdarg>
#include <cstdio>
#include <cstring>
#include <vector>

#include "encoder.hpp"

namespace symcr::detail::encoding {

bool Encoder::is_outside(std::uintptr_t address) {
  // Roots (and container elements, unique_ptr pointees) are indexed when raw pointers exist.
  if ((track_regions_ ? find_region(address) : find_root(address)) != kNoRegion) return false;
  if (!memory_refreshed_) {
    s_.memory.refresh();
    memory_refreshed_ = true;
  }
  return s_.memory.is_static_or_stack(address);
}

std::uint32_t Encoder::find_root(std::uintptr_t address) const {
  for (std::uint32_t r = 0; r < schema_.root_count; ++r) {
    const auto start = reinterpret_cast<std::uintptr_t>(schema_.roots[r].address);
    if (address >= start && address < start + size_of(schema_.roots[r].type)) return r;
  }
  return kNoRegion;
}

void Encoder::classify(std::size_t i) {
  const PointerTarget reference = s_.references[i];
  // Without raw pointers every target is a shared_ptr's whole object, deduplicated by the
  // memo already: no region lookup is needed.
  std::uint32_t region = track_regions_ ? find_region(reference.address) : kNoRegion;
  if (region == kNoRegion) region = new_heap_object(reference);
  s_.references[i].region = region;
}

std::uint32_t Encoder::new_heap_object(const PointerTarget& reference) {
  std::uintptr_t start = reference.address;
  std::uint32_t type = reference.type;
  if (types_[type].flags & kTypePolymorphic) {
    // Saved as its dynamic type, or refused: an object of the static type would be sliced.
    if (!dynamic_type(start, type)) {
      char candidates[80];
      list_dynamic_types(reference.type, candidates, sizeof candidates);
      fail_unsupported(
          "a pointer to polymorphic class %s at %p: its object is no member or "
          "element of the state, and not of a class this build can create (%s)",
          types_[reference.type].name, reinterpret_cast<const void*>(reference.address),
          candidates);
      return 0;
    }
  }
  const std::uint32_t object = schema_.root_count + static_cast<std::uint32_t>(s_.heap.size());
  const std::uint32_t region =
      add_region(Region{start, start + size_of(type), type, RegionKind::Object, object, 0, 0, 0, 0},
                 /*heap_object=*/true);
  if (!ok()) return region;
  put_u32(type);
  s_.heap.push_back(HeapObject{region, pos_});
  put_u8(reference.shared ? 1 : 0);
  encode(type, reinterpret_cast<const std::uint8_t*>(start));
  return region;
}

// Itanium C++ ABI: an object's vtable pointer is its first word, and the word two before
// the address it holds is the offset from this subobject to the complete object, whose own
// vtable pointer identifies its class. On success, `address` and `type` are the complete
// object's.
bool Encoder::dynamic_type(std::uintptr_t& address, std::uint32_t& type) const {
  const auto* vtable = *reinterpret_cast<const std::ptrdiff_t* const*>(address);
  const std::uintptr_t complete = address + static_cast<std::uintptr_t>(vtable[-2]);
  const void* complete_vtable = *reinterpret_cast<const void* const*>(complete);
  for (const SchemaFacts::DynamicType& candidate : facts_.dynamic_types) {
    if (candidate.vtable == complete_vtable) {
      address = complete;
      type = candidate.type;
      return true;
    }
  }
  return false;
}

void Encoder::list_dynamic_types(std::uint32_t base, char* out, std::size_t size) const {
  std::size_t used = 0;
  out[0] = '\0';
  std::vector<std::uint32_t> pending;
  std::vector<bool> derived;  // the candidate and its bases
  for (const SchemaFacts::DynamicType& candidate : facts_.dynamic_types) {
    pending.assign(1, candidate.type);
    derived.clear();
    mark_with_bases(types_, schema_.type_count, pending, derived);
    if (!derived[base]) continue;
    const int n = std::snprintf(out + used, size - used, "%s%s", used ? ", " : "",
                                types_[candidate.type].name);
    if (n < 0 || static_cast<std::size_t>(n) >= size - used) break;
    used += static_cast<std::size_t>(n);
  }
  if (used == 0) std::snprintf(out, size, "none derives from %s", types_[base].name);
}

// A shared_ptr target must be a whole heap object: sharing is kept by owning it.
void Encoder::check_shared_targets() {
  for (const PointerTarget& reference : s_.references) {
    if (!reference.shared) continue;
    const Region& region = s_.regions[reference.region];
    const bool whole_heap_object =
        region.kind == RegionKind::Object && region.object >= schema_.root_count &&
        region.start == reference.address && region.type == reference.type;
    if (!whole_heap_object) {
      return fail_unsupported(
          "a shared_ptr<%s> whose object (%p) lies inside another "
          "checkpointed object",
          types_[reference.type].name, reinterpret_cast<const void*>(reference.address));
    }
    out_[s_.heap[region.object - schema_.root_count].owner_byte] = 1;
  }
}

// ---- reference resolution ------------------------------------------------------------
// Descends from an object of `type` at `base` to the subobject of `target_type` at
// `target`, appending steps; backtracks where several fields start at the same address.
bool Encoder::descend(std::uint32_t type_index, std::uintptr_t base, std::uintptr_t target,
                      std::uint32_t target_type) {
  if (target == base && type_index == target_type) return true;
  const TypeInfo& type = types_[type_index];
  switch (type.kind) {
    case Kind::Struct:
      for (std::uint32_t f = 0; f < type.field_count; ++f) {
        const FieldInfo& field = type.fields[f];
        if (field.bit_width) continue;
        const std::uintptr_t start = base + field.offset;
        if (target < start || target >= start + size_of(field.type)) continue;
        s_.steps.push_back(f);
        if (descend(field.type, start, target, target_type)) return true;
        s_.steps.pop_back();
      }
      return false;
    case Kind::Array: {
      const std::uint32_t stride = size_of(type.element);
      const std::uint64_t index = (target - base) / stride;
      if (index >= type.count) return false;
      s_.steps.push_back(static_cast<std::uint32_t>(index));
      if (descend(type.element, base + index * stride, target, target_type)) return true;
      s_.steps.pop_back();
      return false;
    }
    case Kind::Optional: {
      const void* value =
          static_cast<const OptionalOps*>(type.ops)->get(reinterpret_cast<const void*>(base));
      const auto start = reinterpret_cast<std::uintptr_t>(value);
      if (!value || target < start || target >= start + size_of(type.element)) return false;
      s_.steps.push_back(0);
      if (descend(type.element, start, target, target_type)) return true;
      s_.steps.pop_back();
      return false;
    }
    case Kind::String: {
      // A character: the step is its index, up to the terminator's position.
      const auto* ops = static_cast<const StringOps*>(type.ops);
      const auto* object = reinterpret_cast<const void*>(base);
      const auto start = reinterpret_cast<std::uintptr_t>(ops->data(object));
      const std::uint32_t width = size_of(type.element);
      if (target_type != type.element || target < start || (target - start) % width != 0) {
        return false;
      }
      const std::uint64_t index = (target - start) / width;
      if (index > ops->size(object) || index > 0xFFFFFFFFu) return false;
      s_.steps.push_back(static_cast<std::uint32_t>(index));
      return true;
    }
    case Kind::Variant: {
      const auto* ops = static_cast<const VariantOps*>(type.ops);
      const auto* object = reinterpret_cast<const void*>(base);
      const std::uint32_t index = ops->index(object);
      if (index >= type.alternative_count) return false;
      const auto start = reinterpret_cast<std::uintptr_t>(ops->get(object));
      const std::uint32_t alternative = type.alternatives[index];
      if (target < start || target >= start + size_of(alternative)) return false;
      s_.steps.push_back(index);
      if (descend(alternative, start, target, target_type)) return true;
      s_.steps.pop_back();
      return false;
    }
    default:
      return false;
  }
}

// Fills s_.steps and `base` for the subobject of `type` at `address` inside `region_index`.
bool Encoder::resolve(std::uint32_t region_index, std::uintptr_t address, std::uint32_t type,
                      Base& base, int depth) {
  const Region region = s_.regions[region_index];
  switch (region.kind) {
    case RegionKind::Object:
      base = Base{kBaseObject, region.object, 0};
      return descend(region.type, region.start, address, type);
    case RegionKind::ContainerRun: {
      const std::uint32_t offset =
          static_cast<std::uint32_t>((address - region.start) / region.stride);
      base = Base{kBaseElement, region.object, region.first_index + offset};
      return descend(region.type, region.start + std::uintptr_t{offset} * region.stride, address,
                     type);
    }
    case RegionKind::StringChars: {
      if (depth > kMaxValueNesting) return false;
      const std::uint32_t owner = find_region(region.owner_slot);
      return owner != kNoRegion &&
             resolve(owner, region.owner_slot, region.owner_type, base, depth + 1) &&
             descend(region.owner_type, region.owner_slot, address, type);
    }
    case RegionKind::Owned: {
      if (depth > kMaxValueNesting) return false;
      const std::uint32_t owner = find_region(region.owner_slot);
      if (owner == kNoRegion ||
          !resolve(owner, region.owner_slot, region.owner_type, base, depth + 1)) {
        return false;
      }
      s_.steps.push_back(0);
      return descend(region.type, region.start, address, type);
    }
  }
  return false;
}

void Encoder::write_reference(std::size_t i) {
  const PointerTarget& reference = s_.references[i];
  s_.steps.clear();
  Base base{};
  if (!resolve(reference.region, reference.address, reference.type, base, 0)) {
    if (!exact_) {
      // Resolution may need a heap object in the index (a unique_ptr inside a heap
      // object owning the target): decide in the exact pass.
      overlap_suspected_ = true;
      return;
    }
    char where[120];
    describe(s_.regions[reference.region], where, sizeof where);
    return fail_unsupported(
        "a pointer to %s at %p: it lies inside %s but not at a %s "
        "subobject",
        types_[reference.type].name, reinterpret_cast<const void*>(reference.address), where,
        types_[reference.type].name);
  }
  if (s_.steps.size() > 0xFFFF) return fail_unsupported("a pointer nested 65536 levels deep");
  put_u8(base.kind);
  put_u32(base.a);
  if (base.kind == 1) put_u32(base.b);
  put_u16(static_cast<std::uint16_t>(s_.steps.size()));
  put_bytes(s_.steps.data(), s_.steps.size() * 4);
  put_u32(reference.type);
}

}  // namespace symcr::detail::encoding
