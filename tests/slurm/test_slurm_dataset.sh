#!/usr/bin/env bash
# The data set as a Slurm job array on a single-host Slurm started for the
# test (tests/slurm/local_slurm.sh): scripts/slurm/submit.sh submits every
# knot up to 6 crossings in 4 shards and a merge job that depends on the
# array; the merged file must equal one `knots dataset` run with the same
# seeds and options (positions bit for bit, the same runs, similarities,
# linkage and clusters: tests/slurm/dataset_check.py). Then the faults: a
# shard cancelled midway (scancel) cancels the merge job, leaves journals
# that `knots merge` refuses as unfinished (one line, exit 2), and once
# resubmitted repeats none of its journaled runs and the merge again equals
# the reference; `knots merge` also refuses a missing shard and two shards
# holding the same knot. Every daemon and job is stopped on exit, also on
# failure.
#
# Usage: test_slurm_dataset.sh KNOTS_BINARY SOURCE_DIR
# Exit 0 passed, 1 failed, 77 skipped (Slurm not installed, or not root).
set -uo pipefail

knots=${1:?usage: test_slurm_dataset.sh KNOTS_BINARY SOURCE_DIR}
src=${2:?usage: test_slurm_dataset.sh KNOTS_BINARY SOURCE_DIR}
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
check="$here/dataset_check.py"
# Debian's python3 (with h5py and numpy), not one first on PATH
python=${EK_PYTHON:-/usr/bin/python3}
# shellcheck source=local_slurm.sh
source "$here/local_slurm.sh"

missing=$(slurm_missing)
if [[ -n "$missing" ]]; then
  echo "SKIPPED: Slurm is not installed (missing: $missing). scripts/install-deps.sh installs the" \
    "Debian packages slurmctld slurmd slurm-client munge when run as root (make does it)."
  exit 77
fi
if [[ $(id -u) -ne 0 ]]; then
  echo "SKIPPED: the single-host Slurm of this test runs slurmd, which needs root."
  exit 77
fi

t0=$SECONDS
root=$(mktemp -d "${TMPDIR:-/tmp}/ek-slurm.XXXXXX")
chmod 755 "$root"  # munged needs every folder above its socket searchable
ok=0
cleanup() {
  slurm_stop
  if [[ $ok -eq 1 ]]; then
    rm -rf "$root"
  else
    echo "kept for inspection: $root (daemon logs in $root/cluster/log, job logs in $root/*/logs)"
  fi
}
trap cleanup EXIT
trap 'exit 130' INT TERM HUP

fail() {
  echo "FAILED: $*"
  local f
  for f in "$root"/*/logs/*.out; do
    [[ -f "$f" ]] && { echo "== $f"; tail -n 5 "$f"; }
  done
  for f in "$root"/cluster/log/slurm*.log; do  # without the harmless start-up noise
    [[ -f "$f" ]] && { echo "== $f"; grep -i error "$f" | grep -vE 'pmix|PMIx|MPI|state file' | tail -n 10; }
  done
  exit 1
}
step() { echo "[$((SECONDS - t0)) s] $*"; }

# every knot up to 6 crossings, few samples and short curves: about 0.1-0.3 s
# of CPU per relaxation, so that shard 3 (5_1 and 6_3, 12 runs) still has
# about 2 s of work left when its first run is journaled and it is cancelled
range=(--max-crossings 6)
opts=(--samples 6 -n 200 --no-stiffness --seed 7)
shards=4
victim=3  # the shard cancelled midway
submit=("$src/scripts/slurm/submit.sh" "${range[@]}" --shards "$shards" --knots "$knots")

job_id() { sed -n "s/^$1=//p" <<< "$2"; }
# "knots merge ARGS" must fail with exit 2, one line on stderr containing NEEDLE, and no output file
expect_refused() {
  local needle=$1 out=$2 err status
  shift 2
  err=$("$knots" merge "$@" -o "$out" 2>&1 > /dev/null)
  status=$?
  [[ $status -eq 2 ]] || fail "knots merge $* exited $status (expected 2): $err"
  [[ $(wc -l <<< "$err") -eq 1 ]] || fail "knots merge $*: expected one line, got: $err"
  [[ "$err" == *"$needle"* ]] || fail "knots merge $*: expected '$needle' in: $err"
  [[ ! -e "$out" ]] || fail "knots merge $* wrote '$out' although it refused"
  echo "  refused: $err"
}
# true when a journal in the work folder $1 holds a run: longer than its
# header (~300 bytes) and one record, which holds a curve (n x 24 = 4,800
# bytes); the exact count is taken once the shard is cancelled
journaled() {
  local f
  for f in "$1"/*.journal; do
    [[ -f "$f" && $(stat -c %s "$f" 2> /dev/null || echo 0) -gt 5000 ]] && return 0
  done
  return 1
}
all_completed() {  # STATES EXPECTED_COUNT
  [[ $(grep -c '^COMPLETED$' <<< "$1") -eq $2 && $(wc -l <<< "$1") -eq $2 ]]
}

step "starting munged, slurmctld, slurmd in $root/cluster"
slurm_start "$root/cluster" || fail "the single-host Slurm did not start"
sinfo -N -o '  node %N: %t, %c CPUs, partition %P'

step "reference: knots dataset ${range[*]} ${opts[*]} --jobs 2"
"$knots" dataset "${range[@]}" "${opts[@]}" --jobs 2 --quiet -o "$root/reference.h5" ||
  fail "the reference run failed"

# ---- the array and the merge job ---------------------------------------------
step "submit.sh ${range[*]} --shards $shards --out $root/a -- ${opts[*]}"
ids=$("${submit[@]}" --out "$root/a" -- "${opts[@]}") || fail "submit.sh failed: $ids"
array=$(job_id array_job "$ids") merge=$(job_id merge_job "$ids")
[[ -n "$array" && -n "$merge" ]] || fail "submit.sh printed no job ids: $ids"
scontrol -o show job "$merge" | grep -q "Dependency=afterok:${array}" ||
  fail "the merge job does not depend on the array: $(scontrol -o show job "$merge")"
states=$(slurm_wait_job "$array" 900) || fail "the array did not end"
all_completed "$states" "$shards" || fail "array tasks ended as: $(echo $states)"
state=$(slurm_wait_job "$merge" 300) || fail "the merge job did not end"
[[ "$state" == COMPLETED ]] || fail "the merge job ended as $state"
step "array job $array: $shards tasks COMPLETED; merge job $merge COMPLETED"
for ((i = 1; i <= shards; ++i)); do
  [[ ! -e "$root/a/shard-$i.h5.work" ]] || fail "shard $i left its work folder"
done
"$python" "$check" compare "$root/reference.h5" "$root/a/dataset.h5" --knots "$knots" ||
  fail "the merged data set differs from the reference"

# ---- faults: a shard cancelled midway, resubmitted -----------------------------
step "submit.sh again into $root/b, cancel shard $victim after its first journaled run"
ids=$("${submit[@]}" --out "$root/b" -- "${opts[@]}") || fail "submit.sh failed: $ids"
array=$(job_id array_job "$ids") merge=$(job_id merge_job "$ids")
work="$root/b/shard-$victim.h5.work"
cancelled=0
for ((k = 0; k < 6000; ++k)); do
  if journaled "$work"; then
    scancel "${array}_$victim" && cancelled=1
    break
  fi
  sleep 0.05
done
[[ $cancelled -eq 1 ]] || fail "shard $victim journaled no run within 300 s"
state=$(slurm_wait_job "${array}_$victim" 60) || fail "the cancelled task did not end"
[[ "$state" == CANCELLED ]] || fail "task $victim of array job $array ended as $state, not CANCELLED"
[[ ! -e "$root/b/shard-$victim.h5" ]] || fail "shard $victim finished before it was cancelled: no fault was tested"
counts=$("$python" "$check" saved-runs "$work") || fail "cannot read the journals in $work"
saved=${counts% *} in_journals=${counts#* }
[[ $in_journals -ge 1 ]] || fail "no journal record survived the cancellation"
states=$(slurm_wait_job "$array" 900) || fail "the other tasks did not end"
state=$(slurm_wait_job "$merge" 120) || fail "the merge job was not cancelled (--kill-on-invalid-dep)"
[[ "$state" == CANCELLED ]] || fail "the merge job after a cancelled shard ended as $state"
[[ ! -e "$root/b/dataset.h5" ]] || fail "a merged data set was written although shard $victim was cancelled"
step "task $victim of array job $array CANCELLED with $saved runs saved ($in_journals in journals);" \
  "merge job $merge CANCELLED, nothing merged"

step "knots merge refuses unfinished, missing and overlapping shards"
expect_refused "'$root/b/shard-$victim.h5' is unfinished" "$root/bad.h5" "$root"/b/shard-{1,2,3,4}.h5
expect_refused "'$root/a/shard-9.h5' does not exist" "$root/bad.h5" "$root"/a/shard-{1,9}.h5
expect_refused "is in both '$root/a/shard-1.h5' and '$root/b/shard-1.h5'" "$root/bad.h5" \
  "$root"/a/shard-{1,2,3,4}.h5 "$root/b/shard-1.h5"
expect_refused "is given twice" "$root/bad.h5" "$root"/a/shard-{1,2,1}.h5

step "resubmit shard $victim (submit.sh --only $victim)"
ids=$("${submit[@]}" --out "$root/b" --only "$victim" -- "${opts[@]}") || fail "submit.sh --only $victim failed: $ids"
array=$(job_id array_job "$ids") merge=$(job_id merge_job "$ids")
states=$(slurm_wait_job "$array" 900) || fail "the resubmitted shard did not end"
all_completed "$states" 1 || fail "the resubmitted shard ended as $states"
state=$(slurm_wait_job "$merge" 300) || fail "the merge job did not end"
[[ "$state" == COMPLETED ]] || fail "the merge job after the resubmission ended as $state"
total=$("$python" "$check" runs "$root/a/shard-$victim.h5") || fail "cannot count the runs of shard $victim"
log="$root/b/logs/shard-$victim-job$array.out"
rerun=$("$python" -c 'import json, sys
print([json.loads(l) for l in open(sys.argv[1]) if l.startswith("{")][-1]["runs"])' "$log") ||
  fail "no JSON summary in $log"
[[ $((rerun + saved)) -eq $total ]] ||
  fail "the resubmitted shard ran $rerun runs; with $saved journaled it should run $((total - saved)) of $total"
step "resubmitted shard $victim ran $rerun of its $total runs ($saved kept from before the cancellation)"
"$python" "$check" compare "$root/reference.h5" "$root/b/dataset.h5" --knots "$knots" ||
  fail "the merged data set after the resubmission differs from the reference"

ok=1
step "passed"
