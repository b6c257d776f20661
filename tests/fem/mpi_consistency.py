"""Spec verification 5: the same scenario on 1 and 2 ranks.

Force histories equal within 1e-8 relative to the peak force, and the same
derived quantities (within 1e-8 relative).
"""
from fem_test_lib import *

binary, work, mpiexec = parse_common_arguments()
checks = Checks()
settings = {"Mesh/Contact element size": 100e-6,
            "Time integration/Steps per contact time": 150}
runs = {}
for ranks in (1, 2):
    directory = f"{work}/mpi_{ranks}"
    run(binary, directory, settings, ranks=ranks, mpiexec=mpiexec)
    runs[ranks] = (summary(directory), history(directory, "contact_force")[0])

(s1, f1), (s2, f2) = runs[1], runs[2]
checks.check(len(f1) == len(f2), f"same number of steps ({len(f1)}, {len(f2)})")
n = min(len(f1), len(f2))
difference = max(abs(a - b) for a, b in zip(f1[:n], f2[:n])) / max(f1)
print(f"force histories: largest difference {difference:.3g} of the peak force")
checks.check(difference < 1e-8, "force histories agree within 1e-8")
for key in ("contact_time", "force_max", "approach_max", "restitution"):
    rel = abs(s1[key] - s2[key]) / max(abs(s1[key]), 1e-300)
    print(f"{key}: {s1[key]:.12g} (1 rank), {s2[key]:.12g} (2 ranks), relative difference {rel:.3g}")
    checks.check(rel < 1e-8, f"{key} agrees")
# The balance error is itself a small difference of energies, relative to the
# initial energy: compare it absolutely.
difference = abs(s1["energy_error"] - s2["energy_error"])
print(f"energy_error: {s1['energy_error']:.6g} and {s2['energy_error']:.6g}, difference {difference:.3g}")
checks.check(difference < 1e-8, "energy_error agrees within 1e-8 of the initial energy")
checks.check(s2["ranks"] == 2 and s1["ranks"] == 1, "ranks recorded in the summary")
checks.finish()
