#!/usr/bin/env bash
# The numerical uncertainty of the study: every run of fem/scenarios/study_viscoelastic.prm
# verified (impact-fem --verify: the run and two coarser discretisations,
# refinement ratio 1.5 in space and time) on 2 ranks, and the table of the
# grid convergence index of contact time, peak force, its time, peak
# approach and restitution per velocity, with the wall time.
#
# Usage: fem/bench/verification.sh [BUILD_DIR] [OUTPUT_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${1:-build}"
output="${2:-results/bench/verification}"
binary="$build/bin/impact-fem"
[ -x "$binary" ] || { echo "verification: no executable $binary (build first)" >&2; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mpirun=(mpirun --oversubscribe -np 2)
[ "$(id -u)" -eq 0 ] && mpirun+=(--allow-run-as-root)
rm -rf "$output"
start=$(date +%s)
"${mpirun[@]}" "$binary" "$here/../scenarios/study_viscoelastic.prm" --verify --set "Output/Directory=$output" \
  > "$output.log" 2>&1 || { echo "verification failed, see $output.log" >&2; exit 1; }
echo "verification of the study (6 velocities x 3 levels, 2 ranks): $(( $(date +%s) - start )) s wall"
/usr/bin/python3 - "$output" <<'PY'
import json, os, sys
d = sys.argv[1]
index = json.load(open(os.path.join(d, "index.json")))
names = ("contact_time", "force_max", "time_force_max", "approach_max", "restitution")
print("GCI of the fine level (relative; restitution also absolute), observed order in brackets "
      "(- : not monotone, Fs = 3 on the largest difference)")
print(f"{'V [m/s]':>7} " + " ".join(f"{n:>22}" for n in names) + f" {'e GCI abs':>10} {'wall [s]':>8}")
worst = {n: 0 for n in names}
for run in index["runs"]:
    v = json.load(open(os.path.join(d, run["verification"])))
    q = v["quantities"]
    cells = []
    for n in names:
        order = q[n]["observed_order"]
        cells.append(f"{q[n]['gci_fine']*100:.3f} % ({order:.2f})" if order is not None else
                     f"{q[n]['gci_fine']*100:.3f} % (-)")
        worst[n] = max(worst[n], q[n]["gci_fine_absolute"] if n == "restitution" else q[n]["gci_fine"])
    wall = sum(level["wall_time"] for level in v["levels"])
    print(f"{run['velocity']:>7g} " + " ".join(f"{c:>22}" for c in cells) +
          f" {q['restitution']['gci_fine_absolute']:>10.2e} {wall:>8.1f}")
print("largest: " + ", ".join(f"{n} {worst[n]*100:.3f} %" if n != "restitution" else
                              f"restitution {worst[n]:.2e} absolute" for n in names))
print("targets: contact time, peak force, peak approach <= 0.5 %; restitution <= 0.001 absolute")
PY
