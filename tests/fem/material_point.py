"""Material tests, independent of contact, in two forms:
`Scenario/Analysis = material point` (the constitutive update at one point,
any strain tensor) and `specimen` (a homogeneous axisymmetric cylinder,
finite elements of the impact's degree, quasi-static, the Maxwell history
as a right-hand side from the quadrature-point states; strain histories
with theta-theta = rr prescribed on the boundary, creep under uniaxial
stress on the top face).

Each integrated by the same constant-step update as the impact (the
material's tangents, the Maxwell arms' exponential integrator, the
trapezoidal rule of the Newmark step):
  - generalised Maxwell, strain ramp then hold (relaxation): Prony series in
    shear (two terms) and bulk (one term) against the analytic hereditary
    integral; the exponential integrator is exact for a strain linear in
    each step, so the error is round-off;
  - generalised Maxwell, sinusoidal strain: analytic response, error
    O(dt^2): observed order printed, finest step within 1e-6;
  - Kelvin-Voigt, stress step (creep) with different deviatoric and
    volumetric retardation times: e(t) = s/(2G)(1 - exp(-t/tau_d)),
    theta(t) = p/K (1 - exp(-t/tau_v)); observed order printed, finest
    step within 1e-6.
Relative errors are max |numerical - analytic| / max |analytic| over all
components and times.
"""
import math
from fem_test_lib import *
import numpy as np

binary, work, _ = parse_common_arguments()
checks = Checks()

G_INF, K_INF = 8e10, 1.3333333333333333e11
SHEAR = [(1e10, 1e-6), (2e10, 5e-6)]
BULK = [(3e10, 2e-6)]
EPS = np.array([1e-3, -2e-4, 5e-4, 3e-4])  # rr, zz, tt, rz
MAXWELL = {
    "Scenario/Analysis": "material point",
    "Sphere/Material model": "maxwell",
    "Sphere/Maxwell/Long-term shear modulus": G_INF,
    "Sphere/Maxwell/Long-term bulk modulus": K_INF,
    "Sphere/Maxwell/Shear moduli": ",".join(str(g) for g, _ in SHEAR),
    "Sphere/Maxwell/Shear relaxation times": ",".join(str(t) for _, t in SHEAR),
    "Sphere/Maxwell/Bulk moduli": ",".join(str(k) for k, _ in BULK),
    "Sphere/Maxwell/Bulk relaxation times": ",".join(str(t) for _, t in BULK),
    "Material point/Strain": ",".join(str(e) for e in EPS),
}
COMPONENTS = ["rr", "zz", "thetatheta", "rz"]


def split(v):
    """(deviator, trace) of (rr, zz, tt, rz) vectors (shape (..., 4))."""
    tr = v[..., 0] + v[..., 1] + v[..., 2]
    dev = v.copy()
    dev[..., :3] -= tr[..., None] / 3
    return dev, tr


def run_point(name, settings, specimen=False):
    directory = f"{work}/{'specimen' if specimen else 'material_point'}_{name}"
    if specimen:
        settings = dict(settings, **{"Scenario/Analysis": "specimen"})
    run(binary, directory, settings)
    names = ["time"] + ["strain_" + c for c in COMPONENTS] + ["stress_" + c for c in COMPONENTS]
    data = history(directory, *names)
    t = data[0]
    return t, np.stack(data[1:5], axis=1), np.stack(data[5:9], axis=1)


def maxwell_stress(strain_dev, strain_tr, arm_factor, eps_hat):
    """sigma = 2 G_inf e + K_inf theta I + sum 2 G_i h_i + sum K_j q_j I,
    with the arms' strains h = arm_factor(tau) * (dev or tr of eps_hat)."""
    dev_hat, tr_hat = split(eps_hat)
    sigma = 2 * G_INF * strain_dev
    volumetric = K_INF * strain_tr
    for g, tau in SHEAR:
        sigma = sigma + 2 * g * np.outer(arm_factor(tau), dev_hat)
    for k, tau in BULK:
        volumetric = volumetric + k * arm_factor(tau) * tr_hat
    sigma[:, :3] += volumetric[:, None]
    return sigma


def relative_error(numerical, analytic):
    return np.max(np.abs(numerical - analytic)) / np.max(np.abs(analytic))


def verify(specimen):
    """The three histories at the material point or on the specimen."""
    kind = "specimen" if specimen else "material point"
    eps = EPS_SPECIMEN if specimen else EPS
    maxwell = dict(MAXWELL, **{"Material point/Strain": ",".join(str(e) for e in eps)})
    inhomogeneity = []

    def solve(name, settings):
        t, strain, stress = run_point(name, settings, specimen)
        if specimen:
            inhomogeneity.append(max(history(f"{work}/specimen_{name}", "inhomogeneity")[0]))
        return t, strain, stress

    # 1. Relaxation: ramp over t_r = 1 us (100 steps), hold to 10 us.
    t_r = 1e-6
    t, strain, stress = solve("relaxation", dict(maxwell, **{
        "Material point/Loading": "strain ramp", "Material point/Ramp time": t_r,
        "Material point/Duration": 1e-5, "Material point/Time step": 1e-8}))
    ramp = np.minimum(t / t_r, 1.0)

    def ramp_arm(tau):
        return np.where(t <= t_r, tau / t_r * (1 - np.exp(-t / tau)),
                        tau / t_r * (1 - math.exp(-t_r / tau)) * np.exp(-(t - t_r) / tau))

    dev_hat, tr_hat = split(eps)
    analytic = maxwell_stress(np.outer(ramp, dev_hat), ramp * tr_hat, ramp_arm, eps)
    error = relative_error(stress, analytic)
    print(f"[{kind}] Maxwell relaxation (2 shear + 1 bulk Prony terms, 1000 steps): "
          f"relative error {error:.3g}; sigma_zz relaxes from {np.max(np.abs(stress[:, 1])):.6g} "
          f"to {stress[-1, 1]:.6g} Pa (analytic {analytic[-1, 1]:.6g})")
    checks.check(error < 1e-6, f"[{kind}] Maxwell relaxation within 1e-6 of the analytic response")

    # 2. Sinusoidal strain: convergence of the exponential integrator.
    period = 4e-6
    omega = 2 * math.pi / period
    errors = []
    steps_list = (500, 1000, 2000) if specimen else (500, 1000, 2000, 4000)
    for steps_per_period in steps_list:
        dt = period / steps_per_period
        t, strain, stress = solve(f"oscillation_{steps_per_period}", dict(maxwell, **{
            "Material point/Loading": "strain oscillation",
            "Material point/Angular frequency": omega,
            "Material point/Duration": period if specimen else 2 * period,
            "Material point/Time step": dt}))
        sine = np.sin(omega * t)

        def oscillation_arm(tau):
            wt = omega * tau
            return wt / (1 + wt * wt) * (np.cos(omega * t) + wt * np.sin(omega * t) - np.exp(-t / tau))

        analytic = maxwell_stress(np.outer(sine, dev_hat), sine * tr_hat, oscillation_arm, eps)
        errors.append(relative_error(stress, analytic))
    orders = [math.log2(errors[i] / errors[i + 1]) for i in range(len(errors) - 1)]
    print(f"[{kind}] Maxwell oscillation, steps per period {steps_list[0]}..{steps_list[-1]}: relative errors "
          + ", ".join(f"{e:.3g}" for e in errors) + "; observed orders "
          + ", ".join(f"{p:.3f}" for p in orders))
    checks.check(all(abs(p - 2) < 0.1 for p in orders), f"[{kind}] Maxwell: second order in the time step")
    checks.check(errors[-1] < 1e-6, f"[{kind}] Maxwell oscillation within 1e-6 at the finest step")

    # 3. Kelvin-Voigt creep under a stress step.
    sig = SIG_SPECIMEN if specimen else SIG
    errors = []
    steps_list = (250, 500, 1000, 2000) if specimen else (250, 500, 1000, 2000, 8000)
    for steps in steps_list:
        dt = 8e-6 / steps
        t, strain, stress = solve(f"creep_{steps}", {
            "Scenario/Analysis": "material point",
            "Sphere/Material model": "kelvin-voigt",
            "Sphere/Kelvin-voigt/Young's modulus": E,
            "Sphere/Kelvin-voigt/Poisson's ratio": NU,
            "Sphere/Kelvin-voigt/Retardation time": TAU_D,
            "Sphere/Kelvin-voigt/Volumetric retardation time": TAU_V,
            "Material point/Loading": "stress step",
            "Material point/Stress": ",".join(str(x) for x in sig),
            "Material point/Duration": 8e-6, "Material point/Time step": dt})
        s_dev, s_tr = split(sig)
        analytic = np.outer(1 - np.exp(-t / TAU_D), s_dev / (2 * G))
        analytic[:, :3] += ((1 - np.exp(-t / TAU_V)) * s_tr / (3 * K) / 3)[:, None]
        errors.append(relative_error(strain, analytic))
    orders = [math.log2(errors[i] / errors[i + 1]) for i in range(3)]
    print(f"[{kind}] Kelvin-Voigt creep (tau_d = 1 us, tau_v = 3 us), 250..2000 steps over 8 us: "
          "relative errors " + ", ".join(f"{e:.3g}" for e in errors[:4]) + "; observed orders "
          + ", ".join(f"{p:.3f}" for p in orders)
          + (f"; 8000 steps: {errors[4]:.3g}" if len(errors) > 4 else ""))
    checks.check(all(abs(p - 2) < 0.1 for p in orders), f"[{kind}] Kelvin-Voigt creep: second order in the time step")
    checks.check(errors[-1] < 1e-6, f"[{kind}] Kelvin-Voigt creep within 1e-6 at the finest step")
    if specimen:
        print(f"[specimen] largest inhomogeneity of the stress over the quadrature points: {max(inhomogeneity):.3g}")
        checks.check(max(inhomogeneity) < 1e-9, "[specimen] the stress field is homogeneous")


E, NU, TAU_D, TAU_V = 2e11, 0.25, 1e-6, 3e-6
G, K = E / (2 * (1 + NU)), E / (3 * (1 - 2 * NU))
SIG = np.array([1e8, -4e7, 2e7, 5e7])
# The homogeneous axisymmetric states of the specimen: theta-theta = rr, no
# rz; uniaxial stress for the creep.
EPS_SPECIMEN = np.array([1e-3, -2e-4, 1e-3, 0.0])
SIG_SPECIMEN = np.array([0.0, 1e8, 0.0, 0.0])
verify(specimen=False)
verify(specimen=True)
checks.finish()
