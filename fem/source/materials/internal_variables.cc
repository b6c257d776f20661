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
      const DoFHandler<2>                                        &dof_handler,
      const Mapping<2>                                           &mapping,
      const Quadrature<2>                                        &quadrature,
      const std::function<const Interface &(types::material_id)> &material,
      const VectorType &ghosted_layout)
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
      plastic_force_predicted.reinit(plastic_force_now);
      prepared_force.reinit(plastic_force_now);
      prepared = false;

      FEValues<2>                          fe_values(mapping,
                            dof_handler.get_fe(),
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
      std::vector<types::global_dof_index> dofs(
        dof_handler.get_fe().n_dofs_per_cell());
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
            fe_values.reinit(cell);
            cell->get_dof_indices(dofs);
            plastic_cells.push_back(
              {cell,
               cell->material_id() == body_ids::sphere ? 0u : 1u,
               CellStrainOperator(fe_values, dofs, ghosted_layout),
               storage.get_data(cell),
               false,
               false,
               std::vector<QuadraturePointState>(quadrature.size())});
          }
      const MPI_Comm comm = dof_handler.get_communicator();
      is_active           = Utilities::MPI::logical_or(is_active, comm);
      is_nonlinear        = Utilities::MPI::logical_or(is_nonlinear, comm);
    }


    void
    InternalVariables::save(checkpoint::Writer  &writer,
                            const DoFHandler<2> &dof_handler) const
    {
      // Each state's strain, internal variables, plastic strain and
      // accumulated plastic strain as the doubles they are.
      std::vector<double> values;
      const auto          add = [&](const SymmetricTensor<2, 3> &t) {
        for (unsigned int i = 0; i < t.n_independent_components; ++i)
          values.push_back(t.access_raw_entry(i));
      };
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &state : states(cell))
            {
              add(state->strain);
              for (const auto &internal : state->internal)
                add(internal);
              add(state->plastic_strain);
              values.push_back(state->accumulated_plastic_strain);
            }
      std::vector<bool> candidates;
      for (const auto &c : plastic_cells)
        candidates.push_back(c.candidate);
      writer &values &candidates &dissipated &stored[0] & stored[1] &
        plastic &plastic_correction[0] & plastic_correction[1] &
        max_accumulated[0] & max_accumulated[1];
      checkpoint::save(writer, plastic_force_now);
      checkpoint::save(writer, plastic_force_predicted);
    }


    void
    InternalVariables::load(checkpoint::Reader  &reader,
                            const DoFHandler<2> &dof_handler)
    {
      std::vector<double>                     values;
      std::vector<bool>                       candidates;
      reader &values &candidates &dissipated &stored[0] & stored[1] &
        plastic &plastic_correction[0] & plastic_correction[1] &
        max_accumulated[0] & max_accumulated[1];
      AssertThrow(candidates.size() == plastic_cells.size(),
                  ExcMessage("The checkpoint's plastic cells do not fit the "
                             "run's."));
      std::size_t k     = 0;
      const auto  fetch = [&]() {
        AssertThrow(k < values.size(),
                    ExcMessage("The checkpoint's quadrature-point states do "
                                "not fit the run's."));
        return values[k++];
      };
      const auto read = [&](SymmetricTensor<2, 3> &t) {
        for (unsigned int i = 0; i < t.n_independent_components; ++i)
          t.access_raw_entry(i) = fetch();
      };
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned() && !states(cell).empty())
          for (const auto &state : storage.get_data(cell))
            {
              read(state->strain);
              for (auto &internal : state->internal)
                read(internal);
              read(state->plastic_strain);
              state->accumulated_plastic_strain = fetch();
            }
      AssertThrow(k == values.size(),
                  ExcMessage("The checkpoint's quadrature-point states do not "
                             "fit the run's."));
      for (std::size_t i = 0; i < plastic_cells.size(); ++i)
        plastic_cells[i].candidate = candidates[i];
      prepared             = false;
      const IndexSet owned = plastic_force_now.locally_owned_elements();
      const MPI_Comm comm  = dof_handler.get_communicator();
      checkpoint::load(reader, plastic_force_now, owned, comm);
      checkpoint::load(reader, plastic_force_predicted, owned, comm);
    }


    InternalVariables::States
    InternalVariables::states(const CellIterator &cell) const
    {
      const Interface &m = material_of(cell->material_id());
      if (m.n_internal_variables() == 0 && m.is_linear())
        return {};
      return storage.get_data(cell);
    }


    template <typename Cells, typename PointStress>
    void
    InternalVariables::assemble_plastic_points(
      Cells                           &cells,
      const AffineConstraints<double> &constraints,
      const VectorType                &u,
      const bool                       candidates_only,
      VectorType                      &force,
      const PointStress               &point_stress)
    {
      force = 0;
      std::vector<double>   values;
      Vector<double>        cell_force;
      SymmetricTensor<2, 3> stress;
      for (auto &c : cells)
        {
          if (candidates_only && !c.candidate)
            continue;
          c.strain.gather(u, values);
          cell_force.reinit(values.size());
          bool loaded = false;
          for (unsigned int q = 0; q < c.strain.n_points(); ++q)
            if (point_stress(c, q, c.strain.strain(q, values), stress))
              {
                loaded = true;
                c.strain.add_transpose(q,
                                       stress * c.strain.volume(q),
                                       cell_force);
              }
          // Cells that never yielded add nothing: skip their scatter.
          if (loaded)
            constraints.distribute_local_to_global(cell_force,
                                                   c.strain.dof_indices(),
                                                   force);
        }
      force.compress(VectorOperation::add);
    }


    void
    InternalVariables::plastic_force(
      const AffineConstraints<double> &constraints,
      const VectorType                &ghosted_trial,
      const double                     dt,
      VectorType                      &force) const
    {
      SymmetricTensor<4, 3> tangent;
      QuadraturePointState  end;
      assemble_plastic_points(
        plastic_cells,
        constraints,
        ghosted_trial,
        true,
        force,
        [&](const PlasticCell           &c,
            const unsigned int           q,
            const SymmetricTensor<2, 3> &strain,
            SymmetricTensor<2, 3>       &stress) {
          const Interface &m = material_of(c.cell->material_id());
          m.stress_update(*c.states[q], strain, dt, end, tangent);
          if (end.accumulated_plastic_strain == 0)
            return false;
          stress = m.stiffness_tangent() * end.plastic_strain;
          return true;
        });
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
      const auto                          &fe = dof_handler.get_fe();
      FEValues<2>                          fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_quadrature_points | update_JxW_values);
      const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
      Vector<double>                       cell_force(dofs_per_cell);
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
            const auto        &material = material_of(cell->material_id());
            const auto         states   = storage.get_data(cell);
            const unsigned int body =
              cell->material_id() == body_ids::sphere ? 0 : 1;
            fe_values.reinit(cell);
            fe_values[u].get_function_values(displacement, values);
            fe_values[u].get_function_gradients(displacement, gradients);
            cell_force = 0;
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const double          r     = fe_values.quadrature_point(q)[0];
                const double          dV    = 2 * M_PI * r * fe_values.JxW(q);
                QuadraturePointState &state = *states[q];
                const SymmetricTensor<2, 3> strain =
                  axisymmetric_strain(values[q], gradients[q], r);
                step_dissipated += material.update_internal_variables(
                                     state.internal, state.strain, strain, dt) *
                                   dV;
                state.strain = strain;
                now_stored[body] +=
                  material.internal_energy(state.internal) * dV;
                const SymmetricTensor<2, 3> predictor =
                  material.internal_stress_predictor(state.internal,
                                                     strain,
                                                     dt);
                for (unsigned int i = 0; i < dofs_per_cell; ++i)
                  cell_force(i) +=
                    (predictor *
                     axisymmetric_strain(fe_values[u].value(i, q),
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


    bool
    InternalVariables::prepare_commit(
      const AffineConstraints<double> &constraints,
      const VectorType                &ghosted_trial,
      const double                     dt)
    {
      SymmetricTensor<4, 3> tangent;
      double step_work = 0, correction[2] = {0, 0}, largest[2] = {0, 0};
      bool   missed = false;
      for (auto &c : plastic_cells)
        c.prepared_candidate = false;
      assemble_plastic_points(
        plastic_cells,
        constraints,
        ghosted_trial,
        false,
        prepared_force,
        [&](PlasticCell                 &c,
            const unsigned int           q,
            const SymmetricTensor<2, 3> &strain,
            SymmetricTensor<2, 3>       &stress) {
          const Interface            &m = material_of(c.cell->material_id());
          const QuadraturePointState &start = *c.states[q];
          QuadraturePointState       &end   = c.prepared[q];
          const auto                  C     = m.stiffness_tangent();
          const double                dV    = c.strain.volume(q);
          const SymmetricTensor<2, 3> stress_start =
            C * (start.strain - start.plastic_strain);
          const SymmetricTensor<2, 3> stress_end =
            m.stress_update(start, strain, dt, end, tangent);
          // sigma : d eps^p, trapezoidal in the stress: with the elastic
          // energy 1/2 (eps - eps^p) : C : (eps - eps^p) this is the internal
          // work (Delta eps : mean sigma) of the step exactly.
          step_work += 0.5 *
                       ((stress_start + stress_end) *
                        (end.plastic_strain - start.plastic_strain)) *
                       dV;
          if (end.accumulated_plastic_strain == 0)
            {
              // A candidate of the next step if within the margin of
              // yielding (the stress of a point that never yielded is
              // elastic: stress_end).
              c.prepared_candidate =
                c.prepared_candidate ||
                von_mises(stress_end) >=
                  candidate_stress_fraction * m.yield_stress(0);
              return false;
            }
          if (!c.candidate && start.accumulated_plastic_strain == 0)
            missed = true;
          c.prepared_candidate = true;
          stress               = C * end.plastic_strain;
          correction[c.body] +=
            (0.5 * (stress * end.plastic_strain) - stress * strain) * dV;
          largest[c.body] =
            std::max(largest[c.body], end.accumulated_plastic_strain);
          return true;
        });
      const MPI_Comm comm = prepared_force.get_mpi_communicator();
      if (Utilities::MPI::logical_or(missed, comm))
        {
          // Solved without a cell that yields: it joins the candidates.
          for (auto &c : plastic_cells)
            c.candidate = c.candidate || c.prepared_candidate;
          prepared = false;
          return false;
        }
      prepared_work = Utilities::MPI::sum(step_work, comm);
      for (unsigned int body = 0; body < 2; ++body)
        {
          prepared_correction[body] =
            Utilities::MPI::sum(correction[body], comm);
          prepared_largest[body] = Utilities::MPI::max(largest[body], comm);
        }
      prepared = true;
      return true;
    }


    void
    InternalVariables::commit_plastic_state(
      const AffineConstraints<double> &constraints,
      const VectorType                &displacement,
      const double                     dt)
    {
      AssertThrow(prepared || prepare_commit(constraints, displacement, dt),
                  ExcMessage("Internal error: a point outside the candidate "
                             "cells yielded in a step that was not checked "
                             "(InternalVariables::prepare_commit)."));
      prepared = false;
      for (auto &c : plastic_cells)
        {
          for (unsigned int q = 0; q < c.prepared.size(); ++q)
            *c.states[q] = c.prepared[q];
          c.candidate = c.prepared_candidate;
        }
      // The predictor 2 f_p(n) - f_p(n-1).
      plastic_force_predicted.equ(-1., plastic_force_now);
      plastic_force_now = prepared_force;
      plastic_force_predicted.add(2., plastic_force_now);
      plastic += prepared_work;
      for (unsigned int body = 0; body < 2; ++body)
        {
          plastic_correction[body] = prepared_correction[body];
          max_accumulated[body]    = prepared_largest[body];
        }
    }


  } // namespace materials
} // namespace impact_fem
