"""Campaigns and --verify with the elastic-plastic material
(fem/scenarios/plastic_on_rigid.prm on a coarse mesh: 150 um contact
elements, 60 steps per contact time):
  - a sweep over the sphere's yield strength, `--sweep "Sphere/Yield
    strength=2.03e9,3e9"` at 1 m/s: index.json has the axis and both
    runs, each run's parameters.prm carries its yield strength, and the
    point is applied: the stronger ball dissipates less (plastic work
    smaller, restitution larger, permanent approach smaller), as it must
    since V/V_y falls from 4.55 to 1.72 (V_y ~ Y^(5/2));
  - `--verify` of the elastic-plastic run: verification.json with three
    levels, every level elastic-plastic (plastic work > 0 in its summary),
    the grid convergence index of each quantity finite and the restitution's
    below 0.01 even on this coarse mesh.
"""
import math
import subprocess
from fem_test_lib import *

binary, work, _ = parse_common_arguments()
checks = Checks()
scenario = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "fem",
                        "scenarios", "plastic_on_rigid.prm")
COARSE = ["--set", "Mesh/Contact element size=150e-6",
          "--set", "Time integration/Steps per contact time=60",
          "--set", "Output/Progress interval=0"]


def impact_fem(directory, *arguments):
    if os.path.isdir(directory):
        shutil.rmtree(directory)
    result = subprocess.run([binary, scenario, "--set", f"Output/Directory={directory}"] + COARSE +
                            list(arguments), capture_output=True, text=True)
    output = result.stdout + result.stderr
    if result.returncode != 0:
        print(output)
        sys.exit(f"FAIL: impact-fem exited with {result.returncode}")
    return output


# ---- a sweep over the yield strength ----
campaign = f"{work}/plastic_campaign_sweep"
impact_fem(campaign, "--velocities", "1", "--sweep",
           "Sphere/Yield strength=2.03e9,3e9")
with open(f"{campaign}/index.json") as f:
    index = json.load(f)
axes = [a["parameter"] for a in index["axes"]]
paths = [r["path"] for r in index["runs"]]
print(f"axes {axes}, runs {paths}")
checks.check(axes == ["Sphere/Yield strength", "Scenario/Impact velocity"]
             and len(paths) == 2, "sweep: index.json with the yield-strength axis and two runs")
runs = []
for run_entry, y in zip(index["runs"], (2.03e9, 3e9)):
    d = os.path.join(campaign, run_entry["path"])
    with open(f"{d}/parameters.prm") as f:
        prm = f.read()
    s = summary(d)
    runs.append(s)
    print(f"  Y = {y:.3g} Pa: e = {s['restitution']:.5f}, plastic work {s['plastic_work_fraction'] * 100:.3f} %, "
          f"permanent approach {s['permanent_approach'] * 1e6:.4f} um")
    checks.check(run_entry["point"]["Sphere/Yield strength"] == y
                 and f"{y:g}".replace("e+09", "e9") in prm.replace("e+09", "e9"),
                 f"sweep: run {run_entry['path']} carries Y = {y:g} in its point and parameters.prm")
weak, strong = runs
checks.check(strong["plastic_work_fraction"] < weak["plastic_work_fraction"]
             and strong["restitution"] > weak["restitution"]
             and 0 < strong["permanent_approach"] < weak["permanent_approach"],
             "sweep: the stronger ball dissipates less (point applied)")

# ---- --verify of an elastic-plastic run ----
verified = f"{work}/plastic_campaign_verify"
impact_fem(verified, "--verify")
with open(f"{verified}/verification.json") as f:
    v = json.load(f)
levels = v["levels"]
for level in levels:
    print(f"  level {level['name']}: h = {level['contact_element_size'] * 1e6:.0f} um, "
          f"{level['steps']} steps, plastic work {level['summary']['plastic_work_fraction'] * 100:.3f} %, "
          f"e = {level['summary']['restitution']:.5f}")
checks.check(len(levels) == 3 and all(l["summary"]["plastic_work_fraction"] > 0 for l in levels),
             "verify: three levels, every one elastic-plastic (plastic work > 0)")
for key, q in v["quantities"].items():
    print(f"  {key}: fine {q['fine']:.6g}, medium {q['medium']:.6g}, coarse {q['coarse']:.6g}, "
          f"GCI {q['gci_fine'] * 100:.3f} % ({q['convergence']})")
checks.check(all(math.isfinite(q["gci_fine"]) for q in v["quantities"].values()),
             "verify: a finite GCI for every quantity")
checks.check(v["quantities"]["restitution"]["gci_fine_absolute"] < 0.01,
             "verify: GCI of the restitution below 0.01 on the coarse mesh")
checks.finish()
