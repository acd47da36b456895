# ctest driver for pairs whose programs checkpoint and restore at program points: v0 runs and
# saves into the store at its point; v1 restores at its point and prints what it holds, which
# must equal EXPECT_FILE. The store's path comes from SYMCR_STORE.
#   cmake -DV0=<exe> -DV1=<exe> -DSTORE=<file> -DEXPECT_FILE=<file> -P run_points_pair.cmake
file(REMOVE "${STORE}")
set(ENV{SYMCR_STORE} "${STORE}")
execute_process(COMMAND "${V0}" RESULT_VARIABLE v0_result ERROR_VARIABLE v0_errors)
if(NOT v0_result EQUAL 0)
  message(FATAL_ERROR "v0 (${V0}) failed: ${v0_result}\n${v0_errors}")
endif()
if(NOT EXISTS "${STORE}")
  message(FATAL_ERROR "v0 wrote no store at ${STORE}\n${v0_errors}")
endif()
execute_process(COMMAND "${V1}" RESULT_VARIABLE v1_result OUTPUT_VARIABLE v1_output
                ERROR_VARIABLE v1_errors)
if(NOT v1_result EQUAL 0)
  message(FATAL_ERROR "v1 (${V1}) failed: ${v1_result}\n${v1_output}\n${v1_errors}")
endif()
file(READ "${EXPECT_FILE}" expected)
# A v1 with a restore hook prints the hook's calls first ("hook: ..."): the hook reports a
# successful restore and the runtime logs none; without a hook the runtime logs it.
if(expected MATCHES "^hook: ")
  if(v1_errors MATCHES "restored checkpoint #")
    message(FATAL_ERROR "with a hook set the runtime must leave a success to it:\n${v1_errors}")
  endif()
elseif(NOT v1_errors MATCHES "restored checkpoint #")
  message(FATAL_ERROR "v1 did not restore at its point:\n${v1_errors}")
endif()
if(NOT v1_output STREQUAL expected)
  message(FATAL_ERROR "v1 printed\n${v1_output}\nexpected\n${expected}\n(v1's log: ${v1_errors})")
endif()
message(STATUS "v1 restored at its point and printed the expected values:\n${v1_output}")
