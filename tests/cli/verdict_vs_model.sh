#!/usr/bin/env bash
# bench/verdict_vs_model.py: a run whose model label differs between settings of the model's
# exponent leaves the settled table; a relabelling whose record verdicts differ is refused.
set -euo pipefail
script=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
header="point,repeat,ok,chaotic,lambda_per_s,lambda_uncertainty_per_s,lambda_model_per_s,lambda_model_uncertainty_per_s"
# runs: (record chaotic, model exponent +- sd) -- 0: TP, 1: FN, 2: TN, 3: FP; run 1's label
# flips under the second setting (2.0 +- 1.0 is below 3 sigma), run 3's stays.
printf '%s\n0,0,1,1,nan,nan,4.0,1.0\n1,0,1,0,nan,nan,4.0,1.0\n2,0,1,0,nan,nan,0.1,0.2\n3,0,1,1,nan,nan,0.5,0.4\n' "$header" > "$work/a.csv"
printf '%s\n0,0,1,1,nan,nan,5.0,1.0\n1,0,1,0,nan,nan,2.0,1.0\n2,0,1,0,nan,nan,0.2,0.2\n3,0,1,1,nan,nan,0.6,0.4\n' "$header" > "$work/b.csv"
out=$(python3 "$script" "$work/a.csv" --relabel "$work/b.csv")
all=$(grep -F '**all**' <<<"$out" | head -n 1)
settled=$(grep -F '**all**' <<<"$out" | tail -n 1)
[ "$all" = "| **all** | 4 | 1 | 1 | 1 | 1 | 50.0 % | 0 |" ] || { echo "all runs: $all"; exit 1; }
[ "$settled" = "| **all** | 3 | 1 | 1 | 0 | 1 | 66.7 % | 1 |" ] || { echo "settled: $settled"; exit 1; }
sed 's/^2,0,1,0,/2,0,1,1,/' "$work/b.csv" > "$work/c.csv"
if python3 "$script" "$work/a.csv" --relabel "$work/c.csv" > /dev/null 2> "$work/err"; then
  echo "a relabelling with another record verdict was accepted"; exit 1
fi
grep -q "another record verdict" "$work/err" || { cat "$work/err"; exit 1; }
echo "settled labels counted, mismatched relabelling refused"
