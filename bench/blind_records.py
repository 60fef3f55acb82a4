#!/usr/bin/env python3
"""Records of systems the verdict was never designed on, and the verdicts `analyze` gives them.

Generates 43 record types (chaotic flows and maps, periodic, quasi-periodic, steady,
linear and nonlinear stochastic, non-stationary records; none of them in the validation corpus or the held-out set of
docs/notes/analysis.md) at 10,000 and 5,000 samples as CSV files in DIR, then, with --cli, analyses
each with `analyze`'s defaults (39 surrogates) and without surrogates (the sweep's setting) and
prints the verdicts as a Markdown table. Exit status 1 when a record that is not chaotic is
called chaotic (the verdict's one hard rule); misses of chaotic records are only printed.

The expected class is the prefix of each name: C chaotic, P periodic, Q quasi-periodic,
S steady, N stochastic (docs/validation.md, the blind-records row).

usage: blind_records.py DIR [--cli PATH_TO_PNEUMACHAOS]
"""
import json
import os
import subprocess
import sys

import numpy as np

SAMPLES = 10000
EXPECTED = {"C": "chaotic", "P": "periodic", "Q": "quasi-periodic", "S": "steady",
            "N": "stochastic"}


def rk4(f, x0, dt, n, substeps=1, transient=2000):
    """n samples every dt of the flow f after `transient` samples, classic Runge-Kutta."""
    x = np.array(x0, float)
    h = dt / substeps
    out = np.empty((n, x.size))
    for i in range(transient + n):
        for _ in range(substeps):
            k1 = f(x)
            k2 = f(x + h / 2 * k1)
            k3 = f(x + h / 2 * k2)
            k4 = f(x + h * k3)
            x = x + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
        if i >= transient:
            out[i - transient] = x
    return out


def iterate(f, x0, n, transient=1000):
    x, out = x0, []
    for i in range(transient + n):
        x = f(x)
        if i >= transient:
            out.append(x)
    return np.array(out)


def chua(x):  # double scroll: alpha 15.6, beta 28, m0 -8/7, m1 -5/7 (Chua, Komuro, Matsumoto 1986)
    g = -5 / 7 * x[0] + 0.5 * (-8 / 7 + 5 / 7) * (abs(x[0] + 1) - abs(x[0] - 1))
    return np.array([15.6 * (x[1] - x[0] - g), x[0] - x[1] + x[2], -28 * x[1]])


def chen(x):  # a 35, b 3, c 28 (Chen & Ueta 1999)
    return np.array([35 * (x[1] - x[0]), -7 * x[0] - x[0] * x[2] + 28 * x[1],
                     x[0] * x[1] - 3 * x[2]])


def thomas(x):  # cyclically symmetric, b = 0.18 (Thomas 1999)
    return np.array([np.sin(x[1]) - 0.18 * x[0], np.sin(x[2]) - 0.18 * x[1],
                     np.sin(x[0]) - 0.18 * x[2]])


def sprott_b(x):  # Sprott's system B with the coefficients 0.4 and 1.2 on yz and y
    return np.array([0.4 * x[1] * x[2], x[0] - 1.2 * x[1], 1 - x[0] * x[1]])


def lorenz96(x):  # six sites, forcing 8 (Lorenz 1996)
    return (np.roll(x, -1) - np.roll(x, 2)) * np.roll(x, 1) - x + 8.0


def rossler_hyper(x):  # hyperchaos: a 0.25, b 3, c 0.5, d 0.05 (Rossler 1979)
    return np.array([-x[1] - x[2], x[0] + 0.25 * x[1] + x[3], 3 + x[0] * x[2],
                     -0.5 * x[2] + 0.05 * x[3]])


def brusselator(x):  # A 1, B 3: a limit cycle
    return np.array([1 + x[0] ** 2 * x[1] - 4 * x[0], 3 * x[0] - x[0] ** 2 * x[1]])


def lorenz_r160(x):  # rho 160: a periodic window of the Lorenz system
    return np.array([10 * (x[1] - x[0]), x[0] * (160 - x[2]) - x[1], x[0] * x[1] - 8 / 3 * x[2]])


def duffing_weak(x):  # Holmes' Duffing, delta 0.3, gamma 0.2, omega 1.2: below the chaotic range
    return np.array([x[1], x[0] - x[0] ** 3 - 0.3 * x[1] + 0.2 * np.cos(x[2]), 1.2])


def chaotic(rng):
    ikeda = iterate(lambda z: 1 + 0.9 * z * np.exp(1j * (0.4 - 6 / (1 + abs(z) ** 2))),
                    0.1 + 0.1j, SAMPLES)
    return {
        "C_chua": (rk4(chua, [0.7, 0, 0], 0.05, SAMPLES, 5)[:, 0], 20),
        "C_chen": (rk4(chen, [-10, 0, 37], 0.01, SAMPLES, 4)[:, 0], 100),
        "C_thomas": (rk4(thomas, [0.1, 0, 0], 0.3, SAMPLES, 3, 3000)[:, 0], 1 / 0.3),
        "C_sprottB": (rk4(sprott_b, [0.1, 0.1, 0.1], 0.1, SAMPLES, 2)[:, 0], 10),
        "C_lorenz96": (rk4(lorenz96, 8 + 0.01 * rng.standard_normal(6), 0.05, SAMPLES, 5)[:, 0],
                       20),
        "C_rossler_hyper": (rk4(rossler_hyper, [-10, -6, 0, 10], 0.1, SAMPLES, 4)[:, 0], 10),
        "C_tent": (iterate(lambda x: 1.9999 * min(x, 1 - x), 0.1234, SAMPLES), 1),
        "C_ikeda": (ikeda.real, 1),
        "C_gauss_map": (iterate(lambda x: np.exp(-6.2 * x * x) - 0.5, 0.1, SAMPLES), 1),
    }


def regular():
    t = np.arange(SAMPLES)
    rng = np.random.default_rng(7)
    return {
        "P_square_noise": (np.sign(np.sin(2 * np.pi * t / 50))
                           + 0.05 * rng.standard_normal(SAMPLES), 1),
        "P_triangle": (2 * np.abs(((t / 37) % 1) - 0.5), 1),
        "P_am_commensurate": ((1 + 0.5 * np.sin(2 * np.pi * t / 200))
                              * np.sin(2 * np.pi * t / 20), 1),
        "P_brusselator": (rk4(brusselator, [1, 1], 0.05, SAMPLES, 2)[:, 0], 20),
        "P_lorenz_r160": (rk4(lorenz_r160, [1, 1, 150], 0.01, SAMPLES, 2, 5000)[:, 0], 100),
        "P_duffing_weak": (rk4(duffing_weak, [1, 0, 0], 0.05, SAMPLES, 2, 4000)[:, 0], 20),
        "Q_fm_incommensurate": (np.sin(2 * np.pi * t / 21
                                       + 2 * np.sin(2 * np.pi * t / (21 * np.pi))), 1),
        "Q_am_incommensurate": ((1 + 0.5 * np.sin(2 * np.pi * t / (20 * np.sqrt(5))))
                                * np.sin(2 * np.pi * t / 20), 1),
        "S_damped_to_steady": (np.exp(-t / 1500) * np.sin(2 * np.pi * t / 60) + 2, 1),
    }


def ar(coefficient, shocks):
    y = np.zeros(shocks.size)
    for i in range(1, shocks.size):
        y[i] = coefficient * y[i - 1] + shocks[i]
    return y


def stochastic(rng):
    n = SAMPLES
    spectrum = np.fft.rfft(rng.standard_normal(n))
    f = np.fft.rfftfreq(n)
    spectrum[1:] /= np.sqrt(f[1:])
    spectrum[0] = 0
    e = rng.standard_normal(n + 2)
    arma = np.zeros(n + 2)
    for i in range(2, n + 2):
        arma[i] = 1.5 * arma[i - 1] - 0.8 * arma[i - 2] + e[i] + 0.6 * e[i - 1] + 0.3 * e[i - 2]
    garch, variance = np.zeros(n), np.ones(n)
    for i in range(1, n):
        variance[i] = 0.1 + 0.1 * garch[i - 1] ** 2 + 0.85 * variance[i - 1]
        garch[i] = np.sqrt(variance[i]) * rng.standard_normal()
    oscillator, state = np.zeros(n), np.zeros(2)
    for i in range(n):
        state = state + 0.05 * np.array([state[1], -state[0] - 0.05 * state[1]])
        state[1] += 0.05 * rng.standard_normal()
        oscillator[i] = state[0]
    t = np.arange(n)
    phases, freqs = rng.random(60) * 2 * np.pi, rng.random(60) * 0.2
    return {
        "N_pink": (np.fft.irfft(spectrum, n), 1),
        "N_ou_fine": (ar(0.98, 0.2 * rng.standard_normal(n)), 1),
        "N_arma22": (arma[2:], 1),
        "N_garch": (garch, 1),
        "N_telegraph": (np.cumsum(rng.random(n) < 0.02) % 2 + 0.05 * rng.standard_normal(n), 1),
        "N_ar_cubed": (ar(0.9, rng.standard_normal(n)) ** 3, 1),
        "N_noisy_linear_oscillator": (oscillator, 20),
        "N_random_sines60": (np.sum(np.sin(2 * np.pi * freqs[:, None] * t[None, :]
                                           + phases[:, None]), axis=0), 1),
        "N_cauchy_clipped": (rng.standard_cauchy(n).clip(-50, 50), 1),
    }


def euler_maruyama(drift, noise, x0, dt, n, substeps, rng, transient=2000):
    """First coordinate of dx = drift(x) dt + noise dW, sampled every dt."""
    x = np.array(x0, float)
    h = dt / substeps
    out = np.empty(n)
    for i in range(transient + n):
        for _ in range(substeps):
            x = x + h * drift(x) + np.sqrt(h) * noise * rng.standard_normal(x.size)
        if i >= transient:
            out[i - transient] = x[0]
    return out


def nonlinear_stochastic(rng):
    """Noise-driven nonlinear systems: stochastic, and nonlinear enough to beat surrogates."""
    n = SAMPLES
    e = rng.standard_normal(n)
    setar, bilinear = np.zeros(n), np.zeros(n)
    for i in range(1, n):
        setar[i] = (0.7 if setar[i - 1] <= 0 else -0.5) * setar[i - 1] + e[i]
        bilinear[i] = 0.4 * bilinear[i - 1] + 0.4 * bilinear[i - 1] * e[i - 1] + e[i]
    x, noisy_map = 0.3, []
    for i in range(n + 1000):  # r = 3.5 (period 4) with dynamic noise: exponent still < 0
        x = min(max(3.5 * x * (1 - x) + 0.01 * rng.standard_normal(), 1e-6), 1 - 1e-6)
        if i >= 1000:
            noisy_map.append(x)
    regime = np.cumsum(rng.random(n) < 0.01) % 2
    log_vol = ar(0.98, 0.2 * rng.standard_normal(n))
    return {
        "N_van_der_pol_dynamic_noise": (euler_maruyama(
            lambda s: np.array([s[1], (1 - s[0] ** 2) * s[1] - s[0]]), np.array([0, 0.5]),
            [1, 0], 0.1, n, 10, rng), 10),
        "N_double_well_noise": (euler_maruyama(
            lambda s: np.array([s[1], -0.25 * s[1] + s[0] - s[0] ** 3]), np.array([0, 0.3]),
            [1, 0], 0.1, n, 10, rng), 10),
        "N_phase_diffusion": (np.sin(np.cumsum(2 * np.pi / 40 + 0.05 * rng.standard_normal(n))),
                              1),
        "N_logistic_period4_noise": (np.array(noisy_map), 1),
        "N_setar": (setar, 1),
        "N_bilinear": (bilinear, 1),
        "N_markov_switching": (4.0 * regime - 2.0 + rng.standard_normal(n), 1),
        "N_stochastic_volatility": (np.exp(log_vol / 2) * rng.standard_normal(n), 1),
        "N_ar_squared": (ar(0.95, rng.standard_normal(n)) ** 2, 1),
    }


def nonstationary_and_edge_cases(rng):
    """Regular records that are non-stationary or look irregular, and intermittent chaos."""
    n = SAMPLES
    t = np.arange(n)
    pulses = np.zeros(n)
    for start in np.cumsum(60 + 8 * rng.standard_normal(300)).astype(int):
        if start + 20 < n:
            pulses[start:start + 20] += np.sin(np.pi * np.arange(20) / 20)
    return {
        "C_logistic_intermittent": (iterate(lambda x: 3.8282 * x * (1 - x), 0.3, n), 1),
        "P_chirp": (np.sin(2 * np.pi * (0.01 * t + 0.015 * t * t / n)), 1),
        "P_sine_on_a_trend": (np.sin(2 * np.pi * t / 50) + 3 * t / n, 1),
        "P_sine_aliased": (np.sin(2 * np.pi * 0.4137 * t), 1),
        "Q_beats": (np.sin(2 * np.pi * t / 50) + np.sin(2 * np.pi * t / 52.3), 1),
        "Q_torus3_noise": (np.sin(2 * np.pi * t / 37) + 0.7 * np.sin(2 * np.pi * t / (37 * 2 ** 0.5))
                           + 0.5 * np.sin(2 * np.pi * t / (37 * 3 ** 0.5))
                           + 0.1 * rng.standard_normal(n), 1),
        "N_jittered_pulses": (pulses + 0.01 * rng.standard_normal(n), 1),
    }


def write(directory, name, values, rate):
    with open(os.path.join(directory, name + ".csv"), "w") as f:
        f.write("t,v\n")
        for i, v in enumerate(values):
            f.write(f"{i / rate:.9g},{v:.12g}\n")


def verdict(cli, path, surrogates):
    out = path + f".s{surrogates}.json"
    subprocess.run([cli, "analyze", path, "--surrogates", str(surrogates), "--json", out],
                   capture_output=True, check=True)
    with open(out) as f:
        v = json.load(f)["verdict"]
    return v["regime"], v["chaotic"]


def main(argv):
    if not argv or argv[0].startswith("-"):
        sys.exit(__doc__)
    directory = argv[0]
    cli = argv[2] if len(argv) >= 3 and argv[1] == "--cli" else None
    os.makedirs(directory, exist_ok=True)
    rng = np.random.default_rng(20261124)
    records = {**chaotic(rng), **regular(), **stochastic(rng), **nonlinear_stochastic(rng),
               **nonstationary_and_edge_cases(rng)}
    for name, (values, rate) in records.items():
        write(directory, name, values, rate)
        write(directory, name + "_5k", values[:5000], rate)
    if cli is None:
        return 0
    print("| record | expected | 10,000 (39 surrogates / none) | 5,000 (39 / none) |")
    print("|---|---|---|---|")
    false_chaos = 0
    for name in records:
        expected = EXPECTED[name[0]]
        cells = []
        for suffix in ("", "_5k"):
            path = os.path.join(directory, name + suffix + ".csv")
            pair = [verdict(cli, path, s) for s in (39, 0)]
            false_chaos += sum(1 for _, is_chaotic in pair if is_chaotic and expected != "chaotic")
            cells.append(" / ".join(regime for regime, _ in pair))
        print(f"| {name[2:]} | {expected} | {cells[0]} | {cells[1]} |")
    print(f"\nregular or stochastic records called chaotic: {false_chaos}")
    return 1 if false_chaos else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
