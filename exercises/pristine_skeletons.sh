#!/usr/bin/env bash
# The exercise skeletons as committed, into OUT_DIR/NN_name/skeleton.cpp, for the check that
# every untouched skeleton fails its test (exercises/CMakeLists.txt, MORTAR_PRISTINE_SKELETONS).
# Students edit skeleton.cpp in place, so the files on disk may be solved: the committed ones
# come from git: HEAD, or the commit MORTAR_SKELETONS_REF names (a student who commits solved
# skeletons on a branch of their own sets it to main). Without git history (a tarball) the files
# on disk are taken, and the script says so. A file already up to date is not rewritten, so nothing rebuilds for nothing.
#
#   bash exercises/pristine_skeletons.sh OUT_DIR
set -euo pipefail
out=${1:?usage: bash exercises/pristine_skeletons.sh OUT_DIR}
cd "$(dirname "$0")/.."

# The history must be this tree's own: a tarball unpacked inside another repository has none.
ref=${MORTAR_SKELETONS_REF:-HEAD}
if [ -n "${MORTAR_SKELETONS_REF:-}" ] && ! git rev-parse --verify --quiet "$ref^{commit}" > /dev/null 2>&1; then
  echo "pristine_skeletons.sh: MORTAR_SKELETONS_REF=$ref is not a commit of this repository" >&2
  exit 2
fi
have_history=false
if command -v git > /dev/null && git rev-parse --verify --quiet "$ref^{commit}" > /dev/null 2>&1 &&
   [ "$(git rev-parse --show-toplevel)" = "$(pwd -P)" ]; then
  have_history=true
fi
if $have_history; then
  echo "skeletons as committed at $(git rev-parse --short "$ref^{commit}") ($ref)"
else
  echo "no git history here: the skeletons on disk are taken as the untouched ones"
fi

for folder in exercises/[0-9][0-9]_*/; do
  name=$(basename "$folder")
  mkdir -p "$out/$name"
  fresh=$out/$name/skeleton.cpp.new
  if $have_history && git show "$ref:exercises/$name/skeleton.cpp" > "$fresh" 2> /dev/null; then
    echo "$name: committed skeleton"
  else
    cp "exercises/$name/skeleton.cpp" "$fresh"
    echo "$name: skeleton on disk (not in git history)"
  fi
  if cmp -s "$fresh" "$out/$name/skeleton.cpp"; then
    rm "$fresh"
  else
    mv "$fresh" "$out/$name/skeleton.cpp"
  fi
done
