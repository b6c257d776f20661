#include <impact_fem/axisymmetric_strain.h>
#include <impact_fem/materials/internal_variables.h>
#include <impact_fem/mesh/sphere_plate_mesh.h>

#include <deal.II/base/mpi.h>
#include <deal.II/fe/fe_values.h>

namespace impact_fem
{
  namespace materials
  {
    void
    InternalVariables::initialize(
      const Triangulation<2> &triangulation,
      const Quadrature<2>    &quadrature,
      const std::function<const Interface &(types::material_id)> &material)
    {
      material_of = material;
      is_active   = false;
      dissipated  = 0;
      stored[0] = stored[1] = 0;
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() &&
            material_of(cell->material_id()).n_internal_variables() > 0)
          {
            is_active = true;
            storage.initialize(cell, quadrature.size());
            for (const auto &state : storage.get_data(cell))
              state->internal.assign(
                material_of(cell->material_id()).n_internal_variables(),
                SymmetricTensor<2, 3>());
          }
      is_active = Utilities::MPI::logical_or(is_active,
                                             triangulation.get_communicator());
    }


    InternalVariables::States
    InternalVariables::states(const CellIterator &cell) const
    {
      if (material_of(cell->material_id()).n_internal_variables() == 0)
        return {};
      return storage.get_data(cell);
    }


    void
    InternalVariables::update(const DoFHandler<2>             &dof_handler,
                              const Mapping<2>                &mapping,
                              const Quadrature<2>             &quadrature,
                              const AffineConstraints<double> &constraints,
                              const VectorType                &displacement,
                              const double                     dt,
                              VectorType                      &predictor_force)
    {
      predictor_force = 0;
      if (!is_active)
        return;
      const auto        &fe = dof_handler.get_fe();
      FEValues<2>        fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
      const unsigned int dofs_per_cell = fe.n_dofs_per_cell();
      Vector<double>     cell_force(dofs_per_cell);
      std::vector<types::global_dof_index> local_dofs(dofs_per_cell);
      std::vector<Tensor<1, 2>>            values(quadrature.size());
      std::vector<Tensor<2, 2>>            gradients(quadrature.size());
      const FEValuesExtractors::Vector     u(0);
      double step_dissipated = 0, now_stored[2] = {0, 0};

      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() &&
            material_of(cell->material_id()).n_internal_variables() > 0)
          {
            const auto &material = material_of(cell->material_id());
            const auto  states   = storage.get_data(cell);
            const unsigned int body =
              cell->material_id() == body_ids::sphere ? 0 : 1;
            fe_values.reinit(cell);
            fe_values[u].get_function_values(displacement, values);
            fe_values[u].get_function_gradients(displacement, gradients);
            cell_force = 0;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const double r  = fe_values.quadrature_point(q)[0];
                const double dV = 2 * M_PI * r * fe_values.JxW(q);
                QuadraturePointState       &state = *states[q];
                const SymmetricTensor<2, 3> strain =
                  axisymmetric_strain(values[q], gradients[q], r);
                step_dissipated += material.update_internal_variables(
                                     state.internal, state.strain, strain, dt) *
                                   dV;
                state.strain = strain;
                now_stored[body] += material.internal_energy(state.internal) * dV;
                const SymmetricTensor<2, 3> predictor =
                  material.internal_stress_predictor(state.internal, strain, dt);
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  cell_force(i) +=
                    (predictor * axisymmetric_strain(fe_values[u].value(i, q),
                                                     fe_values[u].gradient(i, q),
                                                     r)) *
                    dV;
              }
            cell->get_dof_indices(local_dofs);
            constraints.distribute_local_to_global(cell_force,
                                                   local_dofs,
                                                   predictor_force);
          }
      predictor_force.compress(VectorOperation::add);
      const MPI_Comm comm = dof_handler.get_communicator();
      dissipated += Utilities::MPI::sum(step_dissipated, comm);
      for (unsigned int body = 0; body < 2; ++body)
        stored[body] = Utilities::MPI::sum(now_stored[body], comm);
    }
  } // namespace materials
} // namespace impact_fem
