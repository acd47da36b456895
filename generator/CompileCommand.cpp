//===- CompileCommand.cpp - compile commands written for g++, read by Clang
//===//

#include "CompileCommand.h"

#include "clang/Driver/Options.h"
#include "llvm/ADT/Triple.h"
#include "llvm/Option/ArgList.h"
#include "llvm/Option/OptTable.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/Host.h"
#include "llvm/Support/MemoryBuffer.h"
#include "llvm/Support/Path.h"
#include "llvm/Support/Program.h"

#include <algorithm>
#include <map>

using namespace clang;
using namespace clang::tooling;

namespace symcr_gen {
namespace {

/// g++ flags that change which programs are well-formed, with Clang's
/// spelling. -fsingle-precision-constant makes unsuffixed floating literals
/// `float` (without it `Rec{x * 0.01}` narrows double to float, an error);
/// Clang's driver accepts the g++ spelling but ignores it.
const std::map<std::string, std::string> &translatedFlags() {
  static const std::map<std::string, std::string> Flags = {
      {"-fsingle-precision-constant", "-cl-single-precision-constant"}};
  return Flags;
}

bool isClang(llvm::StringRef Compiler) {
  return llvm::sys::path::filename(Compiler).contains("clang");
}

/// The dialect a GNU compiler's predefined macros describe, as a -std= value.
std::string standardFromMacros(llvm::StringRef Macros, bool IsC) {
  bool Gnu = !Macros.contains("#define __STRICT_ANSI__");
  auto Value = [&](llvm::StringRef Name) -> long {
    std::string Key = ("#define " + Name + " ").str();
    std::size_t At = Macros.find(Key);
    if (At == llvm::StringRef::npos)
      return 0;
    return std::strtol(Macros.substr(At + Key.size()).str().c_str(), nullptr,
                       10);
  };
  if (IsC) {
    long V = Value("__STDC_VERSION__");
    const char *Year = V >= 202000   ? "2x"
                       : V >= 201710 ? "17"
                       : V >= 201112 ? "11"
                       : V >= 199901 ? "99"
                                     : "89";
    return std::string(Gnu ? "gnu" : "c") + Year;
  }
  long V = Value("__cplusplus");
  const char *Year = V > 202002    ? "2b"
                     : V >= 202002 ? "20"
                     : V >= 201703 ? "17"
                     : V >= 201402 ? "14"
                     : V >= 201103 ? "11"
                                   : "98";
  return std::string(Gnu ? "gnu++" : "c++") + Year;
}

/// Runs \p Compiler with \p Arguments and returns what it wrote to standard
/// output (\p Stderr: to standard error), or None when it could not run.
llvm::Optional<std::string> runCompiler(llvm::StringRef Compiler,
                                        llvm::ArrayRef<std::string> Arguments,
                                        bool Stderr = false) {
  llvm::ErrorOr<std::string> Program = llvm::sys::findProgramByName(Compiler);
  llvm::SmallString<128> Output;
  if (!Program ||
      llvm::sys::fs::createTemporaryFile("symcr-gen-compiler", "txt", Output))
    return llvm::None;
  std::vector<llvm::StringRef> Argv{*Program};
  Argv.insert(Argv.end(), Arguments.begin(), Arguments.end());
  llvm::Optional<llvm::StringRef> Redirects[] = {
      llvm::StringRef(""),
      Stderr ? llvm::StringRef("") : llvm::StringRef(Output),
      Stderr ? llvm::StringRef(Output) : llvm::StringRef("")};
  llvm::Optional<std::string> Result;
  if (llvm::sys::ExecuteAndWait(*Program, Argv, llvm::None, Redirects,
                                /*SecondsToWait=*/30) == 0)
    if (auto Text = llvm::MemoryBuffer::getFile(Output))
      Result = (*Text)->getBuffer().str();
  llvm::sys::fs::remove(Output);
  return Result;
}

/// A GNU cross compiler's own headers, from its `-v` listing: the C++ library's
/// and the C library's directories, in its order. GCC's private directories
/// (lib/gcc/<triple>/<version>/include[-fixed]) are left out: Clang's resource
/// directory has its own versions of those headers.
std::vector<std::string> crossSearchDirectories(llvm::StringRef Listing) {
  std::vector<std::string> Dirs;
  bool Inside = false;
  llvm::SmallVector<llvm::StringRef, 32> Lines;
  Listing.split(Lines, '\n');
  for (llvm::StringRef Line : Lines) {
    if (Line.startswith("#include <...> search starts here:")) {
      Inside = true;
      continue;
    }
    if (Line.startswith("End of search list."))
      break;
    if (!Inside)
      continue;
    llvm::SmallString<256> Dir(Line.trim());
    llvm::sys::path::remove_dots(Dir, /*remove_dot_dot=*/true);
    llvm::StringRef Name = llvm::sys::path::filename(Dir);
    if (llvm::StringRef(Dir).contains("/lib/gcc/") &&
        (Name == "include" || Name == "include-fixed"))
      continue;
    Dirs.push_back(std::string(Dir));
  }
  return Dirs;
}

} // namespace

std::vector<std::string>
CompileCommandAdapter::crossCompilerFlags(const CommandLineArguments &Args,
                                          bool IsC) {
  const std::string &Compiler = Args[0];
  if (isClang(Compiler))
    return {};
  // Flags that choose the target's variant (and so GCC's multilib headers).
  std::vector<std::string> Machine;
  for (std::size_t I = 1; I < Args.size(); ++I)
    if (llvm::StringRef(Args[I]).startswith("-m") ||
        llvm::StringRef(Args[I]).startswith("--specs"))
      Machine.push_back(Args[I]);
  std::string Key = Compiler + (IsC ? "|c" : "|c++");
  for (const std::string &Flag : Machine)
    Key += "|" + Flag;
  {
    std::lock_guard<std::mutex> Guard(Lock);
    auto It = CrossFlags.find(Key);
    if (It != CrossFlags.end())
      return It->second;
  }
  std::vector<std::string> Result;
  llvm::Optional<std::string> Dumped = runCompiler(Compiler, {"-dumpmachine"});
  llvm::Triple Target(llvm::StringRef(Dumped ? *Dumped : "").trim());
  llvm::Triple Host(llvm::sys::getDefaultTargetTriple());
  if (Dumped && Target.getArch() != llvm::Triple::UnknownArch &&
      (Target.getArch() != Host.getArch() || Target.getOS() != Host.getOS())) {
    std::vector<std::string> Query = Machine;
    for (const char *Arg : {"-E", "-x", IsC ? "c" : "c++", "/dev/null", "-v"})
      Query.push_back(Arg);
    llvm::Optional<std::string> Listing =
        runCompiler(Compiler, Query, /*Stderr=*/true);
    Result.push_back("--target=" + Target.str());
    Result.push_back("-nostdlibinc");
    for (const std::string &Dir :
         crossSearchDirectories(Listing ? *Listing : ""))
      Result.insert(Result.end(), {"-isystem", Dir});
  }
  std::lock_guard<std::mutex> Guard(Lock);
  CrossFlags[Key] = Result;
  return Result;
}

std::string CompileCommandAdapter::defaultStandard(const std::string &Compiler,
                                                   bool IsC) {
  if (isClang(Compiler))
    return "";
  std::string Key = Compiler + (IsC ? "|c" : "|c++");
  {
    std::lock_guard<std::mutex> Guard(Lock);
    auto It = Defaults.find(Key);
    if (It != Defaults.end())
      return It->second;
  }
  std::string Result;
  if (llvm::Optional<std::string> Macros = runCompiler(
          Compiler, {"-dM", "-E", "-x", IsC ? "c" : "c++", "/dev/null"}))
    Result = standardFromMacros(*Macros, IsC);
  std::lock_guard<std::mutex> Guard(Lock);
  Defaults[Key] = Result;
  return Result;
}

namespace {
/// Programs a build puts in front of the compiler, which run it.
bool isCompilerLauncher(llvm::StringRef Name) {
  return Name == "symcr-c++" || Name == "symcr-cc" || Name == "ccache" ||
         Name == "sccache" || Name == "distcc";
}
} // namespace

CommandLineArguments
CompileCommandAdapter::adapt(const CommandLineArguments &Command,
                             llvm::StringRef File) {
  // A launcher in front of the compiler ("ccache g++"; "symcr-c++ g++" in a
  // database written by a build through symcr's wrapper) is not the compiler,
  // and the wrapper's options are not the compiler's. The flags the tooling
  // inferred from the launcher's name (--driver-mode=, a target) follow the
  // launcher: they stay, after the compiler.
  CommandLineArguments Args(Command);
  while (Args.size() > 1 &&
         isCompilerLauncher(llvm::sys::path::filename(Args[0]))) {
    std::size_t Compiler = 1;
    while (Compiler + 1 < Args.size() &&
           (llvm::StringRef(Args[Compiler]).startswith("--driver-mode=") ||
            llvm::StringRef(Args[Compiler]).startswith("--target=")))
      ++Compiler;
    CommandLineArguments Unwrapped{Args[Compiler]};
    Unwrapped.insert(Unwrapped.end(), Args.begin() + 1,
                     Args.begin() + Compiler);
    Unwrapped.insert(Unwrapped.end(), Args.begin() + Compiler + 1, Args.end());
    Args = std::move(Unwrapped);
  }
  Args.erase(std::remove_if(Args.begin() + (Args.empty() ? 0 : 1), Args.end(),
                            [](const std::string &Arg) {
                              return llvm::StringRef(Arg).startswith(
                                  "--symcr-");
                            }),
             Args.end());
  if (Args.empty())
    return Args;
  const llvm::opt::OptTable &Table = driver::getDriverOptTable();
  std::vector<const char *> Raw;
  for (std::size_t I = 1; I < Args.size(); ++I)
    Raw.push_back(Args[I].c_str());
  unsigned MissingIndex = 0, MissingCount = 0;
  // Against every option the driver knows (not only those it passes to its
  // front end), so that only flags Clang has never heard of are dropped.
  llvm::opt::InputArgList Parsed =
      Table.ParseArgs(Raw, MissingIndex, MissingCount);
  std::set<unsigned> Unknown;
  for (const llvm::opt::Arg *A : Parsed.filtered(driver::options::OPT_UNKNOWN))
    Unknown.insert(A->getIndex());

  CommandLineArguments Result{Args[0]};
  bool HasStandard = false;
  for (std::size_t I = 1; I < Args.size(); ++I) {
    const std::string &Arg = Args[I];
    if (llvm::StringRef(Arg).startswith("-std=") || Arg == "-std" ||
        llvm::StringRef(Arg).startswith("--std"))
      HasStandard = true;
    auto Translated = translatedFlags().find(Arg);
    if (Translated != translatedFlags().end()) {
      Result.push_back(Translated->second);
      continue;
    }
    if (Unknown.count(static_cast<unsigned>(I - 1))) {
      std::lock_guard<std::mutex> Guard(Lock);
      Dropped.insert(Arg);
      continue;
    }
    Result.push_back(Arg);
  }
  // No -std: the program is compiled in its compiler's default dialect (g++ 12:
  // gnu++17), which may not be Clang's (gnu++14).
  bool IsC = llvm::sys::path::extension(File) == ".c";
  if (!HasStandard) {
    std::string Standard = defaultStandard(Args[0], IsC);
    if (!Standard.empty())
      Result.push_back("-std=" + Standard);
  }
  // A cross compiler's target decides the layouts the schema records.
  for (std::string &Flag : crossCompilerFlags(Args, IsC))
    Result.push_back(std::move(Flag));
  return Result;
}

std::set<std::string> CompileCommandAdapter::droppedFlags() const {
  std::lock_guard<std::mutex> Guard(Lock);
  return Dropped;
}

} // namespace symcr_gen
