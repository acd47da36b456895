//===- SchemaBuilder.cpp - Roots and reachable types from Clang ASTs ------===//
//
// See SchemaBuilder.h: directives and hooks resolved per TU, roots found, and
// the TypeWalker (TypeWalker.h) run from each root.
//
//===----------------------------------------------------------------------===//
#include "SchemaBuilder.h"

#include "Clocks.h"
#include "NameIndex.h"
#include "TypeWalker.h"

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

#include <algorithm>
#include <cstdlib>
#include <functional>

using namespace clang;

namespace symcr_gen {

//===----------------------------------------------------------------------===//
// SchemaBuilder
//===----------------------------------------------------------------------===//

SchemaBuilder::SchemaBuilder(ProgramModel &Program, Diagnostics &Diags,
                             std::vector<Directive> SidecarDirectives)
    : Program(Program), Diags(Diags), Sidecar(std::move(SidecarDirectives)) {
  for (const Directive &D : Sidecar) {
    SidecarMatched.emplace_back(D.Arguments.size(), false);
    if (D.Kind == DirectiveKind::Clock)
      declareClock(D, Program, Diags);
  }
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
  for (const CXXRecordDecl *Class : Index.PolymorphicClasses)
    if (const CXXMethodDecl *Key = vtableKeyFunction(Context, Class))
      if (Key->isDefined())
        Program.EmittedVtables.insert(vtableSymbol(Context, Class));
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
      case DirectiveKind::NotOwner:
      case DirectiveKind::RestoresAlone:
      case DirectiveKind::Range:
      case DirectiveKind::Time:
      case DirectiveKind::Renamed: {
        if (D.Kind == DirectiveKind::Renamed && I == 1)
          continue; // the old name
        if ((D.Kind == DirectiveKind::Range || D.Kind == DirectiveKind::Time) &&
            I >= 1)
          continue; // the bounds; the clock and never value
        const std::string &Text = A.Text;
        std::vector<std::string> Keys;
        std::vector<const RecordDecl *> Records;
        std::string Reason = IsSidecar ? "skipped by the annotation file"
                                       : "skipped by '#pragma symcr skip'";
        TimeSpec Time;
        if (D.Kind == DirectiveKind::Time) {
          std::vector<std::string> Rest;
          std::string Ignored; // parseDirectiveText checked the arguments
          for (std::size_t R = 1; R < D.Arguments.size(); ++R)
            Rest.push_back(D.Arguments[R].Text);
          parseTimeArguments(Rest, Time, Ignored);
          Time.Where = D.Where;
          // time(ms_t, millis): every member declared with the typedef.
          if (Index.Typedefs.count(Text)) {
            Found = true;
            Select.TypedefTimes[Text] = Time;
            break;
          }
        }
        if (D.Kind != DirectiveKind::Include &&
            D.Kind != DirectiveKind::Range && D.Kind != DirectiveKind::Time &&
            D.Kind != DirectiveKind::NotOwner &&
            D.Kind != DirectiveKind::RestoresAlone &&
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
              (D.Kind == DirectiveKind::Skip            ? "skip"
               : D.Kind == DirectiveKind::Include       ? "include"
               : D.Kind == DirectiveKind::NotOwner      ? "not_owner"
               : D.Kind == DirectiveKind::RestoresAlone ? "restores_alone"
               : D.Kind == DirectiveKind::Range         ? "range"
               : D.Kind == DirectiveKind::Time          ? "time"
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
          else if (D.Kind == DirectiveKind::Time)
            Select.FieldTimes[{K, Member}] = Time;
          else if (D.Kind == DirectiveKind::NotOwner)
            Select.NotOwnerFields.insert({K, Member});
          else if (D.Kind == DirectiveKind::RestoresAlone)
            Select.RestoresAloneFields.insert({K, Member});
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
      case DirectiveKind::Clock:
        return; // program points: ProgramPoints; clocks: declareClock (below)
      }
      if (Found && Matched)
        (*Matched)[I] = true;
    }
  };
  for (const Directive &D : PragmaDirectives)
    if (D.Kind == DirectiveKind::Clock)
      declareClock(D, Program, Diags);
  for (std::size_t I = 0; I < Sidecar.size(); ++I)
    Apply(Sidecar[I], /*IsSidecar=*/true, &SidecarMatched[I]);
  for (const Directive &D : PragmaDirectives)
    Apply(D, /*IsSidecar=*/false, nullptr);
  resolveClocks(Context, TUIndex, Program, Diags);

  // Roots defined in this TU.
  TypeWalker Walker(Context, S, TUIndex, Program, Diags, Select);
  Walker.PolymorphicClasses = &Index.PolymorphicClasses;
  const SourceManager &SM = Context.getSourceManager();
  std::vector<std::tuple<std::string, QualType, std::uint32_t>> ClassRoots;
  std::vector<std::uint32_t> RootTypes;
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
      RootTypes.push_back(TypeIndex);
      // A shallow root's unselected members and a root's skipped ones can still
      // be pointed at.
      ClassRoots.emplace_back(Name, Type, TypeIndex);
    }
  }
  Walker.addReferenceMembers(ClassRoots, RootTypes);
}

void SchemaBuilder::dropClassesWithoutVtable() {
  // Code that creates such a class names its vtable, which the link would not
  // find.
  for (std::uint32_t Index = 0; Index < Program.Types.size(); ++Index) {
    TypeModel &Type = Program.Types[Index];
    if (Type.VtableSymbol.empty() || Type.VtableKeyFunction.empty() ||
        Program.EmittedVtables.count(Type.VtableSymbol))
      continue;
    Type.NeedsLifecycle = false;
    Type.VtableSymbol.clear();
    std::string Why =
        Type.Name + ": its vtable is not in this build (its key function '" +
        Type.VtableKeyFunction +
        "' is defined in no source symcr-gen "
        "parsed: compiled out, or in a library source not given with "
        "--library-source)";
    for (TypeModel &Base : Program.Types) {
      auto It =
          std::find(Base.DynamicTypes.begin(), Base.DynamicTypes.end(), Index);
      if (It == Base.DynamicTypes.end())
        continue;
      Base.DynamicTypes.erase(It);
      Base.NotDynamicTypes.push_back(Why);
    }
  }
}

std::set<std::string> SchemaBuilder::typesInState() const {
  std::set<std::string> Names;
  std::vector<std::uint32_t> Pending;
  for (const RootModel &Root : Program.Roots)
    Pending.push_back(Root.Type);
  while (!Pending.empty()) {
    std::uint32_t Index = Pending.back();
    Pending.pop_back();
    if (Index == symcr::kNoType || Index >= Program.Types.size() ||
        !Names.insert(Program.Types[Index].Name).second)
      continue;
    const TypeModel &Type = Program.Types[Index];
    for (const FieldModel &Field : Type.Fields)
      Pending.push_back(Field.Type);
    Pending.insert(Pending.end(), Type.Alternatives.begin(),
                   Type.Alternatives.end());
    if (Type.Element == symcr::kNoType)
      continue;
    // A polymorphic pointee is in the state only as the heap objects restore
    // creates.
    const TypeModel &Element = Program.Types[Type.Element];
    if (Type.Kind == symcr::Kind::Pointer &&
        (Element.Flags & symcr::kTypePolymorphic))
      Pending.insert(Pending.end(), Element.DynamicTypes.begin(),
                     Element.DynamicTypes.end());
    else
      Pending.push_back(Type.Element);
  }
  return Names;
}

void SchemaBuilder::finish(bool CheckUnmatched) {
  Diags.flushUnrestorable();
  dropClassesWithoutVtable();
  // A C++11 wrapper can only name accessible types; one that needs code (ops,
  // a Lifecycle, hooks) and is private cannot be served in that dialect.
  for (const TypeModel &Type : Program.Types) {
    const TranslationUnitModel &Home = Program.TranslationUnits[Type.HomeTU];
    if (Home.IsC || Home.DeducesReturnTypes || Type.Accessible ||
        Type.Spelling.empty())
      continue;
    if (Type.Ops != OpsKind::None || Type.hasLifecycle() ||
        Type.hasValidate(Program) || Type.HasMigrate)
      Diags.error(
          Location(),
          "type '" + Type.Name +
              "' is private or protected, and the code "
              "generated for it must name it, which C++11 cannot do from "
              "outside its class: compile '" +
              Home.Source +
              "' as C++14 or later, or skip the members that reach it");
  }
  // Recorded in the schema (and its file) so that a plan without the program's
  // code knows which heap objects the build can rebuild.
  for (TypeModel &Type : Program.Types) {
    if (Type.hasLifecycle())
      Type.Flags |= symcr::kTypeCreatable;
    if (Type.hasLifecycle() && !Type.VtableSymbol.empty())
      Type.Flags |= symcr::kTypeDynamicType;
    if (Type.hasValidate(Program))
      Type.Flags |= symcr::kTypeValidated;
  }
  std::set<std::string> InState = typesInState();
  for (const TypeModel &Type : Program.Types) {
    if (Type.DynamicTypesReachedBy.empty() || !Type.DynamicTypes.empty())
      continue;
    std::string Reasons;
    for (const std::string &Reason : Type.NotDynamicTypes)
      Reasons += (Reasons.empty() ? " (" : "; ") + Reason;
    Reasons = Reasons.empty() ? " (every class derived from it is abstract)"
                              : Reasons + ")";
    // A pointer can still refer to an object the state holds; when the state
    // holds none of its class, every save with the pointer set would be
    // refused.
    if (InState.count(Type.Name) || Program.Profile != RuntimeProfile::Host) {
      Diags.note(
          Location(),
          "'" + Type.DynamicTypesReachedBy + "' points to polymorphic class '" +
              Type.Name +
              "': it is saved as a reference to the member or "
              "element of the state it points at; no class derived from it "
              "can be created by restore" +
              Reasons + ", so saving refuses a heap object it points to");
      continue;
    }
    const std::string &Skip = Type.DynamicTypesSkipHint;
    // A root that is such a pointer has no member to skip: it is left out of
    // the checkpoint.
    std::string LeaveOut = Skip.empty() ? "Leave it out of the checkpoint (the "
                                          "new build keeps its own value)"
                                        : "Skip it (the new build keeps its "
                                          "own value): '#pragma symcr skip(" +
                                              Skip + ")' or 'skip(" + Skip +
                                              ")' in the annotation file";
    Diags.error(
        Type.DynamicTypesReachedAt,
        "'" + Type.DynamicTypesReachedBy + "' points to polymorphic class '" +
            Type.Name +
            "', which no object of the state is, and restore "
            "can create no class derived from it" +
            Reasons +
            ": every checkpoint taken while it is set would be refused. " +
            LeaveOut + "; or give '" + Type.Name +
            "' or a class derived from "
            "it a public default constructor, so that restore can create its "
            "heap object");
  }
  for (std::size_t I = 0; I < Sidecar.size() && CheckUnmatched; ++I)
    for (std::size_t A = 0; A < Sidecar[I].Arguments.size(); ++A) {
      if (SidecarMatched[I][A] ||
          (Sidecar[I].Kind == DirectiveKind::Renamed && A == 1) ||
          ((Sidecar[I].Kind == DirectiveKind::Range ||
            Sidecar[I].Kind == DirectiveKind::Time) &&
           A >= 1) ||
          Sidecar[I].Kind == DirectiveKind::Clock) // checkClocks
        continue;
      Diags.error(Sidecar[I].Arguments[A].Where,
                  "'" + Sidecar[I].Arguments[A].Text +
                      "' in the annotation file matches nothing in any "
                      "translation unit");
    }
  if (CheckUnmatched)
    checkClocks(Program, Diags);
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
