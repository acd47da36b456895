# symcr-gen -j 8 over a compile database whose paths are relative to each entry's "directory"
# (as waf, make and bear write them): every unit's header exists only relative to its own
# directory (-I../inc), so a parse that resolves it against another unit's directory, or the
# process's, fails. Run a few times: parallel parses overlap differently each time.
#   cmake -DGEN=<symcr-gen> -DCXX=<g++> -DWORK=<scratch dir> -P run.cmake
set(units 8)
file(REMOVE_RECURSE "${WORK}")
# The compiler too is named relative to the directory: symcr-gen asks it for its default dialect
# (no -std= in the commands), and the sources need g++'s (gnu++17; Clang alone parses gnu++14).
file(MAKE_DIRECTORY "${WORK}/bin")
file(CREATE_LINK "${CXX}" "${WORK}/bin/g++" SYMBOLIC)
set(entries "")
set(sources "")
set(annotations "")
math(EXPR last "${units} - 1")
foreach(k RANGE ${last})
  set(unit "${WORK}/unit${k}")
  file(WRITE "${unit}/inc/state.h" "#pragma once\n#include <map>\n#include <string>\n#include \"detail.h\"\nstruct State${k} { int mode; Detail${k} detail; };\n")
  file(WRITE "${unit}/inc/detail.h" "#pragma once\n#include <vector>\nstruct Detail${k} { std::vector<int> samples; };\n")
  file(WRITE "${unit}/src/unit${k}.cpp"
       "#include <unordered_map>\n#include \"state.h\"\n"
       "#if __cplusplus < 201703L\n#error \"parsed in another dialect than the compiler's default\"\n#endif\n"
       "State${k} state${k};\n")
  file(MAKE_DIRECTORY "${unit}/build")
  if(entries)
    string(APPEND entries ",\n")
  endif()
  string(APPEND entries "{\"directory\": \"${unit}/build\", \"arguments\": [\"../../bin/g++\", \"-I../inc\", \"-c\", \"../src/unit${k}.cpp\", \"-o\", \"unit${k}.o\"], \"file\": \"../src/unit${k}.cpp\"}")
  list(APPEND sources "${unit}/src/unit${k}.cpp")
  string(APPEND annotations "checkpoint(state${k})\n")
endforeach()
file(WRITE "${WORK}/db/compile_commands.json" "[\n${entries}\n]\n")
file(WRITE "${WORK}/app.symcr" "${annotations}")

foreach(run 1 2 3)
  file(REMOVE_RECURSE "${WORK}/out")
  execute_process(COMMAND "${GEN}" -p "${WORK}/db" --annotations "${WORK}/app.symcr" -j 8
                          --out-dir "${WORK}/out" --depfile "${WORK}/out/gen.d" ${sources}
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "run ${run}: symcr-gen failed (${result}):\n${out}${err}")
  endif()
  file(READ "${WORK}/out/gen.d" depfile)
  file(READ "${WORK}/out/symcr_schema.cpp" schema)
  foreach(k RANGE ${last})
    # Each header by its absolute path, as the build's dependency tracking needs.
    foreach(header state detail)
      if(NOT depfile MATCHES "${WORK}/unit${k}/inc/${header}.h")
        message(FATAL_ERROR "run ${run}: the depfile lacks unit${k}/inc/${header}.h:\n${depfile}")
      endif()
    endforeach()
    if(NOT schema MATCHES "\"State${k}\"" OR NOT schema MATCHES "\"Detail${k}\"")
      message(FATAL_ERROR "run ${run}: State${k} or Detail${k} missing from the schema")
    endif()
  endforeach()
endforeach()
message("3 runs at -j 8: every unit's headers found, the depfile names them all")
