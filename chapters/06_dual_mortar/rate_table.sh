#!/usr/bin/env bash
# The local-rate table of chapter 6's notes ("Results: the bilateral problem, beside chapter
# 4"): the dual and the standard basis of M_h^1 at h2/h1 = 3/2, 2/3, 1/3 and 3, six levels
# each, one run of ch06_dual_mortar per ratio (about 5 min on two cores; the finest level of
# 1/3 has 1.48M dofs). Prints one line per ratio, quantity and basis: the local rates between
# levels k-1 and k, from the runs' local_rates.csv and standard_local_rates.csv.
#
#   bash chapters/06_dual_mortar/rate_table.sh [BUILD_DIR [OUT_DIR]]
set -euo pipefail
build=${1:-build}
out=${2:-results/ch06_rate_table}
program=$build/ch06_dual_mortar
[ -x "$program" ] || { echo "rate_table.sh: no $program (cmake --build $build --target ch06_dual_mortar)" >&2; exit 2; }
mkdir -p "$out"

# column of local_rates.csv | label
quantities=("err_energy|energy" "err_l2|u, L2" "err_pressure_function|lambda_h as a function, L2"
            "err_pressure|coefficients at the nodes (dual) or lambda_h (standard), L2"
            "err_pressure_hminus|the same, H^{-1/2}_h")
printf '%-6s %-62s %-9s %s\n' "h2/h1" "quantity" "basis" "local rates, levels 0-1, 1-2, ..."
for ratio in 3/2 2/3 1/3 3; do
  folder=$out/ratio_${ratio/\//_}
  "$program" --no-plot --no-hertz --h-ratio "$ratio" --out "$folder" > "$folder.log" 2>&1 ||
    { tail -n 20 "$folder.log" >&2; exit 1; }
  for q in "${quantities[@]}"; do
    IFS='|' read -r column label <<< "$q"
    for basis in dual standard; do
      file=$folder/local_rates.csv
      [ "$basis" = standard ] && file=$folder/standard_local_rates.csv
      rates=$(awk -F, -v want="$column" 'NR == 1 { for (c = 1; c <= NF; ++c) if ($c == want) col = c; next }
                                         col { printf "%s%.2f", (NR > 2 ? " " : ""), $col }' "$file")
      [ -n "$rates" ] && printf '%-6s %-62s %-9s %s\n' "$ratio" "$label" "$basis" "$rates"
    done
  done
done
echo "runs and logs in $out/"
