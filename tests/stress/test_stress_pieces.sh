#!/usr/bin/env bash
# scripts/stress_pieces.sh in a scratch checkout: each piece holds the
# complete rows not saved before (a row cut by an interruption waits for the
# next piece), `restore` rebuilds the log of every saved row, `--commit`
# commits the piece alone, and bad input is one message and exit status 2.
set -euo pipefail
script=$1
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
export EK_STRESS_PIECES_ROOT=$root
fail() { echo "FAIL: $*" >&2; exit 1; }
h="index,knot,seed,status,iterations,seconds,energy,gradient_norm,alexander_preserved"
row() { echo "$1,3_1,$(($1 + 1)),converged-stable,10,0.1,1.0,1e-9,1"; }
mkdir -p "$root/results/stress"
log=$root/results/stress/volume-9.csv.partial
dir=$root/docs/results/stress/volume-9
{ echo "$h"; row 1; row 0; printf '2,3_1,3,conv'; } > "$log"          # the last row cut
"$script" save 9 > /dev/null
[ "$(zcat "$dir/piece-01.csv.gz")" = "$(printf '%s\n%s\n%s' "$h" "$(row 1)" "$(row 0)")" ] || fail "piece 1"
{ echo "$h"; row 1; row 0; row 2; row 3; } > "$log"                    # the run resumed and went on
"$script" save 9 > /dev/null
[ "$(zcat "$dir/piece-02.csv.gz")" = "$(printf '%s\n%s\n%s' "$h" "$(row 2)" "$(row 3)")" ] || fail "piece 2"
[ "$("$script" save 9)" = "stress_pieces: no new rows" ] || fail "an empty piece was written"
[ ! -e "$dir/piece-03.csv.gz" ] || fail "piece 3 exists"
"$script" restore 9 > /dev/null 2>&1 && fail "restore over an existing log"
mv "$log" "$root/old"
"$script" restore 9 > /dev/null
[ "$(sort "$log")" = "$(sort "$root/old")" ] || fail "restore"
# a volume run by a named method has its own log and pieces
cp "$log" "$root/results/stress/volume-9-one-level.csv.partial"
"$script" save 9 --method one-level > /dev/null
[ "$(zcat "$root/docs/results/stress/volume-9-one-level/piece-01.csv.gz" | wc -l)" = 5 ] || fail "method piece"
[ ! -e "$dir/piece-03.csv.gz" ] || fail "the method's rows went into the default volume"
[ "$("$script" save 9 --method default)" = "stress_pieces: no new rows" ] || fail "--method default"
for bad in "save 0" "save x9" "restore 8" "frobnicate 9" "save 9 --method" "save 9 --method A/B" "save 9 --now"; do
  set +e; "$script" $bad > /dev/null 2> "$root/err"; status=$?; set -e
  [ "$status" = 2 ] && [ -s "$root/err" ] || fail "'$bad': status $status"
done
git -C "$root" init -q && git -C "$root" -c user.name=t -c user.email=t@t commit -q --allow-empty -m start
echo "$(row 4)" >> "$log"
touch "$root/other" && git -C "$root" add other
export GIT_AUTHOR_NAME=t GIT_AUTHOR_EMAIL=t@t GIT_COMMITTER_NAME=t GIT_COMMITTER_EMAIL=t@t
"$script" save 9 --commit > /dev/null
committed=$(git -C "$root" show --name-only --format= HEAD)
[ "$committed" = "docs/results/stress/volume-9/piece-03.csv.gz" ] || fail "commit: $committed"
echo "stress_pieces: pieces, restore, bad input and commit as documented"
