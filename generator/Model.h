//===- Model.h - The program schema as plain data ------------------------===//
//
// What symcr-gen learned from the translation units, independent of Clang: the
// types, roots and per-TU exports the emitter writes out. Built by
// SchemaBuilder (one pass per TU, merged by canonical type name), consumed by
// the Emitter.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_MODEL_H
#define SYMCR_GENERATOR_MODEL_H

#include "symcr/generated.hpp"

#include <cstdint>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace symcr_gen {

/// A source position as printed in diagnostics ("file:line:col").
struct Location {
  std::string File;
  unsigned Line = 0;
  unsigned Column = 0;
  bool valid() const { return !File.empty(); }
  std::string str() const {
    return File + ":" + std::to_string(Line) + ":" + std::to_string(Column);
  }
};

/// A member on a selection's path, as diagnostics name it.
struct MemberRef {
  std::string Path;     ///< "vehicle.ahrs.sim_backend"
  std::string SkipHint; ///< "Ahrs::sim_backend"
  std::string TypeName; ///< its type, "SimBackend"
  Location Where;       ///< its declaration
  bool empty() const { return SkipHint.empty(); }
};

/// Collects diagnostics from every TU; a diagnostic repeated by several TUs (a
/// header seen twice) is printed once. Thread-safe: TUs are parsed in parallel.
class Diagnostics {
public:
  /// A quiet instance prints nothing: it collects what a tentative walk would
  /// have said.
  explicit Diagnostics(bool Quiet = false) : Quiet(Quiet) {}
  /// Nothing was reported (errors, held-back leaves).
  bool clean() const { return Errors == 0 && Groups.empty() && Fixes.empty(); }
  /// The first problem reported, for a one-line reason.
  std::string firstProblem() const;
  void error(const Location &Loc, const std::string &Message);
  void warning(const Location &Loc, const std::string &Message);
  void note(const Location &Loc, const std::string &Message);
  unsigned errorCount() const { return Errors; }

  /// Something unrestorable at \p Where, fixed by skipping \p LeafSkip. When
  /// the selection reached it through another object (\p Group: the member
  /// that leads there), it is held back and reported under that member by
  /// flushUnrestorable(), since skipping that one member removes every such
  /// leaf, where the leaves' own skips would drag the other object's type into
  /// the schema.
  void unrestorable(const Location &Where, const std::string &Message,
                    const std::string &LeafSkip, const MemberRef *Group);
  /// Prints the held-back leaves grouped by member, then a closing line with
  /// the skip lines that remove every unrestorable error.
  void flushUnrestorable();

  /// Holds notes back until releaseNotes(), which prints only those not yet in
  /// \p File and adds them there. A build runs one symcr-gen per checkpointed
  /// target, often over the same sources: the build passes one file for all of
  /// them, so that a note is printed once per build tree, not once per target.
  void printNotesOnceIn(const std::string &File) { ShownNotesFile = File; }
  /// Prints the notes held back. After an error every one is printed, since a
  /// note may explain it.
  void releaseNotes();

private:
  void print(const Location &Loc, const char *Severity,
             const std::string &Message);
  struct Leaf {
    Location Where;
    std::string Message;
  };
  struct Group {
    MemberRef Member;
    std::vector<Leaf> Leaves;
  };
  std::mutex Lock;
  bool Quiet = false;
  std::vector<std::string>
      Collected; ///< what a quiet instance would have printed
  std::map<std::string, bool> Seen;
  unsigned Errors = 0;
  std::map<std::string, Group> Groups; ///< by the member's skip hint
  std::vector<std::string> Fixes;      ///< skip lines, in order of first need
  std::string ShownNotesFile;          ///< see printNotesOnceIn()
  std::vector<std::string> HeldNotes;  ///< whole lines, in order
};

/// Which symcr::ops template a type's operation table comes from.
enum class OpsKind {
  None,
  String,
  Container,
  Optional,
  Variant,
  UniquePtr,
  SharedPtr
};

struct FieldModel {
  std::string Name;
  std::uint32_t Type = symcr::kNoType;
  std::uint64_t Offset = 0;
  unsigned BitOffset = 0;
  unsigned BitWidth = 0;
  std::uint32_t Flags = 0;
  std::vector<std::string> RenamedFrom;
  double RangeMin = 0;
  double RangeMax = 0;
  /// kFieldClockTime: the clock whose times the member holds, and its "no time
  /// yet" value.
  std::string Clock;
  std::int64_t Never = 0;
  /// A state flag declared to describe only state that is restored with it
  /// (SYMCR_RESTORES_ALONE, restores_alone): --report warns nothing about it.
  bool RestoresAlone = false;
  /// Spelling of the member for an offsetof() check, or empty when the member
  /// is not checkable at compile time (private, bit-field,
  /// non-standard-layout).
  std::string OffsetCheckMember;
};

struct ProgramModel;

struct TypeModel {
  std::string Name; ///< canonical name (docs/format.md §2)
  symcr::Kind Kind = symcr::Kind::Struct;
  std::uint32_t Flags = 0;
  std::uint64_t Size = 0;
  std::uint64_t Align = 0;
  std::vector<FieldModel> Fields;
  std::vector<std::pair<std::string, std::int64_t>> Enumerators;
  std::uint32_t Element = symcr::kNoType;
  std::uint64_t Count = 0;
  std::vector<std::uint32_t> Alternatives;
  std::uint8_t ContainerKind = 0;
  OpsKind Ops = OpsKind::None;
  /// Restore may have to create the type (a pointee, a container element): the
  /// wrapper emits a Lifecycle when hasLifecycle(), and the type is flagged
  /// kTypeCreatable then.
  bool NeedsLifecycle = false;
  /// A C++ (or C) spelling usable in the home TU, empty if the type cannot be
  /// named there (unnamed or function-local types).
  std::string Spelling;
  /// The spelling may be used at namespace scope: nothing in it is private or
  /// protected. (Otherwise the wrapper names the type through an explicit
  /// instantiation, which needs C++14's deduced return types.)
  bool Accessible = true;
  std::vector<std::string> RenamedFrom;
  /// The program declares `bool symcr_validate(const T&)`: the home TU's
  /// wrapper defines a thunk calling it for TypeInfo::validate.
  bool HasValidate = false;
  /// The program declares `void symcr_migrate(T&, const symcr::OldValues&)`:
  /// the home TU's wrapper defines a thunk calling it for TypeInfo::migrate,
  /// and the type is flagged kTypeMigrated (so schema files record it).
  bool HasMigrate = false;
  /// Index of the TU whose wrapper defines this type's ops and layout checks.
  unsigned HomeTU = 0;
  /// Names the home wrapper's code for the type (ops_<Symbol>,
  /// lifecycle_<Symbol>, ...): see symbolOf().
  std::string Symbol;
  /// A class restore may create as a heap object's dynamic type
  /// (kTypeDynamicType): its vtable's mangled name and the index of its address
  /// point, for Lifecycle::vtable.
  std::string VtableSymbol;
  unsigned VtableAddressPoint = 0;
  /// The function whose definition emits the vtable (the Itanium ABI's key
  /// function), when only the source defining it does: the class is creatable
  /// only if a parsed source defines it.
  std::string VtableKeyFunction;
  /// A polymorphic class a pointer points to: the classes (itself or derived)
  /// saving can recognise as a heap object's dynamic type, and those it cannot,
  /// with why.
  std::vector<std::uint32_t> DynamicTypes;
  std::vector<std::string> NotDynamicTypes;
  std::string
      DynamicTypesReachedBy; ///< the first such pointer's path, for the note
  Location DynamicTypesReachedAt;   ///< that pointer's declaration
  std::string DynamicTypesSkipHint; ///< and its skip line, "Ahrs::_view"

  /// A Lifecycle is emitted only for types the home TU can name and construct
  /// with `new T()` (or calloc in C).
  bool hasLifecycle() const {
    return NeedsLifecycle && !Spelling.empty() && Kind != symcr::Kind::Union &&
           Kind != symcr::Kind::Array;
  }
  /// The type has a user's symcr_validate and a C++ home TU to call it from.
  bool hasValidate(const ProgramModel &Program) const;
  /// Describes the layout and selection; two TUs producing the same name with a
  /// different fingerprint means inconsistent annotations or an ODR problem.
  std::string Fingerprint;
  std::string FirstSeenIn;
  /// A member (or "base B") that is not restored, and why.
  struct LeftMember {
    std::string Name;
    std::string Why;
  };
  /// Members left out of this type and why ("raw", "SYMCR_SKIP"), for --report.
  std::vector<LeftMember> Skipped;
  /// Members the new build re-creates by itself, never restored and needing no
  /// annotation (const and reference members, function and member pointers):
  /// their names go into the schema (TypeInfo::left_to_new_build), and why,
  /// into --report.
  std::vector<LeftMember> LeftToNewBuild;
  /// Members whose values are not saved but which a pointer may target
  /// (kTypeReferenceMembers: a shallow root's unselected members, and the parts
  /// of them on the way to a pointee).
  std::vector<FieldModel> ReferenceMembers;

  std::vector<std::string> leftToNewBuildNames() const {
    std::vector<std::string> Names;
    for (const LeftMember &Left : LeftToNewBuild)
      Names.push_back(Left.Name);
    return Names;
  }
};

/// A boolean or enum member: a "state flag", which often says what state other
/// members of its class hold (started, initialised, a mode).
inline bool isStateFlag(const TypeModel &Type) {
  return Type.Kind == symcr::Kind::Bool || Type.Kind == symcr::Kind::Enum;
}

struct RootModel {
  std::string Name;
  std::uint32_t Type = symcr::kNoType;
  std::uint32_t Flags = 0;
  std::vector<std::string> RenamedFrom;
  unsigned HomeTU = 0;
  std::string Symbol; ///< names symcr_gen_root_<Symbol>: see symbolOf()
  /// Code in the home TU's wrapper that yields the root's address.
  std::string AddressExpression;
  /// Declarations the address expression needs (asm-label aliases, access
  /// helpers), emitted before it in the wrapper.
  std::string AddressPrelude;
  Location Where;
};

/// A checkpoint_at or restore_at directive, and the store all points use.
struct PointModel {
  bool Restore = false; ///< restore_at (else checkpoint_at)
  std::string Function; ///< as written, "Copter::fast_loop" (no leading ::)
  bool AtExit = false;  ///< exit (every return path), else entry
  unsigned Every = 1;   ///< checkpoint_at: save on every N-th pass
  bool StopOnFailure = false; ///< restore_at: on_failure=stop
  bool Strict = false;        ///< restore_at: strict
  std::string Spelling;       ///< the directive as written
  Location Where;             ///< of the directive
  /// Where the function was found defined, for the report and diagnostics.
  std::vector<std::string> InsertedAt;
};

struct PointStoreModel {
  std::string Path;
  unsigned Slots = 0;    ///< 0: the runtime's default
  unsigned SlotSize = 0; ///< 0: the runtime's default
  bool Fdatasync = false;
  unsigned FallbackDepth = 0;   ///< crash-loop fallback; 0: off
  bool FallbackDefault = false; ///< FallbackDepth is the default, not given
  unsigned ConfirmAfter = 0; ///< checkpoints saved after a restore confirm it
  std::string Spelling;
  Location Where; ///< invalid when no store directive was given
};

/// What time(...) or SYMCR_TIME(...) says of a member or typedef.
struct TimeSpec {
  std::string Clock;
  std::int64_t Never = 0;
  Location Where;
};

/// A clock(...) directive: a clock's name and the function that reads it.
struct ClockModel {
  std::string Name;     ///< as time(...) and SYMCR_TIME name it; in the schema
  std::string Function; ///< as written, "AP_HAL::millis" (no leading ::)
  Location Where;       ///< of the first directive naming it
  /// The first TU that declares the function: its wrapper defines the reading
  /// thunk `symcr_gen_clock_<index>`, which calls CallExpression.
  int HomeTU = -1;
  std::string CallExpression;
  std::string Symbol; ///< names symcr_gen_clock_<Symbol>: see symbolOf()
  /// Its function returns an unsigned 64-bit count: the thunk converts it
  /// explicitly.
  bool Unsigned64 = false;
};

/// A text edit of a source's copy (a point's call, an include made absolute).
struct SourceEdit {
  unsigned Offset = 0; ///< in the source's text
  unsigned Length = 0; ///< replaced characters (0: an insertion)
  std::string Text;
  unsigned Point = 0; ///< the PointModel an insertion serves (else unused)
  bool IsPoint = false;
};

struct TranslationUnitModel {
  std::string Source;  ///< absolute path of the user's source file
  std::string Wrapper; ///< generated file that includes Source and adds exports
  bool IsC = false;
  /// Parsed as C++14 or later: the wrapper may use deduced return types.
  bool DeducesReturnTypes = true;
  /// A source of a static library the program links (--library-source): only
  /// checked for roots, which cannot be served there; no wrapper.
  bool LibraryOnly = false;
  /// Program points defined in this source: the wrapper then includes
  /// PointedCopy, a copy of SourceText with Edits applied, instead of Source.
  std::vector<SourceEdit> Edits;
  std::string SourceText;
  std::string PointedCopy;
  bool hasPoints() const { return !PointedCopy.empty(); }
};

/// Per-root summary for --report.
struct RootReport {
  std::string Root;
  std::vector<std::string> Lines; ///< reached types/fields, skips and why
  std::uint64_t Bytes =
      0; ///< fixed-size bytes reached (containers: per element)
};

/// Which runtime the generated code serves (--profile).
enum class RuntimeProfile {
  Host,  ///< runtime/: every supported type, heap objects, stores
  Device ///< runtime/device: no heap; no ops tables, lifecycles or migrations
};

/// A previous build's schema planned against this one (--previous-schema): the
/// plan's image, which the schema source embeds for restore to decode.
struct PreviousPlanModel {
  std::string SchemaFile;
  std::uint64_t WriterHash = 0;
  std::vector<std::uint8_t> Image;
};

struct ProgramModel {
  /// The program's name (--program): its identity in checkpoint headers.
  std::string Name;
  RuntimeProfile Profile = RuntimeProfile::Host;
  std::vector<TypeModel> Types;
  std::map<std::string, std::uint32_t>
      TypeIndex; ///< by canonical name (+ shallow flag)
  std::vector<RootModel> Roots;
  std::vector<TranslationUnitModel> TranslationUnits;
  std::vector<RootReport> Reports;
  std::vector<std::string> Dependencies; ///< every file read (for the depfile)
  std::vector<PointModel> Points;
  PointStoreModel PointStore;
  std::vector<PreviousPlanModel> PreviousPlans;
  /// Vtables (mangled names) of classes with a key function some parsed source
  /// defines.
  std::set<std::string> EmittedVtables;
  /// Clocks, in the byte order of their names: a clock's index in the schema is
  /// its position.
  std::vector<ClockModel> Clocks;
  /// Time members by clock name: where the first one is, for "no such clock"
  /// diagnostics.
  std::map<std::string, Location> ClockUses;
};

/// The suffix of the names of generated code for the type, root or clock at \p
/// Index: the index itself when one run generates the whole program, or
/// "<unit>_<index>" when each translation unit is generated on its own
/// (--unit), so that the wrappers of separately generated units never define
/// the same name and the schema source of their merged parts can name each one.
inline std::string symbolOf(const std::string &Symbol, std::size_t Index) {
  return Symbol.empty() ? std::to_string(Index) : Symbol;
}

inline bool TypeModel::hasValidate(const ProgramModel &Program) const {
  return HasValidate && !Spelling.empty() &&
         !Program.TranslationUnits[HomeTU].IsC;
}

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_MODEL_H
