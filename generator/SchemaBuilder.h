//===- SchemaBuilder.h - Roots and reachable types from Clang ASTs
//---------===//
//
// For each parsed translation unit: resolves the annotations (attributes,
// pragmas, sidecar directives) against its declarations, finds the roots it
// defines and walks every type they reach into the ProgramModel, diagnosing
// what cannot be restored with the path that reaches it and the fix.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_SCHEMABUILDER_H
#define SYMCR_GENERATOR_SCHEMABUILDER_H

#include "Annotations.h"
#include "Model.h"

#include <memory>
#include <set>
#include <vector>

namespace clang {
class ASTContext;
class Sema;
} // namespace clang

namespace symcr_gen {

class SchemaBuilder {
public:
  SchemaBuilder(ProgramModel &Program, Diagnostics &Diags,
                std::vector<Directive> SidecarDirectives);
  ~SchemaBuilder();

  /// Processes one parsed TU. \p PragmaDirectives are the `#pragma symcr`
  /// directives its preprocessor saw. With \p S, class template
  /// specializations that the roots reach but the TU never instantiated (e.g.
  /// only pointed to) are instantiated to learn their layout.
  void addTranslationUnit(clang::ASTContext &Context, clang::Sema *S,
                          unsigned TUIndex,
                          const std::vector<Directive> &PragmaDirectives);

  /// Reports directives that matched nothing in any TU and builds the
  /// per-root reports. Call once after every TU.
  /// Diagnoses what the annotations named and nothing matched (unless
  /// \p CheckUnmatched is false: some sources could not be parsed).
  void finish(bool CheckUnmatched = true);

private:
  /// Takes out of the heap's dynamic types every class whose vtable no parsed
  /// source emits, saying why under each pointer that could have held one.
  void dropClassesWithoutVtable();
  /// Names of the types whose objects the state holds: the roots, what they
  /// contain, and the heap objects restore creates behind their pointers.
  std::set<std::string> typesInState() const;

  struct DirectiveState;
  ProgramModel &Program;
  Diagnostics &Diags;
  std::vector<Directive> Sidecar;
  /// Per sidecar directive argument: matched in some TU.
  std::vector<std::vector<bool>> SidecarMatched;
  /// Checkpoint pragmas whose variable was only declared in their TU, to be
  /// matched by a definition in a later TU: name -> where.
  std::map<std::string, Location> PendingDeclaredRoots;
  std::set<std::string> DefinedRootNames;
};

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_SCHEMABUILDER_H
