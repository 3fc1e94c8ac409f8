#!/usr/bin/env bash
# Set-up and entry point of the course on Debian 12 (as root, so missing packages install).
#
#   bash course.sh run    install what is missing, build, run every chapter, refresh figures/
#   bash course.sh test   install what is missing, build, run the test suite
set -euo pipefail
cd "$(dirname "$0")"

packages=(g++ cmake make libeigen3-dev libgsl-dev gnuplot-nox fonts-dejavu-core
          libsuitesparse-dev libopenblas0-pthread googletest libgtest-dev libgmock-dev)
chapters=(ch01_interface_traces ch02_p1_triangles ch03_pointwise_matching ch04_integral_matching
          ch05_unilateral_uzawa)
jobs=$(nproc 2>/dev/null || echo 2)

install_missing() {
  local missing=()
  for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  if [ "$(id -u)" -ne 0 ]; then
    echo "course.sh: missing Debian packages: ${missing[*]}; run as root to install them" >&2
    exit 1
  fi
  echo "Installing: ${missing[*]}"
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
}

build() {
  # $1: build folder, then extra CMake arguments
  local dir=$1
  shift
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@" > /dev/null
  cmake --build "$dir" -j "$jobs"
}

configure() {
  # $1: build folder, then extra CMake arguments; the caller builds only what it needs
  local dir=$1
  shift
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@" > /dev/null
}

# Further scenes shown in the lecture notes: "program|folder under figures/program|options"
# Chapter 3 at h2/h1 = 1/3, where Theorem 4.1's h^{1/2} shows (about 45 s, 1.5M dofs at the end).
# Chapter 1's square-root edge over 12 levels (about 25 s).
# Chapter 5's exact unilateral solution, Theorem 5.1 measured (about 100 s with the solver comparison).
extra_runs=("ch01_interface_traces|edge|--trace edge --levels 12"
            "ch03_pointwise_matching|ratio_1_3|--h-ratio 1/3 --n0 6 --levels 7"
            "ch05_unilateral_uzawa|partial|--scene partial --levels 4 --no-compare"
            "ch05_unilateral_uzawa|bilateral|--scene bilateral --levels 4 --no-compare"
            "ch05_unilateral_uzawa|signorini|--scene signorini")

run_course() {
  build build
  for program in "${chapters[@]}"; do
    echo "== $program"
    "./build/$program" --out "results/$program"
    mkdir -p "figures/$program"
    rm -rf "figures/$program"/*
    cp "results/$program"/*.png "figures/$program/"
  done
  for run in "${extra_runs[@]}"; do
    IFS='|' read -r program name options <<< "$run"
    echo "== $program $options"
    # shellcheck disable=SC2086
    "./build/$program" $options --out "results/${program}_$name"
    mkdir -p "figures/$program/$name"
    cp "results/${program}_$name"/*.png "figures/$program/$name/"
  done
  echo "Figures refreshed in figures/, full output in results/."
}

run_tests() {
  build build
  ctest --test-dir build --output-on-failure -j "$jobs"
  # The readable fallback: the same solver tests in a build without CHOLMOD.
  configure build-fallback -DMORTAR_USE_CHOLMOD=OFF
  cmake --build build-fallback -j "$jobs" --target test_spd_solver test_dirichlet test_programs
  ctest --test-dir build-fallback --output-on-failure -j "$jobs" -R 'SpdSolver|Dirichlet|Programs.ch02'
  check_skeletons_fail
  # The unit tests once more under AddressSanitizer and UndefinedBehaviorSanitizer, then the
  # programs built the same way: their --quick studies, the hard cases and the fuzzed command lines.
  configure build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMORTAR_SANITIZE=ON
  cmake --build build-sanitize -j "$jobs" --target unit_tests sanitized_programs
  ctest --test-dir build-sanitize --output-on-failure -j "$jobs" -L unit
  ctest --test-dir build-sanitize --output-on-failure -j "$jobs" -L sanitized_programs
  cat build-sanitize/tests/fuzz_runs/*.counts
}

# Every untouched exercise skeleton must fail its test (the solutions pass in the main run).
check_skeletons_fail() {
  configure build-skeleton -DMORTAR_EXERCISES=skeleton
  cmake --build build-skeleton -j "$jobs" --target exercises
  local bad=0
  for folder in exercises/[0-9][0-9]_*/; do
    local name
    name=$(basename "$folder")
    if ctest --test-dir build-skeleton -L exercises -R "^${name}\." > /dev/null 2>&1; then
      echo "exercise $name: the untouched skeleton passes its test" >&2
      bad=1
    else
      echo "exercise $name: the untouched skeleton fails its test, as it should"
    fi
  done
  return $bad
}

case "${1:-}" in
  run) install_missing; run_course ;;
  test) install_missing; run_tests ;;
  *) echo "usage: bash course.sh run|test" >&2; exit 2 ;;
esac
