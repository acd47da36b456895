//===- SchemaTables.cpp - The program's schema as runtime tables ----------===//
//
// See SchemaTables.h.
//
//===----------------------------------------------------------------------===//
#include "SchemaTables.h"

#include "schema_blob.hpp"

namespace symcr_gen {

SchemaTables::SchemaTables(const ProgramModel &Program) {
  for (const ClockModel &Clock : Program.Clocks)
    Clocks.push_back(
        symcr::ClockInfo{Clock.Name.c_str(), nullptr,
                         static_cast<std::uint32_t>(Clocks.size())});
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
                             range(Field),
                             time(Field)};
        if (!Fields[F].time)
          Fields[F].flags &= ~std::uint32_t{symcr::kFieldClockTime};
      }
      Info.fields = Fields.data();
      Info.field_count = static_cast<std::uint32_t>(Fields.size());
    }
    if (!T.Enumerators.empty()) {
      EnumeratorTables.emplace_back();
      std::vector<symcr::EnumeratorInfo> &Enumerators = EnumeratorTables.back();
      for (const auto &E : T.Enumerators)
        Enumerators.push_back(symcr::EnumeratorInfo{E.first.c_str(), E.second});
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
    if (!T.ReferenceMembers.empty()) {
      FieldTables.emplace_back();
      std::vector<symcr::FieldInfo> &Members = FieldTables.back();
      for (const FieldModel &Member : T.ReferenceMembers)
        Members.push_back(symcr::FieldInfo{
            Member.Name.c_str(), Member.Type,
            static_cast<std::uint32_t>(Member.Offset), 0, 0, Member.Flags,
            aliases(Member.RenamedFrom), nullptr, nullptr});
      Info.reference_members = Members.data();
      Info.reference_member_count = static_cast<std::uint32_t>(Members.size());
    }
  }
  for (const RootModel &R : Program.Roots)
    Roots.push_back(symcr::RootInfo{R.Name.c_str(), R.Type, nullptr, R.Flags,
                                    aliases(R.RenamedFrom)});
  Schema = symcr::Schema{Types.empty() ? nullptr : Types.data(),
                         static_cast<std::uint32_t>(Types.size()),
                         Roots.empty() ? nullptr : Roots.data(),
                         static_cast<std::uint32_t>(Roots.size()),
                         Program.Name.empty() ? nullptr : Program.Name.c_str()};
  symcr::detail::serialise_blob(Schema, Blob);
  Serialised = symcr::SerialisedSchema{
      Blob.data, static_cast<std::uint32_t>(Blob.size), Blob.hash};
}

const symcr::FieldRange *SchemaTables::range(const FieldModel &Field) {
  if (!(Field.Flags & symcr::kFieldHasRange))
    return nullptr;
  Ranges.push_back(symcr::FieldRange{Field.RangeMin, Field.RangeMax});
  return &Ranges.back();
}

const symcr::FieldTime *SchemaTables::time(const FieldModel &Field) {
  if (!(Field.Flags & symcr::kFieldClockTime))
    return nullptr;
  for (const symcr::ClockInfo &Clock : Clocks)
    if (Field.Clock == Clock.name) {
      Times.push_back(symcr::FieldTime{&Clock, Field.Never});
      return &Times.back();
    }
  return nullptr; // an undeclared clock: diagnosed (checkClocks), nothing is
                  // written
}

/// A nullptr-terminated list of \p Names, or nullptr when there are none
/// (as the schema source writes it).
const char *const *
SchemaTables::aliases(const std::vector<std::string> &Names) {
  return nameList(Names, [](const std::string &Name) { return Name.c_str(); });
}

/// The names of the members \p T leaves to the new build, listed the same way.
const char *const *SchemaTables::leftToNewBuild(const TypeModel &T) {
  return nameList(T.LeftToNewBuild, [](const TypeModel::LeftMember &Left) {
    return Left.Name.c_str();
  });
}

template <class Items, class NameOf>
const char *const *SchemaTables::nameList(const Items &List, NameOf Name) {
  if (List.empty())
    return nullptr;
  AliasTables.emplace_back();
  std::vector<const char *> &Names = AliasTables.back();
  for (const auto &Item : List)
    Names.push_back(Name(Item));
  Names.push_back(nullptr);
  return Names.data();
}

} // namespace symcr_gen
