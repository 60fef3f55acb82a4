#!/usr/bin/env python3
"""The verdict on dysts's flows seen through observational noise.

Usage:
    build/bench/bench_dysts --records DIR          # writes DIR/index.tsv and the records
    python3 bench/dysts_noise.py PNEUMACHAOS DIR [--samples 10000] [--surrogates N]

Each record of DIR/index.tsv with the given length gets white noise of 5 % and 10 % of its
standard deviation (seeded from its name) and is judged by `pneumachaos analyze` beside its
clean verdict. Prints, per noise level, how many chaotic flows are called chaotic and how many
regular ones (dysts's own non-chaotic systems) are; docs/validation.md quotes the table.
"""
import argparse
import collections
import json
import os
import subprocess
import tempfile
import zlib

import numpy as np


def judge(cli, x, rate, surrogates, scratch):
    with open(scratch, 'w') as f:
        f.write('t[s],x\n')
        f.writelines(f'{i / rate:.9g},{v:.12g}\n' for i, v in enumerate(x))
    done = subprocess.run([cli, 'analyze', scratch, '--column', 'x', '--surrogates',
                           str(surrogates), '--json', scratch + '.json'],
                          capture_output=True, text=True)
    if done.returncode != 0:
        return 'error'
    return json.load(open(scratch + '.json'))['verdict']['regime']


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('cli')
    parser.add_argument('records')
    parser.add_argument('--samples', type=int, default=10000)
    parser.add_argument('--surrogates', type=int, default=0)
    args = parser.parse_args()
    rows = [line.rstrip('\n').split('\t') for line in open(os.path.join(args.records, 'index.tsv'))
            if not line.startswith('#')]
    tally = collections.defaultdict(lambda: [0, 0])
    with tempfile.TemporaryDirectory() as tmp:
        scratch = os.path.join(tmp, 'record.csv')
        for name, samples, rate, kind, *_ in rows:
            if int(samples) != args.samples or kind not in ('chaotic', 'regular'):
                continue
            x = np.loadtxt(os.path.join(args.records, f'{name}_{samples}.txt'))
            rng = np.random.default_rng(zlib.crc32(name.encode()))
            verdicts = []
            for share in (0.0, 0.05, 0.10):
                noisy = x + rng.normal(0.0, share * x.std(), len(x)) if share else x
                regime = judge(args.cli, noisy, float(rate), args.surrogates, scratch)
                verdicts.append(regime)
                called, total = tally[(kind, share)]
                tally[(kind, share)] = [called + (regime == 'chaotic'), total + 1]
            print(f'{name:20s} {kind:8s} ' + ' '.join(f'{v:15s}' for v in verdicts), flush=True)
    for (kind, share), (called, total) in sorted(tally.items()):
        print(f'{kind} flows, noise {share:.0%} of the std: called chaotic {called} of {total}')


if __name__ == '__main__':
    main()
