// Exit codes of every symcr subcommand, part of the CLI's contract with scripts.
#ifndef SYMCR_CLI_EXIT_CODES_HPP
#define SYMCR_CLI_EXIT_CODES_HPP

namespace symcr::cli {

inline constexpr int kExitOk = 0;       // nothing to report
inline constexpr int kExitFinding = 1;  // a finding: invalid (verify), a difference (diff),
                                        // a rejected or, with --strict, lossy decision (plan)
inline constexpr int kExitError = 2;    // usage error, unreadable or corrupt input

}  // namespace symcr::cli

#endif  // SYMCR_CLI_EXIT_CODES_HPP
