#!/usr/bin/env bash
# Every chapter's lesson (chapters/NN_name/README.md) in the course's order: the problem and
# the method (any headings), then
#
#   ## The program   ## Output (optional)   ## Results...   ## Figures
#   ## Exercise(s)   ## What to try next
#
# and no hard cases or asides, which belong to the chapter's evidence (EVIDENCE.md, titled
# "# Chapter N, the evidence: ..."), which the lesson links. A section out of place, or
# missing, fails with the file and the heading.
#
#   check_notes_order.sh SOURCE_DIR
set -u
source_dir=${1:?usage: check_notes_order.sh SOURCE_DIR}
failures=0
for note in "$source_dir"/chapters/[0-9][0-9]_*/README.md; do
  # the headings outside code blocks, each reduced to its kind
  kinds=$(awk '/^```/ {code = !code; next} !code && /^## / {print}' "$note" | sed -E \
    -e 's/^## The program.*/program/' -e 's/^## Output.*/output/' -e 's/^## Results.*/results/' \
    -e 's/^## Figures.*/figures/' -e 's/^## Hard cases.*/hard/' -e 's/^## Exercises?( .*)?$/exercise/' \
    -e 's/^## What to try next.*/next/' -e 's/^## Aside.*/aside/' -e 's/^## .*/other/')
  order=$(printf '%s\n' "$kinds" | uniq | tr '\n' ' ' | sed 's/ $//')
  # the problem and the method first (any number of other headings), then the fixed sequence
  expected_tail="program( output)? results figures exercise next"
  if ! printf '%s' "$order" | grep -Eq "^(other )*${expected_tail}$"; then
    echo "$note: sections in the order [$order], expected [problem/method ... $expected_tail]" >&2
    failures=$((failures + 1))
  fi
  evidence=$(dirname "$note")/EVIDENCE.md
  number=$(basename "$(dirname "$note")" | cut -c1-2)
  if [ ! -f "$evidence" ]; then
    echo "$note: no evidence page beside it ($evidence)" >&2
    failures=$((failures + 1))
  else
    head -1 "$evidence" | grep -Eq "^# Chapter ${number#0}, the evidence: " ||
      { echo "$evidence: the first line is not '# Chapter ${number#0}, the evidence: ...'" >&2; failures=$((failures + 1)); }
    grep -q '(EVIDENCE.md' "$note" || { echo "$note: no link to its EVIDENCE.md" >&2; failures=$((failures + 1)); }
  fi
done
[ "$failures" -eq 0 ] || exit 1
echo "check_notes_order: every lesson reads problem, method, program, result, figures, exercises, what next, and links its evidence"
