#pragma once
/// @file
/// Which family of contact laws the FEM's restitution follows in which velocity range: the
/// elastic and viscoelastic families (by the slope of 1 - e against V in log-log,
/// velocity_trend.hpp: Hunt–Crossley 1, Kuwabara–Kono 1/5, constant e 0), and the plastic one
/// (by the slope of e against V, -1/4 far above the yield velocity: Thornton 1997 as derived
/// in reduced/thornton.hpp). With a yield velocity V_y (an elastic-plastic material) the runs
/// are split there: below V_y the elastic/viscoelastic families are the candidates (and
/// "elastic" when 1 - e stays below elastic_loss_limit at every run), above V_y the plastic
/// family against a constant e. The plastic family's reference slope is -1/4 far above V_y;
/// nearer V_y the plastic laws themselves are shallower (Thornton -0.16 at 1.2-3 V_y), so when
/// plastic laws are given (their e at the same velocities) the reference is the band between
/// their own slopes over the range, and -1/4 otherwise; the range follows the plastic family
/// when its slope is nearer that reference than 0 (a constant e). Without V_y (a material
/// without plasticity) all runs form one range judged against the elastic/viscoelastic
/// families only.

#include "impact_postprocess/models/velocity_trend.hpp"

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// Below this 1 - e at every run a range is called elastic (the FEM's own numerical
/// dissipation and wave radiation of a rigid-flat impact stay below it).
inline constexpr double elastic_loss_limit = 0.01;

/// How a range's family was decided.
enum class FamilyBasis {
  elastic,  ///< 1 - e below elastic_loss_limit at every run
  no_trend, ///< fewer than two runs with 0 < e < 1 at two velocities
  plastic,  ///< above V_y: the slope of e against the plastic band and a constant e
  nearest   ///< the slope of 1 - e against the elastic/viscoelastic reference slopes
};

/// A plastic law's slope of e against V over a range (its own reference of the family).
struct LawSlope {
  std::string law;
  double slope;
};

struct FamilyRange {
  double low, high;   ///< velocities of the first and last run of the range [m/s]
  std::size_t runs;   ///< runs in the range
  bool above_yield;   ///< the range lies above V_y
  std::string family; ///< "elastic", "plastic", "Hunt–Crossley (constant b)", ...
  /// The slope that decided: of ln e (plastic against constant e) or of ln(1 - e) (the
  /// elastic/viscoelastic families); NaN when the range has one run or no 0 < e < 1.
  double slope;
  std::string slope_of;               ///< "e" or "1 - e"
  std::optional<PowerLawTrend> trend; ///< with its interval (three runs or more)
  /// The plastic family's reference slopes of e over the range (above V_y): the band between
  /// the given plastic laws' own slopes, or -1/4 for both without them.
  double plastic_low = plastic_restitution_slope, plastic_high = plastic_restitution_slope;
  FamilyBasis basis = FamilyBasis::no_trend;
  bool plastic_possible = false; ///< a yield velocity was given (the material can yield)
  double largest_loss = 0;       ///< the largest 1 - e of the range's runs
  /// The slope of 1 - e and its fit (both bases plastic and nearest; the same as slope and
  /// trend for nearest).
  double loss_slope = std::numeric_limits<double>::quiet_NaN();
  std::optional<PowerLawTrend> loss_trend;
  std::vector<LawSlope> law_slopes; ///< the plastic laws' slopes (basis plastic)
  double reference_slope = std::numeric_limits<double>::quiet_NaN(); ///< the nearest's (nearest)
};

/// A plastic law's restitution at the runs' velocities (parallel to them).
struct PlasticReference {
  std::string law;
  std::vector<double> restitution;
};

/// The ranges of runs at `velocity` [m/s] with restitution `restitution` (parallel, any
/// order); `yield_velocity` V_y [m/s] splits them, none: one range. Empty without runs.
std::vector<FamilyRange> family_ranges(const std::vector<double>& velocity,
                                       const std::vector<double>& restitution,
                                       std::optional<double> yield_velocity, double level = 0.95,
                                       const std::vector<PlasticReference>& plastic_laws = {});

} // namespace impact::postprocess
