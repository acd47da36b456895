//===- DeviceProfile.cpp - What the device profile's runtime can hold
//------===//

#include "DeviceProfile.h"

#include <cmath>
#include <set>

namespace symcr_gen {
namespace {

/// How to hold what \p Type holds without a heap, or empty when the device
/// profile holds the type as it is.
std::string deviceFix(const TypeModel &Type) {
  switch (Type.Kind) {
  case symcr::Kind::Bool:
  case symcr::Kind::Union:
  case symcr::Kind::Struct:
  case symcr::Kind::Array:
  case symcr::Kind::Pointer:
    return "";
  case symcr::Kind::Int:
  case symcr::Kind::UInt:
  case symcr::Kind::Enum:
    return Type.Size <= 8 ? "" : "an integer of at most 64 bits";
  case symcr::Kind::Float:
    return Type.Size == 4 || Type.Size == 8 ? "" : "float or double";
  case symcr::Kind::String:
    return "a fixed character array (char name[N])";
  case symcr::Kind::Container:
    return "a fixed array and a count (std::array<T, N> or T[N], and a size "
           "member)";
  case symcr::Kind::Optional:
    return "the value and a bool member saying whether it is set";
  case symcr::Kind::Variant:
    return "an enum saying which alternative is held and a union of them";
  case symcr::Kind::UniquePtr:
  case symcr::Kind::SharedPtr:
    return "an object inside the state (a member or an array element) and a "
           "raw pointer to it";
  }
  return "a type of the list in docs/device.md";
}

class DeviceCheck {
public:
  DeviceCheck(const ProgramModel &Program, Diagnostics &Diags)
      : Program(Program), Diags(Diags) {}

  bool run() {
    for (const RootModel &Root : Program.Roots)
      visit(Root.Type, Root.Name, Root.Where);
    for (const PointModel &Point : Program.Points) {
      Diags.error(
          Point.Where,
          "'" + Point.Spelling +
              "': program points save into and "
              "restore from a checkpoint store, which the device profile "
              "has no files for; call symcr::device::Ring's save() and "
              "restore_latest() from the program instead, or build with "
              "the host profile");
      Clean = false;
    }
    return Clean;
  }

private:
  void visit(std::uint32_t Index, const std::string &Path,
             const Location &Where) {
    if (Index >= Program.Types.size())
      return;
    const TypeModel &Type = Program.Types[Index];
    std::string Fix = deviceFix(Type);
    if (!Fix.empty()) {
      // One error per type and member path; an array's elements share one.
      if (Reported.insert(Path).second)
        Diags.error(Where,
                    "'" + Path + "' is a " + Type.Name +
                        ", which the device profile cannot hold (it has no "
                        "heap and no standard containers): make it " +
                        Fix +
                        ", or keep it out of checkpoints with SYMCR_SKIP, or "
                        "build with the host profile");
      Clean = false;
      return;
    }
    if (Type.Kind == symcr::Kind::Array)
      visit(Type.Element, Path + "[]", Where);
    if (Type.Kind == symcr::Kind::Struct)
      for (const FieldModel &Field : Type.Fields) {
        const std::string FieldPath =
            Path + ((Field.Flags & symcr::kFieldBase) ? ".(" + Field.Name + ")"
                                                      : "." + Field.Name);
        checkRange(Field, FieldPath, Where);
        visit(Field.Type, FieldPath, Where);
      }
  }

  /// The device checks a range as doubles, which hold every integer up to
  /// 2^53 exactly: a 64-bit integer's bound from 2^53 on would let a value
  /// just past it round onto it.
  void checkRange(const FieldModel &Field, const std::string &Path,
                  const Location &Where) {
    if (!(Field.Flags & symcr::kFieldHasRange) ||
        Field.Type >= Program.Types.size())
      return;
    const TypeModel &Type = Program.Types[Field.Type];
    const bool Integer = Type.Kind == symcr::Kind::Int ||
                         Type.Kind == symcr::Kind::UInt ||
                         Type.Kind == symcr::Kind::Enum;
    constexpr double Exact = 9007199254740992.0; // 2^53
    if (!Integer || Type.Size < 8 ||
        (std::fabs(Field.RangeMin) < Exact &&
         std::fabs(Field.RangeMax) < Exact))
      return;
    Diags.error(Where, "'" + Path +
                           "' has a SYMCR_RANGE bound of 2^53 or more in "
                           "magnitude, which the device profile cannot "
                           "compare exactly with a 64-bit integer: keep both "
                           "bounds within -9007199254740991 and "
                           "9007199254740991, or build with the host profile");
    Clean = false;
  }

  const ProgramModel &Program;
  Diagnostics &Diags;
  std::set<std::string> Reported;
  bool Clean = true;
};

} // namespace

bool checkDeviceProfile(const ProgramModel &Program, Diagnostics &Diags) {
  return DeviceCheck(Program, Diags).run();
}

} // namespace symcr_gen
