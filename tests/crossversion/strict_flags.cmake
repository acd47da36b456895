# ctest driver: a pair's generated sources (FILES: its wrappers and schema source) compile
# without one diagnostic in symcr's code under the strict warning flags autopilot builds use.
#   cmake -DCXX=<compiler> -DFLAGS=<;-list> [-DCC=<compiler> -DC_FLAGS=<;-list>]
#         -DFILES=<;-list> -DOWN_CODE=<;-list of directories>
#         [-DFILE_INCLUDES=<;-list of <folder>=<include folder>>] -P strict_flags.cmake
# A C wrapper (.c) is compiled with CC and C_FLAGS, the rest with CXX and FLAGS; a file under a
# <folder> of FILE_INCLUDES also with -I<include folder> (a pair whose versions each have their
# own header folder, with headers of the same names).
# The flags are given as warnings, not -Werror, so that every diagnostic is printed: one in a
# file under OWN_CODE (the generated directory, symcr's headers) fails the check, as -Werror
# would fail the user's build. The program's own sources, which each wrapper includes, may warn:
# their code is not symcr's.
set(failures "")
foreach(file IN LISTS FILES)
  set(compiler ${CXX})
  set(flags ${FLAGS})
  if(file MATCHES "\\.c$")
    set(compiler ${CC})
    set(flags ${C_FLAGS})
  endif()
  foreach(pair IN LISTS FILE_INCLUDES)
    string(REGEX MATCH "^([^=]+)=(.+)$" matched "${pair}")
    string(FIND "${file}" "${CMAKE_MATCH_1}/" at)
    if(at EQUAL 0)
      list(APPEND flags -I${CMAKE_MATCH_2})
    endif()
  endforeach()
  execute_process(COMMAND ${compiler} ${flags} -c ${file} -o ${file}.strict.o
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  file(REMOVE ${file}.strict.o)
  string(REPLACE "\n" ";" lines "${out}${err}")
  set(own "")
  foreach(line IN LISTS lines)
    if(NOT line MATCHES "^([^:]+):[0-9]+:[0-9]+: (warning|error):")
      continue()
    endif()
    foreach(dir IN LISTS OWN_CODE)
      string(FIND "${CMAKE_MATCH_1}" "${dir}/" at)
      if(at EQUAL 0)
        string(APPEND own "${line}\n")
        break()
      endif()
    endforeach()
  endforeach()
  if(NOT result EQUAL 0 AND own STREQUAL "")
    # An error elsewhere (the program's source) would hide what symcr's code does.
    string(APPEND failures "${file} did not compile:\n${out}${err}\n")
  elseif(NOT own STREQUAL "")
    string(APPEND failures "${file} (${flags}):\n${own}")
  endif()
endforeach()
if(NOT failures STREQUAL "")
  message(FATAL_ERROR "symcr's code is not clean under the strict flags:\n${failures}")
endif()
list(LENGTH FILES count)
message("${count} generated source(s) clean under ${FLAGS} (C: ${C_FLAGS})")
