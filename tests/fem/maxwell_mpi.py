"""Generalised Maxwell bodies in an impact, on 1 and 2 ranks.

Both bodies Maxwell (two shear and one bulk Prony term), coarse mesh: the
internal variables live at the quadrature points of the locally owned
cells, so a wrong distribution would show as a difference between 1 and 2
ranks. Checks: force histories within 1e-8 of the peak force, restitution
and dissipation equal within 1e-8, energy balance < 0.5 % (the arms' stored
energy included), restitution below the elastic one; a Maxwell body whose
arms are vanishingly stiff recovers the elastic run.
"""
from fem_test_lib import *

binary, work, mpiexec = parse_common_arguments()
checks = Checks()
coarse = {"Mesh/Contact element size": 100e-6,
          "Time integration/Steps per contact time": 150}
maxwell = dict(coarse, **maxwell_bodies())
runs = {}
for ranks in (1, 2):
    directory = f"{work}/maxwell_{ranks}"
    run(binary, directory, maxwell, ranks=ranks, mpiexec=mpiexec)
    runs[ranks] = (summary(directory), history(directory, "contact_force", "internal_energy"))
(s1, (f1, w1)), (s2, (f2, w2)) = runs[1], runs[2]
n = min(len(f1), len(f2))
checks.check(len(f1) == len(f2), f"same number of steps ({len(f1)}, {len(f2)})")
difference = max(abs(a - b) for a, b in zip(f1[:n], f2[:n])) / max(f1)
print(f"force histories 1 vs 2 ranks: largest difference {difference:.3g} of the peak force")
checks.check(difference < 1e-8, "force histories agree within 1e-8")
for key in ("restitution", "dissipated_energy_fraction", "internal_energy_fraction"):
    rel = abs(s1[key] - s2[key]) / max(abs(s1[key]), 1e-300)
    print(f"{key}: {s1[key]:.12g} (1 rank), {s2[key]:.12g} (2 ranks), relative difference {rel:.3g}")
    checks.check(rel < 1e-8, f"{key} agrees")
print(f"Maxwell impact: e = {s1['restitution']:.6f}, dissipated {s1['dissipated_energy_fraction']*100:.4f} %, "
      f"stored in the arms at the end {s1['internal_energy_fraction']*100:.4f} % "
      f"(largest during the impact {max(w1)/s1['initial_energy']*100:.4f} %), "
      f"balance error {s1['energy_error']*100:.5f} %")
checks.check(s1["energy_error"] < 0.005, "energy balance error < 0.5 %")
checks.check(max(w1) > 0, "energy is stored in the Maxwell arms")

elastic_dir, stiff_dir = f"{work}/maxwell_elastic", f"{work}/maxwell_no_arms"
run(binary, elastic_dir, coarse)
no_arms = dict(coarse)
for body in ("Sphere", "Plate"):
    no_arms.update({f"{body}/Material model": "maxwell",
                    f"{body}/Maxwell/Shear moduli": "1e-6",
                    f"{body}/Maxwell/Shear relaxation times": "1e-6",
                    f"{body}/Maxwell/Bulk moduli": "1e-6",
                    f"{body}/Maxwell/Bulk relaxation times": "1e-6"})
run(binary, stiff_dir, no_arms)
e_el, e_0 = summary(elastic_dir)["restitution"], summary(stiff_dir)["restitution"]
print(f"elastic e = {e_el:.10f}; Maxwell with 1e-6 Pa arms e = {e_0:.10f}")
checks.check(s1["restitution"] < e_el, "Maxwell restitution below the elastic one")
checks.check(abs(e_0 - e_el) < 1e-8, "negligible arms recover the elastic result")
checks.finish()
