# Runs symcr-gen over a real-headers program and compiles the same TU, printing both times
# (no timing assertion), then checks that the roots reached only what they should.
#   cmake -DGEN=<symcr-gen> -DCXX=<compiler> -DSOURCE=<file> -DINCLUDE=<dir> -DOUT=<dir> -P ...
file(MAKE_DIRECTORY "${OUT}")
string(TIMESTAMP start "%s%f")
execute_process(COMMAND "${GEN}" --report --out-dir "${OUT}" "${SOURCE}" --
                        -std=c++17 -I${INCLUDE}
                RESULT_VARIABLE gen_result OUTPUT_VARIABLE report ERROR_VARIABLE gen_errors)
string(TIMESTAMP middle "%s%f")
execute_process(COMMAND "${CXX}" -std=c++17 -O2 -I${INCLUDE} -c "${SOURCE}" -o "${OUT}/program.o"
                RESULT_VARIABLE cxx_result ERROR_VARIABLE cxx_errors)
string(TIMESTAMP end "%s%f")
if(NOT gen_result EQUAL 0)
  message(FATAL_ERROR "symcr-gen failed:\n${gen_errors}")
endif()
if(NOT cxx_result EQUAL 0)
  message(FATAL_ERROR "compiling failed:\n${cxx_errors}")
endif()
math(EXPR gen_ms "(${middle} - ${start}) / 1000")
math(EXPR cxx_ms "(${end} - ${middle}) / 1000")
message("${report}")
message("generation (symcr-gen, parse + walk + emit): ${gen_ms} ms")
message("compilation (${CXX} -O2 -c, same TU):        ${cxx_ms} ms")
foreach(expected "reaches 11 type\\(s\\)" "skipped lock: SYMCR_SKIP" "skipped sink: SYMCR_SKIP"
                 "skipped worker: SYMCR_SKIP" "skipped rng: SYMCR_SKIP")
  if(NOT report MATCHES "${expected}")
    message(FATAL_ERROR "report lacks: ${expected}")
  endif()
endforeach()
foreach(unexpected "regex" "mutex" "thread" "function<" "mersenne")
  if(report MATCHES "(Struct|Container|String) [^\n]*${unexpected}")
    message(FATAL_ERROR "the schema reaches a type it should not: ${unexpected}")
  endif()
endforeach()
