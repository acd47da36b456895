//===- PreviousPlans.h - Plans previous builds' schemas at build time -----===//
//
// symcr_add_checkpointing(... PREVIOUS_SCHEMA <file>): the schema file of a
// build this one replaces is resolved against this build's schema now, with
// the runtime's own planner, and the plan's image is embedded in the schema
// source. The first restore of that build's checkpoint in a freshly started
// process then decodes the image instead of planning.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_PREVIOUSPLANS_H
#define SYMCR_GENERATOR_PREVIOUSPLANS_H

#include "Model.h"

#include <string>
#include <vector>

namespace symcr_gen {

/// Plans each of \p SchemaFiles against \p Program's schema into
/// Program.PreviousPlans. A file with this build's own schema needs no plan
/// and is left out. False after a diagnostic (an unreadable file, another
/// program's schema, the device profile, which never plans).
bool planPreviousSchemas(ProgramModel &Program,
                         const std::vector<std::string> &SchemaFiles,
                         Diagnostics &Diags);

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_PREVIOUSPLANS_H
