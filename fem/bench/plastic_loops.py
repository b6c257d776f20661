#!/usr/bin/python3
"""Force history and force-approach loop of impact-fem runs, one PNG.

Usage: fem/bench/plastic_loops.py OUTPUT.png RUN_DIR[:LABEL] ...
Each run directory holds a history.h5 (and a summary.json). Printed per
run: peak force, restitution, permanent approach and the step-to-step force
oscillation (summary's force_oscillation, fraction of the peak)."""
import json
import os
import sys

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

if len(sys.argv) < 3:
    sys.exit(__doc__)
fig, (ax_t, ax_x) = plt.subplots(1, 2, figsize=(12, 4.8))
for arg in sys.argv[2:]:
    directory, _, label = arg.partition(":")
    label = label or os.path.basename(directory.rstrip("/"))
    with h5py.File(os.path.join(directory, "history.h5"), "r") as f:
        t, force, approach = f["time"][:], f["contact_force"][:], f["approach"][:]
    s = json.load(open(os.path.join(directory, "summary.json")))
    t0 = s["first_contact_time"] or t[0]
    ax_t.plot((t - t0) * 1e6, force / 1e3, label=label)
    ax_x.plot(approach * 1e6, force / 1e3, label=label)
    print(f"{label}: F_max {s['force_max']:.1f} N, e {s['restitution']:.5f}, permanent approach "
          f"{(s.get('permanent_approach') or 0) * 1e6:.4f} um, force oscillation "
          f"{s['force_oscillation'] * 100:.4f} % of the peak")
ax_t.set_xlabel("time after first contact [us]")
ax_t.set_ylabel("contact force [kN]")
ax_x.set_xlabel("approach [um]")
ax_x.set_ylabel("contact force [kN]")
for ax in (ax_t, ax_x):
    ax.grid(alpha=0.3)
    ax.legend()
ax_x.axhline(0, color="k", lw=0.5)
fig.tight_layout()
fig.savefig(sys.argv[1], dpi=110)
print("wrote", sys.argv[1])
