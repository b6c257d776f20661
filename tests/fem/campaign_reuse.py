"""A campaign keeps a complete run when only entries that cannot change its
results beyond the solvers' tolerances changed (fem/README.md, "Campaigns":
the nonlinear and contact iteration limits, the nonlinear iteration's strategy and
Anderson depth, the direct solver, the output options), and runs it again when a
physical entry changed.
One run (1 m/s) of the tests' steel bodies on the coarse mesh of sweep.py
(100 um contact elements), one rank:
- restarted with Nonlinear solver/Maximum iterations, Strategy, Anderson depth,
  Contact/Maximum active set iterations, Solver/Direct solver, Output/Snapshot
  interval and Output/Progress interval changed: "complete, skipped", summary.json untouched;
- restarted with the sphere's Young's modulus changed: "parameters changed",
  run again, its restitution and peak force those of the new modulus;
- restarted with Nonlinear solver/Residual tolerance changed (a tolerance is part of
  the run): run again;
- its summary.json made one of an earlier build (no summary_version, its checksum
  updated so that only the version differs): run again, the status naming the
  versions, the new summary.json of this build's version."""
import hashlib
import json
import os
import re
import shutil
import subprocess
from fem_test_lib import *

binary, work, _ = parse_common_arguments()
checks = Checks()
directory = f"{work}/campaign_reuse"
shutil.rmtree(directory, ignore_errors=True)
BASE = ["--velocities", "1", "--set", "Mesh/Contact element size=100e-6",
        "--set", "Time integration/Steps per contact time=300"]
RUN = f"{directory}/v1"


def campaign(label, settings):
    command = [binary, STEEL_PRM, "--set", f"Output/Directory={directory}"] + BASE + sets(settings)
    result = subprocess.run(command, capture_output=True, text=True, timeout=600)
    output = result.stdout + result.stderr
    match = re.search(r"\(v1\): (.*)", output)
    status = match.group(1) if match else ""
    print(f"--- {label}: exit {result.returncode}, status: {status}")
    if result.returncode != 0:
        print(output)
    return result.returncode, status


def stamp():
    return os.stat(f"{RUN}/summary.json").st_mtime_ns


code, status = campaign("first", {})
checks.check(code == 0 and os.path.exists(f"{RUN}/summary.json"), "the first campaign completes its run")
first = summary(RUN)
before = stamp()

not_identity = {"Nonlinear solver/Maximum iterations": 300,
                "Nonlinear solver/Strategy": "modified newton",
                "Nonlinear solver/Anderson depth": 7,
                "Contact/Maximum active set iterations": 500,
                "Solver/Direct solver": "Amesos_Klu",
                "Output/Snapshot interval": 1e-5,
                "Output/Progress interval": 0}
for key, value in not_identity.items():
    code, status = campaign(f"{key} = {value}", {key: value})
    checks.check(code == 0 and status == "complete, skipped" and stamp() == before,
                 f"{key} changed to {value}: the complete run is kept (status '{status}')")
code, status = campaign("all of them", not_identity)
checks.check(code == 0 and status == "complete, skipped" and stamp() == before,
             f"all of them changed at once: the complete run is kept (status '{status}')")

code, status = campaign("Young's modulus", {"Sphere/Elastic/Young's modulus": 2.1e11})
second = summary(RUN) if code == 0 else {}
checks.check(code == 0 and status.startswith("parameters changed") and stamp() != before,
             f"the sphere's Young's modulus changed: the run is done again (status '{status}')")
if second:
    print(f"  F_max {first['force_max']:.6g} -> {second['force_max']:.6g} N")
    checks.check(second["force_max"] > first["force_max"] * 1.005,
                 "  ... with the new modulus: a stiffer sphere, a larger peak force")

before = stamp()
code, status = campaign("Residual tolerance", {"Sphere/Elastic/Young's modulus": 2.1e11,
                                               "Nonlinear solver/Residual tolerance": 1e-7})
checks.check(code == 0 and status.startswith("parameters changed") and stamp() != before,
             f"Nonlinear solver/Residual tolerance changed: the run is done again (status '{status}')")

# A summary of an earlier build: the peak force was then defined otherwise, so
# keeping the run would mix definitions within a campaign and its verification.
with open(f"{RUN}/summary.json") as f:
    old = json.load(f)
old.pop("summary_version", None)
with open(f"{RUN}/summary.json", "w") as f:
    json.dump(old, f, indent=2)
digest = hashlib.sha256(open(f"{RUN}/summary.json", "rb").read()).hexdigest()
manifest = open(f"{RUN}/checksums.sha256").read().splitlines()
with open(f"{RUN}/checksums.sha256", "w") as f:
    for line in manifest:
        f.write((f"{digest}  summary.json" if line.endswith("  summary.json") else line) + "\n")
before = stamp()
code, status = campaign("summary of an earlier build", {"Sphere/Elastic/Young's modulus": 2.1e11,
                                                        "Nonlinear solver/Residual tolerance": 1e-7})
checks.check(code == 0 and status.startswith("summary version 1, this build's is") and stamp() != before,
             f"a summary.json without summary_version: the run is done again (status '{status}')")
checks.check(summary(RUN).get("summary_version", 0) >= 2,
             "  ... and its new summary.json records this build's version")
checks.finish()
