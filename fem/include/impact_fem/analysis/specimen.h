#ifndef IMPACT_FEM_ANALYSIS_SPECIMEN_H
#define IMPACT_FEM_ANALYSIS_SPECIMEN_H

#include <impact_fem/analysis/loading_history.h>

#include <deal.II/base/parameter_handler.h>

namespace impact_fem
{
  using namespace dealii;

  /**
   * `Scenario/Analysis = specimen`: the histories of the material point
   * (material_point.h, subsection "Material point") applied to a
   * homogeneous axisymmetric specimen, a cylinder (radius and height 1 mm,
   * deal.II GridGenerator, 2 x 2 cells of the impact's element degree),
   * quasi-static, with the finite-element assembly of the impact: the
   * material's constant tangents (C + internal tangent + 2/dt D, the
   * trapezoidal rule for the strain rate), the Maxwell arms' history as a
   * right-hand side assembled from the quadrature-point states
   * (CellDataStorage) and updated after each step.
   *  - strain histories: the displacement of the homogeneous strain (rr = theta-theta
   *    = eps_hat_rr, zz = eps_hat_zz; the only homogeneous axisymmetric
   *    states) prescribed on the whole boundary;
   *  - `stress step`: uniaxial stress sigma_hat_zz on the top face, bottom
   *    on rollers, side free (creep);
   *  - `axial strain path`: the top face displaced by the axial strain of
   *    `Axial strain path`, bottom on rollers, side free (uniaxial stress: a
   *    tension or compression test).
   * An elastic-plastic material, and any material under the axial strain
   * path, go through the general stress_update() with Newton iterations on
   * the consistent tangent per step (the history adds the mean accumulated
   * plastic strain, the plastic work and the iterations).
   * Writes `history.h5` with the mean strain and stress over the quadrature
   * points (`strain_*`, `stress_*`) and `inhomogeneity` (largest deviation
   * of a quadrature point's stress from the mean, relative to the mean's
   * largest component).
   */
  class SpecimenTest : public loading_history::SerialAnalysis
  {
  public:
    /// The entries are those of the material point (and Mesh/Polynomial
    /// degree).
    static void
    declare_parameters(ParameterHandler &)
    {}

  private:
    void
    run_on_first_rank(ParameterHandler &prm) override;
  };
} // namespace impact_fem

#endif
