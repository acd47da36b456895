//===- CompileCommand.cpp - compile commands written for g++, read by Clang ===//

#include "CompileCommand.h"

#include "clang/Driver/Options.h"
#include "llvm/Option/ArgList.h"
#include "llvm/Option/OptTable.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/MemoryBuffer.h"
#include "llvm/Support/Path.h"
#include "llvm/Support/Program.h"

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
    const char *Year = V >= 202000 ? "2x" : V >= 201710 ? "17" : V >= 201112 ? "11"
                       : V >= 199901                    ? "99"
                                                        : "89";
    return std::string(Gnu ? "gnu" : "c") + Year;
  }
  long V = Value("__cplusplus");
  const char *Year = V > 202002 ? "2b" : V >= 202002 ? "20" : V >= 201703 ? "17"
                     : V >= 201402                   ? "14"
                     : V >= 201103                   ? "11"
                                                     : "98";
  return std::string(Gnu ? "gnu++" : "c++") + Year;
}

} // namespace

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
  llvm::ErrorOr<std::string> Program = llvm::sys::findProgramByName(Compiler);
  llvm::SmallString<128> Output;
  if (Program && !llvm::sys::fs::createTemporaryFile("symcr-gen-macros", "txt",
                                                      Output)) {
    llvm::StringRef Argv[] = {*Program, "-dM", "-E", "-x", IsC ? "c" : "c++",
                              "/dev/null"};
    llvm::Optional<llvm::StringRef> Redirects[] = {llvm::StringRef(""),
                                                    llvm::StringRef(Output),
                                                    llvm::StringRef("")};
    if (llvm::sys::ExecuteAndWait(*Program, Argv, llvm::None, Redirects,
                                  /*SecondsToWait=*/30) == 0)
      if (auto Text = llvm::MemoryBuffer::getFile(Output))
        Result = standardFromMacros((*Text)->getBuffer(), IsC);
    llvm::sys::fs::remove(Output);
  }
  std::lock_guard<std::mutex> Guard(Lock);
  Defaults[Key] = Result;
  return Result;
}

CommandLineArguments
CompileCommandAdapter::adapt(const CommandLineArguments &Args,
                             llvm::StringRef File) {
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
  if (!HasStandard) {
    bool IsC = llvm::sys::path::extension(File) == ".c";
    std::string Standard = defaultStandard(Args[0], IsC);
    if (!Standard.empty())
      Result.push_back("-std=" + Standard);
  }
  return Result;
}

std::set<std::string> CompileCommandAdapter::droppedFlags() const {
  std::lock_guard<std::mutex> Guard(Lock);
  return Dropped;
}

} // namespace symcr_gen
