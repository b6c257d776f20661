"""Calibration of elastic FEM runs against Hertz: the calibrated law must be Hertz's.

The default scenario (elastic steel, default mesh) is run at 0.5, 1, 2 m/s on 2 ranks,
calibrated with `impact-calibrate --laws none` and reported with `impact-report`.
Checks: the free campaign fit of Hunt-Crossley gives n within 0.05 of 3/2; the campaign
fit with n held at 3/2 gives c within 5 % of the Hertz stiffness computed from the
scenario's materials as run (E, nu of both bodies, sphere radius R; plate flat):
c_Hertz = 4/3 E* sqrt(R), 1/E* = (1 - nu_s^2)/E_s + (1 - nu_p^2)/E_p. (The free fit's c is
in N/m^n with n != 3/2 and is strongly correlated with n, so it is not compared with
c_Hertz; it is printed for information.) The report's Markdown must state the offsets
n - 3/2 and c / c_Hertz - 1 with the calibration's numbers.
argv: impact-fem, work directory, mpiexec, impact-calibrate, impact-report.
"""
import math
import os
import re
import shutil
import subprocess
import time
from fem_test_lib import *

binary, work, mpiexec = parse_common_arguments()
calibrate = sys.argv[4] if len(sys.argv) > 4 else ""
report = sys.argv[5] if len(sys.argv) > 5 else ""
checks = Checks()
SCENARIO = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "fem",
                        "scenarios", "default.prm")
VELOCITIES = "0.5,1,2"
directory = os.path.join(work, "elastic_calibration")
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
for tool, name in ((calibrate, "impact-calibrate"), (report, "impact-report")):
    if not (tool and os.access(tool, os.X_OK)):
        # The project always builds both tools: a missing one is a failure, not a skip.
        sys.exit(f"FAIL: {name} is not built ({tool or 'no path'})")


def read_prm(path):
    """{"Subsection/.../Entry": value} of a deal.II parameter file (comments stripped)."""
    values, stack = {}, []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].strip()
            if line.startswith("subsection "):
                stack.append(line[len("subsection "):].strip())
            elif line == "end":
                stack.pop()
            elif line.startswith("set ") and "=" in line:
                key, value = line[4:].split("=", 1)
                values["/".join(stack + [key.strip()])] = value.strip()
    return values


# 1. The campaign, from scratch (a campaign directory with complete runs would be reused).
if os.path.isdir(directory):
    shutil.rmtree(directory)
start = time.time()
command = [mpiexec, "--allow-run-as-root", "--oversubscribe", "-np", "2", binary, SCENARIO,
           "--velocities", VELOCITIES, "--set", f"Output/Directory={directory}",
           "--set", "Output/Progress interval=0"]
result = subprocess.run(command, capture_output=True, text=True, env=env)
print(f"campaign {VELOCITIES} m/s on 2 ranks: exit {result.returncode} in "
      f"{time.time() - start:.1f} s")
if result.returncode != 0:
    print(result.stdout + result.stderr)
    sys.exit(f"FAIL: impact-fem exited with {result.returncode}")

# 2. The Hertz stiffness of the scenario's materials as run.
prm = read_prm(os.path.join(directory, "v1", "parameters.prm"))
for body in ("Sphere", "Plate"):
    checks.check(prm[f"{body}/Material model"] == "elastic",
                 f"{body}: material model {prm[f'{body}/Material model']} (elastic)")
inverse_modulus = sum((1 - float(prm[f"{body}/Elastic/Poisson's ratio"]) ** 2)
                      / float(prm[f"{body}/Elastic/Young's modulus"])
                      for body in ("Sphere", "Plate"))
radius = float(prm["Scenario/Sphere radius"])
hertz = 4 / 3 / inverse_modulus * math.sqrt(radius)
print(f"Hertz stiffness of the scenario: c_Hertz = {hertz:.5e} N/m^1.5 (R = {radius} m)")

# 3. Calibration.
calibration_file = os.path.join(directory, "calibration.json")
start = time.time()
result = subprocess.run([calibrate, "--campaign", directory, "--laws", "none", "--output",
                         calibration_file, "--quiet"], capture_output=True, text=True)
print(result.stdout + result.stderr + f"(calibration: {time.time() - start:.1f} s)")
checks.check(result.returncode == 0, f"impact-calibrate exit {result.returncode} (0)")
with open(calibration_file) as f:
    calibration = json.load(f)
campaign = calibration["campaign"]
free_fit = campaign["hunt_crossley"]
fixed_fit = campaign["hunt_crossley_hertz_exponent"]
checks.check(campaign["fitted"] and len(campaign["velocities"]) == 3,
             f"campaign fitted over {campaign['velocities']} m/s")
checks.check(free_fit["converged"] and fixed_fit["converged"], "both campaign fits converged")
n = free_fit["parameters"]["n"]["value"]
c_free = free_fit["parameters"]["c"]["value"]
c_fixed = fixed_fit["parameters"]["c"]["value"]
n_interval = free_fit["parameters"]["n"]["interval"]
c_interval = fixed_fit["parameters"]["c"]["interval"]
checks.check(fixed_fit["parameters"]["n"]["fixed"] and fixed_fit["parameters"]["n"]["value"] == 1.5,
             "the fixed-exponent fit holds n = 3/2")
print(f"free fit:        n = {n:.5f} [{n_interval[0]:.5f}, {n_interval[1]:.5f}], "
      f"c = {c_free:.5e} N/m^n, b = {free_fit['parameters']['b']['value']:.4g} s/m, "
      f"RMS {free_fit['rms_residual'] * 100:.3f} % of the peak force")
print(f"n = 3/2 fit:     c = {c_fixed:.5e} [{c_interval[0]:.5e}, {c_interval[1]:.5e}] N/m^1.5, "
      f"b = {fixed_fit['parameters']['b']['value']:.4g} s/m, "
      f"RMS {fixed_fit['rms_residual'] * 100:.3f} % of the peak force")
print(f"offsets from Hertz: n - 3/2 = {n - 1.5:+.4f} (free fit); "
      f"c / c_Hertz - 1 = {(c_fixed / hertz - 1) * 100:+.2f} % (n = 3/2 fit); "
      f"free fit's c / c_Hertz - 1 = {(c_free / hertz - 1) * 100:+.2f} % (for information)")
checks.check(abs(n - 1.5) <= 0.05, f"free fit: |n - 3/2| = {abs(n - 1.5):.4f} <= 0.05")
checks.check(abs(c_fixed / hertz - 1) <= 0.05,
             f"n = 3/2 fit: |c / c_Hertz - 1| = {abs(c_fixed / hertz - 1) * 100:.2f} % <= 5 %")

# 4. The report states the offsets, with the calibration's numbers.
output = os.path.join(directory, "report")
start = time.time()
result = subprocess.run([report, "--campaign", directory, "--calibration", calibration_file,
                         "--output", output, "--quiet"], capture_output=True, text=True)
print(result.stdout + result.stderr + f"(report: {time.time() - start:.1f} s)")
checks.check(result.returncode == 0, f"impact-report exit {result.returncode} (0)")
with open(os.path.join(output, "report.md")) as f:
    markdown = f.read()
number = r"([-+]?[0-9.]+(?:e[-+]?[0-9]+)?)"
match = re.search(r"Offsets of the calibrated elastic part from Hertz \(c_Hertz = " + number +
                  r" N/m\^1\.5\): n - 3/2 = " + number + r" \(free fit of c, n, b: n = " + number +
                  r"\); c / c_Hertz - 1 = " + number + r" % \(fit with n fixed at 3/2, c and b "
                  r"free: c = " + number + r" N/m\^1\.5\); for information, the free fit's "
                  r"c / c_Hertz - 1 = " + number + r" %", markdown)
checks.check(match is not None, "report.md states the offsets from Hertz")
if match:
    print("report.md: " + markdown[match.start():markdown.find("\n", match.start())])
    shown = [float(match.group(i)) for i in range(1, 7)]
    expected = [hertz, n - 1.5, n, (c_fixed / hertz - 1) * 100, c_fixed,
                (c_free / hertz - 1) * 100]
    names = ["c_Hertz", "n - 3/2", "n", "c / c_Hertz - 1 [%]", "c (n = 3/2)",
             "free fit's c / c_Hertz - 1 [%]"]
    # Printed to 3 (offsets), 5 (c_Hertz) or 6 significant digits.
    for name, value, want in zip(names, shown, expected):
        checks.check(abs(value - want) <= 5e-3 * abs(want) + 1e-12,
                     f"report: {name} = {value:g} (calibration: {want:.6g})")
checks.finish()
