#!/usr/bin/env bash
# One run of a chapter program, checked for what every run must keep (docs/running.md, "Output
# contract"): the expected exit status, no sanitizer report, nothing written after a refusal,
# and no NaN or inf in any CSV or JSON written.
#
#   check_program_run.sh STATUS OUT_DIR PROGRAM [ARGS...]    (the program also gets --out OUT_DIR)
set -u
expected=$1
out=$2
shift 2
rm -rf "$out"
output=$("$@" --out "$out" 2>&1)
status=$?
fail() {
  printf '%s\n' "$output"
  echo "check_program_run: $1 (command: ${command_line})" >&2
  exit 1
}
command_line="$* --out $out"
printf '%s\n' "$output" | tail -n 3
if printf '%s\n' "$output" | grep -qE 'runtime error:|AddressSanitizer|LeakSanitizer'; then
  fail "a sanitizer report"
fi
[ "$status" -eq "$expected" ] || fail "exit status $status, expected $expected"
if [ "$status" -eq 2 ] && [ -e "$out" ]; then
  fail "a refused run left $out behind"
fi
if [ -d "$out" ]; then
  bad=$(grep -liE '(^|[,:[ ])[-+]?(nan|inf|infinity)([],} ]|$)' "$out"/*.csv "$out"/*.json 2>/dev/null)
  [ -z "$bad" ] || fail "NaN or inf in $(echo "$bad" | tr '\n' ' ')"
fi
exit 0
