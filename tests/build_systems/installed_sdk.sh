#!/usr/bin/env bash
# ctest driver: README's "Outside CMake" as a new user follows it, against the SDK installed
# into a scratch prefix (cmake --install --component sdk): v0 built with Make through the
# installed symcr-c++ (PATH), v1 built by hand with the installed symcr-gen's own command line
# and pkg-config's symcr.pc; v1 restores v0's checkpoint with the expected values.
#   installed_sdk.sh <symcr build dir> <this folder> <work dir> [<flags>]
# <flags> are added to every compile and link (a sanitizer build's, whose runtime needs them).
set -euo pipefail
build=$1 here=$2 work=$3 flags=${4:-}
rm -rf "$work"
mkdir -p "$work"
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
cmake --install "$build" --prefix "$work/prefix" --component sdk >/dev/null
export PATH="$work/prefix/bin:$PATH"
export PKG_CONFIG_PATH="$work/prefix/lib/pkgconfig"
[ "$(command -v symcr-c++)" = "$work/prefix/bin/symcr-c++" ] || fail "no installed symcr-c++"
[ -x "$work/prefix/bin/symcr-cc" ] || fail "no installed symcr-cc"
[ "$(pkg-config --variable=symcr_gen symcr)" -ef "$work/prefix/bin/symcr-gen" ] ||
  fail "symcr.pc does not name the installed symcr-gen"
cp -r "$here/rover_v0" "$here/rover_v1" "$work/"

# v0: the wrapper in the project's own Makefile (build dir "build" inside the project).
make -s -C "$work/rover_v0" CXX="symcr-c++ g++${flags:+ $flags}" >/dev/null

# v1: the generator's own command line, then the compiler, with pkg-config's flags.
cd "$work/rover_v1"
# shellcheck disable=SC2086 # the flags are words
{
  symcr-gen --out-dir gen --annotations .symcr --schema-file rover.symcr-schema \
            src/main.cpp lib/rover.cpp -- -std=c++17 -Iinclude
  g++ $flags -O2 -std=c++17 -Iinclude $(pkg-config --cflags symcr) -c gen/tu0_main.cpp -o main.o
  g++ $flags -O2 -std=c++17 -Iinclude $(pkg-config --cflags symcr) -c gen/tu1_rover.cpp -o rover.o
  g++ $flags -O2 -std=c++17 -Iinclude -c src/util.cpp -o util.o
  g++ $flags $(pkg-config --cflags symcr) -c gen/symcr_schema.cpp -o symcr_schema.o
  g++ $flags -o rover main.o rover.o util.o symcr_schema.o $(pkg-config --libs symcr)
}

export SYMCR_STORE="$work/rover.store"
"$work/rover_v0/build/rover" >/dev/null || fail "v0 failed"
output=$("$work/rover_v1/rover" 2>"$work/v1.err") || fail "v1 failed: $(cat "$work/v1.err")"
grep -q "restored checkpoint #" "$work/v1.err" || fail "v1 did not restore: $(cat "$work/v1.err")"
[ "$output" = "$(cat "$here/expected.txt")" ] || fail "v1 printed
$output
expected
$(cat "$here/expected.txt")"
echo "the installed SDK: the wrapper, symcr-gen's command line and pkg-config as README says"
