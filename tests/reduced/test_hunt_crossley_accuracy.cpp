// Accuracy of the closed-form Hunt-Crossley impact (reduced library) against references
// computed here in 50/100 digits from the spec's formulas (tests/reduced/
// high_precision_reference.hpp), over the ranges of the spec's accuracy table
// (doc/theory/reduced-models.md, section 1):
//
//   k(beta), V_out                      beta in [1e-12, 1e4]      <= 4e-15
//   beta from k                         k in [1e-6, 1 - 1e-12]    <= 1e-13
//   x_max, F_max, time of F_max         beta in [1e-12, 1e3]      <= 1e-13
//   contact time, compression time      beta in [1e-12, 1e3]      <= 1e-12
//   v(x) on [0, x_max], both branches, incl. x within 1e-10 x_max of x_max   <= 1e-12
//
// plus the Hertz limit b = 0 (t_c V / x_max = 2 (1/p) B(1/p, 1/2)), continuity as beta -> 0,
// and finiteness at beta = 1e4. Each test prints the worst relative error per quantity and
// where it occurred.

#include "high_precision_reference.hpp"

#include "impact_reduced/hunt_crossley.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace impact::reduced;
using hp::expect_target;
using hp::ImpactInput;
using hp::ImpactReference;
using hp::Real100;
using hp::relative_error;
using hp::report;
using hp::WorstError;

// The spec's steel ball on a steel half-space.
constexpr double mass = 0.1;
constexpr double stiffness = 1.7135e10;
constexpr double hertz_exponent = 1.5;

constexpr double target_restitution = 4e-15;
constexpr double target_inverse = 1e-13;
constexpr double target_peak = 1e-13; // x_max, F_max, time of F_max
constexpr double target_time = 1e-12; // contact and compression times
constexpr double target_rate = 1e-12; // v(x)

/// `count` log-spaced values from `first` to `last`, both included.
std::vector<double> log_grid(double first, double last, int count) {
  std::vector<double> grid;
  const double decades = std::log10(last / first);
  for (int i = 0; i < count; ++i) grid.push_back(first * std::pow(10.0, decades * i / (count - 1)));
  grid.front() = first;
  grid.back() = last;
  return grid;
}

std::vector<double> beta_grid(double last, int count) {
  std::vector<double> grid = log_grid(1e-12, last, count);
  for (const double decade : {1e-12, 1e-8, 1e-4, 0.01, 0.1, 1.0, 10.0, 100.0, 1e3, 1e4})
    if (decade <= last) grid.push_back(decade);
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  return grid;
}

ImpactInput input_for(double beta, double exponent, double velocity) {
  return {mass, stiffness, exponent, beta / velocity, velocity};
}

HuntCrossleyImpact make_impact(const ImpactInput& in) {
  return HuntCrossleyImpact(in.mass, in.stiffness, in.exponent, in.damping, in.velocity);
}

/// Evaluates a library call, turning an exception into NaN (recorded as an infinite error)
/// and printing its message.
double call(const std::function<double()>& f, const std::string& what) {
  try {
    return f();
  } catch (const std::exception& error) {
    std::cout << "  EXCEPTION in " << what << ": " << error.what() << "\n";
    return std::numeric_limits<double>::quiet_NaN();
  }
}

// ---------------------------------------------------------------------------------------
// The references themselves
// ---------------------------------------------------------------------------------------

// (a) k(beta) by the literal formula in 50 digits agrees with 100 digits to 1e-20 (50 digits
//     lose ~2 log10(1/beta) digits to the branch point; 100 digits leave > 70);
// (b) the peak condition (n + 1) E = n (exp(psi) - 1) gives the same maximum force as a
//     direct golden-section maximisation of F = -w f(x(w)) in 100 digits;
// (c) the time quadratures in psi = ln(-w) agree with an independent integral
//     t = integral dx / |v(x)| of the closed-form v(x) (W-1 / W0 in 100 digits), per phase;
// (d) at beta = 1e-30 the quadratures reproduce the Hertz Beta-function times.
TEST(HuntCrossleyAccuracy, ReferenceSelfCheck) {
  // (a)
  for (const double beta : beta_grid(1e4, 15)) {
    const Real100 k100 = hp::restitution_reference(Real100(beta));
    const Real100 k50 = Real100(hp::restitution_reference(hp::Real50(beta)));
    EXPECT_LT(static_cast<double>(abs((k50 - k100) / k100)), 1e-20) << "beta = " << beta;
  }
  // (b)
  for (const double beta : {1e-6, 1.0, 1e3}) {
    for (const double n : {1.0, 2.5}) {
      const ImpactInput in = input_for(beta, n, 1.0);
      const ImpactReference r = hp::hunt_crossley_reference(in, false);
      const Real100 b = in.damping, beta100 = b, psi_in = log1p(beta100);
      const Real100 p = Real100(n) + 1;
      auto force = [&](const Real100& delta) {
        const Real100 energy = -(1 + beta100) * expm1(-delta) - delta;
        const Real100 x = pow(p * mass * energy / (Real100(stiffness) * b * b), 1 / p);
        return exp(psi_in - delta) * stiffness * pow(x, Real100(n));
      };
      Real100 lo = 0, hi = psi_in;
      const Real100 golden = (sqrt(Real100(5)) - 1) / 2;
      for (int i = 0; i < 130; ++i) { // interval 1e-27 psi_in: F(peak) to ~1e-54
        const Real100 x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
        if (force(x1) < force(x2))
          lo = x1;
        else
          hi = x2;
      }
      const Real100 f_max = force((lo + hi) / 2);
      EXPECT_LT(static_cast<double>(abs((f_max - r.force_max) / f_max)), 1e-40)
          << "peak force, beta = " << beta << ", n = " << n;
    }
  }
  // (c)
  for (const double beta : {0.3, 20.0}) {
    const ImpactInput in = input_for(beta, hertz_exponent, 1.0);
    const ImpactReference r = hp::hunt_crossley_reference(in);
    const hp::Real50 x_max(r.approach_max), b(in.damping), p(hertz_exponent + 1);
    const hp::Real50 potential_scale = b * b / mass * stiffness / p; // (b^2/m) P = scale x^p
    for (const bool compression : {true, false}) {
      // s = -1 - g = (b^2/m) (P(x_max) - P(x)), x = x_max - d, formed from d; |v| = |y| / b.
      auto integrand = [&](const hp::Real50& x, const hp::Real50& xc) {
        const hp::Real50 d = xc > 0 ? xc : hp::Real50(x_max - x);
        const hp::Real50 s = -potential_scale * pow(x_max, p) * expm1(p * log1p(-d / x_max));
        const Real100 y = hp::one_plus_w_reference(Real100(s), !compression);
        return hp::Real50(b / abs(y));
      };
      hp::Real50 error = 0;
      const hp::Real50 t =
          hp::quadrature50().integrate(integrand, hp::Real50(0), x_max, hp::Real50(1e-30), &error);
      const Real100 reference =
          compression ? r.compression_time : Real100(r.contact_time - r.compression_time);
      const double difference = static_cast<double>(abs((Real100(t) - reference) / reference));
      std::cout << "  " << (compression ? "compression" : "restitution")
                << " time, psi quadrature vs integral dx/|v(x)|, beta = " << beta << ": "
                << difference << " (error estimate " << static_cast<double>(error / t) << ")\n";
      EXPECT_LT(difference, 1e-20);
    }
  }
  // (d)
  for (const double n : {1.0, 1.5, 2.5}) {
    const ImpactInput in = input_for(1e-30, n, 1.0);
    const ImpactReference r = hp::hunt_crossley_reference(in);
    const ImpactReference h = hp::hertz_reference({mass, stiffness, n, 0.0, 1.0});
    EXPECT_LT(static_cast<double>(abs(r.contact_time / h.contact_time - 1)), 1e-25) << n;
    EXPECT_LT(static_cast<double>(abs(r.compression_time / h.compression_time - 1)), 1e-25);
    EXPECT_LT(static_cast<double>(abs(r.approach_max / h.approach_max - 1)), 1e-25);
    EXPECT_LT(static_cast<double>(abs(r.force_max / h.force_max - 1)), 1e-25);
    EXPECT_LT(r.quadrature_error, 1e-25);
  }
}

// ---------------------------------------------------------------------------------------
// Closed forms
// ---------------------------------------------------------------------------------------

TEST(HuntCrossleyAccuracy, RestitutionAndReboundVelocity) {
  WorstError k_free("k(beta) restitution_from_impact_par.", target_restitution);
  WorstError k_member("HuntCrossleyImpact::restitution", target_restitution);
  WorstError v_out("rebound_velocity", target_restitution);
  // Dense (cheap): catches method switches inside the library.
  for (const double beta : beta_grid(1e4, 400)) {
    const Real100 reference = hp::restitution_reference(Real100(beta));
    const double value = call([&] { return restitution_from_impact_parameter(beta); },
                              "restitution_from_impact_parameter");
    k_free.update(relative_error(value, reference), hp::format("beta=%.17g", beta));
  }
  for (const double velocity : {1.0, 0.05, 20.0}) {
    for (const double n : {1.0, 1.5, 2.5}) {
      for (const double beta : beta_grid(1e4, velocity == 1.0 && n == 1.5 ? 40 : 12)) {
        const ImpactInput in = input_for(beta, n, velocity);
        const ImpactReference r = hp::hunt_crossley_reference(in, false);
        double k = std::numeric_limits<double>::quiet_NaN(), v = k;
        try {
          const HuntCrossleyImpact impact = make_impact(in);
          k = impact.restitution();
          v = impact.rebound_velocity();
        } catch (const std::exception& error) {
          std::cout << "  EXCEPTION at " << in.describe() << ": " << error.what() << "\n";
        }
        k_member.update(relative_error(k, r.restitution), in.describe());
        v_out.update(relative_error(v, r.rebound_velocity), in.describe());
      }
    }
  }
  std::cout << "Restitution and rebound velocity, beta in [1e-12, 1e4]:\n";
  expect_target(k_free);
  expect_target(k_member);
  expect_target(v_out);
}

TEST(HuntCrossleyAccuracy, ImpactParameterFromRestitution) {
  std::vector<double> grid = log_grid(1e-6, 0.5, 20);
  for (const double shortfall : log_grid(1e-12, 0.5, 21)) grid.push_back(1.0 - shortfall);
  grid.push_back(0.95); // around the library's switch of method (1 - k = 0.05)
  grid.push_back(std::nextafter(0.95, 0.0));
  grid.push_back(std::nextafter(0.95, 1.0));
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  WorstError inverse("beta from k (impact_parameter_from_r.)", target_inverse);
  WorstError damping("b from k, V = 3 (damping_from_restit.)", target_inverse);
  for (const double k : grid) {
    const Real100 reference = hp::impact_parameter_reference(k);
    inverse.update(relative_error(call([&] { return impact_parameter_from_restitution(k); },
                                       "impact_parameter_from_restitution"),
                                  reference),
                   hp::format("k=%.17g", k));
    damping.update(relative_error(call([&] { return damping_from_restitution(k, 3.0); },
                                       "damping_from_restitution"),
                                  reference / 3),
                   hp::format("k=%.17g", k));
  }
  std::cout << "Inverse restitution map, k in [1e-6, 1 - 1e-12]:\n";
  expect_target(inverse);
  expect_target(damping);
}

TEST(HuntCrossleyAccuracy, ApproachMaxAndPeakForce) {
  WorstError x_max("approach_max", target_peak);
  WorstError f_max("force_peak().force", target_peak);
  WorstError x_peak("force_peak().approach (info)", 1.0);
  for (const double velocity : {1.0, 0.05, 20.0}) {
    for (const double n : {1.0, 1.5, 2.5}) {
      for (const double beta : beta_grid(1e3, velocity == 1.0 ? 100 : 20)) {
        const ImpactInput in = input_for(beta, n, velocity);
        const ImpactReference r = hp::hunt_crossley_reference(in, false);
        double approach_max = std::numeric_limits<double>::quiet_NaN();
        ImpactState peak{approach_max, approach_max, approach_max, approach_max};
        try {
          const HuntCrossleyImpact impact = make_impact(in);
          approach_max = impact.approach_max();
          peak = impact.force_peak();
        } catch (const std::exception& error) {
          std::cout << "  EXCEPTION at " << in.describe() << ": " << error.what() << "\n";
        }
        x_max.update(relative_error(approach_max, r.approach_max), in.describe());
        f_max.update(relative_error(peak.force, r.force_max), in.describe());
        x_peak.update(relative_error(peak.approach, r.approach_at_peak), in.describe());
      }
    }
  }
  std::cout << "x_max and peak force, beta in [1e-12, 1e3], n in {1, 1.5, 2.5}, "
               "V in {1, 0.05, 20}:\n";
  expect_target(x_max);
  expect_target(f_max);
  report(x_peak);
}

// ---------------------------------------------------------------------------------------
// Times (50-digit quadratures: modest grids)
// ---------------------------------------------------------------------------------------

TEST(HuntCrossleyAccuracy, PeakTimeCompressionAndContactTimes) {
  struct Case {
    double exponent, velocity;
    int points;
  };
  const std::vector<Case> cases = {
      {1.5, 1.0, 40}, {1.0, 1.0, 12}, {2.5, 1.0, 12}, {1.5, 0.05, 8}, {1.5, 20.0, 8}};
  WorstError peak_time("force_peak().time", target_peak);
  WorstError compression("compression_time", target_time);
  WorstError contact("contact_time", target_time);
  WorstError response_consistency("response() vs separate calls", 1e-15);
  double worst_quadrature = 0;
  for (const Case& c : cases) {
    for (const double beta : beta_grid(1e3, c.points)) {
      const ImpactInput in = input_for(beta, c.exponent, c.velocity);
      const ImpactReference r = hp::hunt_crossley_reference(in);
      worst_quadrature = std::max(worst_quadrature, r.quadrature_error);
      EXPECT_LT(r.quadrature_error, 1e-25) << "reference quadrature at " << in.describe();
      const double nan = std::numeric_limits<double>::quiet_NaN();
      double t_peak = nan, t_compression = nan, t_contact = nan;
      try {
        const HuntCrossleyImpact impact = make_impact(in);
        t_peak = impact.force_peak().time;
        t_compression = impact.compression_time();
        t_contact = impact.contact_time();
        const ImpactResponse all = impact.response();
        const double consistency =
            std::max({std::fabs(all.time_force_max / t_peak - 1),
                      std::fabs(all.compression_time / t_compression - 1),
                      std::fabs(all.contact_time / t_contact - 1),
                      std::fabs(all.approach_max / impact.approach_max() - 1),
                      std::fabs(all.force_max / impact.force_peak().force - 1),
                      std::fabs(all.rebound_velocity / impact.rebound_velocity() - 1)});
        response_consistency.update(consistency, in.describe());
      } catch (const std::exception& error) {
        std::cout << "  EXCEPTION at " << in.describe() << ": " << error.what() << "\n";
        response_consistency.update(nan, in.describe());
      }
      peak_time.update(relative_error(t_peak, r.time_force_max), in.describe());
      compression.update(relative_error(t_compression, r.compression_time), in.describe());
      contact.update(relative_error(t_contact, r.contact_time), in.describe());
    }
  }
  std::cout << "Times, beta in [1e-12, 1e3] (reference quadrature error estimate <= "
            << worst_quadrature << "):\n";
  expect_target(peak_time);
  expect_target(compression);
  expect_target(contact);
  expect_target(response_consistency);
}

// ---------------------------------------------------------------------------------------
// Approach rate v(x)
// ---------------------------------------------------------------------------------------

/// The double x <= x_max nearest to x_max * fraction (the largest double not beyond x_max
/// for fraction 1).
double approach_at(const Real100& x_max, const Real100& fraction) {
  const Real100 target = x_max * fraction;
  double x = static_cast<double>(target);
  if (Real100(x) > x_max) x = std::nextafter(x, 0.0);
  return x;
}

TEST(HuntCrossleyAccuracy, ApproachRateBothBranches) {
  const std::vector<Real100> fractions = {Real100(0),        Real100(1e-6),      Real100(1) / 10,
                                          Real100(1) / 2,    Real100(9) / 10,    1 - Real100(1e-6),
                                          1 - Real100(1e-8), 1 - Real100(1e-10), Real100(1)};
  const char* fraction_names[] = {"0",      "1e-6",   "0.1",     "0.5",        "0.9",
                                  "1-1e-6", "1-1e-8", "1-1e-10", "1(x<=x_max)"};
  WorstError compression("approach_rate compression (W-1)", target_rate);
  WorstError restitution("approach_rate restitution (W0)", target_rate);
  WorstError near_max("  of which x >= (1-1e-6) x_max", target_rate);
  struct Case {
    double exponent, velocity;
    int points;
  };
  const std::vector<Case> cases = {
      {1.5, 1.0, 40}, {1.0, 1.0, 15}, {2.5, 1.0, 15}, {1.5, 0.05, 8}, {1.5, 20.0, 8}};
  for (const Case& c : cases) {
    std::vector<double> betas = beta_grid(1e4, c.points);
    betas.insert(betas.begin(), 0.0); // Hertz
    for (const double beta : betas) {
      const ImpactInput in = input_for(beta, c.exponent, c.velocity);
      const ImpactReference r = hp::hunt_crossley_reference(in, false);
      std::unique_ptr<HuntCrossleyImpact> impact;
      try {
        impact = std::make_unique<HuntCrossleyImpact>(make_impact(in));
      } catch (const std::exception& error) {
        std::cout << "  EXCEPTION at " << in.describe() << ": " << error.what() << "\n";
      }
      if (impact) {
        // At the library's own x_max (possibly an ulp beyond the true one): no exception,
        // and |v| ~ sqrt(2 f(x_max) dx / m) ~ 1e-8 V.
        for (const ImpactPhase phase : {ImpactPhase::compression, ImpactPhase::restitution}) {
          const double v =
              call([&] { return impact->approach_rate(impact->approach_max(), phase); },
                   "approach_rate(approach_max()) at " + in.describe());
          EXPECT_LE(std::fabs(v), 1e-6 * c.velocity) << in.describe();
        }
      }
      for (std::size_t i = 0; i < fractions.size(); ++i) {
        const double x = approach_at(r.approach_max, fractions[i]);
        for (const bool is_compression : {true, false}) {
          const auto reference = hp::approach_rate_reference(in, x, is_compression);
          ASSERT_TRUE(reference.has_value()) << "x beyond x_max at " << in.describe();
          const std::string where =
              in.describe() + ", x=x_max*" + fraction_names[i] + hp::format(" (x=%.17g)", x);
          double value = std::numeric_limits<double>::quiet_NaN();
          if (impact) {
            value = call(
                [&] {
                  return impact->approach_rate(x, is_compression ? ImpactPhase::compression
                                                                 : ImpactPhase::restitution);
                },
                "approach_rate at " + where);
          }
          double error;
          if (*reference == 0) {
            // x == x_max exactly: v = 0; accept |v| <= target * V.
            error = std::fabs(value) / c.velocity;
          } else {
            error = relative_error(value, *reference);
          }
          (is_compression ? compression : restitution).update(error, where);
          if (i >= 5) near_max.update(error, where + (is_compression ? " (W-1)" : " (W0)"));
        }
      }
    }
  }
  std::cout << "Approach rate v(x), beta in {0} U [1e-12, 1e4], x/x_max in {0, 1e-6, 0.1, "
               "0.5, 0.9, 1-1e-6, 1-1e-8, 1-1e-10, 1}:\n";
  expect_target(compression);
  expect_target(restitution);
  report(near_max);
}

// ---------------------------------------------------------------------------------------
// Limits
// ---------------------------------------------------------------------------------------

// b = 0 (Hertz): closed forms, t_c V / x_max = 2 (1/p) B(1/p, 1/2) (2.94327518432... for
// n = 3/2).
TEST(HuntCrossleyAccuracy, HertzLimit) {
  {
    const ImpactReference h = hp::hertz_reference({mass, stiffness, 1.5, 0.0, 1.0});
    const Real100 constant = h.contact_time / h.approach_max;
    EXPECT_LT(static_cast<double>(abs(constant - Real100("2.94327518432"))), 1e-11)
        << "reference constant " << static_cast<double>(constant);
  }
  WorstError constant("t_c V / x_max (b = 0)", target_time);
  WorstError x_max("approach_max (b = 0)", target_peak);
  WorstError f_max("force_peak().force (b = 0)", target_peak);
  WorstError t_peak("force_peak().time (b = 0)", target_peak);
  WorstError t_compression("compression_time (b = 0)", target_time);
  WorstError t_contact("contact_time (b = 0)", target_time);
  WorstError v_out("rebound_velocity (b = 0)", target_restitution);
  for (const double n : {1.0, 1.5, 2.5}) {
    for (const double velocity : {1.0, 0.05, 20.0}) {
      const ImpactInput in{mass, stiffness, n, 0.0, velocity};
      const ImpactReference h = hp::hertz_reference(in);
      const HuntCrossleyImpact impact = make_impact(in);
      const std::string where = in.describe();
      const ImpactState peak = impact.force_peak();
      constant.update(relative_error(impact.contact_time() * velocity / impact.approach_max(),
                                     h.contact_time * velocity / h.approach_max),
                      where);
      x_max.update(relative_error(impact.approach_max(), h.approach_max), where);
      f_max.update(relative_error(peak.force, h.force_max), where);
      t_peak.update(relative_error(peak.time, h.time_force_max), where);
      t_compression.update(relative_error(impact.compression_time(), h.compression_time), where);
      t_contact.update(relative_error(impact.contact_time(), h.contact_time), where);
      v_out.update(relative_error(impact.rebound_velocity(), h.rebound_velocity), where);
      EXPECT_EQ(impact.restitution(), 1.0) << where;
    }
  }
  std::cout << "Hertz limit b = 0:\n";
  for (const WorstError* w :
       {&constant, &x_max, &f_max, &t_peak, &t_compression, &t_contact, &v_out})
    expect_target(*w);
}

// beta -> 0: tiny positive damping reproduces the Hertz values (to the table's targets: the
// true difference is O(beta) < 1e-20), and the step from b = 0 to beta = 1e-12 is the true
// one: |(q(1e-12) - q(0)) - (q_ref(1e-12) - q_ref(0))| / |q_ref(0)| within the table's target
// (the step itself is O(beta), and O(beta / (1 - x/x_max)) for v(x) near x_max).
TEST(HuntCrossleyAccuracy, ContinuityAsBetaGoesToZero) {
  WorstError tiny_x("x_max, beta in [1e-300, 1e-20]", target_peak);
  WorstError tiny_f("F_max, beta in [1e-300, 1e-20]", target_peak);
  WorstError tiny_tp("t(F_max), beta in [1e-300, 1e-20]", target_peak);
  WorstError tiny_tc("t_c, t_comp, beta in [1e-300, 1e-20]", target_time);
  WorstError tiny_k("k, V_out, beta in [1e-300, 1e-20]", target_restitution);
  WorstError step_peak("step 0->1e-12: x_max, F_max, t(F_max)", target_peak);
  WorstError step_time("step 0->1e-12: t_comp, t_c", target_time);
  WorstError step_k("step 0->1e-12: k", target_restitution);
  WorstError step_rate("step 0->1e-12: v(x)", target_rate);
  double largest_step = 0;
  for (const double n : {1.0, 1.5, 2.5}) {
    const ImpactInput hertz_in{mass, stiffness, n, 0.0, 1.0};
    const ImpactReference h = hp::hertz_reference(hertz_in);
    for (const double beta : {1e-300, 1e-200, 1e-100, 1e-30, 1e-20}) {
      const ImpactInput in = input_for(beta, n, 1.0);
      const std::string where = in.describe();
      try {
        const HuntCrossleyImpact impact = make_impact(in);
        const ImpactState peak = impact.force_peak();
        tiny_x.update(relative_error(impact.approach_max(), h.approach_max), where);
        tiny_f.update(relative_error(peak.force, h.force_max), where);
        tiny_tp.update(relative_error(peak.time, h.time_force_max), where);
        tiny_tc.update(relative_error(impact.contact_time(), h.contact_time), where);
        tiny_tc.update(relative_error(impact.compression_time(), h.compression_time), where);
        tiny_k.update(relative_error(impact.restitution(), h.restitution), where);
        tiny_k.update(relative_error(impact.rebound_velocity(), h.rebound_velocity), where);
      } catch (const std::exception& error) {
        std::cout << "  EXCEPTION at " << where << ": " << error.what() << "\n";
        tiny_x.update(std::numeric_limits<double>::infinity(), where);
      }
    }
    const ImpactInput damped_in = input_for(1e-12, n, 1.0);
    const ImpactReference d = hp::hunt_crossley_reference(damped_in);
    const HuntCrossleyImpact elastic = make_impact(hertz_in);
    const HuntCrossleyImpact damped = make_impact(damped_in);
    const std::string where = hp::format("n=%g", n);
    const auto step_error = [&](WorstError& worst, double value_damped, double value_elastic,
                                const Real100& reference_damped, const Real100& reference_elastic,
                                const std::string& what) {
      const Real100 true_step = reference_damped - reference_elastic;
      const Real100 step = Real100(value_damped) - Real100(value_elastic);
      largest_step =
          std::max(largest_step, static_cast<double>(abs(true_step / reference_elastic)));
      worst.update(static_cast<double>(abs((step - true_step) / reference_elastic)),
                   where + " " + what);
    };
    const ImpactState peak_d = damped.force_peak(), peak_e = elastic.force_peak();
    step_error(step_peak, damped.approach_max(), elastic.approach_max(), d.approach_max,
               h.approach_max, "x_max");
    step_error(step_peak, peak_d.force, peak_e.force, d.force_max, h.force_max, "F_max");
    step_error(step_peak, peak_d.time, peak_e.time, d.time_force_max, h.time_force_max, "t(F_max)");
    step_error(step_time, damped.compression_time(), elastic.compression_time(), d.compression_time,
               h.compression_time, "t_comp");
    step_error(step_time, damped.contact_time(), elastic.contact_time(), d.contact_time,
               h.contact_time, "t_c");
    step_error(step_k, damped.restitution(), elastic.restitution(), d.restitution, h.restitution,
               "k");
    for (const double fraction : {0.5, 0.999, 1 - 1e-6}) {
      const double x = fraction * elastic.approach_max();
      for (const bool compression : {true, false}) {
        const ImpactPhase phase = compression ? ImpactPhase::compression : ImpactPhase::restitution;
        const auto reference_damped = hp::approach_rate_reference(damped_in, x, compression);
        const auto reference_elastic = hp::approach_rate_reference(hertz_in, x, compression);
        ASSERT_TRUE(reference_damped && reference_elastic);
        step_error(step_rate, damped.approach_rate(x, phase), elastic.approach_rate(x, phase),
                   *reference_damped, *reference_elastic,
                   hp::format("v(%.17g x_max)", fraction) + (compression ? " W-1" : " W0"));
      }
    }
  }
  std::cout << "Continuity as beta -> 0 (tiny beta against the Hertz references; the step from "
               "b = 0 to beta = 1e-12 against the true step, largest true step "
            << largest_step << "):\n";
  for (const WorstError* w :
       {&tiny_x, &tiny_f, &tiny_tp, &tiny_tc, &tiny_k, &step_peak, &step_time, &step_k, &step_rate})
    expect_target(*w);
}

// beta = 1e4 (and beyond the table, 1e5): everything finite, no overflow; errors against the
// references reported (the table asks only k and V_out up to 1e4).
TEST(HuntCrossleyAccuracy, LargeImpactParameterIsFinite) {
  std::cout << "Large beta (errors for information; finiteness asserted):\n";
  for (const double beta : {1e4, 1e5}) {
    for (const double n : {1.0, 1.5, 2.5}) {
      const ImpactInput in = input_for(beta, n, 1.0);
      const std::string where = in.describe();
      std::unique_ptr<HuntCrossleyImpact> impact;
      try {
        impact = std::make_unique<HuntCrossleyImpact>(make_impact(in));
      } catch (const std::exception& error) {
        ADD_FAILURE() << "construction throws at " << where << ": " << error.what();
        continue;
      }
      const double nan = std::numeric_limits<double>::quiet_NaN();
      ImpactState peak{nan, nan, nan, nan};
      double t_comp = nan, t_c = nan;
      try {
        peak = impact->force_peak();
        t_comp = impact->compression_time();
        t_c = impact->contact_time();
      } catch (const std::exception& error) {
        ADD_FAILURE() << "throws at " << where << ": " << error.what();
      }
      const double values[] = {impact->approach_max(),
                               impact->restitution(),
                               impact->rebound_velocity(),
                               peak.force,
                               peak.time,
                               t_comp,
                               t_c,
                               impact->approach_rate(0.5 * impact->approach_max(),
                                                     ImpactPhase::compression),
                               impact->approach_rate(0.5 * impact->approach_max(),
                                                     ImpactPhase::restitution)};
      for (const double value : values) EXPECT_TRUE(std::isfinite(value)) << where;
      EXPECT_GT(impact->restitution(), 0.0) << where;
      EXPECT_GT(t_c, t_comp) << where;
      if (beta == 1e4 && n == 1.5) {
        const ImpactReference r = hp::hunt_crossley_reference(in);
        std::cout << "  " << where << ": k " << relative_error(impact->restitution(), r.restitution)
                  << ", x_max " << relative_error(impact->approach_max(), r.approach_max)
                  << ", F_max " << relative_error(peak.force, r.force_max) << ", t(F_max) "
                  << relative_error(peak.time, r.time_force_max) << ", t_comp "
                  << relative_error(t_comp, r.compression_time) << ", t_c "
                  << relative_error(t_c, r.contact_time) << "\n";
      }
    }
  }
}

} // namespace
