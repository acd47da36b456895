//===- AstQueries.h - Small questions about Clang declarations
//--------------===//
//
// What symcr's annotations on a declaration say, where a declaration is, and
// whether a record is a standard library template: the questions every part
// of the schema builder asks.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_ASTQUERIES_H
#define SYMCR_GENERATOR_ASTQUERIES_H

#include "Model.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/Decl.h"
#include "clang/AST/DeclCXX.h"
#include "llvm/ADT/StringRef.h"

#include <string>
#include <vector>

namespace symcr_gen {

/// Values of the `annotate` attributes that symcr's macros put on a
/// declaration or any of its redeclarations.
std::vector<std::string> symcrAnnotations(const clang::Decl *D);

/// The declaration carries the symcr annotation \p Name.
bool hasAnnotation(const clang::Decl *D, llvm::StringRef Name);

/// The old names SYMCR_RENAMED_FROM gives the declaration.
std::vector<std::string> renamedFromAnnotations(const clang::Decl *D);

/// \p Loc as a file, line and column for diagnostics.
Location locationOf(const clang::ASTContext &Context,
                    clang::SourceLocation Loc);

/// \p RD is a specialization of a template of namespace std; \p Name is the
/// template's name.
bool isStdTemplate(const clang::RecordDecl *RD, llvm::StringRef &Name);

/// The mangled name of \p Class's vtable under the Itanium C++ ABI (every GCC
/// and Clang target symcr supports), or empty under another ABI.
std::string vtableSymbol(clang::ASTContext &Context,
                         const clang::CXXRecordDecl *Class);

/// The member function whose definition emits \p Class's vtable (the Itanium
/// ABI's key function: its first virtual function neither pure nor inline), or
/// null when every translation unit that needs the vtable emits its own copy.
const clang::CXXMethodDecl *
vtableKeyFunction(clang::ASTContext &Context,
                  const clang::CXXRecordDecl *Class);

/// The index of the trailing "[N][M]" suffix of an array type name.
std::size_t arraySuffixStart(const std::string &Name);

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_ASTQUERIES_H
