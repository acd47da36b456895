//===- EmitSupport.h - Helpers shared by the generated-source writers -----===//
//
// Spellings that the schema source, the wrappers and the report all print.
//
//===----------------------------------------------------------------------===//
#ifndef SYMCR_GENERATOR_EMITSUPPORT_H
#define SYMCR_GENERATOR_EMITSUPPORT_H

#include "Model.h"

#include <string>

namespace symcr_gen {

/// \p Text as a C and C++ string literal.
std::string quoted(const std::string &Text);

/// The name of a symcr::Kind enumerator ("Struct", "UniquePtr", ...).
const char *kindName(symcr::Kind Kind);

/// The runtime's ops table type for \p Ops ("ContainerOps", ...); null for
/// OpsKind::None.
const char *opsTableType(OpsKind Ops);

/// The type has a user's symcr_migrate and a C++ home TU to call it from,
/// and the profile migrates (the device profile restores its own build only).
bool hasMigrate(const ProgramModel &Program, const TypeModel &Type);

/// The generated code carries the type's Lifecycle: the host profile creates
/// heap objects and staged copies with it; the device profile never allocates.
/// (The schema's kTypeCreatable flag describes the type either way.)
bool emitsLifecycle(const ProgramModel &Program, const TypeModel &Type);

/// The generated code carries the type's ops table (the host profile's
/// strings, containers, optionals, variants and smart pointers).
bool emitsOps(const ProgramModel &Program, const TypeModel &Type);

} // namespace symcr_gen

#endif // SYMCR_GENERATOR_EMITSUPPORT_H
