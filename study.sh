#!/usr/bin/env bash
# The default study, the project's main job: the campaign of fem/scenarios/study.prm
# (Kelvin-Voigt steel ball on a steel plate, V = 0.5, 1, 2, 3, 4, 5 m/s, 2 MPI ranks), each
# run verified (--verify: two coarser levels, the numerical uncertainty of the FEM), the
# calibration of Hunt-Crossley and the comparison laws, the export of the calibrated contact
# to Simbody, MuJoCo and LAMMPS, its runs in those tools, and the validity report with the
# section "In your simulator". Complete (and verified) runs of an earlier or interrupted
# study are reused.
#
# The thin-plate study (./study.sh thin-plate): the same ball on Kelvin-Voigt steel plates
# of 2 mm ... 0.35 m (the massive plate) lying free (fem/scenarios/thin_plate.prm), swept over the plate thickness x
# V = 0.5, 1, 2, 5 m/s (44 runs, each verified), and the report with its validity maps:
# where calibrated Hunt-Crossley, the best law and Zener's thin-plate model hold, per
# thickness and velocity.
#
# Usage: ./study.sh [OUTPUT_DIR]              (default results/study)
#        ./study.sh thin-plate [OUTPUT_DIR]   (default results/thin-plate)
# Both need a build in build/ (or IMPACT_BUILD_DIR=...); the default study also needs the
# simulators (./setup.sh).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
bin="${IMPACT_BUILD_DIR:-build}/bin"

mpirun=(mpirun --oversubscribe -np 2)
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  mpirun+=(--allow-run-as-root)
fi

if [ "${1:-}" = "thin-plate" ]; then
  output="${2:-results/thin-plate}"
  for tool in impact-fem impact-report; do
    [ -x "$bin/$tool" ] || { echo "study: $bin/$tool is missing: build first (README)" >&2; exit 1; }
  done
  start=$SECONDS
  echo "study thin-plate: FEM campaign (11 thicknesses x 4 velocities), verified -> $output/campaign"
  "${mpirun[@]}" "$bin/impact-fem" fem/scenarios/thin_plate.prm --verify \
    --sweep "Scenario/Plate thickness=0.002,0.003,0.005,0.007,0.01,0.015,0.025,0.05,0.1,0.15,0.35" \
    --set "Output/Directory=$output/campaign"
  echo "study thin-plate: report with the validity maps -> $output/report"
  "$bin/impact-report" --campaign "$output/campaign" --output "$output/report"
  echo "study thin-plate: done in $((SECONDS - start)) s"
  echo "report: $(realpath "$output/report/report.html")"
  exit 0
fi

output="${1:-results/study}"
for tool in impact-fem impact-calibrate impact-export impact-report impact-drop-lammps; do
  [ -x "$bin/$tool" ] || { echo "study: $bin/$tool is missing: build first (README)" >&2; exit 1; }
done
# The simulators are checked before the FEM campaign, so that a missing one stops the study
# at once rather than after it (tests/consumers/run_in_simulators.sh needs all three).
missing=()
[ -f /usr/include/simbody/Simbody.h ] || missing+=("Simbody (Debian package libsimbody-dev)")
[ -x "$bin/impact-drop-mujoco" ] ||
  missing+=("MuJoCo ($bin/impact-drop-mujoco is built only when libmujoco-dev is found: install it, then run cmake and build again)")
command -v "${IMPACT_LAMMPS:-lmp}" >/dev/null 2>&1 || command -v lmp_serial >/dev/null 2>&1 ||
  command -v lmp_stable >/dev/null 2>&1 || missing+=("LAMMPS (Debian package lammps: lmp)")
if [ ${#missing[@]} -gt 0 ]; then
  echo "study: the section 'In your simulator' needs Simbody, MuJoCo and LAMMPS; missing:" >&2
  printf '  %s\n' "${missing[@]}" >&2
  echo "study: ./setup.sh installs them" >&2
  exit 1
fi

start=$SECONDS
echo "study: FEM campaign, verified -> $output/campaign"
"${mpirun[@]}" "$bin/impact-fem" fem/scenarios/study.prm --set "Output/Directory=$output/campaign" \
  --verify
echo "study: calibration -> $output/calibration.json"
"$bin/impact-calibrate" --campaign "$output/campaign" --output "$output/calibration.json"
echo "study: export to Simbody, MuJoCo, LAMMPS -> $output/export"
"$bin/impact-export" --campaign "$output/campaign" --calibration "$output/calibration.json" \
  --output "$output/export"
echo "study: the exports run in the simulators -> $output/in_simulator"
rm -rf "$output/in_simulator" # no result of an earlier export stays
IMPACT_BUILD_DIR="$(dirname "$bin")" tests/consumers/run_in_simulators.sh "$output/export" \
  "$output/in_simulator"
echo "study: report -> $output/report"
"$bin/impact-report" --campaign "$output/campaign" --calibration "$output/calibration.json" \
  --simulators "$output/in_simulator" --output "$output/report"
echo "study: done in $((SECONDS - start)) s"
echo "report: $(realpath "$output/report/report.html")"
