// Viscoelastic spheres (G. Kuwabara, K. Kono, Jpn. J. Appl. Phys. 26 (1987) 1230;
// N. V. Brilliantov, F. Spahn, J.-M. Hertzsch, T. Pöschel, Phys. Rev. E 53 (1996) 5382):
//     F = c x^(3/2) + (3/2) A c x^(1/2) x',     A: dissipative constant (s).
//
// The restitution depends on q = A (c/m)^(2/5) V^(1/5) alone (scale x by
// (m V^2 / c)^(2/5)), so 1 - e ~ V^(1/5) at small q:
//     e = 1 - gamma1 q + gamma2 q^2 - ...   (Schwager and Pöschel, Phys. Rev. E 57 (1998)
//     650; R. Ramírez, T. Pöschel, N. V. Brilliantov, T. Schwager, Phys. Rev. E 60 (1999) 4465)
// gamma1 follows from the energy dissipated along the elastic Hertz trajectory:
//     1 - e ~ (1/(m V)) int (3/2) A c x^(1/2) x'^2 dt = (6/5)(5/4)^(3/5) B(3/5, 3/2) q,
// and gamma2 = (3/5) gamma1^2 (Ramírez et al.). No closed form of e(q) exists: the damping
// for a target restitution is found by root finding (TOMS 748) on the exactly integrated
// restitution of the scaled problem (m = c = V = 1, A = q).
//
// "kuwabara-kono-no-tension" is the same force with the contact ending where it returns to
// 0 (ContactEnd::zero_force). The law as written pulls during the last part of the
// restitution (x + (3/2) A x' < 0); a real contact, like the finite-element one, cannot,
// so the bodies separate there with the surfaces not yet recovered. The scaling argument
// holds for that end of contact too, so e still depends on q alone.

#include "impact_reduced/comparison_laws.hpp"

#include "impact_reduced/invalid_input.hpp"
#include "law_catalogue.hpp"

#include <boost/math/special_functions/beta.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace impact::reduced {

namespace {

ContactForceLaw viscoelastic_force(double stiffness, double dissipative_constant) {
  return [=](double x, double rate) {
    const double root = std::sqrt(x);
    return stiffness * root * (x + 1.5 * dissipative_constant * rate);
  };
}

// Restitution of the scaled problem as a function of q; 0 if the law holds the body.
double scaled_restitution(double q, ContactEnd end) {
  if (q == 0) return 1.0;
  try {
    return integrate_impact(1.0, 1.0, viscoelastic_force(1.0, q), 1e-12, end).restitution;
  } catch (const ContactDoesNotEnd&) {
    return 0.0;
  }
}

// q with scaled_restitution(q) = e, to ~1e-11 relative.
double scaled_damping_for_restitution(double restitution, ContactEnd end) {
  if (restitution >= 1) return 0.0;
  const auto gap = [=](double q) { return scaled_restitution(q, end) - restitution; };
  double lower = 0;
  double lower_gap = 1 - restitution;
  double upper = (1 - restitution) / brilliantov_gamma1();
  double upper_gap = gap(upper);
  while (upper_gap > 0) {
    lower = upper;
    lower_gap = upper_gap;
    upper *= 2;
    if (upper > 1e6)
      throw std::runtime_error("kuwabara-kono: no damping gives restitution " +
                               std::to_string(restitution));
    upper_gap = gap(upper);
  }
  std::uintmax_t iterations = 100;
  const auto root =
      boost::math::tools::toms748_solve(gap, lower, upper, lower_gap, upper_gap,
                                        boost::math::tools::eps_tolerance<double>(36), iterations);
  return 0.5 * (root.first + root.second);
}

double scale_of_q(const ContactSetup& setup, double velocity) {
  return std::pow(setup.stiffness / setup.mass, 0.4) * std::pow(velocity, 0.2);
}

} // namespace

double brilliantov_gamma1() {
  return 1.2 * std::pow(1.25, 0.6) * boost::math::beta(0.6, 1.5);
}

double brilliantov_restitution_series(double dissipative_constant, const ContactSetup& setup,
                                      double velocity) {
  require_non_negative("dissipative_constant", dissipative_constant);
  require_positive("mass", setup.mass);
  require_positive("stiffness", setup.stiffness);
  require_positive("velocity", velocity);
  const double q = dissipative_constant * scale_of_q(setup, velocity);
  const double gamma1 = brilliantov_gamma1();
  return 1 - gamma1 * q + 0.6 * gamma1 * gamma1 * q * q;
}

namespace laws {

namespace {

ComparisonLaw viscoelastic_sphere_law(ContactEnd end) {
  const bool no_tension = end == ContactEnd::zero_force;
  ComparisonLaw law;
  law.name = no_tension ? "kuwabara-kono-no-tension" : "kuwabara-kono";
  law.formula = std::string("F = c x^(3/2) + (3/2) A c x^(1/2) x'") +
                (no_tension ? ", contact ends when F returns to 0 (no tension)" : "") +
                ", A from the exactly integrated restitution (root finding; e depends on "
                "A (c/m)^(2/5) V^(1/5) only)";
  law.reference =
      "Kuwabara and Kono, Jpn. J. Appl. Phys. 26 (1987) 1230; Brilliantov et al., "
      "Phys. Rev. E 53 (1996) 5382; Ramirez et al., Phys. Rev. E 60 (1999) 4465";
  law.damping_name = "A";
  law.damping_unit = "s";
  law.required_exponent = 1.5;
  law.damping_for_restitution = [end](double restitution, double velocity,
                                      const ContactSetup& setup) {
    return scaled_damping_for_restitution(restitution, end) / scale_of_q(setup, velocity);
  };
  law.force_law = [](double dissipative_constant, const ContactSetup& setup) {
    return viscoelastic_force(setup.stiffness, dissipative_constant);
  };
  law.contact_end = end;
  return law;
}

} // namespace

ComparisonLaw kuwabara_kono() {
  return viscoelastic_sphere_law(ContactEnd::zero_approach);
}
ComparisonLaw kuwabara_kono_no_tension() {
  return viscoelastic_sphere_law(ContactEnd::zero_force);
}

} // namespace laws
} // namespace impact::reduced
