#!/usr/bin/env bash
# Chapter 9's size table (docs/speed.md, chapter 9's evidence), measured in one run: for each size,
# the distributed contact solve on P ranks (CG + GAMG, inexact Newton), its Newton steps, the
# Krylov iterations of its final solve and of all its solves, its time and the resident-set
# peak of all ranks per unknown; beside it, in the same run and while it fits, the physical
# limit of the level (assemble K, one CHOLMOD factorization and solve, on rank 0) and its
# memory, and on the two smallest sizes chapter 6's whole CHOLMOD answer with the difference.
#
#   bash bench/parallel.sh                # 0.1M to 6.8M unknowns, 2 ranks (about 12 min)
#   bash bench/parallel.sh --large        # and 13.6M unknowns, without CHOLMOD (about 6 min more)
#   bash bench/parallel.sh --quick        # 0.1M and 0.4M unknowns only (about 1 min)
#   bash bench/parallel.sh --ranks 1      # 1 rank; 3 or 4 on this 2-core machine are
#                                         # oversubscribed, and labelled so
#   bash bench/parallel.sh --mumps        # MUMPS's parallel Cholesky instead of GAMG (to 1.7M)
#   bash bench/parallel.sh --keep DIR     # keep each run's output in DIR/<n1>/
#   bash bench/parallel.sh --figure DIR   # and draw DIR/scaling.png (bench/parallel_figure.sh);
#                                         # figures/ch09_size_table/ holds the one of the notes
#
# A benchmark, not a test: it asserts nothing and CI does not run it. It expects
# build/ch09_parallel_petsc (bash course.sh run ch09, or cmake --build build).
set -euo pipefail
cd "$(dirname "$0")/.."

ranks=2 large=0 quick=0 mumps=0 keep="" figure=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --ranks) ranks="${2:?--ranks needs a number}"; shift ;;
    --large) large=1 ;;
    --quick) quick=1 ;;
    --mumps) mumps=1 ;;
    --keep) keep="${2:?--keep needs a folder}"; shift ;;
    --figure) figure="${2:?--figure needs a folder}"; shift ;;
    *) echo "parallel.sh: unknown option '$1' (--ranks P, --large, --quick, --mumps, --keep DIR, --figure DIR)" >&2; exit 2 ;;
  esac
  shift
done
[[ "$ranks" =~ ^[1-9][0-9]*$ ]] || { echo "parallel.sh: --ranks must be a positive integer" >&2; exit 2; }
program=build/ch09_parallel_petsc
[[ -x "$program" ]] || { echo "parallel.sh: $program is missing: build first (bash course.sh run ch09)" >&2; exit 2; }
command -v mpirun > /dev/null || { echo "parallel.sh: mpirun is missing (openmpi-bin)" >&2; exit 2; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1
cores=$(nproc)
label="$ranks ranks"
(( ranks > cores )) && label="$ranks ranks on $cores cores (oversubscribed)"

# n1 (body 1's elements along Gamma_c; h2/h1 = 3/2, square bodies) and what runs beside it
rows=("192 answer" "384 answer" "768 limit" "1086 limit" "1536 limit")
(( large )) && rows+=("2172 none")
(( quick )) && rows=("192 answer" "384 answer")
(( mumps )) && rows=("192 answer" "384 answer" "768 limit")
solver=()
(( mumps )) && solver=(-pc_type cholesky -pc_factor_mat_solver_type mumps)

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "chapter 9, $label, $([[ $mumps == 1 ]] && echo "MUMPS's Cholesky" || echo "CG + GAMG"), final Krylov tolerance 1e-13"
echo
echo "| unknowns | Newton steps | most iterations of a solve | all iterations | time [s] | memory [B/unknown] | limit [s] | limit's memory [B/unknown] | time / limit | vs chapter 6 |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
for row in "${rows[@]}"; do
  read -r n reference <<< "$row"
  out="$work/$n"
  if ! mpirun --oversubscribe -n "$ranks" "$program" --n0 "$n" --levels 1 --reference "$reference" --no-plot \
       --out "$out" "${solver[@]}" > "$work/log" 2>&1; then
    echo "| n1 = $n | did not run: $(grep -m1 -i 'error\|needs' "$work/log" || tail -n 1 "$work/log") |"
    continue
  fi
  cp "$work/log" "$out/log.txt"
  [[ -n "$keep" ]] && { mkdir -p "$keep"; cp -r "$out" "$keep/"; }
  # one data row of convergence.csv, by column name
  awk -F, -v reference="$reference" '
    NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    function v(name) { return (name in col) ? $(col[name]) : "" }
    {
      dofs = v("dofs"); per = 1e6 / dofs
      limit = v("limit_s"); lmem = v("cholmod_memory_mb")
      ratio = limit != "" ? sprintf("%.2f", v("time_s") / limit) : "-"
      diff = reference == "answer" ? sprintf("%.1e, active set %s", v("max_rel_diff_vs_cholmod"),
                                             v("active_set_identical") == 1 ? "identical" : "DIFFERENT") : "-"
      printf "| %d | %d | %d | %d | %.3g | %.0f | %s | %s | %s | %s |\n", dofs, v("newton_steps"),
             v("ksp_iterations_max"), v("ksp_iterations_total"), v("time_s"), v("memory_mb") * per,
             limit != "" ? sprintf("%.3g", limit) : "-", lmem != "" ? sprintf("%.0f", lmem * per) : "-", ratio, diff
    }' "$out/convergence.csv"
done
echo
echo "memory: the resident-set peak of all ranks during the distributed solve (meshes included),"
echo "and of rank 0 during the limit (or chapter 6's answer and the limit), per unknown"
[[ -n "$figure" ]] && bash bench/parallel_figure.sh "$figure" "$work"
exit 0
