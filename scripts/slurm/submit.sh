#!/usr/bin/env bash
# Submits a data set to Slurm: a job array with one task per shard
# (scripts/slurm/shard.sbatch), then one merge job
# (scripts/slurm/merge.sbatch) that depends on it with
# --dependency=afterok:<array job>. Prints the two job ids. docs/cluster.md
# describes the workflow, resubmission and the faults it survives.
set -euo pipefail

usage() {
  cat <<'EOF'
usage: scripts/slurm/submit.sh (--max-crossings C | --names A,B,...) --shards N --out DIR
         [--only LIST] [--cpus-per-task J] [--time T] [--merged FILE] [--knots PATH]
         [--sbatch-arg ARG]... [--dry-run] [-- KNOTS-DATASET-OPTIONS...]

  --max-crossings C   every table knot with 3 .. C crossings
  --names A,B,...     these knot types
  --shards N          number of shards = array tasks (knot k goes to shard k mod N + 1)
  --out DIR           output folder, shared by every node: DIR/shard-I.h5, DIR/logs/
  --only LIST         submit only these shards (Slurm array list, e.g. 3 or 2,5-7);
                      default 1-N. Use it to resubmit cancelled or failed shards:
                      they resume from their journals
  --cpus-per-task J   CPUs per shard task, passed to knots dataset --jobs (default 1)
  --time T            time limit per shard task (sbatch --time; default: the partition's)
  --merged FILE       merged data set (default DIR/dataset.h5)
  --knots PATH        the knots program (default: build/bin/knots of this checkout)
  --sbatch-arg ARG    extra sbatch argument for both jobs (repeatable), e.g. --partition=long
  --dry-run           print the two sbatch commands instead of running them
  -- OPTIONS...       passed to knots dataset: sampling and scale, e.g.
                      -- --adaptive -n 400 --seed 1 (not --jobs, --shard, -o)

Prints "array_job=ID" and "merge_job=ID" on stdout.
EOF
}

fail() {
  echo "submit.sh: error: $*" >&2
  exit 2
}

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
range=() shards="" out="" only="" cpus=1 time_limit="" merged="" dry=0
knots="$here/../../build/bin/knots"
extra=() dataset_opts=()
need() { [[ $# -ge 2 && -n "$2" ]] || fail "$1 needs a value"; }
while [[ $# -gt 0 ]]; do
  [[ "$1" == --?*=* ]] && set -- "${1%%=*}" "${1#*=}" "${@:2}"  # --name=value
  case "$1" in
    --max-crossings | --names) need "$@"; range+=("$1" "$2"); shift 2 ;;
    --shards) need "$@"; shards=$2; shift 2 ;;
    --out) need "$@"; out=$2; shift 2 ;;
    --only) need "$@"; only=$2; shift 2 ;;
    --cpus-per-task) need "$@"; cpus=$2; shift 2 ;;
    --time) need "$@"; time_limit=$2; shift 2 ;;
    --merged) need "$@"; merged=$2; shift 2 ;;
    --knots) need "$@"; knots=$2; shift 2 ;;
    --sbatch-arg) need "$@"; extra+=("$2"); shift 2 ;;
    --dry-run) dry=1; shift ;;
    -h | --help) usage; exit 0 ;;
    --) shift; dataset_opts=("$@"); break ;;
    *) fail "unknown option '$1' (see --help)" ;;
  esac
done

[[ ${#range[@]} -eq 2 ]] || fail "give exactly one of --max-crossings and --names"
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || fail "--shards needs a positive integer, got '$shards'"
[[ -n "$out" ]] || fail "missing --out DIR"
[[ "$cpus" =~ ^[1-9][0-9]*$ ]] || fail "--cpus-per-task needs a positive integer, got '$cpus'"
[[ -n "$only" ]] || only="1-$shards"
[[ "$only" =~ ^[0-9,-]+$ ]] || fail "--only needs a Slurm array list such as 3 or 2,5-7, got '$only'"
for opt in "${dataset_opts[@]}"; do
  case "$opt" in
    -j | --jobs | --jobs=* | --shard | --shard=* | -o | --output | --output=*)
      fail "'$opt' is set by the job array; give --cpus-per-task instead of --jobs" ;;
  esac
done
[[ -x "$knots" ]] || fail "the knots program '$knots' is missing or not executable (make build, or --knots PATH)"
knots=$(realpath "$knots")
out=$(realpath -m "$out")
[[ -n "$merged" ]] || merged="$out/dataset.h5"
merged=$(realpath -m "$merged")

time_args=()
[[ -z "$time_limit" ]] || time_args=(--time="$time_limit")
array_cmd=(sbatch --parsable --array="$only" --cpus-per-task="$cpus" "${time_args[@]}" "${extra[@]}"
  --output="$out/logs/shard-%a-job%A.out" "$here/shard.sbatch" "$knots" "$out" "$shards"
  "${range[@]}" "${dataset_opts[@]}")
merge_cmd=(sbatch --parsable --kill-on-invalid-dep=yes "${extra[@]}"
  --output="$out/logs/merge-job%j.out" "$here/merge.sbatch" "$knots" "$out" "$shards" "$merged")
if [[ $dry -eq 1 ]]; then
  printf '%q ' "${array_cmd[@]}"; echo
  printf '%q ' "${merge_cmd[@]:0:2}" "--dependency=afterok:ARRAY_JOB" "${merge_cmd[@]:2}"; echo
  exit 0
fi
mkdir -p "$out/logs" || fail "cannot create '$out/logs'"
command -v sbatch > /dev/null || fail "sbatch not found (Slurm client commands: Debian package slurm-client)"
array_job=$("${array_cmd[@]}") || fail "sbatch refused the shard array"
array_job=${array_job%%;*}
merge_job=$("${merge_cmd[@]:0:2}" --dependency=afterok:"$array_job" "${merge_cmd[@]:2}") || {
  echo "submit.sh: error: sbatch refused the merge job; the shards run as job $array_job" >&2
  exit 1
}
merge_job=${merge_job%%;*}
echo "array_job=$array_job"
echo "merge_job=$merge_job"
