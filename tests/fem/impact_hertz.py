"""Spec verification 2: elastic impact at V = 1 m/s on the default mesh.

Energy balance error < 0.5 %; peak force, peak approach and contact time
within 5 % of Hertz (3.56 kN, 35.1 um, 103.3 us); restitution in [0.98, 1];
penetration below 1 % of the peak approach.
"""
from fem_test_lib import *

binary, work, _ = parse_common_arguments()
checks = Checks()
directory = f"{work}/impact_1ms"
run(binary, directory, {"Scenario/Impact velocity": 1})
s = summary(directory)
hertz = {"force_max": 3562.7, "approach_max": 35.093e-6, "contact_time": 103.285e-6}
for key, value in hertz.items():
    offset = s[key] / value - 1
    print(f"{key}: {s[key]:.6g} (Hertz {value:.6g}), offset {offset*100:+.2f} %")
    checks.check(abs(offset) < 0.05, f"{key} within 5 % of Hertz")
print(f"energy balance error {s['energy_error']*100:.4f} %, restitution "
      f"{s['restitution']:.5f}, penetration {s['max_penetration']*1e9:.1f} nm "
      f"({s['max_penetration']/s['approach_max']*100:.3f} % of the approach), "
      f"{s['cells']} cells, {s['dofs']} dofs, {s['steps']} steps, "
      f"{s['wall_time']:.1f} s")
checks.check(s["energy_error"] < 0.005, "energy balance error < 0.5 %")
checks.check(0.98 <= s["restitution"] <= 1.0, "restitution in [0.98, 1]")
checks.check(s["max_penetration"] < 0.01 * s["approach_max"],
             "penetration < 1 % of the peak approach")
# The contact force must agree with -m dv/dt of the sphere.
time, force, velocity = history(directory, "time", "contact_force", "sphere_velocity")
mass = 7800 * 4 / 3 * 3.141592653589793 * RADIUS ** 3
worst = 0.0
for i in range(1, len(time) - 1):
    # Newmark: average force over a step = m (v_n - v_{n+1}) / dt
    momentum_force = -mass * (velocity[i + 1] - velocity[i]) / (time[i + 1] - time[i])
    worst = max(worst, abs(momentum_force - 0.5 * (force[i] + force[i + 1])))
print(f"largest |F - (-m dv/dt)| = {worst:.3g} N ({worst/s['force_max']*100:.2g} % of the peak)")
checks.check(worst < 1e-3 * s["force_max"], "contact force = -m dv/dt of the sphere")
# With gravity and an initial gap the energy left in the sphere's vibration
# is still its energy beyond the rigid motion: never negative.
directory = f"{work}/impact_gravity_gap"
run(binary, directory, {"Scenario/Impact velocity": 1, "Scenario/Gravity": 9.81,
                        "Scenario/Initial gap": 1e-3, "Mesh/Contact element size": 100e-6})
g = summary(directory)
print(f"gravity and a 1 mm gap: contact velocity {g['contact_velocity']:.6f} m/s, sphere vibration "
      f"{g['sphere_vibration_energy_fraction']*100:.5f} % of the energy, restitution {g['restitution']:.5f}")
checks.check(g["sphere_vibration_energy_fraction"] >= 0, "sphere vibration energy >= 0 with gravity and a gap")
checks.check(abs(g["contact_velocity"] - (1 + 2 * 9.81 * 1e-3) ** 0.5) < 1e-12,
             "contact velocity after the gap: sqrt(V^2 + 2 g g0)")
checks.finish()
