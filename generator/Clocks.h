//===- Clocks.h - Clocks and the times of their members
//--------------------===//
//
// clock(...) directives become ProgramModel::Clocks; each is resolved to its
// reading function in the first TU that declares it. Marking members as times
// is TypeWalker::fieldTime.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_CLOCKS_H
#define SYMCR_GENERATOR_CLOCKS_H

#include "Annotations.h"
#include "Model.h"

namespace clang {
class ASTContext;
} // namespace clang

namespace symcr_gen {

/// Adds the clock a clock(...) directive names (kept in name order), or
/// diagnoses a second reading function for it.
void declareClock(const Directive &D, ProgramModel &Program,
                  Diagnostics &Diags);
/// Finds, in this TU, the reading function of each clock no earlier TU
/// declared.
void resolveClocks(clang::ASTContext &Context, unsigned TUIndex,
                   ProgramModel &Program, Diagnostics &Diags);
/// After every TU: each clock's function was found, and each time names a
/// declared clock.
void checkClocks(const ProgramModel &Program, Diagnostics &Diags);

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_CLOCKS_H
