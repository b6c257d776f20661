#!/usr/bin/env bash
# The discretisation "auto" over a table of material pairs and velocities: a 10 mm ball on the
# massive plate, both bodies elastic-perfectly plastic with the constants of the material table
# (fem/materials/materials.json), no mesh, step or solver entries (fem/scenarios/your_impact.prm
# with its materials changed), each velocity run with --verify (three levels, refinement ratio
# 1.5). Pairs (ball on plate): AISI 304 on 6061-T6, AISI 52100 hardened on AISI 1006, 6061-T6 on
# 6061-T6, C11000 annealed copper on AISI 1006 steel; velocities VELOCITIES (default
# "0.5 2 5" m/s).
# Prints per run: V/V_y and the contact radius of the expected contact, the chosen contact
# element size, the contact nodes' spacing s (as a / s) and steps per Hertz contact time, the
# fine level's cells and wall time, the GCI of t_c, F_max, x_max (relative) and of e (absolute)
# with the convergence of the levels, the force oscillation and the energy balance error at the
# end; exits 2 naming each miss of the targets: GCI <= 1 % in t_c, F_max, x_max and <= 0.005 in
# e, force oscillation <= 0.5 %, |energy balance error| <= 1e-4 (and each coarser level whose
# contact surface refinements differ from the fine level's).
#
# Usage: fem/bench/automatic_discretisation.sh [BUILD_DIR] [OUTPUT_DIR]
#   environment: VELOCITIES (default "0.5 2 5"), PAIRS (default all four, by their names
#                304-on-6061 52100-on-1006 6061-on-6061 C11000-on-1006), RANKS (MPI ranks,
#                default 2: two runs at once, one rank each)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${1:-build}"
output="${2:-results/bench/automatic_discretisation}"
binary="$build/bin/impact-fem"
[ -x "$binary" ] || { echo "automatic_discretisation: no executable $binary (build first)" >&2; exit 1; }
velocities="${VELOCITIES:-0.5 2 5}"
pairs="${PAIRS:-304-on-6061 52100-on-1006 6061-on-6061 C11000-on-1006}"
ranks="${RANKS:-2}"
launcher=()
if [ "$ranks" -gt 1 ]; then
  launcher=(mpirun --oversubscribe -np "$ranks")
  [ "$(id -u)" -eq 0 ] && launcher+=(--allow-run-as-root)
fi
mkdir -p "$output"

material() { # pair body -> material name
  case "$1:$2" in
    304-on-6061:Sphere) echo "AISI 304" ;;        304-on-6061:Plate) echo "6061-T6" ;;
    52100-on-1006:Sphere) echo "AISI 52100 hardened" ;; 52100-on-1006:Plate) echo "AISI 1006" ;;
    6061-on-6061:*) echo "6061-T6" ;;
    C11000-on-1006:Sphere) echo "C11000 annealed" ;; C11000-on-1006:Plate) echo "AISI 1006" ;;
    *) echo "automatic_discretisation: unknown pair $1" >&2; exit 2 ;;
  esac
}

list="$(echo $velocities | tr ' ' ',')"
start=$SECONDS
for pair in $pairs; do
  sphere="$(material "$pair" Sphere)"; plate="$(material "$pair" Plate)"
  echo "automatic_discretisation: $pair ($sphere on $plate), V = $list m/s -> $output/$pair"
  "${launcher[@]}" "$binary" "$here/../scenarios/your_impact.prm" --verify \
    --set "Sphere/Material=$sphere" --set "Plate/Material=$plate" \
    --set "Campaign/Impact velocities=$list" --set "Output/Directory=$output/$pair" \
    > "$output/$pair.log" 2>&1 || echo "  failed (exit $?), see $output/$pair.log"
done
echo "automatic_discretisation: runs done in $((SECONDS - start)) s"

exec /usr/bin/python3 - "$output" "$pairs" <<'PY'
import glob, json, os, sys
out, pairs = sys.argv[1], sys.argv[2].split()
targets = {"contact_time": 0.01, "force_max": 0.01, "approach_max": 0.01}
missed = []
print(f"{'pair':<16} {'V':>4} {'V/V_y':>7} {'a [mm]':>7} {'h [um]':>7} {'a/s':>4} {'steps':>6} {'cells':>6} "
      f"{'wall [s]':>8} {'GCI t_c':>14} {'GCI F_max':>14} {'GCI x_max':>14} {'GCI e':>16} "
      f"{'osc':>7} {'E err':>9}")
short = {"monotone": "m", "oscillatory": "o", "divergent": "d", "converged": "c"}
for pair in pairs:
    for run in sorted(glob.glob(os.path.join(out, pair, "v*/")),
                      key=lambda p: float(os.path.basename(p.rstrip("/"))[1:])):
        name = f"{pair} {os.path.basename(run.rstrip('/'))}"
        try:
            s = json.load(open(run + "summary.json"))
            q = json.load(open(run + "verification.json"))["quantities"]
        except (OSError, KeyError, ValueError) as error:
            print(f"{name}: incomplete ({error})")
            missed.append(f"{name}: no verified result")
            continue
        d = s["discretisation"]
        x = d["expected_contact"]
        h = d["entries"]["Mesh/Contact element size"]["value"]
        n = d["entries"]["Time integration/Steps per contact time"]["value"]
        k = d["entries"]["Mesh/Contact surface refinements"]["value"]
        # The coarser levels keep the fine level's contact surface refinements as it ran (the
        # energy balance may have raised them).
        for level in (1, 2):
            try:
                lk = json.load(open(os.path.join(run, "verification", f"level{level}",
                                                 "summary.json")))["discretisation"]["entries"][
                    "Mesh/Contact surface refinements"]["value"]
            except (OSError, KeyError, ValueError):
                lk = None
            if lk != k:
                missed.append(f"{name}: level {level} has contact surface refinements {lk}, "
                              f"the fine level {k}")
        cells = [f"{pair:<16} {s['impact_velocity']:>4g} {x.get('velocity_ratio', 0):>7.1f} "
                 f"{x['contact_radius'] * 1e3:>7.3f} {h * 1e6:>7.2f} "
                 f"{x['contact_radius'] / (h / 2 ** k):>4.0f} {n:>6.0f} {s['cells']:>6} "
                 f"{s['wall_time']:>8.0f}"]
        for key, target in targets.items():
            g = q[key]["gci_fine"]
            cells.append(f"{g * 100:>8.3f} % ({short.get(q[key]['convergence'], '?')})")
            if not g <= target:
                missed.append(f"{name}: GCI of {key} {g * 100:.3f} % > {target * 100:g} %")
        ge = q["restitution"]["gci_fine_absolute"]
        cells.append(f"{ge:>10.2e} ({short.get(q['restitution']['convergence'], '?')})")
        if not ge <= 0.005:
            missed.append(f"{name}: GCI of e {ge:.2e} > 0.005")
        osc, err = s["force_oscillation"], s["energy_error_final"]
        cells.append(f"{osc * 100:>6.3f}% {err:>9.1e}")
        if not osc <= 0.005:
            missed.append(f"{name}: force oscillation {osc * 100:.3f} % > 0.5 %")
        if not abs(err) <= 1e-4:
            missed.append(f"{name}: energy balance error {err:.2e}, |.| > 1e-4")
        print(" ".join(cells))
print("(convergence of the levels: m monotone, o oscillatory, d divergent, c converged)")
for m in missed:
    print("target missed:", m)
sys.exit(2 if missed else 0)
PY
