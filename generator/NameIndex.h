//===- NameIndex.h - A TU's declarations by source name
//---------------------===//
//
// Internal to the schema builder.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_NAMEINDEX_H
#define SYMCR_GENERATOR_NAMEINDEX_H

#include "AstQueries.h"

#include "clang/AST/DeclCXX.h"
#include "clang/AST/DeclTemplate.h"
#include "clang/AST/RecursiveASTVisitor.h"

#include <map>
#include <string>
#include <vector>

namespace symcr_gen {

/// Indexes a TU's variables, records and typedefs by their qualified source
/// names so that directives can be resolved.
class NameIndex : public clang::RecursiveASTVisitor<NameIndex> {
public:
  explicit NameIndex(clang::ASTContext &Context) : Context(Context) {}

  bool VisitVarDecl(clang::VarDecl *VD) {
    if (clang::isa<clang::ParmVarDecl>(VD) || !VD->getIdentifier())
      return true;
    Variables[rootName(VD)].push_back(VD);
    return true;
  }
  bool VisitRecordDecl(clang::RecordDecl *RD) {
    if (!RD->isThisDeclarationADefinition() ||
        clang::isa<clang::ClassTemplateSpecializationDecl>(RD))
      return true;
    if (const auto *CRD = clang::dyn_cast<clang::CXXRecordDecl>(RD))
      if (!CRD->isDependentContext() && !CRD->isInvalidDecl() &&
          CRD->isPolymorphic())
        PolymorphicClasses.push_back(CRD);
    std::string Name = qualifiedName(RD);
    if (!Name.empty())
      Records[Name].push_back(RD);
    return true;
  }
  bool VisitClassTemplateDecl(clang::ClassTemplateDecl *TD) {
    Templates[qualifiedDeclName(TD)].push_back(TD);
    return true;
  }
  bool VisitFunctionDecl(clang::FunctionDecl *FD) {
    if (FD->getIdentifier() && FD->getName() == "symcr_validate")
      Validators.push_back(FD);
    if (FD->getIdentifier() && FD->getName() == "symcr_migrate")
      Migrators.push_back(FD);
    return true;
  }
  bool VisitTypedefNameDecl(clang::TypedefNameDecl *TD) {
    Typedefs[qualifiedDeclName(TD)].push_back(TD);
    return true;
  }

  /// "ns::Class::member", "function::local": as a user names a root.
  static std::string rootName(const clang::VarDecl *VD) {
    std::string Prefix;
    const clang::DeclContext *DC = VD->getDeclContext();
    if (const auto *FD = clang::dyn_cast<clang::FunctionDecl>(DC)) {
      Prefix = qualifiedDeclName(FD);
    } else if (const auto *RD = clang::dyn_cast<clang::RecordDecl>(DC)) {
      Prefix = qualifiedName(RD);
    } else if (const auto *ND = clang::dyn_cast<clang::NamedDecl>(DC)) {
      Prefix = qualifiedDeclName(ND);
    }
    return Prefix.empty() ? VD->getName().str()
                          : Prefix + "::" + VD->getName().str();
  }

  /// Qualified name without anonymous or inline namespaces and without
  /// template arguments ("ns::Outer::Inner").
  static std::string qualifiedDeclName(const clang::NamedDecl *ND) {
    std::string Result = qualifiedScope(ND);
    if (ND->getIdentifier())
      return Result + ND->getName().str();
    if (const auto *R = clang::dyn_cast<clang::RecordDecl>(ND))
      if (const clang::TypedefNameDecl *T = R->getTypedefNameForAnonDecl())
        return Result + T->getName().str();
    return "";
  }
  /// The scope \p D is declared in, as a prefix ("ns::Outer::", or "").
  static std::string qualifiedScope(const clang::Decl *D) {
    std::vector<std::string> Parts;
    for (const clang::DeclContext *DC = D->getDeclContext(); DC;
         DC = DC->getParent()) {
      if (const auto *NS = clang::dyn_cast<clang::NamespaceDecl>(DC)) {
        if (NS->isAnonymousNamespace() || NS->isInline())
          continue;
        Parts.push_back(NS->getName().str());
      } else if (const auto *R = clang::dyn_cast<clang::RecordDecl>(DC)) {
        if (R->getIdentifier())
          Parts.push_back(R->getName().str());
        else if (const clang::TypedefNameDecl *T =
                     R->getTypedefNameForAnonDecl())
          Parts.push_back(T->getName().str());
      } else if (const auto *F = clang::dyn_cast<clang::FunctionDecl>(DC)) {
        Parts.push_back(F->getNameAsString());
      }
    }
    std::string Result;
    for (auto It = Parts.rbegin(); It != Parts.rend(); ++It)
      Result += *It + "::";
    return Result;
  }
  static std::string qualifiedName(const clang::RecordDecl *RD) {
    return qualifiedDeclName(RD);
  }

  clang::ASTContext &Context;
  std::map<std::string, std::vector<clang::VarDecl *>> Variables;
  std::map<std::string, std::vector<clang::RecordDecl *>> Records;
  std::map<std::string, std::vector<clang::ClassTemplateDecl *>> Templates;
  std::map<std::string, std::vector<clang::TypedefNameDecl *>> Typedefs;
  /// Class definitions with virtual functions, outside templates: the
  /// candidate dynamic types of heap objects behind polymorphic pointers.
  std::vector<const clang::CXXRecordDecl *> PolymorphicClasses;
  /// Every function named symcr_validate (templates' patterns included).
  std::vector<clang::FunctionDecl *> Validators;
  /// Every function named symcr_migrate (templates' patterns included).
  std::vector<clang::FunctionDecl *> Migrators;
};

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_NAMEINDEX_H
