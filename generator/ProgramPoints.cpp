//===- ProgramPoints.cpp - checkpoint_at / restore_at points
//---------------===//

#include "ProgramPoints.h"
#include "EmitSupport.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/RecursiveASTVisitor.h"
#include "clang/Basic/SourceManager.h"
#include "llvm/Support/Path.h"

#include <algorithm>
#include <cstdlib>
#include <set>
#include <sstream>

using namespace clang;

namespace symcr_gen {

bool isPointDirective(const Directive &D) {
  return D.Kind == DirectiveKind::CheckpointAt ||
         D.Kind == DirectiveKind::RestoreAt || D.Kind == DirectiveKind::Store;
}

namespace {

/// The crash-loop fallback is on unless the store directive says
/// fallback_depth=0: a restored state that crashes the program is passed over
/// at the next start, down to this many older checkpoints, then the initial
/// state.
constexpr unsigned DefaultFallbackDepth = 2;
/// Checkpoint points reached after a restore that confirm it, unless the store
/// directive says confirm_after=N.
constexpr unsigned DefaultConfirmAfter = 10;
/// Slots the fallback keeps beside its depth: the restored checkpoint and one
/// to save into while the restore waits for its confirmation.
constexpr unsigned FallbackSpareSlots = 2;

std::string locationKey(const Location &L) {
  return L.File + ":" + std::to_string(L.Line) + ":" + std::to_string(L.Column);
}

/// "slots=4" -> ("slots", "4"); "strict" -> ("strict", "").
std::pair<std::string, std::string> option(const std::string &Text) {
  std::size_t Equals = Text.find('=');
  if (Equals == std::string::npos)
    return {Text, ""};
  return {Text.substr(0, Equals), Text.substr(Equals + 1)};
}

bool parseCount(const std::string &Text, unsigned &Out) {
  if (Text.empty() || Text.size() > 9 ||
      !std::all_of(Text.begin(), Text.end(),
                   [](char C) { return C >= '0' && C <= '9'; }))
    return false;
  Out = static_cast<unsigned>(std::strtoul(Text.c_str(), nullptr, 10));
  return Out > 0;
}

/// As parseCount, and 0 too (fallback_depth=0 turns the fallback off).
bool parseCountOrZero(const std::string &Text, unsigned &Out) {
  if (Text == "0") {
    Out = 0;
    return true;
  }
  return parseCount(Text, Out);
}

/// Finds the definitions (and declarations) of the points' functions.
class FunctionFinder : public RecursiveASTVisitor<FunctionFinder> {
public:
  explicit FunctionFinder(std::vector<FunctionDecl *> &Out) : Out(Out) {}
  bool VisitFunctionDecl(FunctionDecl *FD) {
    Out.push_back(FD);
    return true;
  }

private:
  std::vector<FunctionDecl *> &Out;
};

std::string describePoint(const PointModel &P) {
  return std::string(P.Restore ? "restore" : "checkpoint") + " at " +
         (P.AtExit ? "exit of " : "entry of ") + P.Function;
}

} // namespace

ProgramPoints::ProgramPoints(ProgramModel &Program, Diagnostics &Diags,
                             const std::vector<Directive> &Sidecar)
    : Program(Program), Diags(Diags) {
  for (const Directive &D : Sidecar)
    if (isPointDirective(D))
      addDirective(D);
}

void ProgramPoints::addDirective(const Directive &D) {
  if (!SeenDirectives.emplace(locationKey(D.Where), true).second)
    return; // a header's pragma, seen again by another TU
  if (D.Kind == DirectiveKind::Store) {
    PointStoreModel Store;
    Store.Spelling = D.Spelling;
    Store.Where = D.Where;
    Store.Path = D.Arguments[0].Text;
    bool DepthGiven = false;
    for (std::size_t I = 1; I < D.Arguments.size(); ++I) {
      const DirectiveArgument &A = D.Arguments[I];
      auto Option = option(A.Text);
      if (Option.first == "slots" && parseCount(Option.second, Store.Slots))
        continue;
      if (Option.first == "slot_size" &&
          parseCount(Option.second, Store.SlotSize))
        continue;
      if (Option.first == "durability" &&
          (Option.second == "page_cache" || Option.second == "fdatasync")) {
        Store.Fdatasync = Option.second == "fdatasync";
        continue;
      }
      if (Option.first == "fallback_depth" &&
          parseCountOrZero(Option.second, Store.FallbackDepth)) {
        DepthGiven = true;
        continue;
      }
      if (Option.first == "confirm_after" &&
          parseCount(Option.second, Store.ConfirmAfter))
        continue;
      Diags.error(A.Where,
                  "unknown store option '" + A.Text +
                      "' (expected slots=N, slot_size=BYTES, "
                      "durability=page_cache|fdatasync, fallback_depth=N or "
                      "confirm_after=N)");
      return;
    }
    if (!DepthGiven) {
      // On by default, as deep as the slots the directive gives leave room for
      // (saves go on while a restore waits for its confirmation).
      Store.FallbackDepth = DefaultFallbackDepth;
      if (Store.Slots != 0)
        Store.FallbackDepth =
            std::min(Store.FallbackDepth, Store.Slots > FallbackSpareSlots
                                              ? Store.Slots - FallbackSpareSlots
                                              : 0u);
      Store.FallbackDefault = true;
    }
    if (Store.ConfirmAfter != 0 && Store.FallbackDepth == 0) {
      Diags.error(
          D.Where,
          DepthGiven
              ? "confirm_after=N confirms the restores of the crash-loop "
                "fallback, which fallback_depth=0 turns off"
              : "confirm_after=N confirms the restores of the crash-loop "
                "fallback, for which slots=" +
                    std::to_string(Store.Slots) +
                    " leaves no room: give fallback_depth=N (the "
                    "store keeps N + 2 slots' worth until the "
                    "confirmation) or more slots");
      return;
    }
    // A restore proves itself over this many checkpoints unless told otherwise.
    if (Store.FallbackDepth != 0 && Store.ConfirmAfter == 0)
      Store.ConfirmAfter = DefaultConfirmAfter;
    PointStoreModel &Current = Program.PointStore;
    if (!Current.Where.valid()) {
      Current = Store;
    } else if (Current.Path != Store.Path || Current.Slots != Store.Slots ||
               Current.SlotSize != Store.SlotSize ||
               Current.Fdatasync != Store.Fdatasync ||
               Current.FallbackDepth != Store.FallbackDepth ||
               Current.ConfirmAfter != Store.ConfirmAfter) {
      Diags.error(D.Where,
                  "a second, different store directive: every point of "
                  "a program uses one store, given at " +
                      locationKey(Current.Where));
    }
    return;
  }

  PointModel P;
  P.Restore = D.Kind == DirectiveKind::RestoreAt;
  P.Spelling = D.Spelling;
  P.Where = D.Where;
  const char *Name = P.Restore ? "restore_at" : "checkpoint_at";
  if (D.Arguments.size() < 2) {
    Diags.error(D.Where, std::string(Name) +
                             "(...) takes the function and where in it: "
                             "entry or exit, e.g. '" +
                             Name + "(Copter::fast_loop, exit)'");
    return;
  }
  P.Function = D.Arguments[0].Text;
  if (llvm::StringRef(P.Function).startswith("::"))
    P.Function = P.Function.substr(2);
  const DirectiveArgument &Where = D.Arguments[1];
  if (Where.Text != "entry" && Where.Text != "exit") {
    Diags.error(Where.Where, "expected 'entry' or 'exit' after the function "
                             "name, got '" +
                                 Where.Text + "'");
    return;
  }
  P.AtExit = Where.Text == "exit";
  for (std::size_t I = 2; I < D.Arguments.size(); ++I) {
    const DirectiveArgument &A = D.Arguments[I];
    auto Option = option(A.Text);
    // "every 10" reaches here as "every10" (whitespace is dropped).
    if (!P.Restore && llvm::StringRef(A.Text).startswith("every")) {
      std::string Count = A.Text.substr(5);
      if (!Count.empty() && Count[0] == '=')
        Count = Count.substr(1);
      if (parseCount(Count, P.Every))
        continue;
    }
    if (P.Restore && Option.first == "on_failure" &&
        (Option.second == "continue" || Option.second == "stop")) {
      P.StopOnFailure = Option.second == "stop";
      continue;
    }
    if (P.Restore && A.Text == "strict") {
      P.Strict = true;
      continue;
    }
    Diags.error(A.Where,
                "unknown " + std::string(Name) + " option '" + A.Text + "' " +
                    (P.Restore ? "(expected on_failure=continue|stop or strict)"
                               : "(expected 'every N', N > 0)"));
    return;
  }
  Program.Points.push_back(std::move(P));
  Declared.push_back(false);
  DefinedInHeader.emplace_back();
  Refused.push_back(false);
}

void ProgramPoints::addTranslationUnit(
    ASTContext &Context, unsigned TUIndex,
    const std::vector<Directive> &Pragmas,
    const std::vector<ResolvedInclude> &Includes) {
  for (const Directive &D : Pragmas)
    if (isPointDirective(D))
      addDirective(D);
  if (Program.Points.empty())
    return;
  TranslationUnitModel &TU = Program.TranslationUnits[TUIndex];
  if (TU.LibraryOnly)
    return;
  std::vector<FunctionDecl *> Functions;
  FunctionFinder(Functions).TraverseDecl(Context.getTranslationUnitDecl());
  const SourceManager &SM = Context.getSourceManager();
  auto Describe = [&](SourceLocation L) {
    PresumedLoc P = SM.getPresumedLoc(SM.getExpansionLoc(L));
    return P.isValid() ? std::string(P.getFilename()) + ":" +
                             std::to_string(P.getLine()) + ":" +
                             std::to_string(P.getColumn())
                       : std::string("<unknown>");
  };
  bool Inserted = false;
  for (FunctionDecl *FD : Functions) {
    const std::string Name = FD->getQualifiedNameAsString();
    for (unsigned I = 0; I < Program.Points.size(); ++I) {
      PointModel &P = Program.Points[I];
      if (P.Function != Name)
        continue;
      Declared[I] = true;
      if (!FD->doesThisDeclarationHaveABody())
        continue;
      if (FD->isDependentContext() || FD->isTemplateInstantiation()) {
        Diags.error(P.Where, "'" + P.Function +
                                 "' is a template: points are "
                                 "inserted in functions only (defined at " +
                                 Describe(FD->getLocation()) + ")");
        Refused[I] = true;
        continue;
      }
      auto *Body = dyn_cast_or_null<CompoundStmt>(FD->getBody());
      if (!Body) {
        Diags.error(P.Where, "'" + P.Function + "' has a function-try-block (" +
                                 Describe(FD->getLocation()) +
                                 "): a point cannot be inserted there");
        Refused[I] = true;
        continue;
      }
      SourceLocation Brace = Body->getLBracLoc();
      if (Brace.isMacroID()) {
        Diags.error(P.Where, "the body of '" + P.Function +
                                 "' comes from a macro (" + Describe(Brace) +
                                 "): a point cannot be inserted there");
        Refused[I] = true;
        continue;
      }
      if (!SM.isWrittenInMainFile(Brace)) {
        DefinedInHeader[I] = Describe(Brace);
        continue;
      }
      SourceEdit Edit;
      Edit.Offset = SM.getFileOffset(Brace) + 1;
      Edit.IsPoint = true;
      Edit.Point = I;
      TU.Edits.push_back(Edit);
      std::string At = Describe(Brace);
      if (std::find(P.InsertedAt.begin(), P.InsertedAt.end(), At) ==
          P.InsertedAt.end())
        P.InsertedAt.push_back(At);
      Inserted = true;
    }
  }
  if (!Inserted)
    return;
  TU.SourceText = SM.getBufferData(SM.getMainFileID()).str();
  for (const ResolvedInclude &Include : Includes) {
    SourceEdit Edit;
    Edit.Offset = Include.Offset;
    Edit.Length = Include.Length;
    Edit.Text = quoted(Include.File);
    TU.Edits.push_back(Edit);
  }
}

void ProgramPoints::finish(bool CheckUnmatched) {
  if (!Program.Points.empty() && !Program.PointStore.Where.valid())
    Diags.error(
        Program.Points.front().Where,
        "program points need a store: add a directive such as "
        "'store(\"state.store\", slots=4)' (the SYMCR_STORE environment "
        "variable may replace its path at run time)");
  if (!CheckUnmatched)
    return;
  for (unsigned I = 0; I < Program.Points.size(); ++I) {
    const PointModel &P = Program.Points[I];
    if (!P.InsertedAt.empty() || Refused[I])
      continue;
    if (!DefinedInHeader[I].empty())
      Diags.error(P.Where, "'" + P.Function + "' is defined in a header (" +
                               DefinedInHeader[I] +
                               "), which symcr-gen does not copy: define it "
                               "in one of the target's sources");
    else if (Declared[I])
      Diags.error(P.Where, "'" + P.Function +
                               "' is declared but never defined in the "
                               "target's sources: a point needs the "
                               "function's body");
    else
      Diags.error(P.Where, "'" + P.Function +
                               "' names no function in the target's sources "
                               "(write it qualified, as 'Class::function' or "
                               "'ns::function')");
  }
}

std::string emitPointStoreDefinition(const ProgramModel &Program) {
  if (Program.Points.empty())
    return "";
  const PointStoreModel &Store = Program.PointStore;
  std::ostringstream OS;
  OS << "#include <symcr/points.h>\n\n"
     << "// The store of the program points (their store directive).\n"
     << "extern \"C\" const struct symcr_point_store "
        "symcr_program_point_store = {"
     << quoted(Store.Path) << ", " << Store.Slots << "u, " << Store.SlotSize
     << "u, " << (Store.Fdatasync ? 1 : 0) << ", " << Store.FallbackDepth
     << "u, " << Store.ConfirmAfter << "u};\n";
  return OS.str();
}

std::string emitPointedCopy(const ProgramModel &Program, unsigned TUIndex) {
  const TranslationUnitModel &TU = Program.TranslationUnits[TUIndex];
  std::ostringstream OS;
  OS << "/* Generated by symcr-gen from " << TU.Source
     << ": the source with its program points\n"
        " * (checkpoint_at, restore_at) inserted. Do not edit. */\n"
     << "#include <symcr/points.h>\n";
  std::vector<SourceEdit> Edits = TU.Edits;
  std::set<unsigned> Defined;
  const std::string FileName = llvm::sys::path::filename(TU.Source).str();
  for (const SourceEdit &Edit : Edits) {
    if (!Edit.IsPoint || !Defined.insert(Edit.Point).second)
      continue;
    const PointModel &P = Program.Points[Edit.Point];
    unsigned Line = 1;
    for (unsigned I = 0; I < Edit.Offset && I < TU.SourceText.size(); ++I)
      Line += TU.SourceText[I] == '\n';
    OS << "static struct symcr_point symcr_gen_point_" << Edit.Point << " = {"
       << quoted(P.Spelling) << ", "
       << quoted(FileName + ":" + std::to_string(Line) + ": " +
                 describePoint(P))
       << ", " << (P.Restore ? "SYMCR_POINT_RESTORE" : "SYMCR_POINT_CHECKPOINT")
       << ", "
       << (P.StopOnFailure ? "SYMCR_POINT_STOP" : "SYMCR_POINT_CONTINUE")
       << ", " << (P.Strict ? 1 : 0) << ", " << P.Every
       << "u, &symcr_program_point_store, 0};\n";
  }
  // Exit guards first: in C a declaration then precedes the entry calls.
  std::stable_sort(Edits.begin(), Edits.end(),
                   [&](const SourceEdit &A, const SourceEdit &B) {
                     if (A.Offset != B.Offset)
                       return A.Offset < B.Offset;
                     bool ExitA = A.IsPoint && Program.Points[A.Point].AtExit;
                     bool ExitB = B.IsPoint && Program.Points[B.Point].AtExit;
                     return ExitA && !ExitB;
                   });
  OS << "#line 1 " << quoted(TU.Source) << "\n";
  unsigned Done = 0;
  for (const SourceEdit &Edit : Edits) {
    OS << TU.SourceText.substr(Done, Edit.Offset - Done);
    Done = Edit.Offset + Edit.Length;
    if (!Edit.IsPoint) {
      OS << Edit.Text;
      continue;
    }
    // On the brace's line, so that every line keeps its number.
    const std::string Point = "symcr_gen_point_" + std::to_string(Edit.Point);
    if (!Program.Points[Edit.Point].AtExit)
      OS << " symcr_point_reached(&" << Point << ");";
    else if (TU.IsC)
      OS << " struct symcr_point* symcr_gen_exit_" << Edit.Point
         << " __attribute__((cleanup(symcr_point_at_scope_exit))) = &" << Point
         << ";";
    else
      OS << " ::symcr::generated::PointAtExit symcr_gen_exit_" << Edit.Point
         << "(&" << Point << ");";
  }
  OS << TU.SourceText.substr(Done);
  return OS.str();
}

std::string renderPointsReport(const ProgramModel &Program) {
  if (Program.Points.empty())
    return "";
  const PointStoreModel &Store = Program.PointStore;
  std::ostringstream OS;
  OS << "program points (store " << quoted(Store.Path) << ", "
     << (Store.Slots ? std::to_string(Store.Slots) : std::string("default"))
     << " slots of "
     << (Store.SlotSize ? std::to_string(Store.SlotSize) + " bytes"
                        : std::string("the default size"))
     << (Store.Fdatasync ? ", fdatasync" : "");
  if (Store.FallbackDepth != 0)
    OS << ", crash-loop fallback depth " << Store.FallbackDepth
       << (Store.FallbackDefault ? " (the default)" : "")
       << ", a restore confirmed after " << Store.ConfirmAfter
       << (Store.ConfirmAfter == 1 ? " checkpoint" : " checkpoints");
  else if (Store.FallbackDefault)
    OS << ", crash-loop fallback off: slots=" << Store.Slots
       << " leaves no room for it (give fallback_depth=N and N + 2 slots)";
  else
    OS << ", crash-loop fallback off (fallback_depth=0)";
  OS << "):\n";
  for (const PointModel &P : Program.Points) {
    OS << "  " << P.Spelling << " (" << locationKey(P.Where) << ")\n";
    for (const std::string &At : P.InsertedAt)
      OS << "    " << describePoint(P) << ": inserted at " << At
         << (P.AtExit ? " (every return path)" : "") << "\n";
  }
  return OS.str();
}

} // namespace symcr_gen
