#!/usr/bin/env python3
"""Checks for the Slurm data-set test (tests/slurm/test_slurm_dataset.sh).

  dataset_check.py compare REF.h5 OTHER.h5 --knots BIN
      exit 0 when OTHER holds what REF holds: the same parameters, knots in
      the same order, positions of every equilibrium bit for bit, the same
      attributes, runs (all but their measured seconds), similarity and
      linkage, and the same clusters from `knots cluster` at three cuts;
      otherwise one line per difference and exit 1.
  dataset_check.py saved-runs WORKDIR
      prints the runs a resumed `knots dataset` need not repeat, and of them
      those in journals: the valid records of every journal in WORKDIR (a
      torn last record does not count, as in src/dataset/src/journal.cpp)
      plus the runs of every finished part WORKDIR/<knot>.h5; two numbers.
  dataset_check.py runs FILE.h5 [KNOT ...]
      prints the number of runs stored for the knots (default: all).
"""
import argparse
import glob
import json
import os
import struct
import subprocess
import sys
import zlib

import h5py
import numpy as np

JOURNAL_MAGICS = (0x324E5552, 0x314E5552)  # "RUN2", and "RUN1" of the first record layout
# file attributes that legitimately differ between two runs
VOLATILE_ATTRS = {"created"}
RUN_COLUMNS_DETERMINISTIC = ["sample", "seed", "status", "equilibrium", "iterations", "energy",
                             "gradient_norm", "contacts", "topology_preserved", "message"]
CUTS = ["0.05", "0.2", "0.5"]


def journal_records(path):
    """Valid records of one journal: header line, options line, then
    (u32 magic, u32 length, payload, u32 CRC-32) records."""
    with open(path, "rb") as f:
        data = f.read()
    pos = 0
    for _ in range(2):  # "elastic-knots-journal 1\n" and the options text
        nl = data.find(b"\n", pos)
        if nl < 0:
            return 0
        pos = nl + 1
    count = 0
    while pos + 8 <= len(data):
        magic, length = struct.unpack_from("<II", data, pos)
        if magic not in JOURNAL_MAGICS or pos + 12 + length > len(data):
            break
        (crc,) = struct.unpack_from("<I", data, pos + 8 + length)
        if zlib.crc32(data[pos + 8:pos + 8 + length]) != crc:
            break
        count += 1
        pos += 12 + length
    return count


def stored_runs(path, knots=None):
    with h5py.File(path, "r") as f:
        names = [n.decode() if isinstance(n, bytes) else n for n in f["knot_names"][()]]
        return sum(len(f["knots"][n]["runs"]["sample"]) for n in names if not knots or n in knots)


def as_text(v):
    if isinstance(v, bytes):
        return v.decode()
    if isinstance(v, np.ndarray):
        return [as_text(x) for x in v.tolist()]
    return v


def compare_arrays(what, a, b, problems):
    a, b = np.asarray(a), np.asarray(b)
    if a.shape != b.shape:
        problems.append(f"{what}: shape {a.shape} vs {b.shape}")
    elif a.dtype.kind == "f":
        # bit for bit (NaN where NaN)
        if a.tobytes() != b.tobytes():
            problems.append(f"{what}: values differ (max |difference| "
                            f"{np.nanmax(np.abs(a - b)) if a.size else 0})")
    elif as_text(a) != as_text(b):
        problems.append(f"{what}: values differ")


def clusters(knots_bin, path, name, cut):
    out = subprocess.run([knots_bin, "cluster", path, name, "--cut", cut, "--json"],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)["clusters"]


def compare(ref, other, knots_bin):
    problems = []
    with h5py.File(ref, "r") as a, h5py.File(other, "r") as b:
        for key in sorted(set(a.attrs) | set(b.attrs)):
            if key in VOLATILE_ATTRS:
                continue
            va, vb = as_text(a.attrs.get(key)), as_text(b.attrs.get(key))
            if not np.array_equal(np.asarray(va), np.asarray(vb)):
                problems.append(f"file attribute {key}: {va} vs {vb}")
        names_a, names_b = as_text(a["knot_names"][()]), as_text(b["knot_names"][()])
        if names_a != names_b:
            problems.append(f"knot_names: {names_a} vs {names_b}")
        if not names_a:
            problems.append("the reference holds no knot")
        for name in (n for n in names_a if n in names_b):
            ka, kb = a["knots"][name], b["knots"][name]
            for key in sorted(set(ka.attrs) | set(kb.attrs)):
                if not np.array_equal(np.asarray(as_text(ka.attrs.get(key))), np.asarray(as_text(kb.attrs.get(key)))):
                    problems.append(f"{name}: attribute {key} differs")
            if ka["equilibria"].shape[0] == 0:
                problems.append(f"{name}: the reference holds no equilibrium")
            for ds in ["equilibria", "attributes", "attribute_names", "similarity", "linkage", "score_history"]:
                compare_arrays(f"{name}/{ds}", ka[ds][()], kb[ds][()], problems)
            for col in RUN_COLUMNS_DETERMINISTIC:
                compare_arrays(f"{name}/runs/{col}", ka["runs"][col][()], kb["runs"][col][()], problems)
            for cut in CUTS:
                if clusters(knots_bin, ref, name, cut) != clusters(knots_bin, other, name, cut):
                    problems.append(f"{name}: clusters at cut {cut} differ")
    for p in problems:
        print(f"{other} vs {ref}: {p}")
    if not problems:
        print(f"{other} equals {ref}: {len(names_a)} knots, {stored_runs(ref)} runs, "
              f"equilibria bit for bit, same clusters")
    return 0 if not problems else 1


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("compare")
    c.add_argument("ref")
    c.add_argument("other")
    c.add_argument("--knots", required=True)
    s = sub.add_parser("saved-runs")
    s.add_argument("workdir")
    r = sub.add_parser("runs")
    r.add_argument("file")
    r.add_argument("knot", nargs="*")
    args = p.parse_args()
    if args.cmd == "compare":
        return compare(args.ref, args.other, args.knots)
    if args.cmd == "saved-runs":
        journals = sum(journal_records(j) for j in glob.glob(os.path.join(args.workdir, "*.journal")))
        parts = sum(stored_runs(h) for h in glob.glob(os.path.join(args.workdir, "*.h5")))
        print(journals + parts, journals)
        return 0
    print(stored_runs(args.file, set(args.knot)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
