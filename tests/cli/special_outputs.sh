#!/bin/sh
# The CLI on special files: a FIFO as input is refused at once (never waited on), and output
# that cannot be written (a full device, a closed stdout) makes the command fail.
#   special_outputs.sh <symcr> <checkpoint> <scratch dir>
set -u
symcr=$1 checkpoint=$2 scratch=$3
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_exit() {  # <expected code> <label> <command...>
  want=$1 label=$2
  shift 2
  "$@" >"$scratch/out" 2>&1
  got=$?
  [ "$got" = "$want" ] || fail "$label: exit $got, expected $want ($(head -c 300 "$scratch/out"))"
}

rm -rf "$scratch" && mkdir -p "$scratch"
mkfifo "$scratch/fifo"
for command in inspect verify; do
  expect_exit 2 "$command on a FIFO" timeout 10 "$symcr" "$command" "$scratch/fifo"
  grep -q "not a regular file" "$scratch/out" || fail "$command on a FIFO: message: $(cat "$scratch/out")"
done
expect_exit 2 "plan on a FIFO" timeout 10 "$symcr" plan "$scratch/fifo" --schema "$scratch/fifo"
expect_exit 2 "diff on a FIFO" timeout 10 "$symcr" diff "$scratch/fifo" "$checkpoint"

# Output failures. The same commands succeed with a writable stdout.
expect_exit 0 "inspect to a file" "$symcr" inspect "$checkpoint"
if [ -w /dev/full ]; then
  "$symcr" inspect "$checkpoint" >/dev/full 2>"$scratch/err"
  code=$?
  [ "$code" = 2 ] || fail "inspect >/dev/full: exit $code, expected 2"
  grep -q "cannot write the output" "$scratch/err" || fail "inspect >/dev/full: $(cat "$scratch/err")"
  "$symcr" inspect --json "$checkpoint" >/dev/full 2>"$scratch/err"
  code=$?
  [ "$code" = 2 ] || fail "inspect --json >/dev/full: exit $code, expected 2"
else
  echo "no writable /dev/full here: the full-device cases did not run"
fi
"$symcr" verify "$checkpoint" >&- 2>"$scratch/err"
code=$?
[ "$code" = 2 ] || fail "verify with stdout closed: exit $code, expected 2"

[ "$failures" = 0 ] && echo "special files and outputs: all checks passed"
exit "$failures"
