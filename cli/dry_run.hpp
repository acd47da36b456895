// The report a restore of a loaded checkpoint into a build (known only by its schema) would
// produce, computed without a live program and without writing anything.
#ifndef SYMCR_CLI_DRY_RUN_HPP
#define SYMCR_CLI_DRY_RUN_HPP

#include "checkpoint_source.hpp"
#include "symcr/symcr.hpp"

namespace symcr::cli {

Report dry_run_restore(const LoadedCheckpoint& checkpoint, const Schema& reader, bool strict);

}  // namespace symcr::cli

#endif  // SYMCR_CLI_DRY_RUN_HPP
