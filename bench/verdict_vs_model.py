#!/usr/bin/env python3
"""Agreement of the record-based chaos verdict with the model's own exponent.

Reads the runs.csv of sweeps run with `--model-exponent` and labels each run chaotic when the
model's exponent exceeds 3 times its uncertainty (docs/sweep.md); the record's label is the
`chaotic` column (docs/notes/analysis.md). Prints the confusion table per sweep and in total, as
Markdown (docs/notes/analysis.md, "Validation against the model's own exponent").

Last, how often the model's exponent lies inside the record's 95 % interval (docs/notes/analysis.md
"Divergence exponent's uncertainty"): runs with a fitted divergence exponent, inside when
|lambda_record - lambda_model| <= 1.96 x the two uncertainties in quadrature.

With --relabel, the same sweeps run again with other, equally valid settings of the model's
exponent (another renormalisation interval, another start-up discarded) follow, one group per
setting in the same order: a run's label is settled when every setting gives it, and a second
table counts only settled runs (docs/notes/analysis.md, "Validation against the model's own
exponent": the labels are not settled). The record
verdict does not depend on those settings; a run whose verdict differs between groups is an
error (the groups are not the same sweeps).

usage: verdict_vs_model.py RUNS_CSV [RUNS_CSV ...] [--relabel RUNS_CSV [RUNS_CSV ...]] ...
"""
import csv
import math
import sys


def labels(path):
    """{(point, repeat): (model label or None when not measured, record's chaotic flag)}."""
    out = {}
    with open(path, newline="") as f:
        for row in csv.DictReader(f):
            lam = float(row["lambda_model_per_s"])
            sd = float(row["lambda_model_uncertainty_per_s"])
            measured = row["ok"] == "1" and not math.isnan(lam) and not math.isnan(sd)
            model = lam > 3.0 * sd and lam > 0.0 if measured else None
            out[(row["point"], row["repeat"])] = (model, row["chaotic"] == "1")
    return out


def settled(path, relabels):
    """The runs of `path` with their label where every relabelling agrees, else None."""
    base = labels(path)
    for other_path in relabels:
        other = labels(other_path)
        if other.keys() != base.keys():
            sys.exit(f"{other_path}: not the same runs as {path}")
        for key, (model, record) in base.items():
            if other[key][1] != record:
                sys.exit(f"{other_path}: run {key} has another record verdict than in {path}")
            if other[key][0] != model:
                base[key] = (None, record)
    return base


def counts(runs):
    c = {"tp": 0, "fp": 0, "fn": 0, "tn": 0, "skipped": 0}
    for model, record in runs.values():
        if model is None:
            c["skipped"] += 1
            continue
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


def table(paths, relabel_groups, skipped_name):
    print(f"| sweep | runs | true pos. | false pos. | false neg. | true neg. | agreement | "
          f"{skipped_name} |")
    print("|---|---|---|---|---|---|---|---|")
    total = {"tp": 0, "fp": 0, "fn": 0, "tn": 0, "skipped": 0}
    for i, p in enumerate(paths):
        c = counts(settled(p, [group[i] for group in relabel_groups]))
        for k in total:
            total[k] += c[k]
        print(line(p, c))
    print(line("**all**", total))


def split_groups(args):
    groups = [[]]
    for a in args:
        if a == "--relabel":
            groups.append([])
        else:
            groups[-1].append(a)
    if not groups[0] or any(len(g) != len(groups[0]) for g in groups):
        sys.exit(__doc__)
    return groups[0], groups[1:]


def main(args):
    paths, relabel_groups = split_groups(args)
    table(paths, [], "skipped")
    inside, n, inside_chaotic, n_chaotic = coverage(paths)
    print(f"\nmodel exponent inside the record's 95 % interval: {inside} of {n} runs with a "
          f"fitted exponent; {inside_chaotic} of {n_chaotic} of those the model calls chaotic")
    if relabel_groups:
        print(f"\nRuns whose label is settled under all {len(relabel_groups) + 1} settings of the "
              "model's exponent (unsettled ones are left out):\n")
        table(paths, relabel_groups, "unsettled or skipped")


if __name__ == "__main__":
    main(sys.argv[1:])
