#!/usr/bin/env bash
# chapters/evidence_tables.sh rewrites only what lies between a table's markers: the text before
# the first table, between tables and after the last stays as it was, and check then agrees;
# a table that differs from its command's output is reported, with status 1.
#
#   check_evidence_tables.sh SOURCE_DIR
set -u
script=$(cd "${1:?usage: check_evidence_tables.sh SOURCE_DIR}" && pwd)/chapters/evidence_tables.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
page=$work/page.md
printf '# Title\n\nText before the first table.\n\n<!-- table: echo "| a |"; echo "|---|"; echo "| 1 |" -->\nstale\n<!-- end table -->\n\nBetween.\n\n<!-- table: printf "| b |\\n|---|\\n| 2 |\\n" -->\n<!-- end table -->\n\nAfter the last.\n' > "$page"
bash "$script" check "$page" > /dev/null 2>&1 && { echo "check passed a stale table"; exit 1; }
(cd "$work" && bash "$script" update page.md) > /dev/null 2>&1 || { echo "update failed"; exit 1; }
expected=$(printf '# Title\n\nText before the first table.\n\n<!-- table: echo "| a |"; echo "|---|"; echo "| 1 |" -->\n| a |\n|---|\n| 1 |\n<!-- end table -->\n\nBetween.\n\n<!-- table: printf "| b |\\n|---|\\n| 2 |\\n" -->\n| b |\n|---|\n| 2 |\n<!-- end table -->\n\nAfter the last.')
[ "$(cat "$page")" = "$expected" ] || { echo "update changed the text around the tables:"; diff <(echo "$expected") "$page"; exit 1; }
bash "$script" check "$page" > /dev/null 2>&1 || { echo "check fails on the page update wrote"; exit 1; }
echo "check_evidence_tables: update rewrites the tables only, check catches a stale one"
