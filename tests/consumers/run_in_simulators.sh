#!/usr/bin/env bash
# Runs the exports of impact-export in the simulators themselves: drops the campaign's sphere
# at each campaign velocity in Simbody, MuJoCo, LAMMPS and LIGGGHTS and writes one result file
# per export (format "impact-simulator-run", postprocess/README.md) into OUTPUT_DIR:
# simbody.json, mujoco.json, lammps-kuwabara-kono.json, lammps-tsuji.json,
# liggghts-thornton.json (when the export has a LIGGGHTS deck: the runs record a yield strength);
# and the damped elastic-plastic law of the export's restitution table through the tools'
# extension points, Simbody's Force::Custom and LAMMPS's fix external (library interface):
# simbody-custom.json, lammps-external.json (when the export has a restitution table).
#
# Usage: tests/consumers/run_in_simulators.sh EXPORT_DIR OUTPUT_DIR [simbody] [mujoco] [lammps]
#          [liggghts] [simbody-custom] [lammps-external]
#        (all by default; needs a build in build/, or IMPACT_BUILD_DIR=...)
# The Simbody drop is compiled here against EXPORT_DIR/simbody/impact_contact.hpp, so that the
# exported header is what runs.
set -euo pipefail
[ $# -ge 2 ] || { sed -n '2,14p' "$0" >&2; exit 2; }
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
export_dir="$(realpath "$1")"
output="$2"
shift 2
tools=("$@")
if [ ${#tools[@]} -eq 0 ]; then
  tools=(simbody mujoco lammps liggghts)
  if [ -d "$export_dir/restitution" ]; then tools+=(simbody-custom lammps-external); fi
fi
bin="$(realpath "${IMPACT_BUILD_DIR:-build}")/bin"
[ -f "$export_dir/export.json" ] || { echo "run_in_simulators: $export_dir/export.json is missing (run impact-export)" >&2; exit 2; }
mkdir -p "$output"
output="$(realpath "$output")"

for tool in "${tools[@]}"; do
  case "$tool" in
    simbody)
      build="$output/simbody-build"
      if ! cmake -S "$here/simbody" -B "$build" -DIMPACT_EXPORT_DIR="$export_dir" \
             -DCMAKE_BUILD_TYPE=Release > "$output/simbody-build.log" 2>&1 ||
         ! cmake --build "$build" >> "$output/simbody-build.log" 2>&1; then
        cat "$output/simbody-build.log" >&2
        echo "run_in_simulators: the Simbody drop does not build (is libsimbody-dev installed? ./setup.sh)" >&2
        exit 1
      fi
      "$build/impact-drop-simbody" "$export_dir" "$output/simbody.json" ;;
    mujoco)
      [ -x "$bin/impact-drop-mujoco" ] || { echo "run_in_simulators: $bin/impact-drop-mujoco is missing (libmujoco-dev: ./setup.sh, then build)" >&2; exit 1; }
      "$bin/impact-drop-mujoco" "$export_dir" "$output/mujoco.json" ;;
    lammps)
      [ -x "$bin/impact-drop-lammps" ] || { echo "run_in_simulators: $bin/impact-drop-lammps is missing (build first)" >&2; exit 1; }
      "$bin/impact-drop-lammps" "$export_dir" "$output" ;;
    liggghts)
      [ -x "$bin/impact-drop-liggghts" ] || { echo "run_in_simulators: $bin/impact-drop-liggghts is missing (build first)" >&2; exit 1; }
      "$bin/impact-drop-liggghts" "$export_dir" "$output" ;;
    simbody-custom)
      [ -x "$bin/impact-drop-simbody-custom" ] || { echo "run_in_simulators: $bin/impact-drop-simbody-custom is missing (libsimbody-dev: ./setup.sh, then build)" >&2; exit 1; }
      "$bin/impact-drop-simbody-custom" "$export_dir" "$output/simbody-custom.json" ;;
    lammps-external)
      [ -x "$bin/impact-drop-lammps-external" ] || { echo "run_in_simulators: $bin/impact-drop-lammps-external is missing (liblammps-dev: ./setup.sh, then build)" >&2; exit 1; }
      "$bin/impact-drop-lammps-external" "$export_dir" "$output" ;;
    *) echo "run_in_simulators: unknown tool '$tool' (simbody, mujoco, lammps, liggghts, simbody-custom, lammps-external)" >&2; exit 2 ;;
  esac
done
