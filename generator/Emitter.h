//===- Emitter.h - Writes the generated sources ---------------------------===//
//
// From the ProgramModel: one wrapper per translation unit (Wrappers.cpp: the
// user's source, included, followed by the ops tables, lifecycles, layout
// checks and root addresses that need its declarations), one schema source
// holding the program's symcr::Schema tables, their serialised form and
// symcr_program_schema() (SchemaSource.cpp), the --report text
// (ReportText.cpp) and the output files (OutputFiles.cpp). No Clang here.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_EMITTER_H
#define SYMCR_GENERATOR_EMITTER_H

#include "Model.h"

#include <string>

namespace symcr_gen {

/// The schema source: tables and symcr_program_schema().
std::string emitSchemaSource(const ProgramModel &Program);

/// The wrapper of translation unit \p TUIndex.
std::string emitWrapper(const ProgramModel &Program, unsigned TUIndex);

/// The --report text: per root, the types and fields reached, bytes, skips.
std::string renderReport(const ProgramModel &Program);

/// Writes \p Content unless the file already holds it, so that an unchanged
/// output keeps its timestamp and dependents are not rebuilt.
bool writeFileIfChanged(const std::string &Path, const std::string &Content,
                        Diagnostics &Diags);

/// A Makefile-style depfile: "<target>: <dependencies...>".
std::string renderDepfile(const std::string &Target,
                          const std::vector<std::string> &Dependencies);

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_EMITTER_H
