"""Regression: run regression_coarse.prm and compare its derived quantities
with regression_coarse.expected using numdiff (relative tolerance 1e-6).
To accept new results after an intended change, copy the written
<work>/regression_coarse.output over the .expected file."""
import os
import subprocess
import sys
from fem_test_lib import *

binary, work, _ = parse_common_arguments()
numdiff = sys.argv[4] if len(sys.argv) > 4 else "numdiff"
here = os.path.dirname(os.path.abspath(__file__))
directory = f"{work}/regression_coarse"
import shutil
shutil.rmtree(directory, ignore_errors=True)
result = subprocess.run([binary, os.path.join(here, "regression_coarse.prm"),
                         "--set", "Output/Directory=" + directory],
                        capture_output=True, text=True)
if result.returncode != 0:
    print(result.stdout + result.stderr)
    sys.exit("FAIL: impact-fem failed")
s = summary(directory)
keys = ["contact_time", "force_max", "time_force_max", "approach_max",
        "rebound_velocity", "restitution", "radiated_energy_fraction",
        "plate_energy_fraction", "cells", "dofs", "steps"]
output = os.path.join(work, "regression_coarse.output")
with open(output, "w") as f:
    f.write("# key value (SI units), impact-fem regression_coarse.prm\n")
    for key in keys:
        f.write(f"{key} {s[key]:.10e}\n")
print(open(output).read())
compare = subprocess.run([numdiff, "-r", "1e-6", "-a", "1e-12", "-q",
                          os.path.join(here, "regression_coarse.expected"), output])
print("numdiff: " + ("identical within 1e-6" if compare.returncode == 0 else "DIFFERENT"))
if compare.returncode != 0:
    subprocess.run([numdiff, "-r", "1e-6", "-a", "1e-12",
                    os.path.join(here, "regression_coarse.expected"), output])
    sys.exit("FAIL: results differ from regression_coarse.expected")
