# Proves that a part of symcr cannot include a header it is not meant to (runtime/CMakeLists.txt):
# with exactly the include folders its sources are compiled with, a header it may include,
# ALLOWED, compiles and the header FORBIDDEN is not found. For a runtime layer, FORBIDDEN is a
# header of the layer above it; for a tool, an internal header it has not named. LINKS, if
# given, is a file listing the part's link libraries, which must not bring in all of the
# runtime's internal headers (symcr_runtime_internal). SOURCE_DIR, for a tool, is the runtime's
# source folder: everything ALLOWED pulls in must come through the tool's own folder of links,
# none straight from there (which a header could reach beside itself, unlisted).
# cmake -DCXX=<compiler> -DFLAGS=<response file> -DALLOWED=<header> -DFORBIDDEN=<header>
#   -DWORK=<dir> [-DLINKS=<file>] [-DSOURCE_DIR=<runtime/>] -P include_probe.cmake
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

if(LINKS)
  file(READ ${LINKS} links)
  if(links MATCHES "symcr_runtime_internal")
    message(FATAL_ERROR "links symcr_runtime_internal, which reaches every internal header: "
                        "${links}")
  endif()
endif()
compile_probe(${ALLOWED} allowed_result allowed_output)
if(NOT allowed_result EQUAL 0)
  message(FATAL_ERROR "${ALLOWED}, which it may include, does not compile with its flags:\n"
                      "${allowed_output}")
endif()
if(SOURCE_DIR)
  string(MAKE_C_IDENTIFIER ${ALLOWED} name)
  execute_process(COMMAND ${CXX} @${FLAGS} -M ${WORK}/probe_${name}.cpp
                  RESULT_VARIABLE result OUTPUT_VARIABLE dependencies ERROR_VARIABLE dependencies)
  string(REGEX MATCH "${SOURCE_DIR}/(src|device/src)/[^ \n]*" unlisted "${dependencies}")
  if(NOT result EQUAL 0 OR unlisted)
    message(FATAL_ERROR "${ALLOWED} reaches ${unlisted} past the tool's list:\n${dependencies}")
  endif()
endif()
compile_probe(${FORBIDDEN} forbidden_result forbidden_output)
if(forbidden_result EQUAL 0)
  message(FATAL_ERROR "${FORBIDDEN}, which it may not include, compiles with its flags")
endif()
if(NOT forbidden_output MATCHES "${FORBIDDEN}['\"]? ?(file )?not found|${FORBIDDEN}: No such file or directory")
  message(FATAL_ERROR "${FORBIDDEN} failed for another reason than not being found:\n"
                      "${forbidden_output}")
endif()
message(STATUS "${ALLOWED} compiles; ${FORBIDDEN} is not found, as it should not be")
