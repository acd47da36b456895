//===- SchemaTables.h - The program's schema as runtime tables ------------===//
//
// The one place where the generator's ProgramModel becomes symcr::TypeInfo,
// FieldInfo, EnumeratorInfo and RootInfo values, and their serialised form
// (docs/format.md §2) and hash, computed by the runtime's own serialiser.
// The schema source prints these tables and embeds the serialised bytes; the
// schema file is written from them: one writer, so the three always agree.
// Ops, lifecycles, hooks and root addresses are null here: they are symbols of
// the generated code, not data.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_SCHEMATABLES_H
#define SYMCR_GENERATOR_SCHEMATABLES_H

#include "Model.h"
#include "schema_blob.hpp"

#include <list>
#include <string>
#include <vector>

namespace symcr_gen {

/// Owns the strings and tables a symcr::Schema points into.
class SchemaTables {
public:
  explicit SchemaTables(const ProgramModel &Program);
  SchemaTables(const SchemaTables &) = delete;
  SchemaTables &operator=(const SchemaTables &) = delete;

  /// The tables, and their serialised form and hash.
  const symcr::Schema &schema() const { return Schema; }
  const symcr::SerialisedSchema &serialised() const { return Serialised; }
  /// The program's clocks, by index (ProgramModel::Clocks' order).
  const std::vector<symcr::ClockInfo> &clocks() const { return Clocks; }

private:
  const char *const *aliases(const std::vector<std::string> &Names);
  /// The field's SYMCR_RANGE bounds, or null without one.
  const symcr::FieldRange *range(const FieldModel &Field);
  /// The field's clock and never value, or null when it holds no time.
  const symcr::FieldTime *time(const FieldModel &Field);
  const char *const *leftToNewBuild(const TypeModel &T);
  template <class Items, class NameOf>
  const char *const *nameList(const Items &List, NameOf Name);

  // Lists: the tables' addresses must not move while more are added.
  std::vector<symcr::TypeInfo> Types;
  std::vector<symcr::RootInfo> Roots;
  std::list<std::vector<symcr::FieldInfo>> FieldTables;
  std::list<std::vector<symcr::EnumeratorInfo>> EnumeratorTables;
  std::list<std::vector<const char *>> AliasTables;
  std::list<symcr::FieldRange> Ranges;
  std::vector<symcr::ClockInfo> Clocks;
  std::list<symcr::FieldTime> Times;
  symcr::detail::SchemaBlob Blob;
  symcr::SerialisedSchema Serialised{};
  symcr::Schema Schema{};
};

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_SCHEMATABLES_H
