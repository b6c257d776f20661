"""A campaign run as two shards in two concurrent jobs into one directory,
against the same campaign run as one job.

Campaign: Scenario/Plate thickness = 0.1, 0.35 m x velocities 0.5, 1 m/s,
4 points on a coarse mesh (100 um contact elements, 300 steps per contact
time, as in fem.sweep). In the campaign's order (velocity fastest) the
points are 0.1/0.5, 0.1/1, 0.35/0.5, 0.35/1; --shard K/2 runs the points
i with i mod 2 = K - 1.

A: one job, mpiexec -np 2 (two rank groups of one rank).
B: the two tasks of a Slurm job array --array=1-2, started together: the
   committed script fem/scripts/campaign_array.sbatch with Slurm's
   variables set as sbatch sets them and a stand-in for srun that starts
   the one rank (no Slurm here), so the shares --shard 1/2 and 2/2 are the
   script's; meanwhile index.json is read again and again.
Checks:
- each task runs exactly its two points (--shard K/2) and exits 0;
- every read of B's index.json while the shards ran parsed as JSON (a
  torn index would not), and no temporary file is left;
- B's index.json is byte for byte A's (it holds no wall times: nothing to
  normalise), and every summary.json equals A's in every key but
  wall_time (the run's own wall-clock time);
- `sha256sum -c` accepts every run of B;
- index.json removed, shard 2/2 started again: it skips its runs and
  writes the whole index anew, the other shard's runs included (any shard
  rebuilds the index from the run directories).
"""
import re
import subprocess
import time
from fem_test_lib import *

binary, work, mpiexec = parse_common_arguments()
array_script = sys.argv[4]
checks = Checks()
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1")
# The tests' steel bodies (a body's constants have no defaults), swept and refined.
CAMPAIGN = [STEEL_PRM, "--sweep", "Scenario/Plate thickness=0.1,0.35", "--velocities", "0.5,1",
            "--set", "Mesh/Contact element size=100e-6",
            "--set", "Time integration/Steps per contact time=300",
            "--set", "Output/Progress interval=0"]
PATHS = [f"plate-thickness-{h}_v{v}" for h in ("0.1", "0.35") for v in ("0.5", "1")]


def command(directory, ranks, shard=None):
    return ([mpiexec, "--allow-run-as-root", "--oversubscribe", "-np", str(ranks), binary] +
            CAMPAIGN + ["--set", f"Output/Directory={directory}"] +
            (["--shard", shard] if shard else []))


# srun's stand-in: drops srun's options, runs the program as one rank.
stand_in = f"{work}/shard_bin"
os.makedirs(stand_in, exist_ok=True)
with open(f"{stand_in}/srun", "w") as f:
    f.write('#!/bin/sh\nwhile [ "${1#-}" != "$1" ]; do shift; done\nexec "$@"\n')
os.chmod(f"{stand_in}/srun", 0o755)


def array_task(directory, task):
    """Task `task` of the array --array=1-2, as sbatch starts it."""
    task_env = dict(env, PATH=stand_in + os.pathsep + env["PATH"], IMPACT_FEM=binary,
                    SLURM_ARRAY_TASK_ID=str(task), SLURM_ARRAY_TASK_MIN="1",
                    SLURM_ARRAY_TASK_MAX="2", SLURM_ARRAY_TASK_COUNT="2")
    return subprocess.Popen(["bash", array_script] + CAMPAIGN +
                            ["--set", f"Output/Directory={directory}"], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            text=True, env=task_env)


def runs_named(output):
    """The run directories of the progress lines ("run 3/4  ... (path): ...")."""
    return sorted(set(re.findall(r"run \d+/\d+ .*\((\S+)\): ", output)))


def status_of(output, path):
    match = re.search(r"\(" + re.escape(path) + r"\): (.*)", output)
    return match.group(1) if match else ""


def summaries(directory):
    result = {}
    for path in PATHS:
        s = summary(f"{directory}/{path}")
        s.pop("wall_time")
        result[path] = s
    return result


def read_bytes(name):
    with open(name, "rb") as f:
        return f.read()


a, b = f"{work}/shard_one_job", f"{work}/shard_two_jobs"
for d in (a, b):
    if os.path.isdir(d):
        shutil.rmtree(d)

# --- B: two shards at once ---
start = time.time()
shards = [array_task(b, k) for k in (1, 2)]
reads, torn = 0, []
while any(p.poll() is None for p in shards):
    try:
        with open(f"{b}/index.json") as f:
            text = f.read()
        reads += 1
        try:
            json.loads(text)
        except ValueError:
            torn.append(text)
    except FileNotFoundError:
        pass
    time.sleep(0.005)
outputs = [p.communicate()[0] for p in shards]
time_b = time.time() - start
for k, (p, output) in enumerate(zip(shards, outputs), start=1):
    print(f"--- array task {k} of 2 (exit {p.returncode}) ---\n{output}")
    mine = [PATHS[i] for i in range(len(PATHS)) if i % 2 == k - 1]
    checks.check(p.returncode == 0 and runs_named(output) == sorted(mine) and
                 all(status_of(output, path) == "running" for path in mine) and
                 f"shard {k}/2: 2 of them" in output,
                 f"array task {k}: shard {k}/2 ran exactly {mine}")
checks.check(reads > 0 and not torn,
             f"index.json read {reads} times while the shards wrote it: always whole JSON "
             f"({len(torn)} torn)")
leftovers = [name for name in os.listdir(b) if ".tmp" in name]
checks.check(not leftovers, f"no temporary file left in the campaign directory ({leftovers})")

# --- A: one job ---
start = time.time()
result = subprocess.run(command(a, 2), capture_output=True, text=True, env=env)
time_a = time.time() - start
print(f"--- one job (exit {result.returncode}) ---\n{result.stdout}{result.stderr}")
checks.check(result.returncode == 0 and runs_named(result.stdout) == sorted(PATHS),
             "the one job ran all 4 points")
print(f"wall time: two concurrent shards of one rank each {time_b:.1f} s, "
      f"one job of two rank groups {time_a:.1f} s")

index_a = read_bytes(f"{a}/index.json")
index_b = read_bytes(f"{b}/index.json")
print("index.json of the shards:\n" + index_b.decode())
checks.check(index_a == index_b, "the shards' index.json is byte for byte the one job's")
checks.check([run["path"] for run in json.loads(index_b)["runs"]] == PATHS,
             "it lists the 4 runs in the campaign's order")
summaries_a, summaries_b = summaries(a), summaries(b)
for path in PATHS:
    print(f"{path}: restitution one job {summaries_a[path]['restitution']!r}, "
          f"shards {summaries_b[path]['restitution']!r}")
checks.check(summaries_a == summaries_b, "same summaries (every key but wall_time)")
for path in PATHS:
    checked = subprocess.run(["sha256sum", "-c", "checksums.sha256"], cwd=f"{b}/{path}",
                             capture_output=True, text=True)
    checks.check(checked.returncode == 0 and checked.stdout.count(": OK") == 3,
                 f"sha256sum -c accepts {path} of the shards")

# --- any shard rebuilds the whole index ---
os.remove(f"{b}/index.json")
stamps = {path: os.stat(f"{b}/{path}/summary.json").st_mtime_ns for path in PATHS}
result = subprocess.run(command(b, 1, "2/2"), capture_output=True, text=True, env=env)
print(f"--- shard 2/2 again, index.json removed (exit {result.returncode}) ---\n{result.stdout}")
checks.check(result.returncode == 0 and
             all(status_of(result.stdout, p) == "complete, skipped" for p in PATHS[1::2]) and
             "(4 of 4 runs)" in result.stdout,
             "shard 2/2 started again skips its runs")
checks.check(os.path.exists(f"{b}/index.json") and read_bytes(f"{b}/index.json") == index_a,
             "and writes the whole index anew, shard 1/2's runs included")
checks.check(all(os.stat(f"{b}/{path}/summary.json").st_mtime_ns == stamps[path] for path in PATHS),
             "nothing recomputed")
checks.finish()
