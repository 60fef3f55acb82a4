#!/usr/bin/env python3
"""Agreement of the record-based chaos verdict with the model's own exponent.

Reads the runs.csv of sweeps run with `--model-exponent` and labels each run chaotic when the
model's exponent exceeds 3 times its uncertainty (docs/sweep.md); the record's label is the
`chaotic` column (docs/analysis.md). Prints the confusion table per sweep and in total, as
Markdown (docs/analysis.md, "Validation against the model").

usage: verdict_vs_model.py RUNS_CSV [RUNS_CSV ...]
"""
import csv
import math
import sys


def counts(path):
    c = {"tp": 0, "fp": 0, "fn": 0, "tn": 0, "skipped": 0}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            lam = float(row["lambda_model_per_s"])
            sd = float(row["lambda_model_uncertainty_per_s"])
            if row["ok"] != "1" or math.isnan(lam) or math.isnan(sd):
                c["skipped"] += 1
                continue
            model = lam > 3.0 * sd and lam > 0.0
            record = row["chaotic"] == "1"
            c[("t" if model == record else "f") + ("p" if record else "n")] += 1
    return c


def line(name, c):
    n = c["tp"] + c["fp"] + c["fn"] + c["tn"]
    agree = (c["tp"] + c["tn"]) / n if n else float("nan")
    return (f"| {name} | {n} | {c['tp']} | {c['fp']} | {c['fn']} | {c['tn']} | "
            f"{100 * agree:.1f} % | {c['skipped']} |")


def main(paths):
    if not paths:
        sys.exit(__doc__)
    print("| sweep | runs | true pos. | false pos. | false neg. | true neg. | agreement | skipped |")
    print("|---|---|---|---|---|---|---|---|")
    total = {"tp": 0, "fp": 0, "fn": 0, "tn": 0, "skipped": 0}
    for p in paths:
        c = counts(p)
        for k in total:
            total[k] += c[k]
        print(line(p, c))
    print(line("**all**", total))


if __name__ == "__main__":
    main(sys.argv[1:])
