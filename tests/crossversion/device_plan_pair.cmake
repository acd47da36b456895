# ctest driver: the device profile's cross-version restore (through the device plan image made
# for v0's schema) equals the host's restore, value for value.
#   1. v0 saves CHECKPOINT;
#   2. v1 restores it in-process (its checks decide) and saves the restored state (HOST);
#   3. v1 restores it through the device profile's plan and saves the result (DEVICE);
#   4. `symcr diff HOST DEVICE` finds no difference.
#   cmake -DV0=<exe> -DV1=<exe> -DCLI=<symcr> -DDIR=<dir> -P device_plan_pair.cmake
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${ARGN}\nfailed (${result}):\n${out}${err}")
  endif()
  message("${out}${err}")
endfunction()
step("${V0}" "${DIR}/v0.ckpt")
step("${CMAKE_COMMAND}" -E env "XV_RESAVE=${DIR}/host.ckpt" "${V1}" "${DIR}/v0.ckpt")
step("${CMAKE_COMMAND}" -E env XV_DEVICE_PLAN=1 "XV_RESAVE=${DIR}/device.ckpt"
     "${V1}" "${DIR}/v0.ckpt")
step("${CLI}" diff "${DIR}/host.ckpt" "${DIR}/device.ckpt")
