#!/usr/bin/env bash
# A local-rate table of the evidence pages, remade from its runs: one run of PROGRAM for each
# mesh ratio h2/h1 in RATIOS, with the OPTIONs given, then for each ratio and each column of
# COLUMNS the rates between levels k-1 and k (the run's local_rates.csv) and the coarsest and
# finest levels' values (convergence.csv), as a Markdown table on stdout. The evidence pages hold its output
# between "<!-- table: ... -->" markers (chapters/evidence_tables.sh remakes and checks them).
#
#   bash chapters/rate_table.sh PROGRAM 'RATIOS' 'COLUMNS' [OPTION...]
#   bash chapters/rate_table.sh ch03_pointwise_matching '3/2 3' 'err_energy err_jump' --n0 6 --levels 7
#
# BUILD (default: build) holds the programs; the runs and their logs go to OUT (default:
# results/PROGRAM_rates/ratio_R), named on stderr.
set -euo pipefail
# shellcheck source=/dev/null
source "$(dirname "$0")/rate_columns.sh"
[ $# -ge 3 ] || { sed -n '2,12p' "$0" >&2; exit 2; }
program=$1 ratios=$2 columns=$3
shift 3
build=${BUILD:-build}
out=${OUT:-results/${program}_rates}
[ -x "$build/$program" ] || { echo "rate_table.sh: no $build/$program (cmake --build $build --target $program)" >&2; exit 2; }
mkdir -p "$out"
rows=()
most=0
for ratio in $ratios; do
  folder=$out/ratio_${ratio/\//_}
  "$build/$program" "$@" --no-plot --h-ratio "$ratio" --out "$folder" > "$folder.log" 2>&1 ||
    { tail -n 20 "$folder.log" >&2; exit 1; }
  for column in $columns; do
    rates=$(awk -F, -v want="$column" 'NR == 1 { for (c = 1; c <= NF; ++c) if ($c == want) col = c; next }
                                       col { printf "%s%.2f", (NR > 2 ? " | " : ""), $col }' "$folder/local_rates.csv")
    [ -n "$rates" ] || { echo "rate_table.sh: no column $column in $folder/local_rates.csv" >&2; exit 2; }
    ends=$(awk -F, -v want="$column" 'NR == 1 { for (c = 1; c <= NF; ++c) if ($c == want) col = c; next }
                                      col { if (NR == 2) first = $col; v = $col } END { printf "%.3g | %.3g", first, v }' "$folder/convergence.csv")
    count=$(($(grep -o ' | ' <<< "$rates" | wc -l) + 1))
    [ "$count" -le "$most" ] || most=$count
    rows+=("$ratio|$column|$count|$rates|$ends")
  done
done
# one column per pair of levels (a shorter run leaves its last cells empty), then the values at
# the coarsest and the finest level
echo "| h2/h1 | column |$(level_header "$most") coarsest level | finest level |"
echo "|---|---|$(level_rule "$most")---|---|"
for row in "${rows[@]}"; do
  IFS='|' read -r ratio column count _ <<< "$row"
  rates=$(cut -d'|' -f4- <<< "$row" | sed 's/ *|[^|]*|[^|]*$//')
  values=$(sed 's/.*|\([^|]*|[^|]*\)$/\1/' <<< "$row")
  pad=""
  for ((k = count; k < most; ++k)); do pad+=" |"; done
  echo "| $ratio | \`$column\` | $rates |$pad $values |"
done
echo "rate_table.sh: runs and logs in $out/" >&2
