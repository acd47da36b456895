//===- SchemaFile.cpp - Writes a build's schema file ----------------------===//
//
// See SchemaFile.h. Written from the same tables (SchemaTables) as the schema
// source; tests/generator/schema_file checks that the file's hash equals the
// one the built program holds.
//
//===----------------------------------------------------------------------===//
#include "SchemaFile.h"
#include "SchemaTables.h"

#include "parsed_schema.hpp"
#include "schema_file.hpp"

namespace symcr_gen {
namespace {

/// The hash stored in an existing schema file, if \p Path is one.
bool existingHash(const std::string &Path, std::uint64_t &Hash) {
  symcr::detail::ParsedSchema Parsed;
  if (!symcr::detail::read_schema_file(Path.c_str(), Parsed).ok())
    return false;
  Hash = Parsed.hash();
  return true;
}

} // namespace

bool writeSchemaFile(const ProgramModel &Program, const std::string &Path,
                     Diagnostics &Diags) {
  SchemaTables Tables(Program);
  std::uint64_t Old = 0;
  if (existingHash(Path, Old) && Old == Tables.serialised().hash)
    return true;
  symcr::Status Status =
      symcr::detail::write_schema_file(Tables.schema(), Path.c_str());
  if (!Status.ok()) {
    Diags.error(Location(), "cannot write the schema file '" + Path +
                                "': " + Status.message());
    return false;
  }
  return true;
}

} // namespace symcr_gen
