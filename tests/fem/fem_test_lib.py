"""Helpers shared by the fem tests: run impact-fem, read its results."""
import json
import os
import shutil
import subprocess
import sys

# Steel ball of the spec (m = 0.1 kg): R, E, nu; E* for equal bodies.
RADIUS = 0.01452
YOUNG = 2e11
POISSON = 0.25
EFFECTIVE_MODULUS = YOUNG / (2 * (1 - POISSON ** 2))


def maxwell_bodies():
    """Both bodies generalised Maxwell: two shear and one bulk Prony term."""
    settings = {}
    for body in ("Sphere", "Plate"):
        settings.update({f"{body}/Material model": "maxwell",
                         f"{body}/Maxwell/Long-term shear modulus": 7e10,
                         f"{body}/Maxwell/Shear moduli": "5e9,5e9",
                         f"{body}/Maxwell/Shear relaxation times": "1e-6,3e-5",
                         f"{body}/Maxwell/Long-term bulk modulus": 1.2e11,
                         f"{body}/Maxwell/Bulk moduli": "1.3333333333333333e10",
                         f"{body}/Maxwell/Bulk relaxation times": "1e-5"})
    return settings


def parse_common_arguments():
    """argv: impact-fem binary, work directory, mpiexec (may be empty)."""
    if len(sys.argv) < 3:
        sys.exit("usage: test.py IMPACT_FEM WORK_DIR [MPIEXEC]")
    binary, work = sys.argv[1], sys.argv[2]
    mpiexec = sys.argv[3] if len(sys.argv) > 3 else ""
    os.makedirs(work, exist_ok=True)
    return binary, work, mpiexec


# The tests' bodies (their material models have no defaults): steel_bodies.prm, and
# the yield strength of an elastic-plastic body, hardened AISI 52100's 2.03 GPa (the
# material table's, fem/materials/materials.json) unless the test sets one.
STEEL_PRM = os.path.join(os.path.dirname(os.path.abspath(__file__)), "steel_bodies.prm")
STEEL_YIELD_STRENGTH = 2.03e9


def with_steel(settings):
    """settings with the yield strength of its elastic-plastic bodies, unless given."""
    settings = dict(settings or {})
    for body in ("Sphere", "Plate"):
        if settings.get(f"{body}/Material model") == "elastic-plastic":
            settings.setdefault(f"{body}/Yield strength", STEEL_YIELD_STRENGTH)
    return settings


def sets(settings):
    """The command-line arguments that set each entry of @p settings."""
    return [argument for key, value in settings.items() for argument in ("--set", f"{key}={value}")]


def run(binary, directory, settings, ranks=1, mpiexec="", expect_success=True, extra=()):
    """Run one case of steel_bodies.prm with --set overrides and the options @p extra
    (e.g. "--verify"); returns (exit code, stdout+stderr)."""
    if os.path.isdir(directory):
        shutil.rmtree(directory)
    command = [binary, STEEL_PRM, "--set", "Output/Directory=" + directory, *extra] + \
        sets(with_steel(settings))
    if ranks > 1:
        command = [mpiexec, "--allow-run-as-root", "--oversubscribe",
                   "-np", str(ranks)] + command
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
    result = subprocess.run(command, capture_output=True, text=True, env=env)
    output = result.stdout + result.stderr
    if expect_success and result.returncode != 0:
        print(output)
        sys.exit(f"FAIL: impact-fem exited with {result.returncode}")
    return result.returncode, output


def summary(directory):
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f)


def history(directory, *names):
    import h5py
    with h5py.File(os.path.join(directory, "history.h5"), "r") as f:
        return [f[name][:] for name in names]


class Checks:
    """Collects pass/fail lines and exits non-zero at the end if any failed."""

    def __init__(self):
        self.failed = 0

    def check(self, ok, text):
        print(("PASS  " if ok else "FAIL  ") + text)
        self.failed += not ok

    def finish(self):
        if self.failed:
            sys.exit(f"{self.failed} check(s) failed")
        print("all checks passed")
