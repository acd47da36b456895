//===- ProgramPoints.h - checkpoint_at / restore_at points
//-----------------===//
//
// The program points of the directives: functions at whose entry or exit the
// program checkpoints into, or restores from, the store of the store(...)
// directive. symcr-gen finds each function's definition in the target's
// sources and writes a copy of that source with the calls inserted at the
// start of the body (an exit point is a guard object there: it runs on every
// return path), under `#line` directives that keep the user's file and line
// numbers. The wrapper compiles the copy instead of the source.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_PROGRAMPOINTS_H
#define SYMCR_GENERATOR_PROGRAMPOINTS_H

#include "Annotations.h"
#include "Model.h"

#include <map>
#include <string>
#include <vector>

namespace clang {
class ASTContext;
} // namespace clang

namespace symcr_gen {

/// A quoted #include of a source, as the front end resolved it: the copy of
/// the source names the file by its absolute path, since the copy lives in
/// another directory.
struct ResolvedInclude {
  unsigned Offset = 0; ///< of the file name token ("x.h", quotes included)
  unsigned Length = 0;
  std::string File; ///< absolute path of the included file
};

class ProgramPoints {
public:
  /// \p Sidecar: the point and store directives of the annotation files.
  ProgramPoints(ProgramModel &Program, Diagnostics &Diags,
                const std::vector<Directive> &Sidecar);

  /// Adds the point directives among \p Pragmas (a header's pragmas, seen by
  /// several TUs, count once), then finds the definitions of every point's
  /// function in this TU's source and records the edits of its copy.
  void addTranslationUnit(clang::ASTContext &Context, unsigned TUIndex,
                          const std::vector<Directive> &Pragmas,
                          const std::vector<ResolvedInclude> &Includes);

  /// Diagnoses points whose function was never defined in a source, and
  /// points without a store. \p CheckUnmatched: false when some source could
  /// not be parsed (its definitions are unknown).
  void finish(bool CheckUnmatched);

private:
  void addDirective(const Directive &D);
  ProgramModel &Program;
  Diagnostics &Diags;
  std::map<std::string, bool> SeenDirectives; ///< by location
  /// Per point: some TU declares a function of that name; where a TU defines
  /// it in a header (not a source symcr-gen can copy).
  std::vector<bool> Declared;
  std::vector<std::string> DefinedInHeader;
  /// Per point: a definition was found but refused (and diagnosed).
  std::vector<bool> Refused;
};

/// True for checkpoint_at, restore_at and store directives.
bool isPointDirective(const Directive &D);

/// The definition of the points' store, symcr_program_point_store, for the
/// schema source ("" when the program has no points): one definition that
/// every copy's points and symcr_points_open_store() refer to.
std::string emitPointStoreDefinition(const ProgramModel &Program);

/// The copy of TU \p TUIndex's source with its points' calls inserted.
std::string emitPointedCopy(const ProgramModel &Program, unsigned TUIndex);

/// The report's section on program points ("" when there are none).
std::string renderPointsReport(const ProgramModel &Program);

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_PROGRAMPOINTS_H
