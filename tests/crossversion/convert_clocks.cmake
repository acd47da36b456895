# ctest driver: `symcr convert --initial` keeps times in step with their clocks when the build
# restores the result later than --initial was saved (its clocks have advanced since):
#   1. v0 saves v0.ckpt;
#   2. v1 saves its initial state (its millisecond clock at 100) and restores v0.ckpt directly;
#   3. `symcr convert v0.ckpt --schema SCHEMA1 --initial initial.ckpt --inline-schema`;
#   4. v1 restores the result with its clock at 1000: its checks expect each time v0 saved moved
#      by the clock's advance since v0's checkpoint (as a direct restore there would), each time
#      kept from the initial state by its advance since that state was saved.
#   cmake -DV0=<exe> -DV1=<exe> -DCLI=<symcr> -DSCHEMA1=<file> -DDIR=<dir> -P convert_clocks.cmake
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
include(${CMAKE_CURRENT_LIST_DIR}/step.cmake)
step("${V0}" "${DIR}/v0.ckpt")
step("${CMAKE_COMMAND}" -E env "XV_INITIAL=${DIR}/initial.ckpt" "${V1}" "${DIR}/v0.ckpt")
step("${CLI}" convert "${DIR}/v0.ckpt" --schema "${SCHEMA1}" --initial "${DIR}/initial.ckpt"
     --inline-schema -o "${DIR}/converted.ckpt")
step("${CMAKE_COMMAND}" -E env XV_NOW_MS=1000 "${V1}" "${DIR}/converted.ckpt")
