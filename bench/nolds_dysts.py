#!/usr/bin/env python3
"""A peer's exponent on the dysts records: nolds's lyap_r (Rosenstein et al. 1993, automatic
settings) beside ours, against the exponent from the equations.

Usage:
    build/bench/bench_dysts --records DIR          # writes the records and DIR/index.tsv
    python3 bench/nolds_dysts.py DIR NOLDS_SRC [--samples N]

NOLDS_SRC is a nolds source tree (the folder holding the `nolds` package; the comparison in
docs/validation.md used release 0.6.1). Only numpy is needed: without scikit-learn nolds fits
its line with numpy's polyfit, as it does itself when RANSAC is unavailable. nolds runs at its
defaults (embedding dimension 10, lag from the autocorrelation, 20 steps followed), told the
sampling interval. Its Theiler window `min_tsep` is computed here as its documentation says
(the mean period, 1 / the power-weighted mean frequency, at most a quarter of the record)
because release 0.6.1 takes the ceiling of a complex number there, which numpy rejects.
Scored as docs/notes/exponent_validation.md scores ours: the chaotic class only, within 10 %
of the truth.
"""
import argparse
import sys
import time
import warnings

import numpy as np


def theiler_window(x):
    n = len(x)
    power = np.abs(np.fft.rfft(x, 2 * n - 1)) ** 2
    freq = np.fft.rfftfreq(2 * n - 1)
    mean_freq = np.sum(freq[1:] * power[1:]) / np.sum(power[1:])
    return min(int(np.ceil(1.0 / mean_freq)), int(0.25 * n))


def read_index(path):
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith('#'):
                continue
            name, samples, rate, cls, truth, ours = line.rstrip('\n').split('\t')
            rows.append(dict(name=name, samples=int(samples), rate=float(rate), cls=cls,
                             truth=float(truth), ours=None if ours == '-' else float(ours)))
    return rows


def error(value, truth):
    return None if value is None or not np.isfinite(value) else value / truth - 1.0


def fmt_error(e):
    return '-' if e is None else f'{100 * e:+.0f}%'


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument('records')
    p.add_argument('nolds_src')
    p.add_argument('--samples', type=int, default=10000)
    a = p.parse_args()
    sys.path.insert(0, a.nolds_src)
    import nolds  # noqa: E402  (from the tree named on the command line)

    rows = [r for r in read_index(f'{a.records}/index.tsv')
            if r['samples'] == a.samples and r['cls'] == 'chaotic']
    if not rows:
        sys.exit(f'{a.records}/index.tsv: no chaotic record of {a.samples} samples')
    print(f"{'system':<20} {'truth':>9} {'ours':>9} {'error':>7} {'nolds':>9} {'error':>7} {'s':>5}")
    within = {'ours': 0, 'nolds': 0}
    for r in rows:
        x = np.loadtxt(f"{a.records}/{r['name']}_{r['samples']}.txt")
        start = time.process_time()
        with warnings.catch_warnings():
            warnings.simplefilter('ignore')
            value = nolds.lyap_r(x, tau=1.0 / r['rate'], min_tsep=theiler_window(x))
        seconds = time.process_time() - start
        e_ours, e_nolds = error(r['ours'], r['truth']), error(value, r['truth'])
        within['ours'] += e_ours is not None and abs(e_ours) <= 0.10
        within['nolds'] += e_nolds is not None and abs(e_nolds) <= 0.10
        ours = '-' if r['ours'] is None else f"{r['ours']:.4f}"
        print(f"{r['name']:<20} {r['truth']:>9.4f} {ours:>9} {fmt_error(e_ours):>7} "
              f"{value:>9.4f} {fmt_error(e_nolds):>7} {seconds:>5.1f}", flush=True)
    print(f"within 10 % of the truth, {len(rows)} chaotic records of {a.samples} samples: "
          f"ours {within['ours']}, nolds {within['nolds']}")


if __name__ == '__main__':
    main()
