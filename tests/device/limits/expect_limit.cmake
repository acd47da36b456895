# Generates the device profile's tables for SOURCE (symcr-gen GEN, --profile=device, into DIR)
# and preprocesses them with COMPILER: the build must stop at the generated #error naming LIMIT,
# as a firmware's build would.
#   cmake -DGEN=... -DCOMPILER=... -DINCLUDES=<dir;dir> -DSOURCE=... -DDIR=... -DLIMIT=... -P
set(includes "")
foreach(dir ${INCLUDES})
  list(APPEND includes -I${dir})
endforeach()
file(REMOVE_RECURSE ${DIR})
execute_process(COMMAND ${GEN} --profile=device --out-dir=${DIR} ${SOURCE} -- -std=c++17
                        ${includes}
                RESULT_VARIABLE generated OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT generated EQUAL 0)
  message(FATAL_ERROR "FAILED: symcr-gen refused ${SOURCE}:\n${output}")
endif()
execute_process(COMMAND ${COMPILER} -std=c++11 -E ${includes} ${DIR}/symcr_schema.cpp
                RESULT_VARIABLE compiled OUTPUT_QUIET ERROR_VARIABLE output)
if(compiled EQUAL 0)
  message(FATAL_ERROR "FAILED: the tables of ${SOURCE} compiled; expected the #error for ${LIMIT}")
endif()
string(FIND "${output}" "#error \"symcr-gen: the device profile's tables cannot hold ${LIMIT}; build with the host profile\"" at)
if(at EQUAL -1)
  message(FATAL_ERROR "FAILED: no #error for ${LIMIT}:\n${output}")
endif()
message(STATUS "the device profile's tables refuse ${LIMIT}")
