#!/usr/bin/env bash
# analyze_progress.sh CLI: `analyze` on a 10^6-sample record shows its progress on a terminal
# (a pseudo-terminal from script(1)): a line on standard error naming the stage and the seconds
# so far; none when standard error is not a terminal, nor with --quiet. Each run is stopped
# after a few seconds (the whole analysis takes minutes): what is checked is its first output.
set -uo pipefail
cli=$(realpath "$1")
command -v script >/dev/null || { echo "no script(1): skipped"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "$*"; exit 1; }
awk 'BEGIN { srand(1); print "t[s],v[m/s]"
             for (i = 0; i < 1000000; i++) { t = i / 1000
               printf "%.3f,%.6f\n", t, 0.05 * sin(24.5 * t) + 0.01 * sin(7.1 * t) + 0.001 * (rand() - 0.5) } }' \
  >"$work/big.csv"
# On a terminal: wait for the progress line (at most 60 s), then stop the run.
script -qfec "'$cli' analyze '$work/big.csv'" /dev/null >"$work/tty" 2>&1 &
pid=$!
for _ in $(seq 1 600); do
  grep -qE 'analyze: [^(]+ \([0-9]+ s\)' "$work/tty" && break
  sleep 0.1
done
kill "$pid" 2>/dev/null; wait "$pid" 2>/dev/null
grep -qE 'analyze: [^(]+ \([0-9]+ s\)' "$work/tty" || { cat -v "$work/tty" | head -c 500; fail "no progress on a terminal"; }
# With --quiet on a terminal, and without a terminal: 8 s of work, no line.
# Both at once.
timeout 8 script -qfec "'$cli' analyze '$work/big.csv' --quiet" /dev/null >"$work/quiet" 2>&1 &
timeout 8 "$cli" analyze "$work/big.csv" >"$work/out" 2>"$work/err" &
wait
grep -q 'analyze: ' "$work/quiet" && fail "progress despite --quiet"
[ -s "$work/err" ] && { head -c 300 "$work/err"; fail "progress on a pipe"; }
echo "analyze progress as expected"
