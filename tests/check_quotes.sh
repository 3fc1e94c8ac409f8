#!/usr/bin/env bash
# Code quoted in the notes is the code that runs. Every ```cpp block of a chapter's lesson or
# evidence page is preceded by a marker naming the file it comes from,
#
#   <!-- quote: common/contact/dual_condensation.cpp -->
#
# and its lines are lines of that file, in the file's order. Comments and blank space do not
# count (a quote may comment differently, or more); lines may be left out, and a comment
# such as "// ..." may say so. A quoted line that is not in the file, or is out of order,
# fails with the note, the block's line and the missing line.
#
#   check_quotes.sh SOURCE_DIR
set -u
source_dir=${1:?usage: check_quotes.sh SOURCE_DIR}
failures=0
blocks=0
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# One line of code as compared: its // comment cut off, all blank space removed.
squeeze='{ sub(/\/\/.*/, ""); gsub(/[ \t\r]/, ""); print }'
for note in "$source_dir"/chapters/[0-9][0-9]_*/README.md "$source_dir"/chapters/[0-9][0-9]_*/EVIDENCE.md; do
  [ -f "$note" ] || continue
  # each block as "LINE<TAB>FILE" (FILE empty when the marker is missing)
  while IFS=$'\t' read -r line file; do
    blocks=$((blocks + 1))
    if [ -z "$file" ]; then
      echo "$note:$line: a cpp block without a '<!-- quote: FILE -->' marker before it" >&2
      failures=$((failures + 1)); continue
    fi
    if [ ! -r "$source_dir/$file" ]; then
      echo "$note:$line: the quoted file $file does not exist" >&2
      failures=$((failures + 1)); continue
    fi
    awk -v from="$line" 'NR > from && /^```/ {exit} NR > from' "$note" | awk "$squeeze" | grep -v '^$' > "$scratch/quote"
    awk "$squeeze" "$source_dir/$file" | grep -v '^$' > "$scratch/source"
    # the quote's lines, a subsequence of the file's lines
    missing=$(awk 'NR == FNR { q[++n] = $0; next } k < n && $0 == q[k + 1] { k++ }
                   END { if (k < n) print q[k + 1] }' "$scratch/quote" "$scratch/source")
    if [ -n "$missing" ]; then
      echo "$note:$line: not in $file (or out of order): $missing" >&2
      failures=$((failures + 1))
    fi
  done < <(awk '/^<!-- quote: / { file = $3; marked = NR; next }
               /^```cpp/ { print NR "\t" (marked == NR - 1 ? file : ""); code = 1; next }
               /^```/ { code = !code }' "$note")
done
[ "$failures" -eq 0 ] || exit 1
echo "check_quotes: $blocks quoted blocks, every line found in its file"
