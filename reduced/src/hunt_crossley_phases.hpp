#pragma once
// Private to the reduced library: the pieces of HuntCrossleyImpact's phase integrals shared
// by hunt_crossley.cpp (the impact, its phases and times) and hunt_crossley_history.cpp
// (the states at given times).

#include <functional>
#include <vector>

namespace impact::reduced::detail {

/// Integral of t / (1 + b t) over [lower, lower + width] divided by width [m/s], exact (no
/// cancellation) for small widths; t > -1/b.
double velocity_work_per_width(double damping, double lower, double width);

/// For ascending targets tau_j, the u_j in [0, upper] with integral_0^u_j density = tau_j
/// (Newton from the previous root, safeguarded by bisection; tanh-sinh quadrature).
std::vector<double> invert_cumulative_integral(const std::function<double(double)>& density,
                                               const std::vector<double>& targets, double upper);

} // namespace impact::reduced::detail
