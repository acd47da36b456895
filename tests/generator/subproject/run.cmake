# Configures and builds the subproject (symcr through add_subdirectory), then runs its program.
#   cmake -DSYMCR_SOURCE=<symcr source> -DSOURCE=<this dir> -DWORK=<scratch dir>
#         -DGEN=<symcr-gen> -P run.cmake
include(${CMAKE_CURRENT_LIST_DIR}/../run_checked.cmake)

file(REMOVE_RECURSE "${WORK}")
run(${CMAKE_COMMAND} -S "${SOURCE}" -B "${WORK}" -G Ninja "-DSYMCR_SOURCE=${SYMCR_SOURCE}"
    "-DSYMCR_GEN_EXECUTABLE=${GEN}" -DSYMCR_BUILD_GENERATOR=OFF -DSYMCR_BUILD_CLI=OFF)
run(${CMAKE_COMMAND} --build "${WORK}" --target hello)
run("${WORK}/hello" save "${WORK}/hello.ckpt")
run("${WORK}/hello" restore "${WORK}/hello.ckpt")
message("symcr built as a subproject; the consumer's build type and targets are its own")
