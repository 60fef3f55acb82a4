#!/usr/bin/env python3
"""The paper's judge and the regime verdict on the rig's records, clean and with sensor noise.

Usage:
    python3 bench/paper_judge_noise.py PNEUMACHAOS RECORDS_DIR

RECORDS_DIR holds the rig records bench/transducer_robustness.py writes (run it first with the
same folder). Each record's first repeat, if at least 3.2 s long, is judged from 2 s by
`analyze --judge paper --surrogates 0` clean and with white noise of 1 % and 3 % of its swing
(seeded from the record's name), and the script prints each record's verdict and the paper's
judgement, then per noise level how many records each judge calls chaotic
(docs/notes/virtual_rig.md, "The random seal against the paper's judge").
"""
import argparse
import csv
import json
import os
import subprocess
import tempfile
import zlib

import numpy as np

LEVELS = (0.0, 0.01, 0.03)


def velocity(path):
    rows = list(csv.reader(open(path)))
    names = [h.split('[')[0] for h in rows[0]]
    table = np.array(rows[1:], float)
    return table[:, 0], table[:, names.index('v')]


def judge(cli, t, v, work):
    record = os.path.join(work, 'record.csv')
    out = os.path.join(work, 'analysis.json')
    np.savetxt(record, np.column_stack([t, v]), delimiter=',', header='t,v', comments='')
    subprocess.run([cli, 'analyze', record, '--column', 'v', '--from', '2', '--judge', 'paper',
                    '--surrogates', '0', '--json', out], capture_output=True, check=True)
    r = json.load(open(out))
    return r['verdict']['regime'], r['paper_judge']['chaotic']


def main():
    p = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    p.add_argument('cli')
    p.add_argument('records')
    a = p.parse_args()
    counts = {level: [0, 0, 0] for level in LEVELS}  # records, verdict chaotic, paper chaotic
    with tempfile.TemporaryDirectory() as work:
        for name in sorted(f for f in os.listdir(a.records) if f.endswith('_0.csv')):
            t, v = velocity(os.path.join(a.records, name))
            if t[-1] < 3.2:
                continue
            swing = v.max() - v.min()
            for level in LEVELS:
                rng = np.random.default_rng(zlib.crc32(f'{name}{level}'.encode()))
                regime, paper = judge(a.cli, t, v + level * swing * rng.standard_normal(len(v)),
                                      work)
                print(f'{name} noise {100 * level:g} %: verdict {regime}, paper {paper}')
                c = counts[level]
                c[0] += 1
                c[1] += regime == 'chaotic'
                c[2] += paper is True
    for level, (n, strict, paper) in counts.items():
        print(f'noise {100 * level:g} %: {n} records, verdict chaotic {strict}, '
              f'paper chaotic {paper}')


if __name__ == '__main__':
    main()
