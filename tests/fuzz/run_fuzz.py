#!/usr/bin/env python3
"""Runs the libFuzzer targets of an EK_FUZZ build (`make fuzz`, and the CTest
tests with label fuzz).

  run_fuzz.py --build BUILD --results DIR [--seconds S] [--targets a,b] [--jobs J]
  run_fuzz.py --build BUILD --results DIR --replay [--targets a,b]

Fuzzing: each target runs for S seconds from its seed corpus
(tests/fuzz/corpus/T, read only) and the inputs it found before
(BUILD/fuzz-corpus/T, where new inputs go), with its dictionary
(tests/fuzz/dict/T.dict). Replay: each input of the seed corpus runs once.
A crash (sanitizer report, uncaught exception, failed check, leak, timeout,
out-of-memory) leaves its input under DIR/T/ and makes the exit status 1.
A crash is what stops libFuzzer itself: the data-set reader reads a file
without checksum in a child process first, and what libFuzzer's handlers
write when such a child dies (a failure of the HDF5 library, contained and
refused by the reader) is removed.
Prints executions, coverage and crashes per target; the full output of each
target is in DIR/T/fuzz.log; with several targets, DIR/summary.json.
"""
import argparse
import concurrent.futures
import json
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ARTIFACT_PREFIXES = ("crash-", "leak-", "timeout-", "oom-")
# [s] libFuzzer's limit per input. A data-set input without checksum is read
# in a child process given 3 s (fuzz_dataset_*.cpp), and libFuzzer runs an
# input a second time when its mallocs and frees differ (to look for a leak):
# such an input may take two child limits plus the reads in this process, on
# a machine busy with other sanitizer builds (over 10 s was seen there). A
# hang outside the child still ends the run, after this time.
UNIT_TIMEOUT = 30
LOG_TAIL_LINES = 25  # lines of a failed target's log printed with its crash


def targets_in(build):
    folder = os.path.join(build, "tests", "fuzz")
    names = [f[len("fuzz_"):] for f in os.listdir(folder) if f.startswith("fuzz_") and f != "fuzz_make_seeds"]
    return sorted(n for n in names if os.access(os.path.join(folder, "fuzz_" + n), os.X_OK))


def new_files(folder, since, prefixes):
    return [os.path.join(folder, f) for f in sorted(os.listdir(folder))
            if f.startswith(prefixes) and os.path.getmtime(os.path.join(folder, f)) >= since]


def last_int(pattern, text):
    found = re.findall(pattern, text)
    return int(found[-1]) if found else None


def run_target(target, args):
    binary = os.path.join(args.build, "tests", "fuzz", "fuzz_" + target)
    seeds = os.path.join(HERE, "corpus", target)
    results = os.path.join(args.results, target)
    os.makedirs(results, exist_ok=True)
    options = ["-artifact_prefix=" + results + "/", "-timeout=%d" % UNIT_TIMEOUT, "-rss_limit_mb=2048",
               "-print_final_stats=1"]
    dictionary = os.path.join(HERE, "dict", target + ".dict")
    if os.path.exists(dictionary):
        options.append("-dict=" + dictionary)
    if args.replay:
        inputs = sorted(os.path.join(seeds, f) for f in os.listdir(seeds))
        command = [binary] + options + inputs
    else:
        work = os.path.join(args.build, "fuzz-corpus", target)
        os.makedirs(work, exist_ok=True)
        command = [binary] + options + ["-max_total_time=%d" % args.seconds, work, seeds]
    env = dict(os.environ, UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1")
    env["TMPDIR"] = results  # scratch files of the data-set target
    start = time.time()
    proc = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, env=env,
                          universal_newlines=True, errors="replace")
    seconds = time.time() - start
    with open(os.path.join(results, "replay.log" if args.replay else "fuzz.log"), "w") as log:
        log.write(" ".join(command) + "\n" + proc.stdout)
    text = proc.stdout
    reported = set(os.path.abspath(p) for p in re.findall(r"Test unit written to (\S+)", text))
    for path in new_files(results, start, ARTIFACT_PREFIXES) + new_files(results, 0, ("ek-fuzz-dataset-",)):
        if os.path.abspath(path) not in reported:
            os.remove(path)  # a contained child's, or a scratch file
    crashes = sorted(reported)
    if proc.returncode != 0 and not crashes:
        crashes = ["(exit status %d, see %s)" % (proc.returncode, log.name)]
    return {
        "target": target,
        "seconds": round(seconds, 1),
        "inputs": len(inputs) if args.replay else None,
        "executions": last_int(r"stat::number_of_executed_units:\s*(\d+)", text),
        "exec_per_second": last_int(r"stat::average_exec_per_sec:\s*(\d+)", text),
        "coverage": last_int(r"cov: (\d+)", text),
        "features": last_int(r"ft: (\d+)", text),
        "corpus": last_int(r"corp: (\d+)/", text),
        "peak_rss_mb": last_int(r"stat::peak_rss_mb:\s*(\d+)", text),
        "crashes": crashes,
        "status": proc.returncode,
        "log": log.name,
    }


def show(value):
    return "-" if value is None else "{:,}".format(value)


def print_log_tail(row):
    """The end of a failed target's log (the input it was running, the
    sanitizer's or libFuzzer's report), so that a CI log names it."""
    try:
        with open(row["log"], errors="replace") as f:
            lines = f.read().splitlines()
    except OSError:
        return
    print("--- last %d lines of %s" % (LOG_TAIL_LINES, row["log"]))
    for line in lines[-LOG_TAIL_LINES:]:
        print("  " + line)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", required=True, help="the EK_FUZZ build folder")
    parser.add_argument("--results", required=True, help="crash inputs and logs go to RESULTS/TARGET/")
    parser.add_argument("--seconds", type=int, default=300, help="seconds per target")
    parser.add_argument("--targets", default="", help="comma-separated targets (default: all built)")
    parser.add_argument("--jobs", type=int, default=1, help="targets run at the same time")
    parser.add_argument("--replay", action="store_true", help="run each seed input once, no fuzzing")
    args = parser.parse_args()
    targets = args.targets.split(",") if args.targets else targets_in(args.build)
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
        rows = list(pool.map(lambda t: run_target(t, args), targets))

    mode = "replay of the seed corpus" if args.replay else "%d s per target" % args.seconds
    print("fuzz (%s):" % mode)
    print("%-12s %8s %14s %10s %9s %9s %8s %8s" %
          ("target", "seconds", "executions", "exec/s", "coverage", "features", "corpus", "crashes"))
    for r in rows:
        print("%-12s %8.1f %14s %10s %9s %9s %8s %8d" %
              (r["target"], r["seconds"], show(r["executions"]), show(r["exec_per_second"]), show(r["coverage"]),
               show(r["features"]), show(r["corpus"] if not args.replay else r["inputs"]), len(r["crashes"])))
    total = sum(r["executions"] or 0 for r in rows)
    print("total executions: {:,}".format(total))
    crashed = [r for r in rows if r["crashes"]]
    for r in crashed:
        for c in r["crashes"]:
            print("CRASH %s: %s" % (r["target"], c))
        print_log_tail(r)
    if len(rows) > 1:
        os.makedirs(args.results, exist_ok=True)
        with open(os.path.join(args.results, "summary.json"), "w") as f:
            json.dump({"mode": mode, "total_executions": total, "targets": rows}, f, indent=1)
    return 1 if crashed else 0


if __name__ == "__main__":
    sys.exit(main())
