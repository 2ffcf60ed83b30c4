#!/usr/bin/env bash
# Keeps a long stress volume (tests/stress/test_stress_long.cpp, `make
# stress`) across sessions: its per-run log results/stress/volume-N.csv.partial
# (not committed) is saved piece by piece under docs/results/stress/volume-N/
# (volume-N-M.csv and volume-N-M/ for a volume run by the named method M),
# each piece the rows finished since the last one, gzipped, so that an ended
# session loses at most the runs since the last piece. `restore` rebuilds the
# .partial log from the pieces; the volume then resumes from it (only the
# missing runs are run). docs/performance.md ("Numerical stress tests").
set -euo pipefail

usage() {
  cat <<'EOF'
usage: scripts/stress_pieces.sh save N [--method M] [--commit]
       scripts/stress_pieces.sh restore N [--method M]

  save N      write the rows of results/stress/volume-N.csv.partial (or of the finished
              volume-N.csv) not yet in a piece to docs/results/stress/volume-N/piece-KK.csv.gz
  --method M  the volume run by the named method M (EK_STRESS_METHOD=M): volume-N-M instead
              of volume-N (M = default: volume-N)
  --commit    git commit that piece (that file alone)
  restore N   write results/stress/volume-N.csv.partial from the pieces (refused when it exists)

Resume with: EK_STRESS_VOLUME=N [EK_STRESS_METHOD=M] EK_STRESS_LOG=results/stress/volume-N[-M].csv \
             build/tests/stress/test_stress_long
EOF
}

header="index,knot,seed,status,iterations,seconds,energy,gradient_norm,alexander_preserved"
[ $# -ge 2 ] || { usage >&2; exit 2; }
action=$1 volume=$2
shift 2
commit=0 method=default
while [ $# -gt 0 ]; do
  case "$1" in
    --commit) commit=1; shift ;;
    --method) [ $# -ge 2 ] || { echo "stress_pieces: --method needs a value" >&2; exit 2; }; method=$2; shift 2 ;;
    *) echo "stress_pieces: unknown option '$1'" >&2; usage >&2; exit 2 ;;
  esac
done
[[ "$volume" =~ ^[1-9][0-9]*$ ]] || { echo "stress_pieces: N must be a positive integer, not '$volume'" >&2; exit 2; }
[[ "$method" =~ ^[a-z][a-z0-9-]*$ ]] || { echo "stress_pieces: M must be a method name, not '$method'" >&2; exit 2; }
cd "${EK_STRESS_PIECES_ROOT:-$(dirname "$0")/..}"  # the checkout (tests: a scratch folder)
name=volume-$volume
[ "$method" = default ] || name=$name-$method
dir=docs/results/stress/$name
log=results/stress/$name.csv

# the rows (without header) of every piece so far
pieces_rows() { for p in "$dir"/piece-*.csv.gz; do if [ -e "$p" ]; then zcat "$p" | tail -n +2; fi; done; }
# how many pieces there are
pieces_count() { local k=0; for p in "$dir"/piece-*.csv.gz; do if [ -e "$p" ]; then k=$((k + 1)); fi; done; echo $k; }

case "$action" in
  save)
    src=$log.partial
    [ -f "$src" ] || src=$log
    [ -f "$src" ] || { echo "stress_pieces: no log $log(.partial)" >&2; exit 2; }
    [ "$(head -1 "$src")" = "$header" ] || { echo "stress_pieces: $src is not a stress log" >&2; exit 2; }
    mkdir -p "$dir"
    saved=$(mktemp)
    trap 'rm -f "$saved" "$dir"/.piece.tmp' EXIT
    pieces_rows | cut -d, -f1 | sort -n > "$saved"
    next=$(( $(pieces_count) + 1 ))
    piece=$(printf '%s/piece-%02d.csv.gz' "$dir" "$next")
    # complete rows only (the last line counts when it ends with a newline), not saved before
    cut_last=cat
    [ -z "$(tail -c 1 "$src")" ] || cut_last="sed \$d"
    { echo "$header"
      tail -n +2 "$src" | $cut_last | awk -F, -v saved="$saved" 'BEGIN { while ((getline k < saved) > 0) s[k] = 1 }
        NF == 9 && $9 ~ /^[01]$/ && !($1 in s)'; } | gzip -n > "$dir"/.piece.tmp
    rows=$(( $(zcat "$dir"/.piece.tmp | wc -l) - 1 ))
    if [ "$rows" -eq 0 ]; then echo "stress_pieces: no new rows"; exit 0; fi
    mv "$dir"/.piece.tmp "$piece"
    total=$(( $(wc -l < "$saved") + rows ))
    echo "stress_pieces: $piece: $rows runs ($total of $volume saved)"
    if [ "$commit" = 1 ]; then
      git add "$piece"
      label="Stress volume of $volume runs"
      [ "$method" = default ] || label="$label by $method"
      git commit -q -m "$label: $(basename "$piece") ($rows runs, $total saved)" -- "$piece"
    fi
    ;;
  restore)
    [ ! -e "$log.partial" ] || { echo "stress_pieces: $log.partial exists; it is left as it is" >&2; exit 2; }
    [ "$(pieces_count)" -gt 0 ] || { echo "stress_pieces: no pieces in $dir" >&2; exit 2; }
    mkdir -p results/stress
    { echo "$header"; pieces_rows; } > "$log.partial.tmp" && mv "$log.partial.tmp" "$log.partial"
    echo "stress_pieces: $log.partial: $(( $(wc -l < "$log.partial") - 1 )) runs"
    ;;
  *) usage >&2; exit 2 ;;
esac
