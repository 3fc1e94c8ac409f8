#!/usr/bin/env bash
# Set-up and entry point of the course on Debian 12 (as root, so missing packages install).
#
#   bash course.sh run    install what is missing, build the programs, run every chapter, refresh figures/
#   bash course.sh run 6  the same for one chapter (6, 06, ch06, ch06_dual_mortar or dual_mortar):
#                         builds its program alone, refreshes figures/ch06_dual_mortar/ only
#   bash course.sh test   install what is missing, build, run the test suite
#   bash course.sh book   install what is missing, write the course book in two editions: book/lessons.{html,pdf}
#                         and book/complete.{html,pdf} (with the evidence); their page counts go into README.md
#
# Each step prints one line; its output goes to build/logs/COMMAND/NN_step.log (one chapter's run:
# build/logs/run/PROGRAM/NN_step.log, kept when another chapter runs), shown (the last 60 lines)
# only when the step fails. The time of every step, and the total, close the run.
set -euo pipefail
cd "$(dirname "$0")"

packages=(g++ cmake make libeigen3-dev libgsl-dev gnuplot-nox fonts-dejavu-core
          libsuitesparse-dev libopenblas0-pthread googletest libgtest-dev libgmock-dev)
# The book (and its test): pandoc, XeLaTeX for the PDF, pdfinfo to count its pages.
book_packages=(pandoc texlive-xetex texlive-latex-recommended texlive-fonts-recommended lmodern
               fonts-dejavu-core poppler-utils)
# Chapter 9: PETSc with OpenMPI, MUMPS and hypre. The course builds and tests without it (and
# says so) where it cannot be installed.
petsc_packages=(libpetsc-real-dev)
chapters=(ch01_interface_traces ch02_p1_triangles ch03_pointwise_matching ch04_integral_matching
          ch05_unilateral_uzawa ch06_dual_mortar ch07_quadratic_elements ch08_friction)
# the chapters after chapter 9 (which needs PETSc and runs between them)
later_chapters=(ch10_adaptive_contact ch11_nitsche_contact)
# OpenMPI refuses to start as root unless told that it is meant (CI and this script run as root);
# its waiting ranks yield the core instead of polling it, which on two cores shared with other
# work made a run of a second take minutes.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_mpi_yield_when_idle=1
jobs=$(nproc 2>/dev/null || echo 2)
logs=build/logs/${1:-none}
step_count=0
step_times=()

# step LABEL COMMAND...: runs COMMAND with its output in a log file; on failure shows the
# log's tail and stops the whole command with COMMAND's status.
step() {
  local label=$1
  shift
  step_count=$((step_count + 1))
  mkdir -p "$logs"
  local log
  log=$logs/$(printf '%02d' "$step_count")_$(echo "$label" | tr -cs 'A-Za-z0-9' '_' | sed 's/_$//').log
  echo "$label"
  [ "$step_count" -gt 1 ] || rm -f "$logs"/*.log
  local start=$SECONDS status=0
  # Not "cmd || status=$?": bash would then ignore set -e inside COMMAND's functions.
  set +e
  (set -e; "$@") > "$log" 2>&1
  status=$?
  set -e
  step_times+=("$(printf '%6d s  %s' $((SECONDS - start)) "$label")")
  if [ "$status" -ne 0 ]; then
    echo "course.sh: step failed (status $status): $label" >&2
    tail -n 60 "$log" >&2
    echo "course.sh: full log: $log" >&2
    exit "$status"
  fi
}

print_times() {
  echo "time per step:"
  printf '%s\n' "${step_times[@]}"
  printf '%6d s  total\n' "$SECONDS"
}

install_missing() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  if [ "$(id -u)" -ne 0 ]; then
    echo "course.sh: missing Debian packages: ${missing[*]}; run as root to install them" >&2
    exit 1
  fi
  step "installing missing packages: ${missing[*]}" apt_install "${missing[@]}"
}

apt_install() {
  # another apt may hold the lock for a while: wait for it rather than fail
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    -o DPkg::Lock::Timeout=600 "$@"
}

configure() {
  # $1: build folder, then extra CMake arguments; the caller builds only what it needs
  local dir=$1
  shift
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@"
}

# Further scenes shown in the lecture notes: "program|folder under figures/program|options|label"
# Chapter 3 at h2/h1 = 1/3, where Theorem 4.1's h^{1/2} shows (about 45 s, 1.5M dofs at the end).
# Chapter 1's square-root edge over 12 levels (about 25 s).
# Chapter 5's smooth closure (the signorini scene, about 100 s with the solver comparison) and its
# exact Hertz solution, Theorem 5.1 measured at true contact edges (about 75 s with the comparison).
# Chapter 7 with pointwise matching: Theorem 4.1's h^{1/2} with P2, beside P1 (about 25 s).
# Chapter 8's Cattaneo-Mindlin scene: normal load, then shear in ten steps, and the load paths
# (about 90 s), and its manufactured scene under Tresca's law (about 40 s).
# Chapter 10's punch (singular corners: adaptive against uniform rates) and its bilateral scene.
# Chapter 11 at the other mesh ratio (six levels, about 65 s), with theta = -1 (about 40 s), and
# its two sweeps on level 4: gamma0 for every theta (about 50 s) and the stiffness ratio with
# each body's traction (about 15 s).
extra_runs=("ch01_interface_traces|edge|--trace edge --levels 12|chapter 1, square-root edge"
            "ch03_pointwise_matching|ratio_1_3|--h-ratio 1/3 --n0 6 --levels 7|chapter 3, h2/h1 = 1/3"
            "ch05_unilateral_uzawa|partial|--scene partial --levels 4 --no-compare|chapter 5, scene partial"
            "ch05_unilateral_uzawa|bilateral|--scene bilateral --levels 4 --no-compare|chapter 5, scene bilateral"
            "ch05_unilateral_uzawa|signorini|--scene signorini|chapter 5, scene signorini"
            "ch05_unilateral_uzawa|hertz_exact|--scene hertz-exact|chapter 5, scene hertz-exact"
            "ch07_quadratic_elements|pointwise|--matching pointwise|chapter 7, pointwise matching"
            "ch08_friction|cattaneo|--scene cattaneo|chapter 8, Cattaneo-Mindlin"
            "ch08_friction|tresca|--law tresca --no-compare|chapter 8, Tresca"
            "ch10_adaptive_contact|punch|--scene punch|chapter 10, the punch"
            "ch10_adaptive_contact|bilateral|--scene bilateral|chapter 10, scene bilateral"
            "ch11_nitsche_contact|ratio_1_3|--h-ratio 1/3 --levels 6|chapter 11, h2/h1 = 1/3"
            "ch11_nitsche_contact|skew|--theta -1|chapter 11, theta = -1"
            "ch11_nitsche_contact|gamma0|--sweep gamma0 --levels 5|chapter 11, gamma0 sweep"
            "ch11_nitsche_contact|stiffness|--sweep stiffness --levels 5|chapter 11, stiffness sweep")

# run_program PROGRAM RESULTS FIGURES [OPTIONS...]: the full output stays in RESULTS; the
# figures (PNG, and PDF when the program writes them) go to FIGURES, the .vtu files do not.
# $launcher, when set, starts the program (launcher="mpirun -n 2" for chapter 9).
run_program() {
  local program=$1 results=$2 figures=$3
  shift 3
  # shellcheck disable=SC2086
  ${launcher:-} "./build/$program" "$@" --out "$results"
  mkdir -p "$figures"
  local figure
  for figure in "$results"/*.png "$results"/*.pdf; do
    [ -e "$figure" ] && cp "$figure" "$figures/"
  done
  return 0
}

run_course() {
  # build/ is also the test command's tree: building only the programs here (not the test and
  # exercise executables) costs what a separate tree without tests would, and the test
  # command then finds the library and the programs already built.
  step "configuring build/" configure build
  step "building the programs" cmake --build build -j "$jobs" --target "${chapters[@]}" "${later_chapters[@]}"
  local program
  for program in "${chapters[@]}"; do
    run_chapter "$program"
  done
  if petsc_found; then
    step "building chapter 9" cmake --build build -j "$jobs" --target ch09_parallel_petsc
    run_chapter ch09_parallel_petsc
  else
    echo "PETSc not found: chapter 9 is not built (apt-get install ${petsc_packages[*]})"
  fi
  for program in "${later_chapters[@]}"; do
    run_chapter "$program"
  done
  echo "figures refreshed in figures/, full output in results/, logs in $logs/"
}

# One chapter: build its program alone, run it and its further scenes, refresh its figures.
run_one_chapter() {
  local program=$1
  step "configuring build/" configure build
  if [ "$program" = ch09_parallel_petsc ] && ! petsc_found; then
    echo "course.sh: PETSc not found: chapter 9 cannot be built (apt-get install ${petsc_packages[*]})" >&2
    exit 1
  fi
  step "building $program" cmake --build build -j "$jobs" --target "$program"
  run_chapter "$program"
  echo "figures refreshed in figures/$program/, full output in results/, logs in $logs/"
}

# run_chapter PROGRAM: its default run and its further scenes (extra_runs); figures/PROGRAM is
# rewritten from them and nothing else is.
run_chapter() {
  local program=$1 run name_program name options label
  rm -rf "figures/${program:?}"
  if [ "$program" = ch09_parallel_petsc ]; then
    step "running chapter 9 (ch09_parallel_petsc) on 2 ranks" \
      env_launcher "mpirun -n 2" run_program ch09_parallel_petsc results/ch09_parallel_petsc figures/ch09_parallel_petsc
    return 0
  fi
  local number=${program:2:2}
  step "running chapter ${number#0} ($program)" run_program "$program" "results/$program" "figures/$program"
  for run in "${extra_runs[@]}"; do
    IFS='|' read -r name_program name options label <<< "$run"
    [ "$name_program" = "$program" ] || continue
    # shellcheck disable=SC2086
    step "running $label" run_program "$program" "results/${program}_$name" "figures/$program/$name" $options
  done
}

# chapter_program WORD: the program of a chapter named by number (6, 06), short name (ch06),
# program (ch06_dual_mortar) or topic (dual_mortar).
chapter_program() {
  local want=$1 program
  for program in "${chapters[@]}" ch09_parallel_petsc "${later_chapters[@]}"; do
    local number=${program:2:2}
    case "$want" in
      "$program" | "ch$number" | "$number" | "${number#0}" | "${program:5}") echo "$program"; return 0 ;;
    esac
  done
  return 1
}

# env_launcher LAUNCHER COMMAND...: COMMAND with $launcher set
env_launcher() {
  local launcher=$1
  shift
  "$@"
}

# CMake found PETSc and MPI in build/ (chapters/CMakeLists.txt)
petsc_found() {
  grep -q '^PETSC_FOUND:INTERNAL=1' build/CMakeCache.txt 2>/dev/null
}

run_tests() {
  # The exercise skeletons as committed, whatever a student did to them in place: each must
  # fail its test (ctest label "skeletons"), while the solutions pass theirs.
  step "taking the committed exercise skeletons" bash exercises/pristine_skeletons.sh build/pristine_skeletons
  step "configuring build/" configure build -DMORTAR_PRISTINE_SKELETONS="$PWD/build/pristine_skeletons"
  step "building the library, programs, tests and exercises" cmake --build build -j "$jobs"
  step "unit, program, exercise, skeleton and book tests" \
    ctest --test-dir build --output-on-failure -j "$jobs"
  # The readable fallback: the same solver tests, and chapter 2's runs, without CHOLMOD.
  step "configuring build-fallback/ (without CHOLMOD)" configure build-fallback -DMORTAR_USE_CHOLMOD=OFF
  step "building the fallback solver tests and chapter 2" build_fallback
  step "fallback solver tests" \
    ctest --test-dir build-fallback --output-on-failure -j "$jobs" -R 'SpdSolver|Dirichlet|Programs.ch02'
  # The unit tests once more under AddressSanitizer and UndefinedBehaviorSanitizer, then the
  # programs built the same way: their --quick studies, the hard cases and the fuzzed command lines.
  # -O1 -g1 (line tables only): the sanitizers' reports keep their file:line stacks, and the
  # tree compiles in about half the time of the default -O2 -g.
  step "configuring build-sanitize/" \
    configure build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMORTAR_SANITIZE=ON \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -DNDEBUG"
  step "sanitizer build" cmake --build build-sanitize -j "$jobs" --target unit_tests sanitized_programs
  step "sanitized unit tests" ctest --test-dir build-sanitize --output-on-failure -j "$jobs" -L unit
  step "sanitized program runs and fuzzing" sanitized_program_runs
}

# The programs under the sanitizers; the log ends with how the fuzzed command lines fared.
sanitized_program_runs() {
  ctest --test-dir build-sanitize --output-on-failure -j "$jobs" -L sanitized_programs
  cat build-sanitize/tests/fuzz_runs/*.counts
}

# The fallback tree needs the library, the two solver tests and chapter 2 only. test_programs
# holds every program test and so depends on all five programs; "/fast" builds it alone
# (the Makefile generator's target without its dependencies) since only chapter 2 runs here.
build_fallback() {
  cmake --build build-fallback -j "$jobs" --target test_spd_solver test_dirichlet ch02_p1_triangles
  cmake --build build-fallback -j "$jobs" --target test_programs/fast
}

make_book() {
  step "writing the course book, both editions" bash book/build.sh book
  # the README gives the page counts of this build, never typed ones (tests/test_book.sh)
  local counts
  counts="lessons $(sed -n 's/^lessons //p' book/pages.txt) pages, complete $(sed -n 's/^complete //p' book/pages.txt) pages"
  sed -i "s|<!-- book pages -->[^<]*<!-- /book pages -->|<!-- book pages -->$counts<!-- /book pages -->|" README.md
  echo "book: book/lessons.html and book/lessons.pdf (the lessons), book/complete.html and book/complete.pdf (with the evidence): $counts"
}

case "${1:-}" in
  run)
    if [ $# -ge 2 ]; then
      program=$(chapter_program "$2") || {
        echo "course.sh: no chapter '$2' (a number 1-10, ch06, ch06_dual_mortar or dual_mortar)" >&2
        exit 2
      }
      # a chapter's logs of its own, so that running another chapter keeps them
      logs=build/logs/run/$program
      install_missing "${packages[@]}" "${petsc_packages[@]}"
      run_one_chapter "$program"
    else
      install_missing "${packages[@]}" "${petsc_packages[@]}"
      run_course
    fi
    ;;
  test) install_missing "${packages[@]}" "${petsc_packages[@]}" "${book_packages[@]}" git; run_tests ;;
  book) install_missing "${book_packages[@]}"; make_book ;;
  *) echo "usage: bash course.sh run [CHAPTER] | test | book" >&2; exit 2 ;;
esac
print_times
