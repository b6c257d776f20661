#!/usr/bin/env bash
# The time integration schemes at equal accuracy: the study's Kelvin-Voigt
# case (fem/scenarios/study_viscoelastic.prm) at 1 and 4 m/s with newmark (average
# acceleration), newmark with gamma = 0.6 (numerically damped, first order)
# and bdf2, each at 150, 300 and 600 steps per contact time. Printed: the
# step-to-step force oscillation and the force after release (fractions of
# the peak), and the errors of contact time, peak force and restitution
# against a reference (bdf2, 1200 steps per contact time), with the wall
# time (1 rank).
#
# Usage: fem/bench/schemes.sh [BUILD_DIR] [OUTPUT_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${1:-build}"
output="${2:-results/bench/schemes}"
binary="$build/bin/impact-fem"
[ -x "$binary" ] || { echo "schemes: no executable $binary (build first)" >&2; exit 1; }
mkdir -p "$output"

run() { # name velocity steps --set arguments...
  local name="$1" v="$2" steps="$3"; shift 3
  [ -f "$output/$name/summary.json" ] && return 0
  "$binary" "$here/../scenarios/study_viscoelastic.prm" --set "Campaign/Impact velocities=" \
    --set "Scenario/Impact velocity=$v" --set "Time integration/Steps per contact time=$steps" \
    --set "Output/Directory=$output/$name" "$@" > "$output/$name.log" 2>&1 \
    || { echo "run $name failed, see $output/$name.log" >&2; exit 1; }
}

for v in 1 4; do
  run "reference-v$v" "$v" 1200 --set "Time integration/Scheme=bdf2"
  for steps in 150 300 600; do
    run "bdf2-$steps-v$v" "$v" "$steps" --set "Time integration/Scheme=bdf2"
    run "newmark-$steps-v$v" "$v" "$steps" --set "Time integration/Scheme=newmark"
    run "newmark-damped-$steps-v$v" "$v" "$steps" --set "Time integration/Scheme=newmark" \
      --set "Time integration/Newmark gamma=0.6" --set "Time integration/Newmark beta=0.3025"
  done
done

/usr/bin/python3 - "$output" <<'PY'
import json, os, sys
d = sys.argv[1]
load = lambda name: json.load(open(os.path.join(d, name, "summary.json")))
print(f"{'scheme':<16} {'V':>3} {'steps':>5} {'osc. %':>8} {'after %':>8} {'t_c err %':>10} {'F_max err %':>11} "
      f"{'e err':>9} {'wall [s]':>8}")
for v in (1, 4):
    ref = load(f"reference-v{v}")
    for scheme in ("newmark", "newmark-damped", "bdf2"):
        for steps in (150, 300, 600):
            s = load(f"{scheme}-{steps}-v{v}")
            print(f"{scheme:<16} {v:>3} {steps:>5} {s['force_oscillation']*100:>8.3f} "
                  f"{s['force_after_release']*100:>8.3f} {(s['contact_time']/ref['contact_time']-1)*100:>10.4f} "
                  f"{(s['force_max']/ref['force_max']-1)*100:>11.4f} {s['restitution']-ref['restitution']:>9.2e} "
                  f"{s['wall_time']:>8.1f}")
    print(f"reference (bdf2, 1200 steps) at {v} m/s: t_c {ref['contact_time']*1e6:.4f} us, "
          f"F_max {ref['force_max']:.2f} N, e {ref['restitution']:.6f}")
PY
