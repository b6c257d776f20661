"""--shard K/N refused when it is no share: exit status 2, a message naming
the option, the value received and the allowed range (1 <= K <= N), and
nothing written. Also refused: --shard without a campaign (a single impact,
a material point test) and --shard without its value; and by the Slurm
script fem/scripts/campaign_array.sbatch, before impact-fem starts, a job
array whose tasks do not cover the shares 1..N (a step: --array=1-7:2; a
list: --array=1,2,9) and a start outside a job array."""
import subprocess
from fem_test_lib import *

binary, work, _ = parse_common_arguments()
array_script = sys.argv[4]
checks = Checks()
directory = f"{work}/shard_refused"
# The tests' steel bodies (a body's constants have no defaults), as a campaign.
CAMPAIGN = [STEEL_PRM, "--velocities", "0.5,1", "--set", f"Output/Directory={directory}"]
RANGE = "1 <= K <= N"


def refused(arguments, words, label):
    if os.path.isdir(directory):
        shutil.rmtree(directory)
    result = subprocess.run([binary] + arguments, capture_output=True, text=True)
    output = result.stdout + result.stderr
    message = " ".join(output.split())
    print(f"{label}\n  -> exit {result.returncode}: {message[:300]}")
    checks.check(result.returncode == 2 and all(w in output for w in words) and
                 not os.path.exists(directory),
                 f"refused with exit 2, naming {words}, nothing written: {label}")


for value in ["0/2", "3/2", "a/b", "1/0", "0/0", "2", "1/2/3", "-1/2", "1.5/2", "+1/2", "1 /2",
              "", "99999999999/99999999999"]:
    refused(CAMPAIGN + ["--shard", value], ["--shard <" + value + ">", RANGE],
            f"--shard '{value}'")
refused(CAMPAIGN + ["--shard=3/2"], ["--shard <3/2>", RANGE], "--shard=3/2")
refused(CAMPAIGN + ["--shard"], ["--shard needs K/N", RANGE], "--shard without its value")
refused([STEEL_PRM, "--set", f"Output/Directory={directory}", "--shard", "1/2"],
        ["--shard 1/2", "only a campaign", "one impact"], "--shard 1/2 without a campaign")
refused(CAMPAIGN + ["--set", "Scenario/Analysis=material point", "--shard", "1/2"],
        ["--shard 1/2", "only a campaign", "one material point"],
        "--shard 1/2 with Scenario/Analysis = material point")

# The Slurm script: the arrays it cannot split into shares 1..N.
for minimum, maximum, count, label in [("1", "7", "4", "--array=1-7:2"),
                                       ("1", "9", "3", "--array=1,2,9"),
                                       (None, None, None, "no job array")]:
    if os.path.isdir(directory):
        shutil.rmtree(directory)
    task_env = dict(os.environ, IMPACT_FEM=binary)
    if minimum:
        task_env.update(SLURM_ARRAY_TASK_ID=minimum, SLURM_ARRAY_TASK_MIN=minimum,
                        SLURM_ARRAY_TASK_MAX=maximum, SLURM_ARRAY_TASK_COUNT=count)
    else:
        task_env = {k: v for k, v in task_env.items() if not k.startswith("SLURM_")}
    result = subprocess.run(["bash", array_script] + CAMPAIGN, capture_output=True, text=True,
                            env=task_env)
    words = ["step 1 (1-N)"] if minimum else ["not a task of a Slurm job array"]
    print(f"campaign_array.sbatch, {label}\n  -> exit {result.returncode}: {result.stderr.strip()}")
    checks.check(result.returncode == 2 and all(w in result.stderr for w in words) and
                 not os.path.exists(directory),
                 f"campaign_array.sbatch refuses {label}, nothing written")
checks.finish()
