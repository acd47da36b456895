# ctest driver: what a restore point does when it cannot restore, and a checkpoint point that
# cannot save.
#   -DCONTINUE=<v1 with on_failure=continue> -DCONTINUE_INITIAL=<its output without a restore>
#   -DSTOP=<v1 with on_failure=stop> -DV0=<a saving program> -DSTORE=<file>
#   -P run_points_failures.cmake
function(run name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output
                  ERROR_VARIABLE errors)
  set(${name}_result "${result}" PARENT_SCOPE)
  set(${name}_output "${output}" PARENT_SCOPE)
  set(${name}_errors "${errors}" PARENT_SCOPE)
endfunction()
function(expect condition message)
  if(NOT ${condition})
    message(FATAL_ERROR "${message}")
  endif()
endfunction()

set(ENV{SYMCR_STORE} "${STORE}")

# No store yet: the initial state, and the restore point creates no file.
file(REMOVE "${STORE}")
run(fresh "${CONTINUE}")
if(NOT fresh_result EQUAL 0 OR NOT fresh_output STREQUAL CONTINUE_INITIAL)
  message(FATAL_ERROR "without a store v1 must run from its initial state:\n${fresh_output}\n${fresh_errors}")
endif()
if(EXISTS "${STORE}" OR NOT fresh_errors MATCHES "no store at")
  message(FATAL_ERROR "a restore point without a store must say so and create nothing:\n${fresh_errors}")
endif()

# A store file that is not a store: on_failure=continue logs the report and runs from the
# initial state; on_failure=stop exits with status 1. Neither touches the file.
string(REPEAT "not a checkpoint store " 300 garbage)
file(WRITE "${STORE}" "${garbage}")
file(SHA256 "${STORE}" before)
run(continue "${CONTINUE}")
if(NOT continue_result EQUAL 0 OR NOT continue_output STREQUAL CONTINUE_INITIAL)
  message(FATAL_ERROR "on_failure=continue must run from the initial state:\n${continue_output}\n${continue_errors}")
endif()
if(NOT continue_errors MATCHES "restore failed; carrying on from the initial state")
  message(FATAL_ERROR "on_failure=continue must log the failed restore:\n${continue_errors}")
endif()
run(stop "${STOP}")
if(NOT stop_result EQUAL 1 OR NOT stop_errors MATCHES "stopping the program")
  message(FATAL_ERROR "on_failure=stop must exit with status 1 (got ${stop_result}):\n${stop_output}\n${stop_errors}")
endif()
if(stop_output MATCHES "resumed")
  message(FATAL_ERROR "on_failure=stop must stop before the function runs:\n${stop_output}")
endif()
file(SHA256 "${STORE}" after)
if(NOT before STREQUAL after)
  message(FATAL_ERROR "a failed restore changed the store file")
endif()

# A store that cannot be written: the program runs on and says so once, not at every point.
set(ENV{SYMCR_STORE} "${STORE}.missing-directory/store")
run(unsaved "${V0}")
if(NOT unsaved_result EQUAL 0)
  message(FATAL_ERROR "a failing checkpoint point must not stop the program:\n${unsaved_errors}")
endif()
string(REGEX MATCHALL "checkpoint failed" failures "${unsaved_errors}")
list(LENGTH failures count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "a failing checkpoint must be logged once (got ${count}):\n${unsaved_errors}")
endif()
message(STATUS "restore and checkpoint failures at points behave as documented")
