# A compile_commands.json written for g++ (no -std, a g++ semantics flag, a flag Clang does not
# know): symcr-gen parses the source as g++ would and names the flag it ignores.
#   cmake -DGEN=<symcr-gen> -DCXX=<g++> -DSOURCE_DIR=<this dir> -DINCLUDE=<runtime/include>
#         -DOUT=<scratch dir> -P run.cmake
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
file(WRITE "${OUT}/compile_commands.json" "[{\"directory\": \"${OUT}\", \"file\": \"${SOURCE_DIR}/log.cpp\",
  \"arguments\": [\"${CXX}\", \"-I${INCLUDE}\", \"-fsingle-precision-constant\",
                  \"-fsymcr-no-such-gcc-flag\", \"-Wall\", \"-c\", \"-o\", \"log.o\",
                  \"${SOURCE_DIR}/log.cpp\"]}]")
execute_process(COMMAND "${CXX}" -I${INCLUDE} -fsingle-precision-constant -fsyntax-only
                        "${SOURCE_DIR}/log.cpp" RESULT_VARIABLE gxx ERROR_VARIABLE gxx_errors)
if(NOT gxx EQUAL 0)
  message(FATAL_ERROR "the source must be valid for g++ as it is: ${gxx_errors}")
endif()
execute_process(COMMAND "${GEN}" -p "${OUT}" --out-dir "${OUT}/gen" --report "${SOURCE_DIR}/log.cpp"
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "symcr-gen failed (${result})")
endif()
foreach(expected "warning: ignored compiler flag\\(s\\) Clang does not know: -fsymcr-no-such-gcc-flag"
                 "root last_record: LogRecord" "std::optional<int32>")
  if(NOT "${out}${err}" MATCHES "${expected}")
    message(FATAL_ERROR "output does not match: ${expected}")
  endif()
endforeach()
if("${err}" MATCHES "-fsingle-precision-constant")
  message(FATAL_ERROR "-fsingle-precision-constant was dropped, not translated")
endif()
