#!/usr/bin/env bash
# The figure of chapter 9's size table: time and memory per unknown against the unknowns, for
# the distributed contact solve (CG + GAMG), the physical limit measured beside it (one CHOLMOD
# factorization) and, if given, the same contact solve with MUMPS's Cholesky of K as the
# preconditioner. It reads the folders bench/parallel.sh --keep writes (one per chain of levels,
# each with shown.csv: the rows of the table).
#
#   bash bench/parallel_figure.sh OUT_DIR GAMG_RUNS [MUMPS_RUNS]
#
# writes OUT_DIR/scaling.dat, scaling.gp, scaling.png and scaling.pdf.
set -euo pipefail
shopt -s nullglob
[[ $# -ge 2 ]] || { echo "usage: parallel_figure.sh OUT_DIR GAMG_RUNS [MUMPS_RUNS]" >&2; exit 2; }
out=$1 gamg=$2 mumps=${3:-}
mkdir -p "$out"

# one line per size: unknowns, time, limit, memory per unknown, limit's memory per unknown
collect() {
  for csv in "$1"/*/shown.csv; do
    awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
      function v(n) { return (n in c) ? $(c[n]) : "NaN" }
      { m = v("cholmod_memory_mb"); t = v("cumulative_s") == "NaN" ? v("time_s") : v("cumulative_s")
        printf "%s %s %s %s %s\n", v("dofs"), t, v("limit_s"),
          1e6 * v("memory_mb") / v("dofs"), m == "NaN" ? "NaN" : 1e6 * m / v("dofs") }' "$csv"
  done | sort -g
}
{
  echo "# unknowns  time_s  limit_s  memory_B_per_unknown  limit_memory_B_per_unknown  (CG + GAMG runs)"
  collect "$gamg"
  if [[ -n "$mumps" ]]; then
    printf '\n\n# the same with MUMPS as the preconditioner\n'
    collect "$mumps"
  fi
} > "$out/scaling.dat"

mumps_time="" mumps_memory=""
if [[ -n "$mumps" ]]; then
  mumps_time=", 'scaling.dat' index 1 using 1:2 with linespoints pt 6 lw 2 title 'contact solve, CG + MUMPS (K factored once)'"
  mumps_memory=", 'scaling.dat' index 1 using 1:4 with linespoints pt 6 lw 2 title 'contact solve, CG + MUMPS'"
fi
body=$(cat <<EOF
reset
set multiplot layout 2,1
set logscale xy
set format x '10^{%L}'
set grid
set xrange [5e4:3e7]
set key bottom right
set xlabel 'unknowns'
set ylabel 'wall time [s]'
set title 'The whole contact solve against one factorization of K'
plot 'scaling.dat' index 0 using 1:2 with linespoints pt 7 lw 2 title 'whole contact solve, nested levels, CG + GAMG (2 ranks)', \\
     'scaling.dat' index 0 using 1:3 with linespoints pt 4 lw 2 dt 2 title 'physical limit: assemble, factorize (CHOLMOD) and solve K once'${mumps_time}, \\
     [1e5:2e7] 2e-6 * x title 'slope 1 (O(n))' dt 3 lc rgb 'black'
unset logscale y
set yrange [0:3000]
set ylabel 'peak memory [bytes per unknown]'
set title 'Peak resident memory per unknown'
set key top right
plot 'scaling.dat' index 0 using 1:4 with linespoints pt 7 lw 2 title 'contact solve, CG + GAMG (all ranks)', \\
     'scaling.dat' index 0 using 1:5 with linespoints pt 4 lw 2 dt 2 title 'CHOLMOD (rank 0, through the limit)'${mumps_memory}
unset multiplot
EOF
)
{
  echo "# Chapter 9's size table as a figure (bench/parallel_figure.sh): two ranks on this machine."
  echo "set terminal pngcairo size 900,1000 font 'sans,11'"
  echo "set output 'scaling.png'"
  echo "$body"
  echo "set terminal pdfcairo size 6.25,6.94 font 'sans,8'"
  echo "set output 'scaling.pdf'"
  echo "$body"
} > "$out/scaling.gp"
(cd "$out" && gnuplot scaling.gp)
echo "wrote $out/scaling.png"
