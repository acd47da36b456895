# Installs symcr into a temporary prefix, configures and builds the consumer against it, runs
# it and its compatibility gate (the installed symcr CLI, passing on the consumer's own
# checkpoint, failing on a damaged one), then edits its header and checks that the build
# regenerates the checkpoint code.
#   cmake -DBUILD=<symcr build dir> -DSOURCE=<this dir> -DWORK=<scratch dir>
#         [-DGEN=<prebuilt symcr-gen>] [-DSANITIZE=ON] -P run.cmake
include(${CMAKE_CURRENT_LIST_DIR}/../run_checked.cmake)

file(REMOVE_RECURSE "${WORK}")
# Only what a consuming project needs (the "sdk" component), not the other tools.
run(${CMAKE_COMMAND} --install "${BUILD}" --prefix "${WORK}/prefix" --component sdk)
file(COPY "${SOURCE}/" DESTINATION "${WORK}/src" PATTERN run.cmake EXCLUDE)
file(MAKE_DIRECTORY "${WORK}/src/field-checkpoints")
set(args -S "${WORK}/src" -B "${WORK}/build" -G Ninja "-DCMAKE_PREFIX_PATH=${WORK}/prefix")
if(GEN)
  list(APPEND args "-DSYMCR_GEN_EXECUTABLE=${GEN}")
endif()
if(SANITIZE)
  list(APPEND args "-DCMAKE_CXX_FLAGS=-fsanitize=address,undefined"
                   "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
endif()
run(${CMAKE_COMMAND} ${args})
run(${CMAKE_COMMAND} --build "${WORK}/build")
run("${WORK}/build/hello" save "${WORK}/hello.ckpt")
run("${WORK}/build/hello" restore "${WORK}/hello.ckpt")

# The gate: planned by the installed CLI, not by a symcr found elsewhere.
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir "${WORK}/build" --show-only=json-v1
                OUTPUT_VARIABLE tests)
string(JSON gate_command ERROR_VARIABLE no_gate GET "${tests}" tests 0 command 0)
if(no_gate OR NOT gate_command STREQUAL "${WORK}/prefix/bin/symcr")
  message(FATAL_ERROR "no gate run by the installed CLI ${WORK}/prefix/bin/symcr:\n${tests}")
endif()
file(COPY_FILE "${WORK}/hello.ckpt" "${WORK}/src/field-checkpoints/release-1.ckpt")
run(${CMAKE_CTEST_COMMAND} --test-dir "${WORK}/build" -R "^symcr\\.compatibility\\.hello$"
    --output-on-failure --no-tests=error)
file(WRITE "${WORK}/src/field-checkpoints/damaged.ckpt" "not a checkpoint")
execute_process(COMMAND ${CMAKE_CTEST_COMMAND} --test-dir "${WORK}/build" --no-tests=error
                RESULT_VARIABLE gate_result OUTPUT_VARIABLE gate_output ERROR_VARIABLE gate_output)
if(gate_result EQUAL 0)
  message(FATAL_ERROR "the gate passed a damaged checkpoint:\n${gate_output}")
endif()
file(REMOVE "${WORK}/src/field-checkpoints/damaged.ckpt")

# Editing the annotated header must regenerate (the generator's depfile lists it).
file(READ "${WORK}/src/state.hpp" header)
string(REPLACE "// MARKER" "int added_by_test = 0;  // MARKER" header "${header}")
file(WRITE "${WORK}/src/state.hpp" "${header}")
run(${CMAKE_COMMAND} --build "${WORK}/build")
file(GLOB_RECURSE schema "${WORK}/build/*/symcr_schema.cpp")
file(READ "${schema}" generated)
if(NOT generated MATCHES "\"added_by_test\"")
  message(FATAL_ERROR "editing state.hpp did not regenerate ${schema}")
endif()
run("${WORK}/build/hello" restore "${WORK}/hello.ckpt")
message("consumer built and ran against the installed symcr, its gate ran; header edit "
        "regenerated")
