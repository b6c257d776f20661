// The Hunt–Crossley family: F = c x^n (1 + b x'), with the damping b that each author
// assigns to a target restitution e at impact velocity V. The force law is Hunt–Crossley's;
// only the map e -> b differs. Since the exact restitution of this force is a function of
// beta = b V alone (the Lambert-W result of the spec), every map below is, in effect, an
// approximation of the exact inverse beta(e), accurate only for e near 1.
//
// Maps, as given by their authors (and tabulated in M. R. da Silva, F. Marques,
// M. T. da Silva, P. Flores, "A compendium of contact force models inspired by Hunt and
// Crossley's cornerstone work", Mech. Mach. Theory 167 (2022) 104501):
//   Lankarani & Nikravesh, J. Mech. Des. 112 (1990) 369-376:   b = 3 (1 - e^2) / (4 V)
//   Flores, Machado, Silva & Martins, Multibody Syst. Dyn. 25 (2011) 357-375:
//                                                               b = 8 (1 - e) / (5 e V)
//   Gonthier, McPhee, Lange & Piedboeuf, Multibody Syst. Dyn. 11 (2004) 209-233:
//                                                               b = (1 - e^2) / (e V)
//   Hu & Guo, Multibody Syst. Dyn. 35 (2015) 131-151:          b = 3 (1 - e) / (2 e V)
//   Zhiying & Qishao, J. Dyn. Control 4 (2006) 294-298:        b = 3 (1 - e^2) exp(2 (1 - e)) / (4 V)

#include "impact_reduced/comparison_laws.hpp"

#include "law_catalogue.hpp"

#include <cmath>
#include <utility>

namespace impact::reduced::laws {

namespace {

ComparisonLaw hertz_damped(std::string name, std::string map, std::string reference,
                           double (*damping)(double restitution, double velocity)) {
  ComparisonLaw law;
  law.name = std::move(name);
  law.formula = "F = c x^n (1 + b x'), " + map;
  law.reference = std::move(reference);
  law.damping_name = "b";
  law.damping_unit = "s/m";
  law.damping_for_restitution = [damping](double restitution, double velocity,
                                          const ContactSetup&) {
    return damping(restitution, velocity);
  };
  law.force_law = [](double b, const ContactSetup& setup) -> ContactForceLaw {
    const double c = setup.stiffness;
    const double n = setup.exponent;
    return [=](double x, double rate) { return c * std::pow(x, n) * (1 + b * rate); };
  };
  return law;
}

} // namespace

ComparisonLaw lankarani_nikravesh() {
  return hertz_damped("lankarani-nikravesh", "b = 3 (1 - e^2) / (4 V)",
                      "Lankarani and Nikravesh, J. Mech. Des. 112 (1990) 369-376",
                      [](double e, double v) { return 3 * (1 - e * e) / (4 * v); });
}

ComparisonLaw flores() {
  return hertz_damped("flores", "b = 8 (1 - e) / (5 e V)",
                      "Flores, Machado, Silva and Martins, Multibody Syst. Dyn. 25 (2011) 357-375",
                      [](double e, double v) { return 8 * (1 - e) / (5 * e * v); });
}

ComparisonLaw gonthier() {
  return hertz_damped(
      "gonthier", "b = (1 - e^2) / (e V)",
      "Gonthier, McPhee, Lange and Piedboeuf, Multibody Syst. Dyn. 11 (2004) 209-233",
      [](double e, double v) { return (1 - e * e) / (e * v); });
}

ComparisonLaw hu_guo() {
  return hertz_damped("hu-guo", "b = 3 (1 - e) / (2 e V)",
                      "Hu and Guo, Multibody Syst. Dyn. 35 (2015) 131-151",
                      [](double e, double v) { return 3 * (1 - e) / (2 * e * v); });
}

ComparisonLaw zhiying_qishao() {
  return hertz_damped("zhiying-qishao", "b = 3 (1 - e^2) exp(2 (1 - e)) / (4 V)",
                      "Zhiying and Qishao, J. Dyn. Control 4 (2006) 294-298",
                      [](double e, double v) {
                        return 3 * (1 - e * e) * std::exp(2 * (1 - e)) / (4 * v);
                      });
}

} // namespace impact::reduced::laws
