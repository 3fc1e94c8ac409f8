#!/usr/bin/env bash
# The course book in two editions, each as one HTML file (math as MathML, images embedded:
# nothing fetched when read) and one PDF (through XeLaTeX, which takes the notes' Unicode as it is):
#
#   lessons   the students' book: README.md, the nine lessons (chapters/NN_name/README.md), the
#             pages of docs/ a lesson links to (the bibliography, the extensions), the exercises
#   complete  the same with each chapter's evidence (chapters/NN_name/EVIDENCE.md) after its
#             lesson, every page of docs/, and every figure under figures/ that no page shows
#             (appendix "All figures")
#
#   bash book/build.sh OUT_DIR     writes OUT_DIR/lessons.{html,pdf}, OUT_DIR/complete.{html,pdf},
#                                  OUT_DIR/pages.txt ("lessons N" and "complete M": the PDFs' pages)
#                                  and OUT_DIR/figures.txt (the figures the complete edition holds)
#
# Needs pandoc, texlive-xetex, texlive-latex-recommended, texlive-fonts-recommended, lmodern
# and poppler-utils (bash course.sh book installs them).
set -euo pipefail
out=${1:?usage: bash book/build.sh OUT_DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$root"

# The notes are written for GitHub: lists may follow a line of text with no blank line between.
reader=markdown+lists_without_preceding_blankline+autolink_bare_uris
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The book's figures: every PNG under figures/ but those git ignores (the wall-time figures,
# which every run draws anew and nobody commits), so that a tree where the course has run gives
# the same book, page for page, as a fresh clone.
book_figures() {
  local all ignored
  all=$(find figures -name '*.png' | LC_ALL=C sort)
  if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
    ignored=$(printf '%s\n' "$all" | git check-ignore --stdin || true)
    [ -z "$ignored" ] || all=$(printf '%s\n' "$all" | grep -vxF -e "$ignored" || true)
  fi
  printf '%s\n' "$all"
}

# notes EDITION: the edition's pages, in reading order
notes() {
  echo README.md
  local lesson
  for lesson in chapters/[0-9][0-9]_*/README.md; do
    echo "$lesson"
    if [ "$1" = complete ] && [ -f "$(dirname "$lesson")/EVIDENCE.md" ]; then
      echo "$(dirname "$lesson")/EVIDENCE.md"
    fi
  done
  local page
  for page in docs/*.md; do
    [ -f "$page" ] || continue
    # the lessons' edition carries a page of docs/ only when a lesson links to it (the
    # bibliography, the extensions); the README's other links keep their text there
    if [ "$1" = complete ] || grep -qF "docs/$(basename "$page")" chapters/[0-9][0-9]_*/README.md; then
      echo "$page"
    fi
  done
  echo exercises/README.md
  ls exercises/[0-9][0-9]_*/README.md
}

# build EDITION: OUT_DIR/EDITION.html and OUT_DIR/EDITION.pdf
build() {
  local edition=$1 dir=$work/$1
  mkdir -p "$dir"
  local -a files book_files_meta=()
  mapfile -t files < <(notes "$edition")
  local note
  for note in "${files[@]}"; do
    book_files_meta+=(-M "book_files=$note")
  done
  # First pass: each note on its own, its paths and anchors made book-wide (book/book.lua).
  # The exercises are sections of the chapter "Exercises", so their headings go one level down.
  local index=0 options
  for note in "${files[@]}"; do
    options=()
    case "$note" in
      README.md) options+=(-M retitle=Introduction) ;;
      exercises/[0-9]*) options+=(--shift-heading-level-by=1) ;;
    esac
    index=$((index + 1))
    pandoc -f "$reader" -t markdown --wrap=none --lua-filter book/book.lua \
      -M "source=$note" "${book_files_meta[@]}" "${options[@]}" \
      -o "$dir/$(printf '%02d' "$index").md" "$note"
  done
  if [ "$edition" = complete ]; then
    # Every figure no note shows goes into an appendix, under its own path.
    {
      echo "# All figures {#all-figures}"
      echo
      echo "The figures under \`figures/\` that no page above shows, each under its path."
      echo
      book_figures | while read -r figure; do
        if ! grep -qF "($figure)" "$dir"/[0-9][0-9].md; then
          printf '![`%s`](%s){file="%s"}\n\n' "$figure" "$figure" "$figure"
        fi
      done
    } > "$dir/99_all_figures.md"
  fi
  local title subtitle
  title=$(sed -n '1s/^# //p' README.md)
  subtitle="After F. Ben Belgacem, P. Hild and P. Laborde, The mortar finite element method for contact problems (1998)"
  [ "$edition" = lessons ] && subtitle="The lessons. $subtitle"
  [ "$edition" = complete ] && subtitle="The lessons with their evidence. $subtitle"
  # the lessons' contents list the chapters; the complete one their sections too
  local depth=2
  [ "$edition" = lessons ] && depth=1
  local common=(-f "$reader" --toc --toc-depth=$depth --lua-filter book/book.lua
                --resource-path="$root" -M lang=en -M "title=$title" -M "subtitle=$subtitle")
  pandoc "${common[@]}" -t html5 --wrap=none --mathml --self-contained --css book/book.css \
    -o "$out/$edition.html" "$dir"/*.md
  pandoc "${common[@]}" -t latex --pdf-engine=xelatex --top-level-division=chapter \
    --include-in-header book/header.tex -V documentclass=report -V fontsize=10pt -V papersize=a4 \
    -V geometry:margin=2.2cm -V colorlinks=true -V mainfont="DejaVu Serif" \
    -V sansfont="DejaVu Sans" -V monofont="DejaVu Sans Mono" \
    -o "$out/$edition.pdf" "$dir"/*.md
}

book_figures > "$out/figures.txt"
build lessons &
lessons_job=$!
build complete
wait "$lessons_job"
{
  for edition in lessons complete; do
    echo "$edition $(pdfinfo "$out/$edition.pdf" | sed -n 's/^Pages: *//p')"
  done
} > "$out/pages.txt"
echo "book: $out/lessons.html, $out/lessons.pdf ($(sed -n 's/^lessons //p' "$out/pages.txt") pages);" \
     "$out/complete.html, $out/complete.pdf ($(sed -n 's/^complete //p' "$out/pages.txt") pages)"
