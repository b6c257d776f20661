#ifndef IMPACT_FEM_TIME_INTEGRATION_NONLINEAR_STEP_H
#define IMPACT_FEM_TIME_INTEGRATION_NONLINEAR_STEP_H

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <functional>
#include <string>

namespace impact_fem
{
  namespace time_integration
  {
    using namespace dealii;

    /**
     * The iteration of one implicit time step of bodies with a plastic
     * stress sigma = C : (eps - eps^p(eps)), around the contact solver.
     *
     * The step's equation for the displacement u at the end of the step is
     *   K_eff u = b + f_p(u) + B^T lambda,  lambda the contact pressures,
     * with K_eff the ELASTIC effective stiffness (factorised once, its
     * contact influence vectors and Delassus matrix computed once), b the
     * right-hand side of the linear scheme and f_p(u) = int B^T C : eps^p dV
     * the plastic force. Every iteration solves the linear problem with
     * contact exactly for a given plastic force f (one back-substitution and
     * one linear complementarity problem): u = S(f). Its out-of-balance force
     * is r = f_p(S(f)) - f. Strategies:
     *  - "modified newton": f_{k+1} = f_p(u_k), the initial-stiffness
     *    iteration (modified Newton on the elastic tangent);
     *  - "anderson": the same fixed-point map accelerated by Anderson
     *    mixing of depth m (Anderson 1965; Walker & Ni 2011, SIAM J. Numer.
     *    Anal. 49, 1715-1735, algorithm AA with the unconstrained least
     *    squares form), its history cleared when the iteration stagnates
     *    (nonlinear_step.cc says when and why).
     * Convergence (both): ||r_k|| <= residual tolerance * load_k, with load_k
     * = ||B^T lambda_k|| + ||f_body|| + ||f_p(u_k)||, the norms of the
     * external forces of the step and of the plastic force (which keeps the
     * reference finite after the bodies separate, where the external forces
     * vanish and a round-off residual could never meet the criterion), and ||u_k - u_{k-1}|| <= increment tolerance * ||u_k - u_n|| (the
     * increment criterion is void at the first iteration, whose residual
     * zero means an exact solution). Not converging in the maximum number of
     * iterations is an error.
     */
    class NonlinearStep
    {
    public:
      using VectorType = TrilinosWrappers::MPI::Vector;

      /// Entries of the subsection "Nonlinear solver".
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm);

      /// u = S(f) for the plastic force f; returns the step's load norm.
      using LinearSolve =
        std::function<double(const VectorType &f, VectorType &u)>;
      /// f_p(u) for a displacement u (owned entries).
      using PlasticForce =
        std::function<void(const VectorType &u, VectorType &f)>;

      struct Result
      {
        unsigned int iterations = 0;
        double       residual   = 0; // ||r|| / load of the accepted iterate
        double       increment  = 0; // ||u_k - u_{k-1}|| / ||u_k - u_n||
        bool         converged  = false;
      };

      /**
       * Iterate from the plastic force @p start_force (that of the state at
       * the start of the step) to the displacement @p u; @p u_start is the
       * displacement at the start of the step. Does not throw: the caller
       * reports a failure (it knows the time and the step).
       */
      Result
      solve(const VectorType   &start_force,
            const VectorType   &u_start,
            VectorType         &u,
            const LinearSolve  &linear_solve,
            const PlasticForce &plastic_force) const;

      /// The convergence criterion, in words, for messages.
      std::string
      criterion() const;

      unsigned int
      maximum_iterations() const
      {
        return max_iterations;
      }

    private:
      std::string  strategy            = "anderson";
      unsigned int max_iterations      = 100;
      unsigned int depth               = 5;
      double       residual_tolerance  = 1e-8;
      double       increment_tolerance = 1e-6;
    };
  } // namespace time_integration
} // namespace impact_fem

#endif
