#pragma once
// The impacting sphere and its contact with a flat, as hc and law take them: the stiffness c
// (with the exponent n) and the mass m given directly, or computed from the materials of both
// bodies: c from hertz_stiffness (n = 3/2) of the sphere (E, nu, R) on the flat (E, nu, or
// rigid), m = solid_sphere_mass(R, rho). Each of c and m by one way only.

#include "command_line.hpp"

#include <optional>
#include <string>
#include <vector>

namespace impact::cli {

/// Exactly one of two ways of giving a quantity: UsageError naming both options otherwise,
/// with `what` (the two ways, in words).
void require_one_of(const CommandLine& options, const std::string& direct,
                    const std::string& derived, const std::string& what);

/// The options, for a command's declarations. `exponent_help` describes --exponent.
std::vector<Option> sphere_flat_options(const std::string& exponent_help);

/// The notes of the usage on which options go together.
std::string sphere_flat_notes();

struct SphereFlat {
  double stiffness;          ///< c [N/m^n]
  double exponent;           ///< n [-]
  double mass;               ///< m [kg]
  std::string contact_basis; ///< where c and n come from, in words
  std::string mass_basis;    ///< where m comes from, in words
};

/// Reads c, n and m. `required_exponent`: the command's law is defined for this n only; it is
/// then the default of --exponent, and c cannot come from the materials (Hertz, n = 3/2)
/// unless it is 3/2 (`law_name` names the law in the message). Throws UsageError naming the
/// options that conflict or are missing.
SphereFlat read_sphere_flat(CommandLine& options, const std::string& law_name = "",
                            std::optional<double> required_exponent = std::nullopt);

} // namespace impact::cli
