#!/usr/bin/env bash
# Runs a paper-scale data set shard by shard and keeps each finished shard's
# ledger (docs/dataset-format.md, "Ledgers") under docs/results/SCALE/ledgers/,
# so that an interrupted run loses at most the shard in progress. Each shard
# is `knots dataset` with the experiments' parameters of SCALE (those of
# exp_dataset: adaptive sampling 50 + 10 up to 500, novelty distance 0.05, the
# default model, the eigen-projected method unless --method, seed 1) and --shard I/N; its data set goes to
# results/SCALE/shards/ (not committed), its ledger to
# docs/results/SCALE/ledgers/shard-II-of-NN.ledger.h5. A shard whose ledger
# exists is skipped; an interrupted shard resumes from its journals.
# The scale truth is the ground truth of the stopping rules: 30 knots of 5 to
# 12 crossings (BB and not, alternating and not) with the full budget of 500
# samples each (no adaptive stop), which exp_adaptive --fixed replays.
# docs/reproducing.md ("The ledgers") describes the workflow.
set -euo pipefail

usage() {
  cat <<'EOF'
usage: scripts/ledger_shards.sh SCALE [--shards N] [--only I,J,...] [--jobs J] [--knots PATH]
                                [--method M] [--commit] [--nice] [--datasets]

  SCALE          sample12 (the stratified 10% of the 11- and 12-crossing knots, every BB knot),
                 paper10 (every knot with 3 to 10 crossings) or truth (30 knots of 5 to 12
                 crossings, 500 samples each: the ground truth of the stopping rules)
  --shards N     shards of the scale (default: sample12 20, paper10 16, truth 4; about 15 minutes
                 each on 2 cores)
  --only LIST    these shards only (comma-separated, 1-based); default every shard without a ledger
  --jobs J       relaxations in parallel per shard (default 2)
  --knots PATH   the knots program (default build/bin/knots of this checkout)
  --method M     the relaxation method (default eigen-projected, the method of the committed
                 ledgers of these scales, so that a lost shard is run again as it was)
  --commit       git commit each finished shard's ledger (that file alone) as soon as it is written
  --nice         run the shards at the lowest CPU priority (nice 19)
  --datasets     also run a shard whose ledger exists when its data set is missing (the data
                 sets are not committed; a replay such as exp_adaptive --fixed needs them): its
                 ledger then goes next to its data set, the committed one is left as it is

Progress: one line per shard start and end in results/SCALE/shards/progress.log.
EOF
}

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=lib/commit_ledger.sh
source "$here/scripts/lib/commit_ledger.sh"
[[ $# -ge 1 ]] || { usage >&2; exit 2; }
[[ "$1" == "-h" || "$1" == "--help" ]] && { usage; exit 0; }
scale=$1
shift
shards="" only="" jobs=2 knots="$here/build/bin/knots" method=eigen-projected commit=0 nice_cmd=() datasets=0
while [[ $# -gt 0 ]]; do
  case "$1" in
    --shards) [[ $# -ge 2 ]] || fail "--shards needs a value"; shards=$2; shift 2 ;;
    --only) [[ $# -ge 2 ]] || fail "--only needs a value"; only=$2; shift 2 ;;
    --jobs) [[ $# -ge 2 ]] || fail "--jobs needs a value"; jobs=$2; shift 2 ;;
    --knots) [[ $# -ge 2 ]] || fail "--knots needs a value"; knots=$2; shift 2 ;;
    --method) [[ $# -ge 2 ]] || fail "--method needs a value"; method=$2; shift 2 ;;
    --commit) commit=1; shift ;;
    --nice) nice_cmd=(nice -n 19); shift ;;
    --datasets) datasets=1; shift ;;
    -h | --help) usage; exit 0 ;;
    *) fail "unknown option '$1' (see --help)" ;;
  esac
done
# The ground truth's knots: per crossing number, alternating and not, BB
# (bridge index = braid index) and not, where the table has them.
truth_knots=5_1,5_2,6_1,6_2,6_3,7_1,7_2,7_4,7_7,8_1,8_5,8_19,8_20,9_1,9_10,9_16,9_42,10_1,10_46,10_124,10_132
truth_knots+=,11a_1,11a_57,11n_1,11n_71,12a_1,12a_146,12n_1,12n_113,12n_200
sampling=(--adaptive)
case "$scale" in
  sample12) select=(--max-crossings 12 --min-crossings 11 --stratified 0.1); shards=${shards:-20} ;;
  paper10) select=(--max-crossings 10); shards=${shards:-16} ;;
  truth) select=(--names "$truth_knots"); sampling=(--samples 500); shards=${shards:-4} ;;
  *) fail "unknown scale '$scale' (sample12, paper10 or truth)" ;;
esac
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || fail "--shards must be a positive integer"
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || fail "--jobs must be a positive integer"
[[ -x "$knots" ]] || fail "no knots program at '$knots' (build it first: make build)"

ledgers="$here/docs/results/$scale/ledgers"
work="$here/results/$scale/shards"
mkdir -p "$ledgers" "$work"
log="$work/progress.log"

list=()
if [[ -n "$only" ]]; then
  IFS=, read -r -a list <<<"$only"
else
  for ((i = 1; i <= shards; i++)); do list+=("$i"); done
fi

for i in "${list[@]}"; do
  [[ "$i" =~ ^[1-9][0-9]*$ && "$i" -le "$shards" ]] || fail "shard '$i' is not in 1..$shards"
  name=$(printf 'shard-%02d-of-%02d' "$i" "$shards")
  ledger="$ledgers/$name.ledger.h5"
  keep=0  # 1: the committed ledger stays; this run's ledger goes next to its data set
  if [[ -f "$ledger" ]]; then
    if [[ $datasets -eq 0 || -f "$work/$name.h5" ]]; then
      echo "$(date -u +%FT%TZ) $scale $name: ledger exists, skipped" >>"$log"
      continue
    fi
    keep=1
    ledger="$work/$name.ledger.h5"
    rm -f "$ledger"
  fi
  echo "$(date -u +%FT%TZ) $scale $name: started" >>"$log"
  start=$(date +%s)
  "${nice_cmd[@]}" "$knots" dataset "${select[@]}" "${sampling[@]}" --novelty-distance 0.05 --method "$method" \
    --jobs "$jobs" --shard "$i/$shards" --quiet -o "$work/$name.h5" --ledger "$ledger"
  echo "$(date -u +%FT%TZ) $scale $name: finished in $(($(date +%s) - start)) s, ledger $(du -k "$ledger" | cut -f1) kB" >>"$log"
  if [[ $commit -eq 1 && $keep -eq 0 ]]; then
    commit_ledger "$here" "$ledger" "Ledger of $scale $name (knots dataset --shard $i/$shards)"
  fi
done
