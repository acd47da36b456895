# No #include climbs out of a folder by "..": a path such as "../api/store.hpp" or
# "symcr/../../src/..." would reach a header past the include folders that keep the runtime's
# layers in order and the tools to the headers they name (runtime/CMakeLists.txt). Scans the
# sources under each of ROOTS (a '|'-separated list); fails naming every such line.
# SELF_TEST=<dir>: first proves the scan finds one, in a file it writes there.
# cmake -DROOTS=<dir;dir...> [-DSELF_TEST=<dir>] -P include_climbs.cmake
function(find_climbs roots out_var)
  set(found)
  foreach(root IN LISTS roots)
    file(GLOB_RECURSE sources ${root}/*.cpp ${root}/*.hpp ${root}/*.h ${root}/*.c ${root}/*.inc)
    foreach(source IN LISTS sources)
      file(STRINGS ${source} lines REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<][^\">]*\\.\\.[/\\\\]")
      foreach(line IN LISTS lines)
        list(APPEND found "${source}: ${line}")
      endforeach()
    endforeach()
  endforeach()
  set(${out_var} "${found}" PARENT_SCOPE)
endfunction()

if(SELF_TEST)
  file(MAKE_DIRECTORY ${SELF_TEST})
  file(WRITE ${SELF_TEST}/climbs.cpp "#include \"ok.hpp\"\n  #  include <symcr/../../src/api/x.hpp>\n")
  find_climbs(${SELF_TEST} climbs)
  list(LENGTH climbs count)
  if(NOT count EQUAL 1)
    message(FATAL_ERROR "the scan should find the one climbing #include it wrote: ${climbs}")
  endif()
endif()
string(REPLACE "|" ";" roots "${ROOTS}")
find_climbs("${roots}" climbs)
if(climbs)
  list(JOIN climbs "\n" text)
  message(FATAL_ERROR "#include climbing out of its folder (name the header by its folder "
                      "on the include path instead):\n${text}")
endif()
message(STATUS "no #include climbs out of its folder")
