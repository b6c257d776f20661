#pragma once
/// @file
/// What the runs' scenario says about the contact without fitting anything: the Hertz
/// stiffness of the two bodies' elastic constants and the sphere radius, and the dissipative
/// constant A of the viscoelastic-sphere law from their retardation times
/// (reduced::kuwabara_kono_dissipative_constant). Read from the parameters impact-fem stores
/// as text attributes of each run file: "<Body>/Material model" = elastic | kelvin-voigt | ...,
/// "<Body>/<Model>/Young's modulus", ".../Poisson's ratio", ".../Retardation time",
/// ".../Volumetric retardation time" (< 0: the deviatoric one), "Scenario/Sphere radius".
/// An elastic-plastic body's "Retardation time" tau_r is a Kelvin–Voigt stress on the whole
/// strain rate: tau_d = tau_v = tau_r. Retardation times all 0 give no A (no viscous loss).

#include "impact_postprocess/run/fem_run.hpp"
#include "impact_postprocess/run/fem_run_format.hpp"

#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// The published steel example's Hertz stiffness (0.1 kg steel ball on steel, N/m^1.5):
/// the fallback when the runs do not record their materials.
inline constexpr double published_hertz_stiffness = 1.7135e10;

struct ScenarioMaterials {
  double hertz_stiffness;       ///< c_Hertz [N/m^1.5]
  std::string hertz_basis;      ///< where it comes from, in words
  bool hertz_from_runs = false; ///< false: the published fallback
  std::optional<double>
      dissipative_constant; ///< A [s] > 0, when both bodies are Kelvin–Voigt, elastic-plastic with a retardation time, or elastic
  std::string dissipative_basis; ///< the formula's inputs, or why there is no A
};

/// The materials of the first run that records them all.
ScenarioMaterials scenario_materials(const std::vector<FemRun>& runs);

/// A constant of one body's material model, "<Body>/<Model>/<entry>" with <Model> the
/// subsection of the value of "<Body>/Material model" (the FEM's contract names them: e.g.
/// body "Plate", entry fem_format::density reads "Plate/Elastic/Density" for an elastic
/// plate), or none.
std::optional<double> material_constant(const FemRun& run, const std::string& body,
                                        const fem_format::MaterialEntry& entry);

/// A number stored as a text attribute of the run (its parameters), or none.
std::optional<double> text_number(const FemRun& run, const std::string& key);

} // namespace impact::postprocess
