//===- OutputFiles.cpp - Writes the generator's output files --------------===//
//
// Outputs are rewritten only when their content changes, so that an unchanged
// output keeps its timestamp; the depfile lists what generation read.
//
//===----------------------------------------------------------------------===//
#include "Emitter.h"

#include <cstdio>
#include <fstream>
#include <sstream>

namespace symcr_gen {

bool writeFileIfChanged(const std::string &Path, const std::string &Content,
                        Diagnostics &Diags) {
  {
    std::ifstream In(Path, std::ios::binary);
    if (In) {
      std::ostringstream Existing;
      Existing << In.rdbuf();
      if (Existing.str() == Content)
        return true;
    }
  }
  std::string Temporary = Path + ".tmp";
  {
    std::ofstream Out(Temporary, std::ios::binary | std::ios::trunc);
    Out << Content;
    if (!Out) {
      Diags.error(Location(), "cannot write '" + Temporary + "'");
      return false;
    }
  }
  if (std::rename(Temporary.c_str(), Path.c_str()) != 0) {
    Diags.error(Location(),
                "cannot rename '" + Temporary + "' to '" + Path + "'");
    return false;
  }
  return true;
}

std::string renderDepfile(const std::string &Target,
                          const std::vector<std::string> &Dependencies) {
  auto Escape = [](const std::string &Path) {
    std::string Out;
    for (char C : Path) {
      if (C == ' ' || C == '#' || C == '\\')
        Out += '\\';
      if (C == '$') {
        Out += "$$";
        continue;
      }
      Out += C;
    }
    return Out;
  };
  std::string Out = Escape(Target) + ":";
  for (const std::string &D : Dependencies)
    Out += " \\\n  " + Escape(D);
  return Out + "\n";
}

} // namespace symcr_gen
