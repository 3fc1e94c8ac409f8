#!/usr/bin/env bash
# Every chapter's notes in the course's order (README.md, "How a chapter reads"): the problem
# and the method (any headings), then
#
#   ## The program   ## Output (optional)   ## Results...   ## Figures   ## Hard cases
#   ## Exercise(s)   ## What to try next   ## Aside... (optional, timing and history)
#
# A section out of place, or missing, fails with the file and the heading.
#
#   check_notes_order.sh SOURCE_DIR
set -u
source_dir=${1:?usage: check_notes_order.sh SOURCE_DIR}
failures=0
for note in "$source_dir"/chapters/0[0-9]_*/README.md; do
  # the headings outside code blocks, each reduced to its kind
  kinds=$(awk '/^```/ {code = !code; next} !code && /^## / {print}' "$note" | sed -E \
    -e 's/^## The program.*/program/' -e 's/^## Output.*/output/' -e 's/^## Results.*/results/' \
    -e 's/^## Figures.*/figures/' -e 's/^## Hard cases.*/hard/' -e 's/^## Exercises?( .*)?$/exercise/' \
    -e 's/^## What to try next.*/next/' -e 's/^## Aside.*/aside/' -e 's/^## .*/other/')
  order=$(printf '%s\n' "$kinds" | uniq | tr '\n' ' ' | sed 's/ $//')
  # the problem and the method first (any number of other headings), then the fixed sequence
  expected_tail="program( output)? results figures hard exercise next( aside)?"
  if ! printf '%s' "$order" | grep -Eq "^(other )*${expected_tail}$"; then
    echo "$note: sections in the order [$order], expected [problem/method ... $expected_tail]" >&2
    failures=$((failures + 1))
  fi
done
[ "$failures" -eq 0 ] || exit 1
echo "check_notes_order: every chapter reads problem, method, program, results, figures, hard cases, exercises, extensions"
