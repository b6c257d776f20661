"""The specimen analysis (`Scenario/Analysis = specimen`, a finite-element
cylinder) with the elastic-plastic material under the `axial strain path`
loading (axial displacement of the top face, bottom on rollers, side free:
uniaxial stress) reproduces the uniaxial flow curve:
  - linear hardening: sigma = E eps up to Y/E, then Y + E_t (eps - Y/E),
    E_t = E H / (E + H); elastic unloading (slope E, eps_p frozen); the
    accumulated plastic strain eps - sigma/E; plastic work
    Y eps_p + H eps_p^2 / 2 (closed form of int sigma d eps_p);
  - perfectly plastic (H = 0): sigma = Y after yield;
  - Johnson-Cook without the rate term: sigma solves
    eps = sigma / E + ((sigma - A) / B)^(1/n), solved here by bisection for
    each prescribed strain (Johnson & Cook 1983's 1006 steel: A = 350 MPa,
    B = 275 MPa, n = 0.36);
  - Johnson-Cook with the rate term (C = 0.022, reference rate 1 /s, strain
    rate 100 /s): the uniaxial backward-Euler answer of the flow rule,
    sigma = (A + B eps_p^n)(1 + C ln(max(d eps_p / dt, 1 /s) / 1 /s)) with
    eps_p = eps - sigma / E, computed here step by step by bisection on the
    scalar equation;
and in every case the lateral stresses vanish and the specimen stays
homogeneous (every quadrature point within 1e-9 of the mean). The 3D radial
return, the consistent tangent and the Newton iteration of the finite-element
specimen meet a scalar uniaxial calculation that shares none of their code.
An `axial strain path` at a material point is refused with the loading named.
"""
import math
from fem_test_lib import *
import numpy as np

binary, work, _ = parse_common_arguments()
checks = Checks()

E, NU = 2e11, 0.3
RAMP = 1e-4


def specimen(name, path, steps_per_segment, law):
    directory = f"{work}/plastic_specimen_{name}"
    settings = {"Scenario/Analysis": "specimen",
                "Sphere/Material model": "elastic-plastic",
                "Sphere/Elastic-plastic/Young's modulus": E,
                "Sphere/Elastic-plastic/Poisson's ratio": NU,
                "Material point/Loading": "axial strain path",
                "Material point/Axial strain path": ", ".join(repr(float(p)) for p in path),
                "Material point/Ramp time": RAMP,
                "Material point/Duration": RAMP * len(path),
                "Material point/Time step": RAMP / steps_per_segment}
    # The yield strength is the body's (one per body), the rest the model's.
    settings.update({(f"Sphere/{k}" if k == "Yield strength" else f"Sphere/Elastic-plastic/{k}"): v
                     for k, v in law.items()})
    code, output = run(binary, directory, settings)
    print(output.strip().splitlines()[-1])
    names = ["time", "strain_zz", "stress_rr", "stress_zz", "stress_thetatheta", "stress_rz",
             "inhomogeneity", "accumulated_plastic_strain", "plastic_work", "newton_iterations"]
    return dict(zip(names, history(directory, *names)))


def common_checks(name, h, scale):
    lateral = max(np.max(np.abs(h["stress_rr"])), np.max(np.abs(h["stress_thetatheta"])),
                  np.max(np.abs(h["stress_rz"]))) / scale
    print(f"  {name}: largest lateral stress {lateral:.1e} of the yield strength, inhomogeneity "
          f"{h['inhomogeneity'].max():.1e}, Newton iterations per step max "
          f"{h['newton_iterations'].max():.0f}")
    checks.check(lateral < 1e-9, f"{name}: uniaxial stress (lateral stresses < 1e-9 Y)")
    checks.check(h["inhomogeneity"].max() < 1e-9, f"{name}: homogeneous (inhomogeneity < 1e-9)")
    checks.check(h["newton_iterations"][1:].max() <= 10, f"{name}: Newton converged in <= 10 iterations")


# ---- linear hardening, loading then elastic unloading ----
Y, H = 4e8, 2e10
Et = E * H / (E + H)
eps_y = Y / E
path = [5 * eps_y, 3 * eps_y]   # load to 5 eps_y (1.36 Y), unload by 2 eps_y to -0.64 Y: elastic
h = specimen("linear", path, 40, {"Yield strength": Y, "Hardening law": "linear",
                                   "Hardening modulus": H})
eps, sigma = h["strain_zz"], h["stress_zz"]
loading = h["time"] <= RAMP * (1 + 1e-12)
expected = np.where(eps <= eps_y, E * eps, Y + Et * (eps - eps_y))
sigma_max = Y + Et * (path[0] - eps_y)
expected = np.where(loading, expected, sigma_max - E * (path[0] - eps))
err = np.max(np.abs(sigma - expected)) / Y
eps_p_expected = np.where(loading, np.maximum(eps - expected / E, 0), path[0] - sigma_max / E)
err_p = np.max(np.abs(h["accumulated_plastic_strain"] - eps_p_expected)) / eps_y
ep_end = path[0] - sigma_max / E
work_expected = (Y * ep_end + H * ep_end ** 2 / 2) * math.pi * 1e-3 ** 2 * 1e-3
err_w = abs(h["plastic_work"][-1] - work_expected) / work_expected
print(f"linear hardening (Y = {Y:.3g} Pa, H = {H:.3g} Pa): axial stress against the closed form "
      f"{err:.1e} of Y, accumulated plastic strain {err_p:.1e} of eps_y, plastic work "
      f"{h['plastic_work'][-1]:.6e} J against {work_expected:.6e} J ({err_w:.1e})")
checks.check(err < 1e-9, "linear hardening: sigma_zz(eps_zz) = E eps, Y + E_t (eps - Y/E), elastic unloading (1e-9 Y)")
checks.check(err_p < 1e-8, "linear hardening: accumulated plastic strain eps - sigma/E, frozen on unloading")
checks.check(err_w < 1e-3, "linear hardening: plastic work Y eps_p + H eps_p^2/2 (trapezoidal, 1e-3)")
common_checks("linear", h, Y)

# ---- perfectly plastic ----
h = specimen("perfect", [5 * eps_y], 40, {"Yield strength": Y, "Hardening law": "linear",
                                          "Hardening modulus": 0})
expected = np.minimum(E * h["strain_zz"], Y)
err = np.max(np.abs(h["stress_zz"] - expected)) / Y
print(f"perfectly plastic: axial stress against min(E eps, Y) {err:.1e} of Y")
checks.check(err < 1e-9, "perfectly plastic: sigma_zz = min(E eps, Y) (1e-9 Y)")
common_checks("perfect", h, Y)

# ---- Johnson-Cook, 1006 steel (Johnson & Cook 1983), no rate term ----
A, B, N, C = 350e6, 275e6, 0.36, 0.022


def bisect(f, lo, hi):
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if f(mid) > 0:
            hi = mid
        else:
            lo = mid
    return 0.5 * (lo + hi)


jc = {"Yield strength": A, "Hardening law": "johnson-cook", "Johnson-Cook B": B,
      "Johnson-Cook n": N, "Johnson-Cook C": 0, "Reference strain rate": 1}
h = specimen("johnson_cook", [0.05], 100, jc)
expected = []
for e in h["strain_zz"]:
    if E * e <= A:
        expected.append(E * e)
    else:
        expected.append(bisect(lambda s: s / E + ((s - A) / B) ** (1 / N) - e, A, E * e))
expected = np.array(expected)
err = np.max(np.abs(h["stress_zz"] - expected)) / A
print(f"Johnson-Cook (A = 350 MPa, B = 275 MPa, n = 0.36), eps to 0.05: axial stress against "
      f"eps = sigma/E + ((sigma - A)/B)^(1/n) {err:.1e} of A; at eps = 0.05: "
      f"{h['stress_zz'][-1] / 1e6:.4f} MPa (closed form {expected[-1] / 1e6:.4f} MPa)")
checks.check(err < 1e-8, "Johnson-Cook: sigma_zz on the flow curve A + B eps_p^n (1e-8 A)")
common_checks("johnson-cook", h, A)

# ---- Johnson-Cook with the rate term, 100 /s ----
jc_rate = dict(jc, **{"Johnson-Cook C": C})
steps = 100
h = specimen("johnson_cook_rate", [0.01], steps, jc_rate)
dt = RAMP / steps
expected, ep = [0.0], 0.0
for e in h["strain_zz"][1:]:
    trial = E * (e - ep)
    flow = lambda s: (A + B * max(e - s / E, 0) ** N) * \
        (1 + C * math.log(max((e - s / E - ep) / dt, 1.0)))
    if trial <= flow(trial) or trial <= A:
        s = trial
    else:
        s = bisect(lambda s: s - flow(s), A, trial)
        ep = e - s / E
    expected.append(s)
expected = np.array(expected)
err = np.max(np.abs(h["stress_zz"] - expected)) / A
rise = h["stress_zz"][-1] / (A + B * h["accumulated_plastic_strain"][-1] ** N) - 1
print(f"Johnson-Cook with C = 0.022 at 100 /s: axial stress against the scalar backward-Euler "
      f"answer {err:.1e} of A; the rate raises the flow stress by {rise * 100:.2f} % "
      f"(1 + C ln(100) - 1 = {C * math.log(100) * 100:.2f} % at the plastic rate of the total rate)")
checks.check(err < 1e-8, "Johnson-Cook with the rate term: sigma_zz of the uniaxial backward-Euler flow rule (1e-8 A)")
checks.check(0.9 * C * math.log(100) < rise < 1.01 * C * math.log(100),
             "Johnson-Cook with the rate term: flow stress raised by about C ln(rate / rate_0)")
common_checks("johnson-cook rate", h, A)

# ---- refused at a material point ----
code, output = run(binary, f"{work}/plastic_specimen_refused",
                   {"Scenario/Analysis": "material point",
                    "Sphere/Material model": "elastic-plastic",
                    "Material point/Loading": "axial strain path"}, expect_success=False)
checks.check(code != 0 and "axial strain path" in output,
             "material point: 'axial strain path' refused with the loading named")
checks.finish()
