#!/usr/bin/env bash
# The course book builds (book/build.sh) into OUT_DIR and holds the whole course: every
# chapter's title, every figure under figures/ (embedded, named in its data-file attribute),
# no formula left as TeX, no figure a note shows that figures/ lacks, no link that leaves the
# book or misses its anchor, no heading printed as text ("## ..."), and at least MIN_PAGES pages
# of PDF. Status 77 (ctest: skipped)
# when pandoc, XeLaTeX or pdfinfo is missing.
#
#   test_book.sh SOURCE_DIR OUT_DIR MIN_PAGES
set -uo pipefail
source_dir=$1
out=$2
min_pages=$3
for tool in pandoc xelatex pdfinfo; do
  if ! command -v "$tool" > /dev/null; then
    echo "test_book: $tool is missing (bash course.sh book installs it): test skipped"
    exit 77
  fi
done
rm -rf "$out"
failures=0
fail() {
  echo "test_book: $1" >&2
  failures=$((failures + 1))
}

if ! bash "$source_dir/book/build.sh" "$out" > "$out.log" 2>&1; then
  cat "$out.log"
  fail "book/build.sh failed"
  exit 1
fi
html=$out/course.html
pdf=$out/course.pdf
[ -s "$html" ] || fail "no course.html"
[ -s "$pdf" ] || fail "no course.pdf"
[ "$failures" -eq 0 ] || exit 1

# pandoc leaves a formula it cannot turn into MathML as TeX, with a warning
if grep -q 'Could not convert TeX math' "$out.log"; then
  grep -A3 'Could not convert TeX math' "$out.log"
  fail "formulas left as TeX in the HTML"
fi
if grep -qF '$$' "$html"; then
  fail "the HTML still holds \$\$"
fi
for note in "$source_dir"/chapters/0[0-9]_*/README.md; do
  title=$(sed -n '/^# /{s/^# //p;q}' "$note")
  grep -qF "$title" "$html" || fail "chapter title missing from the HTML: $title"
done
while read -r figure; do
  grep -qF "data-file=\"$figure\"" "$html" || fail "figure missing from the HTML: $figure"
done < <(cd "$source_dir" && find figures -name '*.png' | LC_ALL=C sort)
if grep -q 'not generated yet' "$html"; then
  grep -o '\[figure [^]]* not generated yet\]' "$html" | sort -u
  fail "a note shows a figure that figures/ does not have"
fi
# every link between notes became an anchor inside the book, and each anchor exists
while read -r anchor; do
  grep -qF "id=\"$anchor\"" "$html" || fail "link to #$anchor, which the book does not have"
done < <(grep -oE 'href="#[^"]*"' "$html" | sed 's/^href="#//; s/"$//' | sort -u)
if grep -qE 'href="[^"#][^":]*"' "$html"; then
  grep -oE 'href="[^"#][^":]*"' "$html" | sort -u
  fail "links to files, which the book does not carry"
fi
# a heading that pandoc did not see (no blank line before it) is printed as text, "## ..."
# inside a paragraph or a list item, and drops out of the contents
stray=$(awk '/<pre/ {code = 1} !code && /(^|>)[[:space:]]*#+ [^ ]/ {print FNR ": " $0} /<\/pre>/ {code = 0}' "$html")
if [ -n "$stray" ]; then
  printf '%s\n' "$stray" | head -5
  fail "a heading printed as text (\"## ...\") in the HTML: a blank line is missing before it in the notes"
fi
# ... or, after a list item, folded into the item's text: a heading in the notes needs a blank
# line before it
for note in "$source_dir"/README.md "$source_dir"/chapters/0[0-9]_*/README.md "$source_dir"/exercises/*README.md \
            "$source_dir"/exercises/[0-9][0-9]_*/README.md; do
  glued=$(awk '/^```/ {code = !code} !code && FNR > 1 && prev != "" && /^#+ / {print FILENAME ":" FNR ": " $0} {prev = $0}' "$note")
  [ -z "$glued" ] || { printf '%s\n' "$glued"; fail "a heading with no blank line before it"; }
  # an equation number "(8)" that begins an indented line of a list item starts a nested list
  numbered=$(awk '/^```/ {code = !code} !code && /^[[:space:]]+\([0-9]+\) / {print FILENAME ":" FNR ": " $0}' "$note")
  [ -z "$numbered" ] || { printf '%s\n' "$numbered"; fail "an equation number at the start of a list item's line (pandoc reads a list)"; }
done
pages=$(pdfinfo "$pdf" | sed -n 's/^Pages: *//p')
echo "course.pdf: $pages pages, course.html: $(du -k "$html" | cut -f1) kB"
[ "${pages:-0}" -ge "$min_pages" ] || fail "course.pdf has $pages pages, expected at least $min_pages"
[ "$failures" -eq 0 ]
