//===- TypeWalker.h - Types reachable from roots, into the model
//------------===//
//
// Internal to the schema builder. The walker's work is split by job:
//   TypeWalker.cpp      the walk: scalars, enums, arrays, pointers, records and
//                       their fields, skips, dynamic types of polymorphic
//                       pointees, registration in the program model
//   CanonicalNames.cpp  the canonical and source names of types
//   StdTypes.cpp        the standard library types it knows (containers,
//                       strings, optional, variant, smart pointers, tuple)
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_TYPEWALKER_H
#define SYMCR_GENERATOR_TYPEWALKER_H

#include "AstQueries.h"
#include "Model.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/DeclCXX.h"
#include "clang/AST/DeclTemplate.h"
#include "clang/AST/PrettyPrinter.h"
#include "clang/Sema/Sema.h"

#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace symcr_gen {

/// Selections resolved from directives, keyed by record names (either the
/// qualified name without template arguments, matching every specialization,
/// or the canonical name) and member names.
struct Selections {
  std::map<std::string, std::string> SkippedTypes; ///< key -> why
  std::map<std::pair<std::string, std::string>, std::string> SkippedFields;
  std::map<std::pair<std::string, std::string>, std::vector<std::string>>
      FieldRenames;
  std::map<std::string, std::vector<std::string>> TypeRenames;
  std::map<std::string, std::vector<std::string>> RootRenames;
  std::set<std::pair<std::string, std::string>> IncludedFields;
  /// not_owner(Type::field): pointers declared never to own a heap object.
  std::set<std::pair<std::string, std::string>> NotOwnerFields;
  /// restores_alone(Type::field): state flags that describe only restored
  /// state.
  std::set<std::pair<std::string, std::string>> RestoresAloneFields;
  /// range(Type::field, lo, hi) directives.
  std::map<std::pair<std::string, std::string>, std::pair<double, double>>
      FieldRanges;
  /// time(Type::field, clock) and time(typedef, clock) directives; typedefs by
  /// qualified name.
  std::map<std::pair<std::string, std::string>, TimeSpec> FieldTimes;
  std::map<std::string, TimeSpec> TypedefTimes;
  /// Record types (canonical) that have a usable `bool symcr_validate(const
  /// T&)` in this TU.
  std::set<const clang::Type *> Validated;
  /// Record types (canonical) that have a usable `void symcr_migrate(T&, const
  /// symcr::OldValues&)` in this TU.
  std::set<const clang::Type *> Migrated;
  struct RootRequest {
    bool Shallow = false;
    Location Where;
  };
  std::map<std::string, RootRequest> Roots; ///< by root name
};

struct WalkContext {
  std::string Path;          ///< "copter.ahrs.backend"
  Location Where;            ///< the declaration that reached the type
  std::string SkipHint;      ///< "AP_AHRS::backend", for the fix in diagnostics
  std::string AnonymousName; ///< name for an unnamed record held by this field
  bool Shallow = false;
  /// The member whose value holds the current one (empty at a root's top
  /// level).
  MemberRef Enclosing;
  /// Where the walk left the selected object for another one through a pointer:
  /// the member to skip for everything unrestorable beyond (empty until then).
  MemberRef Group;
};

/// Walks the types reachable from one TU's roots into the ProgramModel.
class TypeWalker {
public:
  TypeWalker(clang::ASTContext &Context, clang::Sema *S, unsigned TUIndex,
             ProgramModel &Program, Diagnostics &Diags,
             const Selections &Select)
      : Context(Context), S(S), TUIndex(TUIndex), Program(Program),
        Sink(&Diags), Select(Select) {
    Policy =
        std::make_unique<clang::PrintingPolicy>(Context.getPrintingPolicy());
    Policy->SuppressUnwrittenScope = true;
    Policy->SuppressTagKeyword = Context.getLangOpts().CPlusPlus;
    Policy->FullyQualifiedName = true;
  }

  std::uint32_t walk(clang::QualType Type, const WalkContext &C);
  std::string spelling(clang::QualType Type);
  /// Whether code at namespace scope may name \p Type: no part of it (the
  /// class, a class it is nested in, a template argument) is private or
  /// protected.
  static bool accessible(clang::QualType Type);
  std::string canonicalRecordName(const clang::RecordDecl *RD) {
    return recordName(RD, WalkContext());
  }

  /// After every root of the TU is walked: lists, in each root's class, the
  /// members whose values are not saved (a shallow root's unselected members,
  /// skipped members) at or inside which a pointer of the TU's state may point
  /// (kTypeReferenceMembers), so that such a pointer is saved as a reference by
  /// path. \p ClassRoots: each root's name, declared type and type index (roots
  /// not of class type are passed over); \p RootTypes: every root's type index.
  void addReferenceMembers(
      const std::vector<std::tuple<std::string, clang::QualType, std::uint32_t>>
          &ClassRoots,
      const std::vector<std::uint32_t> &RootTypes);

  /// The TU's class definitions with virtual functions (NameIndex).
  const std::vector<const clang::CXXRecordDecl *> *PolymorphicClasses = nullptr;

private:
  /// A model of \p Type with its canonical name, spelling, accessibility,
  /// size and alignment; the caller fills in the rest.
  TypeModel describe(clang::QualType Type, const WalkContext &C);
  std::uint32_t fail(const WalkContext &C, const std::string &What,
                     const std::string &Why);
  std::uint32_t scalar(const clang::BuiltinType *BT, const WalkContext &C);
  std::uint32_t record(clang::QualType Type, const clang::RecordDecl *Decl,
                       const WalkContext &C);
  std::uint32_t stdRecord(clang::QualType Type, const clang::RecordDecl *RD,
                          llvm::StringRef Name, const WalkContext &C);
  std::uint32_t enumeration(clang::QualType Type, const clang::EnumDecl *ED,
                            const WalkContext &C);
  std::uint32_t array(clang::QualType Type, const clang::ConstantArrayType *AT,
                      const WalkContext &C);
  std::uint32_t pointer(clang::QualType Type, const clang::PointerType *PT,
                        const WalkContext &C);
  /// A raw pointer declared never to own a heap object (kTypeNeverOwns): its
  /// pointee is walked, but no heap lifecycle or dynamic type is sought for it.
  std::uint32_t neverOwningPointer(clang::QualType Type, const WalkContext &C);
  std::uint32_t synthesizedPair(clang::QualType Key, clang::QualType Value,
                                const WalkContext &C);
  bool fillFields(const clang::RecordDecl *RD, TypeModel &Model,
                  const WalkContext &C);
  /// Marks \p Field a time of a clock when its member, a directive or a typedef
  /// in its type says so (Clocks.cpp); false after a diagnostic.
  bool fieldTime(const clang::FieldDecl *FD, const TimeSpec *Directive,
                 FieldModel &Field, const WalkContext &F);
  bool checkPointee(clang::QualType Pointee, const WalkContext &C,
                    const char *Holder);
  /// Finds the classes (\p Base or derived from it) a heap object behind a
  /// pointer to \p Base may be saved as, and walks each into the schema.
  void findDynamicTypes(const clang::CXXRecordDecl *Base,
                        std::uint32_t BaseIndex, const WalkContext &C);
  /// Why restore cannot create \p Class as a heap object; empty if it can.
  std::string whyNotCreatable(const clang::CXXRecordDecl *Class);
  /// Walks \p Type, or leaves the program model as it was and says why not.
  std::uint32_t tentativeWalk(clang::QualType Type, const WalkContext &C,
                              std::string &Why);

  /// Registers \p Model under \p Key: reuses the global slot of the same name
  /// and checks that this TU describes it identically.
  std::uint32_t reserve(const std::string &Key, const std::string &Name,
                        bool &Fresh);
  void store(std::uint32_t Index, TypeModel Model, const WalkContext &C);
  std::string fingerprint(const TypeModel &Model) const;
  const char *leftToNewBuild(clang::QualType Type) const;
  std::string canonicalName(clang::QualType Type, const WalkContext &C);
  std::string recordName(const clang::RecordDecl *RD, const WalkContext &C);
  std::string
  templateArgumentsName(const clang::ClassTemplateSpecializationDecl *Spec,
                        const WalkContext &C);
  bool isSkippedType(const clang::RecordDecl *RD, std::string &Why);
  std::vector<std::string> recordKeys(const clang::RecordDecl *RD);

  /// The definition of \p RD, instantiating a class template specialization
  /// the TU only named (never asks for the layout of anything dependent).
  const clang::RecordDecl *completeDefinition(const clang::RecordDecl *RD,
                                              clang::SourceLocation Where);

  clang::ASTContext &Context;
  clang::Sema *S;
  unsigned TUIndex;
  ProgramModel &Program;
  /// Where diagnostics go: the program's, or a quiet one during a tentative
  /// walk.
  Diagnostics *Sink;
  const Selections &Select;
  std::unique_ptr<clang::PrintingPolicy> Policy;
  /// The type a reference member of \p Type is: the type itself when it is a
  /// class some pointer points to (\p Pointees), else a view (kTypeShallow)
  /// holding only the members on the way to such a class; kNoType when it holds
  /// none.
  std::uint32_t referenceView(clang::QualType Type,
                              const std::set<std::uint32_t> &Pointees,
                              const std::string &Root, const WalkContext &C,
                              int Depth);
  /// Views already made, by canonical Type* and root.
  std::map<std::pair<const clang::Type *, std::string>, std::uint32_t> Views;

  /// Types already walked in this TU (by canonical Type* and shallowness).
  std::map<std::pair<const clang::Type *, bool>, std::uint32_t> Walked;
  std::map<const clang::RecordDecl *, std::string> AnonymousNames;
  std::set<std::uint32_t> InProgress;
  /// Polymorphic pointees whose dynamic types this TU has looked for.
  std::set<std::uint32_t> DynamicTypesSought;
};

/// The context for the object a pointer (raw or smart) at \p C points to.
WalkContext intoPointee(const WalkContext &C, const std::string &PointerType);

/// Qualifies the unqualified old names of \p Name like it (see
/// CanonicalNames.cpp).
void qualifyLike(const std::string &Name, std::vector<std::string> &OldNames);

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_TYPEWALKER_H
