//===- AstQueries.cpp - Small questions about Clang declarations
//------------===//
//
// See AstQueries.h.
//
//===----------------------------------------------------------------------===//
#include "AstQueries.h"

#include "clang/AST/Attr.h"
#include "clang/AST/DeclTemplate.h"
#include "clang/AST/Mangle.h"
#include "clang/AST/VTableBuilder.h"
#include "clang/Basic/SourceManager.h"
#include "llvm/Support/raw_ostream.h"

#include <memory>

using namespace clang;

namespace symcr_gen {
namespace {

const char *const AnnotationPrefix = "symcr::";

} // namespace

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

std::string vtableSymbol(ASTContext &Context, const CXXRecordDecl *Class) {
  auto *VTables = dyn_cast<ItaniumVTableContext>(Context.getVTableContext());
  std::unique_ptr<MangleContext> Mangler(Context.createMangleContext());
  auto *Itanium = dyn_cast<ItaniumMangleContext>(Mangler.get());
  if (!Itanium || !VTables || VTables->isRelativeLayout())
    return "";
  std::string Symbol;
  llvm::raw_string_ostream Out(Symbol);
  Itanium->mangleCXXVTable(Class, Out);
  return Out.str();
}

const CXXMethodDecl *vtableKeyFunction(ASTContext &Context,
                                       const CXXRecordDecl *Class) {
  const CXXMethodDecl *Key = Context.getCurrentKeyFunction(Class);
  // A class template's instantiation has its vtable emitted wherever it is
  // used.
  if (!Key || Key->getTemplateSpecializationKind() == TSK_ImplicitInstantiation)
    return nullptr;
  return Key;
}

} // namespace symcr_gen
