# ctest driver: `symcr convert` + the device profile's restore equals the host's restore, value
# for value.
#   1. v0 saves CHECKPOINT;
#   2. v1 restores it in-process (its checks decide), saving the state it started from
#      (INITIAL) and the restored state (HOST);
#   3. `symcr convert CHECKPOINT --schema SCHEMA1 --initial INITIAL -o CONVERTED`;
#   4. v1 restores CONVERTED through the device profile and saves the result (DEVICE);
#   5. `symcr diff HOST DEVICE` finds no difference.
#   cmake -DV0=<exe> -DV1=<exe> -DCLI=<symcr> -DSCHEMA1=<file> -DDIR=<dir> -P convert_pair.cmake
# With -DREFUSE=<regex> [-DCONVERT_ARGS=<args>]: after step 1, the conversion (without
# --initial, with CONVERT_ARGS) must fail with exit code 1 or 2, print REFUSE, and write nothing.
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
include(${CMAKE_CURRENT_LIST_DIR}/step.cmake)
step("${V0}" "${DIR}/v0.ckpt")
if(DEFINED REFUSE)
  execute_process(COMMAND "${CLI}" convert "${DIR}/v0.ckpt" --schema "${SCHEMA1}" ${CONVERT_ARGS}
                          -o "${DIR}/converted.ckpt"
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(result EQUAL 0 OR NOT "${out}${err}" MATCHES "${REFUSE}" OR EXISTS "${DIR}/converted.ckpt")
    message(FATAL_ERROR "expected a refusal matching '${REFUSE}' and no output; exit ${result}")
  endif()
  return()
endif()
step("${CMAKE_COMMAND}" -E env "XV_INITIAL=${DIR}/initial.ckpt" "XV_RESAVE=${DIR}/host.ckpt"
     "${V1}" "${DIR}/v0.ckpt")
step("${CLI}" convert "${DIR}/v0.ckpt" --schema "${SCHEMA1}" --initial "${DIR}/initial.ckpt"
     -o "${DIR}/converted.ckpt")
step("${CMAKE_COMMAND}" -E env XV_DEVICE=1 "XV_RESAVE=${DIR}/device.ckpt"
     "${V1}" "${DIR}/converted.ckpt")
step("${CLI}" diff "${DIR}/host.ckpt" "${DIR}/device.ckpt")
