#include <impact_fem/axisymmetric_strain.h>
#include <impact_fem/impact_problem.h>
#include <impact_fem/postprocess/cell_stress.h>

#include <deal.II/fe/fe_values.h>

#include <Epetra_MultiVector.h>

namespace impact_fem
{
  namespace postprocess
  {
    double
    von_mises(const SymmetricTensor<2, 3> &stress)
    {
      const SymmetricTensor<2, 3> s = deviator(stress);
      return std::sqrt(1.5 * scalar_product(s, s));
    }


    CellStress::CellStress(const ImpactProblem &problem,
                           const std::function<bool(const CellIterator &)> &selected)
    {
      const auto  &fe         = problem.dofs().get_fe();
      const auto  &quadrature = problem.cell_quadrature();
      FEValues<2>  fe_values(problem.geometric_mapping(),
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points);
      const FEValuesExtractors::Vector u(0);
      const unsigned int               n_dofs = fe.n_dofs_per_cell();
      const auto &partitioner = problem.ghosted_displacement().trilinos_partitioner();
      AssertThrow(partitioner.SameAs(problem.ghosted_velocity().trilinos_partitioner()),
                  ExcInternalError());
      std::vector<types::global_dof_index> dofs(n_dofs);
      for (const auto &cell : problem.dofs().active_cell_iterators())
        if (cell->is_locally_owned() && selected(cell))
          {
            fe_values.reinit(cell);
            CellOperator op{cell, fe_values.get_quadrature_points(), {}, {}};
            cell->get_dof_indices(dofs);
            for (const auto dof : dofs)
              op.local_index.push_back(
                partitioner.LID(static_cast<TrilinosWrappers::types::int_type>(dof)));
            op.strain.resize(quadrature.size() * 4 * n_dofs);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const double r = op.points[q][0];
                double      *row = &op.strain[4 * q * n_dofs];
                for (unsigned int i = 0; i < n_dofs; ++i)
                  {
                    const SymmetricTensor<2, 3> e =
                      axisymmetric_strain(fe_values[u].value(i, q),
                                          fe_values[u].gradient(i, q),
                                          r);
                    row[i]              = e[0][0];
                    row[n_dofs + i]     = e[1][1];
                    row[2 * n_dofs + i] = e[2][2];
                    row[3 * n_dofs + i] = e[0][1];
                  }
              }
            cells.push_back(std::move(op));
          }
    }


    void
    CellStress::evaluate(
      const ImpactProblem &problem,
      const std::function<void(const CellIterator &,
                               const std::vector<Point<2>> &,
                               const std::vector<SymmetricTensor<2, 3>> &)> &visit)
      const
    {
      const unsigned int n_dofs = problem.dofs().get_fe().n_dofs_per_cell();
      Vector<double>     local_u(n_dofs), local_v(n_dofs);
      // Vector 0 of the Epetra multivectors: the ghosted values.
      const double *u = problem.ghosted_displacement().trilinos_vector()[0];
      const double *v = problem.ghosted_velocity().trilinos_vector()[0];
      std::vector<SymmetricTensor<2, 3>> stress;
      auto strain_of = [n_dofs](const double *rows, const Vector<double> &values) {
        SymmetricTensor<2, 3> e;
        double                c[4] = {0, 0, 0, 0};
        for (unsigned int k = 0; k < 4; ++k)
          for (unsigned int i = 0; i < n_dofs; ++i)
            c[k] += rows[k * n_dofs + i] * values[i];
        e[0][0] = c[0];
        e[1][1] = c[1];
        e[2][2] = c[2];
        e[0][1] = c[3];
        return e;
      };
      for (const auto &op : cells)
        {
          const auto &material = problem.material_of(op.cell->material_id());
          const auto  C        = material.stiffness_tangent();
          const auto  D        = material.damping_tangent();
          const bool  viscous  = D.norm() > 0;
          const auto  states   = problem.internal_variables().states(op.cell);
          for (unsigned int i = 0; i < n_dofs; ++i)
            local_u[i] = u[op.local_index[i]];
          if (viscous)
            for (unsigned int i = 0; i < n_dofs; ++i)
              local_v[i] = v[op.local_index[i]];
          stress.resize(op.points.size());
          for (unsigned int q = 0; q < op.points.size(); ++q)
            {
              const double *rows = &op.strain[4 * q * n_dofs];
              stress[q]          = C * strain_of(rows, local_u);
              if (viscous)
                stress[q] += D * strain_of(rows, local_v);
              if (!states.empty())
                stress[q] += material.internal_stress(states[q]->internal) -
                             C * states[q]->plastic_strain;
            }
          visit(op.cell, op.points, stress);
        }
    }
  } // namespace postprocess
} // namespace impact_fem
