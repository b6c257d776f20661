// Hunt-Crossley damping on an elastic-plastic spring (hunt_crossley_elastic_plastic.hpp)
// against an independent 50/100-digit reference, against HuntCrossleyImpact on the Hertz
// spring, and against the rate-independent elastic_plastic_impact at b = 0.
//
// The reference evaluates the model literally in the approach x, with nothing of the
// library's formulation (which works in the approach rate, with the branch-point variable
// and the library's laws): the springs are written out here from their published formulas,
// the loading work is the integral of the force (tanh-sinh in 50 digits where it has no
// closed form), the rate is the spec's Lambert W form
//     v(x) = -(1 + W(-exp(g))) / b,   g = -1 - (b^2 / m) E(x),
// with E(x) the spring work between x and x_max and W = W-1 while compressing, W0 while
// restoring; x_max, the force peak (m v F_L' = b F_L^2) and the times
// t = integral dx / |v| (x = x_max - L s^2, which removes the x_max singularity) follow by
// TOMS 748 and tanh-sinh quadrature in 50 digits.

#include "impact_reduced/ghaednia.hpp"
#include "impact_reduced/hertz_contact.hpp"
#include "impact_reduced/hunt_crossley.hpp"
#include "impact_reduced/hunt_crossley_elastic_plastic.hpp"
#include "impact_reduced/invalid_input.hpp"
#include "impact_reduced/sphere_flat_fits.hpp"
#include "impact_reduced/thornton.hpp"
#include "impact_reduced/contact_formulas.hpp"

#include "high_precision_reference.hpp"

#include "graded_event_integration.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace impact::reduced;
using hp::Real100;
using hp::Real50;
using impact::test_reference::GradedEventIntegration;

constexpr double pi = 3.14159265358979323846;

// ---- The springs, written out from their published formulas in 50 digits ----

struct ReferenceSpring {
  std::function<Real50(const Real50&)> force;     // F_L(x)
  std::function<Real50(const Real50&)> stiffness; // F_L'(x)
  std::vector<Real50> breakpoints;                // where F_L or F_L' jumps
  // Work of F_L between a and b (a < b), closed form where there is one.
  std::function<Real50(const Real50&, const Real50&)> work;
  // Hertzian unloading from x_max: stiffness k_u and residual x_r.
  std::function<std::pair<Real50, Real50>(const Real50&)> unloading;
};

Real50 integrate50(const std::function<Real50(const Real50&)>& f, const Real50& a,
                   const Real50& b) {
  if (!(b > a)) return 0;
  return hp::quadrature50().integrate(f, a, b, Real50(1e-30));
}

// Work between a and b, split at the breakpoints.
Real50 split_work(const ReferenceSpring& spring, const Real50& a, const Real50& b) {
  std::vector<Real50> ends{a};
  for (const auto& x : spring.breakpoints)
    if (x > a && x < b) ends.push_back(x);
  ends.push_back(b);
  Real50 work = 0;
  for (std::size_t i = 0; i + 1 < ends.size(); ++i)
    work += integrate50(spring.force, ends[i], ends[i + 1]);
  return work;
}

ReferenceSpring hertz_spring(double stiffness) {
  const Real50 c = stiffness;
  ReferenceSpring s;
  s.force = [c](const Real50& x) { return Real50(c * pow(x, Real50(1.5))); };
  s.stiffness = [c](const Real50& x) { return Real50(1.5 * c * sqrt(x)); };
  s.work = [c](const Real50& a, const Real50& b) {
    return Real50(c * (pow(b, Real50(2.5)) - pow(a, Real50(2.5))) / Real50(2.5));
  };
  s.unloading = [c](const Real50&) { return std::make_pair(c, Real50(0)); };
  return s;
}

// Thornton (1997): Hertz to x_y, then F_y + pi p_y R (x - x_y); unloading on R_p with
// a_p^2 = (2 F* + F_y) / (2 pi p_y), R_p = 4 E* a_p^3 / (3 F*), x_p = x_max - 3 F* / (4 E* a_p).
ReferenceSpring thornton_spring(double radius, double modulus, double yield_pressure) {
  const Real50 R = radius, E = modulus, p = yield_pressure,
               PI = boost::math::constants::pi<Real50>();
  const Real50 c = Real50(4) / 3 * E * sqrt(R);
  const Real50 x_y = R * pow(PI * p / (2 * E), 2);
  const Real50 F_y = c * pow(x_y, Real50(1.5));
  const Real50 k_p = PI * p * R;
  ReferenceSpring s;
  s.force = [=](const Real50& x) {
    return x <= x_y ? Real50(c * pow(x, Real50(1.5))) : Real50(F_y + k_p * (x - x_y));
  };
  s.stiffness = [=](const Real50& x) { return x < x_y ? Real50(1.5 * c * sqrt(x)) : k_p; };
  s.breakpoints = {x_y};
  s.work = [=](const Real50& a, const Real50& b) {
    auto W = [&](const Real50& x) {
      if (x <= x_y) return Real50(c * pow(x, Real50(2.5)) / Real50(2.5));
      return Real50(c * pow(x_y, Real50(2.5)) / Real50(2.5) + F_y * (x - x_y) +
                    k_p * (x - x_y) * (x - x_y) / 2);
    };
    return Real50(W(b) - W(a));
  };
  s.unloading = [=](const Real50& x_max) {
    if (x_max <= x_y) return std::make_pair(c, Real50(0));
    const Real50 F = F_y + k_p * (x_max - x_y);
    const Real50 a_p = sqrt((2 * F + F_y) / (2 * PI * p));
    const Real50 R_p = 4 * E * pow(a_p, 3) / (3 * F);
    return std::make_pair(Real50(Real50(4) / 3 * E * sqrt(R_p)),
                          Real50(x_max - 3 * F / (4 * E * a_p)));
  };
  return s;
}

// ---- The reference impact ----

struct Reference {
  Real100 approach_max, restitution, force_max, compression_time, contact_time;
};

// 1 + W(-exp(-1 - s)) on either branch in 50 digits: Boost's W of the literal argument,
// and below s = 1e-12 (where the argument is within 1e-12 of -1/e) the branch-point series
// of high_precision_reference.hpp, whose first omitted term is ~s^(7/2) = 1e-42 relative.
Real50 one_plus_w(const Real50& s, bool principal) {
  if (s == 0) return 0;
  if (s < Real50(1e-12)) return Real50(hp::one_plus_w_series(Real100(s), principal));
  const Real50 z = -exp(-1 - s);
  return 1 + (principal ? boost::math::lambert_w0(z) : boost::math::lambert_wm1(z));
}

Reference reference_impact(const ReferenceSpring& spring, double mass_, double damping_,
                           double velocity_, bool with_times = true) {
  using boost::math::tools::eps_tolerance;
  using boost::math::tools::toms748_solve;
  const Real50 m = mass_, b = damping_, V = velocity_;
  auto work = [&](const Real50& a, const Real50& x) {
    return spring.work ? spring.work(a, x) : split_work(spring, a, x);
  };
  // Energy stored in the spring at x_max: m V^2 / 2 (b = 0), (m / b^2)(beta - ln(1 + beta)).
  const Real50 beta = b * V;
  const Real50 stored = b == 0 ? Real50(m * V * V / 2) : Real50(m / (b * b) * (beta - log1p(beta)));
  Real50 upper = 1e-12;
  while (work(Real50(0), upper) < stored) upper *= 2;
  std::uintmax_t iterations = 400;
  const auto [low, high] =
      toms748_solve([&](const Real50& x) { return Real50(work(Real50(0), x) - stored); }, Real50(0),
                    upper, eps_tolerance<Real50>(160), iterations);
  const Real50 x_max = (low + high) / 2;
  Reference r;
  r.approach_max = Real100(x_max);

  // The rate from the energy E between x and the turning point: while compressing
  // (m/b^2)(b v - ln(1 + b v)) = (m/b^2)(beta - ln(1+beta)) - W_L(x) = E_L(x) measured from
  // x_max; with s = b^2 E / m, b v = -(1 + W(-exp(-1 - s))).
  auto rate_of_energy = [&](const Real50& energy, bool compressing) {
    if (b == 0) {
      const Real50 speed = sqrt(2 * energy / m);
      return compressing ? speed : Real50(-speed);
    }
    return Real50(-one_plus_w(Real50(b * b * energy / m), !compressing) / b);
  };

  // Restitution: the released energy down to x_s = max(x_r, 0).
  const auto [k_u, x_r] = spring.unloading(x_max);
  auto branch_work = [&](const Real50& x) {
    return Real50(k_u * pow(x - x_r, Real50(2.5)) / Real50(2.5));
  };
  const Real50 x_s = x_r > 0 ? x_r : Real50(0);
  const Real50 released = branch_work(x_max) - branch_work(x_s);
  r.restitution = -Real100(rate_of_energy(released, false)) / Real100(V);

  // Force peak: m v F_L' = b F_L^2 while compressing, in x.
  if (b == 0) {
    r.force_max = Real100(spring.force(x_max));
  } else {
    auto condition = [&](const Real50& x) {
      const Real50 v = rate_of_energy(work(x, x_max), true);
      const Real50 F = spring.force(x);
      return Real50(m * v * spring.stiffness(x) - b * F * F);
    };
    iterations = 400;
    const auto [a, z] = toms748_solve(condition, Real50(x_max * Real50(1e-30)), x_max,
                                      eps_tolerance<Real50>(150), iterations);
    const Real50 x_peak = (a + z) / 2;
    const Real50 v_peak = rate_of_energy(work(x_peak, x_max), true);
    r.force_max = Real100(spring.force(x_peak) * (1 + b * v_peak));
  }
  if (!with_times) return r;

  // Times: x = x_max - L s^2 on [0, 1], dt = 2 L s ds / |v|, split at the breakpoints.
  auto phase_time = [&](const Real50& length, bool compressing) {
    auto density = [&](const Real50& s) -> Real50 {
      // Within 1e-20 of x_max (where x_max - L s^2 rounds to x_max even in 50 digits) the
      // density is its limit at s = 0 to O(s^2) = 1e-40.
      if (s < Real50(1e-20)) {
        // dt/ds -> 2 L / sqrt(2 F(x_max) L / m) ... the limit of 2 L s / |v| at s = 0.
        const Real50 F = compressing ? spring.force(x_max) : k_u * pow(x_max - x_r, Real50(1.5));
        return 2 * sqrt(length * m / (2 * F));
      }
      const Real50 x = x_max - length * s * s;
      const Real50 energy =
          compressing ? work(x, x_max) : Real50(branch_work(x_max) - branch_work(x));
      return 2 * length * s / abs(rate_of_energy(energy, compressing));
    };
    std::vector<Real50> ends{Real50(0)};
    if (compressing)
      for (const auto& x : spring.breakpoints)
        if (x > 0 && x < x_max) ends.push_back(sqrt((x_max - x) / length));
    ends.push_back(Real50(1));
    std::sort(ends.begin(), ends.end());
    Real50 time = 0;
    for (std::size_t i = 0; i + 1 < ends.size(); ++i)
      time += integrate50(density, ends[i], ends[i + 1]);
    return time;
  };
  r.compression_time = Real100(phase_time(x_max, true));
  r.contact_time = r.compression_time + Real100(phase_time(x_max - x_s, false));
  return r;
}

// ---- The cases ----

struct Case {
  std::string name;
  std::shared_ptr<const ElasticPlasticContact> spring;
  ReferenceSpring reference;
  double mass;
  double yield_velocity; // the scale of the velocities (V_y of the contact)
};

// A 10 mm (radius 5 mm) steel ball on a steel flat: E* = 1.154e11 Pa, p_y = 1.6 x 1 GPa.
constexpr double ball_radius = 5e-3;
constexpr double contact_modulus = 1.154e11;
constexpr double yield_strength = 1e9;
const double ball_mass = 4.0 / 3.0 * pi * ball_radius * ball_radius * ball_radius * 7800;

Case hertz_case() {
  const double c = 4.0 / 3.0 * contact_modulus * std::sqrt(ball_radius);
  return {"Hertz", std::make_shared<HertzContact>(c), hertz_spring(c), ball_mass,
          yield_velocity(1.6 * yield_strength, contact_modulus, ball_radius, ball_mass)};
}

Case thornton_case() {
  const double p_y = 1.6 * yield_strength;
  return {"Thornton", std::make_shared<ThorntonContact>(ball_radius, contact_modulus, p_y),
          thornton_spring(ball_radius, contact_modulus, p_y), ball_mass,
          yield_velocity(p_y, contact_modulus, ball_radius, ball_mass)};
}

Case jackson_green_case() {
  const SphereFlatContact contact{ball_radius, contact_modulus, yield_strength, 0.3};
  const double c_nu = 1.295 * std::exp(0.736 * 0.3);
  // No 50-digit spring: its reference is fitted_ode_reference below.
  return {"Jackson-Green", std::make_shared<JacksonGreenContact>(contact), ReferenceSpring{},
          ball_mass,
          yield_velocity(c_nu * yield_strength, contact_modulus, ball_radius, ball_mass)};
}

// Ghaednia et al. (2019) on the same contact: the sphere's E_s = 210 GPa (E* above is steel
// on steel, E_s / (2 (1 - 0.3^2))), E_t = 0.02 E_s as in test_ghaednia.cpp.
constexpr double steel_youngs_modulus = 210e9;
constexpr double steel_tangent_modulus = 0.02 * steel_youngs_modulus;

Case ghaednia_case() {
  const SphereFlatContact contact{ball_radius, contact_modulus, yield_strength, 0.3};
  const double c_nu = 1.295 * std::exp(0.736 * 0.3);
  // No 50-digit spring: its reference is fitted_ode_reference below.
  return {"Ghaednia",
          std::make_shared<GhaedniaContact>(contact, steel_youngs_modulus, steel_tangent_modulus),
          ReferenceSpring{}, ball_mass,
          yield_velocity(c_nu * yield_strength, contact_modulus, ball_radius, ball_mass)};
}

std::string where(const Case& c, double ratio, double beta) {
  return c.name + " V/V_y = " + hp::format("%g", ratio) + " beta = " + hp::format("%g", beta);
}

void sweep(const Case& c, const std::vector<double>& ratios, const std::vector<double>& betas) {
  hp::WorstError e("restitution", 1e-12), x("approach_max", 1e-12), f("force_max", 1e-12),
      tc("compression_time", 1e-10), t("contact_time", 1e-10);
  for (const double ratio : ratios)
    for (const double beta : betas) {
      const double velocity = ratio * c.yield_velocity;
      const double damping = beta / velocity;
      const HuntCrossleyElasticPlasticImpact impact(c.mass, c.spring, damping, velocity);
      const auto response = impact.response();
      const Reference r = reference_impact(c.reference, c.mass, damping, velocity);
      const std::string at = where(c, ratio, beta);
      e.update(hp::relative_error(response.restitution, r.restitution), at);
      x.update(hp::relative_error(response.approach_max, r.approach_max), at);
      f.update(hp::relative_error(response.force_max, r.force_max), at);
      tc.update(hp::relative_error(response.compression_time, r.compression_time), at);
      t.update(hp::relative_error(response.contact_time, r.contact_time), at);
    }
  for (const auto* worst : {&e, &x, &f, &tc, &t}) hp::expect_target(*worst);
}

const std::vector<double> betas{0.0, 1e-4, 0.01, 0.1, 1.0, 10.0};

TEST(HuntCrossleyElasticPlastic, HertzSpringAgainstFiftyDigitReference) {
  sweep(hertz_case(), {0.5, 30.0}, betas);
}

TEST(HuntCrossleyElasticPlastic, ThorntonSpringAgainstFiftyDigitReference) {
  sweep(thornton_case(), {1.5, 30.0, 1000.0}, betas);
}

// Jackson-Green and Ghaednia: their loading work has no closed form, and the 50-digit reference
// above would nest a 50-digit quadrature of the fit in every node (hours). As the library's
// other Jackson-Green tests, the reference is an independent integration of the equation of
// motion in long double instead: Runge-Kutta-Fehlberg 7(8) (Boost.Odeint), the steps graded from
// 1e-12 of their size at first contact (where F ~ x^(3/2) makes the solution non-smooth), every
// event located by bisecting its step: the transition (where the fit's force jumps), the force
// peak (dF/dt = F_L' v (1 + b v) + b F_L x'' = 0), x' = 0, and the separation x = x_s.
struct OdeReference {
  long double approach_max, force_max, compression_time, contact_time, rebound_velocity;
};

// A fitted loading curve, written out here in long double: Hertz's c x^(3/2) up to the
// transition x_t = 1.9 delta_c, then the fit's force F(x) and its contact radius a(x), which
// the unloading keeps: R_u = 4 E* a_m^3 / (3 P_m), x_r = x_max - 3 P_m / (4 E* a_m).
struct FittedLoading {
  long double transition, hertz, contact_modulus; // x_t, c, E*
  std::function<long double(long double)> force;  // the fit's F(x), x > x_t
  std::function<long double(long double)> radius; // a(x), the fit's above x_t
};

OdeReference fitted_ode_reference(const FittedLoading& fit, long double m, long double b,
                                  long double V, long steps) {
  using Real = long double;
  using State = std::array<Real, 2>;
  const Real E = fit.contact_modulus, x_t = fit.transition, c = fit.hertz;
  // The branch is chosen by the phase, not by x: the RK stages of a step that ends just
  // below the transition may reach beyond it, and must not see the fit's jump there.
  bool passed = false;
  auto loading = [&](Real x) -> Real {
    if (x <= 0) return 0;
    if (!passed) return c * std::pow(x, 1.5L);
    return fit.force(x);
  };
  auto slope = [&](Real x) { // central difference, ~1e-12 relative: enough for the event
    const Real h = x * 1e-6L;
    if (!passed) return 1.5L * c * std::sqrt(x);
    return (loading(x + h) - loading(std::max(x_t * (1 + 1e-15L), x - h))) /
           (x + h - std::max(x_t * (1 + 1e-15L), x - h));
  };
  bool restoring = false;
  Real k_u = 0, x_r = 0;
  auto spring = [&](Real x) -> Real {
    if (!restoring) return loading(x);
    const Real s = std::max(Real(0), x - x_r);
    return k_u * s * std::sqrt(s);
  };
  auto force = [&](const State& y) { return spring(y[0]) * (1 + b * y[1]); };
  GradedEventIntegration integration(force, m, V,
                                     std::pow(1.25L * m * V * V / c, 0.4L) / V / steps);
  auto& state = integration.state;
  auto& time = integration.time;
  OdeReference r{};
  auto force_rate = [&](const State& y) {
    return slope(y[0]) * y[1] * (1 + b * y[1]) - b * loading(y[0]) * force(y) / m;
  };
  // Compression to rest, stopping at the transition (where the force jumps: the step must
  // not straddle it) and at a force peak on either side of it.
  Real peak = 0;
  bool seek_peak = true;
  while (state[1] > 0) {
    integration.run_to([&](const State& y) {
      Real event = y[1];
      if (!passed) event = std::min(event, x_t - y[0]);
      if (seek_peak) event = std::min(event, force_rate(y));
      return event;
    });
    peak = std::max(peak, force(state));
    if (state[1] <= 0) break;
    if (!passed && state[0] >= x_t * (1 - 1e-15L)) {
      passed = true;
      state[0] = x_t * (1 + 1e-18L);
      peak = std::max(peak, force(state)); // the fit's side of the jump
      seek_peak = force_rate(state) > 0;
      continue;
    }
    seek_peak = false; // stopped at the peak
  }
  r.approach_max = state[0];
  r.compression_time = time;
  peak = std::max(peak, force(state));
  r.force_max = peak;
  // Unloading on R_u that keeps the contact radius, x_r = x_max - 3 P / (4 E* a).
  if (r.approach_max > x_t) {
    const Real P = loading(r.approach_max), a = fit.radius(r.approach_max);
    const Real R_u = 4 * E * a * a * a / (3 * P);
    k_u = 4 * E * std::sqrt(R_u) / 3;
    x_r = r.approach_max - 3 * P / (4 * E * a);
  } else {
    k_u = c;
    x_r = 0;
  }
  restoring = true;
  state[1] = 0;
  const Real x_s = std::max(Real(0), x_r);
  integration.run_to([&](const State& y) { return y[0] - x_s; });
  r.contact_time = time;
  r.rebound_velocity = state[1];
  return r;
}

// Jackson & Green (2005): Hertz to 1.9 omega_c, then the load fit with H_G of JG.m.
FittedLoading jackson_green_loading(const SphereFlatContact& contact) {
  using Real = long double;
  const Real R = contact.radius, E = contact.contact_modulus, Y = contact.yield_strength;
  const Real PI = 3.141592653589793238462643383279502884L;
  const Real C = 1.295L * std::exp(0.736L * Real(contact.poisson_ratio));
  const Real w_c = std::pow(PI * C * Y / (2 * E), 2) * R;
  const Real P_c = 4.0L / 3 * std::pow(R / E, 2) * std::pow(C * PI * Y / 2, 3);
  const Real B = 0.14L * std::exp(23 * Y / E);
  const Real x_t = 1.9L * w_c, c = 4.0L / 3 * E * std::sqrt(R);
  auto radius = [=](Real x) {
    return x <= x_t ? std::sqrt(R * x) : std::sqrt(R * x) * std::pow(x / x_t, B / 2);
  };
  auto force = [=](Real x) {
    const Real w = x / w_c;
    const Real H = 2.84L * (1 - std::exp(-0.82L * std::pow(radius(x) / R, -0.7L)));
    return P_c * (std::exp(-std::pow(w, 5.0L / 12) / 4) * std::pow(w, 1.5L) +
                  4 * H / C * (1 - std::exp(-std::pow(w, 5.0L / 9) / 25)) * w);
  };
  return {x_t, c, E, force, radius};
}

// Ghaednia, Brake, Berryhill & Jackson (2019), linear hardening of tangent modulus E_t, written
// from the paper's equations as transcribed in tmd-lab/microslip-rough-contact
// ROUTINES/FRIC_MODELS/PLASTIC/GHAEDNIA_ET_AL_FLATTENING.m (equation numbers the paper's):
// Eq. 26 in the corrected form that file takes from the authors' implementation (negative,
// exponent 1 - (x - delta_c)/R; the published one is wrong, it says), Eq. 31 without the stray
// factor pi. E_s is the sphere's Young's modulus, E* = contact.contact_modulus (Eq. 3).
FittedLoading ghaednia_loading(const SphereFlatContact& contact, long double E_s, long double E_t) {
  using Real = long double;
  const Real R = contact.radius, E = contact.contact_modulus, Y = contact.yield_strength;
  const Real PI = 3.141592653589793238462643383279502884L;
  const Real C = 1.295L * std::exp(0.736L * Real(contact.poisson_ratio)); // Eq. 6
  const Real strain = PI * C * Y / (2 * E);
  const Real delta_c = strain * strain * R;                                    // Eq. 5
  const Real B = 0.14L * std::exp(23 * Y / E);                                 // Eq. 24
  const Real F_c = 4.0L / 3 * (R / E) * (R / E) * std::pow(C * PI * Y / 2, 3); // Eq. 29
  const Real r = E_t / E_s, s = std::sqrt(E_s / Y);
  auto radius = [=](Real x) {
    const Real w = x / delta_c, a_e = std::sqrt(R * x);                 // Eq. 1
    const Real a_p = R * strain * std::sqrt(w * std::pow(w / 1.9L, B)); // Eq. 23
    const Real upsilon = -2 * s * std::pow(r, 1 - (x - delta_c) / R) /
                         (4 - 3 * std::exp(-2 * s * r)) / (1 - r); // Eq. 26
    return a_e + (a_p - a_e) * std::exp(upsilon);                  // Eq. 25
  };
  auto force = [=](Real x) {
    const Real w = x / delta_c;
    const Real F_e = 4.0L / 3 * std::sqrt(R) * E * std::pow(x, 1.5L);  // Eq. 31
    const Real H = 2.84L - 0.92L * (1 - std::cos(PI * radius(x) / R)); // Eq. 28
    const Real F_p = F_c * (std::exp(-0.25L * std::pow(w, 5.0L / 12)) * std::pow(w, 1.5L) +
                            4 * H / C * (1 - std::exp(-std::pow(w, 5.0L / 9) / 25)) * w); // 27
    return F_p + (F_e - F_p) * (1 - std::exp(-3.3L * r));                                 // Eq. 30
  };
  return {1.9L * delta_c, 4.0L / 3 * E * std::sqrt(R), E, force, radius};
}

// The library against the reference at V/V_y = 3 and 30 and beta = 0, 0.01, 1: e, x_max and
// F_max within 1e-12, the compression and contact times within 1e-10.
void expect_ode_agreement(const Case& c, const FittedLoading& loading) {
  const char* names[] = {"restitution", "approach_max", "force_max", "compression_time",
                         "contact_time"};
  double worst[5] = {};
  for (const double ratio : {3.0, 30.0})
    for (const double beta : {0.0, 0.01, 1.0}) {
      const double velocity = ratio * c.yield_velocity, damping = beta / velocity;
      const auto ours =
          HuntCrossleyElasticPlasticImpact(c.mass, c.spring, damping, velocity).response();
      const OdeReference r = fitted_ode_reference(loading, c.mass, damping, velocity, 20000);
      const std::string at = where(c, ratio, beta);
      const long double e = -r.rebound_velocity / velocity;
      const double errors[] = {
          static_cast<double>(std::fabs(ours.restitution / e - 1)),
          static_cast<double>(std::fabs(ours.approach_max / r.approach_max - 1)),
          static_cast<double>(std::fabs(ours.force_max / r.force_max - 1)),
          static_cast<double>(std::fabs(ours.compression_time / r.compression_time - 1)),
          static_cast<double>(std::fabs(ours.contact_time / r.contact_time - 1))};
      for (int i = 0; i < 5; ++i) {
        EXPECT_LT(errors[i], i < 3 ? 1e-12 : 1e-10) << names[i] << " " << at;
        worst[i] = std::max(worst[i], errors[i]);
      }
    }
  std::cout << "  " << c.name << ": worst relative error of e " << worst[0] << ", x_max "
            << worst[1] << ", F_max " << worst[2] << ", t_comp " << worst[3] << ", t_c " << worst[4]
            << "\n";
}

TEST(HuntCrossleyElasticPlastic, JacksonGreenSpringAgainstAnIndependentIntegration) {
  const SphereFlatContact contact{ball_radius, contact_modulus, yield_strength, 0.3};
  expect_ode_agreement(jackson_green_case(), jackson_green_loading(contact));
}

// Ghaednia with E_t = 0.02 E_s (as test_ghaednia.cpp), E_s = 210 GPa (the steel of E*): x_max
// from 1.04 to 8.7 x_t, x_r > 0 in every case. Measured worst 1.6e-15 (e; 2026-12-05).
TEST(HuntCrossleyElasticPlastic, GhaedniaSpringAgainstAnIndependentIntegration) {
  const SphereFlatContact contact{ball_radius, contact_modulus, yield_strength, 0.3};
  expect_ode_agreement(ghaednia_case(),
                       ghaednia_loading(contact, steel_youngs_modulus, steel_tangent_modulus));
}

// One implementation: on the Hertz spring every figure is HuntCrossleyImpact's.
TEST(HuntCrossleyElasticPlastic, HertzSpringIsHuntCrossley) {
  const Case c = hertz_case();
  const double stiffness = 4.0 / 3.0 * contact_modulus * std::sqrt(ball_radius);
  for (const double velocity : {0.1, 1.0, 10.0})
    for (const double beta : {0.0, 1e-6, 0.05, 0.5, 3.0, 100.0}) {
      const double damping = beta / velocity;
      const auto ours =
          HuntCrossleyElasticPlasticImpact(c.mass, c.spring, damping, velocity).response();
      const auto theirs = HuntCrossleyImpact(c.mass, stiffness, 1.5, damping, velocity).response();
      for (const auto& [a, z] : {std::pair{ours.restitution, theirs.restitution},
                                 {ours.approach_max, theirs.approach_max},
                                 {ours.force_max, theirs.force_max},
                                 {ours.time_force_max, theirs.time_force_max},
                                 {ours.compression_time, theirs.compression_time},
                                 {ours.contact_time, theirs.contact_time}})
        EXPECT_NEAR(a, z, 1e-14 * std::abs(z)) << "V = " << velocity << " beta = " << beta;
    }
}

// Without damping it is the rate-independent impact of the same spring.
TEST(HuntCrossleyElasticPlastic, UndampedIsTheRateIndependentImpact) {
  for (const Case& c : {thornton_case(), jackson_green_case()})
    for (const double ratio : {0.7, 2.0, 20.0, 300.0}) {
      const double velocity = ratio * c.yield_velocity;
      const auto ours =
          HuntCrossleyElasticPlasticImpact(c.mass, c.spring, 0.0, velocity).response();
      const auto theirs = elastic_plastic_impact(c.mass, velocity, *c.spring);
      const std::string at = where(c, ratio, 0);
      EXPECT_NEAR(ours.restitution, theirs.restitution, 1e-12 * theirs.restitution) << at;
      EXPECT_NEAR(ours.approach_max, theirs.approach_max, 1e-13 * theirs.approach_max) << at;
      EXPECT_NEAR(ours.force_max, theirs.force_max, 1e-13 * theirs.force_max) << at;
      EXPECT_NEAR(ours.contact_time, theirs.contact_time, 1e-11 * theirs.contact_time) << at;
      EXPECT_NEAR(ours.separation_approach, theirs.residual_approach, 1e-12 * theirs.approach_max)
          << at;
    }
}

// Both losses: damping lowers e below the spring's own plastic e, and below yield the
// law is Hunt-Crossley's.
TEST(HuntCrossleyElasticPlastic, CarriesBothLosses) {
  const Case c = thornton_case();
  const double stiffness = 4.0 / 3.0 * contact_modulus * std::sqrt(ball_radius);
  const double below = 0.5 * c.yield_velocity, above = 20 * c.yield_velocity;
  const double damping = 0.05 / below;
  EXPECT_NEAR(HuntCrossleyElasticPlasticImpact(c.mass, c.spring, damping, below).restitution(),
              HuntCrossleyImpact(c.mass, stiffness, 1.5, damping, below).restitution(), 1e-14);
  const double plastic =
      HuntCrossleyElasticPlasticImpact(c.mass, c.spring, 0.0, above).restitution();
  const double both =
      HuntCrossleyElasticPlasticImpact(c.mass, c.spring, damping, above).restitution();
  EXPECT_LT(plastic, 1.0);
  EXPECT_LT(both, plastic);
}

TEST(HuntCrossleyElasticPlastic, HistoryEndsAtTheResponseAndRatesMatch) {
  const Case c = thornton_case();
  const double velocity = 10 * c.yield_velocity, damping = 0.2 / velocity;
  const HuntCrossleyElasticPlasticImpact impact(c.mass, c.spring, damping, velocity);
  const auto response = impact.response();
  const auto states = impact.history(41);
  ASSERT_EQ(states.size(), 41u);
  EXPECT_EQ(states.front().approach, 0.0);
  EXPECT_NEAR(states.back().time, response.contact_time, 1e-15 * response.contact_time);
  EXPECT_NEAR(states.back().approach, response.separation_approach, 1e-12 * response.approach_max);
  EXPECT_NEAR(states.back().approach_rate, response.rebound_velocity, 1e-12 * velocity);
  double peak = 0;
  for (std::size_t i = 1; i + 1 < states.size(); ++i) {
    const auto& s = states[i];
    EXPECT_GT(s.time, states[i - 1].time);
    const auto phase =
        s.time <= response.compression_time ? ImpactPhase::compression : ImpactPhase::restitution;
    EXPECT_NEAR(s.approach_rate, impact.approach_rate(s.approach, phase), 1e-9 * velocity)
        << "t = " << s.time;
    EXPECT_NEAR(s.force, impact.force(s.approach, s.approach_rate, phase),
                1e-12 * response.force_max);
    peak = std::max(peak, s.force);
  }
  EXPECT_LE(peak, response.force_max * (1 + 1e-12));
  EXPECT_GT(peak, 0.95 * response.force_max);
}

TEST(HuntCrossleyElasticPlastic, RefusesBadInputNamingTheParameter) {
  const Case c = thornton_case();
  auto refuses = [&](const char* parameter, auto&& make) {
    try {
      make();
      ADD_FAILURE() << "accepted a bad " << parameter;
    } catch (const InvalidInput& error) {
      EXPECT_EQ(error.parameter(), parameter) << error.what();
    }
  };
  refuses("mass", [&] { HuntCrossleyElasticPlasticImpact(0.0, c.spring, 1.0, 1.0); });
  refuses("spring", [&] { HuntCrossleyElasticPlasticImpact(1.0, nullptr, 1.0, 1.0); });
  refuses("damping", [&] { HuntCrossleyElasticPlasticImpact(1.0, c.spring, -1.0, 1.0); });
  refuses("velocity", [&] { HuntCrossleyElasticPlasticImpact(1.0, c.spring, 1.0, NAN); });
  refuses("stiffness", [&] { HertzContact(-1.0); });
  const HuntCrossleyElasticPlasticImpact impact(c.mass, c.spring, 0.1, 10 * c.yield_velocity);
  refuses("approach",
          [&] { impact.approach_rate(2 * impact.approach_max(), ImpactPhase::restitution); });
  refuses("approach", [&] {
    impact.approach_rate(0.5 * impact.separation_approach(), ImpactPhase::restitution);
  });
  refuses("points", [&] { impact.history(1); });
}

} // namespace
