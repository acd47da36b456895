#include "program_schema.hpp"

namespace symcr::detail {

Status program_schema(const Schema*& out) {
  // symcr_program_schema is weak: null when no generated code is linked in.
  out = symcr_program_schema != nullptr ? symcr_program_schema() : nullptr;
  if (out == nullptr) {
    return Status(Error::NoSchema,
                  "no generated schema is linked into this program: build it with "
                  "symcr_add_checkpointing(), or pass a Schema explicitly");
  }
  return Status();
}

}  // namespace symcr::detail
