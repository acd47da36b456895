# Runs one command and checks its exit code and output (stdout and stderr together).
#   -DCOMMAND=<arg>@@<arg>...   the command line
#   -DEXPECT_EXIT=<n>
#   -DEXPECT=<regex>@@...       each must match the output
#   -DREJECT=<regex>@@...       none may match the output
#   -DVALIDATE_JSON=<python3>   stdout must parse as JSON
#   -DENV=<NAME=value>@@...     environment for the command
foreach(list COMMAND EXPECT REJECT ENV)
  string(REPLACE "@@" ";" ${list} "${${list}}")
endforeach()
set(environment)
if(ENV)
  set(environment ${CMAKE_COMMAND} -E env ${ENV})
endif()
execute_process(COMMAND ${environment} ${COMMAND}
                RESULT_VARIABLE exit_code OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
string(REPLACE ";" " " shown "${COMMAND}")
set(problems "")
if(NOT "${exit_code}" STREQUAL "${EXPECT_EXIT}")
  string(APPEND problems "exit code ${exit_code}, expected ${EXPECT_EXIT}\n")
endif()
foreach(regex IN LISTS EXPECT)
  if(NOT all MATCHES "${regex}")
    string(APPEND problems "output does not match: ${regex}\n")
  endif()
endforeach()
# A sanitizer build reports with exit code 1, which some tests expect: look for the report.
if(err MATCHES "(AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer|runtime error:)")
  string(APPEND problems "sanitizer report\n")
endif()
foreach(regex IN LISTS REJECT)
  if(all MATCHES "${regex}")
    string(APPEND problems "output matches what it must not: ${regex}\n")
  endif()
endforeach()
if(VALIDATE_JSON)
  string(RANDOM LENGTH 12 tag)
  set(json_file "${CMAKE_CURRENT_BINARY_DIR}/run_cli_${tag}.json")
  file(WRITE "${json_file}" "${out}")
  execute_process(COMMAND ${VALIDATE_JSON} -m json.tool "${json_file}"
                  RESULT_VARIABLE json_code OUTPUT_QUIET ERROR_VARIABLE json_err)
  file(REMOVE "${json_file}")
  if(NOT json_code EQUAL 0)
    string(APPEND problems "stdout is not valid JSON: ${json_err}\n")
  endif()
endif()
if(problems)
  message(FATAL_ERROR "${shown}\n${problems}--- output ---\n${all}")
endif()
message(STATUS "${shown}: ok")
