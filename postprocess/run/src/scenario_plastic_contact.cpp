// scenario_plastic_contact (scenario_plastic_contact.hpp).

#include "impact_postprocess/run/scenario_plastic_contact.hpp"
#include "impact_postprocess/number_format.hpp"
#include "impact_postprocess/run/scenario_materials.hpp"

#include <impact_reduced/contact_formulas.hpp>

#include <sstream>
#include <utility>

namespace impact::postprocess {

namespace {

struct BodyStrength {
  double youngs_modulus, poisson_ratio, yield_strength;
  std::string where; // the parameter Y was read from
  bool elastic_plastic;
};

// A body's yield strength and elastic constants; none without a yield strength.
std::optional<BodyStrength> body_strength(const FemRun& run, const std::string& body) {
  const auto model = run.text_attributes.find(fem_format::material_model_parameter(body));
  const bool plastic =
      model != run.text_attributes.end() && model->second == fem_format::elastic_plastic_model;
  // One yield strength per body, "<Body>/Yield strength"; the result files of impact-fem
  // before it kept an elastic-plastic body's in "<Body>/Elastic-plastic/Yield strength".
  std::string key = fem_format::body_parameter(body, fem_format::yield_strength);
  auto strength = text_number(run, key);
  if (plastic && !(strength && *strength > 0)) {
    key = fem_format::material_parameter(body, model->second, fem_format::yield_strength);
    strength = text_number(run, key);
  }
  if (!strength || !(*strength > 0)) return std::nullopt;
  const auto young = material_constant(run, body, fem_format::youngs_modulus);
  const auto poisson = material_constant(run, body, fem_format::poissons_ratio);
  if (!young || !poisson || !(*young > 0) || !(*poisson > -1 && *poisson < 0.5))
    throw PlasticContactError(run.source + ": '" + key + "' = " + significant(*strength, 6) +
                              " Pa, but the body's material does not record a Young's modulus "
                              "> 0 and a Poisson's ratio in (-1, 0.5) ('" +
                              body + "/Material model' and its constants)");
  return BodyStrength{*young, *poisson, *strength, key, plastic};
}

} // namespace

std::optional<PlasticContact> scenario_plastic_contact(const std::vector<FemRun>& runs) {
  if (runs.empty()) return std::nullopt;
  const FemRun& run = runs.front();
  const auto model =
      run.text_attributes.find(fem_format::material_model_parameter(fem_format::plate_body));
  const bool rigid_plate =
      model != run.text_attributes.end() && model->second == fem_format::rigid_model;
  const auto sphere = body_strength(run, fem_format::sphere_body);
  const auto plate = rigid_plate ? std::nullopt : body_strength(run, fem_format::plate_body);
  if (!sphere && !plate) return std::nullopt;
  // Both bodies' elastic constants are needed for E*, also of a body that does not yield.
  const auto elastic = [&](const std::string& body) {
    const auto young = material_constant(run, body, fem_format::youngs_modulus);
    const auto poisson = material_constant(run, body, fem_format::poissons_ratio);
    if (!young || !poisson)
      throw PlasticContactError(run.source + ": the " + body +
                                "'s Young's modulus and Poisson's "
                                "ratio are not recorded ('" +
                                body +
                                "/Material model' and its "
                                "constants): E* of the plastic contact is unknown");
    return std::pair<double, double>{*young, *poisson};
  };
  const auto [sphere_e, sphere_nu] = sphere
                                         ? std::pair{sphere->youngs_modulus, sphere->poisson_ratio}
                                         : elastic(fem_format::sphere_body);
  PlasticContact contact;
  contact.sphere_youngs_modulus = sphere_e;
  contact.sphere_poisson_ratio = sphere_nu;
  if (!rigid_plate) {
    const auto [plate_e, plate_nu] = plate ? std::pair{plate->youngs_modulus, plate->poisson_ratio}
                                           : elastic(fem_format::plate_body);
    contact.plate_youngs_modulus = plate_e;
    contact.plate_poisson_ratio = plate_nu;
    contact.contact_modulus = reduced::contact_modulus(sphere_e, sphere_nu, plate_e, plate_nu);
  } else {
    contact.contact_modulus = sphere_e / (1 - sphere_nu * sphere_nu);
  }
  // Johnson's first yield of the body with the lower strength.
  const BodyStrength& yielding =
      !plate || (sphere && sphere->yield_strength <= plate->yield_strength) ? *sphere : *plate;
  contact.yield_pressure = reduced::johnson_yield_pressure(yielding.yield_strength);
  contact.yield_strength = yielding.yield_strength;
  contact.yield_poisson_ratio = yielding.poisson_ratio;
  contact.elastic_plastic = yielding.elastic_plastic;
  contact.yield_basis =
      "Johnson's p_y = 1.6 Y with Y = " + significant(yielding.yield_strength, 6) + " Pa ('" +
      yielding.where + "' of " + run.source + ", the body that yields first)";
  return contact;
}

std::string hardening_left_out(const FemRun& run) {
  std::string left_out;
  for (const std::string body : {fem_format::sphere_body, fem_format::plate_body}) {
    const auto model = run.text_attributes.find(fem_format::material_model_parameter(body));
    if (model == run.text_attributes.end() || model->second != fem_format::elastic_plastic_model)
      continue;
    const auto law = run.text_attributes.find(
        body + "/" + fem_format::material_subsection(fem_format::elastic_plastic_model) + "/" +
        fem_format::hardening_law_entry);
    const bool johnson_cook =
        law != run.text_attributes.end() && law->second == fem_format::johnson_cook_law;
    std::string hardening;
    if (johnson_cook) {
      const double b = material_constant(run, body, fem_format::johnson_cook_b).value_or(0);
      const double c = material_constant(run, body, fem_format::johnson_cook_c).value_or(0);
      if (b > 0 || c > 0)
        hardening = "Johnson-Cook B = " + significant(b, 6) + " Pa, C = " + significant(c, 6);
    } else if (const auto h = material_constant(run, body, fem_format::hardening_modulus);
               h && *h > 0) {
      hardening = "linear hardening modulus " + significant(*h, 6) + " Pa";
    }
    if (!hardening.empty())
      left_out += (left_out.empty() ? "" : "; ") + std::string("the ") + body + "'s " + hardening;
  }
  return left_out;
}

std::string hardening_note(const FemRun& run) {
  const std::string left_out = hardening_left_out(run);
  return left_out.empty() ? "no hardening: the law is elastic-perfectly-plastic, like the runs' "
                            "material"
                          : "no hardening enters the law (elastic-perfectly-plastic): it leaves "
                            "out " +
                                left_out + " recorded by the runs";
}

} // namespace impact::postprocess
