//===- CompileCommand.h - compile commands written for g++, read by Clang -===//
//
// A compile_commands.json is usually written for the compiler that builds the
// program (g++ for an autopilot), while symcr-gen parses with Clang 14. These
// adjustments make Clang see the program the way that compiler does: its
// default language standard when the command names none, Clang's spelling of
// the g++ flags that change what is well-formed, a cross compiler's target and
// headers (arm-none-eabi-g++ for a microcontroller: the layouts are the
// target's), and a warning naming every flag Clang does not know and drops.
//
//===----------------------------------------------------------------------===//

#ifndef SYMCR_GENERATOR_COMPILECOMMAND_H
#define SYMCR_GENERATOR_COMPILECOMMAND_H

#include "clang/Tooling/ArgumentsAdjusters.h"

#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace symcr_gen {

class CompileCommandAdapter {
public:
  /// The adjusted command for \p File: a launcher in front of the compiler
  /// (ccache, symcr-c++) and the wrapper's --symcr-* options dropped, flags
  /// translated or dropped, and the compiler's default -std added when the
  /// command has none.
  clang::tooling::CommandLineArguments
  adapt(const clang::tooling::CommandLineArguments &Command,
        llvm::StringRef File);

  /// Flags dropped because Clang does not know them, each once, for a warning.
  std::set<std::string> droppedFlags() const;

private:
  /// `-std=` value for the compiler's default dialect of \p Language ("c" or
  /// "c++"): asked of the compiler itself (its __cplusplus/__STDC_VERSION__),
  /// remembered per compiler; empty when the compiler is Clang (whose default
  /// Clang already uses) or cannot be asked.
  std::string defaultStandard(const std::string &Compiler, bool IsC);

  /// For a GNU compiler whose target is not the host's (asked with
  /// -dumpmachine): --target=<its triple>, -nostdlibinc and its own header
  /// directories as -isystem. Empty for a native or a Clang compiler.
  /// Remembered per compiler and -m flags.
  std::vector<std::string>
  crossCompilerFlags(const clang::tooling::CommandLineArguments &Args,
                     bool IsC);

  mutable std::mutex Lock;
  std::set<std::string> Dropped;
  std::map<std::string, std::string> Defaults; ///< "compiler|c" -> "gnu17"
  std::map<std::string, std::vector<std::string>> CrossFlags;
};

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_COMPILECOMMAND_H
