#!/usr/bin/env bash
# The tables of the evidence pages that come from runs, remade by the command that makes them.
# A page holds each such table between two markers, the first naming the command (run from the
# repository's top folder, with the programs in build/ or in BUILD):
#
#   <!-- table: bash chapters/rate_table.sh ch04_integral_matching '3/2 3' 'err_energy' --levels 7 -->
#   | h2/h1 | column | ... |
#   <!-- end table -->
#
#   bash chapters/evidence_tables.sh check PAGE...   run every command, diff its output with the
#                                                    page's table; status 1 when one has drifted
#   bash chapters/evidence_tables.sh update PAGE...  run every command, write its output into the page
#   bash chapters/evidence_tables.sh list PAGE...    the commands only
#
# One chapter's default-size tables: bash chapters/evidence_tables.sh check chapters/04_integral_matching/EVIDENCE.md
# (minutes: the runs are the evidence's). tests/evidence_quick.md holds such tables at the
# programs' --quick sizes; the test suite checks it. RUNS=DIR keeps each table's runs in
# DIR/PAGE_tableK (rate_table.sh's OUT).
set -euo pipefail
mode=${1:-}
shift || true
case "$mode" in check | update | list) ;; *) sed -n '2,19p' "$0" >&2; exit 2 ;; esac
[ $# -ge 1 ] || { echo "evidence_tables.sh: no page given" >&2; exit 2; }
# the pages as given, from where the command was run; the commands from the top folder
pages=()
for page in "$@"; do pages+=("$(realpath -m "$page")"); done
set -- "${pages[@]}"
cd "$(dirname "$0")/.."
drifted=0
# split PAGE DIR: the page cut at the markers: text pieces (DIR/after0, DIR/textK, DIR/afterK),
# one command per table (DIR/cmdK), the tables as written (DIR/oldK), their number (DIR/count)
split() {
  awk -v dir="$2" '
    /^<!-- table: .* -->$/ { n++; cmd = $0; sub(/^<!-- table: /, "", cmd); sub(/ -->$/, "", cmd)
                             print cmd > (dir "/cmd" n); print $0 > (dir "/text" n); inside = 1; next }
    inside && /^<!-- end table -->$/ { inside = 0; close(dir "/old" n); print $0 > (dir "/after" n); next }
    inside { print > (dir "/old" n); next }
    { print > (dir "/after" (n + 0)) }  # n + 0: the text before the first table is after0
    END { if (inside) { print "unterminated table " n > "/dev/stderr"; exit 2 } print n + 0 > (dir "/count") }' "$1"
}


for page in "$@"; do
  [ -r "$page" ] || { echo "evidence_tables.sh: cannot read $page" >&2; exit 2; }
  scratch=$(mktemp -d)
  split "$page" "$scratch"
  count=$(cat "$scratch/count")
  for ((k = 1; k <= count; ++k)); do
    cmd=$(cat "$scratch/cmd$k")
    if [ "$mode" = list ]; then echo "$page: $cmd"; continue; fi
    echo "$page: table $k of $count: $cmd" >&2
    # RUNS, when set, keeps each table's runs in a folder of their own (rate_table.sh's OUT)
    if [ -n "${RUNS:-}" ]; then export OUT=$RUNS/$(basename "$page" .md)_table$k; fi
    bash -c "$cmd" > "$scratch/new$k" 2> "$scratch/log$k" || { cat "$scratch/log$k" >&2; echo "evidence_tables.sh: the command failed" >&2; exit 1; }
    touch "$scratch/old$k"
    if ! diff -u "$scratch/old$k" "$scratch/new$k" > "$scratch/diff$k"; then
      if [ "$mode" = check ]; then
        echo "$page: table $k drifted from what its command prints now:" >&2
        cat "$scratch/diff$k" >&2
        drifted=$((drifted + 1))
      fi
    fi
  done
  if [ "$mode" = update ]; then
    # the page as it is now (it may have been edited while the runs went on), its tables replaced
    mkdir -p "$scratch/now"
    split "$page" "$scratch/now"
    for ((k = 1; k <= count; ++k)); do
      cmp -s "$scratch/cmd$k" "$scratch/now/cmd$k" ||
        { echo "evidence_tables.sh: $page changed its tables while they were run; nothing written" >&2; exit 1; }
    done
    {
      cat "$scratch/now/after0" 2>/dev/null || true
      for ((k = 1; k <= count; ++k)); do
        cat "$scratch/now/text$k" "$scratch/new$k" "$scratch/now/after$k"
      done
    } > "$scratch/page"
    cp "$scratch/page" "$page"
  fi
  rm -rf "$scratch"
done
[ "$mode" = check ] || exit 0
[ "$drifted" -eq 0 ] || exit 1
echo "evidence_tables.sh: every table is what its command prints"
