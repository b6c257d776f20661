#!/usr/bin/env bash
# Cost of elastic-plastic bodies: the default scenario (fem/scenarios/
# default.prm) with both bodies elastic, then elastic-plastic (the study's
# AISI 52100 yield strength 2.03 GPa, fem/scenarios/study.prm; perfectly
# plastic unless HARDENING is set), at each velocity of VELOCITIES, on 1 and
# 2 ranks, and the strategies of the iterated step (anderson, modified
# newton, and "former": the default before 2026-12-04, Anderson depth 5 with
# at most 100 iterations a step) on 1 rank. Printed per run: wall time, its
# ratio to the elastic run on the same ranks, iterations per step (mean, max,
# total), and the results (restitution, peak force, plastic work, permanent
# approach).
# Exits 1 when a target is missed: an elastic-plastic run of the default
# scenario (its 1 m/s) costs at most 3 times the elastic one (Anderson, 1 and
# 2 ranks; run it on an otherwise idle machine), and the energy balance error
# at the end of every run is below 1e-4 of the initial energy.
#
# Far above yield (FAR=1, the default): engineering metals at a few m/s, V/V_y
# in the hundreds to ten thousands, where the iteration on the elastic
# factorisation converges slowly (the elastic stiffness far above the
# elastic-plastic tangent of a large plastic zone). Three cases of the material
# table (fem/materials/materials.json), both bodies elastic-perfectly plastic,
# a 10 mm ball on the massive plate, the first two with the mesh following
# Thornton's contact radius a_T (a_T / 20, uniform zone 1.5 a_T, contact
# surface 2.5 a_T, 150 steps per Hertz contact time):
#   304-on-6061: AISI 304 on 6061-T6 at 3 m/s (V/V_y = 251, a_T = 0.65 mm:
#     32 um, 0.97 mm, 1.62 mm);
#   52100-on-C11000: AISI 52100 hardened on C11000 annealed copper at 5 m/s
#     (V/V_y = 8950, a_T = 1.05 mm: 52 um, 1.57 mm, 2.5 mm = R/2),
#   304-on-6061-refined: the first case at 5 m/s (V/V_y = 416) on the coarse
#     level of its verified run with the automatic mesh: contact elements
#     2.25 a / 20 of the expected (Jackson-Green) contact radius a = 0.8905 mm,
#     the contact surface's cells refined three times, the other sizes and
#     the step of --verify's coarse level (the entries below); one of its
#     steps took 251 iterations with the solver of 43c0e62 (no restarts).
# V_y and a_T^2 = (2 F_max + F_y) / (2 pi p_y) of Thornton's law with the lower
# yield strength, from `impact-reduced plastic --model thornton --radius 0.005
# --density 8000 --modulus 1.93e11 --poisson 0.29 --flat-modulus 6.89e10
# --flat-poisson 0.33 --yield-strength 2.15e8 --velocity 3` (yield_pressure,
# yield_force, force_max) and likewise for the second case.
# Each with Anderson depths ANDERSON_DEPTHS (default "5 10 20"), the former
# default (depth 5, at most 100 iterations) and the build's default solver. A step that does
# not converge ends its run with the error, which the table reports as
# "failed at step N". Exits 1 if the default solver fails on a case.
#
# Usage: fem/bench/plasticity.sh [BUILD_DIR] [OUTPUT_DIR]
#   environment: VELOCITIES (default "1 5"; empty: none), HARDENING [Pa]
#                (default 0), FAR (default 1; 0 skips the cases far above
#                yield), FAR_CASES (default all three), ANDERSON_DEPTHS
#                (default "5 10 20"; empty: none)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${1:-build}"
output="${2:-results/bench/plasticity}"
binary="$build/bin/impact-fem"
velocities="${VELOCITIES-1 5}"
depths="${ANDERSON_DEPTHS-5 10 20}"
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
  # The default scenario's steel (its Elastic constants), now elastic-plastic.
  plastic+=(--set "$body/Material model=elastic-plastic"
            --set "$body/Elastic-plastic/Young's modulus=2e11"
            --set "$body/Elastic-plastic/Poisson's ratio=0.25"
            --set "$body/Elastic-plastic/Density=7800"
            --set "$body/Yield strength=2.03e9"
            --set "$body/Elastic-plastic/Hardening modulus=$hardening")
done

former=(--set "Nonlinear solver/Strategy=anderson" --set "Nonlinear solver/Anderson depth=5"
        --set "Nonlinear solver/Maximum iterations=100")
for v in $velocities; do
  for ranks in 1 2; do
    run "elastic-v$v-np$ranks" "$ranks" "$v"
    run "anderson-v$v-np$ranks" "$ranks" "$v" "${plastic[@]}" --set "Nonlinear solver/Strategy=anderson"
  done
  run "modified-v$v-np1" 1 "$v" "${plastic[@]}" --set "Nonlinear solver/Strategy=modified newton"
  # The default before 2026-12-04 (Anderson depth 5, at most 100 iterations a step): the
  # before of the default's change.
  run "former-v$v-np1" 1 "$v" "${plastic[@]}" "${former[@]}"
done

# A run far above yield that may fail: its log is kept, its failure recorded.
far_run() { # name case_settings... -- solver settings...
  local name="$1"; shift
  [ -f "$output/$name/summary.json" ] || [ -f "$output/$name.failed" ] && return 0
  if ! "$binary" "$here/../scenarios/default.prm" --set "Output/Directory=$output/$name" "$@" \
       > "$output/$name.log" 2>&1; then
    grep -o "Time step [0-9]* (t = [^)]*) did not converge" "$output/$name.log" \
      > "$output/$name.failed" || { echo "run $name failed, see $output/$name.log" >&2; exit 1; }
  fi
}
far_cases=()
if [ "${FAR:-1}" = 1 ]; then
  read -r -a far_cases <<< "${FAR_CASES:-304-on-6061 52100-on-C11000 304-on-6061-refined}"
  # Appends a perfectly plastic body of a table material to settings (array entries,
  # not echoed words: the material names hold spaces).
  body() { # body material
    settings+=(--set "$1/Material model=elastic-plastic" --set "$1/Material=$2"
               --set "$1/Elastic-plastic/Hardening law=linear"
               --set "$1/Elastic-plastic/Hardening modulus=0")
  }
  for case in "${far_cases[@]}"; do
    settings=()
    case "$case" in
      304-on-6061) body Sphere "AISI 304"; body Plate 6061-T6
                   settings+=(--set "Scenario/Impact velocity=3"
                   --set "Mesh/Contact element size=32e-6" --set "Mesh/Uniform zone radius=0.97e-3"
                   --set "Mesh/Contact surface radius=1.62e-3") ;;
      52100-on-C11000) body Sphere "AISI 52100 hardened"; body Plate "C11000 annealed"
                   settings+=(--set "Scenario/Impact velocity=5"
                   --set "Mesh/Contact element size=52e-6" --set "Mesh/Uniform zone radius=1.57e-3"
                   --set "Mesh/Contact surface radius=2.5e-3") ;;
      304-on-6061-refined) body Sphere "AISI 304"; body Plate 6061-T6
                   settings+=(--set "Scenario/Impact velocity=5"
                   --set "Mesh/Contact element size=1.0018434046974592e-4"
                   --set "Mesh/Uniform zone radius=auto" --set "Mesh/Contact surface radius=auto"
                   --set "Mesh/Contact surface refinements=3" --set "Mesh/Maximum element size=0.045"
                   --set "Mesh/Growth factor=1.45"
                   --set "Mesh/Elements across the plate thickness=1.7777777777777777") ;;
      *) echo "plasticity: unknown far case '$case'" >&2; exit 2 ;;
    esac
    steps=150
    [ "$case" = 304-on-6061-refined ] && steps=119.45188639609484
    settings+=(--set "Scenario/Sphere radius=0.005" --set "Time integration/Steps per contact time=$steps")
    for depth in $depths; do
      far_run "far-$case-depth$depth" "${settings[@]}" \
        --set "Nonlinear solver/Strategy=anderson" --set "Nonlinear solver/Anderson depth=$depth"
    done
    far_run "far-$case-former" "${settings[@]}" "${former[@]}"
    far_run "far-$case-default" "${settings[@]}"
  done
fi

/usr/bin/python3 - "$output" "$velocities" "${far_cases[*]:-}" "$depths" <<'PY'
import json, os, sys
import h5py
d, velocities = sys.argv[1], sys.argv[2].split()
far_cases, depths = sys.argv[3].split(), sys.argv[4].split()
load = lambda name: json.load(open(os.path.join(d, name, "summary.json")))
missed = []
print(f"{'run':<22} {'wall [s]':>8} {'/elastic':>8} {'it mean':>7} {'it max':>6} {'it total':>8} "
      f"{'e':>8} {'F_max [N]':>10} {'W_p [%]':>8} {'delta_p [um]':>12} {'E err':>9}")
for v in velocities:
    for name in (f"elastic-v{v}-np1", f"anderson-v{v}-np1", f"former-v{v}-np1", f"modified-v{v}-np1",
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
if far_cases:
    print(f"\nfar above yield (1 rank): {'run':<34} {'wall [s]':>8} {'it mean':>7} {'it max':>6} "
          f"{'steps':>5} {'e':>8} {'F_max [N]':>10} {'E err':>9}")
for case in far_cases:
    for variant in [f"depth{k}" for k in depths] + ["former", "default"]:
        name = f"far-{case}-{variant}"
        failed = os.path.join(d, name + ".failed")
        if os.path.exists(failed):
            print(f"{'':<27}{name:<34} failed: {open(failed).read().strip()}")
            if variant == "default":
                missed.append(f"{name}: the default solver does not converge")
            continue
        s = load(name)
        with h5py.File(os.path.join(d, name, "history.h5"), "r") as f:
            it = f["newton_iterations"][1:]
        print(f"{'':<27}{name:<34} {s['wall_time']:>8.1f} {it.mean():>7.2f} {it.max():>6.0f} "
              f"{len(it):>5} {s['restitution']:>8.5f} {s['force_max']:>10.1f} "
              f"{s['energy_error_final']:>9.1e}")
for m in missed:
    print("target missed:", m)
sys.exit(1 if missed else 0)
PY
