# ctest driver: the device profile's cross-version restore (through the device plan image made
# for v0's schema) equals the host's restore, value for value.
#   1. v0 saves CHECKPOINT;
#   2. v1 restores it in-process (its checks decide) and saves the restored state (HOST);
#   3. v1 restores it through the device profile's plan and saves the result (DEVICE);
#   4. `symcr diff HOST DEVICE` finds no difference; or the device refused the checkpoint
#      whole (Rejected) where the host's report rejected a value.
#   cmake -DV0=<exe> -DV1=<exe> -DCLI=<symcr> -DDIR=<dir> -P device_plan_pair.cmake
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
include(${CMAKE_CURRENT_LIST_DIR}/step.cmake)
step("${V0}" "${DIR}/v0.ckpt")
step("${CMAKE_COMMAND}" -E env "XV_RESAVE=${DIR}/host.ckpt" "${V1}" "${DIR}/v0.ckpt")
set(host_report "${out}")
execute_process(COMMAND "${CMAKE_COMMAND}" -E env XV_DEVICE_PLAN=1 "XV_RESAVE=${DIR}/device.ckpt"
                        "${V1}" "${DIR}/v0.ckpt"
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
# The device restores all or nothing: a value the host leaves out (value-level "rejected", this
# build's value kept) refuses the whole checkpoint there, and nothing else may.
if(NOT result EQUAL 0)
  if("${out}${err}" MATCHES "refused by its range or validator" AND
     host_report MATCHES "[ \t]rejected[ \t]")
    message("the device refused the checkpoint whole, where the host rejected a value")
    return()
  endif()
  message(FATAL_ERROR "the device's restore failed (${result})")
endif()
step("${CLI}" diff "${DIR}/host.ckpt" "${DIR}/device.ckpt")
