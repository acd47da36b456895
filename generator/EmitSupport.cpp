//===- EmitSupport.cpp - Helpers shared by the generated-source writers ---===//
//
// See EmitSupport.h.
//
//===----------------------------------------------------------------------===//
#include "EmitSupport.h"

namespace symcr_gen {

std::string quoted(const std::string &Text) {
  std::string Out = "\"";
  for (char C : Text) {
    if (C == '"' || C == '\\')
      Out += '\\';
    if (C == '\n') {
      Out += "\\n";
      continue;
    }
    Out += C;
  }
  return Out + "\"";
}

const char *kindName(symcr::Kind Kind) {
  switch (Kind) {
  case symcr::Kind::Bool:
    return "Bool";
  case symcr::Kind::Int:
    return "Int";
  case symcr::Kind::UInt:
    return "UInt";
  case symcr::Kind::Float:
    return "Float";
  case symcr::Kind::Enum:
    return "Enum";
  case symcr::Kind::Struct:
    return "Struct";
  case symcr::Kind::Union:
    return "Union";
  case symcr::Kind::Array:
    return "Array";
  case symcr::Kind::String:
    return "String";
  case symcr::Kind::Container:
    return "Container";
  case symcr::Kind::Optional:
    return "Optional";
  case symcr::Kind::Variant:
    return "Variant";
  case symcr::Kind::Pointer:
    return "Pointer";
  case symcr::Kind::UniquePtr:
    return "UniquePtr";
  case symcr::Kind::SharedPtr:
    return "SharedPtr";
  }
  return "Struct";
}

const char *opsTableType(OpsKind Ops) {
  switch (Ops) {
  case OpsKind::String:
    return "StringOps";
  case OpsKind::Container:
    return "ContainerOps";
  case OpsKind::Optional:
    return "OptionalOps";
  case OpsKind::Variant:
    return "VariantOps";
  case OpsKind::UniquePtr:
    return "UniquePtrOps";
  case OpsKind::SharedPtr:
    return "SharedPtrOps";
  case OpsKind::None:
    break;
  }
  return nullptr;
}

/// The type has a user's symcr_migrate and a C++ home TU to call it from.
bool hasMigrate(const ProgramModel &Program, const TypeModel &Type) {
  return Type.HasMigrate && !Type.Spelling.empty() &&
         !Program.TranslationUnits[Type.HomeTU].IsC &&
         Program.Profile == RuntimeProfile::Host;
}

bool emitsLifecycle(const ProgramModel &Program, const TypeModel &Type) {
  return Type.hasLifecycle() && Program.Profile == RuntimeProfile::Host;
}

bool emitsOps(const ProgramModel &Program, const TypeModel &Type) {
  return Type.Ops != OpsKind::None && Program.Profile == RuntimeProfile::Host;
}

} // namespace symcr_gen
