"""Bad input (including the viscoelastic entries and the campaign's
velocity list): each case must exit non-zero with a message naming the cause
and leave no result file (history.h5, summary.json); a run that fails
mid-way leaves only history.incomplete.h5, marked incomplete."""
import os
from fem_test_lib import *

binary, work, _ = parse_common_arguments()
checks = Checks()
small = {"Mesh/Contact element size": 200e-6}


def expect_failure(name, settings, words, extra_args=None):
    directory = f"{work}/bad_{name}"
    if extra_args is not None:  # raw command line, e.g. a parameter file
        import shutil, subprocess
        shutil.rmtree(directory, ignore_errors=True)
        result = subprocess.run([binary] + extra_args + ["--set", "Output/Directory=" + directory],
                                capture_output=True, text=True)
        code, output = result.returncode, result.stdout + result.stderr
    else:
        code, output = run(binary, directory, dict(small, **settings), expect_success=False)
    message = output.strip().splitlines()[-6:]
    print(f"[{name}] exit {code}: " + " ".join(line.strip() for line in message)[:300])
    checks.check(code != 0, f"{name}: non-zero exit")
    checks.check(all(w.lower() in output.lower() for w in words),
                 f"{name}: message names the cause ({', '.join(words)})")
    for result_file in ("history.h5", "summary.json"):
        checks.check(not os.path.exists(os.path.join(directory, result_file)),
                     f"{name}: no {result_file} left")
    return directory


expect_failure("poisson", {"Sphere/Elastic/Poisson's ratio": 0.5}, ["Poisson's ratio", "0.5"])
# The value refused is shown as given ("-1e-05", not std::to_string's "-0.000010").
expect_failure("negative_size", {"Mesh/Contact element size": -1e-5},
               ["Contact element size", "positive", "got -1e-05 m"])
expect_failure("zero_tolerance", {"Sphere/Material model": "elastic-plastic",
                                  "Nonlinear solver/Residual tolerance": 0},
               ["Residual tolerance", "> 0", "got 0 and 1e-06"])
expect_failure("size_above_sphere", {"Mesh/Contact element size": 0.02}, ["Contact element size", "sphere radius"])
expect_failure("negative_gap", {"Scenario/Initial gap": -1e-3}, ["Initial gap"])
expect_failure("unknown_entry_set", {"Scenario/Impact speed": 1}, ["Impact speed"])
expect_failure("malformed_set", {"Scenario/Impact velocity": "fast"}, ["Impact velocity", "fast"])
expect_failure("prony_lists", {"Sphere/Material model": "maxwell", "Sphere/Maxwell/Shear moduli": "1e10,2e10",
                               "Sphere/Maxwell/Shear relaxation times": "1e-6"},
               ["Shear moduli", "relaxation times", "one time per modulus"])
expect_failure("negative_retardation", {"Sphere/Material model": "kelvin-voigt",
                                        "Sphere/Kelvin-voigt/Retardation time": -1e-6},
               ["Retardation time", "does not fit"])
# The elastic-plastic entries: the entry, its range and the value named.
plastic = {"Sphere/Material model": "elastic-plastic"}
for entry, value, words in [
        ("Hardening modulus", -5e9, ["Elastic-plastic/Hardening modulus", ">= 0 Pa", "-5e+09"]),
        ("Johnson-Cook n", 1.5, ["Elastic-plastic/Johnson-Cook n", "(0, 1]", "1.5"]),
        ("Johnson-Cook n", 0, ["Elastic-plastic/Johnson-Cook n", "(0, 1]", "got 0"]),
        ("Johnson-Cook B", -1, ["Elastic-plastic/Johnson-Cook B", ">= 0 Pa", "-1"]),
        ("Johnson-Cook C", -0.01, ["Elastic-plastic/Johnson-Cook C", ">= 0", "-0.01"]),
        ("Reference strain rate", 0, ["Elastic-plastic/Reference strain rate", "> 0 1/s", "got 0"]),
        ("Retardation time", -1e-7, ["Elastic-plastic/Retardation time", ">= 0 s", "-1e-07"]),
        ("Poisson's ratio", 0.5, ["Poisson's ratio", "0.5"])]:
    expect_failure("plastic_" + entry.lower().replace(" ", "_").replace("'", "") + "_" + str(value),
                   dict(plastic, **{"Sphere/Elastic-plastic/" + entry: value}), words)
# One yield strength per body, beside its Material model (materials.py tests the rest).
expect_failure("plastic_yield_strength_negative", dict(plastic, **{"Sphere/Yield strength": -1e8}),
               ["Sphere/Yield strength", "does not fit"])
expect_failure("plastic_yield_strength_0", dict(plastic, **{"Sphere/Yield strength": 0}),
               ["Sphere/Yield strength", "> 0 Pa", "got 0"])
expect_failure("plastic_hardening_law", dict(plastic, **{"Plate/Material model": "elastic-plastic",
                                                         "Plate/Elastic-plastic/Hardening law": "voce"}),
               ["Hardening law", "voce"])
# The static press is one quasi-static solve: a campaign or --verify of it would run impacts
# instead, so both are refused, naming the analysis.
static_press = [STEEL_PRM, "--set", "Scenario/Analysis=static press",
                "--set", "Scenario/Static force=1000", "--set", "Scenario/Plate side=clamped",
                "--set", "Scenario/Plate bottom=clamped"]
expect_failure("static_press_verify", {}, ["static press runs alone", "--verify"],
               extra_args=static_press + ["--verify"])
expect_failure("static_press_campaign", {}, ["static press runs alone", "--velocities"],
               extra_args=static_press + ["--velocities", "1,2"])
# The quasi-static indentation takes elastic-plastic bodies, but not their
# viscous part (a retardation time needs a loading rate).
expect_failure("plastic_indentation_viscous",
               dict(plastic, **{"Scenario/Analysis": "indentation", "Plate/Material model": "rigid",
                                "Indentation/Maximum approach": 2e-6,
                                "Sphere/Elastic-plastic/Retardation time": 1e-7}),
               ["'indentation'", "Elastic-plastic/Retardation time = 0"])
expect_failure("bad_velocities", None, ["velocities", "fast"],
               extra_args=["--velocities", "1,fast"])
expect_failure("missing_gmsh", {"Mesh/Gmsh executable": "/nonexistent/gmsh"}, ["gmsh was not found"])

prm = os.path.join(work, "bad.prm")
with open(prm, "w") as f:
    f.write("subsection Scenario\n  set Impact velocty = 2\nend\n")
expect_failure("unknown_entry_file", None, ["Impact velocty"], extra_args=[prm])
with open(prm, "w") as f:
    f.write("subsection Scenario\n  set Impact velocity = 2 m/s\nend\n")
expect_failure("malformed_file", None, ["Impact velocity"], extra_args=[prm])
expect_failure("missing_file", None, ["parameter file"], extra_args=[os.path.join(work, "none.prm")])

# --print-parameters lists every entry with its default and unit.
import subprocess
listing = subprocess.run([binary, "--print-parameters"], capture_output=True, text=True)
import re
checks.check(listing.returncode == 0 and re.search(r"set Impact velocity +=\s*1\n", listing.stdout)
             and "[m/s]" in listing.stdout and "subsection Time integration" in listing.stdout,
             "--print-parameters lists the entries with defaults and units")

# A failure in the middle of the run: the contact iteration limited to one
# step cannot converge once several nodes touch.
directory = expect_failure("solver", {"Contact/Maximum active set iterations": 1},
                           ["active-set", "did not converge"])
incomplete = os.path.join(directory, "history.incomplete.h5")
checks.check(os.path.exists(incomplete), "solver: history.incomplete.h5 kept")
if os.path.exists(incomplete):
    import h5py
    with h5py.File(incomplete, "r") as f:
        status = f.attrs["status"]
        status = status.decode() if isinstance(status, bytes) else status
        steps = len(f["time"])
    print(f"incomplete file: status = {status}, {steps} steps kept")
    checks.check(status == "incomplete" and steps > 1, "solver: file marked incomplete, steps kept")
checks.finish()
