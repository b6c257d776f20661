"""Sub-steps at contact entry (Time integration/Sub-steps at contact entry): a step in which
the contact's active set changes is taken again as n sub-steps, and so is the step after it.

The work a node's pressure does over the gap it closes (or opens) within its step is the contact
activation's error, first order in the step: with n sub-steps it must fall about n times, like
that of a step n times finer, and the energy balance with it, while the force, the approach, the
contact time and the restitution stay those of the finer step.

Cases (fem/scenarios/plastic_on_rigid.prm: a 52100 ball on a rigid flat, 100 steps per contact
time, 17 contact nodes): the scenario as it is ("auto": no sub-steps), 4 sub-steps, and 400 steps
per contact time (the reference: the step 4 times finer everywhere); a Maxwell body, which cannot
take them (its tangent is made for one step), and entries out of range.
argv: impact-fem, work directory, mpiexec."""
import json
import os
import shutil
import subprocess

import h5py
import numpy as np

from fem_test_lib import STEEL_PRM, Checks, maxwell_bodies, parse_common_arguments, sets

binary, work, mpiexec = parse_common_arguments()
checks = Checks()
SCENARIOS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "fem", "scenarios")
ENTRY = "Time integration/Sub-steps at contact entry"


def run(scenario, name, settings, expect_success=True):
    directory = os.path.join(work, "sub_steps_" + name)
    if os.path.isdir(directory):
        shutil.rmtree(directory)
    command = [binary, os.path.join(SCENARIOS, scenario), "--set", "Output/Directory=" + directory]
    if os.path.isabs(scenario):
        command[1] = scenario
    command += sets(settings)
    result = subprocess.run(command, capture_output=True, text=True)
    output = result.stdout + result.stderr
    if expect_success and result.returncode != 0:
        print(output)
    checks.check((result.returncode == 0) == expect_success,
                 f"{name}: exit {result.returncode}")
    return directory, output


def measured(directory):
    with open(os.path.join(directory, "summary.json")) as f:
        s = json.load(f)
    with h5py.File(os.path.join(directory, "history.h5"), "r") as f:
        energy = f["kinetic_energy"][0]
        s["largest_activation"] = np.abs(f["contact_work"][:]).max() / energy
        s["largest_balance"] = np.abs(f["energy_error"][:]).max()
        steps = np.diff(f["time"][:])
        s["smallest_step_ratio"] = steps.min() / steps.max()
    return s


plain_dir, _ = run("plastic_on_rigid.prm", "none", {})
divided_dir, divided_log = run("plastic_on_rigid.prm", "four", {ENTRY: 4})
finer_dir, _ = run("plastic_on_rigid.prm", "finer",
                   {"Time integration/Steps per contact time": 400})
plain, divided, finer = (measured(d) for d in (plain_dir, divided_dir, finer_dir))

# What each run says it did.
entry = plain["discretisation"]["entries"][ENTRY]
checks.check(entry["value"] == 1 and entry["origin"] == "auto"
             and plain["steps_divided_at_contact_entry"] == 0
             and plain["smallest_step_ratio"] > 1 - 1e-9,
             f"auto: no sub-steps ({entry['value']}, {entry['origin']}), "
             f"{plain['steps_divided_at_contact_entry']} steps divided")
entry = divided["discretisation"]["entries"][ENTRY]
checks.check(entry["value"] == 4 and entry["origin"] == "scenario"
             and "taken as 4 sub-steps" in divided_log,
             f"4 sub-steps: the summary records {entry['value']} ({entry['origin']}), the log says so")
checks.check(divided["steps_divided_at_contact_entry"] > 0
             and abs(divided["smallest_step_ratio"] - 0.25) <= 1e-9
             and divided["time_step"] == plain["time_step"],
             f"4 sub-steps: {divided['steps_divided_at_contact_entry']} steps divided, the smallest "
             f"step {divided['smallest_step_ratio']:.12f} of the step, the step itself unchanged")

# The activation's work and the balance fall as with a 4 times finer step.
for name, s in (("auto", plain), ("4 sub-steps", divided), ("400 steps", finer)):
    print(f"{name}: largest |contact work| {s['largest_activation']:.3e}, largest |balance| "
          f"{s['largest_balance']:.3e}, final {s['energy_error_final']:.3e}; F_max "
          f"{s['force_max']:.2f} N, x_max {s['approach_max'] * 1e6:.4f} um, t_c "
          f"{s['contact_time'] * 1e6:.4f} us, e {s['restitution']:.6f}; wall {s['wall_time']:.2f} s")
checks.check(divided["largest_activation"] <= plain["largest_activation"] / 4,
             f"the largest contact work falls at least 4 times with 4 sub-steps "
             f"({plain['largest_activation']:.3g} -> {divided['largest_activation']:.3g})")
checks.check(divided["largest_activation"] <= 1.5 * finer["largest_activation"],
             f"... to that of the 4 times finer step within 50 % "
             f"({finer['largest_activation']:.3g})")
checks.check(divided["largest_balance"] <= plain["largest_balance"] / 4
             and abs(divided["energy_error_final"]) <= 1e-4,
             f"the balance's largest error falls at least 4 times "
             f"({plain['largest_balance']:.3g} -> {divided['largest_balance']:.3g}) and ends "
             f"within 1e-4 ({divided['energy_error_final']:.3g})")
# The results move toward the finer step's, not away: each within the plain run's distance
# from it (and that is small: the step's own error).
for key in ("force_max", "approach_max", "contact_time", "restitution"):
    off_plain = abs(plain[key] - finer[key])
    off_divided = abs(divided[key] - finer[key])
    checks.check(off_divided <= max(1.2 * off_plain, 1e-4 * abs(finer[key])),
                 f"{key}: 4 sub-steps {divided[key]:.8g} is {off_divided:.3g} from the finer "
                 f"step's {finer[key]:.8g} (the plain run {off_plain:.3g})")

# Maxwell arms: their tangent is made for one step length; the run says so and divides none.
maxwell = {**maxwell_bodies(), "Mesh/Contact element size": 100e-6,
           "Time integration/Steps per contact time": 150, ENTRY: 4}
maxwell_dir, maxwell_log = run(STEEL_PRM, "maxwell", maxwell)
s = measured(maxwell_dir)
checks.check("no sub-steps at contact entry: a body has Maxwell arms" in maxwell_log
             and s["steps_divided_at_contact_entry"] == 0,
             f"Maxwell bodies: no sub-steps ({s['steps_divided_at_contact_entry']} divided)")

# Entries outside [1, 64] or not integers: refused, naming the entry, no results.
for value in ("0", "65", "2.5", "-1", "nan", "many"):
    directory, log = run("plastic_on_rigid.prm", "bad", {ENTRY: value}, expect_success=False)
    checks.check("Sub-steps at contact entry" in log
                 and not os.path.exists(os.path.join(directory, "summary.json")),
                 f"'{value}' refused: {log.strip().splitlines()[-1] if log.strip() else ''}")
checks.finish()
