#!/usr/bin/env bash
# Chapter 9's Newton steps and Krylov iterations per level, from a nested start and from a cold
# one, as a Markdown table on stdout: the parts of a run that repeat digit for digit (the times
# do not; bench/parallel.sh measures them). The lesson and the evidence page hold its output
# between "<!-- table: ... -->" markers (chapters/evidence_tables.sh remakes and checks them).
#
#   bash chapters/09_parallel_petsc/steps_table.sh [RANKS] [OPTION...]
#   bash chapters/09_parallel_petsc/steps_table.sh 2 --quick
#
# Two runs of ch09_parallel_petsc on RANKS ranks (default 2) with the options given: the
# default (nested, multigrid on K glued along the first active set) and --start cold
# --glue-weight 0 (every level from u = 0, multigrid on K). Each is made once and kept in OUT
# (default: results/ch09_tables/<options>) while it is newer than the program; BUILD (default:
# build) holds the program.
set -euo pipefail
ranks=2
if [[ "${1:-}" =~ ^[0-9]+$ ]]; then ranks=$1; shift; fi
build=${BUILD:-build}
program=$build/ch09_parallel_petsc
[ -x "$program" ] || { echo "steps_table.sh: no $program (cmake --build $build --target ch09_parallel_petsc)" >&2; exit 2; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1
name=$(echo "ranks $ranks $*" | tr -c 'A-Za-z0-9.\n-' '_')
out=${OUT:-results/ch09_tables/$name}
run() {  # run FOLDER OPTION...: the printed lines in FOLDER.log
  local folder=$1
  shift
  if [ ! -f "$folder/summary.json" ] || [ "$program" -nt "$folder/summary.json" ]; then
    mkdir -p "$folder"
    mpirun --oversubscribe -n "$ranks" "$program" "$@" --no-plot --out "$folder" > "$folder.log" 2>&1 ||
      { tail -n 20 "$folder.log" >&2; exit 1; }
  fi
}
run "$out/nested" "$@"
run "$out/cold" "$@" --start cold --glue-weight 0
# per level: unknowns, Newton steps, the Krylov iterations of each solve (' while the set moves),
# from the printed lines; the active set first guessed and found, from convergence.csv
solves() { sed -n 's/^level \([0-9]*\): \([0-9]*\) dofs.*, \([0-9]*\) Newton steps, Krylov iterations per solve[^:]*: \([^(]*\) (.*/\1|\2|\3|\4/p' "$1.log"; }
active() { awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next } { print $(c["active_first"]) "|" $(c["active_last"]) }' "$1/convergence.csv"; }
echo "| unknowns | cold: Newton steps | cold: Krylov iterations per solve | nested: Newton steps | nested: Krylov iterations per solve | nested: active nodes guessed, found |"
echo "|---:|---:|---|---:|---|---|"
paste -d'|' <(solves "$out/cold") <(solves "$out/nested") <(active "$out/nested") |
  awk -F'|' '{ sub(/ +$/, "", $4); sub(/ +$/, "", $8)
               printf "| %s | %s | %s | %s | %s | %s, %s |\n", $2, $3, $4, $7, $8, $9, $10 }'
