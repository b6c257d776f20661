#pragma once
/// @file
/// The identities of the models, declared once: the keys by which the calibration (its JSON),
/// the report, its figures and the exports name a model. The comparison laws are named by
/// the reduced library (impact_reduced/comparison_laws.hpp, comparison_law_names()); the
/// other models are these. A key is compared as `model.key == model_keys::calibrated` and
/// stored as std::string(model_keys::calibrated).

#include <string_view>

namespace impact::postprocess::model_keys {

// ---- Fits of the calibration (CampaignCalibration) ----------------------------------------
/// Hunt–Crossley, b constant, fitted to the force histories.
inline constexpr std::string_view hunt_crossley = "hunt-crossley";
/// Hunt–Crossley, b constant, fitted to the force histories and the energy loss.
inline constexpr std::string_view hunt_crossley_energy = "hunt-crossley-energy";
/// Hunt–Crossley with n = 3/2 fixed.
inline constexpr std::string_view hunt_crossley_hertz_exponent = "hunt-crossley-hertz-exponent";
/// Hunt–Crossley with b(V) = b_1 V^-q.
inline constexpr std::string_view hunt_crossley_velocity_damping = "hunt-crossley-velocity-damping";

// ---- Reference models of the calibration (nothing fitted) ---------------------------------
/// Hertz's elastic contact (b = 0).
inline constexpr std::string_view hertz = "hertz";
/// Hunt–Crossley with c from Hertz, n = 3/2 and the published b.
inline constexpr std::string_view hunt_crossley_published = "hunt-crossley-published";
/// Kuwabara–Kono without tension, A from the materials' retardation times.
inline constexpr std::string_view kuwabara_kono_material = "kuwabara-kono-material";
/// Thornton's elastic-plastic law with p_y = 1.6 Y from the material (plastic_models.hpp).
inline constexpr std::string_view thornton_material = "thornton-material";
/// Jackson–Green's elastic-plastic law with E*, Y, nu from the material (jackson_green_model.hpp).
inline constexpr std::string_view jackson_green_material = "jackson-green-material";
/// Hunt–Crossley damping on Thornton's spring, x_y from p_y = 1.6 Y and b(V) from the
/// materials' dissipative constant A (damped_plastic_models.hpp).
inline constexpr std::string_view hunt_crossley_thornton_material =
    "hunt-crossley-thornton-material";
/// The same on Jackson–Green's spring (E*, Y, nu from the material).
inline constexpr std::string_view hunt_crossley_jackson_green_material =
    "hunt-crossley-jackson-green-material";
/// Kuwabara–Kono damping on Thornton's spring and on Jackson–Green's, the spring and A from
/// the material (damped_plastic_models.hpp).
inline constexpr std::string_view kuwabara_kono_thornton_material =
    "kuwabara-kono-thornton-material";
inline constexpr std::string_view kuwabara_kono_jackson_green_material =
    "kuwabara-kono-jackson-green-material";
/// Jackson, Green & Marghitu's (2010) restitution fit from the material: e only, no force
/// history (impact_reduced/jackson_green_marghitu.hpp); drawn in the report's elastic-plastic
/// section, not ranked (the ranking judges t_c, F_max and x_max as well).
inline constexpr std::string_view jackson_green_marghitu_material =
    "jackson-green-marghitu-material";

// ---- Elastic-plastic comparison models, fitted (plastic_models.hpp) -----------------------
/// Thornton (1997), c and the yield approach x_y free.
inline constexpr std::string_view thornton = "thornton";
/// Jackson–Green (2005), c and the yield strength Y free.
inline constexpr std::string_view jackson_green = "jackson-green";

// ---- Damped elastic-plastic comparison models (damped_plastic_models.hpp) ----------------
/// Hunt–Crossley damping on Thornton's spring, x_y and b free (c held at Hertz when known).
inline constexpr std::string_view hunt_crossley_thornton = "hunt-crossley-thornton";
/// Hunt–Crossley damping on Jackson–Green's spring, Y and b free.
inline constexpr std::string_view hunt_crossley_jackson_green = "hunt-crossley-jackson-green";
/// The same springs with b(V) = (3/2) gamma_1 A (c/m)^(2/5) V^(-4/5), A free.
inline constexpr std::string_view hunt_crossley_thornton_from_a = "hunt-crossley-thornton-from-a";
inline constexpr std::string_view hunt_crossley_jackson_green_from_a =
    "hunt-crossley-jackson-green-from-a";
/// Kuwabara–Kono damping F = F_s(x) + A k_t(x) x' on Thornton's spring, x_y and A free.
inline constexpr std::string_view kuwabara_kono_thornton = "kuwabara-kono-thornton";
/// The same on Jackson–Green's spring, Y and A free.
inline constexpr std::string_view kuwabara_kono_jackson_green = "kuwabara-kono-jackson-green";

// ---- Roles on the page ---------------------------------------------------------------------
/// The calibrated Hunt–Crossley law: the campaign's hunt_crossley fit.
inline constexpr std::string_view calibrated = "calibrated";
/// The comparison law ranked first.
inline constexpr std::string_view best_law = "best-law";
/// The validity map's thin-plate and massive-plate models (Zener's impact on a plate).
inline constexpr std::string_view thin_plate = "thin-plate";
inline constexpr std::string_view massive_plate = "massive-plate";

} // namespace impact::postprocess::model_keys
