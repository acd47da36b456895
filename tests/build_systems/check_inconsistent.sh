#!/usr/bin/env bash
# ctest driver: two sources compiled through the wrapper with different sidecars describe the
# type Pos differently (one skips Pos::y). Linking them must fail with an error naming both
# sources, and write no program.
#   check_inconsistent.sh <wrapper dir> <inconsistent folder> <work dir>
set -euo pipefail
wrappers=$1 src=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
cd "$work"
"$wrappers/symcr-c++" g++ --symcr-annotations="$src/a.symcr" -c "$src/a.cpp" -o a.o
"$wrappers/symcr-c++" g++ --symcr-annotations="$src/b.symcr" -c "$src/b.cpp" -o b.o
if "$wrappers/symcr-c++" g++ a.o b.o -o program 2>link.err; then
  echo "FAIL: the link of two different descriptions of Pos succeeded" >&2
  exit 1
fi
cat link.err
grep -q "type 'Pos' is described differently in '$src/b.cpp' than in '$src/a.cpp'" link.err || {
  echo "FAIL: the error does not name the type and both sources" >&2
  exit 1
}
[ ! -e program ] || { echo "FAIL: a program was written" >&2; exit 1; }
echo "the link refused two descriptions of Pos, naming both sources"
