"""Simulate the virtual rig at two valve settings, analyse each velocity record, plot both.

    PYTHONPATH=build/python python3 python/examples/stick_slip_and_chaos.py   # writes example.png
"""

import matplotlib

matplotlib.use("Agg")  # no display needed; remove in a notebook
import matplotlib.pyplot as plt

import pneumachaos as pc

fig, axes = plt.subplots(2, 2, figsize=(10, 6))
for row, S2 in enumerate((0.05, 0.35)):
    scenario = pc.Scenario.default().set("circuit.S2_mm2", S2)
    run = pc.simulate(scenario, duration_s=10.0)
    settled = run.t > 2.0  # leave out the start-up
    result = pc.analyze(run.v[settled], rate_Hz=run.rate_Hz, wolf=False)
    verdict = result.verdict["regime"]
    lam = result["lyapunov"]["divergence"]  # value is None when no linear region was found
    exponent = ("no exponent" if lam["value"] is None
                else f"lambda = {lam['value']:.2f} +- {lam['uncertainty']:.2f} 1/s")
    axes[row, 0].plot(run.t, run.v * 1e3, lw=0.6)
    axes[row, 0].set(xlabel="t [s]", ylabel="v [mm/s]",
                     title=f"S2 = {S2} mm$^2$: {verdict}, {exponent}")
    axes[row, 1].semilogy(result.curves["frequency_Hz"], result.curves["psd"], lw=0.6)
    axes[row, 1].set(xlabel="f [Hz]", ylabel="PSD [(m/s)$^2$/Hz]", xlim=(0, 50))
fig.tight_layout()
fig.savefig("example.png", dpi=120)
print("wrote example.png")
