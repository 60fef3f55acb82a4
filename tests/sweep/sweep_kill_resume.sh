#!/usr/bin/env bash
# kill -9 in the middle of a sweep, then --resume: the result files must equal those of an
# uninterrupted run, and a resume with another seed must be refused.
set -euo pipefail
cli=$1
source "$(dirname "$0")/kill_mid_sweep.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# 42 runs of 10 s records with stick-slip (slow to analyse): the kill lands well before the end.
args=(sweep --grid circuit.S1_mm2=2.6:2.8:0.1 --grid circuit.S2_mm2=0.05:0.35:0.05 --repeats 2
      --set variation.friction_rel_sd=0.05 --threads 2)
"$cli" "${args[@]}" --out "$work/full" >/dev/null
"$cli" "${args[@]}" --out "$work/killed" >/dev/null &
# Wait for a few finished runs, then kill without warning.
kill_mid_sweep "$work/killed" $!
done_before=$(($(wc -l < "$work/killed/journal.csv") - 1))
"$cli" "${args[@]}" --out "$work/killed" --resume >/dev/null
for f in runs.csv points.csv summary.json; do
  cmp "$work/full/$f" "$work/killed/$f"
done
if "$cli" "${args[@]}" --seed 2 --out "$work/killed" --resume 2>"$work/err"; then
  echo "a resume with another seed was accepted"; exit 1
fi
grep -q "different sweep" "$work/err"
echo "kill/resume identical after $done_before of 42 runs; mismatched resume refused"
