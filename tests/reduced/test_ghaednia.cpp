// The Ghaednia-Brake-Berryhill-Jackson (2019) loading law with linear hardening
// (ghaednia.hpp): the formulas against numbers evaluated independently in Python (mpmath,
// 40 digits) and against a re-writing in long double; the jump at 1.9 delta_c; the loading
// work against tanh-sinh quadrature in 50 digits; the stiffness against a central
// difference; the limits E_t = 0 (Jackson-Green-like) and E_t -> E_s; bad input; impacts.

#include "impact_reduced/ghaednia.hpp"
#include "impact_reduced/invalid_input.hpp"
#include "impact_reduced/sphere_flat_fits.hpp"
#include "plastic_impact_reference.hpp"

#include <boost/math/constants/constants.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <tuple>
#include <utility>

namespace {

using namespace impact::reduced;
using boost::multiprecision::cpp_bin_float_50;

// Steel sphere on a steel flat (E = 210 GPa, nu = 0.3), R = 10 mm, Y = 1 GPa.
constexpr double steel_modulus = 210e9;
const SphereFlatContact steel{0.01, 1 / (2 * (1 - 0.09) / steel_modulus), 1e9, 0.3};
const double steel_mass = 4.0 / 3.0 * 3.14159265358979323846 * 1e-6 * 7800;
// Aluminium sphere (71 GPa, 0.33) on a steel flat (200 GPa, 0.3), R = 1 mm, Y = 500 MPa:
// parameter set 4 of tmd-lab/microslip-rough-contact TESTS/verification_normal_plasticity.m.
constexpr double aluminium_modulus = 71e9;
const SphereFlatContact aluminium{1e-3, 1 / ((1 - 0.33 * 0.33) / 71e9 + (1 - 0.09) / 200e9), 500e6,
                                  0.33};

double relative(long double value, long double reference) {
  return double(std::abs(value - reference) / std::abs(reference));
}

// The law re-written from the formulas of the header, in any floating type; the decimal
// constants are exact ratios of integers so that they carry the type's precision.
template <class Real>
struct ReferenceLaw {
  Real radius, e_star, yield, nu, e_s, e_t;
  Real c, critical, critical_load, b, r, s;
  ReferenceLaw(const SphereFlatContact& contact, double youngs, double tangent)
      : radius(contact.radius),
        e_star(contact.contact_modulus),
        yield(contact.yield_strength),
        nu(contact.poisson_ratio),
        e_s(youngs),
        e_t(tangent) {
    using std::exp;
    using std::sqrt;
    const Real pi = boost::math::constants::pi<Real>();
    c = Real(1295) / 1000 * exp(Real(736) / 1000 * nu);
    critical = (pi * c * yield / (2 * e_star)) * (pi * c * yield / (2 * e_star)) * radius;
    const Real pressure = c * pi * yield / 2;
    critical_load =
        Real(4) / 3 * (radius / e_star) * (radius / e_star) * pressure * pressure * pressure;
    b = Real(14) / 100 * exp(23 * yield / e_star);
    r = e_t / e_s;
    s = sqrt(e_s / yield);
  }
  Real transition() const { return Real(19) / 10 * critical; }
  Real hertz(Real x) const {
    using std::sqrt;
    return Real(4) / 3 * e_star * sqrt(radius) * x * sqrt(x);
  }
  Real upsilon(Real x) const {
    using std::exp;
    using std::pow;
    return -2 * s * pow(r, 1 - (x - critical) / radius) / ((4 - 3 * exp(-2 * s * r)) * (1 - r));
  }
  Real contact_radius(Real x) const {
    using std::exp;
    using std::pow;
    using std::sqrt;
    const Real hertzian = sqrt(radius * x);
    if (x <= transition()) return hertzian;
    const Real plastic = hertzian * pow(x / critical / (Real(19) / 10), b / 2);
    return hertzian + (plastic - hertzian) * exp(upsilon(x));
  }
  // F_p with the contact radius a.
  Real plastic(Real x, Real a) const {
    using std::cos;
    using std::exp;
    using std::pow;
    const Real pi = boost::math::constants::pi<Real>();
    const Real w = x / critical;
    const Real hardness = Real(284) / 100 - Real(92) / 100 * (1 - cos(pi * a / radius));
    return critical_load * (exp(-pow(w, Real(5) / 12) / 4) * pow(w, Real(3) / 2) +
                            4 * hardness / c * (1 - exp(-pow(w, Real(5) / 9) / 25)) * w);
  }
  Real force(Real x) const {
    using std::exp;
    if (x <= transition()) return hertz(x);
    const Real fp = plastic(x, contact_radius(x));
    return fp + (hertz(x) - fp) * (1 - exp(-Real(33) / 10 * r));
  }
};

// Numbers from the formulas evaluated independently with mpmath at 40 digits (the script
// below, /usr/bin/python3 with mpmath 1.2.1), rounded to 17 digits: at x = q R, the force
// F, the contact radius a, the work integral_0^x F (mpmath.quad, split at 1.9 delta_c) and
// dF/dx (mpmath.diff).
//
//   from mpmath import mp, mpf, sqrt, exp, cos, pi, quad, diff
//   mp.dps = 40
//   def case(R, Es, nus, Ef, nuf, Y, Et):
//       Estar = 1 / ((1 - nus**2) / Es + (1 - nuf**2) / Ef)
//       C = mpf('1.295') * exp(mpf('0.736') * nus)
//       dc = (pi * C * Y / (2 * Estar))**2 * R
//       Pc = mpf(4) / 3 * (R / Estar)**2 * (C * pi * Y / 2)**3
//       B = mpf('0.14') * exp(23 * Y / Estar)
//       r, s = Et / Es, sqrt(Es / Y)
//       def radius(x):
//           w, ae = x / dc, sqrt(R * x)
//           if w <= mpf('1.9'): return ae
//           ap = ae * (w / mpf('1.9'))**(B / 2)
//           u = -2 * s * r**(1 - (x - dc) / R) / ((4 - 3 * exp(-2 * s * r)) * (1 - r))
//           return ae + (ap - ae) * exp(u)
//       def force(x):
//           w, Fe = x / dc, mpf(4) / 3 * Estar * sqrt(R) * x**mpf('1.5')
//           if w <= mpf('1.9'): return Fe
//           h = mpf('2.84') - mpf('0.92') * (1 - cos(pi * radius(x) / R))
//           Fp = Pc * (exp(-w**(mpf(5) / 12) / 4) * w**mpf('1.5')
//                      + 4 * h / C * (1 - exp(-w**(mpf(5) / 9) / 25)) * w)
//           return Fp + (Fe - Fp) * (1 - exp(-mpf('3.3') * r))
//       print("E* =", mp.nstr(Estar, 17), " delta_c =", mp.nstr(dc, 17))
//       for q in ['1e-5', '0.001', '0.01', '0.05']:
//           x = mpf(q) * R
//           work = quad(force, [0, min(x, mpf('1.9') * dc), x])
//           print(q, [mp.nstr(v, 17) for v in (force(x), radius(x), work, diff(force, x))])
//   case(mpf('0.01'), mpf('210e9'), mpf('0.3'), mpf('210e9'), mpf('0.3'), mpf('1e9'),
//        mpf('0.02') * mpf('210e9'))
//   case(mpf('1e-3'), mpf('71e9'), mpf('0.33'), mpf('200e9'), mpf('0.3'), mpf('500e6'),
//        mpf('0.1') * mpf('71e9'))
//
// Output: steel E* = 115384615384.61538, delta_c = 4.8335689778144957e-6 (x/delta_c = 0.021,
// 2.07, 20.7, 103); aluminium E* = 58477123913.849195, delta_c = 4.9171128769489098e-7
// (x/delta_c = 0.020, 2.03, 20.3, 102).
struct PythonPoint {
  double approach_over_radius, force, contact_radius, work, stiffness;
};
const PythonPoint steel_points[] = {
    {1e-5, 0.4865042554105199, 3.1622776601683793e-5, 1.9460170216420796e-8, 7297563.8311577985},
    {0.001, 485.03691302757534, 0.0003180161145703994, 0.0019461697405392631, 68658714.676765103},
    {0.01, 11156.098386701415, 0.0011736877111102653, 0.48053634094052334, 144286080.00492587},
    {0.05, 79455.127002157587, 0.0029040554401096303, 18.210368569648613, 179152259.23538424}};
const PythonPoint aluminium_points[] = {
    {1e-5, 0.0024656120344488455, 3.1622776601683793e-6, 9.862448137795382e-12, 369841.80516732683},
    {0.001, 2.4516318160216678, 3.1712952645822315e-5, 9.8569637915906128e-7, 3518534.4904571819},
    {0.01, 61.337980734418811, 0.00011082047922994986, 0.00025860386431551201, 8311616.3889436026},
    {0.05, 513.23510974014908, 0.00026429070672253873, 0.011141523882498767, 13179955.068521417}};

void expect_python_points(const GhaedniaContact& law, double radius, const PythonPoint* points,
                          const char* name) {
  double worst_force = 0, worst_radius = 0, worst_work = 0, worst_stiffness = 0;
  for (int i = 0; i < 4; ++i) {
    const PythonPoint& p = points[i];
    const double x = p.approach_over_radius * radius;
    worst_force = std::max(worst_force, relative(law.loading_force(x), p.force));
    worst_radius = std::max(worst_radius, relative(law.contact_radius(x), p.contact_radius));
    worst_work = std::max(worst_work, relative(law.loading_work(x), p.work));
    worst_stiffness = std::max(worst_stiffness, relative(law.loading_stiffness(x), p.stiffness));
  }
  std::cout << name << " vs mpmath: worst relative difference F " << worst_force << ", a "
            << worst_radius << ", W " << worst_work << ", dF/dx " << worst_stiffness << "\n";
  EXPECT_LT(worst_force, 1e-14) << name;
  EXPECT_LT(worst_radius, 1e-14) << name;
  EXPECT_LT(worst_work, 1e-14) << name;
  EXPECT_LT(worst_stiffness, 1e-13) << name;
}

TEST(Ghaednia, CriticalValuesByHand) {
  const GhaedniaContact law(steel, steel_modulus, 0.02 * steel_modulus);
  // The same delta_c and P_c as Jackson-Green (Eqs. 5, 29).
  EXPECT_NEAR(law.critical_interference(), 4.8335689778144957e-6, 1e-15 * 4.83e-6);
  EXPECT_NEAR(law.critical_interference(), jackson_green_critical_interference(steel),
              1e-15 * law.critical_interference());
  EXPECT_NEAR(law.critical_load(), jackson_green_critical_load(steel), 1e-15 * law.critical_load());
  EXPECT_EQ(law.transition_approach(), 1.9 * law.critical_interference());
  EXPECT_NEAR(law.elastic_weight(), 1 - std::exp(-3.3 * 0.02), 1e-16);
}

TEST(Ghaednia, MatchesTheFormulasEvaluatedInPython) {
  expect_python_points(GhaedniaContact(steel, steel_modulus, 4.2e9), steel.radius, steel_points,
                       "steel, E_t/E_s = 0.02");
  expect_python_points(GhaedniaContact(aluminium, aluminium_modulus, 7.1e9), aluminium.radius,
                       aluminium_points, "aluminium, E_t/E_s = 0.1");
}

const double hardening_ratios[] = {0.0, 1e-4, 0.005, 0.02, 0.1, 0.5, 0.9};

TEST(Ghaednia, ForceAndRadiusAgainstALongDoubleRewrite) {
  double worst_force = 0, worst_radius = 0;
  for (const auto& [contact, modulus] :
       {std::pair{steel, steel_modulus}, std::pair{aluminium, aluminium_modulus}})
    for (const double ratio : hardening_ratios) {
      const GhaedniaContact law(contact, modulus, ratio * modulus);
      const ReferenceLaw<long double> reference(contact, modulus, ratio * modulus);
      for (double w = 0.01; w < 2000; w *= 1.07) {
        const double x = w * law.critical_interference();
        worst_force = std::max(worst_force, relative(law.loading_force(x), reference.force(x)));
        worst_radius =
            std::max(worst_radius, relative(law.contact_radius(x), reference.contact_radius(x)));
      }
    }
  std::cout << "vs long double, omega* in [0.01, 2000], 7 hardening ratios, 2 materials: F "
            << worst_force << ", a " << worst_radius << "\n";
  EXPECT_LT(worst_force, 1e-14);
  EXPECT_LT(worst_radius, 1e-14);
}

TEST(Ghaednia, LoadingIsIncreasingUpToTheRadius) {
  // Up to x = R (omega* = 2069 for steel). Beyond, with E_t = 0, the force falls from
  // x = 1.44 R on (a = 2.25 R there: the cosine of Eq. 28 has turned the hardness down).
  for (const double ratio : hardening_ratios) {
    const GhaedniaContact law(steel, steel_modulus, ratio * steel_modulus);
    double previous = 0;
    for (double w = 0.01; w * law.critical_interference() <= steel.radius; w *= 1.01) {
      const double force = law.loading_force(w * law.critical_interference());
      EXPECT_GT(force, previous) << "E_t/E_s = " << ratio << ", omega* = " << w;
      previous = force;
    }
  }
}

TEST(Ghaednia, JumpAtTheTransitionIsMeasured) {
  // At 1.9 delta_c, a_p = a_e, so a = a_e whatever E_t, and F_p(1.9 delta_c) does not depend
  // on E_t: the jump of Eq. 30 is exp(-3.3 r) times the jump of the elastic-perfectly
  // plastic fit.
  double jump_perfectly_plastic = 0;
  for (const auto& [contact, modulus, name] :
       {std::tuple{steel, steel_modulus, "steel"},
        std::tuple{aluminium, aluminium_modulus, "aluminium"}}) {
    std::cout << name << " (Y/E* = " << contact.yield_strength / contact.contact_modulus
              << "): jump at 1.9 delta_c";
    for (const double ratio : {0.0, 0.02, 0.1, 0.5, 0.999999}) {
      const GhaedniaContact law(contact, modulus, ratio * modulus);
      const double t = law.transition_approach();
      const double above = std::nextafter(t, 2 * t);
      const double jump = law.loading_force(above) / law.loading_force(t) - 1;
      // The fit's slope on the right over Hertz's on the left.
      const double slope =
          law.loading_stiffness(t) / law.loading_stiffness(std::nextafter(t, 0.0)) - 1;
      if (ratio == 0) jump_perfectly_plastic = jump;
      std::cout << "  [E_t/E_s = " << ratio << ": F " << jump << ", slope " << slope << "]";
      // The sign depends on C(nu) through the fit: up for steel, down for aluminium.
      EXPECT_GT(std::abs(jump), 0.0);
      EXPECT_LT(std::abs(jump), 0.005);
      EXPECT_NEAR(jump, std::exp(-3.3 * ratio) * jump_perfectly_plastic,
                  1e-10 * std::abs(jump_perfectly_plastic));
      EXPECT_LT(slope, 0.0);
      EXPECT_GT(slope, -0.07);
      EXPECT_EQ(law.contact_radius(t), std::sqrt(contact.radius * t));
      EXPECT_NEAR(law.contact_radius(above), std::sqrt(contact.radius * t),
                  1e-14 * std::sqrt(contact.radius * t));
    }
    std::cout << "\n";
  }
}

TEST(Ghaednia, WorkAgainstTanhSinhIn50Digits) {
  boost::math::quadrature::tanh_sinh<cpp_bin_float_50> integrator;
  double worst = 0;
  for (const auto& [contact, modulus] :
       {std::pair{steel, steel_modulus}, std::pair{aluminium, aluminium_modulus}})
    for (const double ratio : {0.0, 0.02, 0.5}) {
      const GhaedniaContact law(contact, modulus, ratio * modulus);
      const ReferenceLaw<cpp_bin_float_50> reference(contact, modulus, ratio * modulus);
      const cpp_bin_float_50 t = reference.transition();
      const cpp_bin_float_50 hertz_work = reference.hertz(t) * t * 2 / 5;
      for (const double w : {0.5, 1.9, 1.95, 3.0, 10.0, 37.0, 100.0, 1000.0}) {
        const double x = w * law.critical_interference();
        cpp_bin_float_50 work = reference.hertz(x) * x * 2 / 5;
        if (x > t)
          work = hertz_work +
                 integrator.integrate([&](const cpp_bin_float_50& y) { return reference.force(y); },
                                      t, cpp_bin_float_50(x));
        const double error = double(abs(law.loading_work(x) - work) / work);
        EXPECT_LT(error, 1e-15) << "E_t/E_s = " << ratio << ", omega* = " << w;
        worst = std::max(worst, error);
      }
    }
  std::cout << "loading work vs tanh-sinh (50 digits): worst relative difference " << worst << "\n";
}

double central_difference(const ElasticPlasticContact& contact, double x, double h) {
  return (-contact.loading_force(x + 2 * h) + 8 * contact.loading_force(x + h) -
          8 * contact.loading_force(x - h) + contact.loading_force(x - 2 * h)) /
         (12 * h);
}

TEST(Ghaednia, StiffnessAgainstACentralDifference) {
  double worst = 0;
  for (const auto& [contact, modulus] :
       {std::pair{steel, steel_modulus}, std::pair{aluminium, aluminium_modulus}})
    for (const double ratio : hardening_ratios) {
      const GhaedniaContact law(contact, modulus, ratio * modulus);
      for (const double w : {0.2, 1.0, 1.85, 1.95, 3.0, 10.0, 100.0, 1e3, 1e4}) {
        const double x = w * law.critical_interference();
        const double analytic = law.loading_stiffness(x);
        const double error =
            std::abs(analytic - central_difference(law, x, 1e-3 * x)) / std::abs(analytic);
        EXPECT_LT(error, 1e-9) << "E_t/E_s = " << ratio << ", omega* = " << w;
        worst = std::max(worst, error);
      }
    }
  std::cout << "dF/dx vs fourth-order central difference (h = 1e-3 x): worst " << worst << "\n";
}

TEST(Ghaednia, ElasticPerfectlyPlasticLimitIsJacksonGreenLike) {
  const GhaedniaContact law(steel, steel_modulus, 0.0);
  const GhaedniaContact nearly(steel, steel_modulus, 1e-12 * steel_modulus);
  const JacksonGreenContact jackson_green(steel);
  double worst_jg = 0, worst_limit = 0, worst_at = 0;
  for (double w = 1.91; w <= 100; w *= 1.05) {
    const double x = w * law.critical_interference();
    EXPECT_EQ(law.upsilon(x), 0.0);
    // Upsilon = 0: the contact radius is Jackson-Green's.
    EXPECT_NEAR(law.contact_radius(x), jackson_green_contact_radius(x, steel),
                2e-16 * law.contact_radius(x));
    const double difference = relative(law.loading_force(x), jackson_green.loading_force(x));
    if (difference > worst_jg) worst_jg = difference, worst_at = w;
    worst_limit = std::max(worst_limit, relative(nearly.loading_force(x), law.loading_force(x)));
  }
  std::cout << "E_t = 0 vs Jackson-Green (hardness of JG.m), omega* in (1.9, 100]: worst "
            << worst_jg << " (at omega* = " << worst_at << ", a/R = "
            << law.contact_radius(worst_at * law.critical_interference()) / steel.radius
            << "); E_t = 1e-12 E_s vs E_t = 0: " << worst_limit << "\n";
  EXPECT_LT(worst_jg, 0.015);
  EXPECT_LT(worst_limit, 1e-10);
}

TEST(Ghaednia, NearlyElasticHardeningDoesNotReachHertz) {
  // E_t -> E_s: Upsilon -> -infinity, a -> a_e, and F -> F_e - exp(-3.3) (F_e - F_p(a_e)).
  const double ratio = 1 - 1e-9;
  const GhaedniaContact law(steel, steel_modulus, ratio * steel_modulus);
  const ReferenceLaw<long double> reference(steel, steel_modulus, ratio * steel_modulus);
  std::cout << "E_t/E_s = 1 - 1e-9: F/F_Hertz";
  for (const double w : {3.0, 10.0, 100.0, 1000.0}) {
    const double x = w * law.critical_interference();
    const long double hertz = reference.hertz(x);
    const long double limit =
        hertz - std::exp(-3.3L) * (hertz - reference.plastic(x, std::sqrt(steel.radius * x)));
    EXPECT_LT(law.upsilon(x), -1e9);
    EXPECT_EQ(law.contact_radius(x), std::sqrt(steel.radius * x));
    EXPECT_LT(relative(law.loading_force(x), limit), 1e-8) << w;
    EXPECT_LT(law.loading_force(x), 0.999 * double(hertz)) << w;
    std::cout << "  [omega* = " << w << ": " << law.loading_force(x) / hertz << "]";
  }
  std::cout << "\n";
  // The contact radius tends to Hertz's as E_t grows (at omega* = 100).
  const double x = 100 * law.critical_interference();
  double previous = GhaedniaContact(steel, steel_modulus, 0.0).contact_radius(x);
  std::cout << "a/a_Hertz at omega* = 100:";
  for (const double r : {0.01, 0.1, 0.5, 0.9, 0.99}) {
    const double a = GhaedniaContact(steel, steel_modulus, r * steel_modulus).contact_radius(x);
    EXPECT_LE(a, previous) << r; // equal to a_e (exp(Upsilon) underflows) from r = 0.9
    previous = a;
    std::cout << "  [E_t/E_s = " << r << ": " << a / std::sqrt(steel.radius * x) << "]";
  }
  std::cout << "\n";
}

TEST(Ghaednia, RadiusPreservingUnloading) {
  const GhaedniaContact law(steel, steel_modulus, 0.02 * steel_modulus);
  const double e = steel.contact_modulus;
  const double x = 20 * law.critical_interference();
  const double force = law.loading_force(x), a = law.contact_radius(x);
  const HertzianUnloading branch = law.unloading(x);
  EXPECT_NEAR(branch.residual_approach, x - 3 * force / (4 * e * a), 1e-15 * x);
  EXPECT_GT(branch.residual_approach, 0.0);
  EXPECT_NEAR(branch.stiffness, 4.0 / 3.0 * e * std::sqrt(4 * e * a * a * a / (3 * force)),
              1e-15 * branch.stiffness);
  // The branch passes through (x_max, F(x_max)).
  EXPECT_NEAR(branch.stiffness * std::pow(x - branch.residual_approach, 1.5), force, 1e-13 * force);
  // Hertz below the transition.
  const HertzianUnloading elastic = law.unloading(law.critical_interference());
  EXPECT_EQ(elastic.residual_approach, 0.0);
  EXPECT_NEAR(elastic.stiffness, 4.0 / 3.0 * e * std::sqrt(steel.radius),
              1e-15 * elastic.stiffness);
}

TEST(Ghaednia, InvalidInputNamesTheParameter) {
  const auto parameter_of = [](auto call) {
    try {
      call();
    } catch (const InvalidInput& error) {
      return error.parameter();
    }
    return std::string("(nothing thrown)");
  };
  const auto make = [](SphereFlatContact contact, double youngs, double tangent) {
    return [=] { GhaedniaContact law(contact, youngs, tangent); };
  };
  const double e_s = steel_modulus, e_t = 0.02 * steel_modulus;
  SphereFlatContact bad = steel;
  bad.radius = 0;
  EXPECT_EQ(parameter_of(make(bad, e_s, e_t)), "radius");
  bad = steel;
  bad.contact_modulus = -1;
  EXPECT_EQ(parameter_of(make(bad, e_s, e_t)), "contact_modulus");
  bad = steel;
  bad.yield_strength = 0;
  EXPECT_EQ(parameter_of(make(bad, e_s, e_t)), "yield_strength");
  bad = steel;
  bad.poisson_ratio = 0.5;
  EXPECT_EQ(parameter_of(make(bad, e_s, e_t)), "poisson_ratio");
  bad.poisson_ratio = -1;
  EXPECT_EQ(parameter_of(make(bad, e_s, e_t)), "poisson_ratio");
  EXPECT_EQ(parameter_of(make(steel, NAN, e_t)), "youngs_modulus");
  // E_s below E* (1 - nu^2) would need a flat of negative compliance.
  EXPECT_EQ(parameter_of(make(steel, 0.5 * steel.contact_modulus, e_t)), "youngs_modulus");
  // The rigid-flat value is accepted.
  EXPECT_EQ(parameter_of(make(steel, steel.contact_modulus * 0.91, e_t)), "(nothing thrown)");
  EXPECT_EQ(parameter_of(make(steel, e_s, -1)), "tangent_modulus");
  EXPECT_EQ(parameter_of(make(steel, e_s, NAN)), "tangent_modulus");
  EXPECT_EQ(parameter_of(make(steel, e_s, INFINITY)), "tangent_modulus");
  EXPECT_EQ(parameter_of(make(steel, e_s, e_s)), "tangent_modulus");
  EXPECT_EQ(parameter_of(make(steel, e_s, 2 * e_s)), "tangent_modulus");
  const GhaedniaContact law(steel, e_s, e_t);
  EXPECT_EQ(parameter_of([&] { law.loading_force(-1e-9); }), "approach");
  EXPECT_EQ(parameter_of([&] { law.loading_work(NAN); }), "approach");
  EXPECT_EQ(parameter_of([&] { law.loading_stiffness(-1); }), "approach");
  EXPECT_EQ(parameter_of([&] { law.contact_radius(-1); }), "approach");
  EXPECT_EQ(parameter_of([&] { law.upsilon(INFINITY); }), "approach");
  EXPECT_EQ(parameter_of([&] { law.unloading(0); }), "approach_max");
}

impact::testing::PlasticReferenceLaw reference_impact_law(const SphereFlatContact& contact,
                                                          double youngs, double tangent) {
  const ReferenceLaw<long double> law(contact, youngs, tangent);
  const long double e = contact.contact_modulus;
  const auto branch = [=](long double x_max, long double& stiffness, long double& x_r) {
    if (x_max <= law.transition()) {
      stiffness = 4.0L / 3.0L * e * std::sqrt((long double)contact.radius);
      x_r = 0;
      return;
    }
    const long double p_m = law.force(x_max), a_m = law.contact_radius(x_max);
    stiffness = 4.0L / 3.0L * e * std::sqrt(4 * e * a_m * a_m * a_m / (3 * p_m));
    x_r = x_max - 3 * p_m / (4 * e * a_m);
  };
  impact::testing::PlasticReferenceLaw reference;
  reference.loading = [=](long double x) { return law.force(std::max(x, 0.0L)); };
  reference.breakpoints = {law.transition()};
  reference.unloading = [=](long double x, long double x_max) {
    long double stiffness, x_r;
    branch(x_max, stiffness, x_r);
    return stiffness * std::pow(std::max(x - x_r, 0.0L), 1.5L);
  };
  reference.separation_approach = [=](long double x_max) {
    long double stiffness, x_r;
    branch(x_max, stiffness, x_r);
    return std::max(x_r, 0.0L);
  };
  return reference;
}

TEST(Ghaednia, ImpactRestitution) {
  // The velocity that just reaches 1.9 delta_c: W_L(1.9 delta_c) = m V^2 / 2.
  for (const double ratio : {0.0, 0.02, 0.1, 0.5}) {
    const GhaedniaContact law(steel, steel_modulus, ratio * steel_modulus);
    const double v_t = std::sqrt(2 * law.loading_work(law.transition_approach()) / steel_mass);
    const auto elastic = elastic_plastic_impact(steel_mass, 0.5 * v_t, law);
    EXPECT_NEAR(elastic.restitution, 1.0, 1e-15);
    EXPECT_EQ(elastic.residual_approach, 0.0);
    std::cout << "E_t/E_s = " << ratio << " (V_t = " << v_t << " m/s):";
    for (const double multiple : {10.0, 100.0}) {
      const auto impact = elastic_plastic_impact(steel_mass, multiple * v_t, law);
      EXPECT_GT(impact.restitution, 0.0);
      EXPECT_LT(impact.restitution, 1.0);
      EXPECT_GT(impact.residual_approach, 0.0);
      std::cout << "  [V/V_t = " << multiple << ": e = " << impact.restitution
                << ", x_max/delta_c = " << impact.approach_max / law.critical_interference() << "]";
    }
    std::cout << "\n";
  }
}

TEST(Ghaednia, ImpactAgreesWithAnIndependentIntegration) {
  const double ratio = 0.02;
  const GhaedniaContact law(steel, steel_modulus, ratio * steel_modulus);
  const auto reference = reference_impact_law(steel, steel_modulus, ratio * steel_modulus);
  const double v_t = std::sqrt(2 * law.loading_work(law.transition_approach()) / steel_mass);
  for (const double multiple : {10.0, 100.0}) {
    const double v = multiple * v_t;
    const auto impact = elastic_plastic_impact(steel_mass, v, law);
    const auto ode = impact::testing::integrate_plastic_reference(steel_mass, v, reference,
                                                                  impact.approach_max, 16000);
    const double errors[] = {relative(ode.approach_max, impact.approach_max),
                             relative(-ode.rebound_velocity / v, impact.restitution),
                             relative(ode.compression_time, impact.compression_time),
                             relative(ode.contact_time, impact.contact_time),
                             double(std::abs(ode.separation_approach - impact.residual_approach)) /
                                 impact.approach_max};
    std::cout << "V/V_t = " << multiple << " vs RKF7(8): differences x_max, e, t_comp, t_c, x_r:";
    for (const double error : errors) {
      EXPECT_LT(error, 1e-12) << multiple;
      std::cout << " " << error;
    }
    std::cout << "\n";
  }
}

} // namespace
