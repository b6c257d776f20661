#!/usr/bin/env bash
# Elastic-perfectly-plastic indentation of the default ball's hemisphere
# (R = 14.52 mm, E = 200 GPa, nu = 0.3, H = 0) on the rigid flat, against the
# published finite-element fits of sphere-flat contact: Jackson & Green
# (2005) and Kogut & Etsion (2002) for the loading, Brake (2015) and the
# contact-radius-preserving Hertzian unloading for the residual approach
# (as coded in reduced/, sphere_flat_fits.hpp; the oracle program of the
# tests evaluates them). For each ratio E/Y of RATIOS the hemisphere is
# pressed to OMEGA_MAX times Jackson-Green's critical interference omega_c
# in STEPS equal steps and back until the force vanishes, on three meshes
# whose element sizes (contact element size a_c / n for n in LEVELS, a_c =
# sqrt(R omega_c); the uniform zone and contact surface scaled with the
# largest contact radius) halve from level to level. Prints per ratio and
# mesh P/P_c at the interferences of CHECK (multiples of omega_c) against
# both fits, the residual approach against both unloading rules, and the
# grid convergence index of each (Celik et al. 2008, as fem/bench/
# indentation.sh).
#
# Usage: fem/bench/indentation_plastic.sh [BUILD_DIR] [OUTPUT_DIR]
#   environment: RATIOS (default "200 1000"), LEVELS (default "1 2 4"),
#   OMEGA_MAX (default 30), STEPS (default 15), CHECK (default "10 20 30"),
#   MAX_ITERATIONS (default 100, Nonlinear solver/Maximum iterations: beyond
#   about 75 omega_c the iteration of a step on the finer meshes needs more)
set -euo pipefail
build="${1:-build}"
output="${2:-results/bench/indentation_plastic}"
binary="$build/bin/impact-fem"
oracle="$build/bin/fem_test_sphere_flat_oracle"
ratios="${RATIOS:-200 1000}"
levels="${LEVELS:-1 2 4}"
omega_max="${OMEGA_MAX:-30}"
steps="${STEPS:-15}"
check="${CHECK:-10 20 30}"
max_iterations="${MAX_ITERATIONS:-100}"
for program in "$binary" "$oracle"; do
  [ -x "$program" ] || { echo "indentation_plastic: no executable $program (build impact-fem and fem_test_sphere_flat_oracle)" >&2; exit 1; }
done
mkdir -p "$output"
radius=0.01452 young=2e11 poisson=0.3

for ratio in $ratios; do
  yield=$(/usr/bin/python3 -c "print(repr($young / $ratio))")
  estar=$(/usr/bin/python3 -c "print(repr($young / (1 - $poisson ** 2)))")
  omega_c=$("$oracle" "$radius" "$estar" "$yield" "$poisson" 0 |
            /usr/bin/python3 -c "import json,sys; print(repr(json.load(sys.stdin)['jackson_green_critical_interference']))")
  for n in $levels; do
    name="ratio${ratio}_n${n}"
    [ -f "$output/$name/summary.json" ] && continue
    read -r approach size zone surface largest < <(/usr/bin/python3 - "$radius" "$omega_c" "$omega_max" "$n" <<'PY'
import math, sys
R, omega_c, k, n = map(float, sys.argv[1:])
a_c = math.sqrt(R * omega_c)
# The largest contact radius is about 1.4 sqrt(R omega_max) (Jackson-Green's
# a grows as (omega*/1.9)^(B/2) above Hertz's): the uniform zone covers 1.3
# times it, the candidate contact surface 1.5 times.
a_max = 1.4 * math.sqrt(R * k * omega_c)
print(k * omega_c, a_c / n, 1.3 * a_max, 1.5 * a_max, max(40 * a_c / n, 2e-3))
PY
)
    echo "E/Y = $ratio, omega_c = $omega_c m, mesh n = $n: contact element size $size m" >&2
    "$binary" --set "Scenario/Analysis=indentation" --set "Plate/Material model=rigid" \
      --set "Sphere/Material model=elastic-plastic" \
      --set "Sphere/Elastic-plastic/Young's modulus=$young" \
      --set "Sphere/Elastic-plastic/Poisson's ratio=$poisson" \
      --set "Sphere/Elastic-plastic/Density=7800" \
      --set "Sphere/Yield strength=$yield" \
      --set "Sphere/Elastic-plastic/Hardening modulus=0" \
      --set "Indentation/Maximum approach=$approach" --set "Indentation/Steps=$steps" \
      --set "Nonlinear solver/Maximum iterations=$max_iterations" \
      --set "Mesh/Contact element size=$size" --set "Mesh/Uniform zone radius=$zone" \
      --set "Mesh/Contact surface radius=$surface" --set "Mesh/Maximum element size=$largest" \
      --set "Output/Directory=$output/$name" > "$output/$name.log" 2>&1 \
      || { echo "run $name failed, see $output/$name.log" >&2; exit 1; }
  done
done

/usr/bin/python3 - "$output" "$oracle" "$radius" "$young" "$poisson" "$ratios" "$levels" "$check" <<'PY'
import json, math, os, subprocess, sys
import h5py
d, oracle, R, E, nu = sys.argv[1], sys.argv[2], *map(float, sys.argv[3:6])
ratios, levels, check = sys.argv[6].split(), sys.argv[7].split(), [float(c) for c in sys.argv[8].split()]
E_star = E / (1 - nu ** 2)


def gci(fine, medium, coarse, r=2.0):
    """Observed order and GCI_fine (Celik et al. 2008), or 3 max|e| if not monotone."""
    e21, e32 = medium - fine, coarse - medium
    ratio = e21 / e32 if e32 != 0 else float("inf")
    if 0 < ratio < 1:
        p = math.log(e32 / e21) / math.log(r)
        return p, 1.25 * abs(e21 / fine) / (r ** min(p, 2) - 1)
    return float("nan"), 3 * max(abs(e21), abs(e32)) / abs(fine)


for ratio in ratios:
    Y = E / float(ratio)
    base = json.loads(subprocess.run([oracle, str(R), str(E_star), str(Y), str(nu), "0"],
                                     capture_output=True, text=True, check=True).stdout)
    w_c, P_c = base["jackson_green_critical_interference"], base["jackson_green_critical_load"]
    ke_c, ke_P = base["kogut_etsion_critical_interference"], base["kogut_etsion_critical_load"]
    print(f"\nE/Y = {ratio} (Y = {Y/1e6:g} MPa, E* = {E_star/1e9:.2f} GPa): Jackson-Green omega_c = "
          f"{w_c*1e9:.2f} nm, P_c = {P_c:.5g} N; Kogut-Etsion omega_c = {ke_c*1e9:.2f} nm, "
          f"P_c = {ke_P:.5g} N")
    rows = {}
    for n in levels:
        directory = os.path.join(d, f"ratio{ratio}_n{n}")
        s = json.load(open(os.path.join(directory, "summary.json")))
        with h5py.File(os.path.join(directory, "history.h5"), "r") as f:
            approach, force, unloading = f["approach"][:], f["contact_force"][:], f["unloading"][:]
        loading = {round(w / w_c, 6): F for w, F, u in zip(approach, force, unloading) if u == 0}
        rows[n] = (s, loading)
    fits = json.loads(subprocess.run([oracle, str(R), str(E_star), str(Y), str(nu)] +
                                     [str(c * w_c) for c in check],
                                     capture_output=True, text=True, check=True).stdout)["points"]
    print(f"{'n':>3} {'h [um]':>7} {'cells':>6} {'dofs':>7} {'iter':>6} {'wall [s]':>8} " +
          " ".join(f"{'P/Pc@'+format(c, 'g'):>10} {'/JG-1':>7} {'/KE-1':>7}" for c in check) +
          f" {'w_r/w_c':>8} {'/Brake-1':>8} {'/a-rule-1':>9}")
    w_max = max(rows[levels[0]][0]["maximum_approach"], 1e-300)
    fit_max = json.loads(subprocess.run([oracle, str(R), str(E_star), str(Y), str(nu), str(w_max)],
                                        capture_output=True, text=True, check=True).stdout)["points"][0]
    series = {c: [] for c in check}
    residuals = []
    for n in levels:
        s, loading = rows[n]
        cells = []
        for c, fit in zip(check, fits):
            F = loading.get(round(c, 6), float("nan"))
            series[c].append(F)
            cells.append(f"{F/P_c:>10.4g} {(F/fit['jackson_green_load']-1)*100:>+6.2f}% "
                         f"{(F/fit['kogut_etsion_load']-1)*100:>+6.2f}%")
        w_r = s["residual_approach"]
        residuals.append(w_r)
        print(f"{n:>3} {math.sqrt(R * w_c) / float(n) * 1e6:>7.2f} "
              f"{s['cells']:>6} {s['dofs']:>7} {s['newton_iterations']:>6} {s['wall_time']:>8.1f} " +
              " ".join(cells) +
              f" {w_r/w_c:>8.4g} {(w_r/fit_max['residual_brake']-1)*100:>+7.2f}% "
              f"{(w_r/fit_max['residual_contact_radius']-1)*100:>+8.2f}%")
    print("fits: " + ", ".join(f"omega* = {c:g}: JG P/P_c = {fit['jackson_green_load']/P_c:.4g}, "
                               f"KE {fit['kogut_etsion_load']/P_c:.4g}" for c, fit in zip(check, fits)) +
          f"; residual at omega* = {w_max/w_c:.4g}: Brake {fit_max['residual_brake']/w_c:.4g} omega_c, "
          f"contact-radius rule {fit_max['residual_contact_radius']/w_c:.4g} omega_c")
    if len(levels) == 3:
        finest_first = lambda values: list(reversed(values))
        for c in check:
            p, g = gci(*finest_first(series[c]))
            print(f"P at omega* = {c:g}: observed order {p:.2f}, GCI_fine {g*100:.3f} %")
        p, g = gci(*finest_first(residuals))
        print(f"residual approach: observed order {p:.2f}, GCI_fine {g*100:.3f} %")
PY
