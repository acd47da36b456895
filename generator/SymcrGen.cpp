//===- SymcrGen.cpp - symcr-gen: the checkpoint code generator
//-------------===//
//
// Parses the target's sources with Clang (flags from compile_commands.json or
// after `--`, like clang-tidy), collects the symcr annotations, and writes the
// schema source, one wrapper per source, a depfile and an optional report.
// See generator/README.md for the design.
//
//===----------------------------------------------------------------------===//

#include "Annotations.h"
#include "CompileCommand.h"
#include "DeviceProfile.h"
#include "PreviousPlans.h"
#include "Emitter.h"
#include "ModelParts.h"
#include "ProgramPoints.h"
#include "SchemaBuilder.h"
#include "SchemaFile.h"

#include "clang/Driver/Options.h"
#include "clang/Frontend/CompilerInstance.h"
#include "clang/Frontend/FrontendActions.h"
#include "clang/Frontend/Utils.h"
#include "clang/Lex/PPCallbacks.h"
#include "clang/Lex/Preprocessor.h"
#include "clang/Sema/SemaConsumer.h"
#include "clang/Tooling/ArgumentsAdjusters.h"
#include "clang/Tooling/CommonOptionsParser.h"
#include "clang/Tooling/Tooling.h"
#include "llvm/Option/ArgList.h"
#include "llvm/Option/OptTable.h"
#include "llvm/Support/CommandLine.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/Path.h"
#include "llvm/Support/VirtualFileSystem.h"
#include "llvm/Support/raw_ostream.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <set>
#include <thread>

#ifndef SYMCR_CLANG_RESOURCE_DIR
#error "SYMCR_CLANG_RESOURCE_DIR must name Clang's resource directory"
#endif

using namespace clang;
using namespace clang::tooling;
using namespace symcr_gen;

static llvm::cl::OptionCategory Category("symcr-gen options");
static llvm::cl::extrahelp CommonHelp(CommonOptionsParser::HelpMessage);
static llvm::cl::extrahelp MoreHelp(
    "\nWrites <out-dir>/symcr_schema.cpp and, per source N, a wrapper\n"
    "<out-dir>/tu<N>_<file name> that includes the source and adds what needs "
    "its\n"
    "declarations. The build compiles the wrappers instead of the sources.\n");

static llvm::cl::opt<std::string>
    OutDir("out-dir", llvm::cl::desc("Directory for generated sources"),
           llvm::cl::value_desc("dir"), llvm::cl::cat(Category));
static llvm::cl::list<std::string>
    AnnotationFiles("annotations",
                    llvm::cl::desc("Sidecar annotation file (repeatable)"),
                    llvm::cl::value_desc("file"), llvm::cl::cat(Category));
static llvm::cl::opt<std::string> SchemaFile(
    "schema-file",
    llvm::cl::desc("Write the build's schema file (for `symcr plan --schema`)"),
    llvm::cl::value_desc("file"), llvm::cl::cat(Category));
static llvm::cl::opt<std::string> ProgramName(
    "program",
    llvm::cl::desc(
        "The program's name, written into its checkpoints: a restore refuses a "
        "checkpoint of another program (default: none, accepted by any)"),
    llvm::cl::value_desc("name"), llvm::cl::cat(Category));
static llvm::cl::list<std::string> PreviousSchemas(
    "previous-schema",
    llvm::cl::desc("The schema file of an earlier build whose checkpoints this "
                   "build restores: planned now and embedded, so that restore "
                   "does not plan (repeatable)"),
    llvm::cl::value_desc("file"), llvm::cl::cat(Category));
static llvm::cl::list<std::string> LibrarySources(
    "library-source",
    llvm::cl::desc("A source of a static library the program links: a root "
                   "defined there is an error (repeatable)"),
    llvm::cl::value_desc("file"), llvm::cl::cat(Category));
static llvm::cl::opt<std::string>
    Depfile("depfile", llvm::cl::desc("Write a Makefile-style depfile"),
            llvm::cl::value_desc("file"), llvm::cl::cat(Category));
static llvm::cl::opt<std::string> DepfileTarget(
    "depfile-target",
    llvm::cl::desc("Output named in the depfile (default: the schema source)"),
    llvm::cl::cat(Category));
static llvm::cl::opt<bool>
    Report("report",
           llvm::cl::desc("Print, per root, what it reaches and skips"),
           llvm::cl::cat(Category));
static llvm::cl::opt<std::string>
    ReportFile("report-file", llvm::cl::desc("Write the report to this file"),
               llvm::cl::value_desc("file"), llvm::cl::cat(Category));
static llvm::cl::opt<unsigned>
    Jobs("j",
         llvm::cl::desc("Parse this many sources in parallel (default: the "
                        "number of CPUs)"),
         llvm::cl::init(0), llvm::cl::cat(Category));
static llvm::cl::opt<symcr_gen::RuntimeProfile> Profile(
    "profile", llvm::cl::desc("The runtime the generated code serves"),
    llvm::cl::values(
        clEnumValN(symcr_gen::RuntimeProfile::Host, "host",
                   "the host runtime: every supported type (default)"),
        clEnumValN(symcr_gen::RuntimeProfile::Device, "device",
                   "the device profile (runtime/device): no heap; a type it "
                   "cannot hold is an error naming the member and the fix")),
    llvm::cl::init(symcr_gen::RuntimeProfile::Host), llvm::cl::cat(Category));
static llvm::cl::opt<std::string> ShownNotes(
    "shown-notes",
    llvm::cl::desc("Print a note only if this file, shared by the build's "
                   "generation steps, does not list it yet, and list it"),
    llvm::cl::value_desc("file"), llvm::cl::cat(Category));
static llvm::cl::opt<std::string> Unit(
    "unit",
    llvm::cl::desc(
        "Generate the one source given as a unit of a program linked later "
        "from "
        "parts (--part-file, --link-part): its generated code is named after "
        "<name>, which must differ between the program's units"),
    llvm::cl::value_desc("name"), llvm::cl::cat(Category));
static llvm::cl::opt<std::string>
    PartFile("part-file",
             llvm::cl::desc("With --unit: write the unit's part of the "
                            "program's schema to this file"),
             llvm::cl::value_desc("file"), llvm::cl::cat(Category));
static llvm::cl::list<std::string> LinkParts(
    "link-part",
    llvm::cl::desc("Parse no source: merge the parts of the program's units "
                   "(repeatable) and "
                   "write its schema source (--out-dir) and schema file"),
    llvm::cl::value_desc("file"), llvm::cl::cat(Category));
static llvm::cl::opt<bool>
    Timing("time", llvm::cl::desc("Print the time spent per source"),
           llvm::cl::cat(Category));

namespace {

std::string wrapperPath(const std::string &Dir, unsigned Index,
                        const std::string &Source) {
  llvm::SmallString<256> Path(Dir);
  llvm::sys::path::append(Path, "tu" + std::to_string(Index) + "_" +
                                    llvm::sys::path::filename(Source).str());
  return std::string(Path);
}

std::string absolute(const std::string &Path) {
  llvm::SmallString<256> Result(Path);
  llvm::sys::fs::make_absolute(Result);
  llvm::sys::path::remove_dots(Result, /*remove_dot_dot=*/true);
  return std::string(Result);
}

/// \p Path as an absolute path: a relative one is relative to the directory
/// of the compile command that read it (its file manager's working directory),
/// not to the process's, which parallel parses share.
std::string absoluteInCommandDirectory(const FileManager &Files,
                                       llvm::StringRef Path) {
  llvm::SmallString<256> Result(Path);
  Files.makeAbsolutePath(Result);
  llvm::sys::path::remove_dots(Result, /*remove_dot_dot=*/true);
  return std::string(Result);
}

/// Answers for a source with the compile command of its wrapper when the build
/// compiles the wrapper instead: the source is then absent from
/// compile_commands.json, or present with another target's flags.
class WrapperAwareDatabase : public CompilationDatabase {
public:
  WrapperAwareDatabase(const CompilationDatabase &Base,
                       std::map<std::string, std::string> SourceToWrapper)
      : Base(Base), SourceToWrapper(std::move(SourceToWrapper)) {
    for (const std::string &F : Base.getAllFiles())
      Known.insert(absolute(F));
  }

  std::vector<CompileCommand>
  getCompileCommands(llvm::StringRef File) const override {
    std::string Source = absolute(File.str());
    auto It = SourceToWrapper.find(Source);
    // The wrapper's command wins: another target may compile the source itself
    // with other flags.
    if (It == SourceToWrapper.end() || !Known.count(It->second))
      return withAbsoluteCompiler(Base.getCompileCommands(File));
    std::vector<CompileCommand> Commands =
        withAbsoluteCompiler(Base.getCompileCommands(It->second));
    for (CompileCommand &Command : Commands) {
      for (std::string &Arg : Command.CommandLine)
        if (Arg == It->second || absolute(Arg) == It->second)
          Arg = Source;
      Command.Filename = Source;
    }
    return Commands;
  }
  std::vector<std::string> getAllFiles() const override {
    return Base.getAllFiles();
  }

private:
  /// A compiler named by a relative path ("../tools/bin/g++") is relative to
  /// its command's directory; CompileCommandAdapter runs it (to ask its
  /// defaults) from the process's working directory, which parses share.
  static std::vector<CompileCommand>
  withAbsoluteCompiler(std::vector<CompileCommand> Commands) {
    for (CompileCommand &Command : Commands) {
      if (Command.CommandLine.empty())
        continue;
      std::string &Compiler = Command.CommandLine.front();
      if (Compiler.find('/') == std::string::npos ||
          llvm::sys::path::is_absolute(Compiler))
        continue;
      llvm::SmallString<256> Path(Command.Directory);
      llvm::sys::path::append(Path, Compiler);
      Compiler = absolute(std::string(Path));
    }
    return Commands;
  }

  const CompilationDatabase &Base;
  std::map<std::string, std::string> SourceToWrapper;
  std::set<std::string> Known;
};

/// TUs are parsed in parallel but handed to the SchemaBuilder one at a time in
/// command-line order, so type indices, home TUs and diagnostics are the same
/// as in a sequential run.
class TurnOrder {
public:
  /// Blocks until every TU before \p Index has had its turn; true if this is
  /// \p Index's turn (false if it was already taken, e.g. a second command).
  bool await(unsigned Index) {
    std::unique_lock<std::mutex> Guard(Lock);
    Changed.wait(Guard, [&] { return Next >= Index; });
    return Next == Index;
  }
  /// Ends \p Index's turn (also when it could not be parsed).
  void done(unsigned Index) {
    {
      std::lock_guard<std::mutex> Guard(Lock);
      if (Next == Index)
        Next = Index + 1;
    }
    Changed.notify_all();
  }

private:
  std::mutex Lock;
  std::condition_variable Changed;
  unsigned Next = 0;
};

/// Records the source's own quoted #includes as resolved, for a copy of the
/// source in another directory (ProgramPoints).
class IncludeRecorder : public PPCallbacks {
public:
  IncludeRecorder(const SourceManager &SM, std::vector<ResolvedInclude> &Out)
      : SM(SM), Out(Out) {}
  void InclusionDirective(SourceLocation HashLoc, const Token &, StringRef,
                          bool IsAngled, CharSourceRange FilenameRange,
                          const FileEntry *File, StringRef, StringRef,
                          const Module *, SrcMgr::CharacteristicKind) override {
    if (IsAngled || !File || FilenameRange.getBegin().isMacroID() ||
        !SM.isWrittenInMainFile(HashLoc))
      return;
    unsigned Begin = SM.getFileOffset(FilenameRange.getBegin());
    unsigned End = SM.getFileOffset(FilenameRange.getEnd());
    if (End <= Begin)
      return;
    Out.push_back(
        {Begin, End - Begin,
         File->tryGetRealPathName().empty()
             ? absoluteInCommandDirectory(SM.getFileManager(), File->getName())
             : absolute(File->tryGetRealPathName().str())});
  }

private:
  const SourceManager &SM;
  std::vector<ResolvedInclude> &Out;
};

class GenerateAction : public ASTFrontendAction {
public:
  GenerateAction(SchemaBuilder &Builder, ProgramPoints &Points,
                 Diagnostics &Diags, TurnOrder &Turns, unsigned TUIndex,
                 std::set<std::string> &Dependencies)
      : Builder(Builder), Points(Points), Diags(Diags), Turns(Turns),
        TUIndex(TUIndex), Dependencies(Dependencies) {}

  bool BeginSourceFileAction(CompilerInstance &CI) override {
    CI.getPreprocessor().AddPragmaHandler(
        createPragmaHandler(Pragmas, Diags).release());
    CI.getPreprocessor().addPPCallbacks(
        std::make_unique<IncludeRecorder>(CI.getSourceManager(), Includes));
    Collector = std::make_shared<DependencyCollector>();
    Collector->attachToPreprocessor(CI.getPreprocessor());
    return true;
  }

  std::unique_ptr<ASTConsumer> CreateASTConsumer(CompilerInstance &,
                                                 llvm::StringRef) override {
    class Consumer : public SemaConsumer {
    public:
      explicit Consumer(GenerateAction &Action) : Action(Action) {}
      void InitializeSema(Sema &S) override { TheSema = &S; }
      void ForgetSema() override { TheSema = nullptr; }
      void HandleTranslationUnit(ASTContext &Context) override {
        if (Context.getDiagnostics().hasErrorOccurred())
          return; // the front end already failed; no schema from a broken AST
        if (!Action.Turns.await(Action.TUIndex))
          return;
        std::vector<Directive> SchemaPragmas;
        for (const Directive &D : Action.Pragmas)
          if (!isPointDirective(D))
            SchemaPragmas.push_back(D);
        Action.Builder.addTranslationUnit(Context, TheSema, Action.TUIndex,
                                          SchemaPragmas);
        Action.Points.addTranslationUnit(Context, Action.TUIndex,
                                         Action.Pragmas, Action.Includes);
        Action.Turns.done(Action.TUIndex);
      }

    private:
      GenerateAction &Action;
      Sema *TheSema = nullptr;
    };
    return std::make_unique<Consumer>(*this);
  }

  void EndSourceFileAction() override {
    FileManager &Files = getCompilerInstance().getFileManager();
    for (const std::string &File : Collector->getDependencies())
      Dependencies.insert(absoluteInCommandDirectory(Files, File));
  }

private:
  SchemaBuilder &Builder;
  ProgramPoints &Points;
  Diagnostics &Diags;
  TurnOrder &Turns;
  unsigned TUIndex;
  std::set<std::string> &Dependencies;
  std::vector<Directive> Pragmas;
  std::vector<ResolvedInclude> Includes;
  std::shared_ptr<DependencyCollector> Collector;
};

/// --link-part: the program's model merged from its units' parts, written as
/// one run over every source would write it (schema source and schema file; the
/// wrappers exist already).
int linkParts(Diagnostics &Diags) {
  ProgramModel Program;
  for (const std::string &File : LinkParts)
    if (!mergeModelPart(File, Program, Diags))
      break;
  if (!Diags.errorCount() && !ProgramName.empty() &&
      ProgramName != Program.Name)
    Diags.error(Location(), "the parts are of program '" + Program.Name +
                                "', not '" + ProgramName + "'");
  if (!Diags.errorCount())
    planPreviousSchemas(Program, PreviousSchemas, Diags);
  if (Diags.errorCount()) {
    Diags.releaseNotes();
    llvm::errs() << "symcr-gen: " << Diags.errorCount()
                 << " error(s); nothing generated\n";
    return 1;
  }
  if (Program.Roots.empty())
    Diags.warning(Location(), "no roots in any part: the schema is empty");
  if (!ReportFile.empty() &&
      !writeFileIfChanged(ReportFile,
                          renderReport(Program) + renderPointsReport(Program),
                          Diags))
    return 1;
  if (!SchemaFile.empty()) {
    llvm::StringRef Parent = llvm::sys::path::parent_path(SchemaFile);
    if (!Parent.empty())
      llvm::sys::fs::create_directories(Parent);
    if (!writeSchemaFile(Program, SchemaFile, Diags))
      return 1;
  }
  if (!OutDir.empty()) {
    llvm::sys::fs::create_directories(OutDir);
    if (!writeFileIfChanged(absolute(OutDir + "/symcr_schema.cpp"),
                            emitSchemaSource(Program), Diags))
      return 1;
  }
  return 0;
}

class GenerateActionFactory : public FrontendActionFactory {
public:
  GenerateActionFactory(SchemaBuilder &Builder, ProgramPoints &Points,
                        Diagnostics &Diags, TurnOrder &Turns, unsigned TUIndex,
                        std::set<std::string> &Dependencies)
      : Builder(Builder), Points(Points), Diags(Diags), Turns(Turns),
        TUIndex(TUIndex), Dependencies(Dependencies) {}
  std::unique_ptr<FrontendAction> create() override {
    return std::make_unique<GenerateAction>(Builder, Points, Diags, Turns,
                                            TUIndex, Dependencies);
  }

private:
  SchemaBuilder &Builder;
  ProgramPoints &Points;
  Diagnostics &Diags;
  TurnOrder &Turns;
  unsigned TUIndex;
  std::set<std::string> &Dependencies;
};

} // namespace

int main(int argc, const char **argv) {
  auto Parser =
      CommonOptionsParser::create(argc, argv, Category, llvm::cl::ZeroOrMore);
  if (!Parser) {
    llvm::errs() << "symcr-gen: " << llvm::toString(Parser.takeError()) << "\n";
    return 2;
  }
  if (Parser->getSourcePathList().empty() == LinkParts.empty()) {
    llvm::errs() << "symcr-gen: give either sources or --link-part files\n";
    return 2;
  }
  if (!Unit.empty() && Parser->getSourcePathList().size() != 1) {
    llvm::errs() << "symcr-gen: --unit generates exactly one source\n";
    return 2;
  }
  if (!PartFile.empty() && Unit.empty()) {
    llvm::errs() << "symcr-gen: --part-file needs --unit\n";
    return 2;
  }
  Diagnostics Diags;
  if (!ShownNotes.empty())
    Diags.printNotesOnceIn(ShownNotes);
  // Every return below prints the notes held back.
  struct NotesRelease {
    Diagnostics &Diags;
    ~NotesRelease() { Diags.releaseNotes(); }
  } ReleaseNotesOnReturn{Diags};
  std::vector<Directive> Sidecar;
  for (const std::string &File : AnnotationFiles)
    parseSidecarFile(File, Sidecar, Diags);
  if (Diags.errorCount())
    return 1;

  if (!LinkParts.empty())
    return linkParts(Diags);

  ProgramModel Program;
  Program.Profile = Profile;
  Program.Name = ProgramName;
  std::map<std::string, std::string> SourceToWrapper;
  std::vector<std::string> Sources;
  std::vector<std::string> AllSources = Parser->getSourcePathList();
  AllSources.insert(AllSources.end(), LibrarySources.begin(),
                    LibrarySources.end());
  for (std::size_t SourceIndex = 0; SourceIndex < AllSources.size();
       ++SourceIndex) {
    const std::string &Path = AllSources[SourceIndex];
    TranslationUnitModel TU;
    TU.Source = absolute(Path);
    TU.LibraryOnly = SourceIndex >= Parser->getSourcePathList().size();
    llvm::StringRef Extension = llvm::sys::path::extension(TU.Source);
    TU.IsC = Extension == ".c";
    if (!OutDir.empty() && !TU.LibraryOnly) {
      TU.Wrapper = absolute(wrapperPath(
          OutDir, static_cast<unsigned>(Sources.size()), TU.Source));
      SourceToWrapper[TU.Source] = TU.Wrapper;
    }
    Sources.push_back(TU.Source);
    Program.TranslationUnits.push_back(TU);
  }

  WrapperAwareDatabase Database(Parser->getCompilations(), SourceToWrapper);
  ProgramPoints Points(Program, Diags, Sidecar);
  Sidecar.erase(
      std::remove_if(Sidecar.begin(), Sidecar.end(), isPointDirective),
      Sidecar.end());
  SchemaBuilder Builder(Program, Diags, std::move(Sidecar));
  std::set<std::string> Dependencies(AnnotationFiles.begin(),
                                     AnnotationFiles.end());
  Dependencies.insert(PreviousSchemas.begin(), PreviousSchemas.end());
  // Parse with up to -j threads; each TU's dependencies are kept apart and
  // merged after the join.
  std::vector<std::set<std::string>> TUDependencies(Sources.size());
  std::atomic<unsigned> NextSource{0};
  std::atomic<unsigned> UnparsedSources{0};
  CompileCommandAdapter Adapter;
  std::mutex OutputLock;
  TurnOrder Turns;
  auto Worker = [&] {
    for (unsigned I = NextSource++; I < Sources.size(); I = NextSource++) {
      auto Start = std::chrono::steady_clock::now();
      // A file system of its own, whose working directory is this tool's:
      // ClangTool moves it to each command's directory, which over the real
      // file system would change the process's under the other workers.
      ClangTool Tool(Database, {Sources[I]},
                     std::make_shared<PCHContainerOperations>(),
                     llvm::vfs::createPhysicalFileSystem());
      Tool.clearArgumentsAdjusters();
      Tool.appendArgumentsAdjuster(getClangStripOutputAdjuster());
      Tool.appendArgumentsAdjuster(getClangStripDependencyFileAdjuster());
      Tool.appendArgumentsAdjuster(
          [&Adapter](const CommandLineArguments &Args, llvm::StringRef File) {
            return Adapter.adapt(Args, File);
          });
      Tool.appendArgumentsAdjuster(getClangSyntaxOnlyAdjuster());
      Tool.appendArgumentsAdjuster(getInsertArgumentAdjuster(
          {"-DSYMCR_GENERATOR=1", "-resource-dir=" SYMCR_CLANG_RESOURCE_DIR,
           "-w", "-Wno-unknown-warning-option"},
          ArgumentInsertPosition::END));
      GenerateActionFactory Factory(Builder, Points, Diags, Turns, I,
                                    TUDependencies[I]);
      bool Failed = Tool.run(&Factory) != 0;
      // A TU that failed (or had no command) still passes on its turn.
      Turns.await(I);
      Turns.done(I);
      std::lock_guard<std::mutex> Guard(OutputLock);
      if (Failed) {
        llvm::errs() << "symcr-gen: error: Clang could not parse '"
                     << Sources[I] << "' (its errors are above)\n";
        ++UnparsedSources;
      }
      if (Timing)
        llvm::errs() << "symcr-gen: " << Sources[I] << ": "
                     << std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - Start)
                            .count()
                     << " s\n";
    }
  };
  unsigned ThreadCount =
      Jobs ? Jobs.getValue()
           : std::max(1u, std::thread::hardware_concurrency());
  ThreadCount = std::min<unsigned>(ThreadCount, Sources.size());
  std::vector<std::thread> Threads;
  for (unsigned T = 1; T < ThreadCount; ++T)
    Threads.emplace_back(Worker);
  Worker();
  for (std::thread &T : Threads)
    T.join();
  for (const std::set<std::string> &Files : TUDependencies)
    Dependencies.insert(Files.begin(), Files.end());
  std::set<std::string> Dropped = Adapter.droppedFlags();
  if (!Dropped.empty()) {
    std::string List;
    for (const std::string &Flag : Dropped)
      List += " " + Flag;
    llvm::errs()
        << "symcr-gen: warning: ignored compiler flag(s) Clang does not "
           "know:"
        << List << "\n";
  }
  // A source that could not be parsed defines roots and types nothing else
  // sees: "matches nothing" would then be a false lead.
  // A unit is one source of many: what the annotations name may be in another.
  const bool CheckUnmatched = UnparsedSources == 0 && Unit.empty();
  Builder.finish(CheckUnmatched);
  Points.finish(CheckUnmatched);
  if (Program.Profile == RuntimeProfile::Device)
    checkDeviceProfile(Program, Diags);
  if (!UnparsedSources && !Diags.errorCount())
    planPreviousSchemas(Program, PreviousSchemas, Diags);
  if (UnparsedSources || Diags.errorCount()) {
    Diags.releaseNotes(); // before the closing line
    llvm::errs() << "symcr-gen: " << Diags.errorCount() + UnparsedSources
                 << " error(s)";
    if (UnparsedSources)
      llvm::errs() << " (" << UnparsedSources.load()
                   << " source(s) Clang could not parse)";
    llvm::errs() << "; nothing generated\n";
    return 1;
  }

  if (!Unit.empty())
    nameSymbolsForUnit(Program, Unit);
  if (!PartFile.empty() &&
      !writeFileIfChanged(PartFile, writeModelPart(Program), Diags))
    return 1;
  if (Program.Roots.empty() && Unit.empty())
    Diags.warning(Location(),
                  "no roots: nothing is annotated with SYMCR_CHECKPOINT "
                  "or a checkpoint directive; the schema is empty");
  std::string ReportText = renderReport(Program) + renderPointsReport(Program);
  if (Report)
    llvm::outs() << ReportText;
  if (!ReportFile.empty() && !writeFileIfChanged(ReportFile, ReportText, Diags))
    return 1;
  if (!SchemaFile.empty()) {
    llvm::StringRef Parent = llvm::sys::path::parent_path(SchemaFile);
    if (!Parent.empty())
      llvm::sys::fs::create_directories(Parent);
    if (!writeSchemaFile(Program, SchemaFile, Diags))
      return 1;
  }
  if (!OutDir.empty()) {
    llvm::sys::fs::create_directories(OutDir);
    // A source with points is compiled as a copy with their calls inserted.
    for (unsigned I = 0; I < Program.TranslationUnits.size(); ++I) {
      TranslationUnitModel &TU = Program.TranslationUnits[I];
      if (TU.Edits.empty() || TU.LibraryOnly)
        continue;
      TU.PointedCopy = absolute(wrapperPath(OutDir, I, TU.Source));
      TU.PointedCopy.insert(TU.PointedCopy.size() -
                                llvm::sys::path::filename(TU.Source).size(),
                            "points_");
      if (!writeFileIfChanged(TU.PointedCopy, emitPointedCopy(Program, I),
                              Diags))
        return 1;
    }
    // A unit's schema source is written at the link, from every unit's part.
    std::string Schema = absolute(OutDir + "/symcr_schema.cpp");
    if (Unit.empty() &&
        !writeFileIfChanged(Schema, emitSchemaSource(Program), Diags))
      return 1;
    for (unsigned I = 0; I < Program.TranslationUnits.size(); ++I)
      if (!Program.TranslationUnits[I].LibraryOnly &&
          !writeFileIfChanged(Program.TranslationUnits[I].Wrapper,
                              emitWrapper(Program, I), Diags))
        return 1;
    if (!Depfile.empty()) {
      std::vector<std::string> Deps(Dependencies.begin(), Dependencies.end());
      std::string Target =
          DepfileTarget.empty() ? Schema : DepfileTarget.getValue();
      if (!writeFileIfChanged(Depfile, renderDepfile(Target, Deps), Diags))
        return 1;
    }
  }
  return 0;
}
