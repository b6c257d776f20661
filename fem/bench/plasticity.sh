#!/usr/bin/env bash
# Cost of elastic-plastic bodies: the default scenario (fem/scenarios/
# default.prm) with both bodies elastic, then elastic-plastic (the study's
# AISI 52100 yield strength 2.03 GPa, fem/scenarios/study.prm; perfectly
# plastic unless HARDENING is set), at each velocity of VELOCITIES, on 1 and
# 2 ranks, and the strategies of the iterated step (anderson, modified
# newton) on 1 rank. Printed per run: wall time, its ratio to the elastic
# run on the same ranks, iterations per step (mean, max, total), and the
# results (restitution, peak force, plastic work, permanent approach).
# Exits 1 when a target is missed: an elastic-plastic run of the default
# scenario (its 1 m/s) costs at most 3 times the elastic one (Anderson, 1 and
# 2 ranks; run it on an otherwise idle machine), and the energy balance error
# at the end of every run is below 1e-4 of the initial energy.
#
# Usage: fem/bench/plasticity.sh [BUILD_DIR] [OUTPUT_DIR]
#   environment: VELOCITIES (default "1 5"), HARDENING [Pa] (default 0)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${1:-build}"
output="${2:-results/bench/plasticity}"
binary="$build/bin/impact-fem"
velocities="${VELOCITIES:-1 5}"
hardening="${HARDENING:-0}"
[ -x "$binary" ] || { echo "plasticity: no executable $binary (build first)" >&2; exit 1; }
mpiexec="$(command -v mpiexec || command -v mpirun || true)"
mkdir -p "$output"

run() { # name ranks velocity --set arguments...
  local name="$1" ranks="$2" v="$3"; shift 3
  [ -f "$output/$name/summary.json" ] && return 0
  local launcher=()
  [ "$ranks" -gt 1 ] && launcher=("$mpiexec" --allow-run-as-root --oversubscribe -np "$ranks")
  "${launcher[@]}" "$binary" "$here/../scenarios/default.prm" \
    --set "Scenario/Impact velocity=$v" --set "Output/Directory=$output/$name" "$@" \
    > "$output/$name.log" 2>&1 || { echo "run $name failed, see $output/$name.log" >&2; exit 1; }
}

plastic=()
for body in Sphere Plate; do
  plastic+=(--set "$body/Material model=elastic-plastic"
            --set "$body/Yield strength=2.03e9"
            --set "$body/Elastic-plastic/Hardening modulus=$hardening")
done

for v in $velocities; do
  for ranks in 1 2; do
    run "elastic-v$v-np$ranks" "$ranks" "$v"
    run "anderson-v$v-np$ranks" "$ranks" "$v" "${plastic[@]}" --set "Nonlinear solver/Strategy=anderson"
  done
  run "modified-v$v-np1" 1 "$v" "${plastic[@]}" --set "Nonlinear solver/Strategy=modified newton"
done

/usr/bin/python3 - "$output" "$velocities" <<'PY'
import json, os, sys
import h5py
d, velocities = sys.argv[1], sys.argv[2].split()
load = lambda name: json.load(open(os.path.join(d, name, "summary.json")))
missed = []
print(f"{'run':<22} {'wall [s]':>8} {'/elastic':>8} {'it mean':>7} {'it max':>6} {'it total':>8} "
      f"{'e':>8} {'F_max [N]':>10} {'W_p [%]':>8} {'delta_p [um]':>12} {'E err':>9}")
for v in velocities:
    for name in (f"elastic-v{v}-np1", f"anderson-v{v}-np1", f"modified-v{v}-np1",
                 f"elastic-v{v}-np2", f"anderson-v{v}-np2"):
        s = load(name)
        ranks = name[-1]
        ratio = s["wall_time"] / load(f"elastic-v{v}-np{ranks}")["wall_time"]
        with h5py.File(os.path.join(d, name, "history.h5"), "r") as f:
            it = f["newton_iterations"][1:] if "newton_iterations" in f else None
        its = (f"{it.mean():>7.2f} {it.max():>6.0f} {it.sum():>8.0f}" if it is not None
               else f"{'-':>7} {'-':>6} {'-':>8}")
        wp = s.get("plastic_work_fraction", 0) * 100
        dp = s.get("permanent_approach", 0) * 1e6
        print(f"{name:<22} {s['wall_time']:>8.1f} {ratio:>8.2f} {its} {s['restitution']:>8.5f} "
              f"{s['force_max']:>10.1f} {wp:>8.3f} {dp:>12.4f} {s['energy_error_final']:>9.1e}")
        if name.startswith("anderson") and float(v) == 1 and ratio > 3:
            missed.append(f"{name}: {ratio:.2f} times the elastic run (target <= 3)")
        if abs(s["energy_error_final"]) > 1e-4:
            missed.append(f"{name}: energy balance error {s['energy_error_final']:.2e} (target < 1e-4)")
for m in missed:
    print("target missed:", m)
sys.exit(1 if missed else 0)
PY
