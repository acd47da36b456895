//===- ReportText.cpp - Writes symcr-gen's --report text ------------------===//
//
// Per root: the types and fields it reaches, the bytes of fixed payload, what
// is skipped and why, which classes heap objects behind a polymorphic
// pointer are saved as, and the state flags that may describe state that is
// not restored.
//
//===----------------------------------------------------------------------===//
#include "EmitSupport.h"
#include "Emitter.h"
#include "SchemaTables.h"
#include "payload_grammar.hpp"

#include <set>
#include <sstream>

namespace symcr_gen {

/// Whether an object of type \p T is, or has as a base, a \p Class object.
static bool isA(const ProgramModel &Program, std::uint32_t T,
                std::uint32_t Class, int Depth) {
  if (T == Class)
    return true;
  if (Depth > 64 || T >= Program.Types.size())
    return false;
  const TypeModel &Type = Program.Types[T];
  for (const std::vector<FieldModel> *List :
       {&Type.Fields, &Type.ReferenceMembers})
    for (const FieldModel &F : *List)
      if ((F.Flags & symcr::kFieldBase) &&
          isA(Program, F.Type, Class, Depth + 1))
        return true;
  return false;
}

/// The members and elements of the roots (selected or reference members) that
/// are \p Class objects, by path ("vehicle.mode_auto", "vehicle.rtl_modes[]").
static void collectPointees(const ProgramModel &Program, std::uint32_t T,
                            std::uint32_t Class, const std::string &Path,
                            int Depth, std::vector<std::string> &Out) {
  if (Depth > 64 || T >= Program.Types.size())
    return;
  const TypeModel &Type = Program.Types[T];
  if (Type.Kind == symcr::Kind::Array) {
    if (isA(Program, Type.Element, Class, 0))
      Out.push_back(Path + "[]");
    else
      collectPointees(Program, Type.Element, Class, Path + "[]", Depth + 1,
                      Out);
    return;
  }
  for (const std::vector<FieldModel> *List :
       {&Type.Fields, &Type.ReferenceMembers})
    for (const FieldModel &F : *List) {
      if (F.Flags & symcr::kFieldBase)
        continue;
      std::string Member = Path + "." + F.Name;
      if (isA(Program, F.Type, Class, 0))
        Out.push_back(Member);
      else
        collectPointees(Program, F.Type, Class, Member, Depth + 1, Out);
    }
}

/// What the pointer type \p T may point at: the state's objects of its class,
/// by path, and unless it never owns a heap object, the classes of the heap
/// objects it may own.
static void writePointees(std::ostream &OS, const ProgramModel &Program,
                          std::uint32_t T) {
  const TypeModel &Pointer = Program.Types[T];
  std::vector<std::string> Paths;
  for (const RootModel &Root : Program.Roots) {
    if (isA(Program, Root.Type, Pointer.Element, 0))
      Paths.push_back(Root.Name);
    else
      collectPointees(Program, Root.Type, Pointer.Element, Root.Name, 0, Paths);
  }
  OS << "    " << Pointer.Name << " may point at: ";
  for (std::size_t I = 0; I < Paths.size(); ++I)
    OS << (I ? ", " : "") << Paths[I];
  if (Paths.empty())
    OS << "no object of the state";
  const TypeModel &Pointee = Program.Types[Pointer.Element];
  if (Pointer.Flags & symcr::kTypeNeverOwns) {
    OS << "; never a heap object (not_owner)";
  } else if (Pointee.Flags & symcr::kTypePolymorphic) {
    OS << "; heap objects of: ";
    for (std::size_t D = 0; D < Pointee.DynamicTypes.size(); ++D)
      OS << (D ? ", " : "") << Program.Types[Pointee.DynamicTypes[D]].Name;
    if (Pointee.DynamicTypes.empty())
      OS << "none";
  } else {
    OS << "; heap objects of: " << Pointee.Name;
  }
  OS << "\n";
}

/// A restored state flag of a class that leaves members out may say that state
/// is there (started, initialised, a mode) which the restore did not bring
/// back: the new process then acts on state it lacks, as a restored "estimator
/// started" with estimator cores that were never created. One warning per such
/// flag, naming what its class leaves out.
static void writeStateFlagWarnings(std::ostream &OS,
                                   const ProgramModel &Program) {
  std::set<std::string>
      Warned; // a class walked for a shallow root and a deep one
  std::ostringstream Lines;
  for (const TypeModel &Type : Program.Types) {
    if (Type.Skipped.empty())
      continue;
    std::string LeftOut;
    for (const TypeModel::LeftMember &Member : Type.Skipped)
      LeftOut += (LeftOut.empty() ? "" : ", ") + Member.Name;
    for (const FieldModel &F : Type.Fields) {
      if ((F.Flags & symcr::kFieldBase) || F.RestoresAlone ||
          !isStateFlag(Program.Types[F.Type]))
        continue;
      const std::string Flag = Type.Name + "::" + F.Name;
      if (!Warned.insert(Flag).second)
        continue;
      Lines << "  warning: " << Flag << " (" << Program.Types[F.Type].Name
            << ") is restored, but " << Type.Name << " leaves out " << LeftOut
            << ": the restored flag may describe state that was not restored\n";
    }
  }
  if (Warned.empty())
    return;
  OS << "\nstate flags that may describe state not restored (" << Warned.size()
     << "; restores_alone(Type::member) or SYMCR_RESTORES_ALONE declares that "
        "a flag "
        "describes no such state):\n"
     << Lines.str();
}

std::string renderReport(const ProgramModel &Program) {
  std::ostringstream OS;
  OS << "symcr-gen report: " << Program.Roots.size() << " root(s), "
     << Program.Types.size() << " type(s) in the schema\n";
  // The fewest bytes each type takes in a payload, as the runtime computes it.
  SchemaTables Tables(Program);
  const symcr::detail::WireSizes Sizes =
      symcr::detail::wire_sizes(Tables.schema());
  for (const RootModel &Root : Program.Roots) {
    std::set<std::uint32_t> Seen;
    std::vector<std::uint32_t> Order;
    std::vector<std::uint32_t> Pending{Root.Type};
    while (!Pending.empty()) {
      std::uint32_t T = Pending.back();
      Pending.pop_back();
      if (T == symcr::kNoType || !Seen.insert(T).second)
        continue;
      Order.push_back(T);
      const TypeModel &Type = Program.Types[T];
      for (auto It = Type.ReferenceMembers.rbegin();
           It != Type.ReferenceMembers.rend(); ++It)
        Pending.push_back(It->Type);
      for (auto It = Type.Fields.rbegin(); It != Type.Fields.rend(); ++It)
        Pending.push_back(It->Type);
      for (auto It = Type.Alternatives.rbegin(); It != Type.Alternatives.rend();
           ++It)
        Pending.push_back(*It);
      for (auto It = Type.DynamicTypes.rbegin(); It != Type.DynamicTypes.rend();
           ++It)
        Pending.push_back(*It);
      if (Type.Element != symcr::kNoType)
        Pending.push_back(Type.Element);
    }
    std::size_t FieldCount = 0, SkipCount = 0, LeftCount = 0;
    for (std::uint32_t T : Order) {
      FieldCount += Program.Types[T].Fields.size();
      SkipCount += Program.Types[T].Skipped.size();
      LeftCount += Program.Types[T].LeftToNewBuild.size();
    }
    const TypeModel &RootType = Program.Types[Root.Type];
    OS << "\nroot " << Root.Name
       << (Root.Flags & symcr::kRootShallow ? " (shallow)" : "") << ": "
       << RootType.Name << ", " << RootType.Size << " bytes in memory, "
       << Sizes.least[Root.Type] << " bytes of fixed payload\n"
       << "  reaches " << Order.size() << " type(s), " << FieldCount
       << " field(s); skips " << SkipCount << "; leaves " << LeftCount
       << " to the new build\n";
    if (Root.Where.valid())
      OS << "  defined at " << Root.Where.File << ":" << Root.Where.Line
         << "\n";
    for (std::uint32_t T : Order) {
      const TypeModel &Type = Program.Types[T];
      OS << "  " << kindName(Type.Kind) << " " << Type.Name << " (" << Type.Size
         << " B)";
      if (Type.Kind == symcr::Kind::Array)
        OS << " x" << Type.Count;
      OS << "\n";
      for (const FieldModel &F : Type.Fields) {
        OS << "    " << (F.Flags & symcr::kFieldBase ? "base " : "") << F.Name
           << ": " << Program.Types[F.Type].Name << " @" << F.Offset;
        if (F.BitWidth)
          OS << " bits " << F.BitOffset << "+" << F.BitWidth;
        if (!F.RenamedFrom.empty()) {
          OS << " (renamed from";
          for (const std::string &Old : F.RenamedFrom)
            OS << " " << Old;
          OS << ")";
        }
        if (F.Flags & symcr::kFieldClockTime)
          OS << " (time of clock " << F.Clock
             << (F.Never ? ", never " + std::to_string(F.Never) : std::string())
             << ")";
        OS << "\n";
      }
      for (const FieldModel &F : Type.ReferenceMembers)
        OS << "    reference only "
           << (F.Flags & symcr::kFieldBase ? "base " : "") << F.Name << ": "
           << Program.Types[F.Type].Name << " @" << F.Offset << "\n";
      for (const TypeModel::LeftMember &S : Type.Skipped)
        OS << "    skipped " << S.Name << ": " << S.Why << "\n";
      if (Type.Kind == symcr::Kind::Pointer && Type.Element != symcr::kNoType &&
          Program.Types[Type.Element].Kind == symcr::Kind::Struct)
        writePointees(OS, Program, T);
      if (!Type.DynamicTypesReachedBy.empty()) {
        OS << "    heap objects behind a " << Type.Name
           << "* are saved as their class: ";
        for (std::size_t D = 0; D < Type.DynamicTypes.size(); ++D)
          OS << (D ? ", " : "") << Program.Types[Type.DynamicTypes[D]].Name;
        if (Type.DynamicTypes.empty())
          OS << "none; saving refuses them";
        OS << "\n";
        for (const std::string &Not : Type.NotDynamicTypes)
          OS << "    refused on the heap: " << Not << "\n";
      }
    }
    // A heading of their own: what the new build re-creates, which needs no
    // skip line.
    if (LeftCount) {
      OS << "  left to the new build (never restored, no annotation needed):\n";
      for (std::uint32_t T : Order)
        for (const TypeModel::LeftMember &Left :
             Program.Types[T].LeftToNewBuild)
          OS << "    " << Program.Types[T].Name << "::" << Left.Name << ": "
             << Left.Why << "\n";
    }
  }
  writeStateFlagWarnings(OS, Program);
  if (!Program.Clocks.empty()) {
    OS << "\nclocks (each checkpoint records their readings; a restore in "
          "another process "
          "moves their times by their advance):\n";
    for (const ClockModel &Clock : Program.Clocks)
      OS << "  " << Clock.Name << ": read by " << Clock.CallExpression << "\n";
  }
  return OS.str();
}

} // namespace symcr_gen
