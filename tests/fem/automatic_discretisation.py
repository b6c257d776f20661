"""A mesh and a time step that size themselves ("auto", the default of Mesh/Contact element
size, Uniform zone radius, Contact surface radius and Time integration/Steps per contact time):
the sizes follow the expected contact radius a and contact time of the scenario (a / 20, 1.5 a,
2.5 a at most R/2, 300 steps per expected contact time; when a body is expected to yield a / 30
and the contact surfaces' cells refined three times more, kept by the coarser levels of --verify),
Hertz's for elastic bodies and Jackson & Green's elastic-plastic impact when a body can yield;
each run says what it chose (log and summary.json, its history's attributes carry the numbers);
a value the scenario sets wins; a contact too large for the sphere is refused, naming the
entries.

The references are computed here, independently of the program: Hertz's impact in closed form,
and the Jackson-Green (2005) loading fit integrated numerically (Simpson) to the approach that
absorbs the impact energy, with its contact radius a = sqrt(R w) (w* / 1.9)^(B/2); the contact
time of the Jackson-Green impact is compared with `impact-reduced plastic --model
jackson-green`, which the program's estimate must equal (the same law, the wiring checked).
The runs stop after a few steps (Maximum time): the discretisation, not the impact, is tested.
argv: impact-fem, work directory, mpiexec, impact-reduced."""
import json
import math
import os
import subprocess
import sys

import h5py

from fem_test_lib import Checks, parse_common_arguments, run, summary

binary, work, mpiexec = parse_common_arguments()
reduced = sys.argv[4]
checks = Checks()
AUTO = {"Mesh/Contact element size": "auto", "Mesh/Uniform zone radius": "auto",
        "Mesh/Contact surface radius": "auto", "Mesh/Contact surface refinements": "auto",
        "Time integration/Steps per contact time": "auto"}
SHORT = {"Time integration/Maximum time": 2e-6}


def close(a, b, tol):
    return abs(a - b) <= tol * abs(b)


def entries(directory):
    return summary(directory)["discretisation"]["entries"]


# 1. Elastic steel bodies (steel_bodies.prm: E 200 GPa, nu 0.25, rho 7800), R = 14.52 mm, 1 m/s:
# Hertz's impact.
R, E, NU, RHO, V = 0.01452, 2e11, 0.25, 7800, 1.0
m = RHO * 4 / 3 * math.pi * R ** 3
e_star = E / (2 * (1 - NU ** 2))
k = 4 / 3 * e_star * math.sqrt(R)
x_max = (5 * m * V ** 2 / (4 * k)) ** 0.4
a_hertz = math.sqrt(R * x_max)
directory = os.path.join(work, "auto_elastic")
code, log = run(binary, directory, {**AUTO, **SHORT})
s = summary(directory)
d = s["discretisation"]
expected = d["expected_contact"]
checks.check(expected["law"] == "Hertz", f"elastic bodies: the estimate is Hertz's ({expected['law']})")
checks.check(close(expected["contact_radius"], a_hertz, 1e-12),
             f"Hertz contact radius {expected['contact_radius']:.9e} m = sqrt(R x_max) "
             f"{a_hertz:.9e} m")
want = {"Mesh/Contact element size": a_hertz / 20, "Mesh/Uniform zone radius": 1.5 * a_hertz,
        "Mesh/Contact surface radius": 2.5 * a_hertz,
        "Mesh/Contact surface refinements": 0,  # nothing can yield
        "Time integration/Steps per contact time": 300}
for path, value in want.items():
    got = d["entries"][path]
    checks.check(got["origin"] == "auto" and close(got["value"], value, 1e-12),
                 f"{path} = {got['value']:.6e} ({got['origin']}), rule {value:.6e}")
checks.check("Mesh/Contact element size = " in log
             and "(auto: a / 20, a / 30 if a body is expected to yield)" in log,
             "the log says what was chosen and why")
with h5py.File(os.path.join(directory, "history.h5"), "r") as f:
    attribute = f.attrs.get("Mesh/Contact element size")
    attribute = attribute.decode() if isinstance(attribute, bytes) else attribute
checks.check(attribute is not None and close(float(attribute), a_hertz / 20, 1e-12),
             f"history.h5 attribute Mesh/Contact element size = {attribute} (a number, not 'auto')")

# 2. An explicit value wins; the others stay automatic.
directory = os.path.join(work, "auto_explicit")
run(binary, directory, {**AUTO, **SHORT, "Mesh/Contact element size": 1e-4,
                        "Mesh/Contact surface refinements": 1})
got = entries(directory)
checks.check(got["Mesh/Contact element size"] == {"origin": "scenario", "unit": "m", "value": 1e-4},
             f"Contact element size set by the scenario: {got['Mesh/Contact element size']}")
checks.check(got["Mesh/Contact surface refinements"] == {"origin": "scenario", "unit": "1",
                                                          "value": 1},
             f"Contact surface refinements set by the scenario: "
             f"{got['Mesh/Contact surface refinements']}")
# One refinement of the contact surfaces' cells halves the contact nodes' spacing: twice as many.
directory_0 = os.path.join(work, "auto_explicit_0")
run(binary, directory_0, {**AUTO, **SHORT, "Mesh/Contact element size": 1e-4,
                          "Mesh/Contact surface refinements": 0})
n0, n1 = summary(directory_0)["contact_nodes"], summary(directory)["contact_nodes"]
checks.check(n1 == 2 * n0 - 1,
             f"contact nodes {n1} with one surface refinement, {n0} without (2 n - 1 expected)")
for bad in ("1.5", "7", "-1", "many"):
    directory = os.path.join(work, "auto_bad_surface_refinements")
    code, log = run(binary, directory, {**AUTO, **SHORT, "Mesh/Contact surface refinements": bad},
                    expect_success=False)
    checks.check(code == 2 and "Mesh/Contact surface refinements" in log
                 and not os.path.exists(os.path.join(directory, "summary.json")),
                 f"Contact surface refinements = {bad}: exit {code}, refused naming the entry")
checks.check(got["Mesh/Contact surface radius"]["origin"] == "auto"
             and close(got["Mesh/Contact surface radius"]["value"], 2.5 * a_hertz, 1e-12),
             "the contact surface radius stays automatic")

# 3. A stainless ball (AISI 304) on an aluminium plate (6061-T6), R = 5 mm, at 3 m/s: far above
# yield. The sphere has the lower C(nu) Y, so it yields first.
R3, V3 = 0.005, 3.0
E1, NU1, RHO1, Y1 = 1.93e11, 0.29, 8000, 2.15e8  # the material table's AISI 304
E2, NU2 = 6.89e10, 0.33  # 6061-T6
m3 = RHO1 * 4 / 3 * math.pi * R3 ** 3
e3 = 1 / ((1 - NU1 ** 2) / E1 + (1 - NU2 ** 2) / E2)
C = 1.295 * math.exp(0.736 * NU1)
w_c = (math.pi * C * Y1 / (2 * e3)) ** 2 * R3
P_c = 4 / 3 * (R3 / e3) ** 2 * (C * math.pi * Y1 / 2) ** 3
B = 0.14 * math.exp(23 * Y1 / e3)


def jg_radius(w):
    ws = w / w_c
    return math.sqrt(R3 * w) * (1 if ws <= 1.9 else (ws / 1.9) ** (B / 2))


def jg_load(w):
    ws = w / w_c
    if ws <= 1.9:
        return P_c * ws ** 1.5
    hg = Y1 * 2.84 * (1 - math.exp(-0.82 * (jg_radius(w) / R3) ** -0.7))
    return P_c * (math.exp(-ws ** (5 / 12) / 4) * ws ** 1.5
                  + 4 * hg / (C * Y1) * (1 - math.exp(-ws ** (5 / 9) / 25)) * ws)


def simpson(f, a, b, n=4000):
    h = (b - a) / n
    return h / 3 * (f(a) + f(b) + sum((4 if i % 2 else 2) * f(a + i * h) for i in range(1, n)))


def work_to(w):
    t = 1.9 * w_c
    if w <= t:
        return simpson(jg_load, 0, w)
    return simpson(jg_load, 0, t) + simpson(jg_load, t, w)


energy = 0.5 * m3 * V3 ** 2
lo, hi = 0.0, R3 / 10
for _ in range(60):
    mid = 0.5 * (lo + hi)
    lo, hi = (mid, hi) if work_to(mid) < energy else (lo, mid)
w_max = 0.5 * (lo + hi)
a_jg = jg_radius(w_max)
cli = json.loads(subprocess.run(
    [reduced, "plastic", "--model", "jackson-green", "--radius", str(R3), "--mass", repr(m3),
     "--modulus", str(E1), "--poisson", str(NU1), "--flat-modulus", str(E2),
     "--flat-poisson", str(NU2), "--yield-strength", str(Y1), "--velocity", str(V3)],
    check=True, capture_output=True, text=True).stdout)
t_jg = cli["impacts"][0]["contact_time"]
t_hertz = 2.9432 * (5 * m3 * V3 ** 2 / (4 * 4 / 3 * e3 * math.sqrt(R3))) ** 0.4 / V3

plastic = {"Scenario/Sphere radius": R3, "Scenario/Impact velocity": V3,
           "Sphere/Material model": "elastic-plastic", "Sphere/Material": "AISI 304",
           "Plate/Material model": "elastic-plastic", "Plate/Material": "6061-T6",
           # the table's constants, not steel_bodies.prm's
           "Sphere/Elastic-plastic/Young's modulus": E1, "Sphere/Elastic-plastic/Poisson's ratio": NU1,
           "Sphere/Elastic-plastic/Density": RHO1, "Sphere/Yield strength": Y1,
           "Plate/Elastic-plastic/Young's modulus": E2, "Plate/Elastic-plastic/Poisson's ratio": NU2,
           "Plate/Elastic-plastic/Density": 2700, "Plate/Yield strength": 2.76e8}
directory = os.path.join(work, "auto_plastic")
code, log = run(binary, directory, {**AUTO, **SHORT, **plastic})
d = summary(directory)["discretisation"]
expected = d["expected_contact"]
checks.check(expected["law"] == "Jackson-Green" and expected.get("yielding_body") == "sphere",
             f"a body can yield: Jackson-Green's estimate, the sphere yielding first "
             f"({expected['law']}, {expected.get('yielding_body')})")
checks.check(close(expected["approach_max"], w_max, 1e-6),
             f"approach {expected['approach_max']:.9e} m, independent Jackson-Green {w_max:.9e} m")
checks.check(close(expected["contact_radius"], a_jg, 1e-6),
             f"contact radius {expected['contact_radius']:.9e} m, independent {a_jg:.9e} m "
             f"(Hertz's at the same energy would be {math.sqrt(R3 * (5 * m3 * V3 ** 2 / (4 * 4 / 3 * e3 * math.sqrt(R3))) ** 0.4):.4e} m)")
checks.check(close(expected["contact_time"], t_jg, 1e-12),
             f"contact time {expected['contact_time']:.9e} s = impact-reduced's {t_jg:.9e} s")
checks.check(close(expected["velocity_ratio"], cli["impacts"][0]["velocity_ratio"], 1e-12),
             f"V/V_y {expected['velocity_ratio']:.1f} = impact-reduced's")
got = d["entries"]
for path, value in {"Mesh/Contact element size": a_jg / 30,  # a body yields
                    "Mesh/Uniform zone radius": 1.5 * a_jg,
                    "Mesh/Contact surface radius": 2.5 * a_jg,
                    # V/V_y > 1: a fully plastic contact, its nodes every a / 240
                    "Mesh/Contact surface refinements": 3,
                    "Time integration/Steps per contact time": 300 * t_hertz / t_jg}.items():
    checks.check(close(got[path]["value"], value, 1e-6),
                 f"{path} = {got[path]['value']:.6e}, rule {value:.6e}")

# A contact element size the scenario sets is its own mesh: the automatic surface refinement
# stays 0 although a body yields.
directory = os.path.join(work, "auto_plastic_explicit_size")
run(binary, directory, {**AUTO, **SHORT, **plastic, "Mesh/Contact element size": 2e-5})
got = entries(directory)["Mesh/Contact surface refinements"]
checks.check({k: got[k] for k in ("origin", "unit", "value")}
             == {"origin": "auto", "unit": "1", "value": 0}
             and got["rule"].startswith("3 if a body is expected to yield"),
             f"explicit contact element size, a body yielding: Contact surface refinements {got}")

# Verified, the coarser levels keep the fine level's contact surface refinements: their contact
# element sizes are given (r and r^2 times the fine one), and "auto" refines only a mesh the rule
# sized itself, so left "auto" they lost them (contact nodes 321, 29, 21 on 304 on 6061 at 2 m/s:
# an oscillatory GCI of F_max of 16 %). Each level's contact nodes lie r^k times the fine level's
# apart: about 1.5 times fewer per level on the same contact surface.
directory = os.path.join(work, "auto_plastic_verified")
run(binary, directory, {**AUTO, **SHORT, **plastic}, extra=("--verify",))
levels = [summary(directory)] + [summary(os.path.join(directory, "verification", f"level{k}"))
                                 for k in (1, 2)]
refinements = [s["discretisation"]["entries"]["Mesh/Contact surface refinements"]["value"]
               for s in levels]
nodes = [s["contact_nodes"] for s in levels]
checks.check(refinements == [3, 3, 3],
             f"verified: Contact surface refinements of the fine, medium, coarse levels {refinements}")
checks.check(all(1.3 < nodes[k] / nodes[k + 1] < 1.7 for k in (0, 1)),
             f"verified: contact nodes {nodes}, about 1.5 times fewer per level")

# 4. A contact that does not fit on the sphere: soft copper hit at 60 m/s by a 1 mm ball.
directory = os.path.join(work, "auto_too_large")
code, log = run(binary, directory, {**AUTO, **plastic, "Scenario/Sphere radius": 1e-3,
                                    "Scenario/Impact velocity": 60, "Plate/Material": "C11000 annealed",
                                    "Plate/Elastic-plastic/Young's modulus": 1.17e11,
                                    "Plate/Elastic-plastic/Poisson's ratio": 0.34,
                                    "Plate/Elastic-plastic/Density": 8940,
                                    "Plate/Yield strength": 8.5e7}, expect_success=False)
checks.check(code == 2 and "does not fit on the sphere" in log and "Mesh/Contact element" in log
             and not os.path.exists(os.path.join(directory, "summary.json")),
             f"a contact too large for the sphere: exit {code}, refused naming the entries, no output")

checks.finish()
