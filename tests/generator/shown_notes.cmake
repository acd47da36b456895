# --shown-notes: of several generation steps sharing one file (the targets of one build), only
# the first prints a note; a step that fails prints its notes every time, since they explain it.
#   cmake -DGEN=<symcr-gen> -DDIAG=<diagnostics dir> -DFLAGS=<compiler flags> -DWORK=<dir>
#         -P shown_notes.cmake
file(REMOVE_RECURSE "${WORK}")
set(shown "${WORK}/symcr/shown-notes.txt")  # in a directory the steps create

# generate(<out> <source> <expected exit code>): the output of one generation step in <out>.
function(generate out source expected_result)
  execute_process(COMMAND "${GEN}" --shown-notes "${shown}" --out-dir "${WORK}/${out}"
                          "${DIAG}/${source}" -- ${FLAGS}
                  RESULT_VARIABLE result OUTPUT_VARIABLE text ERROR_VARIABLE text)
  if(NOT result EQUAL expected_result)
    message(FATAL_ERROR "${source}: exit ${result}, expected ${expected_result}\n${text}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

set(note "symcr-gen: note: 'copter.flightmode' points to polymorphic class 'Mode'")
generate(first polymorphic_members_only.cpp 0)
string(FIND "${first}" "${note}" at)
if(at EQUAL -1)
  message(FATAL_ERROR "the first step did not print the note:\n${first}")
endif()
generate(second polymorphic_members_only.cpp 0)
if(second MATCHES "note:")
  message(FATAL_ERROR "the second step printed the note again:\n${second}")
endif()

set(error_note "note: these skip lines remove every unrestorable value above")
foreach(attempt failing_once failing_again)
  generate(${attempt} reached_through.cpp 1)
  string(FIND "${${attempt}}" "${error_note}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "${attempt}: a failing step left out its notes:\n${${attempt}}")
  endif()
endforeach()
message("a note printed once; notes of a failing step printed each time")
