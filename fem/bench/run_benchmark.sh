#!/usr/bin/env bash
# Benchmark of impact-fem: the default scenario at V = 1 m/s with each time
# integration scheme on 1 and 2 MPI ranks (wall time, cells, DoFs, steps,
# contact time, peak force, restitution, balance error, force oscillation),
# then the study's campaign (fem/scenarios/study_viscoelastic.prm, six velocities) on 2
# ranks as two groups of one rank (the default) and as every run on both.
#
# Usage: fem/bench/run_benchmark.sh [BUILD_DIR] [OUTPUT_DIR]
#   BUILD_DIR   build tree holding bin/impact-fem (default: build)
#   OUTPUT_DIR  where the runs write their results (default: results/bench)
# CAMPAIGN=0 skips the campaigns. The other benchmarks: schemes.sh (the
# schemes at equal accuracy), verification.sh (the study's numerical
# uncertainty), plate_size.sh (the massive-plate sequence).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${1:-build}"
output="${2:-results/bench}"
binary="$build/bin/impact-fem"
scenario="$here/../scenarios/default.prm"
[ -x "$binary" ] || { echo "run_benchmark: no executable $binary (build first)" >&2; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun=(mpirun --oversubscribe)
[ "$(id -u)" -eq 0 ] && mpirun+=(--allow-run-as-root)

run() { # name ranks extra --set arguments...
  local name="$1" ranks="$2"; shift 2
  "${mpirun[@]}" -np "$ranks" "$binary" "$scenario" \
    --set "Scenario/Impact velocity=1" --set "Output/Directory=$output/$name" "$@" \
    > "$output/$name.log" 2>&1 || { echo "run $name failed, see $output/$name.log" >&2; exit 1; }
}

report() { # name
  /usr/bin/python3 - "$output/$1/summary.json" "$1" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(f"{sys.argv[2]:<14} {s['ranks']:>5} {s['wall_time']:>9.1f} {s['cells']:>7} {s['dofs']:>8} "
      f"{s['steps']:>6} {s['contact_time']*1e6:>12.3f} {s['force_max']/1e3:>11.4f} "
      f"{s['restitution']:>11.5f} {s['energy_error_final']*100:>9.4f} {s['force_oscillation']*100:>8.3f}")
PY
}

mkdir -p "$output"
echo "impact-fem benchmark: default scenario, V = 1 m/s ($(nproc) cores)"
printf "%-14s %5s %9s %7s %8s %6s %12s %11s %11s %9s %8s\n" \
  run ranks "wall [s]" cells DoFs steps "t_c [us]" "F_max [kN]" restitution "E err %" "osc. %"
for scheme in bdf2 newmark; do
  for ranks in 1 2; do
    run "$scheme-np$ranks" "$ranks" --set "Time integration/Scheme=$scheme"
    report "$scheme-np$ranks"
  done
done

if [ "${CAMPAIGN:-1}" = 1 ]; then
  study="$here/../scenarios/study_viscoelastic.prm"
  for ranks_per_run in 1 0; do
    name="campaign-rpr$ranks_per_run"
    rm -rf "$output/$name"
    start=$(date +%s.%N)
    "${mpirun[@]}" -np 2 "$binary" "$study" --set "Output/Directory=$output/$name" \
      --set "Campaign/Ranks per run=$ranks_per_run" > "$output/$name.log" 2>&1 \
      || { echo "campaign $name failed, see $output/$name.log" >&2; exit 1; }
    wall=$(/usr/bin/python3 -c "import time,sys; print(f'{time.time() - float(sys.argv[1]):.1f}')" "$start")
    echo
    echo "study campaign (fem/scenarios/study_viscoelastic.prm, 6 velocities), 2 ranks, Ranks per run = $ranks_per_run: $wall s wall"
    /usr/bin/python3 - "$output/$name" <<'PY'
import json, os, sys
d = sys.argv[1]
index = json.load(open(os.path.join(d, "index.json")))
print(f"{'V [m/s]':>8} {'wall [s]':>9} {'t_c [us]':>9} {'F_max [kN]':>10} {'x_max [um]':>10} {'e':>9} {'1-e^2 %':>8} "
      f"{'dissip %':>9} {'waves %':>8} {'E err %':>8} {'osc. %':>7} {'vM sphere [GPa]':>15}")
for run in index["runs"]:
    s = json.load(open(os.path.join(d, run["path"], "summary.json")))
    waves = s['radiated_energy_fraction'] + s['plate_energy_fraction']
    print(f"{run['velocity']:>8g} {s['wall_time']:>9.1f} {s['contact_time']*1e6:>9.3f} "
          f"{s['force_max']/1e3:>10.4f} {s['approach_max']*1e6:>10.3f} {s['restitution']:>9.5f} "
          f"{s['lost_energy_fraction']*100:>8.3f} {s['dissipated_energy_fraction']*100:>9.3f} {waves*100:>8.3f} "
          f"{s['energy_error_final']*100:>8.4f} {s['force_oscillation']*100:>7.3f} {s['von_mises_max_sphere']/1e9:>15.3f}")
PY
  done
fi
