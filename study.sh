#!/usr/bin/env bash
# The default study, the project's main job: the campaign of fem/scenarios/study.prm
# (Kelvin-Voigt steel ball on a steel plate, V = 0.5, 1, 2, 3, 4, 5 m/s, 2 MPI ranks),
# the calibration of Hunt-Crossley and the comparison laws, and the validity report.
# Complete runs of an earlier (or interrupted) study are reused.
#
# Usage: ./study.sh [OUTPUT_DIR]      (default results/study; needs a build in build/,
#                                      or IMPACT_BUILD_DIR=...)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")"
bin="${IMPACT_BUILD_DIR:-build}/bin"
output="${1:-results/study}"
for tool in impact-fem impact-calibrate impact-report; do
  [ -x "$bin/$tool" ] || { echo "study: $bin/$tool is missing: build first (README)" >&2; exit 1; }
done

mpirun=(mpirun --oversubscribe -np 2)
if [ "$(id -u)" -eq 0 ]; then
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  mpirun+=(--allow-run-as-root)
fi

start=$SECONDS
echo "study: FEM campaign -> $output/campaign"
"${mpirun[@]}" "$bin/impact-fem" fem/scenarios/study.prm --set "Output/Directory=$output/campaign"
echo "study: calibration -> $output/calibration.json"
"$bin/impact-calibrate" --campaign "$output/campaign" --output "$output/calibration.json"
echo "study: report -> $output/report"
"$bin/impact-report" --campaign "$output/campaign" --calibration "$output/calibration.json" \
  --output "$output/report"
echo "study: done in $((SECONDS - start)) s"
echo "report: $(realpath "$output/report/report.html")"
