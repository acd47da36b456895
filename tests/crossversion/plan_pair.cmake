# ctest driver for a build's schema file:
#   cmake -DV0=<exe> -DCLI=<symcr> -DSCHEMA0=<v0's schema file> -DSCHEMA1=<v1's schema file>
#         -DCHECKPOINT=<file> -DEXPECT_EXIT=<0|1> [-DEXPECT=<regex;...>] -P plan_pair.cmake
# v0 checkpoints; the schema hash in v0's schema file, written at build time, must be the one
# v0 computed for its own schema at run time (both printed by `symcr inspect`); then
# `symcr plan <checkpoint> --schema <v1's schema file>` must exit with EXPECT_EXIT and print
# every EXPECT regex.
file(REMOVE "${CHECKPOINT}")
execute_process(COMMAND "${V0}" "${CHECKPOINT}" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "v0 (${V0}) failed: ${result}")
endif()

function(schema_hash file out)
  execute_process(COMMAND "${CLI}" inspect "${file}" RESULT_VARIABLE result
                  OUTPUT_VARIABLE text ERROR_VARIABLE errors)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "symcr inspect ${file} failed (${result}): ${errors}")
  endif()
  if(NOT text MATCHES "schema_hash +([0-9a-f]+)")
    message(FATAL_ERROR "no schema_hash in `symcr inspect ${file}`:\n${text}")
  endif()
  set(${out} "${CMAKE_MATCH_1}" PARENT_SCOPE)
endfunction()
schema_hash("${CHECKPOINT}" run_time)
schema_hash("${SCHEMA0}" build_time)
if(NOT run_time STREQUAL build_time)
  message(FATAL_ERROR "schema file ${SCHEMA0} has hash ${build_time}, the program computes "
                      "${run_time}")
endif()

execute_process(COMMAND "${CLI}" plan "${CHECKPOINT}" --schema "${SCHEMA1}"
                RESULT_VARIABLE result OUTPUT_VARIABLE text ERROR_VARIABLE errors)
message(STATUS "symcr plan (exit ${result}):\n${text}${errors}")
if(NOT result EQUAL EXPECT_EXIT)
  message(FATAL_ERROR "symcr plan exited with ${result}, expected ${EXPECT_EXIT}")
endif()
foreach(pattern IN LISTS EXPECT)
  if(NOT text MATCHES "${pattern}")
    message(FATAL_ERROR "symcr plan's output does not match '${pattern}'")
  endif()
endforeach()
