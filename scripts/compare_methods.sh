#!/usr/bin/env bash
# make compare-methods: the data sets of the default relaxation method and of
# another named method (METHOD: hybrid, the method before it, unless given)
# from the same lattice samples, their paper checks, and their comparison
# (experiments/compare_methods.cpp; docs/reproducing.md, "Comparing the
# relaxation methods").
#   scripts/compare_methods.sh BUILD SCALE RESULTS JOBS KNOT_TABLE [METHOD]
# Results: RESULTS/compare_methods/<method>/<experiment>/ (default and METHOD),
# RESULTS/compare_methods/default-seed2/{dataset,multistability}/ (the default
# method from other lattice samples: the comparison's noise floor) and
# RESULTS/compare_methods/comparison/ (comparison-METHOD/ for a METHOD other
# than hybrid). A method's experiments are rerun when
# one of their summaries is missing or older than a program.
set -euo pipefail
build=$1 scale=$2 results=$3 jobs=$4 method=${6:-hybrid}
table=$(realpath "$5")  # the checks run inside BUILD
exp=$(cd "$build" && pwd)/experiments
mkdir -p "$results/compare_methods"
root=$(cd "$results/compare_methods" && pwd)
experiments="dataset milnor planarity multistability puzzles"
checks='^Paper(Milnor|Planarity|Multistability|Puzzles)\.'

up_to_date() {  # every summary of the method exists and is newer than every program
  local m=$1 es=${2:-$experiments}
  for e in $es; do
    [ -f "$root/$m/$e/summary.json" ] || return 1
    for p in $experiments; do [ "$root/$m/$e/summary.json" -nt "$exp/exp_$p" ] || return 1; done
  done
}

for m in default "$method"; do
  if ! up_to_date "$m"; then
    for e in $experiments; do
      "$exp/exp_$e" --scale "$scale" --method "$m" --out "$root/$m/$e" --jobs "$jobs"
    done
  fi
  echo "== paper checks on the results of the $m method ($root/$m)"
  (cd "$build" && EK_PAPER_RESULTS="$root/$m" KNOT_TABLE="$table" \
     ctest --output-on-failure -L '^paper$' -R "$checks" -E '^paper_run_' -FS '.*')
done
if ! up_to_date default-seed2 "dataset multistability"; then
  for e in dataset multistability; do
    "$exp/exp_$e" --scale "$scale" --method default --seed 2 --out "$root/default-seed2/$e" --jobs "$jobs"
  done
fi
out=$root/comparison
[ "$method" = hybrid ] || out=$root/comparison-$method  # hybrid's folder keeps its earlier name
"$exp/exp_compare_methods" --scale "$scale" --against "$method" --out "$out"
