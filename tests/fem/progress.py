"""The progress line under mpirun: printed as lines, never redrawn in place.

Open MPI runs the ranks behind a pseudo-terminal, so isatty() is true even
when mpirun's own output goes to a file, and the progress line used to be
redrawn in place ('\\r') at every step. Run under `script` (a real
terminal for mpirun) with a progress interval longer than the run: no
carriage return at all, one progress line at the end.
"""
import os
import subprocess
from fem_test_lib import *

binary, work, mpiexec = parse_common_arguments()
checks = Checks()
directory = f"{work}/progress"
command = (f"{mpiexec} --allow-run-as-root --oversubscribe -np 1 {binary} "
           f"{STEEL_PRM} --set Output/Directory={directory} --set 'Mesh/Contact element size=100e-6' "
           f"--set 'Output/Progress interval=1000'")
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
result = subprocess.run(["script", "-qec", command, "/dev/null"], capture_output=True, text=True, env=env)
output = result.stdout
progress = [line for line in output.replace("\r\n", "\n").split("\n") if line.startswith("  t = ")]
carriage_returns = output.replace("\r\n", "\n").count("\r")
print(f"exit {result.returncode}; {carriage_returns} carriage returns, {len(progress)} progress line(s):")
print("\n".join(progress))
checks.check(result.returncode == 0, "the run under mpirun and a pseudo-terminal succeeds")
checks.check(carriage_returns == 0, "no progress line redrawn in place under mpirun")
checks.check(len(progress) == 1, "one progress line (the last) with an interval longer than the run")
checks.finish()
