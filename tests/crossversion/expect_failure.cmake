# ctest driver for wrong annotations: the command must fail and print a message matching
# EXPECT (a regular expression), e.g. "bad.cpp:12:9: error: unknown variable".
#   cmake -DCOMMAND=<;-list> -DEXPECT=<regex> [-DREJECT=<regex>] -P expect_failure.cmake
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE result OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
message("${out}${err}")
if(result EQUAL 0)
  message(FATAL_ERROR "expected failure, got success")
endif()
if(NOT "${out}${err}" MATCHES "${EXPECT}")
  message(FATAL_ERROR "output does not match: ${EXPECT}")
endif()
if(REJECT AND "${out}${err}" MATCHES "${REJECT}")
  message(FATAL_ERROR "output matches what it must not: ${REJECT}")
endif()
