# symcr_add_compatibility_test(<target> CHECKPOINTS <dir> [STRICT] [NAME <test name>])
#
# Adds a ctest that plans every checkpoint in <dir> (single-file checkpoints and stores; the
# directory is read when the test runs, so a file dropped into it is gated without configuring
# again) against <target>'s schema file (its SYMCR_SCHEMA_FILE: <target> must have been passed to
# symcr_add_checkpointing) with `symcr plan`, and fails when one of them would not restore:
# a failed restore, a rejected field, an unreadable file, and with STRICT any lossy decision. The
# test's output is the plan's matrix (one line per checkpoint) and the full report of each
# checkpoint that failed. A gate for CI: keep checkpoints of the releases in the field in <dir>,
# and a patch that cannot restore them fails the build's tests.
#
# The test is named symcr.compatibility.<target> unless NAME is given. The CLI is, in order: the
# cache variable SYMCR_CLI_EXECUTABLE, the target symcr::cli (built in this project), or `symcr`
# found on PATH.
include_guard(GLOBAL)

function(symcr_add_compatibility_test target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "STRICT" "CHECKPOINTS;NAME" "")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "symcr_add_compatibility_test: unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT TARGET ${target})
    message(FATAL_ERROR "symcr_add_compatibility_test: '${target}' is not a target")
  endif()
  get_target_property(schema_file ${target} SYMCR_SCHEMA_FILE)
  if(NOT schema_file)
    message(FATAL_ERROR "symcr_add_compatibility_test: '${target}' has no schema file: call "
                        "symcr_add_checkpointing(${target} ...) first")
  endif()
  if(NOT arg_CHECKPOINTS)
    message(FATAL_ERROR "symcr_add_compatibility_test: CHECKPOINTS <dir> is required")
  endif()
  get_filename_component(checkpoints "${arg_CHECKPOINTS}" ABSOLUTE)
  if(NOT IS_DIRECTORY "${checkpoints}")
    message(FATAL_ERROR "symcr_add_compatibility_test: ${checkpoints} is not a directory")
  endif()

  if(SYMCR_CLI_EXECUTABLE)
    set(cli "${SYMCR_CLI_EXECUTABLE}")
  elseif(TARGET symcr::cli)
    set(cli "$<TARGET_FILE:symcr::cli>")
  else()
    find_program(SYMCR_CLI_FOUND symcr)
    if(NOT SYMCR_CLI_FOUND)
      message(FATAL_ERROR "symcr_add_compatibility_test: no symcr CLI. Build it "
                          "(SYMCR_BUILD_CLI=ON) or set SYMCR_CLI_EXECUTABLE.")
    endif()
    set(cli "${SYMCR_CLI_FOUND}")
  endif()

  set(name "symcr.compatibility.${target}")
  if(arg_NAME)
    set(name "${arg_NAME}")
  endif()
  set(strict)
  if(arg_STRICT)
    set(strict --strict)
  endif()
  add_test(NAME ${name} COMMAND "${cli}" plan "${checkpoints}" --schema "${schema_file}" ${strict})
endfunction()
