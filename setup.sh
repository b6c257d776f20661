#!/usr/bin/env bash
# Installs the Debian packages the project needs, only those that are missing.
# Safe to re-run. Needs root (or sudo) on Debian bookworm.
set -euo pipefail

packages=(
  build-essential cmake pkg-config          # compiler and build system
  libboost-dev libboost-math-dev            # Lambert W, quadrature, root finding, odeint, multiprecision
  libeigen3-dev libceres-dev                # least-squares calibration
  libgtest-dev libbenchmark-dev             # unit tests and benchmarks
  libdeal.ii-dev openmpi-bin libopenmpi-dev # finite-element model, MPI
  libhdf5-openmpi-dev gmsh                  # result files, mesh generation
  nlohmann-json3-dev                        # JSON output of tools
  libssl-dev                                # SHA-256 checksums of campaign runs (libcrypto)
  numdiff                                   # tolerant comparison of outputs in tests
  clang-format                              # the code's style (.clang-format), checked by a test
  universal-ctags                           # the functions' lengths (at most 100 lines), checked by a test
  python3 python3-matplotlib python3-h5py   # figures of the report, HDF5 checks in fem tests
  chromium fonts-dejavu-core                # the report's rendering test (headless screenshot)
  libsimbody-dev libmujoco-dev lammps       # the exports run in Simbody, MuJoCo, LAMMPS (tests/consumers)
  liggghts                                  # ... and in LIGGGHTS 3.8 (thornton_ning, tests/consumers)
  liblammps-dev                             # the restitution table's law in LAMMPS (fix external)
  python3-sphinx python3-myst-parser        # the manual (doc/, target doc, test doc.build): Sphinx, MyST Markdown,
  python3-sphinx-rtd-theme                  # ... its theme,
  doxygen python3-breathe                   # ... the reduced library's API from its headers (Doxygen XML, Breathe)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -q
$sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
