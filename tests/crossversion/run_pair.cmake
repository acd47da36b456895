# ctest driver: run v0 (checkpoints), then v1 (restores and checks); v1's exit code decides.
#   cmake -DV0=<exe> -DV1=<exe> -DCHECKPOINT=<file> -P run_pair.cmake
file(REMOVE "${CHECKPOINT}")
execute_process(COMMAND "${V0}" "${CHECKPOINT}" RESULT_VARIABLE v0_result)
if(NOT v0_result EQUAL 0)
  message(FATAL_ERROR "v0 (${V0}) failed: ${v0_result}")
endif()
execute_process(COMMAND "${V1}" "${CHECKPOINT}" RESULT_VARIABLE v1_result)
if(NOT v1_result EQUAL 0)
  message(FATAL_ERROR "v1 (${V1}) failed: ${v1_result}")
endif()
