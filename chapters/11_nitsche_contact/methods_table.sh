#!/usr/bin/env bash
# A table of chapter 11's notes, remade from a run of ch11_nitsche_contact, as Markdown on stdout.
# The notes hold its output between "<!-- table: ... -->" markers (chapters/evidence_tables.sh
# remakes and checks them).
#
#   bash chapters/11_nitsche_contact/methods_table.sh MODE [OPTION...]
#
#   rates:COLUMN      one row per method: the local rates of COLUMN (err_energy, err_l2,
#                     err_pressure) between levels k-1 and k, and its coarsest and finest values
#   summary           one row per method: the energy and L2 rates over the three finest levels
#                     (summary.json), the finest level's errors and its Newton steps
#   finest            one row per method on the finest level: the errors, |a_h - a|, Newton
#                     steps, Krylov iterations (where counted)
#   values:COLUMN     one row per method: COLUMN (half_width_error_m, ...) on each level
#   steps             one row per method: its Newton steps (mortar: active-set steps) on each level
#   krylov            one row per method: the Krylov iterations of its last matrix on each level
#                     where they were counted (--krylov-max-dofs), and K's beside them
#   speed             one row per method: its time on each level divided by the level's physical
#                     limit (wall times: they differ from run to run, so no page checks them)
#   sweep:COLUMN      --sweep gamma0: COLUMN (err_energy, err_pressure, newton_steps) against
#                     gamma0, one column per variant; runs that did not converge are marked
#   stiffness:COLUMN  --sweep stiffness: COLUMN against E1 / E2, one column per traction and
#                     for the two mortar references
#
# A run with the same options is made once and kept in OUT (default: results/ch11_tables/
# <options>) while it is newer than the program; BUILD (default: build) holds the program.
set -euo pipefail
[ $# -ge 1 ] || { sed -n '2,18p' "$0" >&2; exit 2; }
mode=$1
shift
build=${BUILD:-build}
program=$build/ch11_nitsche_contact
[ -x "$program" ] || { echo "methods_table.sh: no $program (cmake --build $build --target ch11_nitsche_contact)" >&2; exit 2; }
case "$mode" in
  rates:* | values:* | summary | finest | steps | krylov | speed | sweep:* | stiffness:*) ;;
  *) echo "methods_table.sh: unknown mode '$mode' (rates:COLUMN, values:COLUMN, summary, finest, steps, krylov, speed, sweep:COLUMN, stiffness:COLUMN)" >&2
     exit 2 ;;
esac
name=$(echo "default $*" | tr -c 'A-Za-z0-9.\n-' '_')
out=${OUT:-results/ch11_tables/$name}
if [ ! -f "$out/summary.json" ] || [ "$program" -nt "$out/summary.json" ]; then
  mkdir -p "$out"
  "$program" "$@" --no-plot --out "$out" > "$out.log" 2>&1 || { tail -n 20 "$out.log" >&2; exit 1; }
fi
python3 - "$out" "$mode" <<'PY'
import csv, json, math, sys

out, mode = sys.argv[1], sys.argv[2]
methods = [("nitsche", "Nitsche"), ("penalty", "penalty, gamma = gamma0 E/h"), ("penalty_fixed", "penalty, gamma fixed"),
           ("mortar", "mortar, standard basis"), ("dual", "mortar, dual basis")]


def rows(name):
    with open(f"{out}/{name}") as f:
        return list(csv.DictReader(f))


def number(text):
    try:
        v = float(text)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def show(v, digits=3):
    return "-" if v is None else f"{v:.{digits}g}"


def count(text):  # an iteration count: "-" where not counted, "failed" where -1
    v = number(text)
    return "-" if v is None else "failed" if v < 0 else str(int(v))


def rate(v):
    return "-" if v is None or not isinstance(v, (int, float)) else f"{v:.2f}"


def per_level(levels, cell, first=()):
    """One column per level (its dofs), one row per method: cell(key, level row); `first` rows before."""
    print("| method |" + "".join(f" {int(float(r['dofs']))} dofs |" for r in levels))
    print("|---|" + "---|" * len(levels))
    for label, cells in first:
        print(f"| {label} | " + " | ".join(cells) + " |")
    for key, label in methods:
        if key == "mortar" and kind == "krylov":
            label += " (K)"
        if key == "dual" and kind == "krylov":
            label += " (T^T K T)"
        print(f"| {label} | " + " | ".join(cell(key, r) for r in levels) + " |")


def per_method(header, cells):
    """One row per method: its label, then cells(key)."""
    print("| method | " + " | ".join(header) + " |")
    print("|---|" + "---|" * len(header))
    for key, label in methods:
        print(f"| {label} | " + " | ".join(cells(key)) + " |")


kind, _, column = mode.partition(":")
if kind == "rates":
    local, levels = rows("local_rates.csv"), rows("convergence.csv")
    pairs = len(local)
    print("| method |" + "".join(f" {k}-{k + 1} |" for k in range(pairs)) + " coarsest level | finest level |")
    print("|---|" + "---|" * pairs + "---|---|")
    for key, label in methods:
        c = f"{column}_{key}"
        rates = [r[c] for r in local]
        cells = " | ".join("-" if number(r) is None else f"{float(r):.2f}" for r in rates)
        print(f"| {label} | {cells} | {show(number(levels[0][c]))} | {show(number(levels[-1][c]))} |")
elif kind == "summary":
    rates = json.load(open(f"{out}/summary.json"))["rates"]
    last = rows("convergence.csv")[-1]
    per_method(["energy rate", "L2 rate", "energy error", "L2 error", "pressure error", "Newton steps"],
               lambda key: [rate(rates.get(f"err_energy_{key}")), rate(rates.get(f"err_l2_{key}")),
                            show(number(last[f"err_energy_{key}"])), show(number(last[f"err_l2_{key}"])),
                            show(number(last[f"err_pressure_{key}"])), count(last[f"newton_steps_{key}"])])
elif kind == "values":
    per_level(rows("convergence.csv"), lambda key, r: show(number(r[f"{column}_{key}"])))
elif kind == "steps":
    per_level(rows("convergence.csv"), lambda key, r: count(r[f"newton_steps_{key}"]))
elif kind == "krylov":
    per_level([r for r in rows("convergence.csv") if r["krylov_iterations_nitsche"] != ""],
              lambda key, r: count(r[f"krylov_iterations_{key}"]))
elif kind == "finest":
    last = rows("convergence.csv")[-1]
    per_method(["energy error", "L2 error", "pressure error", "\\|a_h - a\\| [m]", "Newton steps", "Krylov iterations"],
               lambda key: [show(number(last[f"err_{e}_{key}"])) for e in ("energy", "l2", "pressure")] +
                           [show(number(last[f"half_width_error_m_{key}"])), count(last[f"newton_steps_{key}"]),
                            count(last[f"krylov_iterations_{key}"])])
elif kind == "speed":
    levels = rows("convergence.csv")

    def ratio(key, r):
        time, limit = number(r[f"time_s_{key}"]), number(r["limit_s"])
        return show(time / limit if time and limit else None)

    per_level(levels, ratio, [("physical limit [s]", [show(number(r["limit_s"])) for r in levels])])
elif kind == "sweep":
    data = rows("gamma_sweep.csv")
    variants = [("nitsche", "1.000000", "theta = 1"), ("nitsche", "0.000000", "theta = 0"),
                ("nitsche", "-1.000000", "theta = -1"), ("penalty", "", "penalty")]
    print("| gamma0 |" + "".join(f" {v[2]} |" for v in variants))
    print("|---|" + "---|" * len(variants))
    for g in sorted({float(r["gamma0"]) for r in data}):
        cells = []
        for method, theta, _ in variants:
            r = next(r for r in data if r["method"] == method and r["theta"] == theta and float(r["gamma0"]) == g)
            v = show(number(r[column]))
            cells.append(v if r["converged"] == "1" else v + " (no conv.)")
        print(f"| {g:.3g} | " + " | ".join(cells) + " |")
elif kind == "stiffness":
    data = rows("stiffness_sweep.csv")
    kinds = [("body1", "Nitsche, body 1's traction"), ("body2", "Nitsche, body 2's traction"),
             ("harmonic", "Nitsche, weighted h/E"), ("mortar", "mortar, standard"), ("dual", "mortar, dual")]
    print("| E1/E2 |" + "".join(f" {k[1]} |" for k in kinds))
    print("|---|" + "---|" * len(kinds))
    for ratio in sorted({float(r["E1_over_E2"]) for r in data}):
        cells = []
        for k, _ in kinds:
            r = next(r for r in data if float(r["E1_over_E2"]) == ratio and (r["traction"] == k or r["method"] == k))
            v = show(number(r[column]))
            cells.append(v if r["converged"] == "1" else v + " (no conv.)")
        print(f"| {ratio:.0e} | " + " | ".join(cells) + " |")
PY
