#!/usr/bin/env bash
# The studies, the project's main job. Each runs an FEM campaign with every run verified
# (--verify: two coarser levels, the numerical uncertainty of the FEM), the calibration of
# Hunt-Crossley, the comparison laws and the elastic-plastic laws, the export of the
# calibrated contact to Simbody, MuJoCo, LAMMPS (and LIGGGHTS when the bodies yield), its
# runs in those tools, and the validity report with the section "In your simulator".
# Complete (and verified) runs of an earlier or interrupted study are reused.
#
#   ./study.sh [OUTPUT_DIR]                 the default study, fem/scenarios/study.prm:
#       elastic-plastic Kelvin-Voigt steel ball on a steel plate (J2 plasticity and
#       viscoelastic damping in both bodies), V = 0.5 ... 5 m/s, 2 MPI ranks
#       (default OUTPUT_DIR results/study)
#   ./study.sh viscoelastic [OUTPUT_DIR]    the same without plasticity,
#       fem/scenarios/study_viscoelastic.prm, the reference of the default study
#       (results/study-viscoelastic)
#   ./study.sh plastic [OUTPUT_DIR]         the plasticity-dominated study,
#       fem/scenarios/steel_on_steel_plastic.prm: the hardened ball on a structural-steel
#       (AISI 1006, Johnson-Cook) plate, V = 0.1 ... 5 m/s (results/plastic)
#   ./study.sh thin-plate [OUTPUT_DIR]      the ball on Kelvin-Voigt steel plates of
#       2 mm ... 0.35 m (the massive plate) lying free (fem/scenarios/thin_plate.prm), swept
#       over the plate thickness x V = 0.5, 1, 2, 5 m/s (44 runs, each verified), and the
#       report with its validity maps: where calibrated Hunt-Crossley, the best law and
#       Zener's thin-plate model hold, per thickness and velocity (results/thin-plate)
#
# All need a build in build/ (or IMPACT_BUILD_DIR=...); all but thin-plate also need the
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

scenario=fem/scenarios/study.prm
output="${1:-results/study}"
case "${1:-}" in
  viscoelastic) scenario=fem/scenarios/study_viscoelastic.prm output="${2:-results/study-viscoelastic}" ;;
  plastic) scenario=fem/scenarios/steel_on_steel_plastic.prm output="${2:-results/plastic}" ;;
  -*) echo "study: unknown option '$1' (usage: sed -n 9,27p study.sh)" >&2; exit 2 ;;
esac
for tool in impact-fem impact-calibrate impact-export impact-report impact-drop-lammps impact-drop-liggghts; do
  [ -x "$bin/$tool" ] || { echo "study: $bin/$tool is missing: build first (README)" >&2; exit 1; }
done
# The simulators are checked before the FEM campaign, so that a missing one stops the study
# at once rather than after it (tests/consumers/run_in_simulators.sh needs all four).
missing=()
[ -f /usr/include/simbody/Simbody.h ] || missing+=("Simbody (Debian package libsimbody-dev)")
[ -x "$bin/impact-drop-mujoco" ] ||
  missing+=("MuJoCo ($bin/impact-drop-mujoco is built only when libmujoco-dev is found: install it, then run cmake and build again)")
command -v "${IMPACT_LAMMPS:-lmp}" >/dev/null 2>&1 || command -v lmp_serial >/dev/null 2>&1 ||
  command -v lmp_stable >/dev/null 2>&1 || missing+=("LAMMPS (Debian package lammps: lmp)")
command -v liggghts >/dev/null 2>&1 || missing+=("LIGGGHTS (Debian package liggghts)")
# The restitution table's law runs in both through their extension points (run_in_simulators.sh).
[ -x "$bin/impact-drop-simbody-custom" ] ||
  missing+=("Simbody's Force::Custom drop ($bin/impact-drop-simbody-custom is built only when libsimbody-dev is found)")
[ -x "$bin/impact-drop-lammps-external" ] ||
  missing+=("LAMMPS's library ($bin/impact-drop-lammps-external is built only when liblammps-dev is found: install it, then run cmake and build again)")
if [ ${#missing[@]} -gt 0 ]; then
  echo "study: the section 'In your simulator' needs Simbody, MuJoCo, LAMMPS and LIGGGHTS; missing:" >&2
  printf '  %s\n' "${missing[@]}" >&2
  echo "study: ./setup.sh installs them" >&2
  exit 1
fi

start=$SECONDS
echo "study: FEM campaign of $scenario, verified -> $output/campaign"
"${mpirun[@]}" "$bin/impact-fem" "$scenario" --set "Output/Directory=$output/campaign" \
  --verify
echo "study: calibration -> $output/calibration.json"
# Exit 3: the calibration is written but some fit did not converge or a figure of merit is
# missing; the study goes on and its report lists these problems. Any other failure stops it.
status=0
"$bin/impact-calibrate" --campaign "$output/campaign" --output "$output/calibration.json" || status=$?
[ "$status" -eq 0 ] || [ "$status" -eq 3 ] || exit "$status"
echo "study: export to Simbody, MuJoCo, LAMMPS, LIGGGHTS -> $output/export"
"$bin/impact-export" --campaign "$output/campaign" --calibration "$output/calibration.json" \
  --output "$output/export"
echo "study: the exports run in the simulators -> $output/in_simulator"
rm -rf "$output/in_simulator" # no result of an earlier export stays
IMPACT_BUILD_DIR="$(dirname "$bin")" tests/consumers/run_in_simulators.sh "$output/export" \
  "$output/in_simulator"
echo "study: report -> $output/report"
report_status=0
"$bin/impact-report" --campaign "$output/campaign" --calibration "$output/calibration.json" \
  --simulators "$output/in_simulator" --output "$output/report" || report_status=$?
[ "$report_status" -eq 0 ] || [ "$report_status" -eq 3 ] || exit "$report_status"
echo "study: done in $((SECONDS - start)) s"
echo "report: $(realpath "$output/report/report.html")"
# 3: complete but with problems the report lists (its section Status).
[ "$status" -eq 0 ] && [ "$report_status" -eq 0 ] || exit 3
