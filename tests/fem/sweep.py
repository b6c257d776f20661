"""Campaign over a parameter sweep on 2 ranks: names, index,
the runs' parameters, restart with damaged runs, moved and copied campaigns,
bad sweep options.

Sweep: Scenario/Plate bottom = absorbing (one value: a text axis),
Scenario/Plate thickness = 0.1, 0.35 (m), velocities 0.5, 1 m/s -> 4 runs
on a coarse mesh (100 um contact elements, 300 steps per contact time).
Checks:
- bad --sweep / Campaign/Sweep options: exit status 2, the message names
  the option and the entry, no directory created;
- the run directories are exactly those of fem/README.md, index.json has
  the axes (values as numbers or text), the paths in order, each run's
  point; each parameters.prm and the history.h5 text attributes carry the
  point; `sha256sum -c checksums.sha256` (coreutils, not our code) accepts
  every run; the thinner plate changes the restitution (the point applied);
- restart untouched: all 4 skipped, summary.json untouched;
- history.h5 truncated to a third: exactly that run "damaged, redone", its
  file whole again, the index unchanged;
- summary.json edited in one run, removed in another: both redone;
- an older run (no checksums.sha256, no Campaign/Sweep
  line, Output/Directory of another place): its parameters recognised, and
  redone once (no checksums);
- the campaign moved (mv) and copied (cp -r): every run skipped in the new
  place, nothing recomputed.
"""
import hashlib
import os
import re
import shutil
import subprocess
from fem_test_lib import *

binary, work, mpiexec = parse_common_arguments()
checks = Checks()
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
SETTINGS = ["--set", "Mesh/Contact element size=100e-6",
            "--set", "Time integration/Steps per contact time=300",
            "--set", "Output/Progress interval=0"]
SWEEP = ["--sweep", "Scenario/Plate bottom=absorbing",
         "--sweep", "Scenario/Plate thickness=0.1,0.35"]
VELOCITIES = ["--velocities", "0.5,1"]
THICKNESSES, SPEEDS = ["0.1", "0.35"], [0.5, 1.0]
PATHS = [f"plate-bottom-absorbing_plate-thickness-{h}_v{v:g}" for h in THICKNESSES for v in SPEEDS]


def campaign(directory, ranks=2, extra=SWEEP + VELOCITIES):
    command = [binary, STEEL_PRM, "--set", f"Output/Directory={directory}"] + SETTINGS + extra
    if ranks > 1:
        command = [mpiexec, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks)] + command
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    output = result.stdout + result.stderr
    return result.returncode, output


def status_of(output, path):
    """The restart status of a run: the text after "(<path>): " on its first line."""
    match = re.search(r"\(" + re.escape(path) + r"\): (.*)", output)
    return match.group(1) if match else ""


def load_index(directory):
    with open(f"{directory}/index.json") as f:
        return json.load(f)


def stamps(directory):
    return {p: os.stat(f"{directory}/{p}/summary.json").st_mtime_ns for p in PATHS}


def restart_skips_every_run(directory, before, label):
    """Restarts the campaign in `directory`: whether it exits 0, says "complete, skipped" for
    every run and leaves every summary.json as it was (`before`: their stamps)."""
    code, output = campaign(directory)
    print(f"--- {label} ---\n" + output)
    return (code == 0 and all(status_of(output, p) == "complete, skipped" for p in PATHS)
            and stamps(directory) == before)


# --- bad sweep options: refused before anything is written ---
bad = f"{work}/sweep_bad"
if os.path.isdir(bad):
    shutil.rmtree(bad)
cases = [
    (["--sweep", "Scenario/Plate thicknes=0.1,0.2"], ["--sweep", "Scenario/Plate thicknes", "no entry"]),
    (["--sweep", "Scenario/Plate thickness=0.1,thick"], ["--sweep", "<thick>", "Scenario/Plate thickness", "Double"]),
    (["--sweep", "Scenario/Plate bottom=absorbing,glued"], ["--sweep", "<glued>", "free|clamped|absorbing|support"]),
    (["--sweep", "Scenario/Plate thickness=0.1,0.10"], ["--sweep", "0.10", "given twice"]),
    (["--sweep", "Scenario/Plate thickness=0.1", "--sweep", "Scenario/Plate thickness=0.2"],
     ["--sweep", "Scenario/Plate thickness", "swept twice"]),
    (["--sweep", "Output/Directory=a,b"], ["--sweep", "Output/Directory", "cannot be swept"]),
    (["--sweep", "Campaign/Ranks per run=1,2"], ["--sweep", "Campaign/Ranks per run", "cannot be swept"]),
    (["--sweep", "Scenario/Impact velocity=1,2"], ["--sweep", "Scenario/Impact velocity", "--velocities"]),
    (["--sweep", "Scenario/Plate thickness"], ["--sweep", "Section/Entry=v1,v2,...", "no '='"]),
    (["--sweep", "Scenario/Plate thickness=0.1,-0.2"], ["Plate thickness = -0.2", "must be positive"]),
    (["--set", "Campaign/Sweep=Scenario/Plate thickness=0.1,0.2; Mesh/Contact size=1e-4"],
     ["Campaign/Sweep", "Mesh/Contact size", "no entry"]),
]
for arguments, words in cases:
    code, output = campaign(bad, ranks=1, extra=arguments + VELOCITIES)
    message = output.strip().splitlines()[-1] if output.strip() else ""
    print(f"{' '.join(arguments)}\n  -> exit {code}: {message}")
    checks.check(code == 2 and all(w in output for w in words) and not os.path.exists(bad),
                 f"refused, naming {words}, nothing written: {' '.join(arguments)}")

# --- the campaign ---
a = f"{work}/sweep_a"
for d in (a, a + "_moved", a + "_copy"):
    if os.path.isdir(d):
        shutil.rmtree(d)
code, output = campaign(a)
print(output)
checks.check(code == 0, "sweep campaign of 4 runs on 2 ranks")
checks.check(all(f"Plate thickness = {h}, V = {v:g} m/s" in output for h in THICKNESSES for v in SPEEDS),
             "progress lines name the point")
directories = sorted(e for e in os.listdir(a) if os.path.isdir(f"{a}/{e}"))
checks.check(directories == sorted(PATHS), f"run directories {directories}")
index = load_index(a)
print("index.json:", json.dumps(index))
checks.check(index["axes"] == [{"parameter": "Scenario/Plate bottom", "values": ["absorbing"]},
                               {"parameter": "Scenario/Plate thickness", "values": [0.1, 0.35]},
                               {"parameter": "Scenario/Impact velocity", "values": [0.5, 1.0]}],
             "index axes: parameters and values (number or text) in the order given, velocity last")
expected_runs = [{"path": f"plate-bottom-absorbing_plate-thickness-{h}_v{v:g}", "velocity": v,
                  "point": {"Scenario/Plate bottom": "absorbing", "Scenario/Plate thickness": float(h),
                            "Scenario/Impact velocity": v}}
                 for h in THICKNESSES for v in SPEEDS]
checks.check(index["runs"] == expected_runs, "index runs: paths, velocities and points in order")

import h5py
restitution = {}
for run in expected_runs:
    d = f"{a}/{run['path']}"
    with open(f"{d}/parameters.prm") as f:
        text = f.read()
    scenario = text[text.index("subsection Scenario"):]
    scenario = scenario[:scenario.index("\nend")]
    h, v = run["point"]["Scenario/Plate thickness"], run["velocity"]
    entries = dict(re.findall(r"set (.+?)\s*= (.*)", scenario))
    checks.check(float(entries["Plate thickness"]) == h and float(entries["Impact velocity"]) == v
                 and entries["Plate bottom"] == "absorbing",
                 f"{run['path']}/parameters.prm: Plate thickness = {entries['Plate thickness']}, "
                 f"Impact velocity = {entries['Impact velocity']}")
    with h5py.File(f"{d}/history.h5", "r") as f:
        attributes = (f.attrs["Scenario/Plate thickness"], f.attrs["Scenario/Impact velocity"])
    checks.check(float(attributes[0]) == h and float(attributes[1]) == v,
                 f"{run['path']}/history.h5 attributes Plate thickness {attributes[0]}, velocity {attributes[1]}")
    checked = subprocess.run(["sha256sum", "-c", "checksums.sha256"], cwd=d, capture_output=True, text=True)
    checks.check(checked.returncode == 0 and checked.stdout.count(": OK") == 3,
                 f"sha256sum -c accepts {run['path']}: {checked.stdout.split()}")
    restitution[(h, v)] = summary(d)["restitution"]
    print(f"{run['path']}: restitution {restitution[(h, v)]:.6f}")
for v in SPEEDS:
    checks.check(abs(restitution[(0.1, v)] - restitution[(0.35, v)]) > 1e-4,
                 f"V = {v:g}: the plate thickness changes the restitution "
                 f"({restitution[(0.1, v)]:.6f} vs {restitution[(0.35, v)]:.6f})")

# --- restart: untouched ---
before = stamps(a)
checks.check(restart_skips_every_run(a, before, "restart, untouched"),
             "untouched: every run skipped, summary.json untouched")
checks.check(load_index(a) == index, "untouched: same index")

# --- restart: history.h5 truncated to a third ---
damaged = PATHS[1]
history_file = f"{a}/{damaged}/history.h5"
size = os.path.getsize(history_file)
with open(history_file, "r+b") as f:
    f.truncate(size // 3)
code, output = campaign(a)
print(f"--- restart, {damaged}/history.h5 truncated from {size} to {size // 3} bytes ---\n" + output)
others = [p for p in PATHS if p != damaged]
checks.check(code == 0 and status_of(output, damaged) == "damaged, redone (history.h5: checksum differs)"
             and all(status_of(output, p) == "complete, skipped" for p in others),
             "truncated history.h5: exactly that run damaged, redone; the others skipped")
checks.check(all(stamps(a)[p] == before[p] for p in others), "the other runs untouched")
with h5py.File(history_file, "r") as f:
    whole = f.attrs["status"] == "complete" and len(f["time"][:]) > 100
checks.check(whole and os.path.getsize(history_file) >= size * 0.9,
             f"the redone history.h5 is whole ({os.path.getsize(history_file)} bytes)")
checks.check(load_index(a) == index, "index fine after the redone run")
checks.check(summary(f"{a}/{damaged}")["restitution"] == restitution[(0.1, 1.0)],
             "the redone run has the same restitution")

# --- restart: summary.json edited in one run, removed in another ---
edited, removed = PATHS[2], PATHS[3]
with open(f"{a}/{edited}/summary.json") as f:
    text = f.read()
with open(f"{a}/{edited}/summary.json", "w") as f:
    f.write(re.sub(r'"restitution": [0-9.e+-]+', '"restitution": 0.5', text))
os.remove(f"{a}/{removed}/summary.json")
code, output = campaign(a)
print("--- restart, summary.json edited / removed ---\n" + output)
checks.check(code == 0 and status_of(output, edited) == "damaged, redone (summary.json: checksum differs)"
             and status_of(output, removed) == "damaged, redone (summary.json: missing)"
             and status_of(output, PATHS[0]) == "complete, skipped" and status_of(output, PATHS[1]) == "complete, skipped",
             "edited and removed summary.json: those runs damaged, redone, the others skipped")
checks.check(summary(f"{a}/{edited}")["restitution"] == restitution[(0.35, 0.5)] and
             os.path.exists(f"{a}/{removed}/summary.json"), "their summaries written anew")
checks.check(load_index(a) == index, "index fine")

# --- restart: a run as written before checksums and sweeps: no checksums, no
# Campaign/Sweep line, Output/Directory of another place ---
old_style = f"{a}/{PATHS[0]}"
os.remove(f"{old_style}/checksums.sha256")
with open(f"{old_style}/parameters.prm") as f:
    text = f.read()
text = re.sub(r"\n *set Sweep *=.*", "", text)
text = re.sub(r"set Directory( *)= .*", r"set Directory\1= /elsewhere/old-campaign/v0.5", text)
with open(f"{old_style}/parameters.prm", "w") as f:
    f.write(text)
code, output = campaign(a)
print("--- restart, a run in the form written before checksums and sweeps ---\n" + output)
checks.check(code == 0 and status_of(output, PATHS[0]) == "no checksums (run before they were kept), redone" and
             os.path.exists(f"{a}/{PATHS[0]}/checksums.sha256") and
             all(status_of(output, p) == "complete, skipped" for p in PATHS[1:]),
             "a run written before checksums: parameters recognised, redone once; the others skipped")

# --- moved and copied ---
moved, copy = a + "_moved", a + "_copy"
before = stamps(a)
os.rename(a, moved)
checks.check(restart_skips_every_run(moved, before, "moved") and not os.path.exists(a),
             "moved campaign: every run recognised, nothing recomputed")
checks.check(load_index(moved) == index, "moved campaign: same index")
subprocess.run(["cp", "-r", moved, copy], check=True)
checks.check(restart_skips_every_run(copy, stamps(copy), "copied"),
             "copied campaign: every run recognised, nothing recomputed")
checks.check(load_index(copy) == index, "copied campaign: same index")
code, output = campaign(moved)
checks.check(code == 0 and output.count("complete, skipped") == 4, "the original, after the copy: all skipped")
checks.finish()
