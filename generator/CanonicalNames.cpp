//===- CanonicalNames.cpp - The names of types
//------------------------------===//
//
// See TypeWalker.h.
//
//===----------------------------------------------------------------------===//
#include "TypeWalker.h"
#include "NameIndex.h"

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

using namespace clang;

namespace symcr_gen {

/// Old names of a root or type resolve like its new name: an unqualified old
/// name is in the same scope (`SYMCR_RENAMED_FROM("g_log")` on
/// `robot::g_journal` is `robot::g_log`), as for a field. A leading `::` names
/// the global scope.
void qualifyLike(const std::string &Name, std::vector<std::string> &OldNames) {
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
      return recordName(Parent, C) +
             "::" + (Unnamed.empty() ? Named->getName().str() : Unnamed);
    if (!Unnamed.empty())
      return NameIndex::qualifiedScope(ED) + Unnamed;
    return NameIndex::qualifiedDeclName(Named);
  }
  if (const auto *RT = Type->getAs<RecordType>())
    return recordName(RT->getDecl(), C);
  return Type.getAsString(*Policy);
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
    if (Field.Flags & symcr::kFieldClockTime)
      F += "{time " + Field.Clock + " never " + std::to_string(Field.Never) +
           "}";
  }
  for (const auto &E : Model.Enumerators)
    F += "|" + E.first + "=" + std::to_string(E.second);
  for (const TypeModel::LeftMember &Left : Model.LeftToNewBuild)
    F += "|left " + Left.Name + ": " + Left.Why;
  for (std::uint32_t A : Model.Alternatives)
    F += "|" + NameOf(A);
  return F;
}

} // namespace symcr_gen
