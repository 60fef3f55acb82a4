#!/usr/bin/env python3
"""The verdict through a transducer: rig records judged clean and corrupted, side by side.

Usage:
    python3 bench/transducer_robustness.py PNEUMACHAOS OUT_DIR [--surrogates N]
        [--max-false-chaos N] [--max-settled-false-chaos N] [--changes]

Three rigs (the default, scenarios/variants/compliant_mount.toml, scenarios/variants/
frozen_light_piston.toml) at S2 = 0.05 ... 3.35 mm^2, three runs each with 3 % seal scatter and
5 % bore texture, 30 s or to the stroke end (records of at least 3.2 s kept), each analysed from
2 s clean and with: white noise of 0.25 / 0.5 / 1 / 2 / 3 % of its swing, 10- and 12-bit quantisation
over +-0.5 m/s, and a first-order lag of 100 / 300 Hz (the transducer stages of docs/model.md,
applied here to the clean velocity so the clean and corrupted records share one motion). Each
corruption is seeded from the record's name. Each record also carries the model's own exponent
over its run (`sweep --model-exponent`): chaotic when it exceeds 3 times its uncertainty.

Prints, per corruption, how many verdicts keep the clean record's class, how many records not
chaotic clean are called chaotic ("false chaos"), how many of those the model's exponent does
not call chaotic either ("model not"), how many have a settled clean verdict — not chaotic
from 1.5 s and 2.5 s either ("settled") — and how many stick-slip flags are kept;
docs/notes/analysis.md "Noise floor" gives the table. --changes lists every record whose class
or flag changed. The records are kept in OUT_DIR and reused. About 1.5 min on two cores with
--surrogates 0 (the sweep's setting), and a minute more to simulate the records the first time.
With --max-false-chaos N it exits 1 when more than N noisy, quantised or band-limited records
are called chaotic whose clean record is not; with --max-settled-false-chaos N, when more than
N are whose clean record is settled (the CTest long.transducer_robustness: 0).
"""
import argparse
import collections
import csv
import json
import math
import os
import subprocess
import zlib

import numpy as np

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RIGS = {'default': [], 'compliant': [os.path.join(REPO, 'scenarios/variants/compliant_mount.toml')],
        'frozen': [os.path.join(REPO, 'scenarios/variants/frozen_light_piston.toml')]}
S2 = [0.05, 0.2, 0.35, 0.5, 0.65, 1.25, 3.35]
REPEATS = 3
RATE_HZ = 1000.0
# A clean verdict is settled when no start half a second either side of 2 s reads it chaotic.
SHIFTED_STARTS_S = (1.5, 2.5)


def velocity(path):
    rows = list(csv.reader(open(path)))
    names = [h.split('[')[0] for h in rows[0]]
    table = np.array(rows[1:], float)
    return table[:, 0], table[:, names.index('v')]


def lag(x, corner_Hz):
    """First-order lag, exact for a signal linear between samples (docs/model.md)."""
    h = 1.0 / RATE_HZ
    tau = 1.0 / (2.0 * math.pi * corner_Hz)
    a = math.exp(-h / tau)
    c = tau / h * (1.0 - a)
    y = np.empty_like(x)
    y[0] = x[0]
    for n in range(1, len(x)):
        y[n] = a * y[n - 1] + (1.0 - c) * x[n] + (c - a) * x[n - 1]
    return y


def quantise(x, bits, full_scale=0.5):
    step = 2.0 * full_scale / 2 ** bits
    return np.clip(np.round(x / step) * step, -full_scale, full_scale - step)


def corruptions(v, seed):
    rng = np.random.default_rng(seed)
    swing = v[2000:].max() - v[2000:].min()
    noisy = {share: v + rng.normal(0.0, share * swing, len(v)) for share in (0.005, 0.01, 0.02, 0.03)}
    noisy[0.0025] = v + rng.normal(0.0, 0.0025 * swing, len(v))  # drawn last: the others as before
    out = {'clean': v}
    for share in sorted(noisy):
        out[f'noise {share:.2%}'] = noisy[share]
    for bits in (10, 12):
        out[f'{bits} bits'] = quantise(v, bits)
    for corner in (100, 300):
        out[f'{corner} Hz'] = lag(v, corner)
    return out


def judge(cli, t, x, path, surrogates, start_s=2.0):
    with open(path, 'w') as f:
        f.write('t[s],v[m/s]\n')
        f.writelines(f'{a:.6f},{b:.9g}\n' for a, b in zip(t, x))
    done = subprocess.run([cli, 'analyze', path, '--from', str(start_s), '--surrogates', str(surrogates),
                           '--json', path + '.json'], capture_output=True, text=True)
    if done.returncode != 0:
        return 'error', False
    verdict = json.load(open(path + '.json'))['verdict']
    return verdict['regime'], verdict['stick_slip']


def model_chaotic(run_path):
    """The model's own exponent beyond 3 times its uncertainty (docs/sweep.md), from the
    runs.csv line `sweep --replay` printed."""
    fields = dict(line.split(None, 1) for line in open(run_path).read().splitlines()[1:]
                  if len(line.split(None, 1)) == 2)
    lam = float(fields['lambda_model_per_s'])
    sd = float(fields['lambda_model_uncertainty_per_s'])
    return lam > 0.0 and lam > 3.0 * sd


def record(cli, out, rig, s2, repeat):
    path = os.path.join(out, f'{rig}_{s2}_{repeat}.csv')
    if not os.path.exists(path + '.run'):
        done = subprocess.run([cli, 'sweep'] + RIGS[rig] + [
            '--grid', f'circuit.S2_mm2={s2}:{s2}:0.1', '--repeats', str(REPEATS),
            '--set', 'variation.friction_rel_sd=0.03', '--set', 'variation.texture_rel=0.05',
            '--set', 'run.duration_s=30', '--model-exponent', '--replay', f'0:{repeat}',
            '-o', path], capture_output=True, text=True, check=True)
        with open(path + '.run', 'w') as f:
            f.write(done.stderr)
    t, v = velocity(path)
    return t, v, model_chaotic(path + '.run')


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument('cli')
    parser.add_argument('out')
    parser.add_argument('--surrogates', type=int, default=0)
    parser.add_argument('--max-false-chaos', type=int, default=None)
    parser.add_argument('--max-settled-false-chaos', type=int, default=None)
    parser.add_argument('--changes', action='store_true',
                        help='also list every record whose class or stick-slip flag changed')
    args = parser.parse_args()
    os.makedirs(args.out, exist_ok=True)
    scratch = os.path.join(args.out, 'judged.csv')
    tally = collections.defaultdict(lambda: [0, 0, 0, 0, 0, 0, 0])
    changes = []
    for rig in RIGS:
        for s2 in S2:
            for repeat in range(REPEATS):
                t, v, truth = record(args.cli, args.out, rig, s2, repeat)
                if len(v) < 3200:
                    continue
                seed = zlib.crc32(f'{rig}{s2}{repeat}'.encode())
                verdicts = {name: judge(args.cli, t, x, scratch, args.surrogates)
                            for name, x in corruptions(v, seed).items()}
                clean, clean_flag = verdicts.pop('clean')
                # Settled: not chaotic clean from half a second earlier or later either.
                settled = clean != 'chaotic' and all(
                    judge(args.cli, t, v, scratch, args.surrogates, start)[0] != 'chaotic'
                    for start in SHIFTED_STARTS_S)
                for name, (regime, flag) in verdicts.items():
                    if regime != clean or flag != clean_flag:
                        changes.append(f'{rig} S2={s2} run {repeat} {name}: '
                                       f'{clean}{"*" if clean_flag else ""} -> '
                                       f'{regime}{"*" if flag else ""}'
                                       f'{" (model: chaotic)" if truth else ""}')
                    kept, total, false_chaos, model_not, on_settled, flags, flagged = tally[name]
                    new_chaos = regime == 'chaotic' and clean != 'chaotic'
                    tally[name] = [kept + (regime == clean), total + 1, false_chaos + new_chaos,
                                   model_not + (new_chaos and not truth),
                                   on_settled + (new_chaos and settled),
                                   flags + (clean_flag and flag), flagged + clean_flag]
    for name, (kept, total, false_chaos, model_not, on_settled, flags, flagged) in tally.items():
        print(f'{name:11s} class kept {kept}/{total}  false chaos {false_chaos} '
              f'(model not {model_not}, settled {on_settled})  stick-slip kept {flags}/{flagged}')
    if args.changes:
        print('changed (* marks the stick-slip flag):')
        print('\n'.join(changes))
    false_chaos = sum(counts[2] for counts in tally.values())
    settled = sum(counts[4] for counts in tally.values())
    print(f'false chaos in all: {false_chaos}, on settled clean records: {settled}')
    if args.max_false_chaos is not None and false_chaos > args.max_false_chaos:
        raise SystemExit(f'{false_chaos} records called chaotic whose clean record is not '
                         f'(at most {args.max_false_chaos} allowed)')
    if args.max_settled_false_chaos is not None and settled > args.max_settled_false_chaos:
        raise SystemExit(f'{settled} records called chaotic whose clean record is not chaotic '
                         f'from any start (at most {args.max_settled_false_chaos} allowed)')


if __name__ == '__main__':
    main()
