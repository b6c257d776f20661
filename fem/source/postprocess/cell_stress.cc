#include <impact_fem/impact_problem.h>
#include <impact_fem/postprocess/cell_stress.h>

#include <deal.II/fe/fe_values.h>

namespace impact_fem
{
  namespace postprocess
  {
    CellStress::CellStress(
      const ImpactProblem                             &problem,
      const std::function<bool(const CellIterator &)> &selected)
    {
      AssertThrow(problem.ghosted_displacement().trilinos_partitioner().SameAs(
                    problem.ghosted_velocity().trilinos_partitioner()),
                  ExcInternalError());
      FEValues<2> fe_values(problem.geometric_mapping(),
                            problem.dofs().get_fe(),
                            problem.cell_quadrature(),
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
      std::vector<types::global_dof_index> dofs(
        problem.dofs().get_fe().n_dofs_per_cell());
      for (const auto &cell : problem.dofs().active_cell_iterators())
        if (cell->is_locally_owned() && selected(cell))
          {
            fe_values.reinit(cell);
            cell->get_dof_indices(dofs);
            cells.push_back(
              {cell,
               CellStrainOperator(fe_values,
                                  dofs,
                                  problem.ghosted_displacement())});
          }
    }


    void
    CellStress::evaluate(
      const ImpactProblem &problem,
      const std::function<void(const CellIterator &,
                               const std::vector<Point<2>> &,
                               const std::vector<SymmetricTensor<2, 3>> &)>
        &visit) const
    {
      std::vector<double>                local_u, local_v;
      std::vector<SymmetricTensor<2, 3>> stress;
      for (const auto &[cell, B] : cells)
        {
          const auto &material = problem.material_of(cell->material_id());
          const auto  C        = material.stiffness_tangent();
          const auto  D        = material.damping_tangent();
          const bool  viscous  = D.norm() > 0;
          const auto  states   = problem.internal_variables().states(cell);
          B.gather(problem.ghosted_displacement(), local_u);
          if (viscous)
            B.gather(problem.ghosted_velocity(), local_v);
          stress.resize(B.n_points());
          for (unsigned int q = 0; q < B.n_points(); ++q)
            {
              stress[q] = C * B.strain(q, local_u);
              if (viscous)
                stress[q] += D * B.strain(q, local_v);
              if (!states.empty())
                stress[q] += material.internal_stress(states[q]->internal) -
                             C * states[q]->plastic_strain;
            }
          visit(cell, B.quadrature_points(), stress);
        }
    }
  } // namespace postprocess
} // namespace impact_fem
