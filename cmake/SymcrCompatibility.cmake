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
# cache variable SYMCR_CLI_EXECUTABLE, the target symcr::cli (built in this project, or imported
# by find_package(symcr), whose sdk component installs it), or `symcr` found on PATH.
#
# add_test() is silently ignored where testing is not enabled, so the function enables testing
# (enable_testing()) at the end of the calling directory and of every directory above it: the
# gate exists whether or not the project calls enable_testing() or include(CTest). Only a
# project that turned testing off with BUILD_TESTING=OFF gets no gate, and a configure message
# says so.
include_guard(GLOBAL)
include(${CMAKE_CURRENT_LIST_DIR}/SymcrCheckpointing.cmake)  # _symcr_tool_missing

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
      _symcr_tool_missing(symcr_add_compatibility_test "symcr CLI" SYMCR_BUILD_CLI
                          SYMCR_CLI_EXECUTABLE)
    endif()
    set(cli "${SYMCR_CLI_FOUND}")
  endif()

  set(name "symcr.compatibility.${target}")
  if(arg_NAME)
    set(name "${arg_NAME}")
  endif()
  if(DEFINED BUILD_TESTING AND NOT BUILD_TESTING)
    message(STATUS "symcr_add_compatibility_test: BUILD_TESTING is OFF: no test ${name}")
    return()
  endif()
  # enable_testing() called here would only set a variable of this function's scope: it is
  # deferred to the end of this directory and of each one above it (still being configured,
  # this one being inside their add_subdirectory), so that ctest in the top build directory
  # reaches the test.
  set(directory "${CMAKE_CURRENT_SOURCE_DIR}")
  while(directory)
    cmake_language(DEFER DIRECTORY "${directory}" CALL enable_testing)
    get_directory_property(directory DIRECTORY "${directory}" PARENT_DIRECTORY)
  endwhile()
  set(strict)
  if(arg_STRICT)
    set(strict --strict)
  endif()
  add_test(NAME ${name} COMMAND "${cli}" plan "${checkpoints}" --schema "${schema_file}" ${strict})
endfunction()
