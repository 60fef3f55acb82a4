#!/usr/bin/env bash
# sweep --replay P:R runs one run of a sweep again: its runs.csv line must come back bit for
# bit, and its record must hold the velocity the analysis judged (v_measured) and the
# pressures as their transducers record them (P1_measured, P2_measured).
set -euo pipefail
cli=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(sweep --grid circuit.S2_mm2=0.05:0.35:0.15 --repeats 2 --set run.duration_s=2
      --set variation.friction_rel_sd=0.05 --set transducer.velocity_noise_mm_per_s=0.5 --threads 2)
"$cli" "${args[@]}" --out "$work/map" >/dev/null
"$cli" "${args[@]}" --replay 1:1 -o "$work/run.csv" 2>"$work/line"
# runs.csv: one coordinate column (the grid has one axis) before the record.
expected=$(awk -F, 'NR > 1 && $2 == 1 && $3 == 1' "$work/map/runs.csv" | cut -d, -f2-)
# The replay names each field, one per line: joined they are the runs.csv line.
grep -q '^sweep: run 1:1 replayed; as runs.csv records it:$' "$work/line" || { cat "$work/line"; exit 1; }
got=$(grep '^  ' "$work/line" | sed -E 's/^  [^ ]+ *//' | paste -sd, -)
[ "$expected" = "$got" ] || { printf 'runs.csv: %s\nreplay:   %s\n' "$expected" "$got"; exit 1; }
head -n 1 "$work/run.csv" | grep -q "v_measured\[m/s\],P1_measured\[Pa\],P2_measured\[Pa\]" ||
  { echo "no measured channels"; exit 1; }
echo "replay 1:1 reproduced its runs.csv line"
