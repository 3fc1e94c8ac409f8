#!/usr/bin/env bash
# The local-rate table of chapter 6's evidence ("The bilateral problem, beside chapter 4"): the
# dual and the standard basis of M_h^1 at h2/h1 = 3/2, 2/3, 1/3 and 3, six levels each, one run
# of ch06_dual_mortar per ratio (about 5 min on two cores; the finest level of 1/3 has 1.48M
# dofs). Prints a Markdown table, one row per ratio, quantity and basis: the local rates between
# levels k-1 and k, from the runs' local_rates.csv and standard_local_rates.csv, and for the dual
# basis the fitted rate over the three finest levels ("rates" in summary.json). Further OPTIONs
# go to every run (--quick: the same table at the small sizes, seconds).
#
#   bash chapters/06_dual_mortar/rate_table.sh [OPTION...]
#
# BUILD (default: build) holds the program; the runs and their logs go to OUT (default:
# results/ch06_rate_table), named on stderr.
set -euo pipefail
# shellcheck source=/dev/null
source "$(dirname "$0")/../rate_columns.sh"
build=${BUILD:-build}
out=${OUT:-results/ch06_rate_table}
program=$build/ch06_dual_mortar
[ -x "$program" ] || { echo "rate_table.sh: no $program (cmake --build $build --target ch06_dual_mortar)" >&2; exit 2; }
mkdir -p "$out"

# column of local_rates.csv | label
quantities=("err_energy|energy" "err_l2|\$u\$, \$L^2\$" "err_pressure_function|\$\\lambda_h\$ as a function, \$L^2\$"
            "err_pressure|coefficients at the nodes (dual) or \$\\lambda_h\$ (standard), \$L^2\$"
            "err_pressure_hminus|the same, \$H^{-1/2}_h\$")
rows=()
most=0
for ratio in 3/2 2/3 1/3 3; do
  folder=$out/ratio_${ratio/\//_}
  "$program" "$@" --no-plot --no-hertz --h-ratio "$ratio" --out "$folder" > "$folder.log" 2>&1 ||
    { tail -n 20 "$folder.log" >&2; exit 1; }
  for q in "${quantities[@]}"; do
    IFS='|' read -r column label <<< "$q"
    for basis in dual standard; do
      file=$folder/local_rates.csv
      [ "$basis" = standard ] && file=$folder/standard_local_rates.csv
      rates=$(awk -F, -v want="$column" 'NR == 1 { for (c = 1; c <= NF; ++c) if ($c == want) col = c; next }
                                         col { printf "%s%.2f", (NR > 2 ? " | " : ""), $col }' "$file")
      [ -n "$rates" ] || continue
      fit=""
      if [ "$basis" = dual ]; then
        # "rates": { "err_energy": 0.9991, ... } in summary.json, the fit over the three finest levels
        fit=$(sed -n '/"rates": {/,/}/p' "$folder/summary.json" |
              sed -n "s/^ *\"$column\": \([-0-9.e+]*\),\{0,1\}$/\1/p" | awk '{printf "%.3f", $1}')
      fi
      count=$(($(grep -o ' | ' <<< "$rates" | wc -l) + 1))
      [ "$count" -le "$most" ] || most=$count
      rows+=("$ratio	$label	$basis	$count	$rates	$fit")
    done
  done
done
echo "| \$h_2/h_1\$ | quantity | basis |$(level_header "$most") fit |"
echo "|---|---|---|$(level_rule "$most")---|"
for row in "${rows[@]}"; do
  IFS=$'\t' read -r ratio label basis count rates fit <<< "$row"
  pad=""
  for ((k = count; k < most; ++k)); do pad+=" |"; done
  echo "| $ratio | $label | $basis | $rates |$pad $fit |"
done
echo "rate_table.sh: runs and logs in $out/" >&2
