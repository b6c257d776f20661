"""Spec verification 1: quasi-static press of the sphere into a clamped plate.

Contact radius within one element of Hertz's a = (3 F R / (4 E*))^(1/3) and
pressure within 3 % of p0 sqrt(1 - r^2/a^2) over r < 0.9 a (error relative to
p0; the largest error relative to the local Hertz value is printed too), at
two load levels. F is the contact force the model transmits.
"""
import math
from fem_test_lib import *

binary, work, _ = parse_common_arguments()
checks = Checks()
element = 25e-6
for load in (1000.0, 3000.0):
    directory = f"{work}/static_{int(load)}"
    run(binary, directory, {
        "Scenario/Analysis": "static press",
        "Scenario/Static force": load,
        "Scenario/Plate side": "clamped", "Scenario/Plate bottom": "clamped",
        "Mesh/Contact element size": element,
        "Mesh/Uniform zone radius": 1e-3,
    })
    radius, pressure, force, contact_radius = history(
        directory, "contact_node_radius", "pressure_at_force_max",
        "contact_force", "contact_radius")
    F = force[-1]
    a = (3 * F * RADIUS / (4 * EFFECTIVE_MODULUS)) ** (1 / 3)
    p0 = 3 * F / (2 * math.pi * a * a)
    worst_p0, worst_local = 0.0, 0.0
    for r, p in zip(radius, pressure):
        if r < 0.9 * a:
            hertz = p0 * math.sqrt(1 - (r / a) ** 2)
            worst_p0 = max(worst_p0, abs(p - hertz) / p0)
            worst_local = max(worst_local, abs(p - hertz) / hertz)
    print(f"F = {F:.1f} N: contact radius {contact_radius[-1]*1e3:.4f} mm, "
          f"Hertz {a*1e3:.4f} mm, element {element*1e3:.3f} mm; "
          f"pressure error over r < 0.9a: {worst_p0*100:.2f} % of p0 = "
          f"{p0/1e9:.3f} GPa (max {worst_local*100:.2f} % of the local value)")
    checks.check(abs(contact_radius[-1] - a) <= element,
                 f"F = {load:.0f} N: contact radius within one element")
    checks.check(worst_p0 < 0.03, f"F = {load:.0f} N: pressure within 3 % of p0")
checks.finish()
