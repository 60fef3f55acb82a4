#!/usr/bin/env python3
"""Writes flows.tsv from dysts's dysts/data/chaotic_attractors.json (see README.md here).

Usage: extract.py chaotic_attractors.json > flows.tsv
Only the systems listed below are kept: those whose right-hand side tests/support/dysts_flows.hpp
implements. The values are copied as they are; nothing is computed here.
"""
import json
import sys

SYSTEMS = """Aizawa Arneodo BurkeShaw Chen ChenLee Coullet Dadras DequanLi Finance GenesioTesi
Hadley Halvorsen HenonHeiles HindmarshRose HyperLorenz Laser LiuChen Lorenz Lorenz84 Lorenz96
LorenzStenflo LuChen LuChenCheng MooreSpiegel NewtonLiepnik NoseHoover PanXuZhou PehlivanWei Qi
QiChen RabinovichFabrikant RikitakeDynamo Rossler Rucklidge Sakarya ShimizuMorioka SprottA
SprottB SprottC SprottD SprottE SprottF SprottG SprottH SprottI SprottJ SprottJerk SprottK
SprottL SprottM SprottN SprottO SprottP SprottQ SprottR SprottS Thomas ThomasLabyrinth Tsucs2
WangSun YuWang ZhouChen""".split()


def main():
    data = json.load(open(sys.argv[1]))
    print("# name\tparameters\tinitial_conditions\tdt\tperiod\tmaximum_lyapunov_estimated")
    for name in SYSTEMS:
        e = data[name]
        params = ";".join(f"{k}={v!r}" for k, v in e["parameters"].items()) or "-"
        ic = ",".join(repr(v) for v in e["initial_conditions"])
        print(f"{name}\t{params}\t{ic}\t{e['dt']!r}\t{e['period']!r}\t"
              f"{e['maximum_lyapunov_estimated']!r}")


if __name__ == "__main__":
    main()
