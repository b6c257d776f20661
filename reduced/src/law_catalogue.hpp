#pragma once
// The entries of the comparison-law registry, one function per law (reduced/src/law_*.cpp).
// To add a law: write law_<name>.cpp returning a ComparisonLaw, declare it here and list it
// in comparison_laws() (comparison_laws.cpp).

#include "impact_reduced/comparison_laws.hpp"

namespace impact::reduced::laws {

ComparisonLaw kelvin_voigt();             // law_kelvin_voigt.cpp
ComparisonLaw lankarani_nikravesh();      // law_hertz_damped.cpp (F = c x^n (1 + b x'))
ComparisonLaw flores();                   // law_hertz_damped.cpp
ComparisonLaw gonthier();                 // law_hertz_damped.cpp
ComparisonLaw hu_guo();                   // law_hertz_damped.cpp
ComparisonLaw zhiying_qishao();           // law_hertz_damped.cpp
ComparisonLaw tsuji();                    // law_tsuji.cpp
ComparisonLaw tsuji_clamped();            // law_tsuji.cpp
ComparisonLaw kuwabara_kono();            // law_kuwabara_kono.cpp
ComparisonLaw kuwabara_kono_no_tension(); // law_kuwabara_kono.cpp (separation at F = 0)

} // namespace impact::reduced::laws
