# ctest driver for `symcr plan` over several checkpoints (the compatibility gate's command):
#   cmake -DCLI=<symcr> -DV0=<exe> -DSCHEMA1=<v1's schema file> -DDIR=<scratch> -P plan_matrix.cmake
# v0 writes two checkpoints into DIR, next to a file that is no checkpoint; planned as a
# directory against v1's schema file, the matrix has a line each (the two rejecting a field,
# the third unreadable), then the report of each checkpoint that would not restore cleanly, and
# the exit status is 2 (a file could not be read). Without the bad file it is 1, and --json
# gives one object per checkpoint.
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
foreach(name a b)
  execute_process(COMMAND "${V0}" "${DIR}/${name}.ckpt" RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "v0 (${V0}) failed: ${result}")
  endif()
endforeach()
file(WRITE "${DIR}/c.txt" "not a checkpoint")

function(plan expected_exit)
  execute_process(COMMAND "${CLI}" plan ${ARGN} --schema "${SCHEMA1}"
                  RESULT_VARIABLE result OUTPUT_VARIABLE text ERROR_VARIABLE errors)
  message(STATUS "symcr plan ${ARGN} (exit ${result}):\n${text}${errors}")
  if(NOT result EQUAL expected_exit)
    message(FATAL_ERROR "symcr plan ${ARGN} exited with ${result}, expected ${expected_exit}")
  endif()
  set(text "${text}" PARENT_SCOPE)
endfunction()
function(expect pattern)
  if(NOT text MATCHES "${pattern}")
    message(FATAL_ERROR "symcr plan's output does not match '${pattern}'")
  endif()
endfunction()

plan(2 "${DIR}")
expect("checkpoint +slot +schema +outcome")
expect("/a\\.ckpt +- +[0-9a-f]+ +rejects 1, 1 lossy\n")
expect("/b\\.ckpt +- +[0-9a-f]+ +rejects 1, 1 lossy\n")
expect("/c\\.txt +- +- +unreadable: ")
expect("0 of 3 would restore; 2 would not, 1 unreadable")
# The report of each failing checkpoint, with the field that fails it.
string(REGEX MATCHALL "sensors\\.narrowed_overflows +rejected" reports "${text}")
list(LENGTH reports count)
if(NOT count EQUAL 2)
  message(FATAL_ERROR "expected the report of both failing checkpoints, got ${count}")
endif()

plan(1 "${DIR}/a.ckpt" "${DIR}/b.ckpt")
expect("0 of 2 would restore; 2 would not, 0 unreadable")

plan(1 "${DIR}/a.ckpt" "${DIR}/b.ckpt" --json)
expect("\"checkpoints\": *\\[")
string(REGEX MATCHALL "\"would_restore\": *true" restoring "${text}")
string(REGEX MATCHALL "\"rejected\": *1" rejecting "${text}")
list(LENGTH rejecting count)
if(restoring STREQUAL "" OR NOT count EQUAL 2)
  message(FATAL_ERROR "--json: expected two plans that restore with one rejection each")
endif()
message(STATUS "symcr plan over several checkpoints gives the matrix and the failing reports")
