#!/usr/bin/env bash
# Where every number of the notes went. The notes of the course before they were split into
# lessons and evidence (README.md and chapters/NN_name/README.md) are kept as an inventory,
# docs/numbers/before.tsv: for each note, each number it printed and how many times. Every
# such number must still be printed, as many times, by the pages that took over that note,
# or be listed, with its reason, in docs/numbers/gone*.tsv ("note<TAB>number<TAB>count<TAB>reason",
# one file per chapter).
#
# A number here is a token with a decimal point or an exponent (0.53, 3.1e-01, 1e-8) or an
# integer of three digits or more (621, 13600): the measured values. Integers of one or two
# digits (equation, chapter and level numbers, most counts) are too common to follow this way.
# Quoted code (```cpp blocks, checked by check_quotes.sh) is left out; everything else counts,
# output blocks and tables included.
#
#   numbers.sh tokens FILE...     the tokens of FILE... as "token<TAB>count"
#   numbers.sh where              for every (note, number): where it is now (up to three lines per
#                                 page), or why it went, as a TSV on stdout (docs/numbers/where.tsv)
#   numbers.sh check              status 1, with the missing numbers, when one is lost
#   numbers.sh inventory COMMIT   rewrite before.tsv from the notes at COMMIT (done once)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
cd "$root"

# tokens < TEXT: one number per line, quoted code left out
tokens() {
  awk '/^```cpp/ {code = 1; next} code && /^```/ {code = 0; next} !code' |
    grep -oE '[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?' |
    grep -E '[.eE]|^[0-9]{3,}$' || true
}

# the pages that took over a note: a chapter's lesson and evidence; the README and docs/
successors() {
  case "$1" in
    README.md) echo README.md; ls docs/*.md 2>/dev/null || true ;;
    chapters/*/README.md) local d; d=$(dirname "$1"); echo "$d/README.md"; ls "$d"/EVIDENCE.md 2>/dev/null || true ;;
  esac
}

case "${1:-}" in
  tokens)
    shift
    cat "$@" | tokens | sort | uniq -c | awk '{printf "%s\t%d\n", $2, $1}'
    ;;
  inventory)
    commit=${2:?usage: numbers.sh inventory COMMIT}
    {
      printf 'note\tnumber\tcount\n'
      for note in README.md $(git ls-tree --name-only "$commit" chapters/ | sed 's|$|/README.md|'); do
        git cat-file -e "$commit:$note" 2>/dev/null || continue
        git show "$commit:$note" | tokens | sort | uniq -c | awk -v n="$note" '{printf "%s\t%s\t%d\n", n, $2, $1}'
      done
    } > "$here/before.tsv"
    echo "numbers.sh: $(($(wc -l < "$here/before.tsv") - 1)) (note, number) pairs from $commit in docs/numbers/before.tsv"
    ;;
  where | check)
    mode=$1
    scratch=$(mktemp -d)
    trap 'rm -rf "$scratch"' EXIT
    [ "$mode" = where ] && printf 'note\tnumber\tcount_before\tcount_now\twhere_now\n'
    lost=0
    for note in $(tail -n +2 "$here/before.tsv" | cut -f1 | uniq); do
      mapfile -t pages < <(successors "$note")
      cat "${pages[@]}" | tokens | sort | uniq -c | awk '{printf "%s\t%d\n", $2, $1}' > "$scratch/now"
      # numbers given up with a reason: "note<TAB>number<TAB>count<TAB>reason"
      awk -F'\t' -v n="$note" '$1 == n {print $2 "\t" $3}' "$here"/gone*.tsv 2>/dev/null > "$scratch/gone" || true
      awk -F'\t' -v n="$note" '$1 == n {print $2 "\t" $3}' "$here/before.tsv" > "$scratch/before"
      if [ "$mode" = where ]; then
        while IFS=$'\t' read -r number count; do
          # compared as strings: 0.01 and 0.010 are different numbers printed
          now=$(awk -F'\t' -v x="$number" '$1 "" == x "" {print $2}' "$scratch/now")
          places=$(for p in "${pages[@]}"; do
                     awk '/^```cpp/ {code = 1; next} code && /^```/ {code = 0; next} !code {print FNR "\t" $0}' "$p" |
                       { grep -E "[^0-9.]${number//./\\.}([^0-9]|\$)|^[0-9]+	${number//./\\.}([^0-9]|\$)" || true; } |
                       cut -f1 | head -3 | sed "s|^|$p:|"
                   done | paste -sd' ')
          gone=$(cat "$here"/gone*.tsv 2>/dev/null |
                 awk -F'\t' -v n="$note" -v x="$number" '$1 == n && $2 "" == x "" {print "gone (" $3 "): " $4}')
          printf '%s\t%s\t%s\t%s\t%s\n' "$note" "$number" "$count" "${now:-0}" "${places:-}${gone:+ $gone}"
        done < "$scratch/before"
      else
        missing=$(awk -F'\t' 'FILENAME == ARGV[1] {now[$1] = $2; next}
                              FILENAME == ARGV[2] {gone[$1] += $2; next}
                              { have = now[$1] + gone[$1]; if (have < $2) printf "  %s: %d of %d\n", $1, $2 - have, $2 }' \
                  "$scratch/now" "$scratch/gone" "$scratch/before")
        if [ -n "$missing" ]; then
          echo "$note: numbers printed before and now in none of [${pages[*]}] nor in docs/numbers/gone*.tsv:" >&2
          printf '%s\n' "$missing" >&2
          lost=$((lost + 1))
        fi
      fi
    done
    [ "$mode" = check ] && { [ "$lost" -eq 0 ] || exit 1; echo "numbers.sh: every number of the notes is still printed, or listed as gone with its reason"; }
    ;;
  *) sed -n '2,17p' "$0" >&2; exit 2 ;;
esac
