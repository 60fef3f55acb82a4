#!/usr/bin/env python3
"""How far the record verdict's own numbers could go: classifiers fitted to the model's labels.

Reads the runs.csv of sweeps run with `--model-exponent` (label: the model's exponent above 3
times its uncertainty, as verdict_vs_model.py) and fits three classifiers to those labels from
the numbers the record analysis stores per run -- divergence exponent and its uncertainty,
broadband share, late autocorrelation, stick-slip flag, 0-1 K, prediction ratio, repeat share,
each with a flag for "not measured" -- and nothing about the run's place in the map or its
model exponent. It prints their 10-fold cross-validated agreement over three shuffles (the
spread given is the shuffles'). The folds are drawn by grid point: every run at one point of
the grid (its repeats, with and without seal variation, under every condition) is in one
fold, so a run is never judged by its own twin (docs/notes/analysis.md, "Validation against
the model's own exponent": what a rule fitted to the labels could do).

With --transfer, the classifiers fitted to every run given first then judge the runs after
--transfer (another rig or configuration): a boundary that holds only on the sweeps it was
fitted to fails there. --relabel groups, as in verdict_vs_model.py, come before --transfer
and leave out the fitted runs whose label is not settled.

Needs numpy alone (the machine has no scipy): k nearest neighbours (k = 5), logistic
regression (ridge, Newton steps) and a tree of depth 2 (Gini splits).

usage: verdict_ceiling.py RUNS_CSV [...] [--relabel RUNS_CSV [...]] ... [--transfer RUNS_CSV [...]]
"""
import csv
import math
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from verdict_vs_model import settled, split_groups  # noqa: E402

FEATURES = ("lambda_per_s", "lambda_uncertainty_per_s", "broadband_share", "late_acf",
            "stick_slip", "zero_one_K", "prediction_ratio", "repeat_share")


def runs(path, relabels):
    """Features (value, 1 if not measured), model label and grid point of every settled,
    labelled run; the point is the run's grid coordinates (the columns before "point")."""
    keep = settled(path, relabels)
    rows, labels, points = [], [], []
    with open(path, newline="") as f:
        reader = csv.DictReader(f)
        coordinates = reader.fieldnames[:reader.fieldnames.index("point")]
        for row in reader:
            model = keep[(row["point"], row["repeat"])][0]
            if model is None:
                continue
            values = [float(row[k]) for k in FEATURES]
            rows.append([x for v in values for x in ((0.0, 1.0) if math.isnan(v) else (v, 0.0))])
            labels.append(1 if model else 0)
            points.append(tuple(row[c] for c in coordinates))
    return rows, labels, points


def gather(paths, relabel_groups):
    rows, labels, points = [], [], []
    for i, p in enumerate(paths):
        r, l, q = runs(p, [group[i] for group in relabel_groups])
        rows += r
        labels += l
        points += q
    x = np.array(rows, dtype=float).reshape(-1, 2 * len(FEATURES))
    return x, np.array(labels, dtype=int), points


def standardise(train, test):
    mean, sd = train.mean(axis=0), train.std(axis=0)
    sd[sd == 0.0] = 1.0  # a number constant in training (say, never "not measured") stays as is
    return (train - mean) / sd, (test - mean) / sd


def nearest_neighbours(x, y, test, k=5):
    a, b = standardise(x, test)
    distance = ((b[:, None, :] - a[None, :, :]) ** 2).sum(axis=-1)
    nearest = np.argsort(distance, axis=1)[:, :k]
    return (y[nearest].mean(axis=1) > 0.5).astype(int)


def logistic(x, y, test, ridge=1.0, steps=50):
    a, b = standardise(x, test)
    a, b = np.c_[np.ones(len(a)), a], np.c_[np.ones(len(b)), b]
    penalty = ridge * np.eye(a.shape[1])
    penalty[0, 0] = 0.0  # the intercept is not shrunk
    w = np.zeros(a.shape[1])
    for _ in range(steps):
        p = 1.0 / (1.0 + np.exp(-(a @ w)))
        hessian = a.T @ (a * (p * (1 - p))[:, None]) + penalty
        w -= np.linalg.solve(hessian, a.T @ (p - y) + penalty @ w)
    return (b @ w > 0).astype(int)


def impurity(y):
    """Gini impurity times the count: 0 for one class, and it falls with every purer split,
    also one that leaves the majority unchanged on both sides (counting errors would not)."""
    p = y.mean() if len(y) else 0.0
    return 2.0 * len(y) * p * (1.0 - p)


def grow(x, y, depth):
    """A node: the majority label, or (feature, threshold, left, right) of least impurity."""
    majority = int(y.mean() > 0.5) if len(y) else 0
    if depth == 0 or impurity(y) == 0.0:
        return majority
    best = None
    for j in range(x.shape[1]):
        values = np.unique(x[:, j])
        for t in (values[:-1] + values[1:]) / 2:
            left = x[:, j] <= t
            cost = impurity(y[left]) + impurity(y[~left])
            if best is None or cost < best[0]:
                best = (cost, j, t)
    if best is None:
        return majority
    _, j, t = best
    left = x[:, j] <= t
    return (j, t, grow(x[left], y[left], depth - 1), grow(x[~left], y[~left], depth - 1))


def tree(x, y, test, depth=2):
    node = grow(x, y, depth)

    def judge(row, n):
        while isinstance(n, tuple):
            n = n[2] if row[n[0]] <= n[1] else n[3]
        return n
    return np.array([judge(row, node) for row in test], dtype=int)


CLASSIFIERS = (("5 nearest neighbours", nearest_neighbours), ("logistic regression", logistic),
               ("tree of depth 2", tree))


def cross_validated(x, y, points, fit, folds=10, seed=1):
    """Agreement out of sample, with every run of one grid point in the same fold."""
    names = sorted(set(points))
    fold_of = dict(zip(names, np.random.default_rng(seed).permutation(len(names)) % folds))
    fold = np.array([fold_of[p] for p in points])
    right = 0
    for k in range(folds):
        test = fold == k
        if test.any():
            right += int((fit(x[~test], y[~test], x[test]) == y[test]).sum())
    return right / len(y)


def main(args):
    fitted, transfer = args, []
    if "--transfer" in args:
        i = args.index("--transfer")
        fitted, transfer = args[:i], args[i + 1:]
        if not transfer or "--relabel" in transfer or "--transfer" in transfer:
            sys.exit("verdict_ceiling.py: --transfer takes runs.csv files only, after every "
                     "--relabel group\n\n" + __doc__)
    x, y, points = gather(*split_groups(fitted))
    if len(y) < 20 or y.min() == y.max():
        sys.exit(f"verdict_ceiling.py: {len(y)} labelled runs with {int(y.sum())} chaotic: too "
                 "few, or one class only, to fit a classifier")
    if len(set(points)) < 10:
        sys.exit(f"verdict_ceiling.py: {len(set(points))} grid points: ten folds need ten")
    print(f"{len(y)} runs at {len(set(points))} grid points, {int(y.sum())} labelled chaotic; "
          f"calling every run regular agrees on {100 * (1 - y.mean()):.1f} %")
    tx, ty = (None, None)
    if transfer:
        tx, ty, _ = gather(transfer, [])
        if len(ty) == 0:
            sys.exit("verdict_ceiling.py: the --transfer files hold no labelled run")
    for name, fit in CLASSIFIERS:
        scores = [100 * cross_validated(x, y, points, fit, seed=s) for s in (1, 2, 3)]
        text = (f"{name}: 10-fold cross-validated agreement {np.mean(scores):.1f} % "
                f"(shuffles {', '.join(f'{s:.1f}' for s in scores)})")
        if transfer:
            p = fit(x, y, tx)
            text += (f"; fitted on all, on the --transfer runs {100 * (p == ty).mean():.1f} % "
                     f"(TP {int(((p == 1) & (ty == 1)).sum())} FP {int(((p == 1) & (ty == 0)).sum())} "
                     f"FN {int(((p == 0) & (ty == 1)).sum())} TN {int(((p == 0) & (ty == 0)).sum())})")
        print(text)


if __name__ == "__main__":
    main(sys.argv[1:])
