//===- Clocks.cpp - Clocks and the times of their members
//------------------===//
//
// clock([name,] function) names a clock and the function that reads it;
// time(...) and SYMCR_TIME(...) mark a member, or every member of a typedef'd
// type, a time of a clock (generator/README.md, "Clocks"). Checkpoints record
// each clock's reading; a restore in another process moves the times by the
// clock's advance.
//
//===----------------------------------------------------------------------===//

#include "Clocks.h"

#include "AstQueries.h"
#include "NameIndex.h"
#include "TypeWalker.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/Decl.h"
#include "clang/AST/DeclCXX.h"
#include "clang/AST/RecursiveASTVisitor.h"
#include "llvm/ADT/StringRef.h"

#include <algorithm>

using namespace clang;

namespace symcr_gen {
namespace {

/// SYMCR_TIME(clock [, never=N]) on \p D, as "clock, never=N".
bool timeAnnotation(const Decl *D, TimeSpec &Out, std::string &Error,
                    bool &Found) {
  Found = false;
  for (const std::string &A : symcrAnnotations(D)) {
    llvm::StringRef Text(A);
    if (!Text.consume_front("time:"))
      continue;
    llvm::SmallVector<llvm::StringRef, 2> Parts;
    Text.split(Parts, ',');
    std::vector<std::string> Arguments;
    for (llvm::StringRef Part : Parts)
      Arguments.push_back(Part.trim().str());
    if (!parseTimeArguments(Arguments, Out, Error))
      return false;
    Found = true;
  }
  return true;
}

class ClockFunctionFinder : public RecursiveASTVisitor<ClockFunctionFinder> {
public:
  ClockFunctionFinder(const std::string &Name,
                      std::vector<const FunctionDecl *> &Out)
      : Name(Name), Out(Out) {}
  bool VisitFunctionDecl(FunctionDecl *FD) {
    if (NameIndex::qualifiedDeclName(FD) == Name)
      Out.push_back(FD);
    return true;
  }
  bool shouldVisitTemplateInstantiations() const { return false; }

private:
  const std::string &Name;
  std::vector<const FunctionDecl *> &Out;
};

/// Why \p FD cannot read a clock, or empty.
std::string whyNotAClock(const FunctionDecl *FD) {
  if (FD->getMinRequiredArguments() != 0)
    return "it takes arguments";
  if (const auto *Method = dyn_cast<CXXMethodDecl>(FD)) {
    if (!Method->isStatic())
      return "it is a non-static member function";
    if (Method->getAccess() != AS_public)
      return "it is not public";
  }
  if (FD->isDependentContext())
    return "it is a template";
  QualType Result = FD->getReturnType().getCanonicalType();
  if (!Result->isIntegerType() || Result->isBooleanType() ||
      Result->isEnumeralType())
    return "it does not return an integer (a clock's reading is an integer "
           "count of its "
           "unit)";
  return "";
}

} // namespace

bool TypeWalker::fieldTime(const FieldDecl *FD, const TimeSpec *Directive,
                           FieldModel &Field, const WalkContext &F) {
  // Every annotation that applies, first the member's own, then its type's
  // typedefs.
  std::vector<std::pair<TimeSpec, std::string>> Specs;
  std::string Error;
  bool Found = false;
  TimeSpec Spec;
  if (!timeAnnotation(FD, Spec, Error, Found)) {
    Sink->error(F.Where, "SYMCR_TIME on '" + F.Path + "': " + Error);
    return false;
  }
  if (Found)
    Specs.push_back({Spec, "SYMCR_TIME"});
  if (Directive)
    Specs.push_back({*Directive, "a time directive"});
  for (QualType T = FD->getType();;) {
    const Type *Ty = T.getTypePtr();
    if (const auto *Typedef = dyn_cast<TypedefType>(Ty)) {
      const TypedefNameDecl *TD = Typedef->getDecl();
      const std::string TypedefName = NameIndex::qualifiedDeclName(TD);
      if (!timeAnnotation(TD, Spec, Error, Found)) {
        Sink->error(locationOf(Context, TD->getLocation()),
                    "SYMCR_TIME on '" + TypedefName + "': " + Error);
        return false;
      }
      if (Found)
        Specs.push_back({Spec, "SYMCR_TIME on typedef '" + TypedefName + "'"});
      if (auto It = Select.TypedefTimes.find(TypedefName);
          It != Select.TypedefTimes.end())
        Specs.push_back({It->second, "time(" + TypedefName + ", ...)"});
      T = Typedef->desugar();
      continue;
    }
    if (const auto *Elaborated = dyn_cast<ElaboratedType>(Ty)) {
      T = Elaborated->getNamedType();
      continue;
    }
    if (const auto *Array = dyn_cast<ArrayType>(Ty)) {
      T = Array->getElementType();
      continue;
    }
    break;
  }
  if (Specs.empty())
    return true;
  for (const auto &Other : Specs)
    if (Other.first.Clock != Specs.front().first.Clock ||
        Other.first.Never != Specs.front().first.Never) {
      Sink->error(F.Where, "'" + F.Path + "' is a time of clock '" +
                               Specs.front().first.Clock + "' by " +
                               Specs.front().second + " and of clock '" +
                               Other.first.Clock + "' by " + Other.second +
                               " (or another never value): keep one");
      return false;
    }
  QualType Element =
      Context.getBaseElementType(FD->getType()).getCanonicalType();
  if (FD->isBitField() || !Element->isIntegerType() ||
      Element->isBooleanType() || Element->isEnumeralType()) {
    Sink->error(
        F.Where,
        "'" + F.Path + "' is marked a time of clock '" +
            Specs.front().first.Clock + "', but " +
            (FD->isBitField()
                 ? std::string("it is a bit-field")
                 : "its type is '" + FD->getType().getAsString(*Policy) + "'") +
            ": a time is an integer count of its clock's unit (or an array "
            "of them)");
    return false;
  }
  Field.Flags |= symcr::kFieldClockTime;
  Field.Clock = Specs.front().first.Clock;
  Field.Never = Specs.front().first.Never;
  Program.ClockUses.emplace(Field.Clock, F.Where);
  return true;
}

void declareClock(const Directive &D, ProgramModel &Program,
                  Diagnostics &Diags) {
  const std::string Function =
      llvm::StringRef(D.Arguments.back().Text).ltrim(':').str();
  // clock(millis) names the clock after its function; clock(ms, AP_HAL::millis)
  // names it.
  const std::string Name = D.Arguments[0].Text;
  auto It = std::find_if(Program.Clocks.begin(), Program.Clocks.end(),
                         [&](const ClockModel &C) { return C.Name == Name; });
  if (It == Program.Clocks.end()) {
    ClockModel Clock;
    Clock.Name = Name;
    Clock.Function = Function;
    Clock.Where = D.Where;
    auto At = std::lower_bound(
        Program.Clocks.begin(), Program.Clocks.end(), Name,
        [](const ClockModel &C, const std::string &N) { return C.Name < N; });
    Program.Clocks.insert(At, Clock);
    return;
  }
  if (It->Function != Function)
    Diags.error(D.Where, "clock '" + Name + "' is read by '" + It->Function +
                             "' (declared at " + It->Where.str() +
                             ") and by '" + Function +
                             "' here: a clock has one reading function");
}

void resolveClocks(ASTContext &Context, unsigned TUIndex, ProgramModel &Program,
                   Diagnostics &Diags) {
  if (Program.TranslationUnits[TUIndex].LibraryOnly)
    return;
  for (ClockModel &Clock : Program.Clocks) {
    if (Clock.HomeTU >= 0)
      continue;
    std::vector<const FunctionDecl *> Candidates;
    ClockFunctionFinder(Clock.Function, Candidates)
        .TraverseDecl(Context.getTranslationUnitDecl());
    if (Candidates.empty())
      continue;
    std::string Why;
    const FunctionDecl *Usable = nullptr;
    for (const FunctionDecl *FD : Candidates) {
      std::string Reason = whyNotAClock(FD);
      if (Reason.empty()) {
        Usable = FD;
        break;
      }
      if (Why.empty())
        Why =
            Reason + " (" + locationOf(Context, FD->getLocation()).str() + ")";
    }
    if (!Usable) {
      Diags.error(Clock.Where,
                  "'" + Clock.Function + "' cannot read clock '" + Clock.Name +
                      "': " + Why +
                      "; name a function that takes no arguments and returns "
                      "an integer");
      Clock.HomeTU = -2; // diagnosed
      continue;
    }
    Clock.HomeTU = static_cast<int>(TUIndex);
    // C has no scope operator; in C++ the global qualification keeps a
    // wrapper's own names out of the lookup.
    Clock.CallExpression = (Context.getLangOpts().CPlusPlus ? "::" : "") +
                           NameIndex::qualifiedDeclName(Usable) + "()";
    QualType Result = Usable->getReturnType().getCanonicalType();
    Clock.Unsigned64 =
        Result->isUnsignedIntegerType() && Context.getTypeSize(Result) == 64;
  }
}

void checkClocks(const ProgramModel &Program, Diagnostics &Diags) {
  for (const ClockModel &Clock : Program.Clocks)
    if (Clock.HomeTU == -1)
      Diags.error(Clock.Where, "clock '" + Clock.Name +
                                   "': no source declares its reading "
                                   "function '" +
                                   Clock.Function + "'");
  for (const auto &Use : Program.ClockUses) {
    bool Declared =
        std::any_of(Program.Clocks.begin(), Program.Clocks.end(),
                    [&](const ClockModel &C) { return C.Name == Use.first; });
    if (!Declared)
      Diags.error(Use.second,
                  "time of an undeclared clock '" + Use.first +
                      "': name its reading function once with 'clock(" +
                      Use.first + ")' (or clock(" + Use.first +
                      ", function)) in the annotation file, '#pragma symcr "
                      "clock(...)' or SYMCR_CLOCK(...)");
  }
}

} // namespace symcr_gen
