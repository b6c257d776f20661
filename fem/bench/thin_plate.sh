#!/usr/bin/env bash
# The thin-plate study's FEM campaign as a benchmark: fem/scenarios/thin_plate.prm
# swept over 11 plate thicknesses (2 mm ... 0.35 m, the massive plate) x 4 velocities
# (0.5, 1, 2, 5 m/s) = 44 runs,
# each verified (--verify), on 2 ranks (two groups of one); the wall time (target: within
# 15 minutes on 2 cores), then per run the FEM's e, t_c, F_max with their GCI against
# Zener's thin-plate model (impact-reduced thin-plate: elastic Hertz contact on an infinite
# Kirchhoff plate) and Zener's lambda. Two control runs on a larger plate (Rp = 0.6 m
# instead of 0.35 m) show that no wave returns from the plate's edge during the contact.
#
# Usage: fem/bench/thin_plate.sh [BUILD_DIR] [OUTPUT_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${1:-build}"
output="${2:-results/bench/thin-plate}"
binary="$build/bin/impact-fem"
reduced="$build/bin/impact-reduced"
for tool in "$binary" "$reduced"; do
  [ -x "$tool" ] || { echo "thin_plate: no executable $tool (build first)" >&2; exit 1; }
done
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun=(mpirun --oversubscribe -np 2)
[ "$(id -u)" -eq 0 ] && mpirun+=(--allow-run-as-root)
thicknesses="0.002,0.003,0.005,0.007,0.01,0.015,0.025,0.05,0.1,0.15,0.35"
rm -rf "$output"
mkdir -p "$output"
start=$(date +%s)
"${mpirun[@]}" "$binary" "$here/../scenarios/thin_plate.prm" --verify \
  --sweep "Scenario/Plate thickness=$thicknesses" --set "Output/Directory=$output/campaign" \
  > "$output/campaign.log" 2>&1 || { echo "thin_plate: campaign failed, see $output/campaign.log" >&2; exit 1; }
echo "thin-plate study (11 thicknesses x 4 velocities = 44 runs, each verified: 3 levels), 2 ranks: $(( $(date +%s) - start )) s wall"
# Controls: the same plate with a larger radius, at the slowest velocity (longest contact).
for h in 0.003 0.01; do
  "$binary" "$here/../scenarios/thin_plate.prm" --set "Campaign/Impact velocities=" \
    --set "Scenario/Impact velocity=0.5" --set "Scenario/Plate thickness=$h" \
    --set "Scenario/Plate radius=0.6" --set "Output/Directory=$output/control-$h" \
    > "$output/control-$h.log" 2>&1 || { echo "thin_plate: control failed, see $output/control-$h.log" >&2; exit 1; }
done
/usr/bin/python3 - "$output" "$reduced" "$here" <<'PY'
import json, math, os, sys
import h5py, numpy as np
d, reduced = sys.argv[1], sys.argv[2]
sys.path.insert(0, sys.argv[3])
from zener_model import R, impact as zener_impact
index = json.load(open(os.path.join(d, "campaign", "index.json")))


def zener(h, v):
    return zener_impact(reduced, h, v)


def gci(run, name):
    path = os.path.join(d, "campaign", run["path"], "verification.json")
    if not os.path.exists(path):
        return float("nan")
    q = json.load(open(path))["quantities"].get(name, {})
    # Relative GCI; for the restitution the absolute one (e -> 0 on thin plates).
    value = q.get("gci_fine_absolute" if name == "restitution" else "gci_fine")
    return float("nan") if value is None else value


fmt = lambda x, f: ("-" if x is None or (isinstance(x, float) and math.isnan(x)) else format(x, f))
print("FEM (Kelvin-Voigt steel, free bottom, absorbing side) against Zener's elastic thin-plate model")
print(f"{'h [mm]':>6} {'h/R':>5} {'V':>4} {'lambda':>7} {'e FEM':>8} {'GCI e':>8} {'e Zener':>8} "
      f"{'tc FEM us':>9} {'tc Zener':>9} {'F FEM N':>8} {'F Zener':>8} {'wall s':>6}")
for run in sorted(index["runs"], key=lambda r: (r["point"]["Scenario/Plate thickness"], r["velocity"])):
    h, v = run["point"]["Scenario/Plate thickness"], run["velocity"]
    s = json.load(open(os.path.join(d, "campaign", run["path"], "summary.json")))
    z = zener(h, v)
    tc = s.get("contact_time")
    print(f"{h*1e3:>6g} {h/R:>5.2f} {v:>4g} {z['zener_lambda']:>7.3f} {fmt(s.get('restitution'), '.4f'):>8} "
          f"{fmt(gci(run, 'restitution'), '.1e'):>8} {z['restitution']:>8.4f} "
          f"{fmt(tc * 1e6 if tc else None, '.1f'):>9} {z['contact_time']*1e6:>9.1f} "
          f"{s['force_max']:>8.0f} {z['force_max']:>8.0f} {s.get('wall_time', float('nan')):>6.1f}")
print("\ncontrols at 0.5 m/s: plate radius 0.6 m against 0.35 m (the campaign's)")
for h in (0.003, 0.01):
    big = os.path.join(d, f"control-{h}")
    run = next(r for r in index["runs"] if r["point"]["Scenario/Plate thickness"] == h and r["velocity"] == 0.5)
    small = os.path.join(d, "campaign", run["path"])
    f = [h5py.File(os.path.join(p, "history.h5"), "r") for p in (small, big)]
    n = min(len(f[0]["contact_force"]), len(f[1]["contact_force"]))
    F0, F1 = f[0]["contact_force"][:n], f[1]["contact_force"][:n]
    s0, s1 = (json.load(open(os.path.join(p, "summary.json"))) for p in (small, big))
    print(f"h = {h*1e3:g} mm: e {fmt(s0.get('restitution'), '.6f')} vs {fmt(s1.get('restitution'), '.6f')}, "
          f"largest force difference {np.max(np.abs(F0 - F1)) / np.max(F0) * 100:.3g} % of the peak "
          f"over {f[0]['time'][n-1]*1e6:.0f} us")
PY
echo
/usr/bin/python3 "$here/thin_plate_threshold.py" "$output/campaign" "$reduced"
