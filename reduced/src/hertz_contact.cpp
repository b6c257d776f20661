#include "impact_reduced/hertz_contact.hpp"

#include "impact_reduced/invalid_input.hpp"

#include <cmath>

namespace impact::reduced {

HertzContact::HertzContact(double stiffness) : stiffness_(stiffness) {
  require_positive("stiffness", stiffness);
}

double HertzContact::loading_force(double approach) const {
  return stiffness_ * approach * std::sqrt(approach);
}

double HertzContact::loading_work(double approach) const {
  return 0.4 * loading_force(approach) * approach;
}

double HertzContact::loading_stiffness(double approach) const {
  return 1.5 * stiffness_ * std::sqrt(approach);
}

std::pair<double, double> HertzContact::loading_force_and_stiffness(double approach) const {
  const double root = std::sqrt(approach);
  return {stiffness_ * approach * root, 1.5 * stiffness_ * root};
}

double HertzContact::loading_approach(double work) const {
  if (!(work > 0)) return 0.0;
  return std::pow(2.5 * work / stiffness_, 0.4);
}

double HertzContact::loading_work_below(double approach_max, double distance) const {
  return detail::hertz_work_below(stiffness_, approach_max, distance);
}

HertzianUnloading HertzContact::unloading(double approach_max) const {
  require_positive("approach_max", approach_max);
  return {stiffness_, 0.0};
}

} // namespace impact::reduced
