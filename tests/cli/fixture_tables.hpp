// The CLI's fixture programs: hand-written schema tables in the form symcr-gen emits, built
// with tests/support/schema_tables.hpp.
#ifndef SYMCR_TESTS_CLI_FIXTURE_TABLES_HPP
#define SYMCR_TESTS_CLI_FIXTURE_TABLES_HPP

#include <cstddef>
#include <cstdint>

#include "schema_tables.hpp"
#include "symcr/ops.hpp"
#include "symcr/generated.hpp"

namespace cli_fixture {

using namespace schema_tables;  // scalar(), record(), field(), ...: tests/support

// Each fixture build defines these.
const symcr::Schema& schema();
void fill_state(int seed);  // distinct, checkable contents per seed

}  // namespace cli_fixture

#endif  // SYMCR_TESTS_CLI_FIXTURE_TABLES_HPP
