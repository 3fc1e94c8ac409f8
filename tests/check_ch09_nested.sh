#!/usr/bin/env bash
# Chapter 9's nested iteration changes the way, not the answer: the --quick levels started from
# the level below and started cold (u = 0, no node in contact) give the same multipliers along
# Gamma_c within 1e-8 of their largest, and the same active set; the cold start takes more
# Newton steps on the finest level.
#
#   check_ch09_nested.sh MPIEXEC PROGRAM OUT_DIR
set -u
mpiexec=$1 program=$2 out=$3
rm -rf "$out"
fail() { echo "check_ch09_nested: $1" >&2; exit 1; }
for start in nested cold; do
  "$mpiexec" --oversubscribe -n 2 "$program" --quick --no-plot --reference none --start "$start" \
    --out "$out/$start" > "$out.$start.log" 2>&1
  status=$?
  [ "$status" -eq 0 ] || { cat "$out.$start.log"; fail "--start $start: exit status $status"; }
  [ -s "$out/$start/multipliers.csv" ] || fail "--start $start wrote no multipliers.csv"
done
steps() { sed -n 's/.*"newton_steps": \([0-9]*\).*/\1/p' "$out/$1/summary.json"; }
[ -n "$(steps nested)" ] && [ -n "$(steps cold)" ] || fail "results.newton_steps missing"

paste -d, "$out/nested/multipliers.csv" "$out/cold/multipliers.csv" | awk -F, -v nested="$(steps nested)" -v cold="$(steps cold)" '
  NR == 1 { next }
  { if ($1 != $4) { print "row " NR - 1 ": x differs (" $1 " and " $4 ")"; bad = 1 }
    d = $2 - $5; if (d < 0) d = -d; if (d > diff) diff = d
    a = $5 < 0 ? -$5 : $5; if (a > scale) scale = a
    if ($3 != $6) { print "row " NR - 1 " at x = " $1 ": active " $3 " nested, " $6 " cold"; bad = 1 }
    rows++ }
  END {
    if (rows == 0 || scale == 0) { print "no rows, or every multiplier zero"; exit 1 }
    rel = diff / scale
    printf "check_ch09_nested: %d multipliers, largest difference %.2e of the largest, active sets %s; Newton steps on the finest level %d nested, %d cold\n", rows, rel, bad ? "DIFFERENT" : "identical", nested, cold
    exit !(rel <= 1e-8 && !bad && nested + 0 < cold + 0)
  }' || fail "nested and cold starts disagree (or nested took as many steps)"
