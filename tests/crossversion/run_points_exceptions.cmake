# ctest driver: an exit point is not reached when an exception leaves the function.
#   -DPROGRAM=<exe> -DSTORE=<file> -P run_points_exceptions.cmake
file(REMOVE "${STORE}")
set(ENV{SYMCR_STORE} "${STORE}")
execute_process(COMMAND "${PROGRAM}" save RESULT_VARIABLE saved OUTPUT_VARIABLE save_output)
if(NOT saved EQUAL 0 OR NOT save_output MATCHES "caught: negative level")
  message(FATAL_ERROR "save run failed (${saved}): ${save_output}")
endif()
execute_process(COMMAND "${PROGRAM}" load RESULT_VARIABLE loaded OUTPUT_VARIABLE output
                ERROR_VARIABLE errors)
if(NOT loaded EQUAL 0 OR NOT output STREQUAL "level=7 at program.cpp:22\n")
  message(FATAL_ERROR "expected level=7 (the value at the last normal exit) at program.cpp:22 (the user's file and line), got:\n${output}\n${errors}")
endif()
if(NOT errors MATCHES "restored checkpoint #1 ")
  message(FATAL_ERROR "expected one checkpoint (the throwing exit is not one):\n${errors}")
endif()
