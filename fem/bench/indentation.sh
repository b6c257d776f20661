#!/usr/bin/env bash
# Mesh convergence of the quasi-static indentation: the elastic default
# ball's hemisphere pressed onto the rigid flat to 20 um (20 steps), on
# three meshes whose contact element size, maximum element size and uniform
# zone scale by r = 2 (100, 50, 25 um at the contact point). Prints the
# force and contact radius at the maximum approach, their offsets to Hertz
# (sphere's E*), the observed order, the Richardson extrapolation and the
# grid convergence index (Celik et al. 2008, as for --verify; fem/README.md).
#
# Usage: fem/bench/indentation.sh [BUILD_DIR] [OUTPUT_DIR]
set -euo pipefail
build="${1:-build}"
output="${2:-results/bench/indentation}"
binary="$build/bin/impact-fem"
[ -x "$binary" ] || { echo "indentation: no executable $binary (build first)" >&2; exit 1; }
mkdir -p "$output"
run() { # name contact-element-size maximum-element-size
  "$binary" --set "Scenario/Analysis=indentation" --set "Plate/Material model=rigid" \
    --set "Sphere/Elastic/Young's modulus=2e11" --set "Sphere/Elastic/Poisson's ratio=0.25" \
    --set "Sphere/Elastic/Density=7800" \
    --set "Indentation/Maximum approach=20e-6" --set "Indentation/Steps=20" \
    --set "Mesh/Contact element size=$2" --set "Mesh/Maximum element size=$3" \
    --set "Output/Directory=$output/$1" > "$output/$1.log" 2>&1 \
    || { echo "run $1 failed, see $output/$1.log" >&2; exit 1; }
}
run coarse 100e-6 40e-3
run medium 50e-6 20e-3
run fine 25e-6 10e-3
/usr/bin/python3 - "$output" <<'PY'
import json, math, os, sys
d = sys.argv[1]
load = lambda name: json.load(open(os.path.join(d, name, "summary.json")))
levels = [(name, load(name)) for name in ("fine", "medium", "coarse")]
R, omega = 0.01452, 20e-6
E_star = 2e11 / (1 - 0.25 ** 2)
hertz = {"force_max": 4 / 3 * E_star * math.sqrt(R) * omega ** 1.5,
         "contact_radius_max": math.sqrt(R * omega)}
print(f"indentation of the default ball on the rigid flat to {omega*1e6:g} um")
print(f"{'mesh':>7} {'h [um]':>7} {'cells':>6} {'dofs':>7} {'F [N]':>10} {'F/Hertz-1':>10} "
      f"{'a [mm]':>8} {'a/Hertz-1':>10} {'wall [s]':>8}")
for (name, s), h in zip(levels, (25, 50, 100)):
    print(f"{name:>7} {h:>7} {s['cells']:>6} {s['dofs']:>7} {s['force_max']:>10.3f} "
          f"{(s['force_max']/hertz['force_max']-1)*100:>9.3f}% {s['contact_radius_max']*1e3:>8.4f} "
          f"{(s['contact_radius_max']/hertz['contact_radius_max']-1)*100:>9.3f}% {s['wall_time']:>8.1f}")
r = 2.0
for key in ("force_max", "contact_radius_max"):
    f1, f2, f3 = (s[key] for _, s in levels)
    e21, e32 = f2 - f1, f3 - f2
    ratio = e21 / e32 if e32 != 0 else float("inf")
    if 0 < ratio < 1:
        p = math.log(e32 / e21) / math.log(r)
        extrapolated = (r ** p * f1 - f2) / (r ** p - 1)
        gci = 1.25 * abs(e21 / f1) / (r ** min(p, 2) - 1)
        print(f"{key}: observed order {p:.2f}, extrapolated {extrapolated:.6g} "
              f"({(extrapolated/hertz[key]-1)*100:+.3f} % from Hertz), GCI_fine {gci*100:.3f} %")
    else:
        gci = 3 * max(abs(e21), abs(e32)) / abs(f1)
        print(f"{key}: not monotone (R = {ratio:.3g}), GCI_fine = 3 max|e| = {gci*100:.3f} %")
PY
