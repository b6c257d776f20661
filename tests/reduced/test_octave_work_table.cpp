// The tabulated loading work of the fitted elastic-plastic laws (octave_work_table.hpp) against
// the independent quadrature it replaced: composite 30-point Gauss-Legendre in x on pieces
// [x, 2x) above the transition, which reaches machine precision there (each piece lies its
// own length away from the fits' branch points at x = 0). Jackson-Green and Ghaednia, over
// yield strains 1e-4 .. 2e-2, interferences 1.9 omega_c .. min(1e6 omega_c, R / 5).

#include "impact_reduced/ghaednia.hpp"
#include "impact_reduced/hertz_contact.hpp"
#include "impact_reduced/thornton.hpp"
#include "impact_reduced/sphere_flat_fits.hpp"
#include "octave_work_table.hpp"

#include <boost/math/quadrature/gauss.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <functional>
#include <thread>
#include <vector>

namespace {

using namespace impact::reduced;

double composite_gauss_work(const ElasticPlasticContact& law, double transition, double approach) {
  double work = law.loading_work(transition);
  for (double lower = transition; lower < approach; lower *= 2) {
    const double upper = std::min(2 * lower, approach);
    work += boost::math::quadrature::gauss<double, 30>::integrate(
        [&](double x) { return law.loading_force(std::max(x, transition * (1 + 1e-15))); }, lower,
        upper);
  }
  return work;
}

std::vector<SphereFlatContact> contacts() {
  std::vector<SphereFlatContact> result;
  for (const double strain : {1e-4, 1e-3, 4.4e-3, 2e-2})
    for (const double nu : {0.0, 0.3, 0.45})
      result.push_back({0.01, 1.15e11, strain * 1.15e11, nu});
  return result;
}

// The two springs whose loading work comes from the octave table: Jackson-Green, and
// Ghaednia with a tangent modulus of 2 % of E = 210 GPa.
struct FittedSprings {
  explicit FittedSprings(const SphereFlatContact& contact)
      : jackson_green(contact),
        ghaednia({contact.radius, youngs / (1 - contact.poisson_ratio * contact.poisson_ratio),
                  contact.yield_strength, contact.poisson_ratio},
                 youngs, 0.02 * youngs) {}
  std::array<const ElasticPlasticContact*, 2> both() const { return {&jackson_green, &ghaednia}; }
  static constexpr double youngs = 2.1e11;
  JacksonGreenContact jackson_green;
  GhaedniaContact ghaednia;
};

std::vector<double> ratios() {
  std::vector<double> result;
  for (double w = 1.9 * 1.0001; w < 1e6; w *= 1.37) result.push_back(w);
  result.push_back(1e6);
  return result;
}

template <class Law>
void check_against_quadrature(const Law& law, double law_radius, double critical, double transition,
                              double& worst_work, double& worst_inverse) {
  for (const double w : ratios()) {
    const double x = w * critical;
    if (x > 0.2 * law_radius) break;
    const double reference = composite_gauss_work(law, transition, x);
    worst_work = std::max(worst_work, std::abs(law.loading_work(x) - reference) / reference);
    worst_inverse = std::max(worst_inverse, std::abs(law.loading_approach(reference) - x) / x);
  }
}

TEST(OctaveWorkTable, JacksonGreenWorkMatchesCompositeGaussLegendre) {
  double worst_work = 0, worst_inverse = 0;
  for (const auto& contact : contacts()) {
    const JacksonGreenContact law(contact);
    check_against_quadrature(law, contact.radius, law.critical_interference(),
                             1.9 * law.critical_interference(), worst_work, worst_inverse);
  }
  std::printf("worst relative error: work %.2e, inverse %.2e\n", worst_work, worst_inverse);
  EXPECT_LE(worst_work, 2e-15);
  EXPECT_LE(worst_inverse, 2e-15);
}

TEST(OctaveWorkTable, GhaedniaWorkMatchesCompositeGaussLegendre) {
  double worst_work = 0, worst_inverse = 0;
  for (const auto& contact : contacts())
    for (const double hardening : {0.0, 0.02, 0.2}) {
      const double youngs = 2.1e11;
      const GhaedniaContact law({contact.radius,
                                 youngs / (1 - contact.poisson_ratio * contact.poisson_ratio),
                                 contact.yield_strength, contact.poisson_ratio},
                                youngs, hardening * youngs);
      check_against_quadrature(law, contact.radius, law.critical_interference(),
                               law.transition_approach(), worst_work, worst_inverse);
    }
  std::printf("worst relative error: work %.2e, inverse %.2e\n", worst_work, worst_inverse);
  EXPECT_LE(worst_work, 2e-15);
  EXPECT_LE(worst_inverse, 2e-15);
}

// Copies share the table, which is built on first use: two threads asking for the same
// octaves get the same works.
TEST(OctaveWorkTable, ConcurrentUseGivesTheSameWork) {
  const JacksonGreenContact law({0.01, 1.15e11, 1e9, 0.3});
  const JacksonGreenContact copy = law;
  std::vector<double> first, second;
  const double critical = law.critical_interference();
  auto run = [&](const JacksonGreenContact& l, std::vector<double>& out) {
    for (const double w : ratios()) out.push_back(l.loading_work(w * critical));
  };
  std::thread a(run, std::cref(law), std::ref(first));
  std::thread b(run, std::cref(copy), std::ref(second));
  a.join();
  b.join();
  EXPECT_EQ(first, second);
}

// W(x_max) - W(x_max - d) of the laws (their series' differences term by term, closed forms:
// Jackson-Green, Ghaednia, Thornton, Hertz)
// against the base class's quadrature, the former implementation (30-point Gauss-Legendre on
// [x_max - d, x_max] split at the breakpoints, differences of W beyond d = x_max / 2), for d
// from 1e-14 x_max to x_max, x_max on both sides of the transition.
template <class Law>
double worst_work_below(const Law& law, double transition) {
  double worst = 0;
  for (const double ratio : {0.3, 0.99, 1.0001, 1.3, 2.0, 2.0001, 7.7, 100.0, 3e3})
    for (double fraction = 1e-14; fraction <= 1.0; fraction *= 3.7) {
      const double x_max = ratio * transition;
      for (const double d :
           {fraction * x_max, std::min(x_max, std::abs(x_max - transition) * 1.01)}) {
        const double reference = law.ElasticPlasticContact::loading_work_below(x_max, d);
        worst = std::max(worst, std::abs(law.loading_work_below(x_max, d) - reference) / reference);
      }
    }
  return worst;
}

TEST(OctaveWorkTable, WorkBelowMatchesTheQuadratureOfTheForce) {
  double worst = 0;
  for (const auto& contact : contacts()) {
    const FittedSprings springs(contact);
    const JacksonGreenContact& jackson_green = springs.jackson_green;
    worst = std::max(worst,
                     worst_work_below(jackson_green, 1.9 * jackson_green.critical_interference()));
    worst =
        std::max(worst, worst_work_below(springs.ghaednia, springs.ghaednia.transition_approach()));
    const ThorntonContact thornton(contact.radius, contact.contact_modulus,
                                   1.6 * contact.yield_strength);
    worst = std::max(worst, worst_work_below(thornton, thornton.yield_approach()));
    const HertzContact hertz(thornton.hertz_stiffness());
    worst = std::max(worst, worst_work_below(hertz, thornton.yield_approach()));
  }
  std::printf("worst relative difference: %.2e\n", worst);
  EXPECT_LE(worst, 4e-15);
}

// F at a given work from the series of F x (what the time integrals use), and F with dF/dx
// (what the force peak's search uses), against the fit's formulas at the inverse.
TEST(OctaveWorkTable, ForceAtWorkMatchesTheFitAtTheInverse) {
  double worst = 0, worst_pair = 0, worst_slope = 0;
  for (const auto& contact : contacts()) {
    const FittedSprings springs(contact);
    const JacksonGreenContact& jackson_green = springs.jackson_green;
    for (const double w : ratios())
      for (const ElasticPlasticContact* law : springs.both()) {
        const double x = w * jackson_green.critical_interference();
        if (x > 0.2 * contact.radius) break;
        const double work = law->loading_work(x);
        const double reference = law->loading_force(law->loading_approach(work));
        worst = std::max(worst, std::abs(law->loading_force_at_work(work) - reference) / reference);
        const double slope = law->loading_stiffness(law->loading_approach(work));
        const auto [pair_force, pair_slope] = law->loading_force_and_stiffness_at_work(work);
        worst_pair = std::max(worst_pair, std::abs(pair_force - reference) / reference);
        worst_slope = std::max(worst_slope, std::abs(pair_slope - slope) / std::abs(slope));
      }
  }
  std::printf("worst relative difference: F %.2e, (F, dF/dx) %.2e, %.2e\n", worst, worst_pair,
              worst_slope);
  EXPECT_LE(worst, 3e-15);
  EXPECT_LE(worst_pair, 3e-15);
  EXPECT_LE(worst_slope, 2e-13);
}

// F and dF/dx at a given approach from the octave's series of F x and its derivative (what
// the Kuwabara-Kono integration evaluates), against the fit's formulas there: on a grid finer
// than the octaves' Chebyshev points (16 approaches per ratio step of 1.37, from just above
// the transition).
TEST(OctaveWorkTable, ForceAndSlopeAtApproachMatchTheFit) {
  double worst_force = 0, worst_slope = 0;
  for (const auto& contact : contacts()) {
    const FittedSprings springs(contact);
    const JacksonGreenContact& jackson_green = springs.jackson_green;
    for (const double w : ratios())
      for (int k = 0; k < 16; ++k)
        for (const ElasticPlasticContact* law : springs.both()) {
          const double x = w * std::pow(1.37, k / 16.0) * jackson_green.critical_interference();
          if (x > 0.2 * contact.radius) break;
          const auto [force, slope] = law->loading_force_and_stiffness(x);
          const auto [table_force, table_slope] = law->loading_force_and_stiffness_from_table(x);
          worst_force = std::max(worst_force, std::abs(table_force - force) / force);
          worst_slope = std::max(worst_slope, std::abs(table_slope - slope) / std::abs(slope));
        }
  }
  std::printf("worst relative difference: F %.2e, dF/dx %.2e\n", worst_force, worst_slope);
  EXPECT_LE(worst_force, 3e-15); // measured 2.15e-15
  EXPECT_LE(worst_slope, 3e-13); // measured 2.40e-13
}

TEST(OctaveWorkTable, PowerLawWorkIsExact) {
  // F = x^(3/2) from x_0 = 1: W = (2/5) x^(5/2), and its inverse.
  const impact::reduced::detail::OctaveWorkTable table(1.0, 0.4);
  const auto force = [](double x) { return x * std::sqrt(x); };
  for (const double x : {1.0, 1.5, 2.0, 3.7, 1e3, 1e9}) {
    const double exact = 0.4 * std::pow(x, 2.5);
    EXPECT_NEAR(table.work(x, force), exact, 1e-15 * exact) << x;
    EXPECT_NEAR(table.approach(exact, force), x, 2e-15 * x) << x;
  }
}

} // namespace
