//===- SchemaFile.cpp - Writes a build's schema file ----------------------===//
//
// See SchemaFile.h. The in-memory tables mirror emitSchemaSource() field for
// field; tests/generator/schema_file checks that the file's hash equals the
// one the built program computes.
//
//===----------------------------------------------------------------------===//
#include "SchemaFile.h"

#include "engine.hpp"
#include "schema_file.hpp"

#include <list>
#include <vector>

namespace symcr_gen {
namespace {

/// Owns the strings and tables a symcr::Schema points into.
class SchemaTables {
public:
  explicit SchemaTables(const ProgramModel &Program) {
    Types.resize(Program.Types.size());
    for (std::size_t I = 0; I < Program.Types.size(); ++I) {
      const TypeModel &T = Program.Types[I];
      symcr::TypeInfo &Info = Types[I];
      Info = symcr::TypeInfo{};
      Info.name = T.Name.c_str();
      Info.kind = T.Kind;
      Info.flags = T.Flags;
      Info.size = static_cast<std::uint32_t>(T.Size);
      Info.align = static_cast<std::uint32_t>(T.Align);
      if (!T.Fields.empty()) {
        FieldTables.emplace_back(T.Fields.size());
        std::vector<symcr::FieldInfo> &Fields = FieldTables.back();
        for (std::size_t F = 0; F < T.Fields.size(); ++F) {
          const FieldModel &Field = T.Fields[F];
          Fields[F] =
              symcr::FieldInfo{Field.Name.c_str(),
                               Field.Type,
                               static_cast<std::uint32_t>(Field.Offset),
                               static_cast<std::uint16_t>(Field.BitOffset),
                               static_cast<std::uint16_t>(Field.BitWidth),
                               Field.Flags,
                               aliases(Field.RenamedFrom),
                               Field.RangeMin,
                               Field.RangeMax};
        }
        Info.fields = Fields.data();
        Info.field_count = static_cast<std::uint32_t>(Fields.size());
      }
      if (!T.Enumerators.empty()) {
        EnumeratorTables.emplace_back();
        std::vector<symcr::EnumeratorInfo> &Enumerators =
            EnumeratorTables.back();
        for (const auto &E : T.Enumerators)
          Enumerators.push_back(
              symcr::EnumeratorInfo{E.first.c_str(), E.second});
        Info.enumerators = Enumerators.data();
        Info.enumerator_count = static_cast<std::uint32_t>(Enumerators.size());
      }
      Info.element = T.Element;
      Info.count = T.Count;
      if (!T.Alternatives.empty()) {
        Info.alternatives = T.Alternatives.data();
        Info.alternative_count =
            static_cast<std::uint32_t>(T.Alternatives.size());
      }
      Info.container_kind = T.ContainerKind;
      Info.renamed_from = aliases(T.RenamedFrom);
      Info.left_to_new_build = leftToNewBuild(T);
    }
    for (const RootModel &R : Program.Roots)
      Roots.push_back(symcr::RootInfo{R.Name.c_str(), R.Type, nullptr, R.Flags,
                                      aliases(R.RenamedFrom)});
    Schema = symcr::Schema{Types.empty() ? nullptr : Types.data(),
                           static_cast<std::uint32_t>(Types.size()),
                           Roots.empty() ? nullptr : Roots.data(),
                           static_cast<std::uint32_t>(Roots.size()),
                           Program.Name.empty() ? nullptr : Program.Name.c_str()};
  }

  const symcr::Schema &schema() const { return Schema; }

private:
  /// A nullptr-terminated list of \p Names, or nullptr when there are none
  /// (as the schema source writes it).
  const char *const *aliases(const std::vector<std::string> &Names) {
    return nameList(Names, [](const std::string &Name) { return Name.c_str(); });
  }

  /// The names of the members \p T leaves to the new build, listed the same way.
  const char *const *leftToNewBuild(const TypeModel &T) {
    return nameList(T.LeftToNewBuild, [](const TypeModel::LeftMember &Left) {
      return Left.Name.c_str();
    });
  }

  template <class Items, class NameOf>
  const char *const *nameList(const Items &List, NameOf Name) {
    if (List.empty())
      return nullptr;
    AliasTables.emplace_back();
    std::vector<const char *> &Names = AliasTables.back();
    for (const auto &Item : List)
      Names.push_back(Name(Item));
    Names.push_back(nullptr);
    return Names.data();
  }

  // Lists: the tables' addresses must not move while more are added.
  std::vector<symcr::TypeInfo> Types;
  std::vector<symcr::RootInfo> Roots;
  std::list<std::vector<symcr::FieldInfo>> FieldTables;
  std::list<std::vector<symcr::EnumeratorInfo>> EnumeratorTables;
  std::list<std::vector<const char *>> AliasTables;
  symcr::Schema Schema{};
};

/// The hash stored in an existing schema file, if \p Path is one.
bool existingHash(const std::string &Path, std::uint64_t &Hash) {
  symcr::detail::ParsedSchema Parsed;
  if (!symcr::detail::read_schema_file(Path.c_str(), Parsed).ok())
    return false;
  Hash = Parsed.hash();
  return true;
}

} // namespace

std::uint64_t schemaHash(const ProgramModel &Program) {
  SchemaTables Tables(Program);
  return symcr::detail::schema_blob(Tables.schema()).hash;
}

bool writeSchemaFile(const ProgramModel &Program, const std::string &Path,
                     Diagnostics &Diags) {
  SchemaTables Tables(Program);
  std::uint64_t Old = 0;
  if (existingHash(Path, Old) &&
      Old == symcr::detail::schema_blob(Tables.schema()).hash)
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
