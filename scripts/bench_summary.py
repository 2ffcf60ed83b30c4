#!/usr/bin/env python3
"""Prints one summary table of every benchmark result under results/bench/.

Google Benchmark JSON files (bench_*.json, run with repetitions) contribute
their median aggregates; macro-benchmark CSV files (*.csv with a header) are
printed as they are. Targets come from the issues and are listed here so the
table shows the margin."""
import csv
import glob
import json
import os
import sys

# benchmark name prefix -> (target, unit) from the issues
TARGETS = {
    "BM_RodEnergyGradientHessian/TwistFree": (100e-6, "s"),
    "BM_ContactBroadPhaseBarrier": (50e-6, "s"),
    "BM_ContactCCDQuery": (100e-6, "s"),
    "BM_LatticeSample": (20e-3, "s"),
    "BM_SimilarityMatrix500": (2.0, "s"),
}

UNIT = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def fmt_seconds(s):
    if s < 1e-3:
        return f"{s * 1e6:9.2f} us"
    if s < 1.0:
        return f"{s * 1e3:9.2f} ms"
    return f"{s:9.3f} s "


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
    for path in sorted(glob.glob(os.path.join(folder, "*.csv"))):
        print(f"\n{os.path.basename(path)}")
        with open(path) as f:
            for row in csv.reader(f):
                print("  " + "  ".join(f"{c:>14}" for c in row))
    if not rows and not glob.glob(os.path.join(folder, "*.csv")):
        print(f"no benchmark results under {folder}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "results/bench"))
