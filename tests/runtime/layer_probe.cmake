# Proves that a runtime layer cannot include a header of the layer above it
# (runtime/CMakeLists.txt): with exactly the include folders the layer's sources are compiled
# with, its own header OWN compiles and the upper layer's header UPPER is not found.
# cmake -DCXX=<compiler> -DFLAGS=<response file> -DOWN=<header> -DUPPER=<header> -DWORK=<dir>
#   -P layer_probe.cmake
file(MAKE_DIRECTORY ${WORK})
function(compile_probe header result_var output_var)
  string(MAKE_C_IDENTIFIER ${header} name)
  set(source ${WORK}/probe_${name}.cpp)
  file(WRITE ${source} "#include \"${header}\"\n")
  execute_process(COMMAND ${CXX} @${FLAGS} -fsyntax-only ${source}
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE out)
  set(${result_var} ${result} PARENT_SCOPE)
  set(${output_var} "${out}" PARENT_SCOPE)
endfunction()

compile_probe(${OWN} own_result own_output)
if(NOT own_result EQUAL 0)
  message(FATAL_ERROR "the layer's own header ${OWN} does not compile with its flags:\n"
                      "${own_output}")
endif()
compile_probe(${UPPER} upper_result upper_output)
if(upper_result EQUAL 0)
  message(FATAL_ERROR "${UPPER}, a header of a higher layer, compiles with this layer's flags")
endif()
if(NOT upper_output MATCHES "${UPPER}: No such file or directory")
  message(FATAL_ERROR "${UPPER} failed for another reason than not being found:\n"
                      "${upper_output}")
endif()
message(STATUS "${OWN} compiles; ${UPPER} is not found, as the layers require")
