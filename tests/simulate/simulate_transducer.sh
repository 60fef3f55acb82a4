#!/usr/bin/env bash
# simulate with a transducer key set writes the measured channels after the simulated ones;
# the same --seed gives the same record, another seed another noise; with the transducers
# ideal (the default) no measured channel is written.
set -euo pipefail
cli=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run() {
  "$cli" simulate --duration 0.2 --set transducer.velocity_noise_mm_per_s=1 --seed "$1" \
    -o "$2" 2>/dev/null
}
run 3 "$work/a.csv"
run 3 "$work/b.csv"
run 4 "$work/c.csv"
head -n 1 "$work/a.csv" | grep -q 'stuck\[-\],v_measured\[m/s\],P1_measured\[Pa\],P2_measured\[Pa\]$' ||
  { echo "no measured channels: $(head -n 1 "$work/a.csv")"; exit 1; }
cmp -s "$work/a.csv" "$work/b.csv" || { echo "the same seed gave another record"; exit 1; }
if cmp -s "$work/a.csv" "$work/c.csv"; then echo "another seed gave the same record"; exit 1; fi
"$cli" simulate --duration 0.05 -o "$work/ideal.csv" 2>/dev/null
if head -n 1 "$work/ideal.csv" | grep -q measured; then echo "measured channels while ideal"; exit 1; fi
echo "simulate wrote the measured channels, the same for the same seed"
