#pragma once
/// @file
/// The names in the result files of impact-fem that the calibration reads, in one place.
/// They follow fem/source/output/history.cc and fem/source/impact_problem.cc
/// (ImpactProblem::write_results); if the FEM output changes, this is the file to change.
///
/// One run = one directory holding
///   history.h5    (or history.incomplete.h5 for a run that did not finish): 1-D double
///                 datasets at the root, one value per time step, each with the string
///                 attributes "unit" and "description"; the run's parameters as string
///                 attributes of the root ("Scenario/Impact velocity", ...), its derived
///                 results as double attributes "result: <summary key>", and the string
///                 attribute "status" = "complete" | "incomplete";
///   summary.json  the derived results (written only for a complete run).

namespace impact::postprocess::fem_format {

// Files of a run directory.
inline constexpr const char* history_file = "history.h5";
inline constexpr const char* incomplete_history_file = "history.incomplete.h5";
inline constexpr const char* summary_file = "summary.json";

// Root attributes of the HDF5 file.
inline constexpr const char* status_attribute = "status";
inline constexpr const char* status_complete = "complete";
inline constexpr const char* status_incomplete = "incomplete";
inline constexpr const char* result_attribute_prefix = "result: "; // + a summary key
inline constexpr const char* sphere_mass_attribute = "sphere_mass [kg]";
inline constexpr const char* impact_velocity_parameter = "Scenario/Impact velocity";

// Per-step datasets (SI units) and their attributes.
inline constexpr const char* time_dataset = "time";                      // s
inline constexpr const char* contact_force_dataset = "contact_force";    // N, >= 0
inline constexpr const char* approach_dataset = "approach";              // m, the reduced x
inline constexpr const char* sphere_velocity_dataset = "sphere_velocity"; // m/s, downward +
inline constexpr const char* unit_attribute = "unit";
inline constexpr const char* description_attribute = "description";

// Keys of summary.json (and, with the prefix above, of the result attributes).
inline constexpr const char* complete_key = "complete";
inline constexpr const char* impact_velocity_key = "impact_velocity";   // m/s, at t = 0
inline constexpr const char* contact_velocity_key = "contact_velocity"; // m/s, at first contact
inline constexpr const char* sphere_mass_key = "sphere_mass";           // kg (optional)
inline constexpr const char* restitution_key = "restitution";
inline constexpr const char* first_contact_time_key = "first_contact_time"; // s
inline constexpr const char* contact_time_key = "contact_time";         // s
inline constexpr const char* force_max_key = "force_max";               // N
inline constexpr const char* time_force_max_key = "time_force_max";     // s
inline constexpr const char* approach_max_key = "approach_max";         // m
inline constexpr const char* rebound_velocity_key = "rebound_velocity"; // m/s
inline constexpr const char* energy_error_key = "energy_error";         // 1
inline constexpr const char* time_step_key = "time_step";               // s
// Smoothness of the force history (fractions of the peak force; force_smoothness.hpp).
inline constexpr const char* force_oscillation_key = "force_oscillation";
inline constexpr const char* force_after_release_key = "force_after_release";

// The numerical uncertainty of a run, beside its summary when the run was verified on three
// discretisations (verification.hpp).
inline constexpr const char* verification_file = "verification.json";

// A campaign directory may hold an index of its runs (see postprocess/README.md).
inline constexpr const char* campaign_index_json = "index.json";
inline constexpr const char* campaign_index_csv = "index.csv";

} // namespace impact::postprocess::fem_format
