#!/usr/bin/python3
"""Load-interference curves of elastic-plastic indentations (fem/bench/
indentation_plastic.sh) against the published fits, one PNG per ratio E/Y.

Usage: fem/bench/indentation_plastic_plot.py ORACLE OUTPUT_DIR RUN_DIR[:LABEL] ...
ORACLE is fem_test_sphere_flat_oracle (the reduced library's fits). Each run
is an elastic-plastic indentation on the rigid flat (history.h5,
summary.json); the runs of one figure share E, nu, Y and R, read from the
parameters stored in history.h5. Left: P/P_c against omega/omega_c (Jackson
& Green's critical values), log-log, loading and unloading, with Jackson-
Green and Kogut-Etsion loading; right: the unloading branches, linear, with
the Hertzian unloading curves of Brake's rule and of the contact-radius rule
from the FEM's own maximum (omega_max, P_m)."""
import json
import os
import subprocess
import sys

import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

if len(sys.argv) < 4:
    sys.exit(__doc__)
oracle, output = sys.argv[1], sys.argv[2]
os.makedirs(output, exist_ok=True)


def attribute(f, key):
    value = f.attrs[key]
    return float(value.decode() if isinstance(value, bytes) else value)


runs = []
for arg in sys.argv[3:]:
    directory, _, label = arg.partition(":")
    with h5py.File(os.path.join(directory, "history.h5"), "r") as f:
        E = attribute(f, "Sphere/Elastic-plastic/Young's modulus")
        nu = attribute(f, "Sphere/Elastic-plastic/Poisson's ratio")
        # One yield strength per body; results written before it kept it in the material's
        # subsection.
        Y = attribute(f, "Sphere/Yield strength" if "Sphere/Yield strength" in f.attrs
                      and attribute(f, "Sphere/Yield strength") else
                      "Sphere/Elastic-plastic/Yield strength")
        R = attribute(f, "Scenario/Sphere radius")
        data = {k: f[k][:] for k in ("approach", "contact_force", "unloading", "contact_radius")}
    runs.append((label or os.path.basename(directory.rstrip("/")), E, nu, Y, R, data,
                 json.load(open(os.path.join(directory, "summary.json")))))

groups = {}
for run in runs:
    groups.setdefault((run[1], run[2], run[3], run[4]), []).append(run)
for (E, nu, Y, R), group in groups.items():
    E_star = E / (1 - nu ** 2)
    w_max = max(r[6]["maximum_approach"] for r in group)
    base = json.loads(subprocess.run([oracle, repr(R), repr(E_star), repr(Y), repr(nu), "0"],
                                     capture_output=True, text=True, check=True).stdout)
    w_c, P_c = base["jackson_green_critical_interference"], base["jackson_green_critical_load"]
    grid = np.geomspace(0.1 * w_c, w_max, 200)
    fit = json.loads(subprocess.run([oracle, repr(R), repr(E_star), repr(Y), repr(nu)] +
                                    [repr(w) for w in grid],
                                    capture_output=True, text=True, check=True).stdout)["points"]
    fig, (ax, ax_u) = plt.subplots(1, 2, figsize=(13, 5.2))
    ax.loglog(grid / w_c, [p["jackson_green_load"] / P_c for p in fit], "k-", lw=2,
              label="Jackson & Green 2005 (reduced/)")
    ax.loglog(grid / w_c, [p["kogut_etsion_load"] / P_c for p in fit], "k--", lw=1.5,
              label="Kogut & Etsion 2002 (reduced/)")
    ax.loglog(grid / w_c, (grid / w_c) ** 1.5, ":", color="grey", label="Hertz")
    for label, _, _, _, _, d, s in group:
        w, F, u = d["approach"], d["contact_force"], d["unloading"]
        load = (u == 0) & (w > 0)
        ax.loglog(w[load] / w_c, F[load] / P_c, "o-", ms=3, label=f"FEM {label} loading")
        unload = (u == 1) & (F > 0)
        line, = ax_u.plot(w[unload] / w_c, F[unload] / P_c, "o-", ms=3, label=f"FEM {label} unloading")
        ax.loglog(w[unload] / w_c, F[unload] / P_c, "x", color=line.get_color(), ms=4)
        ax_u.plot([s["residual_approach"] / w_c], [0], "s", color=line.get_color())
        # Hertzian unloading from the FEM's own maximum by both rules.
        w_m, P_m, a_m = s["maximum_approach"], s["force_max"], s["contact_radius_max"]
        k = 4 / 3 * E_star
        w_b = w_m * (1 - P_m / (k * np.sqrt(R) * w_m ** 1.5))
        R_b = P_m ** 2 / (k ** 2 * (w_m - w_b) ** 3)
        w_a = w_m - 3 * P_m / (4 * E_star * a_m)
        R_a = 4 * E_star * a_m ** 3 / (3 * P_m)
        for w0, Ru, style, name in ((w_b, R_b, "--", "Brake 2015 rule"),
                                    (w_a, R_a, ":", "contact-radius rule")):
            ww = np.linspace(max(w0, 0), w_m, 100)
            ax_u.plot(ww / w_c, k * np.sqrt(Ru) * (ww - w0) ** 1.5 / P_c, style,
                      color=line.get_color(), label=f"{name} from FEM (w_m, P_m) [{label}]")
    ax.set_xlabel("omega / omega_c")
    ax.set_ylabel("P / P_c")
    ax.set_title(f"E/Y = {E/Y:g}, nu = {nu:g}: loading (o) and unloading (x)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    ax_u.set_xlabel("omega / omega_c")
    ax_u.set_ylabel("P / P_c")
    ax_u.set_title("unloading; squares: FEM permanent approach")
    ax_u.grid(True, alpha=0.3)
    ax_u.legend(fontsize=7)
    path = os.path.join(output, f"indentation_plastic_EY{E/Y:g}.png")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(path)
