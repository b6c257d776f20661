#pragma once
/**
 * @file
 * The result files of impact-fem: the names the writer (fem/source/impact_problem.cc,
 * fem/source/output/history.cc, the postprocessors in fem/source/postprocess/, the campaign
 * in fem/source/campaign.cc) and the reader (postprocess/run/) both use, with their SI
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

#include <string>
#include <string_view>

namespace impact_fem::result_files
{
  // ---- Files of a run directory ------------------------------------------------------------
  inline constexpr const char *history_file = "history.h5";
  inline constexpr const char *incomplete_history_file =
    "history.incomplete.h5";
  inline constexpr const char *summary_file      = "summary.json";
  inline constexpr const char *verification_file = "verification.json";

  // ---- A campaign directory: the index of its runs -----------------------------------------
  inline constexpr const char *campaign_index_json = "index.json";

  // ---- Root attributes of the HDF5 file ----------------------------------------------------
  inline constexpr const char *status_attribute  = "status";
  inline constexpr const char *status_complete   = "complete";
  inline constexpr const char *status_incomplete = "incomplete";
  inline constexpr const char *result_attribute_prefix =
    "result: "; // + a summary key
  inline constexpr const char *sphere_mass_attribute = "sphere_mass [kg]";
  // Attributes of every dataset.
  inline constexpr const char *unit_attribute        = "unit";
  inline constexpr const char *description_attribute = "description";

  // ---- Per-step datasets, with their units ---------------------------------------------------
  inline constexpr const char *time_dataset          = "time";
  inline constexpr const char *time_unit             = "s";
  inline constexpr const char *contact_force_dataset = "contact_force"; // >= 0
  inline constexpr const char *contact_force_unit    = "N";
  inline constexpr const char *approach_dataset =
    "approach"; // the reduced models' x
  inline constexpr const char *approach_unit = "m";
  inline constexpr const char *sphere_velocity_dataset =
    "sphere_velocity"; // downward +
  inline constexpr const char *sphere_velocity_unit = "m/s";
  // Nonlinear materials only: the iterations of each step's solve and the out-of-balance
  // force of the accepted iterate relative to the step's load (both dimensionless).
  inline constexpr const char *newton_iterations_dataset = "newton_iterations";
  inline constexpr const char *newton_residual_dataset   = "newton_residual";

  // ---- Keys of summary.json (and, with the prefix above, of the result attributes) ---------
  // Their units: summary_units below.
  inline constexpr const char *complete_key = "complete"; // boolean
  // Which definitions of the derived quantities (contact time, peaks,
  // oscillation) wrote the summary: 2 since the peak force is the vertex of a
  // least-squares parabola (absent before). A campaign redoes a run whose
  // summary has another version, so that a verification never compares peaks
  // of two definitions.
  inline constexpr const char *summary_version_key = "summary_version"; // 1
  inline constexpr int         summary_version     = 2;
  inline constexpr const char *impact_velocity_key =
    "impact_velocity"; // m/s, at t = 0
  inline constexpr const char *contact_velocity_key =
    "contact_velocity"; // m/s, first contact
  inline constexpr const char *sphere_mass_key = "sphere_mass"; // kg
  inline constexpr const char *restitution_key = "restitution"; // 1
  inline constexpr const char *first_contact_time_key =
    "first_contact_time";                                                 // s
  inline constexpr const char *contact_time_key     = "contact_time";     // s
  inline constexpr const char *force_max_key        = "force_max";        // N
  inline constexpr const char *time_force_max_key   = "time_force_max";   // s
  inline constexpr const char *approach_max_key     = "approach_max";     // m
  inline constexpr const char *rebound_velocity_key = "rebound_velocity"; // m/s
  inline constexpr const char *time_step_key        = "time_step";        // s
  // Smoothness of the force history, fractions of the peak force.
  inline constexpr const char *force_oscillation_key = "force_oscillation"; // 1
  inline constexpr const char *force_after_release_key =
    "force_after_release"; // 1
  // Energy balance (the energy postprocessor), fractions of the initial energy.
  inline constexpr const char *energy_error_key = "energy_error"; // 1
  // The balance error at the end of the run (signed), what the FEM's target of 1e-4 judges.
  inline constexpr const char *energy_error_final_key =
    "energy_error_final"; // 1
  inline constexpr const char *lost_energy_fraction_key =
    "lost_energy_fraction"; // 1
  inline constexpr const char *radiated_energy_fraction_key =
    "radiated_energy_fraction"; // 1
  inline constexpr const char *dissipated_energy_fraction_key =
    "dissipated_energy_fraction"; // 1
  // Stresses (the stress postprocessor): "von_mises_max_" + body, "yield_strength_" + body
  // with body "sphere" or "plate" [Pa]; over both bodies max_von_mises [Pa] and
  // yield_exceeded (boolean, null without a yield strength).
  inline constexpr const char *von_mises_max_prefix  = "von_mises_max_";
  inline constexpr const char *yield_strength_prefix = "yield_strength_";
  inline constexpr const char *max_von_mises_key     = "max_von_mises"; // Pa
  inline constexpr const char *yield_exceeded_key = "yield_exceeded"; // boolean
  // The bodies' materials: {"sphere": {...}, "plate": {...}}, each with "material model",
  // "material" (the table's name or null) and "constants": {entry: {"parameter", "value",
  // "unit", "origin" ("scenario" | "table"), "source" (the table's citation)}}.
  inline constexpr const char *materials_key = "materials";
  // The discretisation a run used: {"expected_contact": {"law" ("Hertz" |
  // "Jackson-Green"), "approach_max" [m], "contact_radius" [m],
  // "contact_time" [s], with a yielding body "yielding_body" and
  // "velocity_ratio" V/V_y}, "entries": {entry path: {"value", "unit",
  // "origin" ("auto" | "scenario")}}} for Mesh/Contact element size,
  // Uniform zone radius, Contact surface radius and Time integration/Steps
  // per contact time.
  inline constexpr const char *discretisation_key = "discretisation";

  /// The unit of each numeric summary key (SI; "1" for a ratio), by the names above.
  struct KeyUnit
  {
    const char *key;
    const char *unit;
  };
  inline constexpr KeyUnit summary_units[] = {
    {summary_version_key, "1"},
    {impact_velocity_key, "m/s"},
    {contact_velocity_key, "m/s"},
    {sphere_mass_key, "kg"},
    {restitution_key, "1"},
    {first_contact_time_key, "s"},
    {contact_time_key, "s"},
    {force_max_key, "N"},
    {time_force_max_key, "s"},
    {approach_max_key, "m"},
    {rebound_velocity_key, "m/s"},
    {time_step_key, "s"},
    {force_oscillation_key, "1"},
    {force_after_release_key, "1"},
    {energy_error_key, "1"},
    {energy_error_final_key, "1"},
    {lost_energy_fraction_key, "1"},
    {radiated_energy_fraction_key, "1"},
    {dissipated_energy_fraction_key, "1"},
    {max_von_mises_key, "Pa"}};

  /// The unit of a numeric summary key ("von_mises_max_<body>" and "yield_strength_<body>":
  /// Pa); none for "complete", "yield_exceeded" and any other text.
  inline const char *
  summary_unit(const std::string_view key)
  {
    for (const KeyUnit &entry : summary_units)
      if (key == entry.key)
        return entry.unit;
    if (key.substr(0, std::string_view(von_mises_max_prefix).size()) ==
          von_mises_max_prefix ||
        key.substr(0, std::string_view(yield_strength_prefix).size()) ==
          yield_strength_prefix)
      return "Pa";
    return nullptr;
  }

  // ---- The run's parameters --------------------------------------------------------------
  // impact-fem records each entry of its parameter file as a text attribute of the HDF5 root
  // named "<subsection>/<entry>" (nested subsections joined by '/'); a sweep axis is named
  // the same way. The entries the reader interprets are declared by impact-fem under these
  // names, with the units of their help texts.
  inline constexpr const char *scenario_subsection = "Scenario";
  struct Parameter
  {
    const char *subsection; // of the parameter file
    const char *entry;      // the entry's name in it
    const char *path; // "<subsection>/<entry>": the attribute, the sweep axis
    const char *unit; // SI; "" for a text, a count or a ratio
  };
  inline constexpr Parameter impact_velocity{scenario_subsection,
                                             "Impact velocity",
                                             "Scenario/Impact velocity",
                                             "m/s"};
  inline constexpr Parameter initial_gap{scenario_subsection,
                                         "Initial gap",
                                         "Scenario/Initial gap",
                                         "m"};
  inline constexpr Parameter sphere_radius{scenario_subsection,
                                           "Sphere radius",
                                           "Scenario/Sphere radius",
                                           "m"};
  inline constexpr Parameter plate_radius{scenario_subsection,
                                          "Plate radius",
                                          "Scenario/Plate radius",
                                          "m"};
  inline constexpr Parameter plate_thickness{scenario_subsection,
                                             "Plate thickness",
                                             "Scenario/Plate thickness",
                                             "m"};
  /// The parameters with a unit that a sweep may vary (a sweep axis of any other parameter
  /// carries no unit on the page).
  inline constexpr Parameter scenario_parameters[] = {impact_velocity,
                                                      initial_gap,
                                                      sphere_radius,
                                                      plate_radius,
                                                      plate_thickness};

  /// Whether every path above is its subsection and entry joined by '/'.
  constexpr bool
  paths_are_joined()
  {
    for (const Parameter &parameter : scenario_parameters)
      {
        const char *path = parameter.path;
        for (const char *c = parameter.subsection; *c; ++c, ++path)
          if (*path != *c)
            return false;
        if (*path++ != '/')
          return false;
        for (const char *c = parameter.entry; *c; ++c, ++path)
          if (*path != *c)
            return false;
        if (*path != '\0')
          return false;
      }
    return true;
  }
  static_assert(paths_are_joined(),
                "a parameter's path is not <subsection>/<entry>");

  /// The unit of the parameter at `path` ("Scenario/Plate thickness" -> "m"); "" for any
  /// parameter not listed above.
  inline std::string_view
  parameter_unit(const std::string_view path)
  {
    for (const Parameter &parameter : scenario_parameters)
      if (path == parameter.path)
        return parameter.unit;
    return "";
  }

  // Each body ("Sphere", "Plate") has the entry "Material model" (a material's name, or
  // "rigid" for a fixed rigid plate) and one subsection per material named by
  // material_subsection, holding the material's constants: "<body>/<subsection>/<entry>".
  inline constexpr const char *sphere_body           = "Sphere";
  inline constexpr const char *plate_body            = "Plate";
  inline constexpr const char *material_model_entry  = "Material model";
  inline constexpr const char *elastic_model         = "elastic";
  inline constexpr const char *kelvin_voigt_model    = "kelvin-voigt";
  inline constexpr const char *elastic_plastic_model = "elastic-plastic";
  inline constexpr const char *rigid_model           = "rigid";
  // The constants of a material, with their units ("1": a ratio).
  struct MaterialEntry
  {
    const char *entry;
    const char *unit;
  };
  inline constexpr MaterialEntry youngs_modulus{"Young's modulus", "Pa"};
  inline constexpr MaterialEntry poissons_ratio{"Poisson's ratio", "1"};
  inline constexpr MaterialEntry density{"Density", "kg/m^3"};
  inline constexpr MaterialEntry retardation_time{"Retardation time", "s"};
  // < 0: the deviatoric "Retardation time" (Kelvin-Voigt).
  inline constexpr MaterialEntry volumetric_retardation_time{
    "Volumetric retardation time",
    "s"};
  // Of an elastic-plastic material; also the body's own entry beside "Material model"
  // ("<body>/Yield strength", body_parameter: the stress postprocessor's check, 0: none).
  inline constexpr MaterialEntry yield_strength{"Yield strength", "Pa"};
  // The hardening of an elastic-plastic material: "Hardening law" is linear or johnson-cook.
  inline constexpr const char   *hardening_law_entry = "Hardening law";
  inline constexpr const char   *johnson_cook_law    = "johnson-cook";
  inline constexpr MaterialEntry hardening_modulus{"Hardening modulus", "Pa"};
  inline constexpr MaterialEntry johnson_cook_b{"Johnson-Cook B", "Pa"};
  inline constexpr MaterialEntry johnson_cook_c{"Johnson-Cook C", "1"};

  /// The subsection of a material's constants: its name with an upper-case first letter
  /// ("kelvin-voigt" -> "Kelvin-voigt").
  inline std::string
  material_subsection(const std::string_view model)
  {
    std::string name(model);
    if (!name.empty() && name[0] >= 'a' && name[0] <= 'z')
      name[0] = static_cast<char>(name[0] - 'a' + 'A');
    return name;
  }

  /// "<body>/Material model".
  inline std::string
  material_model_parameter(const std::string_view body)
  {
    return std::string(body) + "/" + material_model_entry;
  }

  /// "<body>/<entry>": an entry of the body's own subsection.
  inline std::string
  body_parameter(const std::string_view body, const MaterialEntry &entry)
  {
    return std::string(body) + "/" + entry.entry;
  }

  /// "<body>/<material_subsection(model)>/<entry>": a constant of the body's material.
  inline std::string
  material_parameter(const std::string_view body,
                     const std::string_view model,
                     const MaterialEntry   &entry)
  {
    return std::string(body) + "/" + material_subsection(model) + "/" +
           entry.entry;
  }
} // namespace impact_fem::result_files
