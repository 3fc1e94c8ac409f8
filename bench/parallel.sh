#!/usr/bin/env bash
# Chapter 9's size table (docs/speed.md, chapter 9's notes and evidence), measured in one run of
# nested levels: each level's contact solve starts from the level below's answer and builds its
# multigrid once. For each size from 0.1M unknowns: the Newton steps, k (the whole contact
# solve, every level up to this one, over one linear solve with the same multigrid on K to the
# same tolerance, measured beside it), the Krylov iterations of all solves and of the largest,
# the set-up of the preconditioner, the time, the resident-set peak of all ranks per unknown, and
# in the same run, while it fits, the physical limit (assemble K, one CHOLMOD factorization and
# solve, on rank 0) and the ratio of the whole contact solve to it.
#
#   bash bench/parallel.sh                # 0.1M to 6.8M unknowns, 2 ranks (about 6 min)
#   bash bench/parallel.sh --large        # and 13.7M unknowns (a second chain, without CHOLMOD:
#                                         # its factor would not fit; about 6 min more)
#   bash bench/parallel.sh --quick        # 0.1M and 0.4M unknowns, against chapter 6 (about 1 min)
#   bash bench/parallel.sh --cold         # every level from u = 0 and on K, as before nested iteration
#   bash bench/parallel.sh --ranks 1      # 1 rank; 3 or 4 on this 2-core machine are
#                                         # oversubscribed, and labelled so
#   bash bench/parallel.sh --mumps        # MUMPS's parallel Cholesky instead of GAMG (to 1.7M)
#   bash bench/parallel.sh --keep DIR     # keep each chain's output in DIR/<n0>/
#   bash bench/parallel.sh --figure DIR   # and draw DIR/scaling.png (bench/parallel_figure.sh);
#                                         # figures/ch09_size_table/ holds the one of the notes
#
# A benchmark, not a test: it asserts nothing and CI does not run it. It expects
# build/ch09_parallel_petsc (bash course.sh run ch09, or cmake --build build).
set -euo pipefail
cd "$(dirname "$0")/.."

ranks=2 large=0 quick=0 mumps=0 cold=0 keep="" figure=""
while [[ $# -gt 0 ]]; do
  case "$1" in
    --ranks) ranks="${2:?--ranks needs a number}"; shift ;;
    --large) large=1 ;;
    --quick) quick=1 ;;
    --mumps) mumps=1 ;;
    --cold) cold=1 ;;
    --keep) keep="${2:?--keep needs a folder}"; shift ;;
    --figure) figure="${2:?--figure needs a folder}"; shift ;;
    *) echo "parallel.sh: unknown option '$1' (--ranks P, --large, --quick, --cold, --mumps, --keep DIR, --figure DIR)" >&2; exit 2 ;;
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

# chains of levels: n0 (body 1's elements along Gamma_c on the first level; h2/h1 = 3/2, square
# bodies), levels, what runs beside each level, and the first level shown (0.1M unknowns on)
chains=("12 8 limit 4")
(( large )) && chains+=("17 8 none 7")
(( quick )) && chains=("12 6 answer 4")
(( mumps )) && chains=("12 7 limit 4")
options=()
(( mumps )) && options+=(-pc_type cholesky -pc_factor_mat_solver_type mumps)
(( cold )) && options+=(--start cold --glue-weight 0)

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "chapter 9, $label, $([[ $mumps == 1 ]] && echo "MUMPS's Cholesky" || echo "CG + GAMG"), $([[ $cold == 1 ]] && echo "every level from a cold start, multigrid on K" || echo "nested levels, multigrid on K glued along the first active set"), final Krylov tolerance 1e-13"
echo
echo "| unknowns | Newton steps | k: linear solves | all iterations | largest solve | set-up [s] | this level [s] | with the levels below [s] | one linear solve [s] | memory [B/unknown] | limit [s] | limit's memory [B/unknown] | contact solve / limit | vs chapter 6 |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
for chain in "${chains[@]}"; do
  read -r n0 levels reference shown <<< "$chain"
  out="$work/$n0"
  if ! mpirun --oversubscribe -n "$ranks" "$program" --n0 "$n0" --levels "$levels" --reference "$reference" --no-plot \
       --out "$out" "${options[@]}" > "$work/log" 2>&1; then
    echo "| n0 = $n0, $levels levels | did not run: $(grep -m1 -i 'error\|needs' "$work/log" || tail -n 1 "$work/log") |"
    continue
  fi
  cp "$work/log" "$out/log.txt"
  # the rows shown, by column name (shown.csv: what the figure reads)
  awk -F, -v shown="$shown" 'NR == 1 || NR - 2 >= shown' "$out/convergence.csv" > "$out/shown.csv"
  [[ -n "$keep" ]] && { mkdir -p "$keep"; cp -r "$out" "$keep/"; }
  awk -F, -v reference="$reference" '
    NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    function v(name) { return (name in col) ? $(col[name]) : "" }
    {
      dofs = v("dofs"); per = 1e6 / dofs
      limit = v("limit_s"); lmem = v("cholmod_memory_mb")
      ratio = limit != "" ? sprintf("%.2f", v("cumulative_s") / limit) : "-"
      diff = reference == "answer" ? sprintf("%.1e, active set %s", v("max_rel_diff_vs_cholmod"),
                                             v("active_set_identical") == 1 ? "identical" : "DIFFERENT") : "-"
      printf "| %d | %d | %.2f | %d | %d | %.3g | %.3g | %.3g | %.3g | %.0f | %s | %s | %s | %s |\n", dofs, v("newton_steps"),
             v("linear_solves"), v("ksp_iterations_total"), v("ksp_iterations_max"), v("pc_setup_s"), v("time_s"),
             v("cumulative_s"), v("linear_s"), v("memory_mb") * per,
             limit != "" ? sprintf("%.3g", limit) : "-", lmem != "" ? sprintf("%.0f", lmem * per) : "-", ratio, diff
    }' "$out/shown.csv"
done
echo
echo "k: the whole contact solve (this level and every level below it) over one linear solve:"
echo "assembly, the same multigrid's set-up on K and CG on K u = f from u = 0 to the same tolerance."
echo "memory: the resident-set peak of all ranks during the distributed solve (meshes included),"
echo "and of rank 0 during the limit (or chapter 6's answer and the limit), per unknown"
[[ -n "$figure" ]] && bash bench/parallel_figure.sh "$figure" "$work"
exit 0
