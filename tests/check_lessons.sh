#!/usr/bin/env bash
# The length of every page a student reads, and the reading times the README promises.
#
# Words are counted outside fenced code blocks (the quoted code and program output; the markers
# naming a quote's file or a table's command count as words); lines of code are the lines
# inside fenced blocks. Reading time, in
# minutes: words / 100 + code lines / 10 (prose with its mathematics at 100 words a minute,
# code and output at 10 lines a minute).
#
# Checks: every lesson (chapters/NN_name/README.md) and the README at most 3,000 words; every
# chapter has its evidence page (EVIDENCE.md); the README's roadmap gives each lesson's and
# each evidence page's reading time within 10% of the computed one ("| ... | 27 min | 41 min |").
#
#   check_lessons.sh SOURCE_DIR            print the table, then check
#   check_lessons.sh SOURCE_DIR --minutes  print "PAGE MINUTES" only
#   check_lessons.sh SOURCE_DIR --write    write each page's minutes into the README's roadmap
#                                          ("[N min](chapters/NN_name/README.md)", the same for EVIDENCE.md)
set -u
source_dir=${1:?usage: check_lessons.sh SOURCE_DIR [--minutes]}
mode=${2:-check}
limit=3000

# words FILE, code_lines FILE
words() {
  awk '/^[[:space:]]*```/ {code = !code; next} !code' "$1" | wc -w
}
code_lines() {
  awk '/^[[:space:]]*```/ {code = !code; next} code' "$1" | wc -l
}
# minutes PAGE [FORMAT]: its reading time, rounded to whole minutes unless FORMAT says otherwise
minutes() {
  awk -v w="$(words "$1")" -v c="$(code_lines "$1")" -v f="${2:-%.0f}" 'BEGIN { printf f, w / 100 + c / 10 }'
}

pages=("$source_dir/README.md")
for lesson in "$source_dir"/chapters/[0-9][0-9]_*/README.md; do
  pages+=("$lesson")
  evidence=$(dirname "$lesson")/EVIDENCE.md
  [ -f "$evidence" ] && pages+=("$evidence")
done

if [ "$mode" = --minutes ]; then
  for page in "${pages[@]}"; do echo "${page#"$source_dir"/} $(minutes "$page")"; done
  exit 0
fi

if [ "$mode" = --write ]; then
  for page in "${pages[@]}"; do
    rel=${page#"$source_dir"/}
    [ "$rel" = README.md ] && continue
    sed -i "s|\[[0-9]* min\](${rel//./\\.})|[$(minutes "$page") min]($rel)|" "$source_dir/README.md"
  done
  mode=check
fi

failures=0
fail() { echo "check_lessons: $1" >&2; failures=$((failures + 1)); }
printf '%-44s %7s %11s %9s\n' page words "code lines" minutes
for page in "${pages[@]}"; do
  printf '%-44s %7d %11d %9d\n' "${page#"$source_dir"/}" "$(words "$page")" "$(code_lines "$page")" "$(minutes "$page")"
done
for page in "${pages[@]}"; do
  case "$page" in */EVIDENCE.md) continue ;; esac
  n=$(words "$page")
  [ "$n" -le "$limit" ] || fail "${page#"$source_dir"/}: $n words, more than $limit"
done

# the roadmap: one row per chapter, the lesson's link first, then its evidence's, each with "N min"
readme=$source_dir/README.md
for lesson in "$source_dir"/chapters/[0-9][0-9]_*/README.md; do
  dir=$(basename "$(dirname "$lesson")")
  evidence=$(dirname "$lesson")/EVIDENCE.md
  [ -f "$evidence" ] || { fail "chapters/$dir has no EVIDENCE.md"; continue; }
  row=$(grep -E "^\|.*\(chapters/$dir/README\.md\)" "$readme" | grep -F "chapters/$dir/EVIDENCE.md" | head -1)
  [ -n "$row" ] || { fail "README.md: no roadmap row linking chapters/$dir/README.md and its EVIDENCE.md"; continue; }
  # the first two "N min" of the row: the lesson's and the evidence's reading times
  read -r said_lesson said_evidence < <(printf '%s\n' "$row" | grep -oE '[0-9]+ min' | head -2 | awk '{printf "%s ", $1}')
  for which in lesson evidence; do
    if [ "$which" = lesson ]; then page=$lesson said=${said_lesson:-}; else page=$evidence said=${said_evidence:-}; fi
    [ -n "$said" ] || { fail "README.md: the roadmap row of $dir gives no reading time for its $which"; continue; }
    true_minutes=$(minutes "$page" %.2f)
    awk -v s="$said" -v t="$true_minutes" 'BEGIN { d = s - t; if (d < 0) d = -d; exit !(d <= 0.1 * t || d < 0.5) }' ||
      fail "README.md: the $which of $dir reads in $true_minutes min, the roadmap says $said min (more than 10% off)"
  done
done
[ "$failures" -eq 0 ] || exit 1
echo "check_lessons: every lesson and the README at most $limit words; the roadmap's reading times within 10%"
