"""The elastic-plastic material (J2, isotropic hardening, radial return) at
one material point (`Scenario/Analysis = material point`, loading `strain
path`), against closed-form answers and an independent integration:
  - uniaxial stress with linear hardening: the lateral strains of uniaxial
    stress are prescribed (elastic branch, then eps_rr = -nu sigma/E -
    eps_p/2), so the radial stresses must vanish and sigma_zz follow
    Y + E_t (eps - Y/E), E_t = E H / (E + H); then elastic unloading (slope E,
    accumulated plastic strain frozen); plastic work Y eps_p + H eps_p^2/2;
  - pure shear (rz), perfectly plastic and hardening: tau = 2 G eps_rz up
    to Y/sqrt(3), then tau = (Y/sqrt(3) + 2 H eps_rz/3) / (1 + H/(3G));
    steps straddle the yield point (radial return is exact for proportional
    loading with linear hardening, so round-off is the tolerance);
  - a non-proportional path (uniaxial strain, then shear at fixed axial
    strain: the flow direction rotates) against the rate equations
    d sigma = (C - 2G 3G/(3G+H) N (x) N) : d eps integrated here with RK4 on
    5 10^4 sub-steps per segment; the radial return (backward Euler) is first
    order: the error must fall with the step at the observed order ~1 and be
    below 2e-3 at 1000 steps per segment.
Johnson-Cook (rate term off) along a near-uniaxial path through points of
its flow curve: on every plastic step the von Mises stress equals
A + B eps_p^n (the consistency condition of the return, solved to
round-off).
"""
import math
from fem_test_lib import *
import numpy as np

binary, work, _ = parse_common_arguments()
checks = Checks()

E, NU, Y, H = 2e11, 0.3, 4e8, 2e10
G = E / (2 * (1 + NU))
K = E / (3 * (1 - 2 * NU))
RAMP = 1e-6


def material(hardening=H, extra=None):
    s = {"Scenario/Analysis": "material point",
         "Sphere/Material model": "elastic-plastic",
         "Sphere/Elastic-plastic/Young's modulus": E,
         "Sphere/Elastic-plastic/Poisson's ratio": NU,
         "Sphere/Yield strength": Y,
         "Sphere/Elastic-plastic/Hardening modulus": hardening,
         "Material point/Loading": "strain path",
         "Material point/Ramp time": RAMP}
    s.update(extra or {})
    return s


def run_path(name, points, steps_per_segment, hardening=H, extra=None):
    directory = f"{work}/plastic_point_{name}"
    path = "; ".join(", ".join(repr(float(c)) for c in p) for p in points)
    settings = material(hardening, extra)
    settings.update({"Material point/Strain path": path,
                     "Material point/Duration": RAMP * len(points),
                     "Material point/Time step": RAMP / steps_per_segment})
    run(binary, directory, settings)
    names = ["time"] + [f"strain_{c}" for c in ("rr", "zz", "thetatheta", "rz")] + \
            [f"stress_{c}" for c in ("rr", "zz", "thetatheta", "rz")] + \
            ["accumulated_plastic_strain", "plastic_work"]
    return dict(zip(names, history(directory, *names)))


# ---- uniaxial stress, linear hardening, then elastic unloading ----
eps_y = Y / E
Et = E * H / (E + H)
eps_f = 5e-3
sig_f = Y + Et * (eps_f - eps_y)
ep_f = (sig_f - Y) / H
lat_f = -NU * sig_f / E - ep_f / 2
unload = 0.5 * sig_f / E
points = [(-NU * eps_y, eps_y, -NU * eps_y, 0),
          (lat_f, eps_f, lat_f, 0),
          (lat_f + NU * unload, eps_f - unload, lat_f + NU * unload, 0)]
h = run_path("uniaxial", points, 50)
t = h["time"]
ezz = h["strain_zz"]
expected = np.where(t <= RAMP * (1 + 1e-9), E * ezz,
                    np.where(t <= 2 * RAMP * (1 + 1e-9), Y + Et * (ezz - eps_y),
                             sig_f - E * (eps_f - ezz)))
scale = np.max(np.abs(expected))
err_zz = np.max(np.abs(h["stress_zz"] - expected)) / scale
err_lateral = max(np.max(np.abs(h[f"stress_{c}"])) for c in ("rr", "thetatheta", "rz")) / scale
print(f"uniaxial stress: sigma_zz error {err_zz:.2e}, lateral stress {err_lateral:.2e} "
      f"(of {scale/1e6:.1f} MPa); final eps_p {h['accumulated_plastic_strain'][-1]:.6e} "
      f"(closed form {ep_f:.6e})")
checks.check(err_zz < 1e-9, "uniaxial stress with linear hardening: sigma_zz = Y + E_t (eps - Y/E) within 1e-9")
checks.check(err_lateral < 1e-9, "uniaxial stress: sigma_rr = sigma_thetatheta = sigma_rz = 0 within 1e-9")
checks.check(abs(h["accumulated_plastic_strain"][-1] - ep_f) < 1e-9 * ep_f,
             "accumulated plastic strain = (sigma - Y)/H")
unloading = t >= 2 * RAMP * (1 - 1e-9)
checks.check(np.ptp(h["accumulated_plastic_strain"][unloading]) == 0,
             "elastic unloading: the accumulated plastic strain stays frozen")
work_closed = Y * ep_f + 0.5 * H * ep_f ** 2
print(f"plastic work {h['plastic_work'][-1]:.6e} J/m^3, closed form {work_closed:.6e}")
checks.check(abs(h["plastic_work"][-1] - work_closed) < 1e-9 * work_closed,
             "plastic work = Y eps_p + H eps_p^2 / 2 within 1e-9")

# ---- pure shear, perfectly plastic and hardening ----
for hardening in (0.0, H):
    gamma_f = 4e-3
    h = run_path(f"shear_{int(hardening)}", [(0, 0, 0, gamma_f)], 37, hardening)
    e = h["strain_rz"]
    tau_y = Y / math.sqrt(3)
    plastic = 2 * G * e > tau_y
    expected = np.where(plastic,
                        (tau_y + 2 * hardening * e / 3) / (1 + hardening / (3 * G)),
                        2 * G * e)
    err = np.max(np.abs(h["stress_rz"] - expected)) / np.max(expected)
    other = max(np.max(np.abs(h[f"stress_{c}"])) for c in ("rr", "zz", "thetatheta")) / np.max(expected)
    print(f"pure shear H = {hardening:.3g} Pa: tau error {err:.2e}, normal stresses {other:.2e}, "
          f"final tau {h['stress_rz'][-1]/1e6:.3f} MPa")
    checks.check(err < 1e-9 and other < 1e-9,
                 f"pure shear, H = {hardening:g} Pa: tau against the closed form within 1e-9")


# ---- non-proportional path: uniaxial strain, then shear at fixed eps_zz ----
def rate_equations_reference(points, substeps, hardening):
    """RK4 on d sigma = C_ep : d eps, d eps_p = sqrt(2/3) |d eps^p|."""
    I = np.eye(3)

    def stress_rate(sig, ep, deps):
        s = sig - np.trace(sig) / 3 * I
        q = math.sqrt(1.5 * np.sum(s * s))
        dsig = 2 * G * (deps - np.trace(deps) / 3 * I) + K * np.trace(deps) * I
        if q >= Y + hardening * ep - 1e-9 * Y:
            N = s / np.linalg.norm(s)
            load = np.sum(N * deps)
            if load > 0:
                dsig -= 2 * G * 3 * G / (3 * G + hardening) * load * N
                dep = math.sqrt(1.5) * 2 * G * load / (3 * G + hardening)
                return dsig, dep
        return dsig, 0.0

    sig, ep = np.zeros((3, 3)), 0.0
    previous = np.zeros((3, 3))
    for p in points:
        target = np.array([[p[0], p[3], 0], [p[3], p[1], 0], [0, 0, p[2]]])
        deps = (target - previous) / substeps
        for _ in range(substeps):
            k1 = stress_rate(sig, ep, deps)
            k2 = stress_rate(sig + k1[0] / 2, ep + k1[1] / 2, deps)
            k3 = stress_rate(sig + k2[0] / 2, ep + k2[1] / 2, deps)
            k4 = stress_rate(sig + k3[0], ep + k3[1], deps)
            sig = sig + (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]) / 6
            ep = ep + (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]) / 6
            # Back onto the yield surface (the sub-step's drift, O(h^5)).
            s = sig - np.trace(sig) / 3 * np.eye(3)
            q = math.sqrt(1.5 * np.sum(s * s))
            if ep > 0 and q > Y + hardening * ep:
                sig = np.trace(sig) / 3 * np.eye(3) + s * (Y + hardening * ep) / q
        previous = target
    return sig, ep


points = [(0, 3e-3, 0, 0), (0, 3e-3, 0, 3e-3)]
ref_sig, ref_ep = rate_equations_reference(points, 50000, H)
errors = []
for steps in (250, 1000):
    h = run_path(f"rotation_{steps}", points, steps)
    sig = np.array([[h["stress_rr"][-1], h["stress_rz"][-1], 0],
                    [h["stress_rz"][-1], h["stress_zz"][-1], 0],
                    [0, 0, h["stress_thetatheta"][-1]]])
    err = np.linalg.norm(sig - ref_sig) / np.linalg.norm(ref_sig)
    errors.append(err)
    print(f"non-proportional path, {steps} steps per segment: stress error {err:.3e}, "
          f"eps_p {h['accumulated_plastic_strain'][-1]:.6e} (reference {ref_ep:.6e})")
order = math.log(errors[0] / errors[1]) / math.log(4)
print(f"observed order {order:.2f}; reference stress rr, zz, tt, rz = "
      f"{ref_sig[0,0]/1e6:.3f}, {ref_sig[1,1]/1e6:.3f}, {ref_sig[2,2]/1e6:.3f}, {ref_sig[0,1]/1e6:.3f} MPa")
checks.check(errors[1] < 2e-3, "rotating flow direction: final stress within 2e-3 of the rate-equation integration")
checks.check(0.8 < order < 1.5, "rotating flow direction: radial return converges at first order")

# ---- Johnson-Cook (rate term off): uniaxial flow curve ----
A, B, n = 3e8, 5e8, 0.4
jc = {"Sphere/Elastic-plastic/Hardening law": "johnson-cook",
      "Sphere/Yield strength": A,
      "Sphere/Elastic-plastic/Johnson-Cook B": B,
      "Sphere/Elastic-plastic/Johnson-Cook n": n}
ep_targets = [0.002, 0.01, 0.03]
points = [(-NU * A / E, A / E, -NU * A / E, 0)]
for ep in ep_targets:
    sig = A + B * ep ** n
    lat = -NU * sig / E - ep / 2
    points.append((lat, sig / E + ep, lat, 0))
h = run_path("johnson_cook", points, 40, extra=jc)
ep = h["accumulated_plastic_strain"]
rr, zz, tt = h["stress_rr"], h["stress_zz"], h["stress_thetatheta"]
q = np.sqrt(0.5 * ((rr - zz) ** 2 + (zz - tt) ** 2 + (tt - rr) ** 2) + 3 * h["stress_rz"] ** 2)
plastic = ep > 0
flow = A + B * ep[plastic] ** n
err = np.max(np.abs(q[plastic] - flow) / flow)
lateral = max(np.max(np.abs(h[f"stress_{c}"])) for c in ("rr", "thetatheta")) / np.max(zz)
print(f"Johnson-Cook uniaxial: max |q - (A + B eps_p^n)| / sigma_y = {err:.2e} on "
      f"{plastic.sum()} plastic steps, final eps_p {ep[-1]:.5f} (path end {ep_targets[-1]}), "
      f"lateral stress {lateral:.2e} of sigma_zz")
checks.check(err < 1e-10, "Johnson-Cook: von Mises stress = A + B eps_p^n on every plastic step")
checks.check(abs(ep[-1] - ep_targets[-1]) < 0.02 * ep_targets[-1],
             "Johnson-Cook: the path's plastic strain is reached (within 2 %)")
checks.finish()
