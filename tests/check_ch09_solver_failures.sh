#!/usr/bin/env bash
# Chapter 9 says when a solve fails, once: a Krylov solve that stops short of its tolerance
# (whatever PETSc option stopped it), or an answer that differs from chapter 6's, ends the run
# with status 1 and one line naming the reason, on every rank (no PETSc trace, no MPI_Abort).
# And --help under mpirun ends with status 0.
#
#   check_ch09_solver_failures.sh MPIEXEC PROGRAM OUT_DIR
set -u
mpiexec=$1 program=$2 out=$3
failures=0
# EXPECTED_STATUS EXPECTED_TEXT ARGS...: two ranks under mpirun
expect() {
  local want=$1 text=$2
  shift 2
  rm -rf "$out"
  local output status lines
  output=$("$mpiexec" -n 2 "$program" --no-plot --out "$out" "$@" 2>&1)
  status=$?
  lines=$(printf '%s\n' "$output" | grep -c '^ch09_parallel_petsc:')
  if [ "$status" -ne "$want" ] || ! printf '%s' "$output" | grep -qF -- "$text" ||
     { [ "$want" -ne 0 ] && [ "$lines" -ne 1 ]; } || printf '%s' "$output" | grep -q 'PETSC ERROR\|MPI_ABORT\|exiting improperly'; then
    echo "not as expected (status $status, wanted $want, '$text' on one line): $*" >&2
    printf '%s\n' "$output" | tail -n 6 >&2
    failures=$((failures + 1))
  fi
}
# PETSc's options that stop the solve early are honoured, and the true residual says so
expect 1 "stopped on CONVERGED_ATOL after 0 iterations" --quick --reference none -ksp_atol 1e10
expect 1 "stopped on DIVERGED_ITS after 5 iterations" --quick --reference none -ksp_max_it 5
# a preconditioner with no smoothing: small in its own norm, not in the forces
expect 1 "above its tolerance 1e-13" --quick --reference none -mg_levels_ksp_max_it 0
expect 1 "the Krylov solve (richardson) stopped on" --quick --reference none -ksp_type richardson
# the difference to chapter 6 is a verdict
expect 1 "differs from chapter 6's answer by" --quick --ksp-rtol 1e-6
# body 1 a million times stiffer than body 2: PETSc's divergence test stopped a warm-started
# solve on round-off (DIVERGED_DTOL after 1 iteration); now it converges
expect 0 "wrote" --quick --reference none --E1 1e6
expect 0 "Usage: ch09_parallel_petsc" --help
[ "$failures" -eq 0 ] || exit 1
echo "check_ch09_solver_failures: every failure said once with status 1, --help with 0"
