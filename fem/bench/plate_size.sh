#!/usr/bin/env bash
# The "massive plate": the elastic restitution at 1 m/s against the plate
# size (absorbing side and bottom, 20 mm far-field elements), which shows
# the default plate (0.35 x 0.35 m) converged within 0.001; the earlier
# default 0.1 x 0.05 m with 5 mm elements for comparison; then the default
# plate at 0.5, 1, 2, 5 m/s with the wave loss against Hunter's half-space
# estimate 1.04 (V / c0)^(3/5) (fem/README.md).
#
# Usage: fem/bench/plate_size.sh [BUILD_DIR] [OUTPUT_DIR]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${1:-build}"
output="${2:-results/bench/plate}"
binary="$build/bin/impact-fem"
[ -x "$binary" ] || { echo "plate_size: no executable $binary (build first)" >&2; exit 1; }
mkdir -p "$output"
run() { # name velocity radius thickness hmax
  [ -f "$output/$1/summary.json" ] && return 0
  "$binary" "$here/../scenarios/default.prm" --set "Scenario/Impact velocity=$2" \
    --set "Scenario/Plate radius=$3" --set "Scenario/Plate thickness=$4" \
    --set "Mesh/Maximum element size=$5" --set "Output/Directory=$output/$1" > "$output/$1.log" 2>&1 \
    || { echo "run $1 failed, see $output/$1.log" >&2; exit 1; }
}
run old-0.1x0.05 1 0.1 0.05 5e-3
for size in 0.1 0.15 0.2 0.3 0.35 0.5 0.8; do run "plate-$size" 1 "$size" "$size" 20e-3; done
for v in 0.5 2 5; do run "default-v$v" "$v" 0.35 0.35 20e-3; done
/usr/bin/python3 - "$output" <<'PY'
import json, math, os, sys
d = sys.argv[1]
load = lambda name: json.load(open(os.path.join(d, name, "summary.json")))
ref = load("plate-0.8")["restitution"]
print("elastic restitution at 1 m/s against the plate size (absorbing side and bottom)")
print(f"{'Rp x H [m]':>12} {'hmax':>6} {'e':>10} {'e - e(0.8)':>11} {'radiated %':>10} {'in plate %':>10} {'cells':>6} {'wall [s]':>8}")
for name, label, hmax in [("old-0.1x0.05", "0.1 x 0.05", "5 mm")] + \
        [(f"plate-{s}", f"{s} x {s}", "20 mm") for s in (0.1, 0.15, 0.2, 0.3, 0.35, 0.5, 0.8)]:
    s = load(name)
    print(f"{label:>12} {hmax:>6} {s['restitution']:>10.7f} {s['restitution'] - ref:>11.2e} "
          f"{s['radiated_energy_fraction']*100:>10.3f} {s['plate_energy_fraction']*100:>10.3f} "
          f"{s['cells']:>6} {s['wall_time']:>8.1f}")
c0 = math.sqrt(2e11 / 7800)
print("\nwave loss on the default plate (0.35 x 0.35 m) against Hunter's 1.04 (V/c0)^(3/5), c0 = sqrt(E/rho)")
print(f"{'V [m/s]':>7} {'e':>9} {'1-e^2 %':>8} {'waves %':>8} {'Hunter %':>9} {'FEM / Hunter':>12}")
for v, name in ((0.5, "default-v0.5"), (1, "plate-0.35"), (2, "default-v2"), (5, "default-v5")):
    s = load(name)
    hunter = 1.04 * (v / c0) ** 0.6
    print(f"{v:>7g} {s['restitution']:>9.6f} {s['lost_energy_fraction']*100:>8.3f} "
          f"{(s['radiated_energy_fraction'] + s['plate_energy_fraction'])*100:>8.3f} {hunter*100:>9.3f} "
          f"{s['lost_energy_fraction'] / hunter:>12.3f}")
PY
