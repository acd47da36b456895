// The running program's generated schema, for the API forms that take none.
#ifndef SYMCR_SRC_PROGRAM_SCHEMA_HPP
#define SYMCR_SRC_PROGRAM_SCHEMA_HPP

#include "symcr/generated.hpp"
#include "symcr/symcr.hpp"

namespace symcr::detail {

// symcr_program_schema() if the program links generated code that defines it and it returns a
// schema; else Error::NoSchema naming the fix.
Status program_schema(const Schema*& out);

}  // namespace symcr::detail

#endif  // SYMCR_SRC_PROGRAM_SCHEMA_HPP
