#!/usr/bin/env bash
# Samples the named knots of a paper-scale data set at its full budget (500
# lattice samples each, no adaptive stop), a few knots per piece, and keeps
# each finished piece's ledger under docs/results/SCALE/full_budget/, so that
# an interrupted run loses at most the piece in progress. A piece is
# `knots dataset --names ... --samples 500` with the scale's other
# parameters (seed 1: each knot's walk is the one of its adaptive run, so its
# first samples are the same ones). exp_milnor reads these ledgers beside the
# scale's own: which knots need them is its summary's far_end_to_sample
# (docs/reproducing.md, "The far end at the full budget"); with
# --until-decided this script asks it, samples those knots and asks again,
# until the list is empty (`make ledger-far-end SCALE=...`).
set -euo pipefail

usage() {
  cat <<'EOF2'
usage: scripts/ledger_far_end.sh SCALE (--names A,B,... | --until-decided) [--per-piece N] [--jobs J]
                                 [--knots PATH] [--method M] [--commit] [--nice]

  SCALE          sample12 or paper10
  --names LIST   the knots to sample at the full budget (comma-separated)
  --until-decided  the knots exp_milnor names (its summary's far_end_to_sample, from the committed
                 ledgers and full-budget ledgers of SCALE), round after round until it names none
  --per-piece N  knots per piece (default: sample12 6, paper10 12; about 15 minutes each on 2 cores)
  --jobs J       relaxations in parallel (default 2)
  --knots PATH   the knots program (default build/bin/knots of this checkout)
  --method M     the relaxation method (default eigen-projected, the method of the committed
                 ledgers of these scales)
  --commit       git commit each finished piece's ledger (that file alone) as soon as it is written
  --nice         run at the lowest CPU priority (nice 19)

Progress: one line per piece start and end in results/SCALE/full_budget/progress.log.
EOF2
}

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
# shellcheck source=lib/commit_ledger.sh
source "$here/scripts/lib/commit_ledger.sh"
[[ $# -ge 1 ]] || { usage >&2; exit 2; }
[[ "$1" == "-h" || "$1" == "--help" ]] && { usage; exit 0; }
scale=$1
shift
names="" until=0 per_piece="" jobs=2 knots="$here/build/bin/knots" method=eigen-projected commit=0 nice_cmd=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --names) [[ $# -ge 2 ]] || fail "--names needs a value"; names=$2; shift 2 ;;
    --until-decided) until=1; shift ;;
    --per-piece) [[ $# -ge 2 ]] || fail "--per-piece needs a value"; per_piece=$2; shift 2 ;;
    --jobs) [[ $# -ge 2 ]] || fail "--jobs needs a value"; jobs=$2; shift 2 ;;
    --knots) [[ $# -ge 2 ]] || fail "--knots needs a value"; knots=$2; shift 2 ;;
    --method) [[ $# -ge 2 ]] || fail "--method needs a value"; method=$2; shift 2 ;;
    --commit) commit=1; shift ;;
    --nice) nice_cmd=(nice -n 19); shift ;;
    -h | --help) usage; exit 0 ;;
    *) fail "unknown option '$1' (see --help)" ;;
  esac
done
case "$scale" in
  sample12) per_piece=${per_piece:-6} ;;
  paper10) per_piece=${per_piece:-12} ;;
  *) fail "unknown scale '$scale' (sample12 or paper10)" ;;
esac
[[ -n "$names" || $until -eq 1 ]] || fail "--names or --until-decided is needed"
[[ -z "$names" || $until -eq 0 ]] || fail "--names and --until-decided exclude each other"
[[ "$per_piece" =~ ^[1-9][0-9]*$ ]] || fail "--per-piece must be a positive integer"
[[ "$jobs" =~ ^[1-9][0-9]*$ ]] || fail "--jobs must be a positive integer"
[[ -x "$knots" ]] || fail "no knots program at '$knots' (build it first: make build)"

ledgers="$here/docs/results/$scale/full_budget"
work="$here/results/$scale/full_budget"
mkdir -p "$ledgers" "$work"
log="$work/progress.log"

# run_pieces LIST: the knots of LIST at the full budget, per_piece knots per piece
run_pieces() {
  local all first piece n name start
  IFS=, read -r -a all <<<"$1"
  for ((first = 0; first < ${#all[@]}; first += per_piece)); do
    piece=$(IFS=,; echo "${all[*]:first:per_piece}")
    # the next number without a ledger: an interrupted piece (same knots) resumes from its journals
    n=1
    while [[ -f "$ledgers/$(printf 'piece-%02d' "$n").ledger.h5" ]]; do n=$((n + 1)); done
    name=$(printf 'piece-%02d' "$n")
    echo "$(date -u +%FT%TZ) $scale $name ($piece): started" >>"$log"
    start=$(date +%s)
    "${nice_cmd[@]}" "$knots" dataset --names "$piece" --samples 500 --novelty-distance 0.05 --method "$method" \
      --jobs "$jobs" --quiet -o "$work/$name.h5" --ledger "$ledgers/$name.ledger.h5"
    echo "$(date -u +%FT%TZ) $scale $name: finished in $(($(date +%s) - start)) s" >>"$log"
    if [[ $commit -eq 1 ]]; then
      commit_ledger "$here" "$ledgers/$name.ledger.h5" \
        "Full-budget ledger of $scale $name (knots dataset --names $piece --samples 500)"
    fi
  done
}

if [[ $until -eq 0 ]]; then
  run_pieces "$names"
  exit 0
fi
milnor="$(dirname "$knots")/../experiments/exp_milnor"
[[ -x "$milnor" ]] || fail "no exp_milnor at '$milnor' (build it first: make build)"
for round in 1 2 3 4 5 6 7 8 9 10; do
  "$milnor" --scale "$scale" --out "$here/docs/results/$scale/milnor" >/dev/null
  names=$(python3 -c 'import json, sys; print(",".join(json.load(open(sys.argv[1]))["far_end_to_sample"]))' \
    "$here/docs/results/$scale/milnor/summary.json")
  if [[ -z "$names" ]]; then
    echo "$(date -u +%FT%TZ) $scale: the far end is decided after round $((round - 1))" >>"$log"
    exit 0
  fi
  echo "$(date -u +%FT%TZ) $scale round $round: $names" >>"$log"
  run_pieces "$names"
done
fail "the far end is still undecided after 10 rounds"
