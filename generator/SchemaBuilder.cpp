//===- SchemaBuilder.cpp - Roots and reachable types from Clang ASTs
//-------===//

#include "SchemaBuilder.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/Attr.h"
#include "clang/AST/DeclCXX.h"
#include "clang/AST/DeclTemplate.h"
#include "clang/AST/Mangle.h"
#include "clang/AST/RecordLayout.h"
#include "clang/AST/RecursiveASTVisitor.h"
#include "clang/AST/VTableBuilder.h"
#include "clang/Basic/SourceManager.h"
#include "clang/Sema/Sema.h"
#include "llvm/ADT/StringExtras.h"
#include "llvm/Support/raw_ostream.h"

#include <algorithm>
#include <cstdlib>
#include <functional>

using namespace clang;

namespace symcr_gen {

namespace {

const char *const AnnotationPrefix = "symcr::";

/// Values of the `annotate` attributes that symcr's macros put on a
/// declaration or any of its redeclarations.
std::vector<std::string> symcrAnnotations(const Decl *D) {
  std::vector<std::string> Result;
  for (const Decl *Redecl : D->redecls())
    for (const auto *Attribute : Redecl->specific_attrs<AnnotateAttr>()) {
      llvm::StringRef Text = Attribute->getAnnotation();
      if (Text.startswith(AnnotationPrefix))
        Result.push_back(Text.drop_front(std::strlen(AnnotationPrefix)).str());
    }
  return Result;
}

bool hasAnnotation(const Decl *D, llvm::StringRef Name) {
  for (const std::string &A : symcrAnnotations(D))
    if (A == Name)
      return true;
  return false;
}

std::vector<std::string> renamedFromAnnotations(const Decl *D) {
  std::vector<std::string> Result;
  for (const std::string &A : symcrAnnotations(D))
    if (llvm::StringRef(A).startswith("renamed_from:"))
      Result.push_back(A.substr(std::strlen("renamed_from:")));
  return Result;
}

Location locationOf(const ASTContext &Context, SourceLocation Loc) {
  const SourceManager &SM = Context.getSourceManager();
  PresumedLoc P = SM.getPresumedLoc(SM.getExpansionLoc(Loc));
  if (P.isInvalid())
    return Location();
  return {P.getFilename(), P.getLine(), P.getColumn()};
}

bool isStdTemplate(const RecordDecl *RD, llvm::StringRef &Name) {
  if (!RD->isInStdNamespace() || !RD->getIdentifier())
    return false;
  Name = RD->getName();
  return true;
}

/// The index of the trailing "[N][M]" suffix of an array type name.
std::size_t arraySuffixStart(const std::string &Name) {
  std::size_t End = Name.size();
  while (End > 0 && Name[End - 1] == ']') {
    std::size_t Open = Name.rfind('[', End - 1);
    if (Open == std::string::npos)
      break;
    End = Open;
  }
  return End;
}

/// Indexes a TU's variables, records and typedefs by their qualified source
/// names so that directives can be resolved.
class NameIndex : public RecursiveASTVisitor<NameIndex> {
public:
  explicit NameIndex(ASTContext &Context) : Context(Context) {}

  bool VisitVarDecl(VarDecl *VD) {
    if (isa<ParmVarDecl>(VD) || !VD->getIdentifier())
      return true;
    Variables[rootName(VD)].push_back(VD);
    return true;
  }
  bool VisitRecordDecl(RecordDecl *RD) {
    if (!RD->isThisDeclarationADefinition() ||
        isa<ClassTemplateSpecializationDecl>(RD))
      return true;
    if (const auto *CRD = dyn_cast<CXXRecordDecl>(RD))
      if (!CRD->isDependentContext() && !CRD->isInvalidDecl() &&
          CRD->isPolymorphic())
        PolymorphicClasses.push_back(CRD);
    std::string Name = qualifiedName(RD);
    if (!Name.empty())
      Records[Name].push_back(RD);
    return true;
  }
  bool VisitClassTemplateDecl(ClassTemplateDecl *TD) {
    Templates[qualifiedDeclName(TD)].push_back(TD);
    return true;
  }
  bool VisitFunctionDecl(FunctionDecl *FD) {
    if (FD->getIdentifier() && FD->getName() == "symcr_validate")
      Validators.push_back(FD);
    if (FD->getIdentifier() && FD->getName() == "symcr_migrate")
      Migrators.push_back(FD);
    return true;
  }
  bool VisitTypedefNameDecl(TypedefNameDecl *TD) {
    Typedefs[qualifiedDeclName(TD)].push_back(TD);
    return true;
  }

  /// "ns::Class::member", "function::local": as a user names a root.
  static std::string rootName(const VarDecl *VD) {
    std::string Prefix;
    const DeclContext *DC = VD->getDeclContext();
    if (const auto *FD = dyn_cast<FunctionDecl>(DC)) {
      Prefix = qualifiedDeclName(FD);
    } else if (const auto *RD = dyn_cast<RecordDecl>(DC)) {
      Prefix = qualifiedName(RD);
    } else if (const auto *ND = dyn_cast<NamedDecl>(DC)) {
      Prefix = qualifiedDeclName(ND);
    }
    return Prefix.empty() ? VD->getName().str()
                          : Prefix + "::" + VD->getName().str();
  }

  /// Qualified name without anonymous or inline namespaces and without
  /// template arguments ("ns::Outer::Inner").
  static std::string qualifiedDeclName(const NamedDecl *ND) {
    std::string Result = qualifiedScope(ND);
    if (ND->getIdentifier())
      return Result + ND->getName().str();
    if (const auto *R = dyn_cast<RecordDecl>(ND))
      if (const TypedefNameDecl *T = R->getTypedefNameForAnonDecl())
        return Result + T->getName().str();
    return "";
  }
  /// The scope \p D is declared in, as a prefix ("ns::Outer::", or "").
  static std::string qualifiedScope(const Decl *D) {
    std::vector<std::string> Parts;
    for (const DeclContext *DC = D->getDeclContext(); DC;
         DC = DC->getParent()) {
      if (const auto *NS = dyn_cast<NamespaceDecl>(DC)) {
        if (NS->isAnonymousNamespace() || NS->isInline())
          continue;
        Parts.push_back(NS->getName().str());
      } else if (const auto *R = dyn_cast<RecordDecl>(DC)) {
        if (R->getIdentifier())
          Parts.push_back(R->getName().str());
        else if (const TypedefNameDecl *T = R->getTypedefNameForAnonDecl())
          Parts.push_back(T->getName().str());
      } else if (const auto *F = dyn_cast<FunctionDecl>(DC)) {
        Parts.push_back(F->getNameAsString());
      }
    }
    std::string Result;
    for (auto It = Parts.rbegin(); It != Parts.rend(); ++It)
      Result += *It + "::";
    return Result;
  }
  static std::string qualifiedName(const RecordDecl *RD) {
    return qualifiedDeclName(RD);
  }

  ASTContext &Context;
  std::map<std::string, std::vector<VarDecl *>> Variables;
  std::map<std::string, std::vector<RecordDecl *>> Records;
  std::map<std::string, std::vector<ClassTemplateDecl *>> Templates;
  std::map<std::string, std::vector<TypedefNameDecl *>> Typedefs;
  /// Class definitions with virtual functions, outside templates: the
  /// candidate dynamic types of heap objects behind polymorphic pointers.
  std::vector<const CXXRecordDecl *> PolymorphicClasses;
  /// Every function named symcr_validate (templates' patterns included).
  std::vector<FunctionDecl *> Validators;
  /// Every function named symcr_migrate (templates' patterns included).
  std::vector<FunctionDecl *> Migrators;
};

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
  /// range(Type::field, lo, hi) directives.
  std::map<std::pair<std::string, std::string>, std::pair<double, double>>
      FieldRanges;
  /// Record types (canonical) that have a usable `bool symcr_validate(const
  /// T&)` in this TU.
  std::set<const Type *> Validated;
  /// Record types (canonical) that have a usable `void symcr_migrate(T&, const
  /// symcr::OldValues&)` in this TU.
  std::set<const Type *> Migrated;
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
  /// The member whose value holds the current one (empty at a root's top level).
  MemberRef Enclosing;
  /// Where the walk left the selected object for another one through a pointer:
  /// the member to skip for everything unrestorable beyond (empty until then).
  MemberRef Group;
};

/// Walks the types reachable from one TU's roots into the ProgramModel.
class TypeWalker {
public:
  TypeWalker(ASTContext &Context, Sema *S, unsigned TUIndex,
             ProgramModel &Program, Diagnostics &Diags,
             const Selections &Select)
      : Context(Context), S(S), TUIndex(TUIndex), Program(Program),
        Sink(&Diags), Select(Select) {
    Policy = std::make_unique<PrintingPolicy>(Context.getPrintingPolicy());
    Policy->SuppressUnwrittenScope = true;
    Policy->SuppressTagKeyword = Context.getLangOpts().CPlusPlus;
    Policy->FullyQualifiedName = true;
  }

  std::uint32_t walk(QualType Type, const WalkContext &C);
  std::string spelling(QualType Type);
  /// Whether code at namespace scope may name \p Type: no part of it (the
  /// class, a class it is nested in, a template argument) is private or
  /// protected.
  static bool accessible(QualType Type);
  std::string canonicalRecordName(const RecordDecl *RD) {
    return recordName(RD, WalkContext());
  }

  /// The TU's class definitions with virtual functions (NameIndex).
  const std::vector<const CXXRecordDecl *> *PolymorphicClasses = nullptr;

private:
  std::uint32_t fail(const WalkContext &C, const std::string &What,
                     const std::string &Why);
  std::uint32_t scalar(const BuiltinType *BT, const WalkContext &C);
  std::uint32_t record(QualType Type, const RecordDecl *RD,
                       const WalkContext &C);
  std::uint32_t stdRecord(QualType Type, const RecordDecl *RD,
                          llvm::StringRef Name, const WalkContext &C);
  std::uint32_t enumeration(QualType Type, const EnumDecl *ED,
                            const WalkContext &C);
  std::uint32_t array(QualType Type, const ConstantArrayType *AT,
                      const WalkContext &C);
  std::uint32_t pointer(QualType Type, const PointerType *PT,
                        const WalkContext &C);
  std::uint32_t synthesizedPair(QualType Key, QualType Value,
                                const WalkContext &C);
  bool fillFields(const RecordDecl *RD, TypeModel &Model, const WalkContext &C);
  bool checkPointee(QualType Pointee, const WalkContext &C, const char *Holder);
  /// Finds the classes (\p Base or derived from it) a heap object behind a
  /// pointer to \p Base may be saved as, and walks each into the schema.
  void findDynamicTypes(const CXXRecordDecl *Base, std::uint32_t BaseIndex,
                        const WalkContext &C);
  /// Why restore cannot create \p Class as a heap object; empty if it can.
  std::string whyNotCreatable(const CXXRecordDecl *Class);
  /// Walks \p Type, or leaves the program model as it was and says why not.
  std::uint32_t tentativeWalk(QualType Type, const WalkContext &C,
                              std::string &Why);

  /// Registers \p Model under \p Key: reuses the global slot of the same name
  /// and checks that this TU describes it identically.
  std::uint32_t reserve(const std::string &Key, const std::string &Name,
                        bool &Fresh);
  void store(std::uint32_t Index, TypeModel Model, const WalkContext &C);
  std::string fingerprint(const TypeModel &Model) const;
  const char *leftToNewBuild(QualType Type) const;
  std::string canonicalName(QualType Type, const WalkContext &C);
  std::string recordName(const RecordDecl *RD, const WalkContext &C);
  std::string templateArgumentsName(const ClassTemplateSpecializationDecl *Spec,
                                    const WalkContext &C);
  bool isSkippedType(const RecordDecl *RD, std::string &Why);
  std::vector<std::string> recordKeys(const RecordDecl *RD);

  /// The definition of \p RD, instantiating a class template specialization
  /// the TU only named (never asks for the layout of anything dependent).
  const RecordDecl *completeDefinition(const RecordDecl *RD,
                                       SourceLocation Where);

  ASTContext &Context;
  Sema *S;
  unsigned TUIndex;
  ProgramModel &Program;
  /// Where diagnostics go: the program's, or a quiet one during a tentative walk.
  Diagnostics *Sink;
  const Selections &Select;
  std::unique_ptr<PrintingPolicy> Policy;
  /// Types already walked in this TU (by canonical Type* and shallowness).
  std::map<std::pair<const Type *, bool>, std::uint32_t> Walked;
  std::map<const RecordDecl *, std::string> AnonymousNames;
  std::set<std::uint32_t> InProgress;
  /// Polymorphic pointees whose dynamic types this TU has looked for.
  std::set<std::uint32_t> DynamicTypesSought;
};

std::uint32_t TypeWalker::fail(const WalkContext &C, const std::string &What,
                               const std::string &Why) {
  bool Grouped = !C.Group.empty() && C.Group.SkipHint != C.SkipHint;
  Sink->unrestorable(C.Where,
                     "'" + C.Path + "' reaches " + What + ", which cannot be " +
                         "checkpointed: " + Why,
                     C.SkipHint, Grouped ? &C.Group : nullptr);
  return symcr::kNoType;
}

/// The context for the object a pointer (raw or smart) at \p C points to. The
/// first such crossing marks the group: the member holding the pointer (or the
/// pointer itself at a root's top level), whose skip removes all beyond.
static WalkContext intoPointee(const WalkContext &C,
                               const std::string &PointerType) {
  WalkContext Target = C;
  Target.Path += "->";
  Target.Shallow = false;
  Target.AnonymousName.clear();
  if (Target.Group.empty())
    Target.Group = !C.Enclosing.empty()
                       ? C.Enclosing
                       : MemberRef{C.Path, C.SkipHint, PointerType, C.Where};
  return Target;
}

const RecordDecl *TypeWalker::completeDefinition(const RecordDecl *RD,
                                                 SourceLocation Where) {
  if (const RecordDecl *Definition = RD->getDefinition())
    return Definition;
  if (!S || RD->isDependentType() || !isa<ClassTemplateSpecializationDecl>(RD))
    return nullptr;
  QualType Type = Context.getRecordType(RD);
  if (S->isCompleteType(Where, Type))
    return RD->getDefinition();
  return nullptr;
}

/// Old names of a root or type resolve like its new name: an unqualified old name is in the same
/// scope (`SYMCR_RENAMED_FROM("g_log")` on `robot::g_journal` is `robot::g_log`), as for a
/// field. A leading `::` names the global scope.
static void qualifyLike(const std::string &Name, std::vector<std::string> &OldNames) {
  std::string::size_type Cut = Name.rfind("::");
  // The scope of the new name, not counting "::" inside template arguments.
  if (Name.find('<') != std::string::npos && Name.find('<') < Cut) {
    int Depth = 0;
    Cut = std::string::npos;
    for (std::string::size_type I = 0; I + 1 < Name.size(); ++I) {
      if (Name[I] == '<')
        ++Depth;
      else if (Name[I] == '>')
        --Depth;
      else if (Depth == 0 && Name.compare(I, 2, "::") == 0)
        Cut = I;
    }
  }
  std::string Scope = Cut == std::string::npos ? "" : Name.substr(0, Cut + 2);
  for (std::string &Old : OldNames) {
    if (Old.compare(0, 2, "::") == 0)
      Old.erase(0, 2);
    else if (Old.find("::") == std::string::npos)
      Old = Scope + Old;
  }
}

bool TypeWalker::accessible(QualType Type) {
  Type = Type.getCanonicalType();
  if (const auto *PT = Type->getAs<PointerType>())
    return accessible(PT->getPointeeType());
  if (const auto *AT = dyn_cast<ArrayType>(Type.getTypePtr()))
    return accessible(AT->getElementType());
  const auto *TT = Type->getAs<TagType>();
  if (!TT)
    return true;
  for (const Decl *D = TT->getDecl(); D && !isa<TranslationUnitDecl>(D);
       D = dyn_cast<Decl>(D->getDeclContext())) {
    if (D->getAccess() == AS_private || D->getAccess() == AS_protected)
      return false;
    if (const auto *Spec = dyn_cast<ClassTemplateSpecializationDecl>(D))
      for (const TemplateArgument &Arg : Spec->getTemplateArgs().asArray())
        if (Arg.getKind() == TemplateArgument::Type &&
            !accessible(Arg.getAsType()))
          return false;
  }
  return true;
}

std::string TypeWalker::spelling(QualType Type) {
  Type = Type.getCanonicalType().getUnqualifiedType();
  if (const auto *RT = Type->getAs<TagType>()) {
    const TagDecl *TD = RT->getDecl();
    if (!TD->getIdentifier() && !TD->getTypedefNameForAnonDecl())
      return "";
    for (const DeclContext *DC = TD->getDeclContext(); DC; DC = DC->getParent())
      if (DC->isFunctionOrMethod())
        return ""; // a local type: cannot be named outside its function
    if (!Context.getLangOpts().CPlusPlus) {
      if (const TypedefNameDecl *TN = TD->getTypedefNameForAnonDecl())
        return TN->getName().str();
      return (TD->isUnion()  ? "union "
              : TD->isEnum() ? "enum "
                             : "struct ") +
             TD->getName().str();
    }
  }
  // Canonical types print fully qualified (TypeName::getFullyQualifiedName
  // drops the scope of template pack arguments in Clang 14).
  PrintingPolicy Spelling = *Policy;
  Spelling.PrintCanonicalTypes = true;
  Spelling.FullyQualifiedName = true;
  std::string Result = Type.getAsString(Spelling);
  // A template argument that is an unnamed or local type cannot be written.
  for (const char *Unwritable : {"(unnamed", "(anonymous", "(lambda"})
    if (Result.find(Unwritable) != std::string::npos)
      return "";
  return Result;
}

std::vector<std::string> TypeWalker::recordKeys(const RecordDecl *RD) {
  std::vector<std::string> Keys;
  const RecordDecl *Named = RD;
  if (const auto *Spec = dyn_cast<ClassTemplateSpecializationDecl>(RD))
    Named = Spec->getSpecializedTemplate()->getTemplatedDecl();
  std::string Qualified = NameIndex::qualifiedName(Named);
  if (!Qualified.empty())
    Keys.push_back(Qualified);
  WalkContext None;
  std::string Canonical = recordName(RD, None);
  if (Canonical != Qualified)
    Keys.push_back(Canonical);
  return Keys;
}

bool TypeWalker::isSkippedType(const RecordDecl *RD, std::string &Why) {
  if (hasAnnotation(RD, "skip")) {
    Why = "SYMCR_SKIP on the type";
    return true;
  }
  for (const std::string &Key : recordKeys(RD)) {
    auto It = Select.SkippedTypes.find(Key);
    if (It != Select.SkippedTypes.end()) {
      Why = It->second;
      return true;
    }
  }
  return false;
}

std::string
TypeWalker::templateArgumentsName(const ClassTemplateSpecializationDecl *Spec,
                                  const WalkContext &C) {
  const TemplateArgumentList &Args = Spec->getTemplateArgs();
  const TemplateParameterList *Params =
      Spec->getSpecializedTemplate()->getTemplateParameters();
  // Drop trailing arguments equal to their parameter's (non-dependent) default.
  unsigned Count = Args.size();
  while (Count > 0 && Count <= Params->size()) {
    const NamedDecl *Param = Params->getParam(Count - 1);
    const TemplateArgument &Arg = Args[Count - 1];
    bool IsDefault = false;
    if (const auto *TP = dyn_cast<TemplateTypeParmDecl>(Param)) {
      if (TP->hasDefaultArgument() && Arg.getKind() == TemplateArgument::Type) {
        QualType Default = TP->getDefaultArgument();
        IsDefault = !Default->isDependentType() &&
                    Context.hasSameType(Default, Arg.getAsType());
      }
    } else if (const auto *NTP = dyn_cast<NonTypeTemplateParmDecl>(Param)) {
      if (NTP->hasDefaultArgument() &&
          Arg.getKind() == TemplateArgument::Integral &&
          !NTP->getDefaultArgument()->isValueDependent()) {
        Expr::EvalResult Result;
        if (NTP->getDefaultArgument()->EvaluateAsInt(Result, Context))
          IsDefault = Result.Val.getInt() == Arg.getAsIntegral();
      }
    }
    if (!IsDefault)
      break;
    --Count;
  }
  // The standard library's defaults depend on earlier arguments
  // (std::allocator<T>); drop them by shape.
  if (Spec->isInStdNamespace()) {
    static const char *const DefaultShapes[] = {
        "std::allocator<", "std::char_traits<", "std::less<",
        "std::hash<",      "std::equal_to<",    "std::default_delete<"};
    while (Count > 1 && Args[Count - 1].getKind() == TemplateArgument::Type) {
      std::string Name = canonicalName(Args[Count - 1].getAsType(), C);
      bool Default = false;
      for (const char *Shape : DefaultShapes)
        Default |= llvm::StringRef(Name).startswith(Shape);
      if (!Default)
        break;
      --Count;
    }
  }
  std::string Result = "<";
  for (unsigned I = 0; I < Count; ++I) {
    if (I)
      Result += ",";
    const TemplateArgument &Arg = Args[I];
    switch (Arg.getKind()) {
    case TemplateArgument::Type:
      Result += canonicalName(Arg.getAsType(), C);
      break;
    case TemplateArgument::Integral:
      Result += Arg.getIntegralType()->isBooleanType()
                    ? (Arg.getAsIntegral().getBoolValue() ? "true" : "false")
                    : llvm::toString(Arg.getAsIntegral(), 10);
      break;
    case TemplateArgument::Pack: {
      bool First = true;
      for (const TemplateArgument &P : Arg.pack_elements()) {
        if (!First)
          Result += ",";
        First = false;
        if (P.getKind() == TemplateArgument::Type)
          Result += canonicalName(P.getAsType(), C);
        else if (P.getKind() == TemplateArgument::Integral)
          Result += llvm::toString(P.getAsIntegral(), 10);
        else {
          std::string S;
          llvm::raw_string_ostream OS(S);
          P.print(*Policy, OS, /*IncludeType=*/false);
          Result += OS.str();
        }
      }
      break;
    }
    default: {
      std::string S;
      llvm::raw_string_ostream OS(S);
      Arg.print(*Policy, OS, /*IncludeType=*/false);
      Result += OS.str();
    }
    }
  }
  // A pack that expanded to nothing leaves a trailing comma.
  if (Result.size() > 1 && Result.back() == ',')
    Result.pop_back();
  return Result + ">";
}

std::string TypeWalker::recordName(const RecordDecl *RD, const WalkContext &C) {
  auto Known = AnonymousNames.find(RD);
  if (Known != AnonymousNames.end())
    return Known->second;
  std::string Name;
  // The enclosing scopes, with record scopes printed canonically.
  std::string Scope;
  const DeclContext *DC = RD->getDeclContext();
  if (const auto *Parent = dyn_cast<RecordDecl>(DC))
    Scope = recordName(Parent, C) + "::";
  else {
    std::vector<std::string> Parts;
    for (; DC && !isa<TranslationUnitDecl>(DC); DC = DC->getParent()) {
      if (const auto *NS = dyn_cast<NamespaceDecl>(DC)) {
        if (NS->isInline())
          continue;
        Parts.push_back(NS->isAnonymousNamespace() ? "(anonymous namespace)"
                                                   : NS->getName().str());
      } else if (const auto *F = dyn_cast<FunctionDecl>(DC)) {
        Parts.push_back(NameIndex::qualifiedDeclName(F));
        break; // carries its own scope
      } else if (const auto *R = dyn_cast<RecordDecl>(DC)) {
        Parts.push_back(recordName(R, C));
        break; // carries its own scope
      }
    }
    for (auto It = Parts.rbegin(); It != Parts.rend(); ++It)
      Scope += *It + "::";
  }
  if (RD->getIdentifier())
    Name = Scope + RD->getName().str();
  else if (const TypedefNameDecl *TD = RD->getTypedefNameForAnonDecl())
    Name = Scope + TD->getName().str();
  else
    Name =
        C.AnonymousName.empty()
            ? Scope + "(anonymous " + (RD->isUnion() ? "union" : "struct") + ")"
            : C.AnonymousName;
  if (const auto *Spec = dyn_cast<ClassTemplateSpecializationDecl>(RD))
    Name += templateArgumentsName(Spec, C);
  return Name;
}

std::string TypeWalker::canonicalName(QualType Type, const WalkContext &C) {
  Type = Type.getCanonicalType().getUnqualifiedType();
  if (const auto *BT = dyn_cast<BuiltinType>(Type.getTypePtr())) {
    if (BT->isBooleanType())
      return "bool";
    std::uint64_t Bits = Context.getTypeSize(BT);
    if (BT->isFloatingPoint())
      return Bits == 32 ? "float32" : Bits == 64 ? "float64" : "float80";
    if (BT->isIntegerType())
      return (BT->isSignedIntegerType() ? "int" : "uint") +
             std::to_string(Bits);
    return BT->getName(*Policy).str();
  }
  if (const auto *PT = Type->getAs<PointerType>())
    return canonicalName(PT->getPointeeType(), C) + "*";
  if (const auto *AT = Context.getAsConstantArrayType(Type)) {
    std::string Element = canonicalName(AT->getElementType(), C);
    std::size_t Suffix = arraySuffixStart(Element);
    return Element.substr(0, Suffix) + "[" +
           llvm::toString(AT->getSize(), 10, false) + "]" +
           Element.substr(Suffix);
  }
  if (const auto *ET = Type->getAs<EnumType>()) {
    // An unnamed enum takes its typedef's name (`typedef enum {...} mode_t;` is
    // `mode_t`, as for structs), else its first enumerator's, which no other
    // enum of the same scope can have: two unnamed enums never share a name.
    const EnumDecl *ED = ET->getDecl();
    const NamedDecl *Named = ED;
    std::string Unnamed;
    if (!ED->getIdentifier()) {
      if (const TypedefNameDecl *TD = ED->getTypedefNameForAnonDecl())
        Named = TD;
      else
        Unnamed = ED->enumerator_begin() == ED->enumerator_end()
                      ? "(anonymous enum)"
                      : "(anonymous enum " +
                            ED->enumerator_begin()->getName().str() + ")";
    }
    if (const auto *Parent = dyn_cast<RecordDecl>(ED->getDeclContext()))
      return recordName(Parent, C) + "::" +
             (Unnamed.empty() ? Named->getName().str() : Unnamed);
    if (!Unnamed.empty())
      return NameIndex::qualifiedScope(ED) + Unnamed;
    return NameIndex::qualifiedDeclName(Named);
  }
  if (const auto *RT = Type->getAs<RecordType>())
    return recordName(RT->getDecl(), C);
  return Type.getAsString(*Policy);
}

/// Why a member of type \p Type is never restored and left to the new build, or null. A
/// const member is the new build's constant (writing it would be undefined behaviour, and would
/// undo a patch that changed it); a reference is bound by the new build's constructor; a
/// function or member pointer is code of the old build (restoring one would be an arc-injection
/// vector).
const char *TypeWalker::leftToNewBuild(QualType Type) const {
  QualType Canonical = Type.getCanonicalType();
  if (Canonical->isReferenceType())
    return "reference member: bound by the new build";
  QualType Element = Context.getBaseElementType(Canonical);
  if (Element.isConstQualified())
    return "const member: the new build's value is kept";
  if (Element->isMemberPointerType())
    return "member pointer: code of the old build";
  if (Element->isFunctionPointerType())
    return "function pointer: code of the old build";
  return nullptr;
}

std::string TypeWalker::fingerprint(const TypeModel &Model) const {
  std::string F =
      Model.Name + "|" + std::to_string(static_cast<int>(Model.Kind)) + "|" +
      std::to_string(Model.Flags) + "|" + std::to_string(Model.Size) + "|" +
      std::to_string(Model.Align) + "|" + std::to_string(Model.Count) + "|";
  auto NameOf = [&](std::uint32_t Index) {
    return Index == symcr::kNoType ? std::string("-")
                                   : Program.Types[Index].Name;
  };
  F += NameOf(Model.Element);
  if (Model.HasValidate)
    F += "|validate";
  if (Model.HasMigrate)
    F += "|migrate";
  for (const FieldModel &Field : Model.Fields) {
    F += "|" + Field.Name + ":" + NameOf(Field.Type) + "@" +
         std::to_string(Field.Offset) + "." + std::to_string(Field.BitOffset) +
         "/" + std::to_string(Field.BitWidth);
    if (Field.Flags & symcr::kFieldHasRange)
      F += "[" + std::to_string(Field.RangeMin) + "," +
           std::to_string(Field.RangeMax) + "]";
  }
  for (const auto &E : Model.Enumerators)
    F += "|" + E.first + "=" + std::to_string(E.second);
  for (const TypeModel::LeftMember &Left : Model.LeftToNewBuild)
    F += "|left " + Left.Name + ": " + Left.Why;
  for (std::uint32_t A : Model.Alternatives)
    F += "|" + NameOf(A);
  return F;
}

std::uint32_t TypeWalker::reserve(const std::string &Key,
                                  const std::string &Name, bool &Fresh) {
  auto It = Program.TypeIndex.find(Key);
  if (It != Program.TypeIndex.end()) {
    Fresh = false;
    return It->second;
  }
  Fresh = true;
  std::uint32_t Index = static_cast<std::uint32_t>(Program.Types.size());
  Program.Types.emplace_back();
  Program.Types.back().Name = Name;
  Program.Types.back().HomeTU = TUIndex;
  Program.TypeIndex.emplace(Key, Index);
  return Index;
}

void TypeWalker::store(std::uint32_t Index, TypeModel Model,
                       const WalkContext &C) {
  TypeModel &Slot = Program.Types[Index];
  Model.Fingerprint = fingerprint(Model);
  if (!Slot.Fingerprint.empty()) {
    const bool SameUnit =
        Slot.FirstSeenIn == Program.TranslationUnits[TUIndex].Source;
    if (Slot.Fingerprint != Model.Fingerprint && SameUnit) {
      // Two types of one translation unit share a canonical name: no annotation
      // placement can fix that, only a name.
      Sink->error(C.Where,
                  "two different types are named '" + Model.Name +
                      "' (the second reached by '" + C.Path +
                      "'): give one of them a distinct name (a typedef or a "
                      "tag) to checkpoint both");
    } else if (Slot.Fingerprint != Model.Fingerprint &&
               Model.Name.find("(anonymous namespace)") != std::string::npos) {
      Sink->error(
          C.Where,
          "two different types are named '" + Model.Name + "' (reached by '" +
              C.Path + "' here and in '" + Slot.FirstSeenIn +
              "'): types with internal linkage in different translation "
              "units need distinct names to be checkpointed");
    } else if (Slot.Fingerprint != Model.Fingerprint) {
      Sink->error(
          C.Where,
          "type '" + Model.Name + "' (reached by '" + C.Path +
              "') is described differently in this translation unit "
              "than in '" +
              Slot.FirstSeenIn +
              "': annotations (pragmas) that select its members must be "
              "visible wherever the type is, e.g. in its header");
    }
    Slot.NeedsLifecycle |= Model.NeedsLifecycle;
    return;
  }
  Model.HomeTU = Slot.HomeTU;
  Model.NeedsLifecycle |= Slot.NeedsLifecycle;
  // Attached while the type was still being walked (a pointer inside it to itself).
  Model.VtableSymbol = std::move(Slot.VtableSymbol);
  Model.VtableAddressPoint = Slot.VtableAddressPoint;
  Model.DynamicTypes = std::move(Slot.DynamicTypes);
  Model.NotDynamicTypes = std::move(Slot.NotDynamicTypes);
  Model.DynamicTypesReachedBy = std::move(Slot.DynamicTypesReachedBy);
  Model.FirstSeenIn = Program.TranslationUnits[TUIndex].Source;
  Slot = std::move(Model);
}

std::uint32_t TypeWalker::walk(QualType Type, const WalkContext &C) {
  Type = Type.getCanonicalType();
  if (Type->isReferenceType())
    return fail(C, "a reference (" + Type.getAsString(*Policy) + ")",
                "a reference cannot be re-seated on restore");
  Type = Type.getUnqualifiedType();
  if (Type.isVolatileQualified())
    Type = Type.getUnqualifiedType();
  auto Key = std::make_pair(Type.getTypePtr(), C.Shallow);
  auto Done = Walked.find(Key);
  if (Done != Walked.end())
    return Done->second;
  std::uint32_t Result = symcr::kNoType;
  if (const auto *BT = dyn_cast<BuiltinType>(Type.getTypePtr()))
    Result = scalar(BT, C);
  else if (const auto *ET = Type->getAs<EnumType>())
    Result = enumeration(Type, ET->getDecl(), C);
  else if (const auto *AT = Context.getAsConstantArrayType(Type))
    Result = array(Type, AT, C);
  else if (Type->isArrayType())
    return fail(C, "'" + Type.getAsString(*Policy) + "'",
                "an array without a constant size has no fixed layout");
  else if (const auto *PT = Type->getAs<PointerType>())
    Result = pointer(Type, PT, C);
  else if (Type->isMemberPointerType())
    return fail(C, "a member pointer", "it is code/layout-dependent, not data");
  else if (Type->isAtomicType())
    return fail(C, "an _Atomic object", "atomics are synchronisation state");
  else if (const auto *RT = Type->getAs<RecordType>())
    Result = record(Type, RT->getDecl(), C);
  else
    return fail(C, "'" + Type.getAsString(*Policy) + "'",
                "this kind of type is not supported");
  if (Result != symcr::kNoType)
    Walked[Key] = Result;
  return Result;
}

std::uint32_t TypeWalker::scalar(const BuiltinType *BT, const WalkContext &C) {
  TypeModel Model;
  Model.Size = Context.getTypeSizeInChars(BT).getQuantity();
  Model.Align = Context.getTypeAlignInChars(BT).getQuantity();
  if (BT->isBooleanType()) {
    Model.Kind = symcr::Kind::Bool;
  } else if (BT->isFloatingPoint()) {
    const llvm::fltSemantics &Semantics =
        Context.getFloatTypeSemantics(QualType(BT, 0));
    if (&Semantics != &llvm::APFloat::IEEEsingle() &&
        &Semantics != &llvm::APFloat::IEEEdouble() &&
        &Semantics != &llvm::APFloat::x87DoubleExtended())
      return fail(
          C, "'" + BT->getName(*Policy).str() + "'",
          "only binary32, binary64 and x87 extended floats are supported");
    Model.Kind = symcr::Kind::Float;
  } else if (BT->isIntegerType()) {
    if (Model.Size != 1 && Model.Size != 2 && Model.Size != 4 &&
        Model.Size != 8)
      return fail(C, "'" + BT->getName(*Policy).str() + "'",
                  "integers wider than 64 bits are not supported");
    Model.Kind =
        BT->isSignedIntegerType() ? symcr::Kind::Int : symcr::Kind::UInt;
  } else {
    return fail(C, "'" + BT->getName(*Policy).str() + "'",
                "it holds no restorable value");
  }
  Model.Name = canonicalName(QualType(BT, 0), C);
  Model.Spelling = BT->getName(*Policy).str();
  bool Fresh;
  std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
  store(Index, std::move(Model), C);
  return Index;
}

std::uint32_t TypeWalker::enumeration(QualType Type, const EnumDecl *ED,
                                      const WalkContext &C) {
  ED = ED->getDefinition();
  if (!ED)
    return fail(C, "an incomplete enum", "its enumerators are unknown");
  TypeModel Model;
  Model.Kind = symcr::Kind::Enum;
  Model.Name = canonicalName(Type, C);
  Model.Spelling = spelling(Type);
  Model.Accessible = accessible(Type);
  Model.Size = Context.getTypeSizeInChars(Type).getQuantity();
  Model.Align = Context.getTypeAlignInChars(Type).getQuantity();
  if (ED->isScoped())
    Model.Flags |= symcr::kTypeScopedEnum;
  Model.RenamedFrom = renamedFromAnnotations(ED);
  qualifyLike(Model.Name, Model.RenamedFrom);
  for (const EnumConstantDecl *E : ED->enumerators()) {
    const llvm::APSInt &Value = E->getInitVal();
    std::int64_t Stored = Value.isSigned()
                              ? Value.getSExtValue()
                              : static_cast<std::int64_t>(Value.getZExtValue());
    Model.Enumerators.emplace_back(E->getName().str(), Stored);
  }
  bool Fresh;
  std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
  Walked[{Type.getTypePtr(), C.Shallow}] = Index;
  Model.Element = walk(ED->getIntegerType(), C);
  if (Model.Element == symcr::kNoType)
    return symcr::kNoType;
  store(Index, std::move(Model), C);
  return Index;
}

std::uint32_t TypeWalker::array(QualType Type, const ConstantArrayType *AT,
                                const WalkContext &C) {
  TypeModel Model;
  Model.Kind = symcr::Kind::Array;
  Model.Name = canonicalName(Type, C);
  Model.Size = Context.getTypeSizeInChars(Type).getQuantity();
  Model.Align = Context.getTypeAlignInChars(Type).getQuantity();
  Model.Count = AT->getSize().getZExtValue();
  WalkContext Element = C;
  Element.Path += "[]";
  Element.Shallow = false;
  Model.Element = walk(AT->getElementType(), Element);
  if (Model.Element == symcr::kNoType)
    return symcr::kNoType;
  bool Fresh;
  std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
  store(Index, std::move(Model), C);
  return Index;
}

bool TypeWalker::checkPointee(QualType Pointee, const WalkContext &C,
                              const char *Holder) {
  Pointee = Pointee.getCanonicalType();
  if (Pointee->isFunctionType()) {
    fail(C, std::string("a function ") + Holder,
         "code addresses differ between builds; re-register callbacks after "
         "restore");
    return false;
  }
  if (Pointee->isVoidType()) {
    fail(C, std::string("a void ") + Holder, "the pointee's type is unknown");
    return false;
  }
  if (const auto *RT = Pointee->getAs<RecordType>()) {
    const RecordDecl *RD =
        completeDefinition(RT->getDecl(), RT->getDecl()->getLocation());
    std::string Name = RT->getDecl()->getName().str();
    if (Name == "_IO_FILE" || Name == "FILE")
      return fail(C, "a FILE handle",
                  "file handles are process state; reopen after "
                  "restore"),
             false;
    if (!RD) {
      fail(C,
           std::string("a ") + Holder + " to incomplete type '" +
               Pointee.getAsString(*Policy) + "'",
           "its layout is unknown here");
      return false;
    }
    // A raw pointer to a polymorphic class is a reference to a checkpointed
    // object (a member, an element), or a heap object saved as its dynamic
    // type (findDynamicTypes). An owning smart pointer would rebuild its
    // object as its static type, slicing it: refused.
    if (const auto *CRD = dyn_cast<CXXRecordDecl>(RD))
      if (CRD->isPolymorphic() && !CRD->hasAttr<FinalAttr>() &&
          llvm::StringRef(Holder) != "pointer") {
        fail(C,
             std::string("a ") + Holder + " to polymorphic class '" +
                 Pointee.getAsString(*Policy) + "'",
             "the pointee's dynamic type may differ from the static type (make "
             "the class "
             "final, or skip the pointer)");
        return false;
      }
  }
  return true;
}

std::uint32_t TypeWalker::pointer(QualType Type, const PointerType *PT,
                                  const WalkContext &C) {
  QualType Pointee = PT->getPointeeType();
  if (!checkPointee(Pointee, C, "pointer"))
    return symcr::kNoType;
  TypeModel Model;
  Model.Kind = symcr::Kind::Pointer;
  Model.Name = canonicalName(Type, C);
  Model.Size = Context.getTypeSizeInChars(Type).getQuantity();
  Model.Align = Context.getTypeAlignInChars(Type).getQuantity();
  bool Fresh;
  std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
  Walked[{Type.getTypePtr(), false}] = Index;
  Model.Element = walk(Pointee, intoPointee(C, Model.Name));
  if (Model.Element == symcr::kNoType)
    return symcr::kNoType;
  // A polymorphic pointee is created by restore as its dynamic type, which
  // has a Lifecycle of its own; the pointee itself may be abstract.
  std::uint32_t Element = Model.Element;
  if (!(Program.Types[Element].Flags & symcr::kTypePolymorphic))
    Program.Types[Element].NeedsLifecycle = true;
  store(Index, std::move(Model), C);
  if (Program.Types[Element].Flags & symcr::kTypePolymorphic)
    findDynamicTypes(Pointee->getAsCXXRecordDecl(), Element,
                     intoPointee(C, Program.Types[Index].Name));
  return Index;
}

std::string TypeWalker::whyNotCreatable(const CXXRecordDecl *Class) {
  std::string Why;
  if (isSkippedType(Class, Why))
    return "skipped (" + Why + ")";
  if (Class->getNumVBases() > 0)
    return "it has virtual bases";
  QualType Type = Context.getRecordType(Class);
  if (spelling(Type).empty() || !accessible(Type))
    return "it cannot be named outside its scope";
  auto *Mutable = const_cast<CXXRecordDecl *>(Class);
  const CXXConstructorDecl *Constructor =
      S ? S->LookupDefaultConstructor(Mutable) : nullptr;
  if (!S ? !Class->hasDefaultConstructor()
         : !Constructor || Constructor->isDeleted() ||
               Constructor->getAccess() != AS_public)
    return "no public default constructor";
  const CXXDestructorDecl *Destructor = S ? S->LookupDestructor(Mutable) : nullptr;
  if (S && (!Destructor || Destructor->isDeleted() ||
            Destructor->getAccess() != AS_public))
    return "no public destructor";
  return "";
}

std::uint32_t TypeWalker::tentativeWalk(QualType Type, const WalkContext &C,
                                        std::string &Why) {
  auto Done = Walked.find({Type.getCanonicalType().getTypePtr(), C.Shallow});
  if (Done != Walked.end())
    return Done->second;
  std::vector<TypeModel> Types = Program.Types;
  std::map<std::string, std::uint32_t> TypeIndex = Program.TypeIndex;
  auto WalkedBefore = Walked;
  auto SoughtBefore = DynamicTypesSought;
  Diagnostics Quiet(/*Quiet=*/true);
  Diagnostics *Outer = Sink;
  Sink = &Quiet;
  std::uint32_t Index = walk(Type, C);
  Sink = Outer;
  if (Index != symcr::kNoType && Quiet.clean())
    return Index;
  Why = Quiet.firstProblem();
  Program.Types = std::move(Types);
  Program.TypeIndex = std::move(TypeIndex);
  Walked = std::move(WalkedBefore);
  DynamicTypesSought = std::move(SoughtBefore);
  return symcr::kNoType;
}

void TypeWalker::findDynamicTypes(const CXXRecordDecl *Base,
                                  std::uint32_t BaseIndex,
                                  const WalkContext &C) {
  if (!Base || !PolymorphicClasses || !DynamicTypesSought.insert(BaseIndex).second)
    return;
  Base = Base->getDefinition();
  if (Program.Types[BaseIndex].DynamicTypesReachedBy.empty())
    Program.Types[BaseIndex].DynamicTypesReachedBy = C.Path.substr(0, C.Path.size() - 2);
  auto NotCreatable = [&](const std::string &Name, const std::string &Why) {
    std::string Entry = Name + ": " + Why;
    std::vector<std::string> &List = Program.Types[BaseIndex].NotDynamicTypes;
    if (std::find(List.begin(), List.end(), Entry) == List.end())
      List.push_back(Entry);
  };
  // Saving recognises a class by its vtable, laid out by the Itanium C++ ABI
  // (every GCC and Clang target symcr supports).
  std::unique_ptr<MangleContext> Mangler(Context.createMangleContext());
  auto *Itanium = dyn_cast<ItaniumMangleContext>(Mangler.get());
  auto *VTables = dyn_cast<ItaniumVTableContext>(Context.getVTableContext());
  if (!Itanium || !VTables || VTables->isRelativeLayout()) {
    NotCreatable(Base->getNameAsString(),
                 "the target's C++ ABI is not the Itanium one");
    return;
  }
  for (const CXXRecordDecl *Class : *PolymorphicClasses) {
    if (Class != Base && !Class->isDerivedFrom(Base))
      continue;
    if (Class->isAbstract())
      continue; // never an object's dynamic type
    std::string Name = canonicalRecordName(Class);
    std::string Why = whyNotCreatable(Class);
    QualType Type = Context.getRecordType(Class);
    std::uint32_t Index = symcr::kNoType;
    if (Why.empty()) {
      WalkContext Candidate = C;
      Candidate.Path = C.Path + "(" + Name + ")";
      Index = tentativeWalk(Type, Candidate, Why);
    }
    if (Index == symcr::kNoType) {
      NotCreatable(Name, Why);
      continue;
    }
    TypeModel &Dynamic = Program.Types[Index];
    Dynamic.NeedsLifecycle = true;
    std::string Symbol;
    llvm::raw_string_ostream Out(Symbol);
    Itanium->mangleCXXVTable(Class, Out);
    Dynamic.VtableSymbol = Out.str();
    Dynamic.VtableAddressPoint =
        VTables->getVTableLayout(Class)
            .getAddressPoint(BaseSubobject(Class, CharUnits::Zero()))
            .AddressPointIndex;
    std::vector<std::uint32_t> &List = Program.Types[BaseIndex].DynamicTypes;
    if (std::find(List.begin(), List.end(), Index) == List.end())
      List.push_back(Index);
  }
}

std::uint32_t TypeWalker::synthesizedPair(QualType Key, QualType Value,
                                          const WalkContext &C) {
  // The staged map element: std::pair<K, V> (symcr::ops::element_t), laid out
  // as the map's pair<const K, V>. Itanium layout of two members; checked by
  // static_assert in the home TU.
  Key = Key.getCanonicalType().getUnqualifiedType();
  Value = Value.getCanonicalType().getUnqualifiedType();
  TypeModel Model;
  Model.Kind = symcr::Kind::Struct;
  Model.Name = "std::pair<" + canonicalName(Key, C) + "," +
               canonicalName(Value, C) + ">";
  std::string KeySpelling = spelling(Key), ValueSpelling = spelling(Value);
  if (!KeySpelling.empty() && !ValueSpelling.empty())
    Model.Spelling = "::std::pair<" + KeySpelling + ", " + ValueSpelling + ">";
  Model.Accessible = accessible(Key) && accessible(Value);
  std::uint64_t KeySize = Context.getTypeSizeInChars(Key).getQuantity();
  std::uint64_t ValueSize = Context.getTypeSizeInChars(Value).getQuantity();
  std::uint64_t KeyAlign = Context.getTypeAlignInChars(Key).getQuantity();
  std::uint64_t ValueAlign = Context.getTypeAlignInChars(Value).getQuantity();
  std::uint64_t SecondOffset = llvm::alignTo(KeySize, ValueAlign);
  Model.Align = std::max(KeyAlign, ValueAlign);
  Model.Size = llvm::alignTo(SecondOffset + ValueSize, Model.Align);
  Model.NeedsLifecycle = true;
  bool Fresh;
  std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
  WalkContext First = C, Second = C;
  First.Path += ".first";
  Second.Path += ".second";
  FieldModel F1, F2;
  F1.Name = "first";
  F1.Type = walk(Key, First);
  F2.Name = "second";
  F2.Type = walk(Value, Second);
  F2.Offset = SecondOffset;
  if (F1.Type == symcr::kNoType || F2.Type == symcr::kNoType)
    return symcr::kNoType;
  Model.Fields = {F1, F2};
  store(Index, std::move(Model), C);
  return Index;
}

/// Finds the storage of element \p Wanted of a libstdc++ std::tuple: the
/// _Head_base<Wanted, T> base, holding the value in _M_head_impl or (empty T)
/// as its own base.
static bool findTupleElement(const ASTContext &Context, const CXXRecordDecl *RD,
                             unsigned Wanted, std::uint64_t Offset,
                             std::uint64_t &ElementOffset) {
  const ASTRecordLayout &Layout = Context.getASTRecordLayout(RD);
  for (const CXXBaseSpecifier &Base : RD->bases()) {
    const CXXRecordDecl *BaseRD = Base.getType()->getAsCXXRecordDecl();
    if (!BaseRD || Base.isVirtual())
      continue;
    std::uint64_t BaseOffset =
        Offset + Layout.getBaseClassOffset(BaseRD).getQuantity();
    const auto *Spec = dyn_cast<ClassTemplateSpecializationDecl>(BaseRD);
    if (Spec && Spec->getName() == "_Head_base" &&
        Spec->getTemplateArgs().size() >= 1 &&
        Spec->getTemplateArgs()[0].getKind() == TemplateArgument::Integral &&
        Spec->getTemplateArgs()[0].getAsIntegral() == Wanted) {
      for (const FieldDecl *F : Spec->fields())
        if (F->getName() == "_M_head_impl") {
          ElementOffset =
              BaseOffset + Context.getASTRecordLayout(Spec).getFieldOffset(
                               F->getFieldIndex()) /
                               8;
          return true;
        }
      ElementOffset = BaseOffset; // empty element stored as a base
      return true;
    }
    if (Spec && Spec->getName() == "_Tuple_impl" &&
        findTupleElement(Context, BaseRD, Wanted, BaseOffset, ElementOffset))
      return true;
  }
  return false;
}

std::uint32_t TypeWalker::stdRecord(QualType Type, const RecordDecl *RD,
                                    llvm::StringRef Name,
                                    const WalkContext &C) {
  const auto *Spec = dyn_cast<ClassTemplateSpecializationDecl>(RD);
  auto Arg = [&](unsigned I) { return Spec->getTemplateArgs()[I].getAsType(); };
  TypeModel Model;
  Model.Name = canonicalName(Type, C);
  Model.Spelling = spelling(Type);
  Model.Accessible = accessible(Type);
  Model.Size = Context.getTypeSizeInChars(Type).getQuantity();
  Model.Align = Context.getTypeAlignInChars(Type).getQuantity();
  bool Fresh;
  auto Reserve = [&] {
    std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
    Walked[{Type.getTypePtr(), false}] = Index;
    return Index;
  };
  auto Element = [&](QualType T, const char *Suffix) {
    WalkContext E = C;
    E.Path += Suffix;
    E.Shallow = false;
    E.AnonymousName.clear();
    return walk(T, E);
  };
  static const std::map<std::string, symcr::ContainerKind> Containers = {
      {"vector", symcr::ContainerKind::Vector},
      {"deque", symcr::ContainerKind::Deque},
      {"list", symcr::ContainerKind::List},
      {"forward_list", symcr::ContainerKind::ForwardList},
      {"set", symcr::ContainerKind::Set},
      {"multiset", symcr::ContainerKind::MultiSet},
      {"unordered_set", symcr::ContainerKind::UnorderedSet},
      {"unordered_multiset", symcr::ContainerKind::UnorderedMultiSet},
      {"map", symcr::ContainerKind::Map},
      {"multimap", symcr::ContainerKind::MultiMap},
      {"unordered_map", symcr::ContainerKind::UnorderedMap},
      {"unordered_multimap", symcr::ContainerKind::UnorderedMultiMap}};
  static const std::map<std::string, std::string> Unrestorable = {
      {"function", "a std::function holds code"},
      {"mutex", "a mutex is synchronisation state"},
      {"recursive_mutex", "a mutex is synchronisation state"},
      {"timed_mutex", "a mutex is synchronisation state"},
      {"shared_mutex", "a mutex is synchronisation state"},
      {"condition_variable", "a condition variable is synchronisation state"},
      {"thread", "a thread is process state"},
      {"jthread", "a thread is process state"},
      {"atomic", "atomics are synchronisation state"},
      {"weak_ptr", "a weak_ptr does not own its pointee"},
      {"basic_fstream", "a file stream is process state"},
      {"basic_ifstream", "a file stream is process state"},
      {"basic_ofstream", "a file stream is process state"},
      {"basic_filebuf", "a file stream is process state"},
      {"reference_wrapper", "a reference cannot be re-seated"},
      {"any", "its contained type is only known at run time"}};
  if (auto It = Unrestorable.find(Name.str()); It != Unrestorable.end())
    return fail(C, "'" + Model.Name + "'", It->second);
  if (Model.Spelling.empty())
    return fail(
        C, "'" + Model.Name + "'",
        "its operations must be instantiated by name, and one of its "
        "template arguments is an unnamed or local type; give that type a "
        "name at namespace or class scope");
  if (!Spec)
    goto Unsupported;
  if (Name == "basic_string") {
    Model.Kind = symcr::Kind::String;
    Model.Ops = OpsKind::String;
    std::uint32_t Index = Reserve();
    Model.Element = Element(Arg(0), "[]");
    if (Model.Element == symcr::kNoType)
      return symcr::kNoType;
    store(Index, std::move(Model), C);
    return Index;
  }
  if (auto It = Containers.find(Name.str()); It != Containers.end()) {
    if (Name == "vector" && Arg(0)->isBooleanType())
      return fail(C, "'std::vector<bool>'",
                  "its elements are bits without addresses; use "
                  "std::vector<uint8_t> or "
                  "std::deque<bool>");
    Model.Kind = symcr::Kind::Container;
    Model.ContainerKind = static_cast<std::uint8_t>(It->second);
    Model.Ops = OpsKind::Container;
    std::uint32_t Index = Reserve();
    bool IsMap = Name.endswith("map");
    bool IsAssociative = IsMap || Name.endswith("set");
    if (IsMap) {
      WalkContext E = C;
      E.Path += "[]";
      E.Shallow = false;
      Model.Element = synthesizedPair(Arg(0), Arg(1), E);
    } else {
      Model.Element = Element(Arg(0), "[]");
    }
    if (Model.Element == symcr::kNoType)
      return symcr::kNoType;
    if (IsAssociative)
      Program.Types[Model.Element].NeedsLifecycle = true;
    store(Index, std::move(Model), C);
    return Index;
  }
  if (Name == "array") {
    Model.Kind = symcr::Kind::Array;
    Model.Count = Spec->getTemplateArgs()[1].getAsIntegral().getZExtValue();
    std::uint32_t Index = Reserve();
    Model.Element = Element(Arg(0), "[]");
    if (Model.Element == symcr::kNoType)
      return symcr::kNoType;
    store(Index, std::move(Model), C);
    return Index;
  }
  if (Name == "optional") {
    Model.Kind = symcr::Kind::Optional;
    Model.Ops = OpsKind::Optional;
    std::uint32_t Index = Reserve();
    Model.Element = Element(Arg(0), ".value");
    if (Model.Element == symcr::kNoType)
      return symcr::kNoType;
    store(Index, std::move(Model), C);
    return Index;
  }
  if (Name == "variant") {
    Model.Kind = symcr::Kind::Variant;
    Model.Ops = OpsKind::Variant;
    std::uint32_t Index = Reserve();
    unsigned Alternative = 0;
    for (const TemplateArgument &A :
         Spec->getTemplateArgs()[0].pack_elements()) {
      std::string Suffix = "<" + std::to_string(Alternative++) + ">";
      std::uint32_t T = Element(A.getAsType(), Suffix.c_str());
      if (T == symcr::kNoType)
        return symcr::kNoType;
      Model.Alternatives.push_back(T);
    }
    store(Index, std::move(Model), C);
    return Index;
  }
  if (Name == "unique_ptr" || Name == "shared_ptr") {
    QualType Pointee = Arg(0);
    if (Pointee->isArrayType())
      return fail(C, "'" + Model.Name + "'",
                  "smart pointers to arrays are not supported");
    if (Name == "unique_ptr") {
      const auto *Deleter = Arg(1)->getAsCXXRecordDecl();
      if (!Deleter || Deleter->getName() != "default_delete")
        return fail(C, "'" + Model.Name + "'",
                    "a custom deleter cannot be recreated");
    }
    if (!checkPointee(Pointee, C,
                      Name == "unique_ptr" ? "unique_ptr" : "shared_ptr"))
      return symcr::kNoType;
    Model.Kind =
        Name == "unique_ptr" ? symcr::Kind::UniquePtr : symcr::Kind::SharedPtr;
    Model.Ops = Name == "unique_ptr" ? OpsKind::UniquePtr : OpsKind::SharedPtr;
    std::uint32_t Index = Reserve();
    Model.Element = walk(Pointee, intoPointee(C, Model.Name));
    if (Model.Element == symcr::kNoType)
      return symcr::kNoType;
    store(Index, std::move(Model), C);
    return Index;
  }
  if (Name == "pair" || Name == "tuple" || Name == "monostate") {
    Model.Kind = symcr::Kind::Struct;
    std::uint32_t Index = Reserve();
    const auto *CRD = cast<CXXRecordDecl>(RD);
    if (Name == "pair") {
      const ASTRecordLayout &Layout = Context.getASTRecordLayout(RD);
      for (const FieldDecl *F : RD->fields()) {
        FieldModel Field;
        Field.Name = F->getName().str();
        Field.Offset = Layout.getFieldOffset(F->getFieldIndex()) / 8;
        Field.Type = Element(F->getType(), ("." + Field.Name).c_str());
        if (Field.Type == symcr::kNoType)
          return symcr::kNoType;
        Model.Fields.push_back(Field);
      }
    } else if (Name == "tuple") {
      unsigned I = 0;
      for (const TemplateArgument &A :
           Spec->getTemplateArgs()[0].pack_elements()) {
        FieldModel Field;
        Field.Name = std::to_string(I);
        if (!findTupleElement(Context, CRD, I, 0, Field.Offset))
          return fail(C, "'" + Model.Name + "'",
                      "this standard library's std::tuple layout is not known "
                      "to symcr-gen");
        Field.Type = Element(A.getAsType(), ("." + Field.Name).c_str());
        if (Field.Type == symcr::kNoType)
          return symcr::kNoType;
        Model.Fields.push_back(Field);
        ++I;
      }
    }
    store(Index, std::move(Model), C);
    return Index;
  }
Unsupported:
  return fail(C, "'" + Model.Name + "'",
              "this standard library type is not supported (its members are "
              "implementation details)");
}

bool TypeWalker::fillFields(const RecordDecl *RD, TypeModel &Model,
                            const WalkContext &C) {
  const ASTRecordLayout &Layout = Context.getASTRecordLayout(RD);
  const auto *CRD = dyn_cast<CXXRecordDecl>(RD);
  std::vector<std::string> Keys = recordKeys(RD);
  std::string OwnerName = Keys.empty() ? Model.Name : Keys.front();
  bool Ok = true;
  auto Lookup = [&](const auto &Map, const std::string &Field) {
    for (const std::string &K : Keys) {
      auto It = Map.find(std::make_pair(K, Field));
      if (It != Map.end())
        return It;
    }
    return Map.end();
  };
  if (CRD) {
    for (const CXXBaseSpecifier &Base : CRD->bases()) {
      const CXXRecordDecl *BaseRD = Base.getType()->getAsCXXRecordDecl();
      if (!BaseRD)
        continue;
      WalkContext B = C;
      B.Where = locationOf(Context, Base.getBeginLoc());
      std::string Why;
      if (isSkippedType(BaseRD, Why)) {
        Model.Skipped.push_back("base " + BaseRD->getNameAsString() + ": " +
                                Why);
        continue;
      }
      if (BaseRD->isEmpty() && !BaseRD->isPolymorphic())
        continue; // an empty base holds no state
      FieldModel Field;
      Field.Type = walk(Base.getType(), B);
      if (Field.Type == symcr::kNoType) {
        Ok = false;
        continue;
      }
      Field.Name = Program.Types[Field.Type].Name;
      Field.Flags = symcr::kFieldBase;
      Field.Offset = Layout.getBaseClassOffset(BaseRD).getQuantity();
      Model.Fields.push_back(Field);
    }
  }
  bool StandardLayout = !CRD || CRD->isStandardLayout();
  for (const FieldDecl *FD : RD->fields()) {
    if (FD->isUnnamedBitfield())
      continue;
    unsigned FieldIndex = FD->getFieldIndex();
    std::string Name = FD->getName().str();
    bool Anonymous = FD->isAnonymousStructOrUnion() || Name.empty();
    if (Anonymous) {
      const RecordDecl *Inner = FD->getType()->getAsRecordDecl();
      Name = std::string("(anonymous ") +
             (Inner && Inner->isUnion() ? "union" : "struct") + " at field " +
             std::to_string(FieldIndex) + ")";
    }
    WalkContext F = C;
    // "sim->lock", not "sim->.lock"
    F.Path = C.Path + (llvm::StringRef(C.Path).endswith("->") ? "" : ".") + Name;
    F.Enclosing = C.SkipHint.empty()
                      ? MemberRef()
                      : MemberRef{C.Path, C.SkipHint, Model.Name, C.Where};
    F.Where = locationOf(Context, FD->getLocation());
    F.SkipHint = OwnerName + "::" + Name;
    F.Shallow = false;
    F.AnonymousName.clear();
    std::string Why;
    if (const char *Why = leftToNewBuild(FD->getType())) {
      Model.LeftToNewBuild.push_back({Name, Why});
      Model.Flags |= symcr::kTypeLeavesMembers;
      continue;
    }
    if (hasAnnotation(FD, "skip")) {
      Model.Skipped.push_back(Name + ": SYMCR_SKIP");
      continue;
    }
    if (auto It = Lookup(Select.SkippedFields, Name);
        It != Select.SkippedFields.end()) {
      Model.Skipped.push_back(Name + ": " + It->second);
      continue;
    }
    QualType FieldType = FD->getType();
    QualType Innermost = Context.getBaseElementType(FieldType);
    if (const RecordDecl *FieldRD = Innermost->getAsRecordDecl())
      if (isSkippedType(FieldRD, Why)) {
        Model.Skipped.push_back(
            Name + ": type " + recordName(FieldRD, WalkContext()) + ": " + Why);
        continue;
      }
    if (C.Shallow) {
      bool Included =
          hasAnnotation(FD, "include") ||
          Lookup(Select.IncludedFields, Name) != Select.IncludedFields.end();
      bool Plain = Innermost->isScalarType() && !Innermost->isPointerType() &&
                   !Innermost->isMemberPointerType();
      if (!Included && !Plain) {
        Model.Skipped.push_back(Name +
                                ": not selected for a shallow root "
                                "(SYMCR_INCLUDE or '#pragma symcr include(" +
                                OwnerName + "::" + Name + ")' selects it)");
        continue;
      }
    }
    if (Anonymous) {
      const RecordDecl *Inner = FieldType->getAsRecordDecl();
      if (Inner)
        AnonymousNames[Inner] = Model.Name + "::" + Name;
    } else if (const RecordDecl *Inner = FieldType->getAsRecordDecl()) {
      if (!Inner->getIdentifier() && !Inner->getTypedefNameForAnonDecl())
        AnonymousNames.emplace(
            Inner, Model.Name + "::(anonymous " +
                       (Inner->isUnion() ? "union" : "struct") + " at field " +
                       std::to_string(FieldIndex) + ")");
    }
    FieldModel Field;
    Field.Name = Name;
    Field.Type = walk(FieldType, F);
    if (Field.Type == symcr::kNoType) {
      Ok = false;
      continue;
    }
    std::uint64_t Bits = Layout.getFieldOffset(FieldIndex);
    if (FD->isBitField()) {
      std::uint64_t UnitBytes =
          Context.getTypeSizeInChars(FieldType).getQuantity();
      Field.BitWidth = FD->getBitWidthValue(Context);
      if (Field.BitWidth == 0)
        continue;
      std::uint64_t UnitBits = UnitBytes * 8;
      Field.Offset = (Bits / UnitBits) * UnitBytes;
      Field.BitOffset = static_cast<unsigned>(Bits - Field.Offset * 8);
      if (Field.BitOffset + Field.BitWidth > UnitBits) {
        Sink->error(F.Where, "bit-field '" + F.Path +
                                 "' straddles its storage unit "
                                 "(packed layout); not supported");
        Ok = false;
        continue;
      }
    } else {
      Field.Offset = Bits / 8;
      bool Public = FD->getAccess() == AS_public || FD->getAccess() == AS_none;
      if (StandardLayout && Public && !Anonymous && !Model.Spelling.empty())
        Field.OffsetCheckMember = Name;
    }
    Field.RenamedFrom = renamedFromAnnotations(FD);
    if (auto It = Lookup(Select.FieldRenames, Name);
        It != Select.FieldRenames.end())
      Field.RenamedFrom.insert(Field.RenamedFrom.end(), It->second.begin(),
                               It->second.end());
    for (const std::string &A : symcrAnnotations(FD)) {
      llvm::StringRef Range(A);
      if (!Range.consume_front("range:"))
        continue;
      auto Bounds = Range.split(':');
      char *End1 = nullptr, *End2 = nullptr;
      std::string Lo = Bounds.first.str(), Hi = Bounds.second.str();
      Field.RangeMin = std::strtod(Lo.c_str(), &End1);
      Field.RangeMax = std::strtod(Hi.c_str(), &End2);
      if (Lo.empty() || Hi.empty() || *End1 || *End2 ||
          Field.RangeMin > Field.RangeMax) {
        Sink->error(F.Where,
                    "SYMCR_RANGE needs two numeric bounds lo <= hi, got '" +
                        Range.str() + "'");
        Ok = false;
      }
      Field.Flags |= symcr::kFieldHasRange;
    }
    if (auto It = Lookup(Select.FieldRanges, Name);
        It != Select.FieldRanges.end()) {
      if ((Field.Flags & symcr::kFieldHasRange) &&
          (Field.RangeMin != It->second.first ||
           Field.RangeMax != It->second.second)) {
        Sink->error(F.Where, "member '" + F.Path +
                                 "' has SYMCR_RANGE and a different "
                                 "range directive");
        Ok = false;
      }
      Field.RangeMin = It->second.first;
      Field.RangeMax = It->second.second;
      Field.Flags |= symcr::kFieldHasRange;
    }
    Model.Fields.push_back(Field);
  }
  return Ok;
}

std::uint32_t TypeWalker::record(QualType Type, const RecordDecl *Decl,
                                 const WalkContext &C) {
  const RecordDecl *RD = completeDefinition(Decl, Decl->getLocation());
  if (!RD)
    return fail(C, "incomplete type '" + Type.getAsString(*Policy) + "'",
                "its layout is unknown here");
  if (RD->isInvalidDecl() || RD->isDependentType())
    return fail(C, "'" + Type.getAsString(*Policy) + "'",
                "the type is invalid or dependent");
  llvm::StringRef StdName;
  if (isStdTemplate(RD, StdName))
    return stdRecord(Type, RD, StdName, C);
  const auto *CRD = dyn_cast<CXXRecordDecl>(RD);
  if (CRD && CRD->isLambda())
    return fail(C, "a lambda", "closures hold code");
  if (CRD && CRD->getNumVBases() > 0)
    return fail(C, "class '" + CRD->getNameAsString() + "' with virtual bases",
                "virtual base offsets are only known at run time");
  std::string PlainName = NameIndex::qualifiedName(RD);
  if (llvm::StringRef(PlainName).startswith("pthread_") ||
      llvm::StringRef(PlainName).startswith("__pthread") ||
      PlainName == "_IO_FILE")
    return fail(C, "'" + PlainName + "'",
                "threads, locks and files are process state");

  TypeModel Model;
  Model.Name = canonicalName(Type, C);
  Model.Spelling = spelling(Type);
  Model.Accessible = accessible(Type);
  Model.Size = Context.getTypeSizeInChars(Type).getQuantity();
  Model.Align = Context.getTypeAlignInChars(Type).getQuantity();
  Model.RenamedFrom = renamedFromAnnotations(RD);
  for (const std::string &K : recordKeys(RD)) {
    auto It = Select.TypeRenames.find(K);
    if (It != Select.TypeRenames.end())
      Model.RenamedFrom.insert(Model.RenamedFrom.end(), It->second.begin(),
                               It->second.end());
  }
  qualifyLike(Model.Name, Model.RenamedFrom);
  if (RD->isUnion()) {
    Model.Kind = symcr::Kind::Union;
    if (CRD && !CRD->isTriviallyCopyable())
      return fail(
          C, "union '" + Model.Name + "' with non-trivial members",
          "a union is restored as raw bytes, which only works for trivially "
          "copyable members");
    // Raw bytes must not carry addresses of the old process.
    std::vector<QualType> Pending{Type};
    while (!Pending.empty()) {
      QualType T = Context.getBaseElementType(Pending.back());
      Pending.pop_back();
      if (T->isPointerType() || T->isMemberPointerType() ||
          T->isReferenceType())
        return fail(C, "union '" + Model.Name + "' containing a pointer",
                    "its raw bytes would hold addresses of the old process");
      if (const RecordDecl *Inner = T->getAsRecordDecl())
        if (const RecordDecl *Def = Inner->getDefinition())
          for (const FieldDecl *F : Def->fields())
            Pending.push_back(F->getType());
    }
    bool Fresh;
    std::uint32_t Index = reserve(Model.Name, Model.Name, Fresh);
    store(Index, std::move(Model), C);
    return Index;
  }
  Model.Kind = symcr::Kind::Struct;
  if (CRD && CRD->isPolymorphic() && !CRD->hasAttr<FinalAttr>())
    Model.Flags |= symcr::kTypePolymorphic;
  std::string Key = Model.Name;
  if (C.Shallow) {
    Model.Flags |= symcr::kTypeShallow;
    Key += " (shallow)";
  }
  bool Fresh;
  std::uint32_t Index = reserve(Key, Model.Name, Fresh);
  Walked[{Type.getTypePtr(), C.Shallow}] = Index;
  if (!fillFields(RD, Model, C))
    return symcr::kNoType;
  if (CRD && !Model.Spelling.empty() &&
      Select.Validated.count(
          Type.getCanonicalType().getUnqualifiedType().getTypePtr())) {
    Model.HasValidate = true;
    // Restore checks a staged copy, created with the lifecycle unless the
    // type is plain bytes.
    if (CRD->hasDefaultConstructor())
      Model.NeedsLifecycle = true;
  }
  if (CRD && !Model.Spelling.empty() &&
      Select.Migrated.count(
          Type.getCanonicalType().getUnqualifiedType().getTypePtr())) {
    Model.HasMigrate = true;
    Model.Flags |= symcr::kTypeMigrated;
  }
  store(Index, std::move(Model), C);
  return Index;
}

} // namespace

//===----------------------------------------------------------------------===//
// SchemaBuilder
//===----------------------------------------------------------------------===//

SchemaBuilder::SchemaBuilder(ProgramModel &Program, Diagnostics &Diags,
                             std::vector<Directive> SidecarDirectives)
    : Program(Program), Diags(Diags), Sidecar(std::move(SidecarDirectives)) {
  for (const Directive &D : Sidecar)
    SidecarMatched.emplace_back(D.Arguments.size(), false);
}

SchemaBuilder::~SchemaBuilder() = default;

namespace {

/// Resolves "Type" to record keys and checks that it names a record, typedef
/// or class template of the TU.
bool resolveTypeName(
    const NameIndex &Index, const std::string &Text,
    std::vector<std::string> &Keys, std::vector<const RecordDecl *> *Records,
    const std::function<std::string(const RecordDecl *)> &CanonicalName) {
  bool Found = false;
  if (auto It = Index.Records.find(Text); It != Index.Records.end()) {
    Keys.push_back(Text);
    if (Records)
      Records->insert(Records->end(), It->second.begin(), It->second.end());
    Found = true;
  }
  if (auto It = Index.Templates.find(Text); It != Index.Templates.end()) {
    Keys.push_back(Text);
    if (Records)
      for (const ClassTemplateDecl *TD : It->second) {
        if (const CXXRecordDecl *Pattern = TD->getTemplatedDecl())
          Records->push_back(Pattern);
      }
    Found = true;
  }
  // "AP_Param<int8>" (canonical) or "AP_Param<signed char>" (as spelt in C++):
  // exactly that specialisation.
  if (std::size_t Angle = Text.find('<'); Angle != std::string::npos) {
    auto Compact = [](std::string Name) {
      Name.erase(std::remove(Name.begin(), Name.end(), ' '), Name.end());
      return Name;
    };
    auto Template = Index.Templates.find(Text.substr(0, Angle));
    if (Template != Index.Templates.end())
      for (ClassTemplateDecl *TD : Template->second)
        for (const ClassTemplateSpecializationDecl *Spec :
             TD->specializations()) {
          if (!Spec->getDefinition())
            continue;
          std::string Canonical = CanonicalName(Spec);
          std::string Spelt = Compact(
              QualType(Spec->getTypeForDecl(), 0)
                  .getAsString(Spec->getASTContext().getPrintingPolicy()));
          if (Compact(Canonical) == Text || Spelt == Text) {
            Keys.push_back(Canonical);
            if (Records)
              Records->push_back(Spec);
            Found = true;
          }
        }
  }
  if (auto It = Index.Typedefs.find(Text); It != Index.Typedefs.end()) {
    for (const TypedefNameDecl *TD : It->second) {
      QualType T = TD->getUnderlyingType().getCanonicalType();
      if (const RecordDecl *RD = T->getAsRecordDecl()) {
        // A typedef of a specialization keys by the specialization's
        // canonical name ("AP_Param<int8>"), not by every specialization.
        if (isa<ClassTemplateSpecializationDecl>(RD))
          Keys.push_back(CanonicalName(RD));
        else
          Keys.push_back(NameIndex::qualifiedName(RD));
        if (Records)
          Records->push_back(RD);
        Found = true;
      }
    }
  }
  std::sort(Keys.begin(), Keys.end());
  Keys.erase(std::unique(Keys.begin(), Keys.end()), Keys.end());
  return Found;
}

/// The class a hook's first parameter names, spelt as in its wanted signature.
std::string hookClassName(ASTContext &Context, QualType Param) {
  PrintingPolicy Policy = Context.getPrintingPolicy();
  Policy.SuppressTagKeyword = true;
  return Param.getNonReferenceType().getUnqualifiedType().getAsString(Policy);
}

/// A hook is called unqualified from namespace symcr_gen: it must be declared
/// in its class's innermost enclosing namespace (a hidden friend counts), where
/// argument-dependent lookup finds it, or globally, where ordinary lookup does.
bool hookIsFoundByLookup(const FunctionDecl *FD, const RecordDecl *RD) {
  const DeclContext *Home = FD->getDeclContext()->getRedeclContext();
  const DeclContext *Enclosing =
      RD->getEnclosingNamespaceContext()->getRedeclContext();
  return Home->isTranslationUnit() || Home->Equals(Enclosing);
}

/// The class type a hook is for, as the key of the hooked-type sets.
const Type *hookedType(QualType Param) {
  return Param.getNonReferenceType()
      .getUnqualifiedType()
      .getCanonicalType()
      .getTypePtr();
}

/// A user hook found by its function name (symcr_validate, symcr_migrate).
struct HookForm {
  const char *Noun; ///< "validation hook", for diagnostics
  /// Which declarations of the name are meant as the hook (by parameter
  /// count); the others are ignored.
  bool (*IsCandidate)(const FunctionDecl *FD);
  /// The exact signature, given the first parameter (canonical).
  bool (*HasSignature)(const FunctionDecl *FD, QualType Param);
  /// The wanted declaration for the class spelt `Class`.
  std::string (*Wanted)(const std::string &Class);
};

/// Finds the hooks of `Form` among `Candidates`: non-template, non-member
/// functions whose first parameter names a class T, declared where
/// hookIsFoundByLookup. A candidate of the wrong signature or place is an
/// error rather than a silently unused hook.
void findHooks(ASTContext &Context,
               const std::vector<FunctionDecl *> &Candidates,
               const HookForm &Form, std::set<const Type *> &Hooked,
               Diagnostics &Diags) {
  for (const FunctionDecl *FD : Candidates) {
    if (FD->getTemplatedKind() != FunctionDecl::TK_NonTemplate ||
        FD->isDependentContext() || isa<CXXMethodDecl>(FD) ||
        !Form.IsCandidate(FD))
      continue;
    QualType Param = FD->getParamDecl(0)->getType().getCanonicalType();
    const RecordDecl *RD = Param.getNonReferenceType()->getAsRecordDecl();
    if (!RD)
      continue;
    Location Where = locationOf(Context, FD->getLocation());
    std::string Wanted = "'" + Form.Wanted(hookClassName(Context, Param)) + "'";
    if (!Form.HasSignature(FD, Param)) {
      Diags.error(Where, std::string("a ") + Form.Noun + " must be declared " +
                             Wanted);
      continue;
    }
    if (!hookIsFoundByLookup(FD, RD)) {
      Diags.error(Where, std::string(Form.Noun) + " " + Wanted +
                             " must be declared in the namespace of its "
                             "class (or as its friend, or globally), where "
                             "argument-dependent lookup finds it");
      continue;
    }
    Hooked.insert(hookedType(Param));
  }
}

/// `bool symcr_validate(const T&)`.
const HookForm ValidationHook = {
    "validation hook",
    [](const FunctionDecl *FD) { return FD->getNumParams() == 1; },
    [](const FunctionDecl *FD, QualType Param) {
      return Param->isLValueReferenceType() &&
             Param.getNonReferenceType().isConstQualified() &&
             !Param.getNonReferenceType().isVolatileQualified() &&
             FD->getReturnType().getCanonicalType()->isBooleanType();
    },
    [](const std::string &Class) {
      return "bool symcr_validate(const " + Class + "&)";
    }};

/// `void symcr_migrate(T&, const symcr::OldValues&)`.
const HookForm MigrationHook = {
    "migration hook",
    [](const FunctionDecl *FD) { return FD->getNumParams() != 0; },
    [](const FunctionDecl *FD, QualType Param) {
      if (FD->getNumParams() != 2 || !Param->isLValueReferenceType() ||
          Param.getNonReferenceType().isConstQualified() ||
          Param.getNonReferenceType().isVolatileQualified() ||
          !FD->getReturnType().getCanonicalType()->isVoidType())
        return false;
      QualType Old = FD->getParamDecl(1)->getType().getCanonicalType();
      if (!Old->isLValueReferenceType())
        return false;
      QualType Pointee = Old.getNonReferenceType();
      const RecordDecl *OldRecord = Pointee->getAsRecordDecl();
      return Pointee.isConstQualified() && !Pointee.isVolatileQualified() &&
             OldRecord &&
             OldRecord->getQualifiedNameAsString() == "symcr::OldValues";
    },
    [](const std::string &Class) {
      return "void symcr_migrate(" + Class + "&, const symcr::OldValues&)";
    }};

/// The base class of \p RD (at any depth) that declares \p Member, or null.
const CXXRecordDecl *baseDeclaring(const RecordDecl *RD,
                                   const std::string &Member) {
  const auto *CRD = dyn_cast_or_null<CXXRecordDecl>(RD->getDefinition());
  if (!CRD)
    return nullptr;
  for (const CXXBaseSpecifier &B : CRD->bases()) {
    const CXXRecordDecl *Base = B.getType()->getAsCXXRecordDecl();
    if (!Base || !Base->getDefinition())
      continue;
    for (const FieldDecl *F : Base->getDefinition()->fields())
      if (F->getName() == Member)
        return Base;
    if (const CXXRecordDecl *Deeper = baseDeclaring(Base, Member))
      return Deeper;
  }
  return nullptr;
}

bool recordHasMember(const RecordDecl *RD, const std::string &Member) {
  const RecordDecl *Def = RD->getDefinition();
  if (!Def)
    return false;
  for (const FieldDecl *F : Def->fields())
    if (F->getName() == Member)
      return true;
  if (const auto *CRD = dyn_cast<CXXRecordDecl>(Def)) {
    for (const CXXBaseSpecifier &B : CRD->bases())
      if (const CXXRecordDecl *Base = B.getType()->getAsCXXRecordDecl())
        if (Base->getNameAsString() == Member)
          return true;
  }
  // "(anonymous union at field N)" names an unnamed member.
  return llvm::StringRef(Member).startswith("(anonymous");
}

} // namespace

void SchemaBuilder::addTranslationUnit(
    ASTContext &Context, Sema *S, unsigned TUIndex,
    const std::vector<Directive> &PragmaDirectives) {
  NameIndex Index(Context);
  Index.TraverseDecl(Context.getTranslationUnitDecl());
  Selections Select;
  Program.TranslationUnits[TUIndex].DeducesReturnTypes =
      Context.getLangOpts().CPlusPlus14;

  if (Context.getLangOpts().CPlusPlus) {
    findHooks(Context, Index.Validators, ValidationHook, Select.Validated,
              Diags);
    findHooks(Context, Index.Migrators, MigrationHook, Select.Migrated, Diags);
  }

  TypeWalker Namer(Context, S, TUIndex, Program, Diags, Select);
  auto CanonicalName = [&](const RecordDecl *RD) {
    return Namer.canonicalRecordName(RD);
  };

  auto Apply = [&](const Directive &D, bool IsSidecar,
                   std::vector<bool> *Matched) {
    for (std::size_t I = 0; I < D.Arguments.size(); ++I) {
      const DirectiveArgument &A = D.Arguments[I];
      bool Found = false;
      auto Report = [&](const std::string &Message) {
        if (!IsSidecar)
          Diags.error(A.Where, Message);
      };
      switch (D.Kind) {
      case DirectiveKind::Checkpoint: {
        auto It = Index.Variables.find(A.Text);
        if (It == Index.Variables.end()) {
          Report("unknown variable '" + A.Text +
                 "' in symcr checkpoint directive");
          break;
        }
        Found = true;
        bool Usable = false;
        for (const VarDecl *VD : It->second) {
          if (!VD->hasGlobalStorage()) {
            Diags.error(A.Where,
                        "'" + A.Text +
                            "' is a local variable with automatic "
                            "storage; a root must be a namespace-scope, "
                            "static member or function-local static "
                            "variable");
            continue;
          }
          Usable = true;
        }
        if (Usable) {
          auto &Request = Select.Roots[A.Text];
          Request.Shallow |= D.Shallow;
          if (!Request.Where.valid())
            Request.Where = A.Where;
          if (!IsSidecar)
            PendingDeclaredRoots.emplace(A.Text, A.Where);
        }
        break;
      }
      case DirectiveKind::Skip:
      case DirectiveKind::Include:
      case DirectiveKind::Range:
      case DirectiveKind::Renamed: {
        if (D.Kind == DirectiveKind::Renamed && I == 1)
          continue; // the old name
        if (D.Kind == DirectiveKind::Range && I >= 1)
          continue; // the bounds
        const std::string &Text = A.Text;
        std::vector<std::string> Keys;
        std::vector<const RecordDecl *> Records;
        std::string Reason = IsSidecar ? "skipped by the annotation file"
                                       : "skipped by '#pragma symcr skip'";
        if (D.Kind != DirectiveKind::Include &&
            D.Kind != DirectiveKind::Range &&
            resolveTypeName(Index, Text, Keys, &Records, CanonicalName)) {
          Found = true;
          for (const std::string &K : Keys) {
            if (D.Kind == DirectiveKind::Skip)
              Select.SkippedTypes[K] = Reason;
            else
              Select.TypeRenames[K].push_back(D.Arguments[1].Text);
          }
          break;
        }
        if (D.Kind == DirectiveKind::Renamed && Index.Variables.count(Text)) {
          Found = true;
          Select.RootRenames[Text].push_back(D.Arguments[1].Text);
          break;
        }
        std::size_t Split = Text.rfind("::");
        if (Split == std::string::npos) {
          Report(
              "unknown " +
              std::string(D.Kind == DirectiveKind::Skip ? "type" : "member") +
              " '" + Text + "' in symcr " +
              (D.Kind == DirectiveKind::Skip      ? "skip"
               : D.Kind == DirectiveKind::Include ? "include"
               : D.Kind == DirectiveKind::Range   ? "range"
                                                  : "renamed") +
              " directive");
          break;
        }
        std::string Owner = Text.substr(0, Split),
                    Member = Text.substr(Split + 2);
        if (!resolveTypeName(Index, Owner, Keys, &Records, CanonicalName)) {
          Report("unknown type '" + Owner + "' in symcr directive");
          break;
        }
        bool HasMember = false;
        for (const RecordDecl *RD : Records)
          HasMember |= recordHasMember(RD, Member);
        if (!HasMember) {
          // C++ qualified-name lookup: `Copter::ahrs` names a member Copter
          // inherits, declared in a base; the directive is the base's.
          const CXXRecordDecl *Declaring = nullptr;
          for (const RecordDecl *RD : Records)
            if (!Declaring)
              Declaring = baseDeclaring(RD, Member);
          if (Declaring) {
            Keys.clear();
            Records.clear();
            HasMember = resolveTypeName(Index, CanonicalName(Declaring), Keys,
                                        &Records, CanonicalName);
          }
        }
        if (!HasMember) {
          Report("type '" + Owner + "' has no member '" + Member + "'");
          break;
        }
        Found = true;
        for (const std::string &K : Keys) {
          if (D.Kind == DirectiveKind::Skip)
            Select.SkippedFields[{K, Member}] = Reason;
          else if (D.Kind == DirectiveKind::Include)
            Select.IncludedFields.insert({K, Member});
          else if (D.Kind == DirectiveKind::Range)
            Select.FieldRanges[{K, Member}] = {
                std::strtod(D.Arguments[1].Text.c_str(), nullptr),
                std::strtod(D.Arguments[2].Text.c_str(), nullptr)};
          else
            Select.FieldRenames[{K, Member}].push_back(D.Arguments[1].Text);
        }
        break;
      }
      case DirectiveKind::CheckpointAt:
      case DirectiveKind::RestoreAt:
      case DirectiveKind::Store:
        return; // program points: ProgramPoints
      }
      if (Found && Matched)
        (*Matched)[I] = true;
    }
  };
  for (std::size_t I = 0; I < Sidecar.size(); ++I)
    Apply(Sidecar[I], /*IsSidecar=*/true, &SidecarMatched[I]);
  for (const Directive &D : PragmaDirectives)
    Apply(D, /*IsSidecar=*/false, nullptr);

  // Roots defined in this TU.
  TypeWalker Walker(Context, S, TUIndex, Program, Diags, Select);
  Walker.PolymorphicClasses = &Index.PolymorphicClasses;
  const SourceManager &SM = Context.getSourceManager();
  for (auto &Entry : Index.Variables) {
    for (VarDecl *VD : Entry.second) {
      bool Annotated = hasAnnotation(VD, "checkpoint") ||
                       hasAnnotation(VD, "checkpoint_shallow");
      auto Request = Select.Roots.find(Entry.first);
      if (!Annotated && Request == Select.Roots.end())
        continue;
      Location Where = locationOf(Context, VD->getLocation());
      if (!VD->hasGlobalStorage()) {
        if (Annotated)
          Diags.error(Where, "'" + Entry.first +
                                 "' is a local variable with automatic "
                                 "storage; a root must be a namespace-scope, "
                                 "static member or function-local static "
                                 "variable");
        continue;
      }
      if (VD->isThisDeclarationADefinition() == VarDecl::DeclarationOnly)
        continue;
      if (Program.TranslationUnits[TUIndex].LibraryOnly) {
        // The program links this source's object from a library: the code that
        // exports the root's address cannot be compiled into it from here.
        DefinedRootNames.insert(Entry.first);
        Diags.error(Where,
                    "root '" + Entry.first + "' is defined in '" +
                        Program.TranslationUnits[TUIndex].Source +
                        "', a source of a static library the program links, "
                        "so it would not be checkpointed: define it in one of "
                        "the program's own sources, or compile this source as "
                        "part of the program");
        continue;
      }
      bool Shallow = hasAnnotation(VD, "checkpoint_shallow") ||
                     (Request != Select.Roots.end() && Request->second.Shallow);
      const std::string &Name = Entry.first;
      bool InMainFile = SM.isInMainFile(SM.getExpansionLoc(VD->getLocation()));
      if (DefinedRootNames.count(Name)) {
        if (!VD->isExternallyVisible() || VD->isStaticLocal()) {
          if (InMainFile)
            Diags.error(
                Where,
                "two roots are named '" + Name +
                    "' (one per translation unit with internal linkage); "
                    "rename one of them");
          else
            Diags.error(Where,
                        "root '" + Name +
                            "' has internal linkage and is defined "
                            "in a header: every translation unit has "
                            "its own copy; make it 'extern' or 'inline'");
        }
        continue;
      }
      if (!Context.getLangOpts().CPlusPlus && VD->isStaticLocal()) {
        Diags.error(Where,
                    "function-local static '" + Name +
                        "' in C cannot be a root (C compilers give it an "
                        "unpredictable symbol name); move it to file scope");
        continue;
      }
      DefinedRootNames.insert(Name);
      PendingDeclaredRoots.erase(Name);
      WalkContext C;
      C.Path = Name;
      C.Where = Where;
      C.Shallow = Shallow;
      QualType Type = VD->getType();
      if (Type.isConstQualified() || VD->isConstexpr()) {
        Diags.error(Where,
                    "root '" + Name +
                        "' is const: restoring would write into read-only "
                        "memory; remove the annotation or the const");
        continue;
      }
      if (VD->getTLSKind() != VarDecl::TLS_None) {
        Diags.error(Where,
                    "root '" + Name +
                        "' is thread_local: each thread has its own copy, "
                        "which a process-wide root cannot name");
        continue;
      }
      if (Shallow && !Type->getAsRecordDecl()) {
        Diags.error(Where,
                    "shallow root '" + Name + "' must be a struct or class");
        continue;
      }
      if (const RecordDecl *RD = Type->getAsRecordDecl()) {
        if (!RD->getIdentifier() && !RD->getTypedefNameForAnonDecl())
          C.AnonymousName = "(anonymous struct of " + Name + ")";
        if (hasAnnotation(RD, "skip")) {
          Diags.error(Where,
                      "root '" + Name + "' has a type marked SYMCR_SKIP");
          continue;
        }
      }
      std::uint32_t TypeIndex = Walker.walk(Type, C);
      if (TypeIndex == symcr::kNoType)
        continue;
      RootModel Root;
      Root.Name = Name;
      Root.Type = TypeIndex;
      Root.Flags =
          Shallow ? static_cast<std::uint32_t>(symcr::kRootShallow) : 0u;
      Root.RenamedFrom = renamedFromAnnotations(VD);
      if (auto It = Select.RootRenames.find(Name);
          It != Select.RootRenames.end())
        Root.RenamedFrom.insert(Root.RenamedFrom.end(), It->second.begin(),
                                It->second.end());
      qualifyLike(Root.Name, Root.RenamedFrom);
      Root.HomeTU = TUIndex;
      Root.Where = Where;
      std::uint32_t RootNumber =
          static_cast<std::uint32_t>(Program.Roots.size());
      std::string Helper = "symcr_gen_local_" + std::to_string(RootNumber);
      if (!Context.getLangOpts().CPlusPlus) {
        Root.AddressExpression = "(void*)&" + VD->getName().str();
      } else if (VD->isStaticLocal()) {
        // A function-local static is unnamed outside its function: alias its
        // symbol (same TU, since the wrapper includes the source).
        std::unique_ptr<MangleContext> Mangler(Context.createMangleContext());
        std::string Mangled;
        llvm::raw_string_ostream OS(Mangled);
        Mangler->mangleName(GlobalDecl(VD), OS);
        OS.flush();
        Root.AddressPrelude =
            "extern char " + Helper + " __asm__(\"" + Mangled + "\");\n";
        Root.AddressExpression = "static_cast<void*>(&" + Helper + ")";
      } else {
        bool Accessible = true;
        for (const Decl *D = VD; D; D = dyn_cast<Decl>(D->getDeclContext())) {
          if (D->getAccess() == AS_private || D->getAccess() == AS_protected)
            Accessible = false;
          if (isa<TranslationUnitDecl>(D) || isa<NamespaceDecl>(D))
            break;
        }
        PrintingPolicy Policy = Context.getPrintingPolicy();
        Policy.SuppressUnwrittenScope = true;
        std::string Qualified;
        llvm::raw_string_ostream OS(Qualified);
        VD->printQualifiedName(OS, Policy);
        OS.flush();
        std::string Target = "&::" + Qualified;
        if (Accessible) {
          Root.AddressExpression =
              "const_cast<void*>(static_cast<const volatile void*>(" + Target +
              "))";
        } else {
          // Explicit instantiations may name private members (the usual
          // access-check exemption); a friend function exports the address.
          std::string Tag = "symcr_gen_root_tag_" + std::to_string(RootNumber);
          Root.AddressPrelude = "namespace symcr_gen_access {\nstruct " + Tag +
                                " { friend void* address(" + Tag +
                                "); };\ntemplate struct export_address<" + Tag +
                                ", decltype(" + Target + "), " + Target +
                                ">;\n}\n";
          Root.AddressExpression =
              "address(symcr_gen_access::" + Tag + "{})"; // by ADL
        }
      }
      Program.Roots.push_back(std::move(Root));
    }
  }
}

void SchemaBuilder::finish(bool CheckUnmatched) {
  Diags.flushUnrestorable();
  // A C++11 wrapper can only name accessible types; one that needs code (ops,
  // a Lifecycle, hooks) and is private cannot be served in that dialect.
  for (const TypeModel &Type : Program.Types) {
    const TranslationUnitModel &Home = Program.TranslationUnits[Type.HomeTU];
    if (Home.IsC || Home.DeducesReturnTypes || Type.Accessible ||
        Type.Spelling.empty())
      continue;
    if (Type.Ops != OpsKind::None || Type.hasLifecycle() ||
        Type.hasValidate(Program) || Type.HasMigrate)
      Diags.error(Location(),
                  "type '" + Type.Name + "' is private or protected, and the code "
                  "generated for it must name it, which C++11 cannot do from "
                  "outside its class: compile '" + Home.Source +
                  "' as C++14 or later, or skip the members that reach it");
  }
  // Recorded in the schema (and its file) so that a plan without the program's code knows
  // which heap objects the build can rebuild.
  for (TypeModel &Type : Program.Types) {
    if (Type.hasLifecycle())
      Type.Flags |= symcr::kTypeCreatable;
    if (Type.hasLifecycle() && !Type.VtableSymbol.empty())
      Type.Flags |= symcr::kTypeDynamicType;
    if (Type.hasValidate(Program))
      Type.Flags |= symcr::kTypeValidated;
  }
  for (const TypeModel &Type : Program.Types) {
    if (Type.DynamicTypesReachedBy.empty() || !Type.DynamicTypes.empty())
      continue;
    std::string Reasons;
    for (const std::string &Reason : Type.NotDynamicTypes)
      Reasons += (Reasons.empty() ? " (" : "; ") + Reason;
    Diags.note(Location(),
               "'" + Type.DynamicTypesReachedBy + "' points to polymorphic class '" +
                   Type.Name + "': it is saved as a reference to the member or "
                   "element of the state it points at; no class derived from it "
                   "can be created by restore" + (Reasons.empty() ? "" : Reasons + ")") +
                   ", so saving refuses a heap object it points to");
  }
  for (std::size_t I = 0; I < Sidecar.size() && CheckUnmatched; ++I)
    for (std::size_t A = 0; A < Sidecar[I].Arguments.size(); ++A) {
      if (SidecarMatched[I][A] ||
          (Sidecar[I].Kind == DirectiveKind::Renamed && A == 1) ||
          (Sidecar[I].Kind == DirectiveKind::Range && A >= 1))
        continue;
      Diags.error(Sidecar[I].Arguments[A].Where,
                  "'" + Sidecar[I].Arguments[A].Text +
                      "' in the annotation file matches nothing in any "
                      "translation unit");
    }
  for (const auto &Pending : PendingDeclaredRoots)
    if (CheckUnmatched && !DefinedRootNames.count(Pending.first))
      Diags.error(
          Pending.second,
          "root '" + Pending.first +
              "' is declared here but not defined in any translation unit that "
              "sees this directive; put the pragma next to its definition or "
              "use "
              "the annotation file");
}

} // namespace symcr_gen
