# ctest driver: `symcr plan` foresees the restore, entry by entry (docs/resolution.md, Plans).
#   cmake -DV0=<exe> -DV1=<exe> -DCLI=<symcr> -DSCHEMA1=<v1's schema file> -DDIR=<scratch dir>
#         -P plan_restore_pair.cmake
# v0 checkpoints; v1 restores it and writes its first restore's report (XV_REPORT,
# report_file.h); `symcr plan <checkpoint> --schema <v1's schema file> --json` must list the
# same entries in the same order: path, decision, lossiness and detail. Validator verdicts
# aside: a schema file has no validator's code, so the plan notes that a verdict cannot be
# foreseen (an entry made only for that note may have no counterpart in the restore), and the
# restore's entries of values a validator refused have none in the plan. A clock's entry
# "(clock NAME)" is compared without its detail: the restore says how far the clock moved, the
# plan, which has no clock to read, only what it read at the checkpoint.
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
set(checkpoint "${DIR}/v0.ckpt")
set(report_file "${DIR}/restore.json")
execute_process(COMMAND "${V0}" "${checkpoint}" RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "v0 (${V0}) failed: ${result}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -E env "XV_REPORT=${report_file}" "${V1}" "${checkpoint}"
                RESULT_VARIABLE result OUTPUT_QUIET)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "v1 (${V1}) failed: ${result}")
endif()
if(NOT EXISTS "${report_file}")
  message(FATAL_ERROR "v1 wrote no report (XV_REPORT)")
endif()
file(READ "${report_file}" restore_json)
execute_process(COMMAND "${CLI}" plan "${checkpoint}" --schema "${SCHEMA1}" --json
                RESULT_VARIABLE result OUTPUT_VARIABLE plan_json ERROR_VARIABLE errors)
if(NOT result EQUAL 0 AND NOT result EQUAL 1)
  message(FATAL_ERROR "symcr plan failed (${result}): ${errors}")
endif()

set(unforeseen_note "checked by symcr_validate\\([^)]*\\) when restored: its verdict cannot be foreseen here")

# Reads the entries at <keys...> of <json> into <prefix>_<i> ("path | decision[ *] | detail")
# and <prefix>_count; with NOTES, an entry whose detail was only the validator's note is
# marked <prefix>_<i>_note_only.
function(read_entries json prefix)
  cmake_parse_arguments(PARSE_ARGV 2 arg "NOTES;VERDICTS" "" "KEYS")
  string(JSON length LENGTH "${json}" ${arg_KEYS})
  set(count 0)
  if(length GREATER 0)
    math(EXPR last "${length} - 1")
    foreach(i RANGE ${last})
      string(JSON path GET "${json}" ${arg_KEYS} ${i} path)
      string(JSON decision GET "${json}" ${arg_KEYS} ${i} decision)
      string(JSON detail GET "${json}" ${arg_KEYS} ${i} detail)
      string(JSON lossy GET "${json}" ${arg_KEYS} ${i} lossy)
      # The restore's verdicts of validators: values refused, elements left out for them.
      if(arg_VERDICTS AND decision STREQUAL "rejected" AND detail MATCHES "symcr_validate")
        continue()
      endif()
      # A clock's entry: the plan has no clock to read now, so its detail differs.
      if(path MATCHES "^\\(clock ")
        set(detail "")
      endif()
      set(note_only FALSE)
      if(arg_NOTES AND detail MATCHES "${unforeseen_note}")
        string(REGEX REPLACE "(; )?${unforeseen_note}" "" detail "${detail}")
        string(REGEX REPLACE "^; " "" detail "${detail}")
        if(detail STREQUAL "" AND decision STREQUAL "restored")
          set(note_only TRUE)
        endif()
      endif()
      set(star "")
      if(lossy)
        set(star " *")
      endif()
      set(${prefix}_${count} "${path} | ${decision}${star} | ${detail}" PARENT_SCOPE)
      set(${prefix}_${count}_note_only ${note_only} PARENT_SCOPE)
      math(EXPR count "${count} + 1")
    endforeach()
  endif()
  set(${prefix}_count ${count} PARENT_SCOPE)
endfunction()

read_entries("${restore_json}" restored VERDICTS KEYS entries)
read_entries("${plan_json}" planned NOTES KEYS report entries)

set(r 0)
set(p 0)
set(differences "")
while(r LESS restored_count OR p LESS planned_count)
  set(restored_entry "(none)")
  set(planned_entry "(none)")
  if(r LESS restored_count)
    set(restored_entry "${restored_${r}}")
  endif()
  if(p LESS planned_count)
    set(planned_entry "${planned_${p}}")
  endif()
  if(restored_entry STREQUAL planned_entry)
    math(EXPR r "${r} + 1")
    math(EXPR p "${p} + 1")
  elseif(p LESS planned_count AND planned_${p}_note_only)
    math(EXPR p "${p} + 1")
  else()
    string(APPEND differences "  restore: ${restored_entry}\n  plan:    ${planned_entry}\n")
    break()
  endif()
endwhile()
if(NOT differences STREQUAL "")
  message(FATAL_ERROR "symcr plan's entries differ from the restore's, first at:\n"
                      "${differences}restore report:\n${restore_json}\nplan:\n${plan_json}")
endif()
message(STATUS "symcr plan foresees the restore's ${restored_count} entries")
