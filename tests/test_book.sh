#!/usr/bin/env bash
# The course book builds (book/build.sh) into OUT_DIR in its two editions. The complete one
# holds the whole course: every lesson's and evidence page's title, every figure under
# figures/ (embedded, named in its data-file attribute); the lessons' one every lesson's title
# in at most MAX_LESSON_PAGES pages. In both: no formula left as TeX, no figure a note shows
# that figures/ lacks, no link that leaves the book or misses its anchor, no heading printed as
# text ("## ..."). The README gives both page counts as the build finds them (course.sh book
# writes them there). Status 77 (ctest: skipped) when pandoc, XeLaTeX or pdfinfo is missing.
#
#   test_book.sh SOURCE_DIR OUT_DIR MAX_LESSON_PAGES
set -uo pipefail
source_dir=$1
out=$2
max_lesson_pages=$3
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
for edition in lessons complete; do
  [ -s "$out/$edition.html" ] || fail "no $edition.html"
  [ -s "$out/$edition.pdf" ] || fail "no $edition.pdf"
done
[ "$failures" -eq 0 ] || exit 1

# pandoc leaves a formula it cannot turn into MathML as TeX, with a warning
if grep -q 'Could not convert TeX math' "$out.log"; then
  grep -A3 'Could not convert TeX math' "$out.log"
  fail "formulas left as TeX in the HTML"
fi
for note in "$source_dir"/chapters/[0-9][0-9]_*/README.md "$source_dir"/chapters/[0-9][0-9]_*/EVIDENCE.md; do
  [ -f "$note" ] || continue
  # the title as text: up to its first formula, which the HTML sets as MathML
  title=$(sed -n '/^# /{s/^# //p;q}' "$note" | sed 's/ *\$.*//')
  grep -qF "$title" "$out/complete.html" || fail "title missing from complete.html: $title"
  case "$note" in
    */README.md) grep -qF "$title" "$out/lessons.html" || fail "lesson title missing from lessons.html: $title" ;;
  esac
done
while read -r figure; do
  grep -qF "data-file=\"$figure\"" "$out/complete.html" || fail "figure missing from complete.html: $figure"
done < "$out/figures.txt"
# the book's figures are every PNG under figures/ but the wall-time ones git ignores
[ "$(wc -l < "$out/figures.txt")" -ge "$(cd "$source_dir" && git ls-files 'figures/*.png' 2>/dev/null | wc -l)" ] ||
  fail "the book holds fewer figures than git tracks under figures/"
for edition in lessons complete; do
  html=$out/$edition.html
  if grep -qF '$$' "$html"; then
    fail "$edition.html still holds \$\$"
  fi
  if grep -q 'not generated yet' "$html"; then
    grep -o '\[figure [^]]* not generated yet\]' "$html" | sort -u
    fail "a note shows a figure that figures/ does not have"
  fi
  # every link between notes became an anchor inside the book, and each anchor exists
  while read -r anchor; do
    grep -qF "id=\"$anchor\"" "$html" || fail "$edition.html: link to #$anchor, which the book does not have"
  done < <(grep -oE 'href="#[^"]*"' "$html" | sed 's/^href="#//; s/"$//' | sort -u)
  if grep -qE 'href="[^"#][^":]*"' "$html"; then
    grep -oE 'href="[^"#][^":]*"' "$html" | sort -u
    fail "$edition.html: links to files, which the book does not carry"
  fi
  # a heading that pandoc did not see (no blank line before it) is printed as text, "## ..."
  # inside a paragraph or a list item, and drops out of the contents
  stray=$(awk '/<pre/ {code = 1} !code && /(^|>)[[:space:]]*#+ [^ ]/ {print FNR ": " $0} /<\/pre>/ {code = 0}' "$html")
  if [ -n "$stray" ]; then
    printf '%s\n' "$stray" | head -5
    fail "$edition.html: a heading printed as text (\"## ...\"): a blank line is missing before it in the notes"
  fi
done
# ... or, after a list item, folded into the item's text: a heading in the notes needs a blank
# line before it
for note in "$source_dir"/README.md "$source_dir"/chapters/[0-9][0-9]_*/*.md "$source_dir"/docs/*.md "$source_dir"/exercises/*README.md \
            "$source_dir"/exercises/[0-9][0-9]_*/README.md; do
  glued=$(awk '/^```/ {code = !code} !code && FNR > 1 && prev != "" && /^#+ / {print FILENAME ":" FNR ": " $0} {prev = $0}' "$note")
  [ -z "$glued" ] || { printf '%s\n' "$glued"; fail "a heading with no blank line before it"; }
  # an equation number "(8)" that begins an indented line of a list item starts a nested list
  numbered=$(awk '/^```/ {code = !code} !code && /^[[:space:]]+\([0-9]+\) / {print FILENAME ":" FNR ": " $0}' "$note")
  [ -z "$numbered" ] || { printf '%s\n' "$numbered"; fail "an equation number at the start of a list item's line (pandoc reads a list)"; }
done
lessons_pages=$(sed -n 's/^lessons //p' "$out/pages.txt")
complete_pages=$(sed -n 's/^complete //p' "$out/pages.txt")
echo "lessons.pdf: $lessons_pages pages, complete.pdf: $complete_pages pages"
[ "${lessons_pages:-9999}" -le "$max_lesson_pages" ] ||
  fail "the lessons' edition has $lessons_pages pages, more than $max_lesson_pages"
said=$(grep -o '<!-- book pages -->[^<]*<!-- /book pages -->' "$source_dir/README.md" | sed 's/<[^>]*>//g')
[ "$said" = "lessons $lessons_pages pages, complete $complete_pages pages" ] ||
  fail "README.md says [$said] of the book, the build gives lessons $lessons_pages pages, complete $complete_pages pages (bash course.sh book writes them)"
[ "$failures" -eq 0 ]
