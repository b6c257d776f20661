"""The verification mode (spec verification 7) on a small case.

impact-fem --verify runs the scenario (the fine level) and two coarser ones
(element sizes and time step times 1.5 and 2.25) and writes
verification.json: checked here for its format, the three levels, the
fine level being the run itself, and the observed order, Richardson
extrapolation and GCI of each quantity recomputed from the three values
(Celik et al. 2008, Fs = 1.25, order capped at 2; Fs = 3 on the largest
difference for a non-monotone sequence). A campaign with --verify links
each run's verification.json from index.json, and a restart skips the
verified runs; a complete campaign verified later keeps its runs, and so
does one stopped in a coarser level (its fine level certified before them). Bad input
(refinement ratio below 1.5, a coarsest level with fewer than 10 steps per
contact time, nested meshes with a ratio other than 2 or fewer than two
contact refinements) stops with a message naming the entry and writes no
verification.json. Nested levels (Verification/Meshes = nested) drop one
contact refinement each.
"""
import math
import os
import re
import shutil
import signal
import subprocess
import time
from fem_test_lib import *

binary, work, _ = parse_common_arguments()
checks = Checks()
SMALL = {"Mesh/Contact element size": 100e-6, "Time integration/Steps per contact time": 150,
         "Scenario/Plate radius": 0.05, "Scenario/Plate thickness": 0.05,
         "Mesh/Maximum element size": 5e-3}
for body in ("Sphere", "Plate"):
    SMALL.update({f"{body}/Material model": "kelvin-voigt",
                  f"{body}/Kelvin-voigt/Retardation time": 1.147e-6})
QUANTITIES = ("contact_time", "force_max", "time_force_max", "approach_max", "restitution")


def verify(directory, settings, extra=()):
    if os.path.isdir(directory):
        shutil.rmtree(directory)
    command = [binary, STEEL_PRM, "--set", "Output/Directory=" + directory, "--verify", *extra]
    return subprocess.run(command + sets(settings), capture_output=True, text=True)


def expected(f1, f2, f3, r):
    """(order, extrapolated, absolute GCI, convergence) by the formulas."""
    e21, e32 = f2 - f1, f3 - f2
    if e21 == 0:
        return None, f1, 0.0, "monotone"
    R = e21 / e32 if e32 != 0 else math.inf
    if 0 < R < 1:
        p = math.log(e32 / e21) / math.log(r)
        return p, (r ** p * f1 - f2) / (r ** p - 1), 1.25 * abs(e21) / (r ** min(p, 2) - 1), "monotone"
    return None, None, 3 * max(abs(e21), abs(e32)), "oscillatory" if R < 0 else "divergent"


directory = f"{work}/verification_single"
result = verify(directory, SMALL)
print(result.stdout[-1500:])
checks.check(result.returncode == 0, "--verify runs")
with open(f"{directory}/verification.json") as f:
    v = json.load(f)
checks.check(v["format"] == "impact-verification" and v["format_version"] == 1, "format and version")
r = v["refinement_ratio"]
checks.check(r == 1.5 and [level["name"] for level in v["levels"]] == ["fine", "medium", "coarse"],
             "three levels fine/medium/coarse, r = 1.5")
steps = [level["time_step"] for level in v["levels"]]
sizes = [level["contact_element_size"] for level in v["levels"]]
dofs = [level["dofs"] for level in v["levels"]]
checks.check(all(abs(steps[i + 1] / steps[i] - r) < 1e-9 and abs(sizes[i + 1] / sizes[i] - r) < 1e-12
                 for i in range(2)), f"time step and contact element size grow by r: {steps}, {sizes}")
checks.check(dofs[0] > dofs[1] > dofs[2], f"the levels get coarser: {dofs} dofs")
run_summary = summary(directory)
for name in QUANTITIES:
    q = v["quantities"][name]
    checks.check(q["fine"] == run_summary[name], f"{name}: the fine level is the run itself")
    order, extrapolated, gci, convergence = expected(q["fine"], q["medium"], q["coarse"], r)
    same = (q["convergence"] == convergence and abs(q["gci_fine_absolute"] - gci) <= 1e-12 * abs(q["fine"])
            and (order is None) == (q["observed_order"] is None)
            and (order is None or abs(q["observed_order"] - order) < 1e-9)
            and (extrapolated is None or abs(q["extrapolated"] - extrapolated) <= 1e-12 * abs(q["fine"])))
    print(f"{name}: {q['fine']:.8g} {q['medium']:.8g} {q['coarse']:.8g}, {q['convergence']}, "
          f"observed order {q['observed_order']}, extrapolated {q['extrapolated']}, GCI {q['gci_fine']:.3%}")
    checks.check(same, f"{name}: order, extrapolation and GCI as recomputed")
    checks.check(abs(q["gci_fine"] - q["gci_fine_absolute"] / abs(q["fine"])) < 1e-15,
                 f"{name}: relative GCI = absolute / |fine|")

# A coarser level made before with the same entries and complete is kept (a verification stopped
# in its last level keeps the others): the same --verify again makes only the fine level, with the
# same verification.json; a level that did not finish, or whose entries changed, is made again.
again_command = [binary, STEEL_PRM, "--set", "Output/Directory=" + directory, "--verify"] + \
    sets(SMALL)
stamps = [os.stat(f"{directory}/verification/level{k}/summary.json").st_mtime_ns for k in (1, 2)]
again = subprocess.run(again_command, capture_output=True, text=True)
with open(f"{directory}/verification.json") as f:
    v_again = json.load(f)
checks.check(again.returncode == 0 and all(f"verification: level {k} kept" in again.stdout
                                           for k in (1, 2))
             and [os.stat(f"{directory}/verification/level{k}/summary.json").st_mtime_ns
                  for k in (1, 2)] == stamps
             and v_again["quantities"] == v["quantities"],
             "the same --verify again keeps both coarser levels, and the same result")
os.remove(f"{directory}/verification/level2/summary.json")
partial = subprocess.run(again_command, capture_output=True, text=True)
checks.check(partial.returncode == 0 and "verification: level 1 kept" in partial.stdout
             and "verification: level 2 kept" not in partial.stdout
             and os.path.exists(f"{directory}/verification/level2/summary.json"),
             "a level without its summary is made again, the other kept")
changed = subprocess.run(again_command + ["--set", "Time integration/Steps per contact time=160"],
                         capture_output=True, text=True)
checks.check(changed.returncode == 0 and "kept" not in changed.stdout,
             "a changed step makes both coarser levels again")

# A campaign verifies every run and links the files; a restart skips them.
campaign = f"{work}/verification_campaign"
result = verify(campaign, SMALL, ("--velocities", "1,2"))
checks.check(result.returncode == 0, "a verified campaign runs")
with open(f"{campaign}/index.json") as f:
    index = json.load(f)
checks.check([run.get("verification") for run in index["runs"]] == ["v1/verification.json", "v2/verification.json"],
             "index.json links each run's verification.json")
again = subprocess.run([binary, STEEL_PRM, "--set", f"Output/Directory={campaign}", "--verify", "--velocities", "1,2"]
                       + sets(SMALL),
                       capture_output=True, text=True)
checks.check(again.returncode == 0 and again.stdout.count("complete, skipped") == 2,
             "a restart skips the verified runs")
# verification.json is covered by the run's checksums, and a run
# redone because it is damaged is verified anew (its old verification.json
# is not trusted).
with open(f"{campaign}/v2/checksums.sha256") as f:
    checksummed = [line.split()[1] for line in f]
checks.check("verification.json" in checksummed, f"checksums.sha256 covers {checksummed}")
stamp = os.stat(f"{campaign}/v2/verification.json").st_mtime_ns
history_file = f"{campaign}/v2/history.h5"
with open(history_file, "r+b") as f:
    f.truncate(os.path.getsize(history_file) // 3)
redone = subprocess.run(again.args, capture_output=True, text=True)
print(redone.stdout)
checks.check(redone.returncode == 0 and "(v2): damaged, redone (history.h5: checksum differs)" in redone.stdout
             and "(v1): complete, skipped" in redone.stdout
             and os.stat(f"{campaign}/v2/verification.json").st_mtime_ns != stamp,
             "a damaged verified run is redone and verified anew, the other skipped")
with open(f"{campaign}/index.json") as f:
    checks.check(json.load(f) == index, "the index is the same after the redone run")
# Unverified runs are verified later without running them again.
plain = f"{work}/verification_later"
if os.path.isdir(plain):
    shutil.rmtree(plain)
base = [binary, STEEL_PRM, "--set", f"Output/Directory={plain}", "--velocities", "1"] + \
       sets(SMALL)
first = subprocess.run(base, capture_output=True, text=True)
wall = summary(f"{plain}/v1")["wall_time"]
later = subprocess.run(base + ["--verify"], capture_output=True, text=True)
checks.check(later.returncode == 0 and "complete, verifying" in later.stdout and
             os.path.exists(f"{plain}/v1/verification.json") and summary(f"{plain}/v1")["wall_time"] == wall,
             "a complete run is verified later and kept")

# A verified campaign stopped in a coarser level (here by SIGKILL, as a job's time limit may)
# keeps its fine level: the fine level is certified before the coarser levels are made, so the
# restart finds the run complete and only verifies it.
stopped = f"{work}/verification_stopped"
if os.path.isdir(stopped):
    shutil.rmtree(stopped)
base = [binary, STEEL_PRM, "--set", f"Output/Directory={stopped}", "--velocities", "1", "--verify"] + \
       sets(SMALL)
process = subprocess.Popen(base, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                           start_new_session=True)
while process.poll() is None and not os.path.exists(f"{stopped}/v1/verification/level1/parameters.prm"):
    time.sleep(0.005)
in_level1 = process.poll() is None
if in_level1:
    os.killpg(process.pid, signal.SIGKILL)
output, _ = process.communicate()
print(output[-600:])
checks.check(in_level1, "the verified campaign is stopped while its level 1 runs")
with open(f"{stopped}/v1/checksums.sha256") as f:
    certified = sorted(line.split()[1] for line in f)
checks.check(certified == ["history.h5", "parameters.prm", "summary.json"]
             and not os.path.exists(f"{stopped}/v1/verification.json"),
             f"the stopped run's fine level is certified, without a verification: {certified}")
wall = summary(f"{stopped}/v1")["wall_time"]
resumed = subprocess.run(base, capture_output=True, text=True)
print(resumed.stdout[-800:])
with open(f"{stopped}/v1/checksums.sha256") as f:
    certified = sorted(line.split()[1] for line in f)
with open(f"{stopped}/index.json") as f:
    linked = [run.get("verification") for run in json.load(f)["runs"]]
checks.check(resumed.returncode == 0 and "(v1): complete, verifying" in resumed.stdout
             and summary(f"{stopped}/v1")["wall_time"] == wall
             and "verification.json" in certified and linked == ["v1/verification.json"],
             "the restart keeps the fine level, verifies it, and certifies and links verification.json")

# Nested levels: one contact refinement fewer per level, ratio 2, the
# contact element size doubling and the mesh beyond the contact surface the
# same (the fine level's cells outnumber the medium's by less than 4).
nested = f"{work}/verification_nested"
NESTED = dict(SMALL, **{"Mesh/Contact element size": 200e-6, "Mesh/Contact refinements": 2,
                        "Verification/Refinement ratio": 2, "Verification/Meshes": "nested"})
result = verify(nested, NESTED)
print(result.stdout[-1200:])
checks.check(result.returncode == 0, "--verify with nested meshes runs")
with open(f"{nested}/verification.json") as f:
    v = json.load(f)
levels = v["levels"]
sizes = [level["contact_element_size"] for level in levels]
steps = [level["time_step"] for level in levels]
cells = [level["cells"] for level in levels]
checks.check(v["meshes"] == "nested" and v["refinement_ratio"] == 2 and sizes == [50e-6, 100e-6, 200e-6]
             and all(abs(steps[i + 1] / steps[i] - 2) < 1e-9 for i in range(2)),
             f"nested levels: contact element sizes {sizes}, time steps {steps}")
checks.check(cells[0] > cells[1] > cells[2] and cells[0] < 4 * cells[1],
             f"only the contact zone is refined: {cells} cells")
meshes = []
for level in ("", "/verification/level1", "/verification/level2"):
    with open(f"{nested}{level}/mesh.msh", "rb") as f:
        meshes.append(f.read())
checks.check(meshes[0] == meshes[1] == meshes[2], "the three levels refine the same gmsh mesh")
checks.check(all(f"verification: level {level} (contact refinements {2 - level}," in result.stdout
                 for level in (0, 1, 2)), "the levels have 2, 1 and 0 contact refinements")

# Bad input.
NESTED_2 = dict(SMALL, **{"Verification/Meshes": "nested", "Verification/Refinement ratio": 2})
for base, entry, value, words in ((SMALL, "Verification/Refinement ratio", 1.2, "Refinement ratio must lie in [1.5, 3], got 1.2."),
                                  (SMALL, "Time integration/Steps per contact time", 20,
                                   "Steps per contact time"),
                                  (SMALL, "Verification/Meshes", "nested", "got 1.5."),
                                  (NESTED_2, "Mesh/Contact refinements", 1, "Contact refinements >= 2")):
    directory = f"{work}/verification_bad"
    result = verify(directory, dict(base, **{entry: value}))
    message = result.stderr.strip().splitlines()[-1] if result.stderr.strip() else ""
    print(f"{entry} = {value}: exit {result.returncode}: {message}")
    checks.check(result.returncode != 0 and words in result.stderr and
                 not os.path.exists(f"{directory}/verification.json"),
                 f"{entry} = {value} is refused, naming the entry, without verification.json")
checks.finish()
