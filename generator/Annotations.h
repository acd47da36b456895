//===- Annotations.h - The three annotation forms
//--------------------------===//
//
// Macros (Clang `annotate` attributes read while walking), `#pragma symcr ...`
// and the sidecar annotation file both produce Directives with the same meaning
// (generator/README.md). Directives name things by source names; SchemaBuilder
// resolves them against each translation unit and reports names that match
// nothing.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_ANNOTATIONS_H
#define SYMCR_GENERATOR_ANNOTATIONS_H

#include "Model.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace clang {
class PragmaHandler;
} // namespace clang

namespace symcr_gen {

enum class DirectiveKind {
  Checkpoint,   ///< checkpoint(var, ... [, shallow])
  Skip,         ///< skip(Type, Type::field, ...)
  Renamed,      ///< renamed(Type::field | Type | var, old_name)
  Include,      ///< include(Type::field, ...): selected for a shallow root
  Range,        ///< range(Type::field, lo, hi): as SYMCR_RANGE(lo, hi)
  CheckpointAt, ///< checkpoint_at(function, entry|exit [, every N])
  RestoreAt, ///< restore_at(function, entry|exit [, on_failure=continue|stop]
             ///< ...)
  Store,     ///< store(path [, slots=N] [, slot_size=N] [, durability=...]
             ///< [, fallback_depth=N [, confirm_after=N]])
  Clock,     ///< clock([name,] function): a clock and its reading function
  Time, ///< time(Type::field | typedef, clock [, never=N]): a time of a clock
  NotOwner,      ///< not_owner(Type::field, ...): as SYMCR_NOT_OWNER
  RestoresAlone, ///< restores_alone(Type::field, ...): as SYMCR_RESTORES_ALONE
};

/// Parses SYMCR_TIME's text ("millis" or "millis, never=0xFFFFFFFF"); false
/// with \p Error set when it is malformed.
bool parseTimeArguments(const std::vector<std::string> &Arguments,
                        TimeSpec &Out, std::string &Error);

/// A range bound's text and value (its strtod): when the text is an integer
/// literal (an optional sign, then decimal or 0x digits) that no double holds
/// exactly, the error that names the two nearest a double holds; else empty.
/// Ranges hold doubles, so such a bound would silently be another number.
std::string inexactRangeBound(const std::string &Text, double Value);

struct DirectiveArgument {
  /// "Copter::mission", whitespace removed outside quotes; the quotes of a
  /// quoted argument are removed.
  std::string Text;
  Location Where;
};

struct Directive {
  DirectiveKind Kind = DirectiveKind::Checkpoint;
  std::vector<DirectiveArgument> Arguments; ///< without the trailing `shallow`
  bool Shallow = false;
  bool FromSidecar = false;
  Location Where;
  std::string Spelling; ///< the directive as written, "skip(A::b)"
};

/// Parses a sidecar annotation file: one directive per line, written as in a
/// pragma with or without the `#pragma symcr` prefix; `//` and `#` comments.
/// Returns false (after reporting) when the file cannot be read or parsed.
bool parseSidecarFile(const std::string &Path, std::vector<Directive> &Out,
                      Diagnostics &Diags);

/// Parses one directive's text ("skip(A::b, C)") starting at \p Where; used by
/// the sidecar parser and the pragma handler. Columns advance per character.
bool parseDirectiveText(const std::string &Text, const Location &Where,
                        bool FromSidecar, std::vector<Directive> &Out,
                        Diagnostics &Diags);

/// The `#pragma symcr` handler: appends every directive of the TU to \p Out.
std::unique_ptr<clang::PragmaHandler>
createPragmaHandler(std::vector<Directive> &Out, Diagnostics &Diags);

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_ANNOTATIONS_H
