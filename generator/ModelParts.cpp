//===- ModelParts.cpp - One translation unit's model, written and merged --===//
//
// See ModelParts.h. The part is JSON (LLVM's reader and writer): it is written
// and read by this tool only, and a reader that finds a field missing or of
// another kind reports the part as unreadable instead of guessing.
//
//===----------------------------------------------------------------------===//
#include "ModelParts.h"

#include "llvm/Support/JSON.h"
#include "llvm/Support/MemoryBuffer.h"

#include <algorithm>

namespace symcr_gen {
namespace json = llvm::json;
namespace {

/// Bumped whenever the part's fields change: a part of another format is
/// refused (rebuild).
constexpr std::int64_t PartFormat = 1;

json::Array strings(const std::vector<std::string> &List) {
  json::Array Out;
  for (const std::string &S : List)
    Out.push_back(S);
  return Out;
}

json::Array indices(const std::vector<std::uint32_t> &List) {
  json::Array Out;
  for (std::uint32_t I : List)
    Out.push_back(static_cast<std::int64_t>(I));
  return Out;
}

json::Value location(const Location &Where) {
  return json::Object{{"file", Where.File},
                      {"line", static_cast<std::int64_t>(Where.Line)},
                      {"column", static_cast<std::int64_t>(Where.Column)}};
}

json::Value field(const FieldModel &F) {
  return json::Object{{"name", F.Name},
                      {"type", static_cast<std::int64_t>(F.Type)},
                      {"offset", static_cast<std::int64_t>(F.Offset)},
                      {"bit_offset", static_cast<std::int64_t>(F.BitOffset)},
                      {"bit_width", static_cast<std::int64_t>(F.BitWidth)},
                      {"flags", static_cast<std::int64_t>(F.Flags)},
                      {"renamed_from", strings(F.RenamedFrom)},
                      {"range_min", F.RangeMin},
                      {"range_max", F.RangeMax},
                      {"clock", F.Clock},
                      {"never", F.Never},
                      {"offset_check_member", F.OffsetCheckMember}};
}

json::Array fields(const std::vector<FieldModel> &List) {
  json::Array Out;
  for (const FieldModel &F : List)
    Out.push_back(field(F));
  return Out;
}

json::Value type(const TypeModel &T, const std::string &Key) {
  json::Array Enumerators;
  for (const auto &E : T.Enumerators)
    Enumerators.push_back(json::Array{E.first, E.second});
  json::Array Left;
  for (const TypeModel::LeftMember &L : T.LeftToNewBuild)
    Left.push_back(json::Array{L.Name, L.Why});
  return json::Object{
      {"key", Key},
      {"name", T.Name},
      {"kind", static_cast<std::int64_t>(T.Kind)},
      {"flags", static_cast<std::int64_t>(T.Flags)},
      {"size", static_cast<std::int64_t>(T.Size)},
      {"align", static_cast<std::int64_t>(T.Align)},
      {"fields", fields(T.Fields)},
      {"enumerators", std::move(Enumerators)},
      {"element", static_cast<std::int64_t>(T.Element)},
      {"count", static_cast<std::int64_t>(T.Count)},
      {"alternatives", indices(T.Alternatives)},
      {"container_kind", static_cast<std::int64_t>(T.ContainerKind)},
      {"ops", static_cast<std::int64_t>(T.Ops)},
      {"needs_lifecycle", T.NeedsLifecycle},
      {"spelling", T.Spelling},
      {"accessible", T.Accessible},
      {"renamed_from", strings(T.RenamedFrom)},
      {"has_validate", T.HasValidate},
      {"has_migrate", T.HasMigrate},
      {"symbol", T.Symbol},
      {"vtable_symbol", T.VtableSymbol},
      {"vtable_address_point", static_cast<std::int64_t>(T.VtableAddressPoint)},
      {"dynamic_types", indices(T.DynamicTypes)},
      {"fingerprint", T.Fingerprint},
      {"first_seen_in", T.FirstSeenIn},
      {"left_to_new_build", std::move(Left)},
      {"reference_members", fields(T.ReferenceMembers)}};
}

/// Reads what writeModelPart() wrote; any field missing or of another kind
/// fails the read.
class PartReader {
public:
  explicit PartReader(std::string &Error) : Error(Error) {}

  bool program(const json::Value &Value, ProgramModel &P,
               std::vector<std::string> &Keys) {
    const json::Object *O = object(Value, "part");
    if (!O)
      return false;
    std::int64_t Format = 0;
    std::int64_t Profile = 0;
    if (!integer(*O, "format", Format))
      return false;
    if (Format != PartFormat)
      return fail(
          "written by another version of symcr-gen (rebuild the object)");
    if (!string(*O, "program", P.Name) || !integer(*O, "profile", Profile))
      return false;
    P.Profile = Profile ? RuntimeProfile::Device : RuntimeProfile::Host;
    for (const json::Value &V : *array(*O, "units")) {
      const json::Object *U = object(V, "unit");
      TranslationUnitModel TU;
      if (!U || !string(*U, "source", TU.Source) || !boolean(*U, "c", TU.IsC) ||
          !boolean(*U, "deduces_return_types", TU.DeducesReturnTypes))
        return false;
      P.TranslationUnits.push_back(TU);
    }
    for (const json::Value &V : *array(*O, "types")) {
      const json::Object *T = object(V, "type");
      TypeModel M;
      std::string Key;
      if (!T || !type(*T, M, Key))
        return false;
      Keys.push_back(Key);
      P.Types.push_back(std::move(M));
    }
    for (const json::Value &V : *array(*O, "roots")) {
      const json::Object *R = object(V, "root");
      RootModel M;
      if (!R || !string(*R, "name", M.Name) || !u32(*R, "type", M.Type) ||
          !u32(*R, "flags", M.Flags) ||
          !strings(*R, "renamed_from", M.RenamedFrom) ||
          !unsignedValue(*R, "home", M.HomeTU) ||
          !string(*R, "symbol", M.Symbol) || !where(*R, M.Where))
        return false;
      P.Roots.push_back(std::move(M));
    }
    for (const json::Value &V : *array(*O, "clocks")) {
      const json::Object *C = object(V, "clock");
      ClockModel M;
      std::int64_t Home = 0;
      if (!C || !string(*C, "name", M.Name) ||
          !string(*C, "function", M.Function) || !integer(*C, "home", Home) ||
          !string(*C, "call", M.CallExpression) ||
          !boolean(*C, "unsigned64", M.Unsigned64) ||
          !string(*C, "symbol", M.Symbol))
        return false;
      M.HomeTU = static_cast<int>(Home);
      P.Clocks.push_back(std::move(M));
    }
    for (const json::Value &V : *array(*O, "points")) {
      const json::Object *Pt = object(V, "point");
      PointModel M;
      if (!Pt || !boolean(*Pt, "restore", M.Restore) ||
          !string(*Pt, "function", M.Function) ||
          !boolean(*Pt, "exit", M.AtExit) ||
          !unsignedValue(*Pt, "every", M.Every) ||
          !boolean(*Pt, "stop", M.StopOnFailure) ||
          !boolean(*Pt, "strict", M.Strict) ||
          !string(*Pt, "spelling", M.Spelling))
        return false;
      P.Points.push_back(std::move(M));
    }
    const json::Object *S = O->getObject("store");
    if (!S)
      return fail("no store");
    PointStoreModel &Store = P.PointStore;
    return string(*S, "path", Store.Path) &&
           unsignedValue(*S, "slots", Store.Slots) &&
           unsignedValue(*S, "slot_size", Store.SlotSize) &&
           boolean(*S, "fdatasync", Store.Fdatasync) &&
           unsignedValue(*S, "fallback_depth", Store.FallbackDepth) &&
           unsignedValue(*S, "confirm_after", Store.ConfirmAfter) &&
           string(*S, "spelling", Store.Spelling);
  }

private:
  bool type(const json::Object &T, TypeModel &M, std::string &Key) {
    std::int64_t Kind = 0, Ops = 0, ContainerKind = 0;
    if (!string(T, "key", Key) || !string(T, "name", M.Name) ||
        !integer(T, "kind", Kind) || !u32(T, "flags", M.Flags) ||
        !u64(T, "size", M.Size) || !u64(T, "align", M.Align) ||
        !fields(T, "fields", M.Fields) || !u32(T, "element", M.Element) ||
        !u64(T, "count", M.Count) ||
        !indices(T, "alternatives", M.Alternatives) ||
        !integer(T, "container_kind", ContainerKind) ||
        !integer(T, "ops", Ops) ||
        !boolean(T, "needs_lifecycle", M.NeedsLifecycle) ||
        !string(T, "spelling", M.Spelling) ||
        !boolean(T, "accessible", M.Accessible) ||
        !strings(T, "renamed_from", M.RenamedFrom) ||
        !boolean(T, "has_validate", M.HasValidate) ||
        !boolean(T, "has_migrate", M.HasMigrate) ||
        !string(T, "symbol", M.Symbol) ||
        !string(T, "vtable_symbol", M.VtableSymbol) ||
        !unsignedValue(T, "vtable_address_point", M.VtableAddressPoint) ||
        !indices(T, "dynamic_types", M.DynamicTypes) ||
        !string(T, "fingerprint", M.Fingerprint) ||
        !string(T, "first_seen_in", M.FirstSeenIn) ||
        !fields(T, "reference_members", M.ReferenceMembers))
      return false;
    M.Kind = static_cast<symcr::Kind>(Kind);
    M.Ops = static_cast<OpsKind>(Ops);
    M.ContainerKind = static_cast<std::uint8_t>(ContainerKind);
    const json::Array *Enumerators = T.getArray("enumerators");
    const json::Array *Left = T.getArray("left_to_new_build");
    if (!Enumerators || !Left)
      return fail("a type without enumerators or left members");
    for (const json::Value &E : *Enumerators) {
      const json::Array *Pair = E.getAsArray();
      if (!Pair || Pair->size() != 2 || !(*Pair)[0].getAsString() ||
          !(*Pair)[1].getAsInteger())
        return fail("a malformed enumerator");
      M.Enumerators.emplace_back((*Pair)[0].getAsString()->str(),
                                 *(*Pair)[1].getAsInteger());
    }
    for (const json::Value &E : *Left) {
      const json::Array *Pair = E.getAsArray();
      if (!Pair || Pair->size() != 2 || !(*Pair)[0].getAsString() ||
          !(*Pair)[1].getAsString())
        return fail("a malformed left member");
      M.LeftToNewBuild.push_back(
          {(*Pair)[0].getAsString()->str(), (*Pair)[1].getAsString()->str()});
    }
    return true;
  }

  bool fields(const json::Object &O, const char *Name,
              std::vector<FieldModel> &Out) {
    const json::Array *List = O.getArray(Name);
    if (!List)
      return fail(std::string("no ") + Name);
    for (const json::Value &V : *List) {
      const json::Object *F = object(V, "field");
      FieldModel M;
      if (!F || !string(*F, "name", M.Name) || !u32(*F, "type", M.Type) ||
          !u64(*F, "offset", M.Offset) ||
          !unsignedValue(*F, "bit_offset", M.BitOffset) ||
          !unsignedValue(*F, "bit_width", M.BitWidth) ||
          !u32(*F, "flags", M.Flags) ||
          !strings(*F, "renamed_from", M.RenamedFrom) ||
          !number(*F, "range_min", M.RangeMin) ||
          !number(*F, "range_max", M.RangeMax) ||
          !string(*F, "clock", M.Clock) || !integer(*F, "never", M.Never) ||
          !string(*F, "offset_check_member", M.OffsetCheckMember))
        return false;
      Out.push_back(std::move(M));
    }
    return true;
  }

  bool where(const json::Object &O, Location &Out) {
    const json::Object *W = O.getObject("where");
    return W && string(*W, "file", Out.File) &&
           unsignedValue(*W, "line", Out.Line) &&
           unsignedValue(*W, "column", Out.Column);
  }
  const json::Object *object(const json::Value &V, const char *What) {
    const json::Object *O = V.getAsObject();
    if (!O)
      fail(std::string("a ") + What + " is not an object");
    return O;
  }
  const json::Array *array(const json::Object &O, const char *Name) {
    static const json::Array Empty;
    const json::Array *A = O.getArray(Name);
    if (!A) {
      fail(std::string("no ") + Name);
      return &Empty;
    }
    return A;
  }
  bool string(const json::Object &O, const char *Name, std::string &Out) {
    llvm::Optional<llvm::StringRef> S = O.getString(Name);
    if (!S)
      return fail(std::string("no string ") + Name);
    Out = S->str();
    return true;
  }
  bool strings(const json::Object &O, const char *Name,
               std::vector<std::string> &Out) {
    const json::Array *A = O.getArray(Name);
    if (!A)
      return fail(std::string("no list ") + Name);
    for (const json::Value &V : *A) {
      if (!V.getAsString())
        return fail(std::string("a non-string in ") + Name);
      Out.push_back(V.getAsString()->str());
    }
    return true;
  }
  bool indices(const json::Object &O, const char *Name,
               std::vector<std::uint32_t> &Out) {
    const json::Array *A = O.getArray(Name);
    if (!A)
      return fail(std::string("no list ") + Name);
    for (const json::Value &V : *A) {
      llvm::Optional<std::int64_t> I = V.getAsInteger();
      if (!I || *I < 0 || *I > UINT32_MAX)
        return fail(std::string("a bad index in ") + Name);
      Out.push_back(static_cast<std::uint32_t>(*I));
    }
    return true;
  }
  bool integer(const json::Object &O, const char *Name, std::int64_t &Out) {
    llvm::Optional<std::int64_t> I = O.getInteger(Name);
    if (!I)
      return fail(std::string("no integer ") + Name);
    Out = *I;
    return true;
  }
  bool u64(const json::Object &O, const char *Name, std::uint64_t &Out) {
    std::int64_t I = 0;
    if (!integer(O, Name, I) || I < 0)
      return fail(std::string("a bad ") + Name);
    Out = static_cast<std::uint64_t>(I);
    return true;
  }
  bool u32(const json::Object &O, const char *Name, std::uint32_t &Out) {
    std::uint64_t I = 0;
    if (!u64(O, Name, I) || I > UINT32_MAX)
      return fail(std::string("a bad ") + Name);
    Out = static_cast<std::uint32_t>(I);
    return true;
  }
  bool unsignedValue(const json::Object &O, const char *Name, unsigned &Out) {
    std::uint32_t I = 0;
    if (!u32(O, Name, I))
      return false;
    Out = I;
    return true;
  }
  bool boolean(const json::Object &O, const char *Name, bool &Out) {
    llvm::Optional<bool> B = O.getBoolean(Name);
    if (!B)
      return fail(std::string("no boolean ") + Name);
    Out = *B;
    return true;
  }
  bool number(const json::Object &O, const char *Name, double &Out) {
    llvm::Optional<double> D = O.getNumber(Name);
    if (!D)
      return fail(std::string("no number ") + Name);
    Out = *D;
    return true;
  }
  bool fail(const std::string &Why) {
    if (Error.empty())
      Error = Why;
    return false;
  }
  std::string &Error;
};

std::uint32_t remapped(std::uint32_t Index,
                       const std::vector<std::uint32_t> &Map) {
  return Index == symcr::kNoType || Index >= Map.size() ? Index : Map[Index];
}

void remapFields(std::vector<FieldModel> &Fields,
                 const std::vector<std::uint32_t> &Map) {
  for (FieldModel &F : Fields)
    F.Type = remapped(F.Type, Map);
}

/// Every type index names a type of the part, every unit index one of its
/// units: the merge and the emitters index with them.
bool indicesInRange(const ProgramModel &Part) {
  const std::size_t Types = Part.Types.size();
  const std::size_t Units = Part.TranslationUnits.size();
  auto TypeOk = [&](std::uint32_t I) {
    return I == symcr::kNoType || I < Types;
  };
  auto FieldsOk = [&](const std::vector<FieldModel> &Fields) {
    return std::all_of(Fields.begin(), Fields.end(),
                       [&](const FieldModel &F) { return TypeOk(F.Type); });
  };
  for (const TypeModel &T : Part.Types)
    if (T.HomeTU >= Units || !TypeOk(T.Element) || !FieldsOk(T.Fields) ||
        !FieldsOk(T.ReferenceMembers) ||
        !std::all_of(T.Alternatives.begin(), T.Alternatives.end(), TypeOk) ||
        !std::all_of(T.DynamicTypes.begin(), T.DynamicTypes.end(),
                     [&](std::uint32_t I) { return I < Types; }))
      return false;
  for (const RootModel &R : Part.Roots)
    if (R.HomeTU >= Units || R.Type >= Types)
      return false;
  for (const ClockModel &C : Part.Clocks)
    if (C.HomeTU >= static_cast<int>(Units))
      return false;
  return true;
}

} // namespace

void nameSymbolsForUnit(ProgramModel &Program, const std::string &Unit) {
  for (std::size_t I = 0; I < Program.Types.size(); ++I)
    Program.Types[I].Symbol = Unit + "_" + std::to_string(I);
  for (std::size_t I = 0; I < Program.Roots.size(); ++I)
    Program.Roots[I].Symbol = Unit + "_" + std::to_string(I);
  for (std::size_t I = 0; I < Program.Clocks.size(); ++I)
    Program.Clocks[I].Symbol = Unit + "_" + std::to_string(I);
}

std::string writeModelPart(const ProgramModel &Program) {
  std::vector<std::string> Keys(Program.Types.size());
  for (const auto &Entry : Program.TypeIndex)
    if (Entry.second < Keys.size())
      Keys[Entry.second] = Entry.first;
  json::Array Units, Types, Roots, Clocks, Points;
  for (const TranslationUnitModel &TU : Program.TranslationUnits)
    Units.push_back(
        json::Object{{"source", TU.Source},
                     {"c", TU.IsC},
                     {"deduces_return_types", TU.DeducesReturnTypes}});
  for (std::size_t I = 0; I < Program.Types.size(); ++I)
    Types.push_back(type(Program.Types[I], Keys[I]));
  for (const RootModel &R : Program.Roots)
    Roots.push_back(json::Object{{"name", R.Name},
                                 {"type", static_cast<std::int64_t>(R.Type)},
                                 {"flags", static_cast<std::int64_t>(R.Flags)},
                                 {"renamed_from", strings(R.RenamedFrom)},
                                 {"home", static_cast<std::int64_t>(R.HomeTU)},
                                 {"symbol", R.Symbol},
                                 {"where", location(R.Where)}});
  for (const ClockModel &C : Program.Clocks)
    Clocks.push_back(json::Object{{"name", C.Name},
                                  {"function", C.Function},
                                  {"home", static_cast<std::int64_t>(C.HomeTU)},
                                  {"call", C.CallExpression},
                                  {"unsigned64", C.Unsigned64},
                                  {"symbol", C.Symbol}});
  for (const PointModel &P : Program.Points)
    Points.push_back(json::Object{{"restore", P.Restore},
                                  {"function", P.Function},
                                  {"exit", P.AtExit},
                                  {"every", static_cast<std::int64_t>(P.Every)},
                                  {"stop", P.StopOnFailure},
                                  {"strict", P.Strict},
                                  {"spelling", P.Spelling}});
  const PointStoreModel &Store = Program.PointStore;
  json::Object Part{
      {"format", PartFormat},
      {"program", Program.Name},
      {"profile", Program.Profile == RuntimeProfile::Device ? 1 : 0},
      {"units", std::move(Units)},
      {"types", std::move(Types)},
      {"roots", std::move(Roots)},
      {"clocks", std::move(Clocks)},
      {"points", std::move(Points)},
      {"store",
       json::Object{
           {"path", Store.Path},
           {"slots", static_cast<std::int64_t>(Store.Slots)},
           {"slot_size", static_cast<std::int64_t>(Store.SlotSize)},
           {"fdatasync", Store.Fdatasync},
           {"fallback_depth", static_cast<std::int64_t>(Store.FallbackDepth)},
           {"confirm_after", static_cast<std::int64_t>(Store.ConfirmAfter)},
           {"spelling", Store.Spelling}}}};
  std::string Text;
  llvm::raw_string_ostream OS(Text);
  OS << json::Value(std::move(Part)) << "\n";
  return OS.str();
}

bool mergeModelPart(const std::string &File, ProgramModel &Program,
                    Diagnostics &Diags) {
  const Location Where{File, 0, 0};
  auto Buffer = llvm::MemoryBuffer::getFile(File);
  if (!Buffer) {
    Diags.error(Where, "cannot read the part: " + Buffer.getError().message());
    return false;
  }
  llvm::Expected<json::Value> Value = json::parse((*Buffer)->getBuffer());
  if (!Value) {
    Diags.error(Where,
                "not a symcr-gen part: " + llvm::toString(Value.takeError()));
    return false;
  }
  ProgramModel Part;
  std::vector<std::string> Keys;
  std::string Error;
  if (!PartReader(Error).program(*Value, Part, Keys) || !Error.empty()) {
    Diags.error(Where, "not a readable symcr-gen part: " + Error);
    return false;
  }
  if (!indicesInRange(Part)) {
    Diags.error(Where, "not a readable symcr-gen part: an index out of range");
    return false;
  }
  const bool First = Program.TranslationUnits.empty();
  if (!First &&
      (Part.Name != Program.Name || Part.Profile != Program.Profile)) {
    Diags.error(
        Where,
        "generated for program '" + Part.Name + "' (profile " +
            (Part.Profile == RuntimeProfile::Device ? "device" : "host") +
            "), where the other objects are '" + Program.Name + "' (profile " +
            (Program.Profile == RuntimeProfile::Device ? "device" : "host") +
            "): compile every source of one program with the same options");
    return false;
  }
  Program.Name = Part.Name;
  Program.Profile = Part.Profile;
  const unsigned UnitBase =
      static_cast<unsigned>(Program.TranslationUnits.size());
  Program.TranslationUnits.insert(Program.TranslationUnits.end(),
                                  Part.TranslationUnits.begin(),
                                  Part.TranslationUnits.end());

  // Types: by the key one run merges them by (canonical name, and the shallow
  // view's own key).
  std::vector<std::uint32_t> Map(Part.Types.size());
  std::vector<bool> Fresh(Part.Types.size(), false);
  bool Consistent = true;
  for (std::size_t I = 0; I < Part.Types.size(); ++I) {
    auto It = Program.TypeIndex.find(Keys[I]);
    if (It == Program.TypeIndex.end()) {
      Map[I] = static_cast<std::uint32_t>(Program.Types.size());
      Program.TypeIndex.emplace(Keys[I], Map[I]);
      Program.Types.emplace_back();
      Fresh[I] = true;
      continue;
    }
    Map[I] = It->second;
    const TypeModel &Known = Program.Types[It->second];
    if (Known.Fingerprint != Part.Types[I].Fingerprint) {
      // Named by both sources; the part's own file is a temporary of the link.
      Diags.error(
          Location(),
          "type '" + Part.Types[I].Name + "' is described differently in '" +
              Part.Types[I].FirstSeenIn + "' than in '" + Known.FirstSeenIn +
              "': the annotations (pragmas, sidecar) that select its members "
              "and the definition must be the same in both");
      Consistent = false;
    }
  }
  if (!Consistent)
    return false;
  for (std::size_t I = 0; I < Part.Types.size(); ++I) {
    TypeModel T = std::move(Part.Types[I]);
    remapFields(T.Fields, Map);
    remapFields(T.ReferenceMembers, Map);
    T.Element = remapped(T.Element, Map);
    for (std::uint32_t &A : T.Alternatives)
      A = remapped(A, Map);
    for (std::uint32_t &D : T.DynamicTypes)
      D = remapped(D, Map);
    T.HomeTU += UnitBase;
    TypeModel &Slot = Program.Types[Map[I]];
    if (Fresh[I]) {
      Slot = std::move(T);
      continue;
    }
    // Every unit's wrapper defines the code of every type it reaches; one unit
    // may create a type on restore where another only holds it: the type is
    // served from one that creates.
    for (std::uint32_t D : T.DynamicTypes)
      if (std::find(Slot.DynamicTypes.begin(), Slot.DynamicTypes.end(), D) ==
          Slot.DynamicTypes.end())
        Slot.DynamicTypes.push_back(D);
    if (T.hasLifecycle() && !Slot.hasLifecycle()) {
      Slot.NeedsLifecycle = true;
      Slot.HomeTU = T.HomeTU;
      Slot.Symbol = T.Symbol;
      Slot.VtableSymbol = T.VtableSymbol;
      Slot.VtableAddressPoint = T.VtableAddressPoint;
    }
    Slot.Flags |= T.Flags & (symcr::kTypeCreatable | symcr::kTypeDynamicType);
  }

  for (RootModel &R : Part.Roots) {
    for (const RootModel &Known : Program.Roots)
      if (Known.Name == R.Name) {
        Diags.error(R.Where,
                    "root '" + R.Name + "' is defined in '" +
                        Program.TranslationUnits[UnitBase + R.HomeTU].Source +
                        "' and in '" +
                        Program.TranslationUnits[Known.HomeTU].Source + "'");
        return false;
      }
    R.Type = remapped(R.Type, Map);
    R.HomeTU += UnitBase;
    Program.Roots.push_back(std::move(R));
  }
  for (ClockModel &C : Part.Clocks) {
    auto Known =
        std::find_if(Program.Clocks.begin(), Program.Clocks.end(),
                     [&](const ClockModel &K) { return K.Name == C.Name; });
    if (C.HomeTU >= 0)
      C.HomeTU += static_cast<int>(UnitBase);
    if (Known == Program.Clocks.end())
      Program.Clocks.push_back(std::move(C));
    else if (Known->HomeTU < 0 && C.HomeTU >= 0)
      *Known = std::move(C);
  }
  // The clocks' order is their index in the schema: their names' byte order, as
  // one run has.
  std::sort(
      Program.Clocks.begin(), Program.Clocks.end(),
      [](const ClockModel &A, const ClockModel &B) { return A.Name < B.Name; });
  for (PointModel &P : Part.Points)
    if (std::none_of(
            Program.Points.begin(), Program.Points.end(),
            [&](const PointModel &K) { return K.Spelling == P.Spelling; }))
      Program.Points.push_back(std::move(P));
  if (Program.PointStore.Spelling.empty())
    Program.PointStore = Part.PointStore;
  return true;
}

} // namespace symcr_gen
