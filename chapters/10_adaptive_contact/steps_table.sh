#!/usr/bin/env bash
# A table of chapter 10's evidence page, remade from a run of ch10_adaptive_contact: the run's
# adaptive steps (convergence.csv) or uniform levels (uniform.csv), the columns named, every
# EVERY-th row and the last, as a Markdown table on stdout. The evidence page holds its output
# between "<!-- table: ... -->" markers (chapters/evidence_tables.sh remakes and checks them).
#
#   bash chapters/10_adaptive_contact/steps_table.sh FILE EVERY 'COLUMNS' [OPTION...]
#   bash chapters/10_adaptive_contact/steps_table.sh convergence.csv 3 'dofs err_energy effectivity' --scene punch
#
# FILE is convergence.csv, uniform.csv or summary.json (then COLUMNS are keys of "results",
# printed as one row). A run with the same options is made once and kept in OUT (default:
# results/ch10_tables/<options>) while it is newer than the program; BUILD (default: build)
# holds the program.
set -euo pipefail
[ $# -ge 3 ] || { sed -n '2,14p' "$0" >&2; exit 2; }
file=$1 every=$2 columns=$3
shift 3
build=${BUILD:-build}
program=$build/ch10_adaptive_contact
[ -x "$program" ] || { echo "steps_table.sh: no $program (cmake --build $build --target ch10_adaptive_contact)" >&2; exit 2; }
name=$(echo "default $*" | tr -c 'A-Za-z0-9.\n-' '_')
out=${OUT:-results/ch10_tables/$name}
if [ ! -f "$out/summary.json" ] || [ "$program" -nt "$out/summary.json" ]; then
  mkdir -p "$out"
  "$program" "$@" --no-plot --out "$out" > "$out.log" 2>&1 || { tail -n 20 "$out.log" >&2; exit 1; }
fi
if [ "$file" = summary.json ]; then
  python3 - "$out/summary.json" $columns <<'PY'
import json, sys
results = json.load(open(sys.argv[1]))["results"]
keys = sys.argv[2:]
print("| " + " | ".join(keys) + " |")
print("|" + "---|" * len(keys))
def show(v):
    return "n/a" if v is None else (f"{v:.4g}" if isinstance(v, float) else str(v))
print("| " + " | ".join(show(results.get(k)) for k in keys) + " |")
PY
  exit 0
fi
python3 - "$out/$file" "$every" $columns <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
every, keys = int(sys.argv[2]), sys.argv[3:]
for k in keys:
    if k not in rows[0]:
        sys.exit(f"steps_table.sh: no column {k} in {sys.argv[1]}")
def show(k, v):
    x = float(v)
    if k in ("step", "dofs", "newton_steps", "marked", "active_rows"): return f"{x:.0f}"
    if k.startswith("err_energy") or k == "estimator" or k.startswith("share_"): return f"{100 * x:.3g} %"
    return f"{x:.3g}"
print("| " + " | ".join(keys) + " |")
print("|" + "---:|" * len(keys))
for i, r in enumerate(rows):
    if i % every == 0 or i == len(rows) - 1:
        print("| " + " | ".join(show(k, r[k]) for k in keys) + " |")
PY
