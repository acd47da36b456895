//===- SchemaFile.h - Writes a build's schema file ------------------------===//
//
// The schema of the program being generated, as a file that tools read without
// running the program (`symcr plan <checkpoint> --schema <file>`, tracker issue
// 5). The ProgramModel is turned into an in-memory symcr::Schema holding the
// same tables the schema source declares (ops, lifecycles, validation hooks and
// root addresses are null: they are not serialised), and the runtime's
// write_schema_file() writes it, so its hash is the one the running program
// computes for its own schema.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_SCHEMAFILE_H
#define SYMCR_GENERATOR_SCHEMAFILE_H

#include "Model.h"

#include <cstdint>
#include <string>

namespace symcr_gen {

/// The hash (docs/format.md §2) of the schema the generated code defines.
std::uint64_t schemaHash(const ProgramModel &Program);

/// Writes the schema file to \p Path, unless it already holds this schema (so
/// that an unchanged schema keeps the file's timestamp). False after a
/// diagnostic.
bool writeSchemaFile(const ProgramModel &Program, const std::string &Path,
                     Diagnostics &Diags);

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_SCHEMAFILE_H
