#ifndef IMPACT_FEM_MATERIALS_INTERNAL_VARIABLES_H
#define IMPACT_FEM_MATERIALS_INTERNAL_VARIABLES_H

#include <impact_fem/cell_strain_operator.h>
#include <impact_fem/materials/interface.h>
#include <impact_fem/output/checkpoint.h>

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
      using VectorType   = TrilinosWrappers::MPI::Vector;
      using CellIterator = typename Triangulation<2>::cell_iterator;
      using States = std::vector<std::shared_ptr<const QuadraturePointState>>;

      /// Relaxed arms and zero plastic strain on every owned cell of a body
      /// with a history; @p material_of maps a cell's material id to its
      /// material. The displacements given later have the layout (owned
      /// and ghost entries) of @p ghosted_layout.
      void
      initialize(
        const DoFHandler<2>                                        &dof_handler,
        const Mapping<2>                                           &mapping,
        const Quadrature<2>                                        &quadrature,
        const std::function<const Interface &(types::material_id)> &material_of,
        const VectorType &ghosted_layout);

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

      /// The plastic force of the last completed step's state [N].
      const VectorType &
      committed_plastic_force() const
      {
        return plastic_force_now;
      }

      /// The start of the next step's iteration: the plastic force
      /// extrapolated linearly from the last two completed steps,
      /// 2 f_p(n) - f_p(n-1) [N] (f_p(n) after the first step).
      const VectorType &
      predicted_plastic_force() const
      {
        return plastic_force_predicted;
      }

      /**
       * plastic_force() visits only the candidate cells: those where a point
       * has yielded or comes within candidate_stress_fraction of its yield
       * stress (chosen at every commit). Far from the contact the bodies stay
       * elastic, and the stress updates there would be most of an
       * iteration's cost. This call makes the screen exact: it computes the
       * states of all points at the converged displacement @p ghosted_trial
       * of the step (distributed, ghosted), to be committed by the next
       * update(), and returns false when a point outside the candidates
       * yielded there; its cell is then a candidate, and the step must be
       * solved again (and prepared again).
       */
      bool
      prepare_commit(const AffineConstraints<double> &constraints,
                     const VectorType                &ghosted_trial,
                     const double                     dt);

      /// Fraction of its yield stress at which a point's cell becomes a
      /// candidate: a margin that only saves repeated steps, since
      /// prepare_commit() makes the screen exact.
      static constexpr double candidate_stress_fraction = 0.5;

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

      /// The states of the owned cells of @p dof_handler (in its order),
      /// the candidate cells, the plastic forces and the energies, at the
      /// end of a step, for a checkpoint.
      void
      save(checkpoint::Writer &writer, const DoFHandler<2> &dof_handler) const;

      /// Reads what save() wrote into the states initialize() made on the
      /// same mesh and partition.
      void
      load(checkpoint::Reader &reader, const DoFHandler<2> &dof_handler);

    private:
      std::function<const Interface &(types::material_id)> material_of;
      CellDataStorage<CellIterator, QuadraturePointState>  storage;
      bool   is_active = false, is_nonlinear = false;
      double dissipated = 0, stored[2] = {0, 0};
      double plastic = 0, plastic_correction[2] = {0, 0},
             max_accumulated[2] = {0, 0};
      VectorType plastic_force_now, plastic_force_predicted;
      // The step prepared by prepare_commit(): its plastic force, work,
      // energy correction and largest accumulated strain, committed by
      // update().
      bool       prepared = false;
      VectorType prepared_force;
      double     prepared_work = 0, prepared_correction[2] = {0, 0},
             prepared_largest[2] = {0, 0};

      // The owned cells of the nonlinear bodies with their strain operators
      // (computed once) and their states.
      struct PlasticCell
      {
        CellIterator                                       cell;
        unsigned int                                       body;
        CellStrainOperator                                 strain;
        std::vector<std::shared_ptr<QuadraturePointState>> states;
        // Visited by plastic_force() (see prepare_commit()), now and
        // from the prepared step on.
        bool candidate, prepared_candidate;
        // The states at the end of the prepared step.
        std::vector<QuadraturePointState> prepared;
      };
      std::vector<PlasticCell> plastic_cells;

      /// The prepared step becomes the state (prepared here first if the
      /// caller did not: then a point outside the candidates must not have
      /// yielded, or the step was solved without it).
      void
      commit_plastic_state(const AffineConstraints<double> &constraints,
                           const VectorType                &displacement,
                           const double                     dt);

      /// force = sum over the plastic cells (the candidates only if
      /// @p candidates_only) of int B^T stress dV, the stress of each point
      /// given by point_stress(cell, q, strain of the ghosted displacement
      /// @p u, stress), which returns false for a point that adds nothing.
      /// (@p cells: plastic_cells, const or not, as the visitor needs.)
      template <typename Cells, typename PointStress>
      static void
      assemble_plastic_points(Cells                           &cells,
                              const AffineConstraints<double> &constraints,
                              const VectorType                &u,
                              const bool                       candidates_only,
                              VectorType                      &force,
                              const PointStress               &point_stress);
    };
  } // namespace materials
} // namespace impact_fem

#endif
