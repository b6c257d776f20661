"""The anchor case of the elastic-plastic impact, fem/scenarios/plastic_on_rigid.prm
as shipped (elastic-perfectly-plastic AISI 52100 ball on the rigid flat,
nu = 0.3, V = 1 m/s = 4.55 V_y), against Thornton's law (J. Appl. Mech. 64
(1997) 383, computed by `impact-reduced plastic --model thornton`) and
against what an elastic-plastic impact must look like:
  - the contact pressure is capped by plasticity: its largest value lies
    above Thornton's limiting pressure p_y = 1.6 Y (Johnson's first yield,
    Contact Mechanics 1985 sec. 4.2: beyond it the plastic zone grows and
    carries more) and below 3 Y (the fully plastic mean pressure, the
    hardness of a perfectly plastic solid, Johnson sec. 6.2);
  - hence, the FEM contact carrying more than Thornton's truncated pressure,
    the FEM's peak force exceeds Thornton's, its peak approach, permanent
    approach and energy loss are smaller, its restitution larger: the
    direction in which a pressure cap of 1.6 Y errs;
  - the loop: a Hertz-like unloading branch, F ~ (x - x_p)^m with m fitted
    in [1.3, 1.7] (Hertz 1.5), which ends at the permanent approach x_p
    (zero force below it, none after release), x_p between 0 and x_max;
  - energy: the lost kinetic energy 1 - e^2 is the plastic work plus the
    elastic vibration left in the sphere, to within 5e-4 of the impact
    energy (BDF2's numerical dissipation: 1.7e-4 measured);
"""
import csv
import io
import math
import subprocess
import time
from fem_test_lib import *
import numpy as np

binary, work, _ = parse_common_arguments()
reduced = sys.argv[4]
checks = Checks()
scenario = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "fem",
                        "scenarios", "plastic_on_rigid.prm")
R, E, NU, RHO, Y, V = 0.01452, 2e11, 0.3, 7810, 2.03e9, 1.0   # the scenario's constants

directory = f"{work}/plastic_on_rigid"
if os.path.isdir(directory):
    shutil.rmtree(directory)
start = time.time()
result = subprocess.run([binary, scenario, "--set", f"Output/Directory={directory}"],
                        capture_output=True, text=True)
wall = time.time() - start
if result.returncode != 0:
    print(result.stdout + result.stderr)
    sys.exit("FAIL: impact-fem exited with " + str(result.returncode))
s = summary(directory)
x, force, pressure = history(directory, "approach", "contact_force", "max_pressure")

text = subprocess.run([reduced, "plastic", "--model", "thornton", "--radius", str(R),
                       "--density", str(RHO), "--modulus", str(E), "--poisson", str(NU),
                       "--flat", "rigid", "--yield-strength", str(Y),
                       "--velocity", str(V), "--format", "csv"],
                      check=True, capture_output=True, text=True).stdout
t = {k: float(v) for k, v in next(csv.DictReader(io.StringIO(text))).items()}
print(f"V/V_y = {t['velocity_ratio']:.3f}; wall {wall:.1f} s")
print(f"{'':<22}{'FEM':>12}{'Thornton':>12}")
for label, fem_value, th_value in (
        ("restitution", s["restitution"], t["restitution"]),
        ("peak force [N]", s["force_max"], t["force_max"]),
        ("peak approach [um]", s["approach_max"] * 1e6, t["approach_max"] * 1e6),
        ("permanent appr. [um]", s["permanent_approach"] * 1e6, t["residual_approach"] * 1e6),
        ("contact time [us]", s["contact_time"] * 1e6, t["contact_time"] * 1e6),
        ("energy lost [%]", s["lost_energy_fraction"] * 100, (1 - t["restitution"] ** 2) * 100)):
    print(f"{label:<22}{fem_value:>12.5g}{th_value:>12.5g}")

p_max = pressure.max()
print(f"largest contact pressure {p_max / Y:.3f} Y (p_y = 1.6 Y)")
checks.check(s["dent_radius"] is None and s["max_accumulated_plastic_strain_plate"] is None
             and s["sphere_dent_radius"] > 0,
             "no plate body: its dent radius and plastic strain are null; the sphere's dent > 0")
checks.check(1.6 * Y < p_max < 3 * Y, "contact pressure capped between 1.6 Y and 3 Y")
checks.check(s["force_max"] > t["force_max"], "peak force above Thornton's (pressure above 1.6 Y)")
checks.check(s["approach_max"] < t["approach_max"], "peak approach below Thornton's")
checks.check(0 < s["permanent_approach"] < t["residual_approach"],
             "permanent approach > 0 and below Thornton's")
checks.check(t["restitution"] < s["restitution"] < 1, "restitution between Thornton's and 1")

i = int(np.argmax(force))
x_p = s["permanent_approach"]
after = np.arange(len(force)) > i
branch = after & (force > 0.05 * force[i])
m, _ = np.polyfit(np.log(x[branch] - x_p), np.log(force[branch]), 1)
below = after & (x < x_p - 1e-3 * s["approach_max"])
print(f"unloading branch F ~ (x - x_p)^{m:.3f} from the peak to 5 % of it; largest force after "
      f"the approach fell below x_p: {np.max(force[below], initial=0):.3g} N; force after release "
      f"{s['force_after_release']:.3g} N")
checks.check(1.3 <= m <= 1.7, "Hertz-like unloading branch (exponent in [1.3, 1.7])")
checks.check(np.all(force[below] == 0) and s["force_after_release"] == 0,
             "unloading ends at the permanent approach: no force below x_p, none after release")
checks.check(0 < x_p < s["approach_max"], "0 < permanent approach < peak approach")

lost = 1 - s["restitution"] ** 2
accounted = s["plastic_work_fraction"] + s["sphere_vibration_energy_fraction"]
print(f"1 - e^2 = {lost:.6f}, plastic work + sphere vibration = {accounted:.6f} of the impact energy")
checks.check(abs(lost - accounted) < 5e-4, "1 - e^2 = plastic work + vibration (5e-4)")
checks.finish()
