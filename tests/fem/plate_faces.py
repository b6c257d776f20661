"""Conditions per face of the plate (Scenario/Plate side, Plate bottom).

- A free plate (side and bottom free) conserves the axial momentum of sphere
  and plate together: no external force acts on the pair (BDF2 conserves
  linear momentum exactly when the contact forces balance; the bound 1e-8 is
  the linear solver's precision, far below the time-discretisation error).
  The plate takes the momentum the sphere loses, (1 + e) m V.
- A clamped plate does not move at its clamped faces (the mean displacement
  of the bottom is exactly zero), and the pair's momentum is not conserved.
- A plate lying on an elastic foundation ('support', stiffness k per area)
  and pressed statically with F: equilibrium of the plate says the foundation
  carries F, so the mean bottom displacement is F / (k pi Rp^2) (up to the
  static press's regularising springs, separated below).
- Bad input: the replaced entry Far boundary, a support without stiffness,
  a static press on a plate nothing holds.
"""
import math
from fem_test_lib import *

binary, work, _ = parse_common_arguments()
checks = Checks()
coarse = {"Mesh/Contact element size": 100e-6, "Mesh/Maximum element size": 10e-3,
          "Time integration/Steps per contact time": 100,
          "Scenario/Plate thickness": 0.01, "Scenario/Plate radius": 0.1}


def momenta(directory):
    mass = summary(directory)["sphere_mass"]
    v, p_plate = history(directory, "sphere_velocity", "plate_momentum")
    return mass, mass * v + p_plate, p_plate


# Free plate: momentum of the pair.
free = f"{work}/faces_free"
run(binary, free, dict(coarse, **{"Scenario/Plate side": "free", "Scenario/Plate bottom": "free"}))
mass, pair, p_plate = momenta(free)
e = summary(free)["restitution"]
drift = max(abs(p - pair[0]) for p in pair) / pair[0]
print(f"free 10 mm plate: e = {e:.5f}, pair momentum drift {drift:.2e} of m V, "
      f"plate momentum at the end {p_plate[-1] / (mass * 1.0):.5f} m V (1 + e = {1 + e:.5f})")
checks.check(drift < 1e-8, "free plate: momentum of sphere + plate conserved within 1e-8")
# 1e-5: the discrete sphere starts at 0.9999988 V (its first sample).
checks.check(abs(p_plate[-1] / mass - (1 + e)) < 1e-5,
             "free plate: the plate carries away (1 + e) m V")
checks.check(e < 0.9, "free 10 mm plate: restitution below 0.9 (flexural waves)")

# Clamped plate: the bottom does not move, momentum goes into the support.
clamped = f"{work}/faces_clamped"
run(binary, clamped, dict(coarse, **{"Scenario/Plate side": "clamped", "Scenario/Plate bottom": "clamped"}))
(bottom,) = history(clamped, "plate_displacement")
mass, pair, _ = momenta(clamped)
e = summary(clamped)["restitution"]
print(f"clamped 10 mm plate: e = {e:.5f}, largest |mean bottom displacement| "
      f"{max(abs(bottom)):.1e} m, pair momentum at the end {pair[-1] / pair[0]:.5f} m V")
checks.check(max(abs(bottom)) == 0.0, "clamped plate: the bottom does not move")
checks.check(pair[-1] / pair[0] < 0.5, "clamped plate: the support takes the momentum")

# Plate on an elastic foundation, pressed statically. The static press ties
# every degree of freedom to the ground by soft regularising springs (one step
# from rest, Parameters::time_step); those on the plate carry a small share of
# the load, a stiffness s per area in parallel with the foundation, the same
# for any k. So F / (A u_bottom) = k + s with one s for two foundations: the
# foundation itself is exact.
load, Rp = 1000.0, 0.1
measured = {}
for k in (1e10, 1e11):
    support = f"{work}/faces_support_{k:g}"
    run(binary, support, dict(coarse, **{"Scenario/Analysis": "static press",
                                         "Scenario/Static force": load,
                                         "Scenario/Plate side": "free",
                                         "Scenario/Plate bottom": "support",
                                         "Scenario/Support stiffness": k}))
    bottom, force = history(support, "plate_displacement", "contact_force")
    measured[k] = force[-1] / (math.pi * Rp ** 2 * bottom[-1]) - k
    print(f"plate on a foundation k = {k:g} N/m^3 under F = {force[-1]:.2f} N: mean bottom "
          f"displacement {bottom[-1]:.6e} m, F / (A u) - k = {measured[k]:.5e} N/m^3")
s1, s2 = measured[1e10], measured[1e11]
checks.check(abs(s2 / s1 - 1) < 0.01 and 0 < s1 < 0.01 * 1e10,
             "support: F / (A u_bottom) = k + s, s the same for k = 1e10 and 1e11 "
             "(within 1 %) and below 1 % of k")

# Bad input: refused with the entry named.
for settings, named in (({"Scenario/Far boundary": "absorbing"}, "Plate side"),
                        ({"Scenario/Plate bottom": "support"}, "Support stiffness"),
                        ({"Scenario/Analysis": "static press", "Scenario/Static force": 100,
                          "Scenario/Plate side": "free", "Scenario/Plate bottom": "absorbing"},
                         "Plate bottom"),
                        ({"Scenario/Plate side": "support"}, "Plate side")):
    directory = f"{work}/faces_bad"
    code, output = run(binary, directory, dict(coarse, **settings), expect_success=False)
    checks.check(code != 0 and named in output and not os.path.exists(f"{directory}/summary.json"),
                 f"refused {settings} naming '{named}' (exit {code})")
checks.finish()
