# The watchdog example's story, checked (ctest examples.watchdog; README.md tells it):
#   cmake -DV1=<exe> -DV2=<exe> -DCLI=<symcr> -DSCHEMA2=<v2's schema file> -DDIR=<dir>
#         -P scenario.cmake
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
set(ram "${DIR}/backup-ram.bin")
get_filename_component(schema_dir "${SCHEMA2}" DIRECTORY)
set(SCHEMA1 "${schema_dir}/watchdog_v1.symcr-schema")

# run(<expected exit> <regex>... COMMAND <command>...): the output must match every regex.
function(run expected_exit)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "COMMAND")
  execute_process(COMMAND ${arg_COMMAND} WORKING_DIRECTORY "${DIR}" RESULT_VARIABLE result
                  OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("$ ${arg_COMMAND}\n${out}${err}")
  if(NOT result EQUAL expected_exit)
    message(FATAL_ERROR "exit ${result}, expected ${expected_exit}")
  endif()
  foreach(expected IN LISTS arg_UNPARSED_ARGUMENTS)
    if(NOT "${out}${err}" MATCHES "${expected}")
      message(FATAL_ERROR "output does not match: ${expected}")
    endif()
  endforeach()
endfunction()

# v1 flies 120 loops, checkpointing at 50 and 100; the watchdog resets it.
run(0 "v1: boot: no checkpoint yet"
      "v1: checkpoint #2 at loop 100\nstate: loops=100 waypoint=2 battery=95.00 armed=1 yaw=1.00"
      "watchdog reset"
    COMMAND "${V1}" --backup "${ram}" --loops 120)
# After the reset v1 carries on from loop 100.
run(0 "v1: boot: restored checkpoint #2\nstate: loops=100 waypoint=2 battery=95.00 armed=1"
    COMMAND "${V1}" --backup "${ram}" --loops 30)
# v2 flashed over it cannot restore v1's checkpoint on its own: it starts from its initial state.
run(0 "v2: boot: nothing restored \\(record of another build's schema\\)"
      "state: loops=0 mission_index=0 battery=100.00 armed=0"
    COMMAND "${V2}" --backup "${ram}")
# The update, done right: the tool reads v1's newest checkpoint and v2's initial state, converts,
# and hands the result to v2's first boot.
run(0 "saved old.ckpt" COMMAND "${V1}" --backup "${ram}" --export old.ckpt)
run(0 "saved v2-initial.ckpt" COMMAND "${V2}" --save-initial v2-initial.ckpt)
# A device's record names its schema by hash: the host tools need the writer's schema file.
run(2 "give the schema file of the build that wrote it \\(--writer-schema\\)"
    COMMAND "${CLI}" inspect old.ckpt)
run(0 "vehicle.loops += 100" "vehicle.waypoint += 2"
    COMMAND "${CLI}" inspect old.ckpt --writer-schema "${SCHEMA1}")
run(2 "old.ckpt names schema [0-9a-f]+, but .* is schema [0-9a-f]+: not the build that wrote it"
    COMMAND "${CLI}" convert old.ckpt --schema "${SCHEMA2}" --writer-schema "${SCHEMA2}"
            --initial v2-initial.ckpt -o new.ckpt)
run(0 "vehicle.mission_index +converted +renamed from waypoint"
      "vehicle.loops +converted +uint32 -> uint64" "vehicle.home_alt_m +kept"
      "converted: new.ckpt"
    COMMAND "${CLI}" convert old.ckpt --schema "${SCHEMA2}" --writer-schema "${SCHEMA1}"
            --initial v2-initial.ckpt -o new.ckpt)
run(0 "v2: boot: restored checkpoint #2\nstate: loops=100 mission_index=2 battery=95.00 armed=1 yaw=1.00 home_alt=584.0"
      "v2: checkpoint #3 at loop 150"
    COMMAND "${V2}" --backup "${ram}" --restore-from new.ckpt --loops 60)
# And v2 keeps its own checkpoints across its own resets.
run(0 "v2: boot: restored checkpoint #3\nstate: loops=150 mission_index=3"
    COMMAND "${V2}" --backup "${ram}")
