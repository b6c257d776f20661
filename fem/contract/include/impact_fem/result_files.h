#pragma once
/**
 * @file
 * The result files of impact-fem: the names the writer (fem/source/impact_problem.cc,
 * fem/source/output/history.cc, the postprocessors in fem/source/postprocess/, the campaign
 * in fem/source/campaign.cc) and the reader (postprocess/src/run/) both use, with their SI
 * units. Both sides include this header, so a name changed here changes both, and a name
 * removed here fails to compile on both. Plain C++17, no deal.II: the postprocess library
 * builds without it.
 *
 * One run = one directory holding
 *   history.h5    (or history.incomplete.h5 for a run that did not finish): 1-D double
 *                 datasets at the root, one value per time step, each with the string
 *                 attributes "unit" and "description"; the run's parameters as string
 *                 attributes of the root ("Scenario/Impact velocity", ...), its derived
 *                 results as double attributes "result: <summary key>", and the string
 *                 attribute "status" = "complete" | "incomplete";
 *   summary.json  the derived results (written only for a complete run);
 *   verification.json  the numerical uncertainty, when the run was verified.
 */

namespace impact_fem::result_files
{
  // ---- Files of a run directory ------------------------------------------------------------
  inline constexpr const char *history_file            = "history.h5";
  inline constexpr const char *incomplete_history_file = "history.incomplete.h5";
  inline constexpr const char *summary_file            = "summary.json";
  inline constexpr const char *verification_file       = "verification.json";

  // ---- A campaign directory: the index of its runs -----------------------------------------
  inline constexpr const char *campaign_index_json = "index.json";

  // ---- Root attributes of the HDF5 file ----------------------------------------------------
  inline constexpr const char *status_attribute        = "status";
  inline constexpr const char *status_complete         = "complete";
  inline constexpr const char *status_incomplete       = "incomplete";
  inline constexpr const char *result_attribute_prefix = "result: "; // + a summary key
  inline constexpr const char *sphere_mass_attribute   = "sphere_mass [kg]";
  inline constexpr const char *impact_velocity_parameter = "Scenario/Impact velocity";
  // Attributes of every dataset.
  inline constexpr const char *unit_attribute        = "unit";
  inline constexpr const char *description_attribute = "description";

  // ---- Per-step datasets, with their units ---------------------------------------------------
  inline constexpr const char *time_dataset            = "time";
  inline constexpr const char *time_unit               = "s";
  inline constexpr const char *contact_force_dataset   = "contact_force"; // >= 0
  inline constexpr const char *contact_force_unit      = "N";
  inline constexpr const char *approach_dataset        = "approach"; // the reduced models' x
  inline constexpr const char *approach_unit           = "m";
  inline constexpr const char *sphere_velocity_dataset = "sphere_velocity"; // downward +
  inline constexpr const char *sphere_velocity_unit    = "m/s";
  // Nonlinear materials only: the iterations of each step's solve and the out-of-balance
  // force of the accepted iterate relative to the step's load (both dimensionless).
  inline constexpr const char *newton_iterations_dataset = "newton_iterations";
  inline constexpr const char *newton_residual_dataset   = "newton_residual";

  // ---- Keys of summary.json (and, with the prefix above, of the result attributes) ---------
  // Units in the comments: SI, 1 for a ratio.
  inline constexpr const char *complete_key           = "complete";         // boolean
  inline constexpr const char *impact_velocity_key    = "impact_velocity";  // m/s, at t = 0
  inline constexpr const char *contact_velocity_key   = "contact_velocity"; // m/s, first contact
  inline constexpr const char *sphere_mass_key        = "sphere_mass";      // kg
  inline constexpr const char *restitution_key        = "restitution";      // 1
  inline constexpr const char *first_contact_time_key = "first_contact_time"; // s
  inline constexpr const char *contact_time_key       = "contact_time";     // s
  inline constexpr const char *force_max_key          = "force_max";        // N
  inline constexpr const char *time_force_max_key     = "time_force_max";   // s
  inline constexpr const char *approach_max_key       = "approach_max";     // m
  inline constexpr const char *rebound_velocity_key   = "rebound_velocity"; // m/s
  inline constexpr const char *time_step_key          = "time_step";        // s
  // Smoothness of the force history, fractions of the peak force.
  inline constexpr const char *force_oscillation_key   = "force_oscillation";   // 1
  inline constexpr const char *force_after_release_key = "force_after_release"; // 1
  // Energy balance (the energy postprocessor), fractions of the initial energy.
  inline constexpr const char *energy_error_key               = "energy_error"; // 1
  inline constexpr const char *lost_energy_fraction_key       = "lost_energy_fraction"; // 1
  inline constexpr const char *radiated_energy_fraction_key   = "radiated_energy_fraction"; // 1
  inline constexpr const char *dissipated_energy_fraction_key = "dissipated_energy_fraction"; // 1
  // Stresses (the stress postprocessor): "von_mises_max_" + body, "yield_strength_" + body
  // with body "sphere" or "plate" [Pa]; over both bodies max_von_mises [Pa] and
  // yield_exceeded (boolean, null without a yield strength).
  inline constexpr const char *von_mises_max_prefix  = "von_mises_max_";
  inline constexpr const char *yield_strength_prefix = "yield_strength_";
  inline constexpr const char *max_von_mises_key     = "max_von_mises";  // Pa
  inline constexpr const char *yield_exceeded_key    = "yield_exceeded"; // boolean
} // namespace impact_fem::result_files
