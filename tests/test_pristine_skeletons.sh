#!/usr/bin/env bash
# exercises/pristine_skeletons.sh gives the committed skeleton even when a student has solved
# it in place, and the file on disk when there is no git history (a tarball). Run on a copy
# of the repository in WORK_DIR, with exercise 01's skeleton replaced by its solution.
#
#   test_pristine_skeletons.sh SOURCE_DIR WORK_DIR
set -uo pipefail
source_dir=$1
work=$2
exercise=exercises/01_merge_grids
rm -rf "$work"
mkdir -p "$work"
failures=0
fail() {
  echo "test_pristine_skeletons: $1" >&2
  failures=$((failures + 1))
}
# solve_in_place REPO: the student's move, the solution copied over the skeleton
solve_in_place() {
  cp "$1/$exercise/solution.cpp" "$1/$exercise/skeleton.cpp"
}

if command -v git > /dev/null && git -C "$source_dir" rev-parse --verify --quiet HEAD > /dev/null; then
  git clone --quiet "$source_dir" "$work/clone"
  # the script under test is the one in the source tree, committed or not
  cp "$source_dir/exercises/pristine_skeletons.sh" "$work/clone/exercises/"
  solve_in_place "$work/clone"
  bash "$work/clone/exercises/pristine_skeletons.sh" "$work/from_git" > "$work/from_git.log"
  git -C "$work/clone" show "HEAD:$exercise/skeleton.cpp" > "$work/committed.cpp"
  cmp -s "$work/from_git/01_merge_grids/skeleton.cpp" "$work/committed.cpp" ||
    fail "with git history, the skeleton taken is not the committed one"
  cmp -s "$work/from_git/01_merge_grids/skeleton.cpp" "$work/clone/$exercise/skeleton.cpp" &&
    fail "with git history, the skeleton taken is the one solved in place"
  mkdir -p "$work/tarball"
  git -C "$work/clone" archive HEAD | tar -x -C "$work/tarball"
  cp "$source_dir/exercises/pristine_skeletons.sh" "$work/tarball/exercises/"
else
  echo "no git history in $source_dir: only the tarball case is checked"
  mkdir -p "$work/tarball"
  cp -r "$source_dir/exercises" "$work/tarball/"
fi

# Without history the files on disk are all there is: they are taken, and the log says so.
solve_in_place "$work/tarball"
bash "$work/tarball/exercises/pristine_skeletons.sh" "$work/from_disk" > "$work/from_disk.log"
cmp -s "$work/from_disk/01_merge_grids/skeleton.cpp" "$work/tarball/$exercise/skeleton.cpp" ||
  fail "without git history, the skeleton taken is not the file on disk"
grep -q 'no git history' "$work/from_disk.log" ||
  fail "without git history, the script does not say it takes the files on disk"
count=$(find "$work/from_disk" -name skeleton.cpp | wc -l)
expected=$(find "$source_dir/exercises" -mindepth 2 -maxdepth 2 -name skeleton.cpp | wc -l)
[ "$count" -eq "$expected" ] || fail "$count skeletons taken, $expected exercises"
[ "$failures" -eq 0 ]
