#!/usr/bin/env python3
"""Prints one summary table of every benchmark result under results/bench/.

Google Benchmark JSON files (bench_*.json, run with repetitions) contribute
their median aggregates; macro-benchmark CSV files (*.csv with a header) are
printed as they are. The speed targets (docs/performance.md) are listed here so
the table shows the margin."""
import csv
import glob
import json
import os
import sys

# benchmark name prefix -> (target, unit) of the speed targets
# (the run-name prefixes of the benchmarks the targets are about)
TARGETS = {
    "BM_EnergyGradientHessian/0/": (100e-6, "s"),   # twist-free rod E + g + H, n = 400
    "BM_UpdateGradientHessian/0/": (50e-6, "s"),    # broad phase + barrier g + H, knot13
    "BM_MaxStep/": (100e-6, "s"),                   # one CCD query
    "BM_FirstSample/": (20e-3, "s"),                # one lattice sample, 12 crossings
    "BM_NextSample/": (20e-3, "s"),
    "BM_SimilarityMatrix/500/": (2.0, "s"),         # 500 x 500 similarity matrix
}

UNIT = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}

# "Skip what a scene does not need": each skip measured on and off.
# (what is skipped, benchmark with the skip, benchmark without it); names are
# Google Benchmark run names (median aggregates) or "solver_skips:VARIANT"
# (total seconds of exp_bench_solver --skips over the same lattice samples).
SKIPS = [
    ("twist-free path (Θ free): rod energy+gradient+Hessian, 3n vs 4n+1 dofs",
     "BM_EnergyGradientHessian/0", "BM_EnergyGradientHessian/1"),
    ("twist-free path (Θ free): relaxations of the fixed samples (total)",
     "solver_skips:default", "solver_skips:full-model"),
    ("no contact work when no pair is near: broad phase vs all-pairs distances (circle, n=400)",
     "BM_NoContact", "BM_NoContactAllPairs"),
    ("collision detection only on broad-phase pairs (knot13, step 0.1)",
     "BM_MaxStep/0/1", "BM_MaxStepAllPairs/0/1"),
    ("collision detection only on broad-phase pairs (knot13, step 0.5)",
     "BM_MaxStep/0/5", "BM_MaxStepAllPairs/0/5"),
    ("swept broad phase of the collision detection kept while the motion stays within ccd_skin (knot13, step 0.1)",
     "BM_MaxStepKept/0/1", "BM_MaxStep/0/1"),
    ("broad phase reused while no vertex moved skin/2 (knot13)",
     "BM_BroadPhase/0/0", "BM_BroadPhase/0/1"),  # second argument 1: skin 0 (fresh)
    ("projected pair Hessians in their <= 5-dim range, not 12x12 eigen-decompositions (knot13, 52 pairs)",
     "BM_PairHessianProjection/0/2", "BM_PairHessianProjection/0/0"),
    ("symbolic factorisation reused while the contact set is unchanged (simplicial, ordering kept)",
     "BM_FactorizeNumericOnly/0", "BM_FactorizeSymbolicAndNumeric/0/1"),
    ("eigen-analysis (stiffness attribute) only when asked: relaxations of the fixed samples (total)",
     "solver_skips:default", "solver_skips:eigen"),
]


def fmt_seconds(s):
    if s < 1e-3:
        return f"{s * 1e6:9.2f} us"
    if s < 1.0:
        return f"{s * 1e3:9.2f} ms"
    return f"{s:9.3f} s "


def skips_table(rows, folder):
    """Prints the SKIPS table from the medians in rows and solver_skips.csv."""
    times = {name: sec for _, name, sec, _ in rows}
    path = os.path.join(folder, "solver_skips.csv")
    if os.path.exists(path):
        with open(path) as f:
            for r in csv.DictReader(f):
                times["solver_skips:" + r["variant"]] = float(r["total_seconds"])

    def lookup(name):
        # a run name may carry a label or repetitions suffix after the arguments
        if name in times:
            return times[name]
        hits = [t for n, t in times.items() if n.startswith(name + "/") and not n[len(name) + 1:].isdigit()]
        return hits[0] if len(hits) == 1 else None

    lines = []
    for what, on, off in SKIPS:
        t_on, t_off = lookup(on), lookup(off)
        if t_on is None or t_off is None:
            continue
        lines.append((what, t_on, t_off))
    if not lines:
        return
    width = max(len(w) for w, _, _ in lines)
    print(f"\nskips: time with the skip (on) and without it (off), one core")
    print(f"{'skip':<{width}}  {'on':>12}  {'off':>12}  {'speed-up':>8}")
    for what, t_on, t_off in lines:
        print(f"{what:<{width}}  {fmt_seconds(t_on):>12}  {fmt_seconds(t_off):>12}  {t_off / t_on:7.2f}x")


def main(folder):
    rows = []
    for path in sorted(glob.glob(os.path.join(folder, "bench_*.json"))):
        with open(path) as f:
            data = json.load(f)
        for b in data.get("benchmarks", []):
            if b.get("aggregate_name", "median") != "median":
                continue
            name = b.get("run_name", b["name"]).replace("_median", "")
            seconds = b["real_time"] * UNIT.get(b.get("time_unit", "ns"), 1e-9)
            target = next((t for p, (t, _) in TARGETS.items() if name.startswith(p)), None)
            rows.append((os.path.basename(path)[:-5], name, seconds, target))
    if rows:
        width = max(len(r[1]) for r in rows)
        print(f"{'executable':<16} {'benchmark':<{width}}  {'median':>12}  {'target':>12}  ok")
        for exe, name, s, t in rows:
            ok = "" if t is None else ("yes" if s <= t else "NO")
            print(f"{exe:<16} {name:<{width}}  {fmt_seconds(s):>12}  {fmt_seconds(t) if t else '':>12}  {ok}")
    skips_table(rows, folder)
    # the macro tables: the default method, then contact-stiffness continuation
    # (make bench writes it to continuation/)
    tables = sorted(glob.glob(os.path.join(folder, "*.csv")))
    tables += sorted(glob.glob(os.path.join(folder, "continuation", "solver_macro.csv")))
    for path in tables:
        print(f"\n{os.path.relpath(path, folder)}")
        with open(path) as f:
            for row in csv.reader(f):
                print("  " + "  ".join(f"{c:>14}" for c in row))
    if not rows and not glob.glob(os.path.join(folder, "*.csv")):
        print(f"no benchmark results under {folder}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "results/bench"))
