# Sourced by the ledger scripts.

# fail MESSAGE: the script's one-line error, exit status 2.
fail() {
  echo "${0##*/}: error: $*" >&2
  exit 2
}

# commit_ledger ROOT FILE MESSAGE: git commit
# FILE alone (git commit --only: whatever else is staged stays staged),
# retrying while another git command holds the index lock.
commit_ledger() {
  local root=$1 file=$2 message=$3 attempt
  for attempt in 1 2 3 4 5; do
    if git -C "$root" add "$file" && git -C "$root" commit -q --only "$file" -m "$message"; then
      return 0
    fi
    sleep 5
  done
  echo "commit_ledger: could not commit $file" >&2
  return 1
}
