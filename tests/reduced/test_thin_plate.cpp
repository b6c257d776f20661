// Zener's sphere-on-thin-plate model (thin_plate.hpp) against an independent integration:
// the unscaled system in sphere position z and plate deflection w, integrated here by
// Dormand–Prince 5(4) with dense output in long double at 1e-17, its events found by bisection and Brent's
// method on the dense output (not the library's re-stepping and TOMS 748), and kept going
// after the separation to count contacts. Also: the rigid limit against the closed form of
// HuntCrossleyImpact, the energy balance, Zener's scaling (equal lambda, equal impact),
// monotonicity in lambda, and every kind of bad input.

#include "impact_reduced/hunt_crossley.hpp"
#include "impact_reduced/invalid_input.hpp"
#include "impact_reduced/thin_plate.hpp"

#include <boost/math/tools/minima.hpp>
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint.hpp>
#pragma GCC diagnostic pop
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <utility>

namespace {

using impact::reduced::HuntCrossleyImpact;
using impact::reduced::InvalidInput;
using impact::reduced::KirchhoffPlate;
using impact::reduced::ThinPlateImpact;
using impact::reduced::ThinPlateImpactResult;

constexpr double pi = 3.14159265358979323846;
constexpr double inf = std::numeric_limits<double>::infinity();

// The study's ball: steel, m = 0.1 kg (R = 14.52 mm), Hertz c on a steel half-space.
constexpr double mass = 0.1;
constexpr double stiffness = 1.7135e10;
constexpr double hertz = 1.5;
constexpr double velocity = 1.0;

double relative_error(double value, double exact) {
  return std::abs(value / exact - 1);
}

// Zener's time unit and the impedance that gives `lambda`.
double time_unit(double m, double c, double n, double V) {
  return std::pow(m * std::pow(V, 1 - n) / c, 1 / (n + 1));
}
double impedance_for(double lambda, double m, double c, double n, double V) {
  return m / (lambda * time_unit(m, c, n, V));
}

// The reference: state (z, v, w, plate energy, damping energy) in units of the Hertz
// approach x_H = ((n+1) m V^2 / (2 c))^(1/(n+1)), V, x_H, m V^2, m V^2; time in x_H / V.
struct Reference {
  ThinPlateImpactResult result{};
  int contacts = 0;
  double velocity_after = 0; // sphere velocity long after the separation [m/s]
};

Reference reference_impact(double m_in, double c_in, double n_in, double b_in, double Z_in,
                           double V_in) {
  namespace odeint = boost::numeric::odeint;
  using Real = long double; // 64-bit mantissa: a reference well below the library's 1e-14
  using State = std::array<Real, 5>;
  const Real m = m_in, c = c_in, n = n_in, b = b_in, Z = Z_in, V = V_in;
  const Real length = std::pow((n + 1) * m * V * V / (2 * c), 1 / (n + 1));
  const Real time = length / V;
  // Contact force and plate velocity from Z w' = F, F = c x^n (1 + b (v - w')).
  const auto plate_rate = [&](const State& y) -> Real { // w' [m/s]
    const Real gap = length * (y[0] - y[2]);
    if (gap <= 0) return 0;
    const Real spring = c * std::pow(gap, n);
    return std::max<Real>(spring * (1 + b * V * y[1]) / (Z + b * spring), 0);
  };
  const auto force = [&](const State& y) { return Z * plate_rate(y); };
  const auto approach_rate = [&](const State& y) { return V * y[1] - plate_rate(y); }; // m/s
  const auto gap = [](const State& s) { return s[0] - s[2]; };
  const auto system = [&](const State& y, State& d, Real) {
    const Real w_rate = plate_rate(y);
    const Real F = Z * w_rate;
    const Real x = length * gap(y);
    const Real rate = V * y[1] - w_rate;
    d[0] = y[1];
    d[1] = -F * time / (m * V);
    d[2] = w_rate * time / length;
    d[3] = F * w_rate * time / (m * V * V);
    d[4] = x > 0 ? b * c * std::pow(x, n) * rate * rate * time / (m * V * V) : 0;
  };
  auto stepper = odeint::make_dense_output(Real(1e-17), Real(1e-17),
                                           odeint::runge_kutta_dopri5<State, Real>());
  stepper.initialize(State{0, 1, 0, 0, 0}, Real(0), Real(1e-4));
  Reference out;
  out.contacts = 1;
  bool in_contact = true, compressing = true;
  Real separation = 0;
  State y;
  const auto bisect = [&](Real lower, Real upper, auto event) {
    const bool positive_at_lower = event(stepper.previous_state()) > 0;
    for (int i = 0; i < 200 && upper - lower > 1e-19L * upper; ++i) {
      const Real middle = (lower + upper) / 2;
      stepper.calc_state(middle, y);
      ((event(y) > 0) == positive_at_lower ? lower : upper) = middle;
    }
    return (lower + upper) / 2;
  };
  const auto maximise = [&](Real lower, Real upper, auto value) {
    const auto found = boost::math::tools::brent_find_minima(
        [&](Real t) {
          stepper.calc_state(t, y);
          return -value(y);
        },
        lower, upper, 32);
    return std::make_pair(-found.second, found.first);
  };
  while (true) {
    const auto [t0, t1] = stepper.do_step(system);
    const State& start = stepper.previous_state();
    const State& end = stepper.current_state();
    if (in_contact) {
      const auto [f, tf] = maximise(t0, t1, force);
      if (f > out.result.force_max) {
        out.result.force_max = static_cast<double>(f);
        out.result.time_force_max = static_cast<double>(tf * time);
      }
      const auto [x, tx] = maximise(t0, t1, gap);
      if (length * x > out.result.approach_max)
        out.result.approach_max = static_cast<double>(length * x);
      if (compressing && approach_rate(end) <= 0) {
        compressing = false;
        out.result.time_approach_max = static_cast<double>(bisect(t0, t1, approach_rate) * time);
      }
      if (!compressing && gap(end) <= 0) {
        separation = bisect(t0, t1, gap);
        stepper.calc_state(separation, y);
        out.result.contact_time = static_cast<double>(separation * time);
        out.result.restitution = static_cast<double>(-y[1]);
        out.result.plate_deflection = static_cast<double>(length * y[2]);
        out.result.plate_energy_fraction = static_cast<double>(2 * y[3]);
        out.result.damping_energy_fraction = static_cast<double>(2 * y[4]);
        in_contact = false;
      }
    } else if (gap(end) > 0 && !(gap(start) > 0)) {
      ++out.contacts; // a new contact: the bodies meet again
      in_contact = compressing = true;
    }
    if (!in_contact && t1 > 3 * separation) {
      out.velocity_after = static_cast<double>(V * end[1]);
      break;
    }
  }
  return out;
}

// -------------------------------------------------------------------------------------

TEST(ThinPlate, ImpedanceAndRigidity) {
  const KirchhoffPlate steel{2e11, 0.25, 7800, 0.01};
  const double D = 2e11 * 1e-6 / (12 * (1 - 0.0625));
  EXPECT_LT(relative_error(impact::reduced::flexural_rigidity(steel), D), 1e-15);
  EXPECT_LT(relative_error(impact::reduced::plate_point_impedance(steel),
                           8 * std::sqrt(D * 7800 * 0.01)),
            1e-15);
}

// Worst errors of the library against the reference over lambda in [0.01, 10], bV in {0, 0.1,
// 1}, at a given tolerance: relative in t_c, F_max, x_max, both absolute and relative in e
// (e falls to 7e-6 at lambda = 10, and its absolute error is that of the sphere velocity,
// set by the tolerance).
struct Worst {
  double restitution_absolute = 0, restitution = 0, contact_time = 0, force_max = 0,
         approach_max = 0;
};

Worst compare_with_reference(double tolerance) {
  Worst worst;
  for (const double beta : {0.0, 0.1, 1.0}) {
    for (const double lambda : {0.01, 0.03, 0.1, 0.3, 1.0, 3.0, 10.0}) {
      const double Z = impedance_for(lambda, mass, stiffness, hertz, velocity);
      const double b = beta / velocity;
      const auto result = ThinPlateImpact(stiffness, hertz, b, mass, Z).impact(velocity, tolerance);
      // The references are computed once for both tolerances (1.5 s in long double).
      static std::map<std::pair<double, double>, Reference> references;
      auto known = references.find({beta, lambda});
      if (known == references.end())
        known = references
                    .emplace(std::make_pair(beta, lambda),
                             reference_impact(mass, stiffness, hertz, b, Z, velocity))
                    .first;
      const Reference& reference = known->second;
      const auto& exact = reference.result;
      EXPECT_NEAR(result.zener_lambda, lambda, 1e-14 * lambda);
      const auto track = [](double& slot, double error) { slot = std::max(slot, error); };
      track(worst.restitution_absolute, std::abs(result.restitution - exact.restitution));
      track(worst.restitution, relative_error(result.restitution, exact.restitution));
      track(worst.contact_time, relative_error(result.contact_time, exact.contact_time));
      track(worst.force_max, relative_error(result.force_max, exact.force_max));
      track(worst.approach_max, relative_error(result.approach_max, exact.approach_max));
      EXPECT_LT(relative_error(result.time_approach_max, exact.time_approach_max), 1e-8);
      EXPECT_LT(relative_error(result.time_force_max, exact.time_force_max),
                1e-7); // Brent: sqrt(eps)
      EXPECT_LT(relative_error(result.plate_deflection, exact.plate_deflection), 1e-8);
      EXPECT_NEAR(result.plate_energy_fraction, exact.plate_energy_fraction, 1e-9);
      EXPECT_NEAR(result.damping_energy_fraction, exact.damping_energy_fraction, 1e-9);
      // One contact, and the sphere leaves (and stays) at -e V.
      EXPECT_EQ(reference.contacts, 1);
      EXPECT_EQ(result.number_of_contacts, 1u);
      EXPECT_NEAR(-reference.velocity_after / velocity, exact.restitution, 1e-15);
      if (tolerance == 1e-14)
        std::printf(
            "lambda %5.2f bV %3.1f  e = %.12e  t_c = %.10e s  F_max = %.8e N  "
            "x_max = %.8e m  plate %.6f damping %.6f\n",
            lambda, beta, result.restitution, result.contact_time, result.force_max,
            result.approach_max, result.plate_energy_fraction, result.damping_energy_fraction);
    }
  }
  std::printf(
      "tolerance %.0e: worst e %.2e absolute, %.2e relative; t_c %.2e, F_max %.2e, "
      "x_max %.2e relative\n",
      tolerance, worst.restitution_absolute, worst.restitution, worst.contact_time, worst.force_max,
      worst.approach_max);
  return worst;
}

TEST(ThinPlate, MatchesAnIndependentIntegrationAtTheTightestTolerance) {
  const Worst worst = compare_with_reference(1e-14);
  EXPECT_LT(worst.restitution, 1e-9);
  EXPECT_LT(worst.contact_time, 1e-9);
  EXPECT_LT(worst.force_max, 1e-9);
  EXPECT_LT(worst.approach_max, 1e-9);
}

TEST(ThinPlate, MatchesAnIndependentIntegrationAtTheDefaultTolerance) {
  const Worst worst = compare_with_reference(1e-11);
  EXPECT_LT(worst.restitution_absolute, 1e-10);
  EXPECT_LT(worst.contact_time, 1e-8);
  EXPECT_LT(worst.force_max, 1e-9);
  EXPECT_LT(worst.approach_max, 1e-9);
}

TEST(ThinPlate, RigidPlateIsTheClosedFormHuntCrossley) {
  double worst = 0;
  for (const double n : {1.0, 1.5, 2.5}) {
    for (const double beta : {0.0, 0.1, 1.0, 5.0}) {
      const double b = beta / velocity;
      const auto result = ThinPlateImpact(stiffness, n, b, mass, inf).impact(velocity);
      const HuntCrossleyImpact exact(mass, stiffness, n, b, velocity);
      const auto response = exact.response();
      EXPECT_EQ(result.zener_lambda, 0.0);
      EXPECT_EQ(result.plate_energy_fraction, 0.0);
      const double errors[] = {relative_error(result.restitution, response.restitution),
                               relative_error(result.contact_time, response.contact_time),
                               relative_error(result.force_max, response.force_max),
                               relative_error(result.time_force_max, response.time_force_max),
                               relative_error(result.approach_max, response.approach_max),
                               relative_error(result.time_approach_max, response.compression_time)};
      for (const double error : errors) {
        EXPECT_LT(error, 1e-9) << "n " << n << " beta " << beta;
        worst = std::max(worst, error);
      }
      EXPECT_NEAR(result.damping_energy_fraction, 1 - response.restitution * response.restitution,
                  1e-9);
    }
  }
  std::printf("rigid limit: worst relative error %.2e\n", worst);
  // Continuity: a very stiff plate approaches the rigid one.
  const auto rigid = ThinPlateImpact(stiffness, hertz, 0, mass, inf).impact(velocity);
  const auto stiff = ThinPlateImpact(stiffness, hertz, 0, mass,
                                     impedance_for(1e-8, mass, stiffness, hertz, velocity))
                         .impact(velocity);
  EXPECT_NEAR(stiff.restitution, rigid.restitution, 1e-7);
  EXPECT_LT(stiff.restitution, rigid.restitution);
}

TEST(ThinPlate, EnergyBalance) {
  double worst = 0;
  for (const double beta : {0.0, 0.01, 0.3, 3.0}) {
    for (double lambda = 1e-3; lambda < 200; lambda *= 3) {
      const double Z = impedance_for(lambda, mass, stiffness, hertz, velocity);
      const auto r = ThinPlateImpact(stiffness, hertz, beta / velocity, mass, Z).impact(velocity);
      const double balance =
          1 - r.restitution * r.restitution - r.plate_energy_fraction - r.damping_energy_fraction;
      EXPECT_LT(std::abs(balance), 1e-9) << "lambda " << lambda << " beta " << beta;
      worst = std::max(worst, std::abs(balance));
      if (beta == 0) {
        EXPECT_EQ(r.damping_energy_fraction, 0.0);
      }
      // Momentum: the plate point keeps w = m V (1 + e) / Z.
      EXPECT_LT(relative_error(r.plate_deflection, mass * velocity * (1 + r.restitution) / Z),
                1e-9);
    }
  }
  std::printf("energy balance: worst |1 - e^2 - plate - damping| = %.2e\n", worst);
}

TEST(ThinPlate, RestitutionFallsWithLambdaAndThereIsOneContact) {
  for (const double beta : {0.0, 0.2}) {
    double previous = 1.0;
    for (double lambda = 1e-3; lambda < 200; lambda *= 1.5) {
      const double Z = impedance_for(lambda, mass, stiffness, hertz, velocity);
      const auto r = ThinPlateImpact(stiffness, hertz, beta / velocity, mass, Z).impact(velocity);
      EXPECT_LT(r.restitution, previous) << "lambda " << lambda;
      EXPECT_GT(r.restitution, 0.0) << "lambda " << lambda;
      EXPECT_EQ(r.number_of_contacts, 1u);
      previous = r.restitution;
    }
  }
}

TEST(ThinPlate, EqualLambdaGivesTheSameImpact) {
  // Steel ball R = 14.52 mm on a 5 mm steel plate at 1 m/s, and a glass ball R = 3 mm on an
  // aluminium plate at 4 m/s with the thickness that gives the same lambda.
  const KirchhoffPlate steel{2e11, 0.25, 7800, 0.005};
  const double lambda = impact::reduced::zener_lambda(0.01452, 7800, 2e11, 0.25, steel, 1.0);
  KirchhoffPlate aluminium{7e10, 0.33, 2700, 0.001};
  const auto glass_lambda = [&](const KirchhoffPlate& p) {
    return impact::reduced::zener_lambda(0.003, 2500, 6.3e10, 0.22, p, 4.0);
  };
  aluminium.thickness *= std::sqrt(glass_lambda(aluminium) / lambda); // lambda ~ 1/h^2
  ASSERT_LT(relative_error(glass_lambda(aluminium), lambda), 1e-14);

  const auto impact_of = [](double R, double rho, double E, double nu, const KirchhoffPlate& p,
                            double V, double beta) {
    const double m = 4.0 / 3.0 * pi * R * R * R * rho;
    const double E_star =
        1 / ((1 - nu * nu) / E + (1 - p.poisson_ratio * p.poisson_ratio) / p.youngs_modulus);
    const double c = 4.0 / 3.0 * E_star * std::sqrt(R);
    const double Z = impact::reduced::plate_point_impedance(p);
    const auto result = ThinPlateImpact(c, 1.5, beta / V, m, Z).impact(V);
    return std::make_pair(result, time_unit(m, c, 1.5, V));
  };
  for (const double beta : {0.0, 0.5}) {
    const auto [a, ta] = impact_of(0.01452, 7800, 2e11, 0.25, steel, 1.0, beta);
    const auto [g, tg] = impact_of(0.003, 2500, 6.3e10, 0.22, aluminium, 4.0, beta);
    EXPECT_LT(relative_error(a.zener_lambda, lambda), 1e-14);
    EXPECT_LT(relative_error(g.zener_lambda, lambda), 1e-14);
    EXPECT_LT(relative_error(a.restitution, g.restitution), 1e-10);
    EXPECT_LT(relative_error(a.contact_time / ta, g.contact_time / tg), 1e-10);
    EXPECT_LT(relative_error(a.plate_energy_fraction, g.plate_energy_fraction), 1e-10);
    std::printf("equal lambda %.6f, beta %.1f: e = %.12f and %.12f\n", lambda, beta, a.restitution,
                g.restitution);
  }
}

TEST(ThinPlate, ZenerLambdaInMaterialTerms) {
  for (const double h : {0.002, 0.01, 0.05}) {
    for (const double V : {0.5, 5.0}) {
      const KirchhoffPlate p{7e10, 0.33, 2700, h};
      const double R = 0.01452, rho = 7800, E = 2e11, nu = 0.25;
      const double E_star = 1 / ((1 - nu * nu) / E + (1 - 0.33 * 0.33) / 7e10);
      const double expected = std::pow(pi, 0.6) / std::sqrt(3.0) * (R / h) * (R / h) *
                              std::pow(V / std::sqrt(7e10 / 2700), 0.2) *
                              std::pow(rho / 2700, 0.6) * std::pow(E_star / 7e10, 0.4) *
                              std::sqrt(1 - 0.33 * 0.33);
      EXPECT_LT(relative_error(impact::reduced::zener_lambda(R, rho, E, nu, p, V), expected),
                4e-15);
    }
  }
}

TEST(ThinPlate, HistoryStartsAndEndsAtTouch) {
  const double Z = impedance_for(0.5, mass, stiffness, hertz, velocity);
  const ThinPlateImpact model(stiffness, hertz, 0.1, mass, Z);
  const auto result = model.impact(velocity);
  const auto samples = model.history(velocity, 101);
  ASSERT_EQ(samples.size(), 101u);
  EXPECT_EQ(samples.front().time, 0.0);
  EXPECT_EQ(samples.front().approach, 0.0);
  EXPECT_EQ(samples.front().sphere_velocity, velocity);
  EXPECT_EQ(samples.back().time, result.contact_time);
  EXPECT_EQ(samples.back().approach, 0.0);
  EXPECT_DOUBLE_EQ(samples.back().sphere_velocity, -result.restitution * velocity);
  EXPECT_DOUBLE_EQ(samples.back().plate_deflection, result.plate_deflection);
  for (std::size_t i = 1; i < samples.size(); ++i) {
    EXPECT_LE(samples[i].force, result.force_max * (1 + 1e-12));
    EXPECT_LE(samples[i].approach, result.approach_max * (1 + 1e-12));
    EXPECT_GE(samples[i].plate_deflection, samples[i - 1].plate_deflection); // never moves back
  }
}

TEST(ThinPlate, BadInputNamesTheParameter) {
  const auto expect_invalid = [](auto call, const std::string& parameter) {
    try {
      call();
      ADD_FAILURE() << "no error for " << parameter;
    } catch (const InvalidInput& error) {
      EXPECT_EQ(error.parameter(), parameter);
      EXPECT_NE(std::string(error.what()).find(parameter), std::string::npos) << error.what();
    }
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const double bad : {0.0, -1.0, nan, inf}) {
    expect_invalid([&] { ThinPlateImpact(bad, 1.5, 0, 1, 1); }, "stiffness");
    expect_invalid([&] { ThinPlateImpact(1, bad, 0, 1, 1); }, "exponent");
    expect_invalid([&] { ThinPlateImpact(1, 1.5, 0, bad, 1); }, "mass");
    expect_invalid([&] { ThinPlateImpact(1, 1.5, 0, 1, 1).impact(bad); }, "velocity");
    expect_invalid([&] { ThinPlateImpact(1, 1.5, 0, 1, 1).zener_lambda(bad); }, "velocity");
    expect_invalid(
        [&] {
          impact::reduced::flexural_rigidity({bad, 0.3, 1, 1});
        },
        "plate.youngs_modulus");
    expect_invalid(
        [&] {
          impact::reduced::plate_point_impedance({1, 0.3, bad, 1});
        },
        "plate.density");
    expect_invalid(
        [&] {
          impact::reduced::plate_point_impedance({1, 0.3, 1, bad});
        },
        "plate.thickness");
    const KirchhoffPlate plate{1, 0.3, 1, 1};
    expect_invalid([&] { impact::reduced::zener_lambda(bad, 1, 1, 0.3, plate, 1); },
                   "sphere_radius");
    expect_invalid([&] { impact::reduced::zener_lambda(1, bad, 1, 0.3, plate, 1); },
                   "sphere_density");
    expect_invalid([&] { impact::reduced::zener_lambda(1, 1, bad, 0.3, plate, 1); },
                   "sphere_youngs_modulus");
    expect_invalid([&] { impact::reduced::zener_lambda(1, 1, 1, 0.3, plate, bad); }, "velocity");
  }
  for (const double bad : {-1e-9, -1.0, nan, inf})
    expect_invalid([&] { ThinPlateImpact(1, 1.5, bad, 1, 1); }, "damping");
  for (const double bad : {0.0, -1.0, nan, -inf})
    expect_invalid([&] { ThinPlateImpact(1, 1.5, 0, 1, bad); }, "impedance");
  for (const double bad : {-1.0, 0.5, 0.7, -1.5, nan}) {
    expect_invalid(
        [&] {
          impact::reduced::flexural_rigidity({1, bad, 1, 1});
        },
        "plate.poisson_ratio");
    expect_invalid(
        [&] {
          impact::reduced::zener_lambda(1, 1, 1, bad, {1, 0.3, 1, 1}, 1);
        },
        "sphere_poisson_ratio");
  }
  for (const double bad : {0.0, 1e-15, 1e-2, nan})
    expect_invalid([&] { ThinPlateImpact(1, 1.5, 0, 1, 1).impact(1, bad); }, "relative_tolerance");
  expect_invalid([&] { ThinPlateImpact(1, 1.5, 0, 1, 1).history(1, 1); }, "points");
}

} // namespace
