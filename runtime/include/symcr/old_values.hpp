// Migration hooks (docs/resolution.md): for a change no mechanical rule expresses (a unit change, a
// field split in two), the new build declares, next to the type,
//
//   void symcr_migrate(Nav& nav, const symcr::OldValues& old);
//
// and restore calls it on every restored Nav whose checkpointed type differs from this build's,
// after the mechanical rules wrote it (nested objects' hooks first). `old` reads the value the
// checkpoint holds for that object by the *old* build's field names:
//
//   double alt_m;
//   if (old.get("alt_m", alt_m)) nav.alt_cm = static_cast<std::int32_t>(alt_m * 100.0);
//
// A value the rules could not restore anywhere inside the object (an enumerator this build
// removed, 12.5 for an int) kept this build's value and is the hook's to handle, here by its
// old name: `old.enumerator("mode", name)` gives "Return", and the report does not count it as
// lost.
//
// Every query returns false (or an invalid view, or 0) and leaves its output untouched when the
// field is absent or of a kind the query cannot convert; nothing here crashes on any schema the
// checkpoint parser accepted. A view is only valid during the hook call. Fields of base classes
// are found by their own names too; a base itself is a field named after its type.
#ifndef SYMCR_OLD_VALUES_HPP
#define SYMCR_OLD_VALUES_HPP

#include <cstddef>
#include <cstdint>
#include <string>

namespace symcr {

struct Schema;  // <symcr/generated.hpp>
class OldValues;
namespace detail {
struct WireSizes;
struct OldValuesAccess;  // how restore makes a view
}  // namespace detail

class OldValues {
 public:
  OldValues() = default;  // invalid: every query fails

  bool valid() const { return writer_ != nullptr; }
  const char* type_name() const;  // the checkpoint's name of the viewed type; "" when invalid

  // In every query, `field` names a member of the viewed struct; nullptr names the viewed value
  // itself (e.g. an element of an array of numbers: old.element("samples", 2).get(nullptr, v)).
  bool has(const char* field) const;

  // Numbers from any Bool/Int/UInt/Float/Enum (an enum as its underlying value). Integers need
  // the value to fit; from floating point only integral values convert. A double takes any
  // finite-in-range number (integers beyond 2^53 round).
  bool get(const char* field, bool& out) const;
  bool get(const char* field, std::int64_t& out) const;
  bool get(const char* field, std::uint64_t& out) const;
  bool get(const char* field, double& out) const;
  // A string of 1-byte characters, or a fixed array of 1-byte integers (up to its first NUL).
  bool get(const char* field, std::string& out) const;
  // An enum's enumerator name in the checkpoint's build (valid during the hook call).
  bool enumerator(const char* field, const char*& name) const;

  // A view of a member (any kind; an optional or unique_ptr as its contained value, invalid
  // when empty or null).
  OldValues child(const char* field) const;
  // Elements of a fixed array or a container member (0 for other kinds), and a view of one.
  std::size_t count(const char* field) const;
  OldValues element(const char* field, std::size_t index) const;

 private:
  struct Span {
    std::uint32_t type;
    const std::uint8_t* bytes;
    std::size_t size;
  };
  friend struct detail::OldValuesAccess;
  OldValues(const Schema& writer, const detail::WireSizes& sizes, std::uint32_t type,
            const std::uint8_t* bytes, std::size_t size);
  bool locate(const char* field, Span& out) const;

  const Schema* writer_ = nullptr;
  const detail::WireSizes* sizes_ = nullptr;
  std::uint32_t type_ = 0xFFFFFFFFu;  // no type
  const std::uint8_t* bytes_ = nullptr;
  std::size_t size_ = 0;
};

}  // namespace symcr

#endif  // SYMCR_OLD_VALUES_HPP
