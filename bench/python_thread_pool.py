#!/usr/bin/env python3
"""Relaxations in a Python thread pool: relax() releases the GIL, so a pool
of 2 threads relaxes 2 curves in about the time of one on 2 cores.

Relaxes the same lattice samples (400 vertices, the data set's curves) one
after the other and in a ThreadPoolExecutor of --threads workers, --repeat
times, alternating the two ways, and reports for each way the wall time, the
process CPU time (all threads) and their ratio (how many cores were busy on
average). The speed-up is the sequential wall time over the pool's. On a
machine shared with other work the wall times include waiting for a core; the
CPU times do not, so both are reported, and so is the overlap of the pool's
relaxations: the time both ran at once over the mean time of one (1: fully
concurrent, 0: one after the other, as they would be if relax() held the
GIL), which does not depend on the load. Writes python_thread_pool.csv to
--out.

    PYTHONPATH=build/python python3 bench/python_thread_pool.py --out results/bench
"""
import argparse
import csv
import os
import time
from concurrent.futures import ThreadPoolExecutor

import elastic_knots as ek


def measure(run):
    """(wall seconds, process CPU seconds) of run()."""
    w0, c0 = time.perf_counter(), time.process_time()
    run()
    return time.perf_counter() - w0, time.process_time() - c0


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--knot", default="8_19")
    ap.add_argument("--vertices", type=int, default=400)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--out", default=None, help="folder for python_thread_pool.csv")
    a = ap.parse_args()

    curves = ek.sample(a.knot, count=a.threads, vertices=a.vertices, seed=11)
    ek.relax(curves[0])  # warm-up: the straight-rod eigenvalue cache, the FFTW and table loads
    sequential, pooled, overlaps = [], [], []

    def timed_relax(P):
        t0 = time.perf_counter()
        ek.relax(P)
        return t0, time.perf_counter()

    with ThreadPoolExecutor(max_workers=a.threads) as pool:
        for _ in range(a.repeat):
            sequential.append(measure(lambda: [ek.relax(P) for P in curves]))
            spans = []
            pooled.append(measure(lambda: spans.extend(pool.map(timed_relax, curves))))
            both = max(0.0, min(e for _, e in spans) - max(s for s, _ in spans))
            overlaps.append(both / (sum(e - s for s, e in spans) / len(spans)))

    def row(way, runs):
        wall = sum(w for w, _ in runs) / len(runs)
        cpu = sum(c for _, c in runs) / len(runs)
        return {"way": way, "relaxations": len(curves), "wall_s": round(wall, 4), "cpu_s": round(cpu, 4),
                "cpu_per_wall": round(cpu / wall, 3)}

    rows = [row("sequential", sequential), row(f"pool of {a.threads}", pooled)]
    rows[0]["overlap"] = 0.0
    rows[1]["overlap"] = round(sum(overlaps) / len(overlaps), 3)
    speedup = rows[0]["wall_s"] / rows[1]["wall_s"]
    for r in rows:
        r["speedup"] = round(rows[0]["wall_s"] / r["wall_s"], 3)
    load = os.getloadavg()
    print(f"{a.threads} relaxations of {a.knot} lattice samples (n = {a.vertices}), mean of {a.repeat}; "
          f"{os.cpu_count()} cores, load average {load[0]:.1f} at the start")
    for r in rows:
        print(f"  {r['way']:12} wall {r['wall_s']:8.3f} s  cpu {r['cpu_s']:8.3f} s  "
              f"cpu/wall {r['cpu_per_wall']:5.2f}  speed-up {r['speedup']:5.2f}")
    print(f"speed-up of the pool: {speedup:.2f} (wall); CPU time pool/sequential "
          f"{rows[1]['cpu_s'] / rows[0]['cpu_s']:.2f}; overlap of the pool's relaxations "
          f"{rows[1]['overlap']:.2f} (min {min(overlaps):.2f})")
    if a.out:
        os.makedirs(a.out, exist_ok=True)
        with open(os.path.join(a.out, "python_thread_pool.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
            w.writeheader()
            w.writerows(rows)


if __name__ == "__main__":
    main()
