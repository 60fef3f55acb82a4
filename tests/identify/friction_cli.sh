#!/usr/bin/env bash
# friction on a simulated stick-slip record: outputs appear together; bad input exits 2 naming
# the place; a fit that does not converge exits 3 and writes nothing.
set -uo pipefail
cli=$1 rig=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "$*"; exit 1; }
"$cli" simulate "$rig" --set circuit.S2_mm2=0.2 --duration 6 >"$work/rec.csv" 2>/dev/null || fail "simulate failed"
"$cli" friction "$work/rec.csv" "$rig" --json "$work/f.json" --series-out "$work/curves" \
  --scenario-out "$work/fitted.toml" >"$work/out.txt" 2>&1 || { cat "$work/out.txt"; fail "friction failed"; }
for key in '"fits"' '"breakaway_N"' '"stick_intervals"' '"rms_N"' '"preferred_model"' '"Fc_N"' \
           '"Fs_N"' '"vs_mm_per_s"' '"B_Ns_per_m"' '"stderr"' '"unit"' '"sigma0_N_per_m"'; do
  grep -q "$key" "$work/f.json" || fail "no $key in the JSON"
done
for f in force.csv steady_curve.csv loop_marks.csv model_classic.csv model_stribeck.csv; do
  [ -s "$work/curves/$f" ] || fail "no $f"
done
grep -q '^\[friction\]' "$work/fitted.toml" || fail "no [friction] table"
"$cli" simulate "$work/fitted.toml" --duration 0.05 >/dev/null 2>&1 || fail "the fitted scenario does not simulate"
# Bad input: a missing column, a velocity in mm/s labelled m/s, non-uniform time.
cut -d, -f1,2,3,4 "$work/rec.csv" >"$work/no_p2.csv"
"$cli" friction "$work/no_p2.csv" "$rig" >"$work/log" 2>&1
[ $? -eq 2 ] && grep -q 'no_p2.csv:1: missing column "P2"' "$work/log" || { cat "$work/log"; fail "missing P2"; }
awk -F, 'BEGIN{OFS=","} NR>1{$3=$3*1000} {print}' "$work/rec.csv" >"$work/mm.csv"
"$cli" friction "$work/mm.csv" "$rig" >"$work/log" 2>&1
[ $? -eq 2 ] && grep -qE 'mm.csv:[0-9]+:3 \(v\[m/s\]\): .*look like mm/s' "$work/log" || { cat "$work/log"; fail "velocity unit"; }
sed '500d' "$work/rec.csv" >"$work/gap.csv"
"$cli" friction "$work/gap.csv" "$rig" >"$work/log" 2>&1
[ $? -eq 2 ] && grep -q 'gap.csv:500: time is not uniform' "$work/log" || { cat "$work/log"; fail "gap"; }
# A fit that does not converge: exit 3, no JSON, no scenario.
"$cli" friction "$work/rec.csv" "$rig" --max-iterations 1 --json "$work/g.json" \
  --scenario-out "$work/g.toml" >"$work/log" 2>&1
[ $? -eq 3 ] && grep -q 'did not converge' "$work/log" || { cat "$work/log"; fail "non-convergence"; }
[ -e "$work/g.json" ] || [ -e "$work/g.toml" ] && fail "outputs written after a failed fit"
echo "friction command as expected"
