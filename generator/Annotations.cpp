//===- Annotations.cpp - Pragmas and the sidecar annotation file
//-----------===//

#include "Annotations.h"

#include <algorithm>

#include "clang/Basic/SourceManager.h"
#include "clang/Lex/Pragma.h"
#include "clang/Lex/Preprocessor.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/MemoryBuffer.h"
#include "llvm/Support/Path.h"
#include "llvm/Support/raw_ostream.h"
#include "symcr/format/payload.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace symcr_gen {

void Diagnostics::print(const Location &Loc, const char *Severity,
                        const std::string &Message) {
  std::string Line;
  if (Loc.valid())
    Line = Loc.File + ":" + std::to_string(Loc.Line) + ":" +
           std::to_string(Loc.Column) + ": ";
  else
    Line = "symcr-gen: ";
  Line += std::string(Severity) + ": " + Message;
  if (!Seen.emplace(Line, true).second)
    return;
  if (!Quiet && !ShownNotesFile.empty() && std::string(Severity) == "note") {
    HeldNotes.push_back(Line);
    return;
  }
  if (Quiet)
    Collected.push_back(Message);
  else
    llvm::errs() << Line << "\n";
}

void Diagnostics::releaseNotes() {
  std::vector<std::string> Notes;
  {
    std::lock_guard<std::mutex> Guard(Lock);
    Notes.swap(HeldNotes);
  }
  if (Notes.empty())
    return;
  // The file is shared by the generation steps that a parallel build runs at
  // once.
  int Fd = -1;
  if (!Errors) {
    llvm::StringRef Parent = llvm::sys::path::parent_path(ShownNotesFile);
    if (!Parent.empty())
      llvm::sys::fs::create_directories(Parent);
    Fd = ::open(ShownNotesFile.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  }
  if (Fd < 0 || ::flock(Fd, LOCK_EX) != 0) {
    if (Fd >= 0)
      ::close(Fd);
    for (const std::string &Line : Notes)
      llvm::errs() << Line << "\n";
    return;
  }
  std::string Shown;
  char Buffer[4096];
  for (ssize_t N; (N = ::read(Fd, Buffer, sizeof Buffer)) > 0;)
    Shown.append(Buffer, static_cast<std::size_t>(N));
  std::string Added;
  for (const std::string &Line : Notes) {
    if (("\n" + Shown).find("\n" + Line + "\n") != std::string::npos)
      continue;
    llvm::errs() << Line << "\n";
    Shown += Line + "\n";
    Added += Line + "\n";
  }
  // Appended where the read ended; should it fail, a later step prints the note
  // again.
  ssize_t Written = ::write(Fd, Added.data(), Added.size());
  (void)Written;
  ::close(Fd);
}

std::string Diagnostics::firstProblem() const {
  if (!Collected.empty())
    return Collected.front();
  for (const auto &Entry : Groups)
    if (!Entry.second.Leaves.empty())
      return Entry.second.Leaves.front().Message;
  return "";
}

void Diagnostics::error(const Location &Loc, const std::string &Message) {
  std::lock_guard<std::mutex> Guard(Lock);
  std::string Key = Loc.File + ":" + std::to_string(Loc.Line) + ":" +
                    std::to_string(Loc.Column) + Message;
  if (Seen.count("error " + Key))
    return;
  Seen.emplace("error " + Key, true);
  ++Errors;
  print(Loc, "error", Message);
}

void Diagnostics::warning(const Location &Loc, const std::string &Message) {
  std::lock_guard<std::mutex> Guard(Lock);
  print(Loc, "warning", Message);
}

void Diagnostics::note(const Location &Loc, const std::string &Message) {
  std::lock_guard<std::mutex> Guard(Lock);
  print(Loc, "note", Message);
}

void Diagnostics::unrestorable(const Location &Where,
                               const std::string &Message,
                               const std::string &LeafSkip,
                               const MemberRef *Group) {
  const std::string &Fix = Group ? Group->SkipHint : LeafSkip;
  {
    std::lock_guard<std::mutex> Guard(Lock);
    if (!Fix.empty() &&
        std::find(Fixes.begin(), Fixes.end(), Fix) == Fixes.end())
      Fixes.push_back(Fix);
    if (Group) {
      auto &Entry = Groups[Group->SkipHint];
      if (Entry.Member.empty())
        Entry.Member = *Group;
      for (const Leaf &Existing : Entry.Leaves)
        if (Existing.Message == Message)
          return; // the same leaf reached again (a header seen twice)
      Entry.Leaves.push_back(Leaf{Where, Message});
      return;
    }
  }
  std::string Text = Message;
  if (!LeafSkip.empty())
    Text += "; skip it: SYMCR_SKIP on the member, or '#pragma symcr skip(" +
            LeafSkip + ")'";
  error(Where, Text);
}

void Diagnostics::flushUnrestorable() {
  std::map<std::string, Group> Pending;
  std::vector<std::string> AllFixes;
  {
    std::lock_guard<std::mutex> Guard(Lock);
    Pending.swap(Groups);
    AllFixes = Fixes;
  }
  for (const auto &Entry : Pending) {
    const Group &G = Entry.second;
    error(G.Member.Where,
          std::to_string(G.Leaves.size()) +
              " unrestorable value(s) in an object reached through '" +
              G.Member.Path + "' (" + G.Member.SkipHint + ", type " +
              G.Member.TypeName + "): '#pragma symcr skip(" +
              G.Member.SkipHint + ")' (or 'skip(" + G.Member.SkipHint +
              ")' in the annotation file) removes all of them");
    for (const Leaf &L : G.Leaves)
      note(L.Where, L.Message);
  }
  if (AllFixes.empty() || Errors == 0)
    return;
  std::string List;
  for (const std::string &Fix : AllFixes)
    List += (List.empty() ? "skip(" : ", ") + Fix;
  note(Location(),
       "these skip lines remove every unrestorable value above: " + List + ")");
}

std::string inexactRangeBound(const std::string &Text, double Value) {
  llvm::StringRef Digits = llvm::StringRef(Text).trim();
  const bool Negative = Digits.consume_front("-");
  if (!Negative)
    Digits.consume_front("+");
  const unsigned Radix =
      Digits.consume_front("0x") || Digits.consume_front("0X") ? 16 : 10;
  unsigned long long Magnitude = 0;
  if (Digits.empty() || Digits.getAsInteger(Radix, Magnitude))
    return ""; // not an integer literal: a double as written
  const double Held = std::fabs(Value);
  if (symcr::format::compare_integer(Magnitude, false, Held) == 0)
    return "";
  // The two doubles around the literal: the one strtod chose and its neighbour.
  const bool RoundedDown =
      symcr::format::compare_integer(Magnitude, false, Held) > 0;
  const double Other = std::nextafter(Held, RoundedDown ? HUGE_VAL : 0.0);
  const double Low = RoundedDown ? Held : Other;
  const double High = RoundedDown ? Other : Held;
  char Nearest[128];
  std::snprintf(Nearest, sizeof Nearest, "%s%.0f or %s%.0f",
                Negative ? "-" : "", Negative ? High : Low, Negative ? "-" : "",
                Negative ? Low : High);
  return "range bound " + Text +
         " is not a number a double holds exactly (ranges hold doubles, so it "
         "would be another number): use " +
         Nearest;
}

bool parseTimeArguments(const std::vector<std::string> &Arguments,
                        TimeSpec &Out, std::string &Error) {
  if (Arguments.empty() || Arguments.size() > 2 || Arguments[0].empty() ||
      Arguments[0].find('=') != std::string::npos) {
    Error = "a time names its clock, and optionally never=N: (millis) or "
            "(millis, never=0)";
    return false;
  }
  Out.Clock = Arguments[0];
  Out.Never = 0;
  if (Arguments.size() == 2) {
    llvm::StringRef Never(Arguments[1]);
    Never = Never.trim();
    if (!Never.consume_front("never=")) {
      Error = "unexpected '" + Arguments[1] +
              "' in a time annotation (expected never=N)";
      return false;
    }
    Never = Never.trim();
    bool Negative = Never.consume_front("-");
    unsigned long long Value = 0;
    if (Never.getAsInteger(0, Value) || (Negative && Value > (1ull << 63))) {
      Error = "never=" + Never.str() + " is not an integer";
      return false;
    }
    Out.Never = Negative ? static_cast<std::int64_t>(0ull - Value)
                         : static_cast<std::int64_t>(Value);
  }
  return true;
}

static bool directiveKindFromName(const std::string &Name,
                                  DirectiveKind &Kind) {
  if (Name == "checkpoint")
    Kind = DirectiveKind::Checkpoint;
  else if (Name == "skip")
    Kind = DirectiveKind::Skip;
  else if (Name == "renamed")
    Kind = DirectiveKind::Renamed;
  else if (Name == "include")
    Kind = DirectiveKind::Include;
  else if (Name == "range")
    Kind = DirectiveKind::Range;
  else if (Name == "checkpoint_at")
    Kind = DirectiveKind::CheckpointAt;
  else if (Name == "restore_at")
    Kind = DirectiveKind::RestoreAt;
  else if (Name == "store")
    Kind = DirectiveKind::Store;
  else if (Name == "clock")
    Kind = DirectiveKind::Clock;
  else if (Name == "time")
    Kind = DirectiveKind::Time;
  else if (Name == "not_owner")
    Kind = DirectiveKind::NotOwner;
  else if (Name == "restores_alone")
    Kind = DirectiveKind::RestoresAlone;
  else
    return false;
  return true;
}

static bool isNameChar(char C) {
  return std::isalnum(static_cast<unsigned char>(C)) || C == '_' || C == ':' ||
         C == '<' || C == '>' || C == ',' || C == '*' || C == ' ';
}

/// The directive as one writes it, whatever the spacing (a macro's tokens
/// arrive spaced apart): a space only between two words and after commas.
static std::string normalizedSpelling(const std::string &Text) {
  auto IsWord = [](char C) {
    return std::isalnum(static_cast<unsigned char>(C)) || C == '_';
  };
  std::string Out;
  bool InQuotes = false;
  bool PendingSpace = false;
  for (char C : Text) {
    if (InQuotes) {
      Out += C;
      InQuotes = C != '"';
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(C))) {
      PendingSpace = true;
      continue;
    }
    if (PendingSpace && !Out.empty() && IsWord(Out.back()) && IsWord(C))
      Out += ' ';
    PendingSpace = false;
    Out += C;
    InQuotes = C == '"';
    if (C == ',')
      Out += ' ';
  }
  return Out;
}

bool parseDirectiveText(const std::string &Text, const Location &Where,
                        bool FromSidecar, std::vector<Directive> &Out,
                        Diagnostics &Diags) {
  auto At = [&](std::size_t Index) {
    Location L = Where;
    L.Column += static_cast<unsigned>(Index);
    return L;
  };
  std::size_t I = 0;
  auto SkipSpace = [&] {
    while (I < Text.size() && std::isspace(static_cast<unsigned char>(Text[I])))
      ++I;
  };
  SkipSpace();
  std::size_t NameBegin = I;
  while (I < Text.size() &&
         (std::isalnum(static_cast<unsigned char>(Text[I])) || Text[I] == '_'))
    ++I;
  std::string Name = Text.substr(NameBegin, I - NameBegin);
  Directive D;
  D.FromSidecar = FromSidecar;
  D.Where = At(NameBegin);
  if (!directiveKindFromName(Name, D.Kind)) {
    Diags.error(
        At(NameBegin),
        "unknown symcr directive '" + Name +
            "' (expected checkpoint, skip, renamed, include, range, "
            "checkpoint_at, restore_at, store, clock, time, not_owner or "
            "restores_alone)");
    return false;
  }
  SkipSpace();
  if (I >= Text.size() || Text[I] != '(') {
    Diags.error(At(I), "expected '(' after '" + Name + "'");
    return false;
  }
  ++I;
  // Arguments are separated by commas outside template angle brackets and
  // quotes; whitespace is dropped outside quotes.
  int AngleDepth = 0;
  bool InQuotes = false;
  std::string Current;
  std::size_t CurrentBegin = I;
  bool Closed = false;
  auto Flush = [&]() {
    std::size_t Lead = 0;
    while (CurrentBegin + Lead < Text.size() &&
           std::isspace(static_cast<unsigned char>(Text[CurrentBegin + Lead])))
      ++Lead;
    D.Arguments.push_back({Current, At(CurrentBegin + Lead)});
    Current.clear();
  };
  for (; I < Text.size(); ++I) {
    char C = Text[I];
    if (InQuotes) {
      Current += C;
      InQuotes = C != '"';
      continue;
    }
    if (C == '"') {
      InQuotes = true;
      Current += C;
      continue;
    }
    if (C == '<')
      ++AngleDepth;
    else if (C == '>')
      --AngleDepth;
    if (C == ')' && AngleDepth == 0) {
      Flush();
      Closed = true;
      ++I;
      break;
    }
    if (C == ',' && AngleDepth == 0) {
      Flush();
      CurrentBegin = I + 1;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(C)))
      continue;
    if (!isNameChar(C) && C != '.' && C != '-' && C != '+' && C != '=' &&
        C != '/') {
      Diags.error(At(I), std::string("unexpected character '") + C +
                             "' in symcr directive");
      return false;
    }
    Current += C;
  }
  if (!Closed) {
    Diags.error(At(Text.size()), "expected ')' to end the symcr directive");
    return false;
  }
  D.Spelling = normalizedSpelling(Text.substr(NameBegin, I - NameBegin));
  SkipSpace();
  if (I < Text.size()) {
    Diags.error(At(I), "unexpected text after the symcr directive");
    return false;
  }
  for (DirectiveArgument &A : D.Arguments) {
    if (A.Text.size() >= 2 && A.Text.front() == '"' && A.Text.back() == '"')
      A.Text = A.Text.substr(1, A.Text.size() - 2);
    if (A.Text.empty()) {
      Diags.error(A.Where, "empty argument in symcr directive");
      return false;
    }
  }
  if (D.Kind == DirectiveKind::Checkpoint && D.Arguments.size() > 1 &&
      D.Arguments.back().Text == "shallow") {
    D.Shallow = true;
    D.Arguments.pop_back();
  }
  if (D.Kind == DirectiveKind::Renamed && D.Arguments.size() != 2) {
    Diags.error(D.Where, "renamed(...) takes two arguments: the new name "
                         "(Type::field, Type or variable) and the old name");
    return false;
  }
  if (D.Kind == DirectiveKind::Clock &&
      (D.Arguments.empty() || D.Arguments.size() > 2)) {
    Diags.error(
        D.Where,
        "clock(...) takes the clock's reading function, or a name and the "
        "function: clock(millis) or clock(ms, AP_HAL::millis)");
    return false;
  }
  if (D.Kind == DirectiveKind::Time) {
    std::vector<std::string> Rest;
    for (std::size_t A = 1; A < D.Arguments.size(); ++A)
      Rest.push_back(D.Arguments[A].Text);
    TimeSpec Spec;
    std::string Error;
    if (D.Arguments.size() < 2 || !parseTimeArguments(Rest, Spec, Error)) {
      Diags.error(
          D.Where,
          Error.empty()
              ? "time(...) takes the member (Type::field) or typedef, the "
                "clock, and optionally never=N: time(Vehicle::last_ms, "
                "millis)"
              : Error);
      return false;
    }
  }
  if (D.Kind == DirectiveKind::Range) {
    if (D.Arguments.size() != 3) {
      Diags.error(D.Where, "range(...) takes three arguments: the member "
                           "(Type::field) and the bounds lo and hi");
      return false;
    }
    double Bounds[2];
    for (int B = 0; B < 2; ++B) {
      const DirectiveArgument &A = D.Arguments[1 + B];
      char *End = nullptr;
      Bounds[B] = std::strtod(A.Text.c_str(), &End);
      if (*End != '\0') {
        Diags.error(A.Where, "range bound '" + A.Text + "' is not a number");
        return false;
      }
      const std::string Inexact = inexactRangeBound(A.Text, Bounds[B]);
      if (!Inexact.empty()) {
        Diags.error(A.Where, Inexact);
        return false;
      }
    }
    if (!(Bounds[0] <= Bounds[1])) { // NaN too
      Diags.error(D.Arguments[1].Where, "range(...) needs lo <= hi, got '" +
                                            D.Arguments[1].Text + "' and '" +
                                            D.Arguments[2].Text + "'");
      return false;
    }
  }
  Out.push_back(std::move(D));
  return true;
}

bool parseSidecarFile(const std::string &Path, std::vector<Directive> &Out,
                      Diagnostics &Diags) {
  auto Buffer = llvm::MemoryBuffer::getFile(Path);
  if (!Buffer) {
    Diags.error(Location(), "cannot read annotation file '" + Path +
                                "': " + Buffer.getError().message());
    return false;
  }
  llvm::StringRef Content = (*Buffer)->getBuffer();
  bool Ok = true;
  unsigned LineNumber = 0;
  while (!Content.empty()) {
    auto Split = Content.split('\n');
    Content = Split.second;
    ++LineNumber;
    std::string Line = Split.first.str();
    if (auto Comment = Line.find("//"); Comment != std::string::npos)
      Line.resize(Comment);
    std::size_t Begin = 0;
    while (Begin < Line.size() &&
           std::isspace(static_cast<unsigned char>(Line[Begin])))
      ++Begin;
    if (Begin == Line.size())
      continue;
    llvm::StringRef Rest(Line.data() + Begin, Line.size() - Begin);
    if (Rest.startswith("#pragma")) {
      std::size_t Skip = Begin + 7;
      while (Skip < Line.size() &&
             std::isspace(static_cast<unsigned char>(Line[Skip])))
        ++Skip;
      if (llvm::StringRef(Line).substr(Skip).startswith("symcr")) {
        Begin = Skip + 5;
      } else {
        Diags.error({Path, LineNumber, static_cast<unsigned>(Skip + 1)},
                    "expected 'symcr' after '#pragma' in an annotation file");
        Ok = false;
        continue;
      }
    } else if (Rest.startswith("#")) {
      continue; // a comment line
    }
    Location Where{Path, LineNumber, static_cast<unsigned>(Begin + 1)};
    Ok &= parseDirectiveText(Line.substr(Begin), Where, /*FromSidecar=*/true,
                             Out, Diags);
  }
  return Ok;
}

namespace {

/// Handles `#pragma symcr <directive>(...)` by re-spelling its tokens and
/// parsing them like a sidecar line, keeping the pragma's own location.
class SymcrPragmaHandler : public clang::PragmaHandler {
public:
  SymcrPragmaHandler(std::vector<Directive> &Out, Diagnostics &Diags)
      : clang::PragmaHandler("symcr"), Out(Out), Diags(Diags) {}

  void HandlePragma(clang::Preprocessor &PP, clang::PragmaIntroducer,
                    clang::Token &FirstToken) override {
    clang::SourceManager &SM = PP.getSourceManager();
    clang::Token Tok;
    PP.Lex(Tok);
    if (Tok.is(clang::tok::eod))
      return;
    clang::PresumedLoc Start = SM.getPresumedLoc(Tok.getLocation());
    (void)FirstToken;
    // Rebuild the text with each token at its column so that argument
    // locations point into the source line.
    std::string Text;
    unsigned StartColumn = Start.isValid() ? Start.getColumn() : 1;
    while (Tok.isNot(clang::tok::eod)) {
      clang::PresumedLoc P = SM.getPresumedLoc(Tok.getLocation());
      unsigned Column = P.isValid() && P.getLine() == Start.getLine()
                            ? P.getColumn()
                            : StartColumn + static_cast<unsigned>(Text.size());
      std::size_t Wanted = Column > StartColumn ? Column - StartColumn : 0;
      if (Text.size() < Wanted)
        Text.append(Wanted - Text.size(), ' ');
      else if (Text.size() > Wanted)
        Text += ' '; // tokens from a macro expansion: keep them apart
      Text += PP.getSpelling(Tok);
      PP.Lex(Tok);
    }
    Location Where;
    if (Start.isValid())
      Where = {Start.getFilename(), Start.getLine(), StartColumn};
    parseDirectiveText(Text, Where, /*FromSidecar=*/false, Out, Diags);
  }

private:
  std::vector<Directive> &Out;
  Diagnostics &Diags;
};

} // namespace

std::unique_ptr<clang::PragmaHandler>
createPragmaHandler(std::vector<Directive> &Out, Diagnostics &Diags) {
  return std::make_unique<SymcrPragmaHandler>(Out, Diags);
}

} // namespace symcr_gen
