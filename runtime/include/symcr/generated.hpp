// The contract between the code symcr-gen emits and the runtime: the schema tables (types,
// fields, enumerators, roots), the per-kind operations tables and lifecycles, and the program's
// serialised schema. User code never needs to include or read this header: programs use
// <symcr/symcr.hpp>, migration hooks <symcr/old_values.hpp>.
//
// symcr-gen emits one `symcr::Schema` per program as constant tables. The runtime walks live
// memory with it when saving, serialises it into checkpoints (docs/format.md), and resolves a
// checkpoint's (writer) schema against the running build's (reader) schema when restoring.
// Nothing here allocates or needs exceptions/RTTI. Change it only together with the generator
// and docs/format.md.
#ifndef SYMCR_GENERATED_HPP
#define SYMCR_GENERATED_HPP

#include <cstddef>
#include <cstdint>

// symcr_program_schema(), which the generated code defines, and what C code shares
#include "symcr/generated.h"

namespace symcr {

class OldValues;  // <symcr/old_values.hpp>: a migration hook's view of the checkpoint's value

// The kind of a type. The numeric values are part of the checkpoint format.
enum class Kind : std::uint8_t {
  Bool = 1,        // bool; 1 byte on the wire (0 or 1)
  Int = 2,         // signed integer of `size` bytes (char, short, int, long, long long, wchar_t...)
  UInt = 3,        // unsigned integer of `size` bytes (incl. char8/16/32_t, unsigned char)
  Float = 4,       // IEEE binary32 (size 4), binary64 (8), x87 extended long double (16)
  Enum = 5,        // scoped or not; `element` is the underlying Int/UInt type; has enumerators
  Struct = 6,      // class/struct/pair/tuple; `fields` (bases first, flagged kFieldBase)
  Union = 7,       // raw bytes of `size` (the largest member), as in the paper
  Array = 8,       // fixed array or std::array: `count` elements of `element`
  String = 9,      // std::basic_string; `element` is the character type; ops: StringOps
  Container = 10,  // vector/deque/list/set/map/...: elements of `element`; ops: ContainerOps
  Optional = 11,   // std::optional<element>; ops: OptionalOps
  Variant = 12,    // std::variant<alternatives...>; ops: VariantOps
  Pointer = 13,    // raw T*; `element` is T; target restored symbolically (docs/resolution.md)
  UniquePtr = 14,  // std::unique_ptr<element>; owns its pointee; ops: UniquePtrOps
  SharedPtr = 15,  // std::shared_ptr<element>; sharing kept; ops: SharedPtrOps
};

// Which standard container a Kind::Container type is. Informational (names, CLI); restore
// treats any container as "its contents" (docs/resolution.md).
enum class ContainerKind : std::uint8_t {
  Vector = 1,
  Deque,
  List,
  ForwardList,
  Set,
  MultiSet,
  UnorderedSet,
  UnorderedMultiSet,
  Map,
  MultiMap,
  UnorderedMap,
  UnorderedMultiMap,
};

constexpr std::uint32_t kNoType = 0xFFFFFFFFu;

// TypeInfo::flags
enum : std::uint32_t {
  kTypeScopedEnum = 1u << 0,     // enum class
  kTypeShallow = 1u << 1,        // a shallow root's restricted view of its class (§3)
  kTypeMigrated = 1u << 2,       // the build has a symcr_migrate hook for the type; recorded in
                                 // schema files so that `symcr plan` reports the migration
  kTypeCreatable = 1u << 3,      // the build has a Lifecycle for the type (restore can create it
                                 // on the heap); recorded in schema files so that `symcr plan`
                                 // foresees heap objects rebuilt through raw pointers
  kTypeValidated = 1u << 4,      // the build has a symcr_validate for the type; recorded in schema
                                 // files so that `symcr plan` says it cannot foresee the verdict
  kTypePolymorphic = 1u << 5,    // a class with virtual functions (not final): a raw pointer to it
                                 // targets a checkpointed object (a member, an element) or a heap
                                 // object of one of the build's kTypeDynamicType classes
  kTypeLeavesMembers = 1u << 6,  // left_to_new_build lists members this build never restores
                                 // (const, reference, function and member pointers): a
                                 // checkpoint's value for one of them is not lost but left
  kTypeDynamicType = 1u << 7,    // a class restore can create as the dynamic type of a heap
                                 // object behind a pointer to one of its polymorphic bases: its
                                 // Lifecycle names its vtable, by which saving recognises it
  kTypeReferenceMembers = 1u << 8,  // reference_members lists members a pointer may target
                                    // although their values are not saved (format.md §2)
  kTypeNeverOwns = 1u << 9,  // a Pointer declared never to own a heap object (SYMCR_NOT_OWNER):
                             // it targets the state or lies outside it, never a heap object
};

// FieldInfo::flags
enum : std::uint32_t {
  kFieldBase = 1u << 0,       // a base-class subobject; `name` is the base's type name
  kFieldHasRange = 1u << 1,   // range_min/range_max validate restored values
  kFieldClockTime = 1u << 2,  // a time of a named clock (`time`): rebased on restore
};

// RootInfo::flags
enum : std::uint32_t {
  kRootShallow = 1u << 0,
};

struct EnumeratorInfo {
  const char* name;    // unqualified enumerator name, e.g. "AUTO"
  std::int64_t value;  // its value (unsigned 64-bit enumerators are stored bit-cast)
};

// SYMCR_RANGE's inclusive bounds on a member's value. Apart from FieldInfo: few members have one.
struct FieldRange {
  double min;
  double max;
};

// A clock the program names (symcr-gen's `clock(...)`): checkpoints record its reading, and a
// restore in another process moves the clock's times by its advance since the checkpoint.
// Clocks are numbered in the byte order of their names (docs/format.md §3).
struct ClockInfo {
  const char* name;        // null in the device profile's tables
  std::int64_t (*read)();  // the program's reading function; null in a schema without code
  std::uint32_t index;     // this clock's number among the schema's clocks
};

// A member that holds a time of `clock` (kFieldClockTime). `never` (0 unless annotated) means
// "no time yet" and is restored as it is.
struct FieldTime {
  const ClockInfo* clock;
  std::int64_t never;
};

struct FieldInfo {
  const char* name;                 // source name of the member (or base type name)
  std::uint32_t type;               // index into Schema::types
  std::uint32_t offset;             // byte offset in the enclosing object; for a bit-field,
                                    // the offset of the storage unit it lives in
  std::uint16_t bit_offset;         // bit-field: first bit within the unit (LSB = 0)
  std::uint16_t bit_width;          // bit-field width in bits; 0 = not a bit-field
  std::uint32_t flags;              // kField*
  const char* const* renamed_from;  // nullptr-terminated list of old names, or nullptr
  const FieldRange* range;          // with kFieldHasRange: the bounds on the value; else null
  const FieldTime* time;            // with kFieldClockTime: the clock of its times; else null
};

// Per-kind operations: the only code the runtime cannot derive from offsets. Implemented as
// templates in <symcr/ops.hpp>; the generator instantiates them per type.
// For types that are heap-allocated or staged: create, destroy, vtable. One type with the
// generated code of C sources, which defines lifecycles too (<symcr/generated.h>).
typedef ::symcr_lifecycle Lifecycle;

struct StringOps {
  std::size_t (*size)(const void* s);  // in characters
  const void* (*data)(const void* s);
  void (*assign)(void* s, const void* chars, std::size_t n);
};

struct ContainerOps {
  std::size_t (*size)(const void* c);
  // Save: calls visit(context, element) for each element in iteration order.
  void (*for_each)(const void* c, void (*visit)(void* context, const void* element), void* context);
  // Element i in iteration order (O(i) for node containers); nullptr if out of range.
  void* (*element_at)(void* c, std::size_t i);
  void (*clear)(void* c);
  void (*reserve)(void* c, std::size_t n);  // no-op where meaningless
  // Sequences: append a value-initialised element and return it (stable until the next
  // append only for vectors, which is why restore reserves first). nullptr for associative.
  void* (*append)(void* c);
  // Associative containers: insert a staged element (created and destroyed with the element
  // type's Lifecycle); moves from it; returns the inserted element, or nullptr if the key was
  // already present (a duplicate: the checkpoint is inconsistent). nullptr for sequences.
  void* (*insert)(void* c, void* staged_element);
  // Contiguous sequences (std::vector, except vector<bool>): the first element, so that runs
  // of fixed-width scalars move as one block. nullptr for other containers (and when the
  // member is left out of a table: both are optional).
  const void* (*contiguous_data)(const void* c);
  // Contiguous sequences: resize to n value-initialised elements and return the first
  // (nullptr when n == 0 may be returned). nullptr for other containers.
  void* (*resize_default)(void* c, std::size_t n);
};

struct OptionalOps {
  const void* (*get)(const void* o);  // nullptr when empty
  void* (*emplace)(void* o);          // engage with a value-initialised value; returns it
  void (*reset)(void* o);
};

struct VariantOps {
  std::uint32_t (*index)(const void* v);           // kNoType when valueless
  const void* (*get)(const void* v);               // the active alternative
  void* (*emplace)(void* v, std::uint32_t index);  // value-initialise alternative
};

struct UniquePtrOps {
  const void* (*get)(const void* p);
  void* (*make)(void* p);  // p.reset(new T()); returns the pointee
  void (*reset)(void* p);
};

struct SharedPtrOps {
  const void* (*get)(const void* p);
  // A runtime-owned std::shared_ptr<T> holding a new value-initialised T; returns the holder.
  void* (*make_holder)();
  void* (*holder_get)(void* holder);                        // the T inside a holder
  void (*assign_from_holder)(void* p, const void* holder);  // p = *holder
  void (*destroy_holder)(void* holder);
  void (*reset)(void* p);
};

struct TypeInfo {
  const char* name;  // canonical name: "Copter", "AP_Int8<int8_t>", "int32",
                     // "std::vector<Waypoint>" (see docs/format.md §names)
  Kind kind;
  std::uint32_t flags;      // kType*
  std::uint32_t size;       // sizeof(T) in the running build
  std::uint32_t align;      // alignof(T)
  const FieldInfo* fields;  // Struct, Union (Union may list its members; unused)
  std::uint32_t field_count;
  const EnumeratorInfo* enumerators;  // Enum
  std::uint32_t enumerator_count;
  std::uint32_t element;              // Enum: underlying; Array/Container/Optional/pointers:
                                      // element/pointee; String: character type; else kNoType
  std::uint64_t count;                // Array length
  const std::uint32_t* alternatives;  // Variant
  std::uint32_t alternative_count;
  std::uint8_t container_kind;           // Container: a ContainerKind
  const void* ops;                       // the kind's *Ops table, or nullptr
  const Lifecycle* lifecycle;            // for pointee/element types that restore must create
  bool (*validate)(const void* object);  // user's symcr_validate(const T&), or nullptr
  const char* const* renamed_from;       // SYMCR_RENAMED_FROM on the type; nullptr-terminated
  // User's symcr_migrate(T&, const OldValues&), or nullptr. Restore calls it on each restored
  // instance whose checkpointed type differs from this one, after the mechanical rules.
  void (*migrate)(void* object, const OldValues& old);
  // With kTypeLeavesMembers: the names of the members this build leaves to itself (const,
  // reference, function and member pointers); nullptr-terminated. They are not fields.
  const char* const* left_to_new_build;
  // With kTypeReferenceMembers (Struct): members whose values are not saved but at or inside
  // which a pointer may point (a shallow root's unselected members, and what they hold down to
  // the pointees). Only name, type, offset and renamed_from are used. A reference's step at a
  // struct numbers its fields first, then these: field_count + i is reference_members[i].
  const FieldInfo* reference_members;
  std::uint32_t reference_member_count;
};

struct RootInfo {
  const char* name;  // qualified source name: "copter", "ns::state",
                     // "Class::member", "function::local"
  std::uint32_t type;
  void* address;        // the variable in this process
  std::uint32_t flags;  // kRoot*
  const char* const* renamed_from;
};

struct Schema {
  const TypeInfo* types;
  std::uint32_t type_count;
  const RootInfo* roots;
  std::uint32_t root_count;
  // The program's name (symcr-gen --program; the CMake project's name by default). Its hash is
  // written into every checkpoint, and a restore refuses a checkpoint of another program. Null:
  // an anonymous program, whose checkpoints any program accepts and which accepts any.
  const char* program;
};

}  // namespace symcr

namespace symcr {
// The program's schema serialised (docs/format.md §2) and its FNV-1a 64 hash, as symcr-gen
// computed them from the same tables: a program never serialises or hashes its own schema at
// run time. Tables written otherwise are serialised once, at their first use.
struct SerialisedSchema {
  const std::uint8_t* bytes;
  std::uint32_t size;
  std::uint64_t hash;
};
}  // namespace symcr
extern "C" const symcr::SerialisedSchema* symcr_program_serialised_schema(void)
    __attribute__((weak));
// The hash alone: what the device profile needs, without keeping the serialised bytes in a
// firmware that never reads them.
extern "C" std::uint64_t symcr_program_schema_hash(void) __attribute__((weak));

namespace symcr {
// A plan symcr-gen resolved at build time: how checkpoints of a previous build (the schema
// file given as PREVIOUS_SCHEMA, whose schema hashes to writer_hash) restore into this one.
// Restore reads it instead of planning. `image` is internal to the runtime of this release.
struct PlannedSchema {
  std::uint64_t writer_hash;
  const std::uint8_t* image;
  std::uint32_t size;
};
}  // namespace symcr
// The build's planned schemas (*count of them), or the symbol is absent when there are none.
extern "C" const symcr::PlannedSchema* symcr_program_plans(std::uint32_t* count)
    __attribute__((weak));

namespace symcr {
// The device profile's compact tables (PROFILE device): what its runtime reads of each type and
// field, in 12 and 6 bytes on a 32-bit target where a TypeInfo takes 96 and a FieldInfo 32.
// A DeviceSchema begins with a Schema whose `types` is null while `type_count` counts the
// entries of `types` here; its roots and program are that Schema's. The device runtime accepts
// either form wherever it takes a Schema; the host runtime only TypeInfo tables.
struct DeviceTypeInfo {
  std::uint32_t size;   // sizeof(T) in the running build
  std::uint32_t count;  // Array: its elements; Struct: its fields (bases first) in the low 16
                        // bits, its reference members in the high 16
  union {
    std::uint16_t element;      // Enum: underlying; Array: element; Pointer: pointee; else 0xFFFF
    std::uint16_t first_field;  // Struct: its first field in DeviceSchema's field tables, then
                                // its reference members follow its fields
  };
  std::uint8_t kind;       // a Kind
  std::uint8_t validator;  // 1 + its symcr_validate's index in `validators`; 0: none
};
constexpr std::uint16_t kDeviceNoType = 0xFFFF;
// The few bit-fields, SYMCR_RANGE bounds and clocks' times, by their field's index.
struct DeviceBitField {
  std::uint32_t field;
  std::uint8_t bit_offset;  // first bit within the unit (the field's offset)
  std::uint8_t bit_width;
};
struct DeviceFieldRange {
  std::uint32_t field;
  FieldRange range;
};
struct DeviceFieldTime {
  std::uint32_t field;
  FieldTime time;
};
struct DeviceSchema {
  Schema schema;  // types null: the types are `types` below
  const DeviceTypeInfo* types;
  // Per field, in two arrays (6 bytes a field, unpadded): its offset as FieldInfo's (a
  // bit-field's storage unit) and its type, an index into `types`.
  const std::uint32_t* field_offsets;
  const std::uint16_t* field_types;
  bool (*const* validators)(const void* object);
  const DeviceBitField* bit_fields;
  std::uint32_t bit_field_count;
  const DeviceFieldRange* ranges;
  std::uint32_t range_count;
  const DeviceFieldTime* times;
  std::uint32_t time_count;
};
}  // namespace symcr
// The device profile's compact schema of the program (PROFILE device only): the same types and
// roots as symcr_program_schema(), whose TypeInfo tables a firmware then never links.
extern "C" const symcr::DeviceSchema* symcr_program_device_schema(void) __attribute__((weak));

#endif  // SYMCR_GENERATED_HPP
