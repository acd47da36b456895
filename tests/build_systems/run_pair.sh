#!/usr/bin/env bash
# ctest driver: builds the rover pair (rover_v0, rover_v1: a static library in between, the
# annotations in a sidecar found upward) with a build system other than CMake, through the
# compiler wrapper only (CXX="symcr-c++ g++"), then checks
#   - from scratch: every source generated once, the program linked once; the source symcr has
#     nothing to do with (util.cpp) compiled into the same bytes as without the wrapper;
#   - v1 restores v0's checkpoint at its restore point with the expected values;
#   - incrementally: touching one source regenerates that source alone and relinks; touching
#     the header, or the sidecar, regenerates every source including it, or reading it; a
#     rebuild of nothing generates nothing.
#   - with Meson, whose compilation database then names the wrapper ("symcr-c++ g++ ..."),
#     symcr-gen run by hand over that database parses with g++'s command, and writes the
#     schema source the wrapper's link wrote from the merged parts.
#   run_pair.sh <make|meson> <wrapper dir> <this folder> <work dir> <symcr-gen> [<flags>]
# <flags> are added to every compile and link (a sanitizer build's, whose runtime needs them).
set -euo pipefail
system=$1 wrappers=$2 here=$3 work=$4 generator=$5 flags=${6:-}
rm -rf "$work"
mkdir -p "$work"
cp -r "$here/rover_v0" "$here/rover_v1" "$here/rover.mk" "$work/"
export SYMCR_WRAPPER_LOG="$work/wrapper.log"
cxx="$wrappers/symcr-c++ g++${flags:+ $flags}"

fail() {
  echo "FAIL ($system): $*" >&2
  exit 1
}

# build <version>: builds the version's program; prints its path.
build() {
  local version=$1 src="$work/rover_$1" out="$work/build_$1"
  case $system in
    make) make -s -f "$src/Makefile" SRC="$src" BUILD="$out" CXX="$cxx" >&2
          echo "$out/rover" ;;
    meson) if [ ! -d "$out" ]; then
             CXX="$cxx" meson setup "$out" "$src" >"$work/setup_$version.log" 2>&1 ||
               { cat "$work/setup_$version.log" >&2; fail "meson setup"; }
             : >"$SYMCR_WRAPPER_LOG" # setup's compiler checks are not the project's sources
           fi
           ninja -C "$out" >&2
           echo "$out/rover" ;;
    *) fail "unknown build system '$system'" ;;
  esac
}

# expect_log [<lines>]: the wrapper's log since the last call is exactly these lines, in any order.
expect_log() {
  local expected actual
  expected=$(printf '%s\n' "${1:-}" | sed '/^$/d' | sort)
  actual=$(sort "$SYMCR_WRAPPER_LOG" 2>/dev/null || true)
  [ "$expected" = "$actual" ] || fail "the wrapper ran
$actual
expected
$expected"
  : >"$SYMCR_WRAPPER_LOG"
}

sources_of() {
  local src="$work/rover_$1"
  echo "generate $src/src/main.cpp"
  echo "generate $src/src/util.cpp"
  echo "generate $src/lib/rover.cpp"
}

v0=$(build v0)
expect_log "$(sources_of v0; echo "link $v0")"
v1=$(build v1)
expect_log "$(sources_of v1; echo "link $v1")"

# restore_pair: v0 saves at its point, v1 restores at its own and prints what it holds.
restore_pair() {
  export SYMCR_STORE="$work/rover.store"
  rm -f "$SYMCR_STORE"
  (cd "$work" && "$v0" >/dev/null) || fail "v0 failed"
  [ -f "$SYMCR_STORE" ] || fail "v0 wrote no store"
  local output
  output=$(cd "$work" && "$v1" 2>"$work/v1.err") || fail "v1 failed: $(cat "$work/v1.err")"
  grep -q "restored checkpoint #" "$work/v1.err" || fail "v1 did not restore: $(cat "$work/v1.err")"
  [ "$output" = "$(cat "$here/expected.txt")" ] ||
    fail "v1 printed
$output
expected
$(cat "$here/expected.txt")"
}
restore_pair

# The source symcr has nothing to do with: no part in its object, the bytes of a plain compile.
util=$(find "$work/build_v0" -name '*util*.o' | head -1)
main=$(find "$work/build_v0" -name '*main*.o' | head -1)
has_part() { readelf -S "$1" >"$work/sections.txt" && grep -q '\.symcr_part' "$work/sections.txt"; }
has_part "$main" || fail "$main carries no part"
if has_part "$util"; then fail "$util carries a part"; fi
if [ "$system" = make ]; then
  # shellcheck disable=SC2086 # the flags are words
  g++ $flags -O2 -std=c++17 -Wall -I"$work/rover_v0/include" -MMD -MP \
    -c "$work/rover_v0/src/util.cpp" -o "$work/plain_util.o"
  cmp -s "$util" "$work/plain_util.o" || fail "util.o differs from a plain compile's"
fi

# Incremental: the build system decides (its depfiles), the wrapper regenerates what it compiles.
build v0 >/dev/null
expect_log
sleep 1 # a newer timestamp than the objects', on file systems with coarse ones
touch "$work/rover_v0/lib/rover.cpp"
build v0 >/dev/null
expect_log "$(echo "generate $work/rover_v0/lib/rover.cpp"; echo "link $v0")"
sleep 1
touch "$work/rover_v0/include/rover.hpp"
build v0 >/dev/null
expect_log "$(sources_of v0; echo "link $v0")"
sleep 1
touch "$work/rover_v0/.symcr" # read by symcr-gen for every source, even one without a root
build v0 >/dev/null
expect_log "$(sources_of v0; echo "link $v0")"
restore_pair

if [ "$system" = meson ]; then
  grep -q 'symcr-c++ g++ ' "$work/build_v0/compile_commands.json" ||
    fail "the database does not name the wrapper"
  (cd "$work/rover_v0" && "$generator" -p "$work/build_v0" --out-dir "$work/by_hand" \
     --annotations .symcr src/main.cpp lib/rover.cpp) >"$work/by_hand.log" 2>&1 ||
    fail "symcr-gen over the wrapper's database: $(cat "$work/by_hand.log")"
  if grep -q error "$work/by_hand.log"; then fail "$(cat "$work/by_hand.log")"; fi
  # The units' merged parts give the tables of one run over the same sources, in the same order:
  # the same schema source but for the units' names in the generated code's symbols.
  tables() { grep -v '^//' "$1" | sed -E 's/_u[0-9a-f]{12}_/_/g'; }
  diff <(tables "$work/by_hand/symcr_schema.cpp") \
       <(tables "$work/build_v0/rover.symcr/symcr_schema.cpp") >"$work/tables.diff" ||
    fail "the merged parts' schema differs from one run's: $(cat "$work/tables.diff")"
fi
echo "$system: built from scratch and incrementally, v1 restored v0's checkpoint"
