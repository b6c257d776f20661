"""Smooth contact-force histories (spec verification 6).

A small Kelvin-Voigt case (the study's material, tau_r = 1.147 us in both
bodies, 35 um contact elements as in the study, a small plate to keep it
cheap) at 1 and 4 m/s with the default scheme (bdf2): the step-to-step
oscillation of the contact force max |F_i - (F_{i-1} + F_{i+1})/2| inside
the contact (5 steps at each end excluded) stays within 0.3 % of the peak
force, and after the first zero-force step that follows the peak no force
exceeds 0.1 % of the peak. The same case with the average-acceleration
Newmark rule shows what the check catches (an oscillation of several per
cent), and elastic and generalised-Maxwell bodies stay as clean.
The figures are computed here from history.h5 and compared with the
summary's force_oscillation and force_after_release.
"""
from fem_test_lib import *

binary, work, _ = parse_common_arguments()
checks = Checks()
SMALL = {"Mesh/Contact element size": 35e-6,
         "Scenario/Plate radius": 0.05, "Scenario/Plate thickness": 0.05,
         "Mesh/Maximum element size": 5e-3}
TAU = 1.147e-6


def kelvin_voigt():
    settings = {}
    for body in ("Sphere", "Plate"):
        settings.update({f"{body}/Material model": "kelvin-voigt",
                         f"{body}/Kelvin-voigt/Retardation time": TAU})
    return settings


def measure(force):
    """(oscillation, after release) as fractions of the peak force."""
    on = [i for i, f in enumerate(force) if f > 0]
    first = on[0]
    last = first
    while last + 1 < len(force) and force[last + 1] > 0:
        last += 1
    peak = max(force)
    inner = range(first + 6, last - 5)
    oscillation = max(abs(force[i] - 0.5 * (force[i - 1] + force[i + 1])) for i in inner) / peak
    zero = next(i for i in range(int(max(range(len(force)), key=lambda i: force[i])), len(force))
                if force[i] <= 0)
    return oscillation, max(force[zero:]) / peak


cases = {"kelvin-voigt 1 m/s": (dict(SMALL, **kelvin_voigt(), **{"Scenario/Impact velocity": 1}), True),
         "kelvin-voigt 4 m/s": (dict(SMALL, **kelvin_voigt(), **{"Scenario/Impact velocity": 4}), True),
         "elastic 2 m/s": (dict(SMALL, **{"Scenario/Impact velocity": 2}), True),
         "maxwell 2 m/s": (dict(SMALL, **maxwell_bodies(), **{"Scenario/Impact velocity": 2}), True),
         "kelvin-voigt 1 m/s, newmark": (dict(SMALL, **kelvin_voigt(), **{"Scenario/Impact velocity": 1,
                                                                         "Time integration/Scheme": "newmark"}), False)}
for name, (settings, smooth) in cases.items():
    directory = f"{work}/smoothness_" + name.replace(" ", "_").replace("/", "").replace(",", "")
    run(binary, directory, settings)
    (force,) = history(directory, "contact_force")
    oscillation, after = measure(list(force))
    s = summary(directory)
    print(f"{name}: step-to-step oscillation {oscillation:.3%} of the peak force, "
          f"after release {after:.3%} (summary: {s['force_oscillation']:.3%}, "
          f"{s['force_after_release']:.3%}); e = {s['restitution']:.5f}")
    checks.check(abs(oscillation - s["force_oscillation"]) < 1e-12 and
                 abs(after - s["force_after_release"]) < 1e-12,
                 f"{name}: the summary reports the same figures")
    if smooth:
        checks.check(oscillation <= 3e-3, f"{name}: oscillation <= 0.3 % of the peak")
        checks.check(after <= 1e-3, f"{name}: no force above 0.1 % of the peak after release")
    else:
        checks.check(oscillation > 3e-2, f"{name}: the check detects the Newmark oscillation (> 3 %)")
checks.finish()
