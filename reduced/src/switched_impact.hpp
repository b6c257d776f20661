#pragma once
// integrate_impact for a law that changes at the maximum approach (an elastic-plastic
// spring's unloading branch depends on x_max): one integration instead of two. Internal to
// the library (kuwabara_kono_elastic_plastic.cpp, for springs that are not Hertz's below their
// first breakpoint; the others go by kuwabara_kono_stretch_root.hpp).
//
// The impact is integrated with `loading` until the step in which x' changes sign; there x_max
// is located, that step ends at it (x' = 0 exactly), and the integration goes on from it with
// at_maximum(x_max). The law's slope changes at x_max, so no step holds that kink. The
// result is the integration with the switched law from t = 0 split at x_max, as long as the two
// laws agree while x' >= 0, without the first integration that found x_max.

#include "impact_reduced/impact_ode.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace impact::reduced::detail {

/// The law from the maximum approach on, given x_max [m].
using LawAtMaximum = std::function<ContactForceLaw(double approach_max)>;

/// As integrate_impact, the law switched at x_max.
OdeImpactResult integrate_switched_impact(double mass, double velocity,
                                          const ContactForceLaw& loading,
                                          const LawAtMaximum& at_maximum, double relative_tolerance,
                                          ContactEnd end);

/// As integrate_impact_history, the law switched at x_max.
std::vector<ImpactSample> integrate_switched_impact_history(
    double mass, double velocity, const ContactForceLaw& loading, const LawAtMaximum& at_maximum,
    std::size_t points, double relative_tolerance, ContactEnd end);

} // namespace impact::reduced::detail
