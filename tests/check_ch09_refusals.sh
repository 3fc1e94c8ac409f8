#!/usr/bin/env bash
# Chapter 9 refuses bad input like every program: status 2, one line naming the problem (no
# PETSc trace), nothing written; a PETSc option that PETSc does not know is refused, not
# ignored, and so is one whose value PETSc refuses, or that the chapter cannot honour.
#
#   check_ch09_refusals.sh MPIEXEC PROGRAM OUT_DIR
set -u
mpiexec=$1 program=$2 out=$3
failures=0
# RANKS EXPECTED_TEXT ARGS...: 1 rank runs the program alone (MPI's singleton start, a
# third of mpirun's), 2 ranks under mpirun
expect_refused() {
  local ranks=$1 text=$2
  shift 2
  rm -rf "$out"
  local output status launcher=()
  [ "$ranks" -eq 1 ] || launcher=("$mpiexec" -n "$ranks")
  output=$("${launcher[@]}" "$program" --no-plot --out "$out" "$@" 2>&1)
  status=$?
  if [ "$status" -ne 2 ] || ! printf '%s' "$output" | grep -qF -- "$text" || [ -e "$out" ] ||
     [ "$(printf '%s\n' "$output" | grep -c '^ch09_parallel_petsc:')" -ne 1 ] ||
     printf '%s' "$output" | grep -q 'PETSC ERROR\|MPI_ABORT\|exiting improperly'; then
    echo "not refused as expected (status $status, wanted 2 and '$text'): $*" >&2
    printf '%s\n' "$output" | tail -n 5 >&2
    failures=$((failures + 1))
  fi
}
expect_refused 2 "PETSc does not know or does not use -ksp_tipe" --quick -ksp_tipe cg
expect_refused 1 "PETSc does not know or does not use -pc_gamg_treshold" --quick -pc_gamg_treshold 0.01
expect_refused 2 "--bogus: unknown option" --quick --bogus
expect_refused 1 "--start: expects one of nested|cold, got 'warm'" --quick --start warm
expect_refused 1 "--glue-weight: must be in [0, 1000000], got -1" --quick --glue-weight -1
expect_refused 1 "--glue-weight: expects a finite number, got 'nan'" --quick --glue-weight nan
# PETSc's values, found by the trial solve and named
expect_refused 2 "-pc_type bogus: PETSc refuses it" --quick -pc_type bogus
expect_refused 2 "-ksp_type bogus: PETSc refuses it" --quick -ksp_type bogus
expect_refused 2 "-pc_type: PETSc refuses it" --quick -pc_type
expect_refused 2 "-ksp_divtol abc: PETSc refuses it" --quick -ksp_divtol abc
expect_refused 2 "-options_file /nonexistent: cannot be read" --quick -options_file /nonexistent
# options the chapter cannot honour
expect_refused 2 "-ksp_rtol: the Krylov tolerances are the course's --ksp-rtol" --quick -ksp_rtol -1
expect_refused 1 "-ksp_rtol: the Krylov tolerances are the course's --ksp-rtol" --quick -ksp_rtol abc
expect_refused 2 "-ksp_type preonly:" --quick -ksp_type preonly
expect_refused 2 "-ksp_norm_type none:" --quick -ksp_norm_type none
expect_refused 2 "-mat_type:" --quick -mat_type dense
# bodies 1000 times taller than wide: double precision cannot fix u to --agreement
expect_refused 1 "--L: bodies 1e+03 times as tall" --quick --L 1e-3
expect_refused 1 "--agreement" --quick --agreement 0
expect_refused 1 "--agreement: double precision fixes u only to about" --quick --agreement 1e-15
expect_refused 1 "--E1" --quick --E1 -1
expect_refused 1 "--nu2" --quick --nu2 0.5
expect_refused 1 "--n0" --n0 0
expect_refused 1 "--levels" --quick --levels 3
expect_refused 1 "--ksp-rtol" --quick --ksp-rtol 0
expect_refused 1 "--delta" --quick --delta 2
expect_refused 1 "--loose-rtol" --quick --loose-rtol 0.5
expect_refused 1 "--reference" --quick --reference exact
expect_refused 1 "--scene" --quick --scene signorini
expect_refused 1 "--E1" --quick --E1 1e11
expect_refused 1 "GB of memory, 84.9 GB of it for the distributed solve" --n0 1024 --levels 3
# the distributed solve fits (15 GB), chapter 6's CHOLMOD on rank 0 would not (28 GB)
expect_refused 1 "chapter 6's CHOLMOD answer or limit on rank 0" --n0 1800 --levels 1
[ "$failures" -eq 0 ] || exit 1
echo "check_ch09_refusals: every bad input refused with status 2, nothing written"
