#ifndef IMPACT_FEM_TIME_INTEGRATION_NEWMARK_H
#define IMPACT_FEM_TIME_INTEGRATION_NEWMARK_H

#include <deal.II/base/parameter_handler.h>

namespace impact_fem
{
  using namespace dealii;

  /**
   * Newmark's method for M a + C v + K u = f, written for the displacement
   * at the end of the step:
   *   (K + c_M M + c_C C) u_{n+1} = f_{n+1} + M (c_M u + c_v v + c_a a)_n
   *                                         + C (c_C u + d_v v + d_a a)_n.
   * The default (beta, gamma) = (1/4, 1/2) is the average-acceleration rule:
   * unconditionally stable, second order and free of numerical dissipation,
   * so its discrete energy balance is exact for the linear part and the only
   * energy error left is the work of the contact forces (measured).
   *
   * The time step follows the contact: dt = (Hertz contact time) / (steps
   * per contact time), constant over the run so that the effective stiffness
   * is factorised once.
   */
  class Newmark
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /// Fix the step from the Hertz estimate of the contact time [s].
    void
    set_time_step(const double hertz_contact_time);

    double beta  = 0.25;
    double gamma = 0.5;
    double time_step = 0;             ///< [s]
    double steps_per_contact_time = 0; ///< [-]
    double prescribed_time_step = 0;  ///< [s], 0: from steps_per_contact_time
    double time_after_separation = 0; ///< fraction of the contact time [-]
    double maximum_time = 0;          ///< [s], 0: automatic

    // Coefficients of the update, see the class documentation; after the
    // solve a_{n+1} = c_M (u_{n+1} - u_n) - c_v v_n - c_a a_n and
    // v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1}).
    double c_M = 0, c_C = 0, c_v = 0, c_a = 0, d_v = 0, d_a = 0;
  };
} // namespace impact_fem

#endif
