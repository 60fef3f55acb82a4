#!/usr/bin/env bash
# sweep --adaptive: kill -9 in the middle and --resume gives the files of an uninterrupted
# adaptive sweep; its runs are the full sweep's lines; an inferred point can be replayed
# (which evaluates it) and gives the full sweep's line.
set -euo pipefail
cli=$1
source "$(dirname "$0")/kill_mid_sweep.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
args=(sweep --grid circuit.S1_mm2=2.45:3.70:0.25 --grid circuit.S2_mm2=0.05:0.95:0.15
      --repeats 2 --set variation.friction_rel_sd=0.05 --threads 2)
adaptive=(--adaptive --adaptive-step 2)
"$cli" "${args[@]}" --out "$work/full" >/dev/null
"$cli" "${args[@]}" "${adaptive[@]}" --out "$work/adaptive" >"$work/adaptive.log"
grep -q "^adaptive: [0-9]* of 42 points evaluated" "$work/adaptive.log" || { cat "$work/adaptive.log"; exit 1; }
"$cli" "${args[@]}" "${adaptive[@]}" --out "$work/killed" >/dev/null &
kill_mid_sweep "$work/killed" $!
"$cli" "${args[@]}" "${adaptive[@]}" --out "$work/killed" --resume >/dev/null
for f in runs.csv points.csv summary.json; do cmp "$work/adaptive/$f" "$work/killed/$f"; done
# A full sweep's resume into the adaptive directory is another sweep.
if "$cli" "${args[@]}" --out "$work/killed" --resume 2>"$work/err"; then
  echo "a full sweep resumed an adaptive one"; exit 1
fi
grep -q "different sweep" "$work/err"
# Every adaptive run is the full sweep's run, line for line.
if grep -vxF -f "$work/full/runs.csv" "$work/adaptive/runs.csv"; then
  echo "the adaptive runs above differ from the full sweep's"; exit 1
fi
# The first inferred point (points.csv's column `inferred`), replayed.
point=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "inferred") c = i }
                 NR > 1 && $c == 1 { print $1; exit }' "$work/adaptive/points.csv")
[ -n "$point" ] || { echo "no inferred point"; exit 1; }
"$cli" "${args[@]}" "${adaptive[@]}" --replay "$point:1" -o "$work/run.csv" 2>"$work/line"
expected=$(awk -F, -v p="$point" 'NR > 1 && $3 == p && $4 == 1' "$work/full/runs.csv" | cut -d, -f3-)
got=$(grep '^  ' "$work/line" | sed -E 's/^  [^ ]+ *//' | paste -sd, -)  # the named fields
[ "$expected" = "$got" ] || { printf 'full:   %s\nreplay: %s\n' "$expected" "$got"; exit 1; }
echo "adaptive: killed and resumed identical; evaluated runs are the full sweep's; inferred point replayed"
