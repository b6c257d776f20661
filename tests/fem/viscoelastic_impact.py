"""Viscoelastic impacts (spec verification 4) and the Kuwabara-Kono trend.

Coarse mesh (100 um at the contact, 150 steps per contact time), so that
the fifteen runs take about half a minute on two cores (two runs at a time).

1. Default plate (the massive 0.35 x 0.35 m plate, absorbing far faces),
   both bodies Kelvin-Voigt steel with the study's tau_r = 1.147 us, V = 0.5, 1, 2 m/s, against elastic runs at
   the same V: restitution below the elastic one and falling with V; the
   lost kinetic energy 1 - e^2 equals dissipated + radiated + what is left
   in the bodies within 0.5 % of the initial energy; tau_r = 1e-12 s gives
   the elastic result back. The yield check: a yield strength of 1.5 GPa
   in the sphere is exceeded at 1 m/s (where and when), 5 GPa in the plate
   is not.
2. Kuwabara-Kono / Brilliantov: 1 - e ~ V^(1/5) for a viscoelastic sphere at
   small beta (tau_r / t_c ~ 0.01). To isolate the material dissipation:
   a small plate (0.1 x 0.05 m) with clamped far faces (no radiation: the
   waves come back during the contact, the elastic e is 0.9999), only the
   sphere viscous (tau_r = 1 us), the plate elastic, and the viscous
   restitution taken relative to the elastic run at the same V
   (e_visc = e / e_elastic). With the plate clamped, the lost kinetic
   energy is the dissipation (checked within 0.5 % of the initial energy).
"""
import math
from concurrent.futures import ThreadPoolExecutor
from fem_test_lib import *

binary, work, _ = parse_common_arguments()
checks = Checks()
COARSE = {"Mesh/Contact element size": 100e-6,
          "Time integration/Steps per contact time": 150}
TAU_STUDY = 1.147e-6


def kelvin_voigt(body, tau):
    return {f"{body}/Material model": "kelvin-voigt",
            f"{body}/Kelvin-voigt/Retardation time": tau}


def impact(name, settings):
    directory = f"{work}/viscoelastic_{name}"
    run(binary, directory, dict(COARSE, **settings))
    return summary(directory)


cases = {}
for v in (0.5, 1, 2):
    cases[f"elastic_v{v}"] = {"Scenario/Impact velocity": v}
    cases[f"kv_v{v}"] = dict({"Scenario/Impact velocity": v},
                             **kelvin_voigt("Sphere", TAU_STUDY), **kelvin_voigt("Plate", TAU_STUDY))
# The yield check rides on the elastic run at 1 m/s (no effect on its results).
cases["elastic_v1"].update({"Sphere/Yield strength": 1.5e9, "Plate/Yield strength": 5e9})
cases["kv_tau0_v1"] = dict({"Scenario/Impact velocity": 1},
                           **kelvin_voigt("Sphere", 1e-12), **kelvin_voigt("Plate", 1e-12))
KK_VELOCITIES = (0.5, 1, 2, 4)
for v in KK_VELOCITIES:
    clamped = {"Scenario/Impact velocity": v, "Scenario/Plate side": "clamped", "Scenario/Plate bottom": "clamped",
               "Scenario/Plate radius": 0.1, "Scenario/Plate thickness": 0.05,
               "Mesh/Maximum element size": 5e-3}
    cases[f"clamped_elastic_v{v}"] = clamped
    cases[f"clamped_kv_v{v}"] = dict(clamped, **kelvin_voigt("Sphere", 1e-6))
with ThreadPoolExecutor(max_workers=2) as pool:
    results = dict(zip(cases, pool.map(lambda item: impact(*item), cases.items())))

# 1. Default plate.
print("V [m/s]   e elastic   e Kelvin-Voigt   lost 1-e^2   dissipated   radiated   left in bodies   balance error")
previous = None
for v in (0.5, 1, 2):
    el, kv = results[f"elastic_v{v}"], results[f"kv_v{v}"]
    lost = 1 - kv["restitution"] ** 2
    left = kv["plate_energy_fraction"] + kv["sphere_vibration_energy_fraction"]
    accounted = kv["dissipated_energy_fraction"] + kv["radiated_energy_fraction"] + left
    print(f"{v:6.2f} {el['restitution']:11.6f} {kv['restitution']:14.6f} {lost*100:11.4f} % "
          f"{kv['dissipated_energy_fraction']*100:9.4f} % {kv['radiated_energy_fraction']*100:8.4f} % "
          f"{left*100:11.4f} % {kv['energy_error']*100:12.5f} %")
    checks.check(kv["restitution"] < el["restitution"], f"V = {v}: restitution below the elastic one")
    checks.check(abs(lost - accounted) < 0.005,
                 f"V = {v}: lost kinetic energy = dissipated + radiated + left in the bodies "
                 f"(difference {abs(lost - accounted)*100:.4f} % of the initial energy)")
    checks.check(kv["energy_error"] < 0.005, f"V = {v}: energy balance error < 0.5 %")
    if previous is not None:
        checks.check(kv["restitution"] < previous, f"V = {v}: restitution falls with V")
    previous = kv["restitution"]
e_el, e_0 = results["elastic_v1"]["restitution"], results["kv_tau0_v1"]["restitution"]
print(f"tau_r = 1e-12 s at 1 m/s: e = {e_0:.10f}, elastic {e_el:.10f} (difference {abs(e_0 - e_el):.2g})")
checks.check(abs(e_0 - e_el) < 1e-6, "tau_r -> 0 recovers the elastic restitution")
checks.check(abs(results["kv_tau0_v1"]["force_max"] / results["elastic_v1"]["force_max"] - 1) < 1e-6,
             "tau_r -> 0 recovers the elastic peak force")

# Yield check (elastic, 1 m/s; Hertz: p0 = 3.34 GPa, a = 0.714 mm, the von
# Mises maximum about 0.63 p0 at 0.48 a below each surface, on the axis).
s = results["elastic_v1"]
a_hertz = 0.7138e-3
print(f"von Mises max: sphere {s['von_mises_max_sphere']/1e9:.4f} GPa at t = {s['von_mises_max_sphere_time']*1e6:.2f} us, "
      f"(r, z) = ({s['von_mises_max_sphere_r']*1e3:.4f}, {s['von_mises_max_sphere_z']*1e3:.4f}) mm; "
      f"plate {s['von_mises_max_plate']/1e9:.4f} GPa at ({s['von_mises_max_plate_r']*1e3:.4f}, "
      f"{s['von_mises_max_plate_z']*1e3:.4f}) mm; sphere yield strength 1.5 GPa exceeded: "
      f"{s['yield_exceeded_sphere']} from t = {s['yield_time_sphere']*1e6:.2f} us at "
      f"({s['yield_r_sphere']*1e3:.4f}, {s['yield_z_sphere']*1e3:.4f}) mm; plate (5 GPa): {s['yield_exceeded_plate']}")
checks.check(s["yield_exceeded"] is True and s["yield_exceeded_sphere"] is True
             and s["yield_exceeded_plate"] is False, "yield: sphere (1.5 GPa) exceeded, plate (5 GPa) not")
checks.check(0 < s["yield_time_sphere"] < s["von_mises_max_sphere_time"] <= s["separation_time"]
             and s["yield_time_plate"] is None, "yield: first exceeded before the peak, during contact")
for body, sign in (("sphere", 1), ("plate", -1)):
    depth = sign * s[f"von_mises_max_{body}_z"] / a_hertz
    checks.check(0.3 < depth < 0.7 and s[f"von_mises_max_{body}_r"] < 0.2 * a_hertz
                 and 0.55 < s[f"von_mises_max_{body}"] / 3.34e9 < 0.7,
                 f"yield: {body} maximum on the axis at {depth:.3f} a below the surface, "
                 f"{s[f'von_mises_max_{body}']/3.34e9:.3f} p0")
checks.check(results["kv_v1"]["yield_exceeded"] is None, "yield: null without a yield strength")

# 2. Kuwabara-Kono trend.
print("clamped plate, viscous sphere (tau_r = 1 us):")
print("V [m/s]   e elastic   e viscous   1 - e/e_elastic   lost 1-e^2   dissipated")
xs, ys = [], []
for v in KK_VELOCITIES:
    el, kv = results[f"clamped_elastic_v{v}"], results[f"clamped_kv_v{v}"]
    loss = 1 - kv["restitution"] / el["restitution"]
    lost = 1 - kv["restitution"] ** 2
    print(f"{v:6.2f} {el['restitution']:11.6f} {kv['restitution']:11.6f} {loss:15.6f} "
          f"{lost*100:11.4f} % {kv['dissipated_energy_fraction']*100:9.4f} %")
    checks.check(abs(lost - kv["dissipated_energy_fraction"]) < 0.005,
                 f"V = {v}: dissipated energy = lost kinetic energy within 0.5 % "
                 f"({abs(lost - kv['dissipated_energy_fraction'])*100:.4f} %)")
    xs.append(math.log(v))
    ys.append(math.log(loss))
n = len(xs)
mx, my = sum(xs) / n, sum(ys) / n
p = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
local = [(ys[i + 1] - ys[i]) / (xs[i + 1] - xs[i]) for i in range(n - 1)]
print(f"1 - e ~ V^p: least-squares p = {p:.4f} (Kuwabara-Kono 0.2); between neighbouring V: "
      + ", ".join(f"{q:.4f}" for q in local))
checks.check(abs(p - 0.2) <= 0.05, "p within 0.2 +- 0.05")
checks.finish()
