#!/usr/bin/python3
"""Force-approach loops of fem/bench/dynamic_plastic.sh: the FEM's fine level
and Thornton's law (dashed) for each V/V_y, normalised by Thornton's
x_y and F_y (the Hertz approach and force at first yield, p0 = 1.6 Y), one
panel per velocity, one PNG.

Usage: fem/bench/dynamic_plastic_loops.py BENCH_OUTPUT_DIR OUTPUT.png"""
import csv
import glob
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

if len(sys.argv) != 3:
    sys.exit(__doc__)
# The scenario's constants (fem/scenarios/plastic_on_rigid.prm).
R, E, NU, Y = 0.01452, 2e11, 0.3, 2.03e9
E_star, p_y = E / (1 - NU ** 2), 1.6 * Y
x_y = R * (math.pi * p_y / (2 * E_star)) ** 2
F_y = math.pi ** 3 * R ** 2 * p_y ** 3 / (6 * E_star ** 2)
runs = sorted(glob.glob(os.path.join(sys.argv[1], "ratio*", "loops.csv")),
              key=lambda p: float(os.path.basename(os.path.dirname(p))[5:]))
if not runs:
    sys.exit(f"dynamic_plastic_loops: no ratio*/loops.csv in {sys.argv[1]}")
rows = 1 if len(runs) == 1 else 2
columns = (len(runs) + rows - 1) // rows
fig, axes = plt.subplots(rows, columns, figsize=(4.2 * columns, 4 * rows), squeeze=False)
for ax in axes.flat[len(runs):]:
    ax.remove()  # an odd number of runs leaves one panel empty
for ax, path in zip(axes.flat, runs):
    data = {"fem": ([], []), "thornton": ([], [])}
    with open(path) as f:
        next(f)
        for row in csv.DictReader(f):
            data[row["source"]][0].append(float(row["approach"]) / x_y)
            data[row["source"]][1].append(float(row["force"]) / F_y)
    ax.plot(*data["fem"], ".-", ms=2, lw=1, label="FEM (fine level)")
    ax.plot(*data["thornton"], "--", lw=1, label="Thornton 1997")
    ax.set_title("V/V_y = " + os.path.basename(os.path.dirname(path))[5:])
    ax.set_xlabel("approach / x_y")
    ax.set_ylabel("force / F_y")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=90)
print(f"wrote {sys.argv[2]} ({len(runs)} loops)")
