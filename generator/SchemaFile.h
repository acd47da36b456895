//===- SchemaFile.h - Writes a build's schema file ------------------------===//
//
// The schema of the program being generated, as a file that tools read without
// running the program (`symcr plan <checkpoint> --schema <file>`), written by
// the runtime's write_schema_file() from the tables the schema source embeds
// (SchemaTables), so its hash is the one the running program holds.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_SCHEMAFILE_H
#define SYMCR_GENERATOR_SCHEMAFILE_H

#include "Model.h"

#include <cstdint>
#include <string>

namespace symcr_gen {

/// Writes the schema file to \p Path, unless it already holds this schema (so
/// that an unchanged schema keeps the file's timestamp). False after a
/// diagnostic.
bool writeSchemaFile(const ProgramModel &Program, const std::string &Path,
                     Diagnostics &Diags);

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_SCHEMAFILE_H
