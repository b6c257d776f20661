"""Elastic-plastic impact (both bodies `elastic-plastic`, small mesh):
  - with a yield strength no stress reaches, the iterated step reproduces
    the elastic run (same contact force history to 1e-9 of the peak, one
    iteration per step): the iteration changes nothing where nothing yields;
  - a yielding impact: every step converged (newton_residual below the
    tolerance in history.h5), the energy balance with the plastic work
    closes to < 0.01 % of the initial kinetic energy at the end, plastic work
    > 0, restitution below the elastic one, a permanent approach > 0, the
    summary's plastic entries present, and the two strategies (anderson,
    modified newton) agree;
  - the direct solver `auto` is KLU on one rank with an elastic-plastic body
    and MUMPS with elastic bodies (the log says which), and the two give the
    same yielding impact (force history to 1e-9 of the peak);
  - a step that cannot converge (Maximum iterations = 1) stops the run:
    non-zero exit, a message naming the step, its time and the criterion,
    history.incomplete.h5 kept, no history.h5 or summary.json.
"""
import os
from fem_test_lib import *
import numpy as np

binary, work, _ = parse_common_arguments()
checks = Checks()

small = {"Mesh/Contact element size": 200e-6, "Scenario/Impact velocity": 3,
         "Time integration/Steps per contact time": 150}
YIELD = 2.03e9


def bodies(model, yield_strength=YIELD, extra=None):
    s = dict(small)
    for body in ("Sphere", "Plate"):
        s[f"{body}/Material model"] = model
        if model == "elastic-plastic":
            s[f"{body}/Yield strength"] = yield_strength
    s.update(extra or {})
    return s


elastic_dir = f"{work}/plastic_elastic_reference"
_, elastic_output = run(binary, elastic_dir, bodies("elastic"))
checks.check("Solver/Direct solver = Amesos_Mumps  (auto: elastic bodies, one rank)" in elastic_output,
             "direct solver auto: MUMPS for elastic bodies, and the log says so")
e_force, = history(elastic_dir, "contact_force")
e = summary(elastic_dir)

# ---- nothing yields: the iterated step is the elastic one ----
high = f"{work}/plastic_no_yield"
run(binary, high, bodies("elastic-plastic", 1e12))
force, iterations = history(high, "contact_force", "newton_iterations")
diff = np.max(np.abs(force - e_force)) / np.max(e_force)
print(f"yield strength 1e12 Pa: contact force differs from the elastic run by {diff:.2e} of the peak, "
      f"iterations per step {iterations.min():.0f}..{iterations.max():.0f}")
checks.check(len(force) == len(e_force) and diff < 1e-9,
             "no yield: contact force history of the elastic run (1e-9 of the peak)")
checks.check(np.all(iterations[1:] == 1), "no yield: one iteration per step (after the initial state)")

# ---- a yielding impact, both strategies ----
results = {}
for strategy in ("anderson", "modified newton"):
    directory = f"{work}/plastic_{strategy.replace(' ', '_')}"
    code, output = run(binary, directory,
                       bodies("elastic-plastic", extra={"Nonlinear solver/Strategy": strategy}))
    s = summary(directory)
    iterations, residual, energy_error, work_p = history(
        directory, "newton_iterations", "newton_residual", "energy_error", "plastic_work")
    results[strategy] = s
    if strategy == "anderson":
        klu = "Solver/Direct solver = Amesos_Klu  (auto: an elastic-plastic body, one rank)"
        checks.check(klu in output, "direct solver auto: KLU on one rank with an elastic-plastic body, "
                     "and the log says so")
        mumps_dir = f"{work}/plastic_anderson_mumps"
        run(binary, mumps_dir, bodies("elastic-plastic", extra={"Solver/Direct solver": "Amesos_Mumps"}))
        klu_force, = history(directory, "contact_force")
        mumps_force, = history(mumps_dir, "contact_force")
        diff = (np.max(np.abs(klu_force - mumps_force)) / np.max(mumps_force)
                if len(klu_force) == len(mumps_force) else np.inf)
        print(f"KLU against MUMPS: force histories differ by {diff:.1e} of the peak")
        checks.check(diff < 1e-9, "KLU and MUMPS give the same yielding impact (1e-9 of the peak)")
    print(f"{strategy}: iterations per step max {iterations.max():.0f}, total {iterations.sum():.0f}, "
          f"largest accepted residual {residual.max():.2e}; e = {s['restitution']:.5f} "
          f"(elastic {e['restitution']:.5f}), plastic work {s['plastic_work_fraction']*100:.3f} %, "
          f"permanent approach {s['permanent_approach']*1e6:.4f} um, dent radius "
          f"{s['dent_radius']*1e3:.3f} mm, max eps_p {s['max_accumulated_plastic_strain']:.3e}, "
          f"energy error at the end {s['energy_error_final']:.2e}, yield onset at "
          f"{s['yield_onset_velocity']:.3f} m/s, wall {s['wall_time']:.1f} s")
    checks.check(residual.max() <= 1e-8, f"{strategy}: every step converged (residual <= 1e-8 of the load)")
    checks.check(s["plastic_work"] > 0 and work_p[-1] == s["plastic_work"], f"{strategy}: plastic work > 0")
    checks.check(s["restitution"] < e["restitution"] - 1e-3, f"{strategy}: restitution below the elastic one")
    checks.check(s["permanent_approach"] > 0, f"{strategy}: permanent approach > 0")
    checks.check(0 < s["yield_onset_velocity"] < small["Scenario/Impact velocity"],
                 f"{strategy}: yield onset velocity between 0 and V")
    checks.check(s["max_accumulated_plastic_strain"] > 0, f"{strategy}: max accumulated plastic strain > 0")
a, m = results["anderson"], results["modified newton"]
for key in ("restitution", "force_max", "permanent_approach", "plastic_work"):
    rel = abs(a[key] - m[key]) / abs(m[key])
    print(f"  {key}: anderson {a[key]:.8g}, modified newton {m[key]:.8g}, relative difference {rel:.1e}")
    checks.check(rel < 1e-5, f"strategies agree on {key} (1e-5)")

# ---- energy: with the average-acceleration rule the balance is exact but for
# the work of the discretised contact constraint (contact_work, also there for
# elastic bodies), so kinetic + strain + plastic work + radiated - initial
# must equal the contact work to round-off and the Newton tolerance ----
directory = f"{work}/plastic_newmark"
run(binary, directory, bodies("elastic-plastic", extra={"Time integration/Scheme": "newmark"}))
s = summary(directory)
error, contact_work = history(directory, "energy_error", "contact_work")
gap = np.max(np.abs(error - contact_work / s["initial_energy"]))
print(f"newmark: energy error at the end {s['energy_error_final']:.3e} of the initial energy, of which "
      f"contact work {contact_work[-1] / s['initial_energy']:.3e}; balance with the contact work "
      f"closes to {gap:.2e} over the run; plastic work {s['plastic_work_fraction']*100:.3f} %")
checks.check(gap < 1e-8, "energy balance with plastic work (and the contact work) closes to < 1e-8 over the run")
checks.check(abs(s["energy_error_final"] - contact_work[-1] / s["initial_energy"]) < 1e-4,
             "energy balance error at the end < 0.01 % of the initial energy besides the contact work")

# ---- a sweep over an entry of the new material, and snapshots ----
import glob, subprocess, h5py
directory = f"{work}/plastic_sweep"
import shutil
shutil.rmtree(directory, ignore_errors=True)
command = [binary, STEEL_PRM, "--velocities", "3", "--sweep", "Sphere/Yield strength=2.03e9,4e9",
           "--set", "Output/Directory=" + directory, "--set", "Output/Snapshot interval=2e-5"] + \
    sets(bodies("elastic-plastic"))
result = subprocess.run(command, capture_output=True, text=True)
print("sweep: exit", result.returncode, (result.stdout + result.stderr).strip().splitlines()[-1:])
runs = {}
for path in glob.glob(f"{directory}/**/history.h5", recursive=True):
    with h5py.File(path, "r") as f:
        runs[float(f.attrs["Sphere/Yield strength"])] = os.path.dirname(path)
print("sweep runs:", {k: os.path.relpath(v, directory) for k, v in sorted(runs.items())})
checks.check(result.returncode == 0 and sorted(runs) == [2.03e9, 4e9],
             "sweep over Sphere/Yield strength: one run per value")
if sorted(runs) == [2.03e9, 4e9]:
    w = {y: summary(d)["max_accumulated_plastic_strain_sphere"] for y, d in runs.items()}
    print(f"  sphere's max accumulated plastic strain: {w}")
    checks.check(w[4e9] < w[2.03e9], "sweep: a stronger sphere yields less")
    vtus = glob.glob(f"{runs[2.03e9]}/snapshots/*.vtu")
    named = [v for v in vtus if "accumulated_plastic_strain" in open(v, errors="ignore").read()]
    print(f"  snapshots: {len(vtus)} .vtu files, {len(named)} with accumulated_plastic_strain")
    checks.check(len(vtus) > 0 and len(named) == len(vtus),
                 "snapshots carry the accumulated plastic strain")

# ---- a step that does not converge ----
directory = f"{work}/plastic_no_convergence"
code, output = run(binary, directory,
                   bodies("elastic-plastic", extra={"Nonlinear solver/Maximum iterations": 1}),
                   expect_success=False)
print("non-convergence: exit", code, "|", " ".join(output.strip().splitlines()[-4:])[:400])
checks.check(code != 0, "non-convergence: non-zero exit")
checks.check(all(w in output for w in ("Time step", "t =", "did not converge", "Residual tolerance",
                                         "Maximum iterations")),
             "non-convergence: message names the step, its time and the criterion")
checks.check(os.path.exists(os.path.join(directory, "history.incomplete.h5")),
             "non-convergence: history.incomplete.h5 kept")
checks.check(not os.path.exists(os.path.join(directory, "history.h5")) and
             not os.path.exists(os.path.join(directory, "summary.json")),
             "non-convergence: no history.h5, no summary.json")
checks.finish()
