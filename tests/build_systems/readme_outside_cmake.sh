#!/usr/bin/env bash
# ctest driver: README.md's "Outside CMake" as a new user follows it. The commands are README's
# own: each fenced block after a line "<!-- outside-cmake: <name> -->" in README, run as written
# but for two substitutions: the scratch prefix for /opt/symcr, and this build tree for the SDK's
# build tree (configuring and building the SDK is what this build tree did; only README's
# `cmake --install` line runs). The project is the rover of this folder:
#   install    the `cmake --install` line: the SDK into the scratch prefix
#   wrapper    its exports, then the Make line in rover_v0, the Meson line in rover_v1
#   sidecar    the example sidecar: rover_v0's annotations (its own .symcr is replaced)
#   pkg-config in a scratch folder holding a source that calls symcr
#   generator  in rover_v1 again, over the Meson build's compilation database
# Then v0 (Make, through the wrapper) saves, and v1 built both ways (Meson through the wrapper,
# by hand with symcr-gen's command line) restores v0's checkpoint with the expected values.
#   readme_outside_cmake.sh <README.md> <symcr build dir> <this folder> <work dir> [<flags>]
# <flags> are added to every compile and link (a sanitizer build's, whose runtime needs them).
set -euo pipefail
readme=$1 build=$2 here=$3 work=$4 flags=${5:-}
rm -rf "$work"
mkdir -p "$work"
prefix="$work/prefix"
fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# block <name>: the fenced block after README's marker, without the fence's indentation, with the
# scratch prefix for /opt/symcr. A missing marker or block fails.
block() {
  local text
  text=$(awk -v marker="<!-- outside-cmake: $1 -->" '
    { line = $0; sub(/^ */, "", line) }
    !found && line == marker { found = 1; next }
    found && /^ *```/ { if (inside) exit; inside = 1; match($0, /^ */); indent = RLENGTH; next }
    inside { print substr($0, indent + 1) }' "$readme")
  [ -n "$text" ] || fail "README.md has no block after <!-- outside-cmake: $1 -->"
  printf '%s\n' "${text//\/opt\/symcr/$prefix}"
}

# run <dir> <commands>: README's commands, as a shell runs them, in <dir>; echoed for the log.
run() {
  echo "+ (in ${1#"$work"}/) $2" | sed 's/^/  /' >&2
  (cd "$1" && eval "$2") || fail "README's command failed in $1: $2"
}

# The flags a sanitizer build needs reach every compile and link through g++ itself.
if [ -n "$flags" ]; then
  mkdir -p "$work/compiler"
  for tool in g++ gcc; do
    printf '#!/bin/sh\nexec %s %s "$@"\n' "$(command -v $tool)" "$flags" >"$work/compiler/$tool"
    chmod +x "$work/compiler/$tool"
  done
  export PATH="$work/compiler:$PATH"
fi

cp -r "$here/rover_v0" "$here/rover_v1" "$here/rover.mk" "$work/"
block sidecar >"$work/rover_v0/.symcr"

install=$(block install | grep '^cmake --install ') || fail "README installs with no cmake --install"
run "$work" "${install/ build\/sdk / $build }"

wrapper=$(block wrapper)
while IFS= read -r line; do
  case $line in
    export\ *) eval "$line" ;;
    make\ *) run "$work/rover_v0" "$line" ;;
    *meson\ setup*) run "$work/rover_v1" "$line" ;;
    *) fail "README's wrapper block has a line this test does not know: $line" ;;
  esac
done <<<"$wrapper"
[ "$(command -v symcr-c++)" = "$prefix/bin/symcr-c++" ] || fail "README's PATH has no symcr-c++"

mkdir "$work/pkg-config"
cat >"$work/pkg-config/main.cpp" <<'EOF'
#include <symcr/symcr.hpp>
int main() { return symcr::checkpoint("main.ckpt").ok() ? 0 : 1; }
EOF
pkg=$(block pkg-config)
while IFS= read -r line; do
  case $line in
    export\ *) eval "$line" ;;
    *--variable=symcr_gen*) # prints what README's comment says, the installed symcr-gen
      gen=$(cd "$work/pkg-config" && eval "$line")
      if [ "$gen" != "${line##*# }" ] || [ ! "$gen" -ef "$prefix/bin/symcr-gen" ]; then
        fail "$line printed $gen"
      fi ;;
    *) run "$work/pkg-config" "$line" ;;
  esac
done <<<"$pkg"
[ -f "$work/pkg-config/main.o" ] || fail "README's pkg-config compile wrote no main.o"

run "$work/rover_v1" "$(block generator)"

export SYMCR_STORE="$work/rover.store"
for v1 in rover_v1/build/rover rover_v1/rover; do
  # A fresh store for each v1: a restore not yet confirmed by checkpoints (v1 makes none) is
  # taken at the next start for one that crashed, and passed over (the crash-loop fallback).
  rm -f "$SYMCR_STORE"
  "$work/rover_v0/build/rover" >/dev/null || fail "v0 failed"
  output=$("$work/$v1" 2>"$work/v1.err") || fail "$v1 failed: $(cat "$work/v1.err")"
  grep -q "restored checkpoint #" "$work/v1.err" ||
    fail "$v1 did not restore: $(cat "$work/v1.err")"
  [ "$output" = "$(cat "$here/expected.txt")" ] || fail "$v1 printed
$output
expected
$(cat "$here/expected.txt")"
done
echo "README's outside-CMake commands: the wrapper with Make and Meson, pkg-config and" \
  "symcr-gen's command line, against the installed SDK"
