# ctest driver of the firmware update under QEMU: V0 runs and checkpoints, then V1 boots with the
# backup SRAM as V0 left it and restores V0's checkpoint.
#   cmake -DQEMU=<qemu-system-arm> -DV0=<elf> -DV1=<elf> -DDIR=<dir> -P run_update.cmake
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
foreach(image V0 V1)
  execute_process(COMMAND "${QEMU}" -M mps2-an386 -nographic
                          -semihosting-config enable=on,target=native -kernel "${${image}}"
                  WORKING_DIRECTORY "${DIR}" TIMEOUT 60
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}${err}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${image} exited with ${result}")
  endif()
endforeach()
