# Hostile input: for byte offsets across a checkpoint (every STEP-th), inverts the byte and
# re-signs the file (schema hash and checksum fixed up) so that it passes the integrity checks
# and reaches the schema parser and payload decoder. Every subcommand must then answer with an
# exit code of 0, 1 or 2 — an error message, never a crash.
#   -DSYMCR=<cli> -DFIXTURE=<fixture program> -DSOURCE=<checkpoint> -DSCHEMA=<schema file>
#   -DWORK=<scratch dir> -DSTEP=<n>
file(MAKE_DIRECTORY "${WORK}")
file(SIZE "${SOURCE}" size)
set(mutant "${WORK}/mutant.ckpt")
set(rejected 0)
set(offset 0)
while(offset LESS size)
  file(COPY_FILE "${SOURCE}" "${mutant}")
  execute_process(COMMAND ${FIXTURE} flip-resign "${mutant}" ${offset} RESULT_VARIABLE code)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "could not make the mutant at offset ${offset}")
  endif()
  foreach(command "inspect" "verify" "plan;--schema;${SCHEMA}")
    execute_process(COMMAND ${SYMCR} ${command} "${mutant}"
                    RESULT_VARIABLE code OUTPUT_QUIET ERROR_VARIABLE err)
    # A sanitizer build reports with exit code 1: look for the report too.
    if(NOT code MATCHES "^[012]$" OR
       err MATCHES "(AddressSanitizer|LeakSanitizer|UndefinedBehaviorSanitizer|runtime error:)")
      message(FATAL_ERROR "symcr ${command} on a mutant (byte ${offset} inverted): ${code}\n${err}")
    endif()
    if(command STREQUAL "inspect" AND code EQUAL 2)
      math(EXPR rejected "${rejected} + 1")
    endif()
  endforeach()
  math(EXPR offset "${offset} + ${STEP}")
endwhile()
# The mutants must really be hostile: most of them must be refused as corrupt.
math(EXPR tried "(${size} + ${STEP} - 1) / ${STEP}")
message(STATUS "${rejected} of ${tried} mutants refused by inspect")
if(rejected EQUAL 0)
  message(FATAL_ERROR "no mutant was refused: the mutation does not reach the decoder")
endif()
