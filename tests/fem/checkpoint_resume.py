"""A run stopped before its end goes on from its checkpoint (output/checkpoint.h), bit for bit.

Case: an elastic-plastic impact of the steel bodies (both yield, small mesh, BDF2, four sub-steps
at contact entry), one rank. The reference runs uninterrupted. Then:
1. SIGINT a second run once its checkpoint exists: it stops at the next step with a non-zero
   exit, leaving checkpoint/ and history.incomplete.h5; run again, it says it resumed from a step
   after the first and ends with summary.json equal to the reference's (every key but wall_time)
   and every dataset of history.h5 equal to the reference's, bit for bit; its checkpoint is gone;
2. SIGKILL a third run once its checkpoint exists (nothing written at the kill): the same;
3. a checkpoint damaged after its stamp: the run stops with exit 1, naming the checkpoint and
   what to do, and writes no summary.json;
4. a checkpoint of other entries (another impact velocity, and a maximum time that ends it
   early) is not resumed: that run starts from the first contact and completes;
5. on two ranks (mpirun forwards SIGTERM to them): stopped and resumed, it equals the
   uninterrupted two-rank run bit for bit. Both with KLU (Solver/Direct solver = Amesos_Klu):
   with MUMPS, the default on several ranks, two uninterrupted two-rank runs of this case differ
   from each other from a step that varies (the 86th, the 211th) by up to 4e-14 of the peak
   force (also with OMP_NUM_THREADS = OPENBLAS_NUM_THREADS = 1); with KLU they are equal to the
   bit (measured 2026-12-07).
argv: impact-fem, work directory, mpiexec."""
import os
import shutil
import signal
import subprocess
import time

import h5py
import numpy as np

from fem_test_lib import STEEL_PRM, Checks, parse_common_arguments, sets, summary, with_steel

binary, work, mpiexec = parse_common_arguments()
checks = Checks()
SETTINGS = {"Mesh/Contact element size": 200e-6, "Scenario/Impact velocity": 3,
            "Time integration/Steps per contact time": 150,
            "Time integration/Sub-steps at contact entry": 4}
for body in ("Sphere", "Plate"):
    SETTINGS[f"{body}/Material model"] = "elastic-plastic"
    SETTINGS[f"{body}/Yield strength"] = 1e9


ranks = 1


def command(directory, settings=None):
    launcher = [] if ranks == 1 else [mpiexec, "--allow-run-as-root", "--oversubscribe",
                                      "-np", str(ranks)]
    return launcher + [binary, STEEL_PRM, "--set", f"Output/Directory={directory}"] + \
        sets(with_steel({**SETTINGS, **(settings or {})}))


def fresh(name):
    directory = os.path.join(work, name)
    if os.path.isdir(directory):
        shutil.rmtree(directory)
    return directory


def run(directory, settings=None):
    result = subprocess.run(command(directory, settings), capture_output=True, text=True)
    return result.returncode, result.stdout + result.stderr


def stopped(directory, stop_signal, settings=None):
    """Starts a run and sends @p stop_signal once its checkpoint exists."""
    process = subprocess.Popen(command(directory, settings), stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
    checkpoint = os.path.join(directory, "checkpoint")
    while process.poll() is None and not os.path.isdir(checkpoint):
        time.sleep(0.01)
    # A few steps more, so that the run stops between two checkpoints.
    time.sleep(0.3)
    process.send_signal(stop_signal)
    output, _ = process.communicate()
    return process.returncode, output


def same_as_reference(name, directory):
    s = summary(directory)
    s.pop("wall_time")
    different = [k for k in reference_summary if s.get(k) != reference_summary[k]]
    checks.check(s.keys() == reference_summary.keys() and not different,
                 f"{name}: summary.json equals the reference's (all keys but wall_time)"
                 + (f"; differ: {different}" if different else ""))
    with h5py.File(os.path.join(directory, "history.h5"), "r") as f, \
            h5py.File(os.path.join(reference, "history.h5"), "r") as g:
        names = sorted(f.keys())
        unequal = [n for n in names if not np.array_equal(f[n][:], g[n][:])]
        checks.check(names == sorted(g.keys()) and not unequal,
                     f"{name}: the {len(names)} datasets of history.h5 equal the reference's, "
                     f"bit for bit" + (f"; differ: {unequal}" if unequal else ""))
    checks.check(not os.path.exists(os.path.join(directory, "checkpoint"))
                 and not os.path.exists(os.path.join(directory, "history.incomplete.h5")),
                 f"{name}: no checkpoint or incomplete history left")


def resumed_step(output):
    marker = "resumed from the checkpoint of step "
    if marker not in output:
        return None
    return int(output.split(marker)[1].split()[0])


reference = fresh("checkpoint_reference")
start = time.time()
code, output = run(reference)
checks.check(code == 0, f"reference run (exit {code}, {time.time() - start:.1f} s)")
if code != 0:
    print(output)
    checks.finish()
reference_summary = summary(reference)
reference_summary.pop("wall_time")
steps = reference_summary["steps"]

for name, stop_signal in (("SIGINT", signal.SIGINT), ("SIGKILL", signal.SIGKILL)):
    directory = fresh(f"checkpoint_{name.lower()}")
    code, output = stopped(directory, stop_signal)
    kept = os.path.isfile(os.path.join(directory, "checkpoint", "rank-0.bin"))
    checks.check(code != 0 and kept and not os.path.exists(os.path.join(directory, "summary.json")),
                 f"{name}: stopped (exit {code}), checkpoint/rank-0.bin kept, no summary.json")
    if stop_signal == signal.SIGKILL:
        # Copies of the stopped run for 3. and 4.
        for copy in ("checkpoint_damaged", "checkpoint_other_entries"):
            shutil.copytree(directory, fresh(copy))
    if stop_signal == signal.SIGINT:
        checks.check("Interrupted by signal 2" in output
                     and os.path.exists(os.path.join(directory, "history.incomplete.h5")),
                     f"{name}: the run says it was interrupted and keeps history.incomplete.h5")
    code, output = run(directory)
    step = resumed_step(output)
    checks.check(code == 0 and step is not None and 0 < step < steps,
                 f"{name}: run again, it resumed from step {step} of {steps} (exit {code})")
    if code != 0:
        print(output)
    else:
        same_as_reference(name, directory)

# 3. Damaged after its stamp: an error that names the checkpoint, not a run from a torn state.
directory = os.path.join(work, "checkpoint_damaged")
part = os.path.join(directory, "checkpoint", "rank-0.bin")
size = os.path.getsize(part) if os.path.exists(part) else 0
if size:
    with open(part, "r+b") as f:
        f.truncate(size // 2)
code, output = run(directory)
checks.check(size > 0 and code == 1 and "checkpoint" in output and "cannot be read" in output
             and "remove it" in output
             and not os.path.exists(os.path.join(directory, "summary.json")),
             f"damaged checkpoint: exit {code}, the message names it and what to do: "
             f"{output.strip().splitlines()[-1] if output.strip() else ''}")

# 4. Another run's checkpoint: not resumed (the other run ends early, to be quick).
directory = os.path.join(work, "checkpoint_other_entries")
code, output = run(directory, {"Scenario/Impact velocity": 2.5,
                               "Time integration/Maximum time": 5e-6})
checks.check(code == 0 and resumed_step(output) is None
             and summary(directory)["impact_velocity"] == 2.5
             and not os.path.exists(os.path.join(directory, "checkpoint")),
             f"a checkpoint of other entries is not resumed: the run starts from the first contact "
             f"(exit {code})")

# 5. Two ranks: each rank writes and reads its own part.
if not mpiexec:
    checks.check(False, "an mpiexec to run two ranks")
else:
    ranks = 2
    SETTINGS["Solver/Direct solver"] = "Amesos_Klu"
    reference = fresh("checkpoint_reference_2_ranks")
    code, output = run(reference)
    checks.check(code == 0, f"two ranks: reference run (exit {code})")
    reference_summary = summary(reference)
    reference_summary.pop("wall_time")
    directory = fresh("checkpoint_sigterm_2_ranks")
    code, output = stopped(directory, signal.SIGTERM)
    kept = all(os.path.isfile(os.path.join(directory, "checkpoint", f"rank-{r}.bin"))
               for r in (0, 1))
    checks.check(code != 0 and kept, f"two ranks: stopped by SIGTERM (exit {code}), "
                 "checkpoint/rank-0.bin and rank-1.bin kept")
    code, output = run(directory)
    step = resumed_step(output)
    checks.check(code == 0 and step is not None and step > 0,
                 f"two ranks: run again, it resumed from step {step} (exit {code})")
    if code == 0:
        same_as_reference("two ranks", directory)
    else:
        print(output)
checks.finish()
