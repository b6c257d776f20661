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
    /// Strain and internal variables at one quadrature point at the end of
    /// the last completed step.
    struct QuadraturePointState
    {
      SymmetricTensor<2, 3>              strain;
      std::vector<SymmetricTensor<2, 3>> internal;
    };


    /**
     * The internal variables (Maxwell arms) of the bodies that have them, on
     * the locally owned cells: advanced after every step along the strain
     * path of the step (exactly, Interface::update_internal_variables), with
     * the energy they dissipate and store, and the force their history
     * contributes to the next step's right-hand side,
     * int B^T internal_stress_predictor dV.
     */
    class InternalVariables
    {
    public:
      using VectorType = TrilinosWrappers::MPI::Vector;
      using CellIterator = typename Triangulation<2>::cell_iterator;
      using States = std::vector<std::shared_ptr<const QuadraturePointState>>;

      /// Relaxed arms on every owned cell of a body with internal variables;
      /// @p material_of maps a cell's material id to its material.
      void
      initialize(const Triangulation<2> &triangulation,
                 const Quadrature<2>    &quadrature,
                 const std::function<const Interface &(types::material_id)> &material_of);

      /// Any states at all (a body with internal variables exists).
      bool
      active() const
      {
        return is_active;
      }

      /**
       * Advance to the end of a step of length @p dt, the displacement
       * (distributed, ghosted) at its end given; @p predictor_force becomes
       * the history force of the next step.
       */
      void
      update(const DoFHandler<2>             &dof_handler,
             const Mapping<2>                &mapping,
             const Quadrature<2>             &quadrature,
             const AffineConstraints<double> &constraints,
             const VectorType                &ghosted_displacement,
             const double                     dt,
             VectorType                      &predictor_force);

      /// The states of a cell (empty for a body without internal variables).
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
      bool   is_active = false;
      double dissipated = 0, stored[2] = {0, 0};
    };
  } // namespace materials
} // namespace impact_fem

#endif
