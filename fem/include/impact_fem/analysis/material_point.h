#ifndef IMPACT_FEM_ANALYSIS_MATERIAL_POINT_H
#define IMPACT_FEM_ANALYSIS_MATERIAL_POINT_H

#include <impact_fem/analysis/loading_history.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace impact_fem
{
  using namespace dealii;

  /**
   * `Scenario/Analysis = material point`: the sphere's material at one
   * quadrature point of a homogeneous specimen under a prescribed history,
   * integrated with the same constant-step update as the impact (the
   * material's tangents, internal-variable predictor and update; the
   * trapezoidal rule of the Newmark step for the strain rate):
   *  - `strain ramp`: eps(t) = min(t / t_ramp, 1) eps_hat (relaxation);
   *  - `strain oscillation`: eps(t) = sin(omega t) eps_hat;
   *  - `stress step`: sigma(t) = sigma_hat for t > 0 (creep; needs a
   *    viscous material, e.g. Kelvin-Voigt).
   * Writes `history.h5` (time, strain_* and stress_* in the (r, z, theta)
   * basis, internal_energy, dissipated_energy) to Output/Directory.
   */
  class MaterialPointTest : public loading_history::SerialAnalysis
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

  private:
    void
    run_on_first_rank(ParameterHandler &prm) override;
  };
} // namespace impact_fem

#endif
