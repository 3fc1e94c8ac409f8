#!/usr/bin/env bash
# The speed table of docs/speed.md ("Speed: the physical limit"), measured in one run: for each
# chapter and size, the finest level's time, its physical limit (assemble K, one Cholesky
# factorization, one solve), their ratio, the spread of each over the repetitions, and the
# memory peak of the level against the limit's. Each program times its finest level and the
# limit interleaved, at least twice each, and keeps the minimum of each
# (common/linalg/physical_limit.hpp).
#
#   bash bench/speed_table.sh            # every row, up to the largest sizes (about 12 min)
#   bash bench/speed_table.sh --quick    # the default sizes only (about 1 min)
#   bash bench/speed_table.sh --threads 1   # the same with one BLAS/OpenMP thread
#   bash bench/speed_table.sh --keep DIR    # keep each run's output (summary.json, the phases
#                                           # in profile.csv, the printed log) in DIR/<row>/
#
# This is a benchmark, not a test: it asserts nothing and CI does not run it. It expects the
# programs in build/ (bash course.sh run, or cmake --build build).
set -euo pipefail
cd "$(dirname "$0")/.."

quick=0
threads=""  # the programs' default: every core
keep=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --quick) quick=1 ;;
    --threads) threads="${2:?--threads needs a number}"; shift ;;
    --keep) keep="${2:?--keep needs a folder}"; shift ;;
    *) echo "speed_table.sh: unknown option '$1' (--quick, --threads N, --keep DIR)" >&2; exit 2 ;;
  esac
  shift
done
[[ -z "$threads" || "$threads" =~ ^[1-9][0-9]*$ ]] || { echo "speed_table.sh: --threads must be a positive integer" >&2; exit 2; }
for p in ch02_p1_triangles ch03_pointwise_matching ch04_integral_matching ch05_unilateral_uzawa ch06_dual_mortar \
         ch07_quadratic_elements ch08_friction; do
  [[ -x "build/$p" ]] || { echo "speed_table.sh: build/$p is missing: build first (bash course.sh run)" >&2; exit 2; }
done

# One row per run: the program and its options (always --no-plot; chapters 5 and 6 also
# --no-compare, chapter 6 --no-hertz: its bilateral study alone; chapter 7 --no-p1: its P2
# study alone; chapter 8 --no-compare: its convergence study alone, Coulomb and Tresca).
runs=(
  "ch02_p1_triangles"
  "ch03_pointwise_matching"
  "ch04_integral_matching"
  "ch04_integral_matching --h-ratio 0.3333333 --levels 5"
  "ch05_unilateral_uzawa --no-compare"
  "ch05_unilateral_uzawa --no-compare --solver uzawa"
  "ch06_dual_mortar --no-compare --no-hertz"
  "ch07_quadratic_elements --no-p1"
  "ch07_quadratic_elements --no-p1 --matching pointwise"
)
if [[ $quick == 0 ]]; then
  runs+=(
    "ch02_p1_triangles --n0 16 --levels 7"
    "ch03_pointwise_matching --levels 7"
    "ch04_integral_matching --levels 7"
    "ch04_integral_matching --h-ratio 0.3333333 --levels 6"
    "ch04_integral_matching --saddle-solver elimination --levels 7"
    "ch04_integral_matching --saddle-solver elimination --h-ratio 0.3333333 --levels 6"
    "ch04_integral_matching --saddle-solver lu --levels 7"
    "ch05_unilateral_uzawa --no-compare --levels 7"
    "ch05_unilateral_uzawa --no-compare --levels 7 --solver uzawa"
    "ch05_unilateral_uzawa --no-compare --levels 7 --solver uzawa --acceleration none"
    "ch05_unilateral_uzawa --no-compare --levels 7 --matching pointwise"
    "ch06_dual_mortar --no-compare --no-hertz --levels 7"
    "ch07_quadratic_elements --no-p1 --levels 7"
    "ch08_friction --no-compare"
    "ch08_friction --no-compare --law tresca"
  )
fi

# A number from the "results" object of summary.json (the writer puts one key per line).
result() { sed -n "/\"results\"/,\$ s/^ *\"$2\": *\([^,]*\),\{0,1\}$/\1/p" "$1/summary.json" | head -1; }

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "threads: ${threads:-$(nproc) (the default, every core)}; $(nproc) cores; $(date -u +%Y-%m-%d)"
echo
echo "| run | dofs | time s | limit s | ratio | spread (time, limit) | peak memory / limit's |"
echo "|---|---|---|---|---|---|---|"
row=0
for run in "${runs[@]}"; do
  read -r -a args <<<"$run"
  row=$((row + 1))
  dir="$out/run"
  [[ -n "$keep" ]] && dir="$keep/$row"
  rm -rf "$dir"
  mkdir -p "$dir"
  extra=(--no-plot --profile --out "$dir")
  [[ -n "$threads" ]] && extra+=(--threads "$threads")
  if ! "build/${args[0]}" "${args[@]:1}" "${extra[@]}" >"$dir/log.txt" 2>&1; then
    echo "| \`$run\` | failed: $(tail -1 "$dir/log.txt") | | | | | |"
    continue
  fi
  echo "$run" >"$dir/command.txt"
  printf '| `%s` | %s | %.3g | %.3g | %.2f | %.0f%%, %.0f%% | %.2f |\n' "$run" \
    "$(result "$dir" dofs)" "$(result "$dir" time_s)" "$(result "$dir" limit_s)" \
    "$(result "$dir" limit_ratio)" "$(awk "BEGIN{print 100*$(result "$dir" time_spread)}")" \
    "$(awk "BEGIN{print 100*$(result "$dir" limit_spread)}")" "$(result "$dir" memory_ratio)"
done
