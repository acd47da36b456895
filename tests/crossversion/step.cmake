# step(<command> <args>...): runs one step of a ctest driver script, stops the test with the
# command and its output when it fails, and prints its output; `out` holds it in the caller.
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${ARGN}\nfailed (${result}):\n${out}${err}")
  endif()
  message("${out}${err}")
  set(out "${out}" PARENT_SCOPE)
endfunction()
