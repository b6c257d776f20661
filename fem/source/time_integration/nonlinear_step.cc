#include <impact_fem/as_written.h>
#include <impact_fem/time_integration/nonlinear_step.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <sstream>
#include <vector>

namespace impact_fem
{
  namespace time_integration
  {
    void
    NonlinearStep::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      prm.declare_entry("Strategy",
                        "anderson",
                        Patterns::Selection("anderson|modified newton"),
                        "Iteration of a step with an elastic-plastic body, "
                        "on the elastic factorisation: 'modified newton' "
                        "(initial-stiffness iteration) or 'anderson' (the "
                        "same iteration with Anderson acceleration); the "
                        "default is the faster one measured (fem/README.md).");
      prm.declare_entry("Maximum iterations",
                        "200",
                        Patterns::Integer(1),
                        "Iterations allowed per step [-], >= 1; a step "
                        "that needs more stops the run with an error.");
      prm.declare_entry("Anderson depth",
                        "20",
                        Patterns::Integer(1, 50),
                        "Past iterates mixed by the Anderson acceleration "
                        "[-], in [1, 50]; 20 converges far above yield "
                        "(V/V_y ~ 10^4), where 5 did not "
                        "(fem/bench/plasticity.sh).");
      prm.declare_entry("Residual tolerance",
                        "1e-8",
                        Patterns::Double(0),
                        "Converged when the out-of-balance force is at most "
                        "this fraction of the step's force norm "
                        "||B^T lambda|| + ||f_body|| + ||f_p|| [-], > 0 ...");
      prm.declare_entry("Increment tolerance",
                        "1e-6",
                        Patterns::Double(0),
                        "... and the last displacement correction at most "
                        "this fraction of the step's displacement increment "
                        "[-], > 0.");
      prm.leave_subsection();
    }


    void
    NonlinearStep::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Nonlinear solver");
      strategy            = prm.get("Strategy");
      max_iterations      = prm.get_integer("Maximum iterations");
      depth               = prm.get_integer("Anderson depth");
      residual_tolerance  = prm.get_double("Residual tolerance");
      increment_tolerance = prm.get_double("Increment tolerance");
      prm.leave_subsection();
      AssertThrow(residual_tolerance > 0 && increment_tolerance > 0,
                  ExcMessage("Nonlinear solver/Residual tolerance and "
                             "Increment tolerance must be > 0, got " +
                             as_written(residual_tolerance) + " and " +
                             as_written(increment_tolerance) + "."));
    }


    std::string
    NonlinearStep::criterion() const
    {
      std::ostringstream s;
      s << "||r|| <= " << residual_tolerance
        << " (||B^T lambda|| + ||f_body|| + ||f_p||) and ||du|| <= "
        << increment_tolerance << " ||u - u_n|| within " << max_iterations
        << " iterations (Nonlinear solver/Residual tolerance, Increment "
           "tolerance, Maximum iterations; strategy "
        << strategy << ")";
      return s.str();
    }


    namespace
    {
      using VectorType = NonlinearStep::VectorType;

      /**
       * Iterations without a new smallest residual after which Anderson's
       * history is cleared. The map is only piecewise smooth (points that
       * yield or unload, contact nodes that enter or leave), and a history
       * that spans a change of these sets can keep the iteration wandering:
       * on the coarse verification level of AISI 304 on 6061-T6 at 5 m/s
       * (contact surface refined three times, V/V_y = 416) one step just
       * after the force peak took 251 iterations without a restart, its
       * residual between 5e-6 and 2e-4 of the load for 230 of them;
       * restarted after 20 iterations without progress it took 142, after
       * 10 it took 116, every other step of the run unchanged
       * (doc/results/fem-model.md). PETSc's Anderson (SNESANDERSON) offers
       * restarts for the same reason (-snes_anderson_restart_type).
       */
      constexpr unsigned int stagnation_window = 10;

      /**
       * Anderson's mixing of depth m (Walker & Ni's algorithm AA): the next
       * plastic force is the map value g minus the combination of the last m
       * map-value differences whose residual differences best cancel the
       * residual r.
       */
      class AndersonMixing
      {
      public:
        explicit AndersonMixing(const unsigned int depth)
          : depth(depth)
        {}

        /// The force of the next iteration from this iteration's residual
        /// @p r and map value @p g.
        void
        next_force(const VectorType &r, const VectorType &g, VectorType &x);

        /// Forget the history: the next force is the map value alone.
        void
        restart()
        {
          first = true;
          dR.clear();
          dG.clear();
          gram.clear();
        }

      private:
        /// The differences to the previous iteration join the history, the
        /// oldest leaving beyond the depth.
        void
        add_differences(const VectorType &r, const VectorType &g);

        /// x -= dG gamma, gamma = argmin ||r - dR gamma||.
        void
        mix(const VectorType &r, VectorType &x) const;

        const unsigned int depth;
        bool               first = true;
        // Differences of the last m residuals and map values (Walker & Ni's
        // Delta F and Delta G), oldest first, and the Gram matrix of the
        // residual differences, gram[i][j] = dR[i] . dR[j]: each difference
        // enters it once (m products per iteration instead of m^2 / 2, each
        // a global reduction), with the same products as a fresh
        // computation.
        std::deque<VectorType>          dR, dG;
        std::deque<std::vector<double>> gram;
        VectorType                      last_r, last_g;
      };


      void
      AndersonMixing::next_force(const VectorType &r,
                                 const VectorType &g,
                                 VectorType       &x)
      {
        if (!first)
          add_differences(r, g);
        first  = false;
        last_r = r;
        last_g = g;
        x      = g;
        if (!dR.empty())
          mix(r, x);
      }


      void
      AndersonMixing::add_differences(const VectorType &r, const VectorType &g)
      {
        last_r.sadd(-1., 1., r); // r_k - r_{k-1}
        last_g.sadd(-1., 1., g);
        if (dR.size() == depth)
          {
            dR.pop_front();
            dG.pop_front();
            gram.pop_front();
            for (auto &row : gram)
              row.erase(row.begin());
          }
        std::vector<double> row(dR.size() + 1);
        for (unsigned int j = 0; j < dR.size(); ++j)
          {
            row[j] = dR[j] * last_r;
            gram[j].push_back(row[j]);
          }
        row.back() = last_r * last_r;
        gram.push_back(std::move(row));
        dR.push_back(last_r);
        dG.push_back(last_g);
      }


      // The normal equations, with a relative regularisation against nearly
      // dependent differences.
      void
      AndersonMixing::mix(const VectorType &r, VectorType &x) const
      {
        const unsigned int n = dR.size();
        FullMatrix<double> A(n, n);
        Vector<double>     b(n), gamma(n);
        double             largest = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            b(i) = dR[i] * r;
            for (unsigned int j = 0; j <= i; ++j)
              A(i, j) = A(j, i) = gram[i][j];
            largest = std::max(largest, A(i, i));
          }
        for (unsigned int i = 0; i < n; ++i)
          A(i, i) += 1e-12 * largest;
        A.gauss_jordan();
        A.vmult(gamma, b);
        for (unsigned int i = 0; i < n; ++i)
          x.add(-gamma(i), dG[i]);
      }
    } // namespace


    NonlinearStep::Result
    NonlinearStep::solve(const VectorType   &start_force,
                         const VectorType   &u_start,
                         VectorType         &u,
                         const LinearSolve  &linear_solve,
                         const PlasticForce &plastic_force) const
    {
      const bool     anderson = strategy == "anderson";
      AndersonMixing mixing(depth);
      Result         result;
      VectorType     x(start_force), g(start_force), r(start_force),
        previous_u(u_start), step(u_start);

      // The smallest residual so far and the iterations since it was set.
      double       smallest = std::numeric_limits<double>::max();
      unsigned int since    = 0;
      for (unsigned int k = 1; k <= max_iterations; ++k)
        {
          // The reference force: the external forces and the plastic force;
          // after the bodies separate the external forces vanish, and a
          // round-off residual could never meet a criterion relative to them.
          double load = linear_solve(x, u);
          plastic_force(u, g);
          load += g.l2_norm();
          r = g;
          r -= x;
          result.iterations = k;
          result.residual   = r.l2_norm() / std::max(load, 1e-300);
          step              = u;
          step -= u_start;
          const double scale = step.l2_norm();
          previous_u -= u;
          result.increment =
            k == 1 ? 0. : previous_u.l2_norm() / std::max(scale, 1e-300);
          previous_u = u;
          if (r.l2_norm() <= residual_tolerance * load &&
              (k == 1 || result.increment <= increment_tolerance))
            {
              result.converged = true;
              return result;
            }

          // Next plastic force: g (modified Newton) or Anderson's mixing,
          // restarted when it stagnates.
          if (result.residual < smallest)
            smallest = result.residual, since = 0;
          else if (++since == stagnation_window)
            mixing.restart(), since = 0;
          if (anderson)
            mixing.next_force(r, g, x);
          else
            x = g;
        }
      return result;
    }
  } // namespace time_integration
} // namespace impact_fem
