"""Bad `--set` values, a bounded fuzz of impact-fem's entries: for each entry
of a scenario a handful of values it cannot take (text, NaN, +-inf, 1e400,
1e+-300, 5e-324, 0, -1, out of its range, the range's finite extremes). Each case must exit with status 2
(bad input), name the entry in its message, end within the time limit (no
hang, no signal) and leave nothing in the output directory: no history.h5,
history.incomplete.h5 or summary.json."""
import os
import shutil
import subprocess
from fem_test_lib import *

binary, work, _ = parse_common_arguments()
checks = Checks()
small = {"Mesh/Contact element size": 200e-6}
special = ["fast", "nan", "inf", "-inf", "1e400", ""]
plastic = {"Sphere/Material model": "elastic-plastic"}

# (entry, values, other settings of the case)
# Finite extremes refused by a range (before it, 1e-300 m/s, a 1e300 m gap or plate,
# 1e300 steps per contact time or a 1e-300 s time step ended in a solver or gmsh failure,
# exit 1, or did not end).
cases = [
    ("Scenario/Impact velocity", special + ["0", "-1", "1e300", "-5e-324", "5e-324", "1e-300"], {}),
    ("Scenario/Sphere radius", special + ["0", "-1", "1e300"], {}),
    ("Scenario/Plate thickness", special + ["0", "-0.01", "1e300"], {}),
    ("Scenario/Plate radius", ["0.01", "1e300"], {}),
    ("Scenario/Initial gap", ["-1e-3", "nan", "1,2", "1e300"], {}),
    ("Mesh/Contact element size", special + ["0", "-1e-5", "1e300"], {}),
    ("Mesh/Growth factor", ["0.5", "1e300", "x"], {}),
    ("Sphere/Elastic/Poisson's ratio", ["0.5", "-1", "1e300", "nan"], {}),
    ("Sphere/Elastic/Young's modulus", ["0", "-2e11", "1e400", "abc"], {}),
    ("Sphere/Material model", ["steel", "0"], {}),
    ("Time integration/Steps per contact time", ["0", "5", "-1e300", "many", "1e300"], {}),
    ("Time integration/Time step", ["-1", "1e-300", "1e300"], {}),
    ("Time integration/Time after separation", ["-1", "1e300"], {}),
    ("Sphere/Yield strength", ["0", "-1e8", "nan"], plastic),
]


def run_case(index, entry, value, settings):
    directory = f"{work}/set_value_{index}"
    shutil.rmtree(directory, ignore_errors=True)
    command = [binary, STEEL_PRM, "--set", "Output/Directory=" + directory] + \
        sets(dict(small, **settings)) + ["--set", f"{entry}={value}"]
    try:
        result = subprocess.run(command, capture_output=True, text=True, timeout=120)
    except subprocess.TimeoutExpired:
        return None, "", directory
    return result.returncode, result.stdout + result.stderr, directory


index = 0
for entry, values, settings in cases:
    for value in values:
        index += 1
        code, output, directory = run_case(index, entry, value, settings)
        last = " ".join(line.strip() for line in output.strip().splitlines()[-4:])[:240]
        label = f"--set \"{entry}={value}\""
        print(f"{label}: exit {code}: {last}")
        checks.check(code == 2, f"{label}: exit status 2 (got {code})")
        checks.check(entry.split("/")[-1].lower() in output.lower(),
                     f"{label}: the message names the entry")
        left = [name for name in ("history.h5", "history.incomplete.h5", "summary.json")
                if os.path.exists(os.path.join(directory, name))]
        checks.check(not left, f"{label}: nothing written ({', '.join(left) or 'none'})")
checks.finish()
