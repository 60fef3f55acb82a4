#!/usr/bin/env bash
# kill -9 a small calibration at KILLS random moments, resuming each time: the final outputs
# must be byte-identical to an uninterrupted run's.
set -euo pipefail
cli=$1
spec=$2
kills=$3
source "$(dirname "$0")/calibrate_outputs_equal.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
start=$(date +%s%N)
"$cli" calibrate "$spec" --out "$work/full" --threads 2 >/dev/null
length_ms=$((($(date +%s%N) - start) / 1000000))
moments=()
for ((i = 0; i < kills; i++)); do
  # A moment within the uninterrupted run's length, measured from the (re)start.
  at_ms=$((RANDOM % (length_ms > 50 ? length_ms : 50)))
  moments+=("$at_ms")
  "$cli" calibrate "$spec" --out "$work/killed" --threads 2 --resume >/dev/null 2>&1 &
  pid=$!
  sleep "$(printf '%d.%03d' $((at_ms / 1000)) $((at_ms % 1000)))"
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
done
"$cli" calibrate "$spec" --out "$work/killed" --threads 2 --resume >/dev/null
if ! same_outputs "$work/full" "$work/killed"; then
  echo "kill moments (ms after each start): ${moments[*]}"; exit 1
fi
echo "identical after $kills kills at ${moments[*]} ms (uninterrupted: $length_ms ms)"
