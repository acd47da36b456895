//===- ModelParts.h - One translation unit's model, written and merged ----===//
//
// The compiler wrapper (symcr-c++) generates each translation unit on its own
// (--unit): that run's ProgramModel is written as a *part* (--part-file), which
// travels inside the TU's object file. Linking merges the parts of every object
// (--link-part) into the program's model, from which the schema source and
// schema file are written as if one run had parsed every source.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_MODELPARTS_H
#define SYMCR_GENERATOR_MODELPARTS_H

#include "Model.h"

#include <string>

namespace symcr_gen {

/// Names the generated code of a one-TU run after \p Unit (symbolOf()), so that
/// the wrappers of separately generated TUs never define the same symbol. Call
/// after the TU was generated.
void nameSymbolsForUnit(ProgramModel &Program, const std::string &Unit);

/// The part of a one-TU run: its model as JSON, what merging and emitting need.
std::string writeModelPart(const ProgramModel &Program);

/// Adds the part in \p File to \p Program. A type described differently than in
/// a part already merged is an error naming both sources; so is a root defined
/// twice. Returns false after an error.
bool mergeModelPart(const std::string &File, ProgramModel &Program,
                    Diagnostics &Diags);

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_MODELPARTS_H
