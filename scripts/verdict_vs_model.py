#!/usr/bin/env python3
"""Agreement of the record-based chaos verdict with the model's own exponent.

Reads the runs.csv of sweeps run with `--model-exponent` and labels each run chaotic when the
model's exponent exceeds 3 times its uncertainty (docs/sweep.md); the record's label is the
`chaotic` column (docs/analysis.md). Prints the confusion table per sweep and in total, as
Markdown (docs/analysis.md, "Validation against the model").

Last, how often the model's exponent lies inside the record's 95 % interval (docs/analysis.md
"Divergence exponent's uncertainty"): runs with a fitted divergence exponent, inside when
|lambda_record - lambda_model| <= 1.96 x the two uncertainties in quadrature.

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


def coverage(paths):
    """(inside, runs) over all runs with a fitted exponent, and over the model-chaotic ones."""
    n = inside = n_chaotic = inside_chaotic = 0
    for path in paths:
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                vals = [float(row[k]) for k in ("lambda_per_s", "lambda_uncertainty_per_s",
                                                "lambda_model_per_s",
                                                "lambda_model_uncertainty_per_s")]
                if row["ok"] != "1" or any(math.isnan(v) for v in vals) or vals[0] == 0.0:
                    continue
                lam, sd, model, model_sd = vals
                ok = abs(lam - model) <= 1.96 * math.hypot(sd, model_sd)
                chaotic = model > 3.0 * model_sd and model > 0.0
                n += 1
                inside += ok
                n_chaotic += chaotic
                inside_chaotic += ok and chaotic
    return inside, n, inside_chaotic, n_chaotic


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
    inside, n, inside_chaotic, n_chaotic = coverage(paths)
    print(f"\nmodel exponent inside the record's 95 % interval: {inside} of {n} runs with a "
          f"fitted exponent; {inside_chaotic} of {n_chaotic} of those the model calls chaotic")


if __name__ == "__main__":
    main(sys.argv[1:])
