#!/usr/bin/env bash
# command_progress.sh CLI VARIANT: the long commands show their progress on a terminal (a
# pseudo-terminal from script(1)) once they have run 2 s: `simulate` and `lyapunov` on the
# frozen-volume rig (VARIANT, no stroke end) over 4,000 s and 2,000 s of model time (about 5
# and 9 s of work); `friction` and `fit` on a 120 s record of the compliant-mount rig (the
# compliant_mount.toml beside VARIANT; on the one-body default
# `friction` ends within the 2 s) with a 20 m stroke (about 3 s and minutes of work); each
# stopped once its line appears; none with --quiet, nor when standard error is not a terminal.
set -uo pipefail
cli=$(realpath "$1")
variant=$(realpath "$2")
mount_rig="$(dirname "$variant")/compliant_mount.toml"
command -v script >/dev/null || { echo "no script(1): skipped"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "$*"; exit 1; }
line() { grep -qE "$1: [^(]+ \([0-9]+ s\)" "$2"; }

check() {  # check NAME ARGS...: a progress line on a terminal, none with --quiet or a pipe
  local name=$1; shift
  local typed
  typed=$(printf " %q" "$cli" "$name" "$@")
  script -qfec "$typed" /dev/null >"$work/tty" 2>&1 &
  local pid=$!
  for _ in $(seq 1 300); do line "$name" "$work/tty" && break; sleep 0.1; done
  kill "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
  line "$name" "$work/tty" || { cat -v "$work/tty" | head -c 400; fail "$name: no progress on a terminal"; }
  # Both at once: 4 s each, twice the 2 s after which a line would show.
  timeout 4 script -qfec "$typed --quiet" /dev/null >"$work/quiet" 2>&1 &
  timeout 4 "$cli" "$name" "$@" >/dev/null 2>"$work/err" &
  wait
  line "$name" "$work/quiet" && fail "$name: progress despite --quiet"
  line "$name" "$work/err" && fail "$name: progress on a pipe"
  echo "$name: progress as expected"
}
check simulate "$variant" --duration 4000 --rate 10 -o "$work/run.csv"
check lyapunov "$variant" --measure 2000
long_stroke=("$mount_rig" --set cylinder.stroke_mm=20000)
"$cli" simulate "${long_stroke[@]}" --duration 120 --quiet -o "$work/record.csv" 2>"$work/simulate.err" \
  || fail "could not simulate the 120 s record"
check friction "$work/record.csv" "${long_stroke[@]}"
check fit "$work/record.csv" "${long_stroke[@]}"
