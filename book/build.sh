#!/usr/bin/env bash
# The course book: README.md, the chapters' notes in order, the exercises and every figure
# under figures/, as one HTML file (math as MathML, images embedded: nothing fetched when
# read) and one PDF (through XeLaTeX, which takes the notes' Unicode as it is).
#
#   bash book/build.sh OUT_DIR     writes OUT_DIR/course.html and OUT_DIR/course.pdf
#
# Needs pandoc, texlive-xetex, texlive-latex-recommended, texlive-fonts-recommended, lmodern
# (bash course.sh book installs them).
set -euo pipefail
out=${1:?usage: bash book/build.sh OUT_DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$root"

# The notes are written for GitHub: lists may follow a line of text with no blank line between.
reader=markdown+lists_without_preceding_blankline+autolink_bare_uris
notes=(README.md chapters/0[0-9]_*/README.md exercises/README.md exercises/[0-9][0-9]_*/README.md)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

book_files_meta=()
for note in "${notes[@]}"; do
  book_files_meta+=(-M "book_files=$note")
done

# First pass: each note on its own, its paths and anchors made book-wide (book/book.lua).
# The exercises are sections of the chapter "Exercises", so their headings go one level down.
index=0
for note in "${notes[@]}"; do
  options=()
  case "$note" in
    README.md) options+=(-M retitle=Introduction) ;;
    exercises/[0-9]*) options+=(--shift-heading-level-by=1) ;;
  esac
  index=$((index + 1))
  pandoc -f "$reader" -t markdown --wrap=none --lua-filter book/book.lua \
    -M "source=$note" "${book_files_meta[@]}" "${options[@]}" \
    -o "$work/$(printf '%02d' "$index").md" "$note"
done

# Every figure no note shows goes into an appendix, under its own path.
appendix=$work/99_all_figures.md
{
  echo "# All figures {#all-figures}"
  echo
  echo "The figures under \`figures/\` that no note above shows, each under its path."
  echo
  find figures -name '*.png' | LC_ALL=C sort | while read -r figure; do
    if ! grep -qF "($figure)" "$work"/[0-9][0-9].md; then
      printf '![`%s`](%s){file="%s"}\n\n' "$figure" "$figure" "$figure"
    fi
  done
} > "$appendix"

title=$(sed -n '1s/^# //p' README.md)
common=(-f "$reader" --toc --toc-depth=2 --lua-filter book/book.lua
        --resource-path="$root" -M lang=en -M "title=$title"
        -M "subtitle=After F. Ben Belgacem, P. Hild and P. Laborde, The mortar finite element method for contact problems (1998)")

pandoc "${common[@]}" -t html5 --wrap=none --mathml --self-contained --css book/book.css \
  -o "$out/course.html" "$work"/*.md

pandoc "${common[@]}" -t latex --pdf-engine=xelatex --top-level-division=chapter \
  --include-in-header book/header.tex -V documentclass=report -V fontsize=10pt -V papersize=a4 \
  -V geometry:margin=2.2cm -V colorlinks=true -V mainfont="DejaVu Serif" \
  -V sansfont="DejaVu Sans" -V monofont="DejaVu Sans Mono" \
  -o "$out/course.pdf" "$work"/*.md

echo "book: $out/course.html, $out/course.pdf"
