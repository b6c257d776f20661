"""Velocity campaign on 2 ranks: index, restart after SIGTERM and SIGKILL,
and the calibration's reader.

A: the campaign 0.5, 1, 2 m/s (coarse mesh) uninterrupted.
B: the same campaign into another directory, interrupted by SIGTERM once a
   run is complete and another is in its time loop, started again and
   killed by SIGKILL while redoing that run, and started a third time. Checks: the restarts
   skip the complete runs (their summary.json untouched) and redo the
   interrupted one; B's index equals A's and every summary equals A's (all
   keys but wall_time).
Then `impact-calibrate --campaign A` reads the campaign.
"""
import glob
import json
import os
import signal
import subprocess
import time
from fem_test_lib import *

binary, work, mpiexec = parse_common_arguments()
calibrate = sys.argv[4] if len(sys.argv) > 4 else ""
checks = Checks()
VELOCITIES = "0.5,1,2"
settings = ["--set", "Mesh/Contact element size=100e-6",
            "--set", "Time integration/Steps per contact time=300",
            "--set", "Output/Progress interval=0"]
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")


def command(directory):
    return [mpiexec, "--allow-run-as-root", "--oversubscribe", "-np", "2", binary,
            STEEL_PRM, "--velocities", VELOCITIES, "--set", f"Output/Directory={directory}"] + settings


def complete_runs(directory):
    return sorted(os.path.dirname(p) for p in glob.glob(f"{directory}/v*/summary.json"))


def running_runs(directory):
    """Runs in their time loop (progress lines in run.log) and not complete."""
    running = []
    for log in glob.glob(f"{directory}/v*/run.log"):
        run_directory = os.path.dirname(log)
        if not os.path.exists(f"{run_directory}/summary.json"):
            with open(log) as f:
                if "  t = " in f.read():
                    running.append(run_directory)
    return running


def interrupted_campaign(directory, kill_signal, complete_wanted):
    """Start; once `complete_wanted` runs are complete and another one is in
    its time loop, send the signal."""
    process = subprocess.Popen(command(directory), stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True, env=env,
                               start_new_session=True)
    while process.poll() is None and not (
            len(complete_runs(directory)) >= complete_wanted and running_runs(directory)):
        time.sleep(0.02)
    running = running_runs(directory)
    if kill_signal == signal.SIGKILL:
        os.killpg(process.pid, signal.SIGKILL)  # mpirun and its ranks
    else:
        process.send_signal(kill_signal)        # mpirun forwards it to the ranks
    output, _ = process.communicate()
    print(f"--- interrupted by {kill_signal.name} (exit {process.returncode}) while "
          f"{[os.path.basename(p) for p in running]} ran ---\n{output}")
    return process.returncode, running


def load(directory):
    with open(f"{directory}/index.json") as f:
        index = json.load(f)
    summaries = {}
    for entry in index["runs"]:
        s = summary(os.path.join(directory, entry["path"]))
        s.pop("wall_time")
        summaries[entry["path"]] = s
    return index, summaries


a, b = f"{work}/campaign_a", f"{work}/campaign_b"
for d in (a, b):
    if os.path.isdir(d):
        shutil.rmtree(d)
start = time.time()
result = subprocess.run(command(a), capture_output=True, text=True, env=env)
print(result.stdout + result.stderr)
checks.check(result.returncode == 0, f"uninterrupted campaign ({time.time() - start:.1f} s)")
index_a, summaries_a = load(a)
print("index.json:", json.dumps(index_a))
checks.check([r["velocity"] for r in index_a["runs"]] == [0.5, 1, 2] and
             [r["path"] for r in index_a["runs"]] == ["v0.5", "v1", "v2"],
             "index lists the three runs in order")
checks.check(index_a.get("axes") == [{"parameter": "Scenario/Impact velocity", "values": [0.5, 1, 2]}] and
             [r["point"] for r in index_a["runs"]] == [{"Scenario/Impact velocity": v} for v in (0.5, 1, 2)],
             "index axes: the velocity axis only; each run's point")
for path, s in summaries_a.items():
    print(f"{path}: restitution {s['restitution']:.6f}, contact time {s['contact_time']*1e6:.3f} us, ranks {s['ranks']}")

code, interrupted = interrupted_campaign(b, signal.SIGTERM, 1)
checks.check(code != 0, "SIGTERM stops the campaign with a non-zero exit status")
done = complete_runs(b)
# A run the campaign never began has no directory: it is incomplete all the
# same (the signal can reach a run group in the last moments of its run, so
# that the runs begun all completed and the stop shows only in the runs left).
incomplete = [f"{b}/{name}" for name in ("v0.5", "v1", "v2") if f"{b}/{name}" not in done]
print(f"after SIGTERM: complete {[os.path.basename(p) for p in done]}, "
      f"incomplete {[os.path.basename(p) for p in incomplete]}")
checks.check(len(done) >= 1 and len(incomplete) >= 1, "interrupted mid-way: complete and incomplete runs")
# The runs that were in their time loop keep their history; a run the other rank group had
# only begun to set up (its mesh, no step yet) has none to keep.
checks.check(len(interrupted) >= 1 and
             all(os.path.exists(f"{p}/history.incomplete.h5") or p in done for p in interrupted),
             f"the interrupted run(s) {[os.path.basename(p) for p in interrupted]} kept "
             "history.incomplete.h5")
stamps = {p: os.stat(f"{p}/summary.json").st_mtime_ns for p in done}

code, _ = interrupted_campaign(b, signal.SIGKILL, len(done))
checks.check(code != 0 and len(complete_runs(b)) == len(done),
             "killed again (SIGKILL) while redoing the interrupted run")
result = subprocess.run(command(b), capture_output=True, text=True, env=env)
print("--- restarted ---\n" + result.stdout + result.stderr)
checks.check(result.returncode == 0, "restarted campaign completes")
checks.check(result.stdout.count("complete, skipped") >= len(done), "complete runs skipped")
checks.check(all(os.stat(f"{p}/summary.json").st_mtime_ns == stamps[p] for p in done),
             "complete runs not recomputed (summary.json untouched)")
index_b, summaries_b = load(b)
checks.check(index_a == index_b, "same index as the uninterrupted campaign")
same = summaries_a.keys() == summaries_b.keys() and all(
    summaries_a[k] == summaries_b[k] for k in summaries_a)
checks.check(same, "same summaries (all keys but wall_time)")

if calibrate and os.access(calibrate, os.X_OK):
    result = subprocess.run([calibrate, "--campaign", a, "--output", f"{work}/campaign_calibration.json",
                             "--quiet"], capture_output=True, text=True)
    print(result.stdout + result.stderr)
    checks.check(result.returncode == 0, f"impact-calibrate --campaign reads the campaign (exit {result.returncode})")
    with open(f"{work}/campaign_calibration.json") as f:
        calibration = json.load(f)
    checks.check(calibration["campaign"]["fitted"] is True and not calibration.get("problems"),
                 "the calibration fitted the campaign without problems")
else:
    # The project always builds impact-calibrate: a missing one is a failure, not a skip.
    checks.check(False, f"impact-calibrate is built ({calibrate or 'no path'}) to read the campaign")
checks.finish()
