#include "impact_postprocess/run/scenario_materials.hpp"
#include "impact_postprocess/number_format.hpp"

#include <impact_reduced/contact_formulas.hpp>
#include <impact_reduced/viscoelastic_dissipation.hpp>

#include <sstream>

namespace impact::postprocess {

namespace {

struct Body {
  std::string model; // "elastic", "kelvin-voigt", ...
  double youngs_modulus;
  double poisson_ratio;
  std::optional<double> deviatoric_retardation_time; // kelvin-voigt only
  std::optional<double> volumetric_retardation_time;
};

// "<Body>/Material model" = name, constants in "<Body>/<Name>/Young's modulus", ...
std::optional<Body> body_of(const FemRun& run, const std::string& body) {
  const auto model = run.text_attributes.find(fem_format::material_model_parameter(body));
  if (model == run.text_attributes.end() || model->second.empty()) return std::nullopt;
  const auto young = material_constant(run, body, fem_format::youngs_modulus);
  const auto poisson = material_constant(run, body, fem_format::poissons_ratio);
  if (!young || !poisson) return std::nullopt;
  Body result{model->second, *young, *poisson, std::nullopt, std::nullopt};
  if (model->second == fem_format::elastic_model) {
    result.deviatoric_retardation_time = result.volumetric_retardation_time = 0.0;
  } else if (model->second == fem_format::elastic_plastic_model) {
    // impact-fem's elastic-plastic body: a Kelvin–Voigt stress C : tau_r d eps/dt in parallel
    // (fem/README), deviatoric and volumetric alike, so tau_d = tau_v = tau_r.
    const auto retardation = material_constant(run, body, fem_format::retardation_time);
    if (retardation)
      result.deviatoric_retardation_time = result.volumetric_retardation_time = *retardation;
  } else if (model->second == fem_format::kelvin_voigt_model) {
    result.deviatoric_retardation_time = material_constant(run, body, fem_format::retardation_time);
    const auto volumetric = material_constant(run, body, fem_format::volumetric_retardation_time);
    if (result.deviatoric_retardation_time && volumetric)
      result.volumetric_retardation_time =
          *volumetric < 0 ? *result.deviatoric_retardation_time : *volumetric;
  }
  return result;
}

std::string describe(const std::string& name, const Body& body) {
  std::string text = name + " " + body.model + " E = " + significant(body.youngs_modulus, 4) +
                     " Pa, nu = " + significant(body.poisson_ratio, 4);
  if (body.model == fem_format::elastic_plastic_model && body.deviatoric_retardation_time)
    text += ", tau_r = " + significant(*body.deviatoric_retardation_time, 4) +
            " s (Kelvin–Voigt in "
            "parallel: tau_d = tau_v = tau_r)";
  else if (body.model == fem_format::kelvin_voigt_model && body.deviatoric_retardation_time &&
           body.volumetric_retardation_time)
    text += ", tau_d = " + significant(*body.deviatoric_retardation_time, 4) +
            " s, tau_v = " + significant(*body.volumetric_retardation_time, 4) + " s";
  return text;
}

} // namespace

std::optional<double> text_number(const FemRun& run, const std::string& key) {
  const auto found = run.text_attributes.find(key);
  if (found == run.text_attributes.end()) return std::nullopt;
  try {
    std::size_t end = 0;
    const double value = std::stod(found->second, &end);
    if (end == found->second.size()) return value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

std::optional<double> material_constant(const FemRun& run, const std::string& body,
                                        const fem_format::MaterialEntry& entry) {
  const auto model = run.text_attributes.find(fem_format::material_model_parameter(body));
  if (model == run.text_attributes.end() || model->second.empty()) return std::nullopt;
  return text_number(run, fem_format::material_parameter(body, model->second, entry));
}

ScenarioMaterials scenario_materials(const std::vector<FemRun>& runs) {
  ScenarioMaterials materials{published_hertz_stiffness,
                              "the runs do not record the scenario's materials, so the published "
                              "steel value 1.7135e10 N/m^1.5 (0.1 kg steel ball on steel) is used",
                              false, std::nullopt, "the runs do not record the bodies' materials"};
  for (const auto& run : runs) {
    const auto sphere = body_of(run, fem_format::sphere_body);
    // "Plate/Material model = rigid" (impact-fem): the fixed rigid plane, no
    // compliance. Hertz's E* is then the sphere's own, twice the E* of two
    // bodies of the sphere's material, and the compliance-weighted A of
    // Kuwabara–Kono is the sphere's own, that of two such bodies: the
    // formulas below are applied to the sphere twice and c doubled.
    const auto plate_model =
        run.text_attributes.find(fem_format::material_model_parameter(fem_format::plate_body));
    const bool rigid_plate =
        plate_model != run.text_attributes.end() && plate_model->second == fem_format::rigid_model;
    const auto plate = rigid_plate ? sphere : body_of(run, fem_format::plate_body);
    const auto radius = text_number(run, fem_format::sphere_radius.path);
    if (!sphere || !plate || !radius) continue;
    try {
      materials.hertz_stiffness =
          (rigid_plate ? 2.0 : 1.0) *
          reduced::hertz_stiffness({sphere->youngs_modulus, sphere->poisson_ratio, *radius},
                                   {plate->youngs_modulus, plate->poisson_ratio});
    } catch (const std::exception&) {
      continue;
    }
    materials.hertz_from_runs = true;
    materials.hertz_basis =
        "Hertz value of the scenario's materials (sphere E = " +
        significant(sphere->youngs_modulus, 4) +
        " Pa, nu = " + significant(sphere->poisson_ratio, 4) + ", R = " + significant(*radius, 4) +
        (rigid_plate ? std::string(" m; rigid plate")
                     : " m; plate E = " + significant(plate->youngs_modulus, 4) +
                           " Pa, nu = " + significant(plate->poisson_ratio, 4)) +
        ") read from " + run.source;
    const bool viscoelastic =
        sphere->deviatoric_retardation_time && sphere->volumetric_retardation_time &&
        plate->deviatoric_retardation_time && plate->volumetric_retardation_time;
    if (sphere->model == fem_format::elastic_model && plate->model == fem_format::elastic_model) {
      materials.dissipative_basis =
          rigid_plate ? "the sphere is elastic and the plate rigid: A = 0, the Hertz model"
                      : "the bodies are elastic: A = 0, the Hertz model";
      return materials;
    }
    if (!viscoelastic) {
      materials.dissipative_basis =
          "no A from the material: the bodies are " + sphere->model + " and " + plate->model +
          " (the formula needs Kelvin–Voigt, elastic-plastic or elastic bodies with their "
          "retardation times)";
      return materials;
    }
    try {
      materials.dissipative_constant = reduced::kuwabara_kono_dissipative_constant(
          {sphere->youngs_modulus, sphere->poisson_ratio, *sphere->deviatoric_retardation_time,
           *sphere->volumetric_retardation_time},
          {plate->youngs_modulus, plate->poisson_ratio, *plate->deviatoric_retardation_time,
           *plate->volumetric_retardation_time});
      materials.dissipative_basis =
          "A = (1 - nu) [tau_v (1 + nu) - tau_d (1 - 2 nu)]^2 / (3 nu^2 [tau_v (1 + nu) + "
          "2 tau_d (1 - 2 nu)]) per body (Brilliantov et al. 1996; = tau when tau_d = tau_v), "
          "compliance-weighted over the two bodies, from " +
          describe("sphere", *sphere) +
          (rigid_plate ? std::string("; rigid plate") : "; " + describe("plate", *plate));
      if (!(*materials.dissipative_constant > 0)) {
        materials.dissipative_constant.reset();
        materials.dissipative_basis =
            "the bodies' retardation times are 0: A = 0, no viscous "
            "loss (" +
            describe("sphere", *sphere) + ")";
      }
    } catch (const std::exception& error) {
      materials.dissipative_basis = std::string("no A from the material: ") + error.what();
    }
    return materials;
  }
  return materials;
}

} // namespace impact::postprocess
