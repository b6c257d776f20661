#ifndef IMPACT_FEM_MATERIALS_INTERNAL_VARIABLES_H
#define IMPACT_FEM_MATERIALS_INTERNAL_VARIABLES_H

#include <impact_fem/materials/interface.h>

#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <vector>

namespace impact_fem
{
  namespace materials
  {
    /**
     * The history of the quadrature points of the bodies that have one, on
     * the locally owned cells: the Maxwell arms of a linear model with
     * memory and the plastic state of a nonlinear (elastic-plastic) model.
     *
     * Maxwell arms are advanced after every step along the strain path of
     * the step (exactly, Interface::update_internal_variables), with the
     * energy they dissipate and store, and the force their history
     * contributes to the next step's right-hand side,
     * int B^T internal_stress_predictor dV.
     *
     * A nonlinear model writes sigma = C : (eps - eps^p(eps)): the time step
     * keeps the elastic stiffness and sees plasticity as the force
     *   f_p(u) = int B^T C : eps^p(eps(u)) dV
     * (plastic_force(), a trial that commits nothing), whose value at the
     * converged displacement becomes the state by update().
     */
    class InternalVariables
    {
    public:
      using VectorType = TrilinosWrappers::MPI::Vector;
      using CellIterator = typename Triangulation<2>::cell_iterator;
      using States = std::vector<std::shared_ptr<const QuadraturePointState>>;

      /// Relaxed arms and zero plastic strain on every owned cell of a body
      /// with a history; @p material_of maps a cell's material id to its
      /// material. The displacements given later have the layout (owned
      /// and ghost entries) of @p ghosted_layout.
      void
      initialize(const DoFHandler<2>   &dof_handler,
                 const Mapping<2>      &mapping,
                 const Quadrature<2>   &quadrature,
                 const std::function<const Interface &(types::material_id)> &material_of,
                 const VectorType      &ghosted_layout);

      /// A body with a nonlinear stress (elastic-plastic) exists: the
      /// step must iterate on plastic_force().
      bool
      nonlinear() const
      {
        return is_nonlinear;
      }

      /**
       * The plastic force f_p(u) = int B^T C : eps^p dV of a trial
       * displacement @p ghosted_trial (distributed, ghosted) at the end of a
       * step of length @p dt, eps^p from the stress update of the states of
       * the last completed step. Nothing is committed.
       */
      void
      plastic_force(const AffineConstraints<double> &constraints,
                    const VectorType                &ghosted_trial,
                    const double                     dt,
                    VectorType                      &force) const;

      /// The plastic force of the last completed step's state (the start
      /// of the next step's iteration) [N].
      const VectorType &
      committed_plastic_force() const
      {
        return plastic_force_now;
      }

      /// Cumulative plastic work int sigma : d eps^p over both bodies and
      /// all ranks [J] (trapezoidal in the stress over each step: the work
      /// that closes the average-acceleration rule's energy identity).
      double
      plastic_work() const
      {
        return plastic;
      }

      /// Elastic energy of a body that 1/2 u^T K u leaves out for its
      /// plastic strain, int (1/2 eps^p:C:eps^p - eps^p:C:eps) dV [J].
      double
      plastic_energy_correction(const unsigned int body) const
      {
        return plastic_correction[body];
      }

      /// Largest accumulated plastic strain of a body, all ranks [-].
      double
      max_accumulated_plastic_strain(const unsigned int body) const
      {
        return max_accumulated[body];
      }

      /// Any states at all (a body with internal variables exists).
      bool
      active() const
      {
        return is_active;
      }

      /**
       * Advance to the end of a step of length @p dt, the displacement
       * (distributed, ghosted) at its end given; @p predictor_force becomes
       * the history force of the next step, committed_plastic_force() the
       * plastic force of the new state.
       */
      void
      update(const DoFHandler<2>             &dof_handler,
             const Mapping<2>                &mapping,
             const Quadrature<2>             &quadrature,
             const AffineConstraints<double> &constraints,
             const VectorType                &ghosted_displacement,
             const double                     dt,
             VectorType                      &predictor_force);

      /// The states of a cell (empty for a body without a history).
      States
      states(const CellIterator &cell) const;

      /// Energy dissipated in the arms since the start, all ranks [J].
      double
      dissipated_energy() const
      {
        return dissipated;
      }

      /// Elastic energy stored in the arms of a body now, all ranks [J].
      double
      stored_energy(const unsigned int body) const
      {
        return stored[body];
      }

    private:
      std::function<const Interface &(types::material_id)> material_of;
      CellDataStorage<CellIterator, QuadraturePointState>  storage;
      bool   is_active = false, is_nonlinear = false;
      double dissipated = 0, stored[2] = {0, 0};
      double plastic = 0, plastic_correction[2] = {0, 0},
             max_accumulated[2] = {0, 0};
      VectorType plastic_force_now;

      // The owned cells of the nonlinear bodies with their strain operators,
      // computed once (the higher-order mapping is costly to re-evaluate in
      // every iteration): strain[(4 q + c) n + i] is component c (rr, zz,
      // theta-theta, rz) of the strain of shape function i at point q.
      struct PlasticCell
      {
        CellIterator                         cell;
        unsigned int                         body;
        std::vector<types::global_dof_index> dofs;
        std::vector<int>                     local_index;
        std::vector<double>                  strain, volume;
      };
      std::vector<PlasticCell> plastic_cells;

      /// Advance the plastic states to the displacement at the end of the
      /// step (the converged iterate): work, energy, plastic force.
      void
      commit_plastic_state(const AffineConstraints<double> &constraints,
                           const VectorType                &displacement,
                           const double                     dt);

      /// cell_force += B_q^T stress (stress already weighted by dV).
      static void
      add_strain_transpose(const PlasticCell           &c,
                           const unsigned int           q,
                           const SymmetricTensor<2, 3> &stress,
                           Vector<double>              &cell_force);

      /// The strain of point q of a plastic cell from the cell's values.
      static SymmetricTensor<2, 3>
      strain_at(const PlasticCell &c, const unsigned int q, const double *values);

      /// Visit the points of the plastic cells with the strain of the
      /// ghosted displacement @p u there: visit(cell, q, strain).
      template <typename Visitor>
      void
      for_each_plastic_point(const VectorType &u, const Visitor &visit) const;
    };
  } // namespace materials
} // namespace impact_fem

#endif
