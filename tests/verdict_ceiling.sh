#!/usr/bin/env bash
# scripts/verdict_ceiling.py: classifiers fitted to labels that one number decides must find
# that boundary (the best cross-validated agreement >= 95 %; each at least 10 points above
# calling every run regular: nearest neighbours lose some to the irrelevant numbers), must
# not find one in labels drawn at
# random (no better than calling every run regular, give or take the folds' spread), and must
# fail on --transfer runs where the same number means the opposite.
set -euo pipefail
python=$1
script=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# make_runs FILE MODE: 200 runs, broadband share uniform in 0..1; MODE "rule": chaotic (model
# 5 +- 1) above 0.7, "inverted": below 0.3, "random": chaotic one run in four at random.
make_runs() {
  "$python" - "$1" "$2" <<'PY'
import random, sys
path, mode = sys.argv[1], sys.argv[2]
rng = random.Random(7)
with open(path, "w") as f:
    f.write("point,repeat,ok,chaotic,lambda_per_s,lambda_uncertainty_per_s,broadband_share,"
            "late_acf,stick_slip,zero_one_K,prediction_ratio,repeat_share,lambda_model_per_s,"
            "lambda_model_uncertainty_per_s\n")
    for i in range(200):
        b = rng.random()
        chaotic = {"rule": b > 0.7, "inverted": b < 0.3, "random": rng.random() < 0.25}[mode]
        other = [rng.random() for _ in range(4)]
        k = "nan" if rng.random() < 0.2 else f"{rng.random():.4f}"  # "not measured" flags too
        f.write(f"{i},0,1,0,nan,nan,{b:.4f},{other[0]:.4f},{int(other[1] > 0.5)},{k},"
                f"{other[2]:.4f},{other[3]:.4f},{5.0 if chaotic else 0.0},1.0\n")
PY
}
make_runs "$work/rule.csv" rule
make_runs "$work/inverted.csv" inverted
make_runs "$work/random.csv" random
fitted=$("$python" "$script" "$work/rule.csv" --transfer "$work/inverted.csv")
echo "$fitted"
"$python" - "$fitted" <<'PY'
import re, sys
text = sys.argv[1]
baseline = float(re.search(r"regular agrees on ([0-9.]+) %", text).group(1))
lines = [l for l in text.splitlines() if "cross-validated" in l]
assert len(lines) == 3, lines
best = 0.0
for l in lines:
    cv = float(re.search(r"agreement ([0-9.]+) %", l).group(1))
    transfer = float(re.search(r"--transfer runs ([0-9.]+) %", l).group(1))
    best = max(best, cv)
    assert cv >= baseline + 10.0, f"no better than calling every run regular: {l}"
    assert transfer <= 60.0, f"an inverted boundary was not caught: {l}"
assert best >= 95.0, f"the one-number boundary was not found (best {best} %)"
PY
noise=$("$python" "$script" "$work/random.csv")
echo "$noise"
"$python" - "$noise" <<'PY'
import re, sys
text = sys.argv[1]
baseline = float(re.search(r"regular agrees on ([0-9.]+) %", text).group(1))
for l in [l for l in text.splitlines() if "cross-validated" in l]:
    cv = float(re.search(r"agreement ([0-9.]+) %", l).group(1))
    assert cv <= baseline + 5.0, f"a boundary found in random labels: {l}"
PY
sed 's/,5.0,1.0$/,0.0,1.0/' "$work/rule.csv" > "$work/one_class.csv"
if "$python" "$script" "$work/one_class.csv" > /dev/null 2> "$work/err"; then
  echo "one class only was accepted"; exit 1
fi
grep -q "one class only" "$work/err" || { cat "$work/err"; exit 1; }
echo "boundary found, random labels not fitted, transfer failure shown"
