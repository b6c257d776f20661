#pragma once
// The ranges of the physical quantities that the subcommands of impact-reduced accept, one
// place for all of them. The library takes any finite positive number, but far outside these
// ranges its closed forms and integrations overflow, underflow or stall; within them every
// subcommand gives finite results (tests/reduced/test_cli_fuzz.cpp draws at their ends). They
// are wide: from nanometre particles to metre-sized bodies and beyond, from soft foams to
// diamond. A quantity computed from others (a mass from radius and density, c from the
// materials) is held to the range of the option that would give it directly.

#include "command_line.hpp"

namespace impact::cli::ranges {

inline Range mass() {
  return Range::closed(1e-15, 1e6);
} // kg
inline Range velocity() {
  return Range::closed(1e-6, 1e4);
} // m/s
inline Range stiffness() {
  return Range::closed(1e-3, 1e20);
} // c, N/m^n
inline Range exponent() {
  return Range::closed(0.5, 4.0);
} // n
/// n of a thin-plate impact: the exponents of its verification (thin_plate.hpp, rigid limit
/// for n in {1, 1.5, 2.5}); below about 0.8 the sphere may not leave the plate.
inline Range plate_exponent() {
  return Range::closed(1.0, 2.5);
}
inline Range damping() {
  return Range::closed(0.0, 1e6);
} // b, s/m
inline Range modulus() {
  return Range::closed(1e3, 1e13);
} // Young's modulus, Pa
inline Range poisson() {
  return Range::open(-1.0, 0.5);
} // Poisson's ratio
inline Range radius() {
  return Range::closed(1e-9, 1e3);
} // m
inline Range density() {
  return Range::closed(0.1, 1e5);
} // kg/m^3
inline Range yield_strength() {
  return Range::closed(1e3, 1e11);
} // Pa
inline Range thickness() {
  return Range::closed(1e-6, 1e3);
} // m
inline Range restitution() {
  return Range::closed(1e-6, 1.0);
} // e
inline Range stiffness_c1() {
  return Range::closed(1e-6, 1e15);
} // oscillator c1, N/m
inline Range stiffness_c2() {
  return Range::closed(-1e15, 1e15);
} // c2, N/m^(v+1)
inline Range viscous() {
  return Range::closed(0.0, 1e12);
} // k, N s/m
inline Range power() {
  return Range::closed(0.0, 10.0);
} // v
inline Range amplitude() {
  return Range::closed(1e-12, 1e3);
} // a0, m

/// Largest impact parameter beta = b V of an impact (hc): the times are accurate to 1e-12 up
/// to it (hunt_crossley.hpp); the restitution is then about 1e-3.
constexpr double largest_impact_parameter = 1e3;

/// Largest Zener lambda of a thin-plate impact: the range over which its integration is
/// verified (thin_plate.hpp: energy balance for lambda in [1e-3, 200]); beyond it the
/// restitution falls below the integration's accuracy (about 1e-13 at lambda = 330) and the
/// sphere may not leave the plate within the step limit.
constexpr double largest_zener_lambda = 200;

/// The elastic-plastic laws (plastic) are fits and closed forms for small strains: a yield
/// strain Y/E* of at most this (metals 1e-3 to 1e-2, polymers a few 1e-2; beyond it the
/// Jackson-Green contact radius grows as (omega*)^(0.07 exp(23 Y/E*)) and overflows) ...
constexpr double largest_yield_strain = 0.05;
/// ... and a maximum approach of at most this fraction of the radius.
constexpr double largest_approach_ratio = 0.5;

} // namespace impact::cli::ranges
