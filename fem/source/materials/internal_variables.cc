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
      const DoFHandler<2>   &dof_handler,
      const Mapping<2>      &mapping,
      const Quadrature<2>   &quadrature,
      const std::function<const Interface &(types::material_id)> &material,
      const VectorType      &ghosted_layout)
    {
      material_of  = material;
      is_active    = false;
      is_nonlinear = false;
      dissipated   = 0;
      plastic      = 0;
      for (unsigned int body = 0; body < 2; ++body)
        stored[body] = plastic_correction[body] = max_accumulated[body] = 0;
      plastic_cells.clear();
      plastic_force_now.reinit(ghosted_layout.locally_owned_elements(),
                               dof_handler.get_communicator());

      const auto        &fe = dof_handler.get_fe();
      FEValues<2>        fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
      const unsigned int n_dofs = fe.n_dofs_per_cell();
      const FEValuesExtractors::Vector u(0);
      const auto &partitioner = ghosted_layout.trilinos_partitioner();
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const Interface &m = material_of(cell->material_id());
            if (m.n_internal_variables() == 0 && m.is_linear())
              continue;
            is_active = true;
            storage.initialize(cell, quadrature.size());
            for (const auto &state : storage.get_data(cell))
              state->internal.assign(m.n_internal_variables(),
                                     SymmetricTensor<2, 3>());
            if (m.is_linear())
              continue;
            is_nonlinear = true;
            PlasticCell c;
            c.cell = cell;
            c.body = cell->material_id() == body_ids::sphere ? 0 : 1;
            c.dofs.resize(n_dofs);
            cell->get_dof_indices(c.dofs);
            for (const auto dof : c.dofs)
              c.local_index.push_back(
                partitioner.LID(static_cast<TrilinosWrappers::types::int_type>(dof)));
            fe_values.reinit(cell);
            c.strain.resize(quadrature.size() * 4 * n_dofs);
            c.volume.resize(quadrature.size());
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const double r = fe_values.quadrature_point(q)[0];
                c.volume[q]    = 2 * M_PI * r * fe_values.JxW(q);
                double *row    = &c.strain[4 * q * n_dofs];
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
            plastic_cells.push_back(std::move(c));
          }
      const MPI_Comm comm = dof_handler.get_communicator();
      is_active    = Utilities::MPI::logical_or(is_active, comm);
      is_nonlinear = Utilities::MPI::logical_or(is_nonlinear, comm);
    }


    InternalVariables::States
    InternalVariables::states(const CellIterator &cell) const
    {
      const Interface &m = material_of(cell->material_id());
      if (m.n_internal_variables() == 0 && m.is_linear())
        return {};
      return storage.get_data(cell);
    }


    SymmetricTensor<2, 3>
    InternalVariables::strain_at(const PlasticCell &c,
                                 const unsigned int q,
                                 const double      *values)
    {
      const unsigned int n   = c.dofs.size();
      const double      *row = &c.strain[4 * q * n];
      double             e[4] = {0, 0, 0, 0};
      for (unsigned int k = 0; k < 4; ++k)
        for (unsigned int i = 0; i < n; ++i)
          e[k] += row[k * n + i] * values[i];
      SymmetricTensor<2, 3> strain;
      strain[0][0] = e[0];
      strain[1][1] = e[1];
      strain[2][2] = e[2];
      strain[0][1] = e[3];
      return strain;
    }


    template <typename Visitor>
    void
    InternalVariables::for_each_plastic_point(const VectorType &u,
                                              const Visitor    &visit) const
    {
      // Vector 0 of the Epetra multivector: the owned and ghost values.
      const double       *data = u.trilinos_vector()[0];
      std::vector<double> values;
      for (const auto &c : plastic_cells)
        {
          values.resize(c.local_index.size());
          for (unsigned int i = 0; i < values.size(); ++i)
            values[i] = data[c.local_index[i]];
          for (unsigned int q = 0; q < c.volume.size(); ++q)
            visit(c, q, strain_at(c, q, values.data()));
        }
    }


    void
    InternalVariables::plastic_force(const AffineConstraints<double> &constraints,
                                     const VectorType &ghosted_trial,
                                     const double      dt,
                                     VectorType       &force) const
    {
      force = 0;
      Vector<double>        cell_force;
      SymmetricTensor<4, 3> tangent;
      QuadraturePointState  end;
      const PlasticCell    *current = nullptr;
      bool                  loaded  = false;
      std::vector<std::shared_ptr<const QuadraturePointState>> states;
      const auto flush = [&]() {
        if (current != nullptr && loaded)
          constraints.distribute_local_to_global(cell_force, current->dofs, force);
      };
      for_each_plastic_point(
        ghosted_trial,
        [&](const PlasticCell &c, const unsigned int q, const SymmetricTensor<2, 3> &strain) {
          if (&c != current)
            {
              flush();
              current = &c;
              loaded  = false;
              states  = storage.get_data(c.cell);
              cell_force.reinit(c.dofs.size());
            }
          const Interface &m = material_of(c.cell->material_id());
          m.stress_update(*states[q], strain, dt, end, tangent);
          if (end.accumulated_plastic_strain == 0)
            return;
          loaded = true;
          const SymmetricTensor<2, 3> stress =
            m.stiffness_tangent() * end.plastic_strain * c.volume[q];
          add_strain_transpose(c, q, stress, cell_force);
        });
      flush();
      force.compress(VectorOperation::add);
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
            material_of(cell->material_id()).n_internal_variables() > 0 &&
            material_of(cell->material_id()).is_linear())
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
      if (is_nonlinear)
        commit_plastic_state(constraints, displacement, dt);
    }


    void
    InternalVariables::commit_plastic_state(
      const AffineConstraints<double> &constraints,
      const VectorType                &displacement,
      const double                     dt)
    {
      plastic_force_now = 0;
      Vector<double>        cell_force;
      SymmetricTensor<4, 3> tangent;
      QuadraturePointState  end;
      double step_work = 0, correction[2] = {0, 0}, largest[2] = {0, 0};
      const PlasticCell *current = nullptr;
      bool               loaded  = false;
      std::vector<std::shared_ptr<QuadraturePointState>> states;
      const auto flush = [&]() {
        if (current != nullptr && loaded)
          constraints.distribute_local_to_global(cell_force,
                                                 current->dofs,
                                                 plastic_force_now);
      };
      for_each_plastic_point(
        displacement,
        [&](const PlasticCell &c, const unsigned int q, const SymmetricTensor<2, 3> &strain) {
          if (&c != current)
            {
              flush();
              current = &c;
              loaded  = false;
              states  = storage.get_data(c.cell);
              cell_force.reinit(c.dofs.size());
            }
          const Interface &m = material_of(c.cell->material_id());
          QuadraturePointState &state = *states[q];
          const auto C = m.stiffness_tangent();
          const SymmetricTensor<2, 3> stress_start =
            C * (state.strain - state.plastic_strain);
          const SymmetricTensor<2, 3> stress_end =
            m.stress_update(state, strain, dt, end, tangent);
          // sigma : d eps^p, trapezoidal in the stress: with the elastic
          // energy 1/2 (eps - eps^p) : C : (eps - eps^p) this is the internal
          // work (Delta eps : mean sigma) of the step exactly.
          step_work += 0.5 * ((stress_start + stress_end) *
                              (end.plastic_strain - state.plastic_strain)) *
                       c.volume[q];
          state = end;
          if (state.accumulated_plastic_strain == 0)
            return;
          const SymmetricTensor<2, 3> plastic_stress = C * state.plastic_strain;
          correction[c.body] += (0.5 * (plastic_stress * state.plastic_strain) -
                                 plastic_stress * strain) *
                                c.volume[q];
          largest[c.body] = std::max(largest[c.body], state.accumulated_plastic_strain);
          loaded = true;
          add_strain_transpose(c, q, plastic_stress * c.volume[q], cell_force);
        });
      flush();
      plastic_force_now.compress(VectorOperation::add);
      const MPI_Comm comm = plastic_force_now.get_mpi_communicator();
      plastic += Utilities::MPI::sum(step_work, comm);
      for (unsigned int body = 0; body < 2; ++body)
        {
          plastic_correction[body] = Utilities::MPI::sum(correction[body], comm);
          max_accumulated[body]    = Utilities::MPI::max(largest[body], comm);
        }
    }


    void
    InternalVariables::add_strain_transpose(const PlasticCell           &c,
                                            const unsigned int           q,
                                            const SymmetricTensor<2, 3> &stress,
                                            Vector<double>              &cell_force)
    {
      // B^T sigma with B the strain of the shape functions; the shear
      // component counts twice (sigma : eps = ... + 2 sigma_rz eps_rz).
      const unsigned int n   = c.dofs.size();
      const double      *row = &c.strain[4 * q * n];
      const double       s[4] = {stress[0][0], stress[1][1], stress[2][2], 2 * stress[0][1]};
      for (unsigned int k = 0; k < 4; ++k)
        for (unsigned int i = 0; i < n; ++i)
          cell_force(i) += s[k] * row[k * n + i];
    }
  } // namespace materials
} // namespace impact_fem
