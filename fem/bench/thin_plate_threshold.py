"""The thin-plate study's FEM restitution against the thin-plate and massive-plate models, and
the plate thickness where the massive-plate model leaves 5 % / 2 % in the energy loss.

Both models as in the report's validity map (postprocess/README.md): Hertz contact (n = 3/2)
with Hunt-Crossley damping b(V) chosen so that the model reproduces the FEM restitution of
the most massive plate of the campaign at the same velocity; the thin-plate model on Zener's
infinite Kirchhoff plate, the massive-plate model on a rigid support. The thresholds use the
thin-plate model as the stand-in for the FEM between the campaign's thicknesses.

Usage: /usr/bin/python3 fem/bench/thin_plate_threshold.py CAMPAIGN_DIR IMPACT_REDUCED
"""
import json, os, sys
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from zener_model import R, impact

campaign, reduced = sys.argv[1], sys.argv[2]


def zener(h, v, b):
    return impact(reduced, h, v, b)


RIGID = 1e3  # a 1 km plate: lambda ~ 1e-10, rigid for every digit shown


def damping(h, v, e_target):
    """b with which the model on plate h reproduces e_target (bisection on e(b), decreasing)."""
    low, high = 0.0, 1.0 / v
    while zener(h, v, high)["restitution"] > e_target:
        high *= 2
    for _ in range(50):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if zener(h, v, mid)["restitution"] > e_target else (low, mid)
    return 0.5 * (low + high)


index = json.load(open(os.path.join(campaign, "index.json")))
runs = {}
for run in index["runs"]:
    s = json.load(open(os.path.join(campaign, run["path"], "summary.json")))
    runs[(run["point"]["Scenario/Plate thickness"], run["velocity"])] = s.get("restitution")
h_ref = max(h for h, _ in runs)
velocities = sorted({v for _, v in runs})
b_thin = {v: damping(h_ref, v, runs[(h_ref, v)]) for v in velocities}
b_rigid = {v: damping(RIGID, v, runs[(h_ref, v)]) for v in velocities}
print(f"damping from the {h_ref * 1e3:g} mm plate: " +
      ", ".join(f"b = {b_thin[v]:.4g} (thin) / {b_rigid[v]:.4g} (rigid) s/m at {v:g} m/s" for v in velocities))
print(f"{'h [mm]':>7} {'h/R':>6} {'V':>4} {'lambda':>7} {'e FEM':>7} {'e thin':>7} {'e massive':>9}")
for (h, v) in sorted(runs):
    z, r = zener(h, v, b_thin[v]), zener(RIGID, v, b_rigid[v])
    e = runs[(h, v)]
    print(f"{h * 1e3:>7g} {h / R:>6.2f} {v:>4g} {z['zener_lambda']:>7.3f} "
          f"{'-' if e is None else format(e, '.4f'):>7} {z['restitution']:>7.4f} {r['restitution']:>9.4f}")
print("energy loss of the massive-plate model against the thin-plate model:")
hs = np.geomspace(0.02, 2.0, 60)
for v in velocities:
    loss_rigid = 1 - zener(RIGID, v, b_rigid[v])["restitution"] ** 2
    error = np.array([loss_rigid / (1 - zener(h, v, b_thin[v])["restitution"] ** 2) - 1 for h in hs])
    limits = []
    for limit in (0.05, 0.02):
        i = int(np.argmax(np.abs(error) < limit))  # the first thickness within
        f = (np.log(abs(error[i - 1])) - np.log(limit)) / (np.log(abs(error[i - 1])) - np.log(abs(error[i])))
        limits.append(np.exp(np.log(hs[i - 1]) + f * (np.log(hs[i]) - np.log(hs[i - 1]))))
    print(f"  V = {v:g} m/s: within 5 % above h = {limits[0] * 1e3:.0f} mm (h/R = {limits[0] / R:.1f}), "
          f"within 2 % above {limits[1] * 1e3:.0f} mm (h/R = {limits[1] / R:.1f})")
