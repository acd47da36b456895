# cmake -DSYMCR_SOURCE=<symcr checkout> -DGEN=<symcr-gen> -DSOURCE=<this dir> -DWORK=<scratch>
#       -P run.cmake
file(REMOVE_RECURSE "${WORK}")
execute_process(COMMAND ${CMAKE_COMMAND} -S "${SOURCE}" -B "${WORK}" -G Ninja
                        "-DSYMCR_SOURCE=${SYMCR_SOURCE}" "-DSYMCR_GEN_EXECUTABLE=${GEN}"
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "configure failed:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK}" --target app_plain_library
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "a program linking a library without roots must build:\n${out}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build "${WORK}" --target app_roots_in_library
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(result EQUAL 0)
  message(FATAL_ERROR "roots defined in a linked library were silently left out")
endif()
foreach(root "nav::home" "nav::waypoint_index")
  if(NOT out MATCHES "nav.cpp:[0-9]+:[0-9]+: error: root '${root}' is defined in '[^']*nav.cpp', a source of a static library")
    message(FATAL_ERROR "no diagnostic naming ${root}")
  endif()
endforeach()
