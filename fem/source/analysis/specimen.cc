// The homogeneous specimen (Scenario/Analysis = specimen).

#include <impact_fem/as_written.h>
#include <impact_fem/analysis/loading_history.h>
#include <impact_fem/analysis/specimen.h>
#include <impact_fem/axisymmetric_strain.h>
#include <impact_fem/materials/interface.h>
#include <impact_fem/output/history.h>
#include <impact_fem/quadrature.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/quadrature_point_data.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

namespace impact_fem
{
  using namespace loading_history;

  namespace
  {
    // Appends t, the mean strain and stress over a specimen's quadrature
    // points and the inhomogeneity: the largest deviation of a point's
    // stress from the mean, relative to the largest mean component.
    void
    append_specimen_means(History                                  &history,
                          const double                              t,
                          const std::vector<SymmetricTensor<2, 3>> &strains,
                          const std::vector<SymmetricTensor<2, 3>> &stresses)
    {
      SymmetricTensor<2, 3> mean_strain, mean_stress;
      for (unsigned int k = 0; k < strains.size(); ++k)
        {
          mean_strain += strains[k] / strains.size();
          mean_stress += stresses[k] / stresses.size();
        }
      double deviation = 0, scale = 0;
      for (unsigned int a = 0; a < 3; ++a)
        for (unsigned int b = a; b < 3; ++b)
          scale = std::max(scale, std::abs(mean_stress[a][b]));
      for (const auto &sigma : stresses)
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = a; b < 3; ++b)
            deviation =
              std::max(deviation, std::abs(sigma[a][b] - mean_stress[a][b]));
      append_components(history, t, mean_strain, mean_stress);
      history.append("inhomogeneity", scale > 0 ? deviation / scale : 0.);
    }
    // The specimen's history.h5 in @p directory, with its loading, time
    // step and discretisation as attributes.
    void
    write_specimen_history(const History       &history,
                           const std::string   &directory,
                           const std::string   &loading,
                           const double         dt,
                           const DoFHandler<2> &dof_handler)
    {
      std::filesystem::create_directories(directory);
      std::map<std::string, std::string> text;
      text["Scenario/Analysis"]      = "specimen";
      text["Material point/Loading"] = loading;
      std::map<std::string, double> numbers;
      numbers["time_step [s]"] = dt;
      numbers["cells"] = dof_handler.get_triangulation().n_active_cells();
      numbers["dofs"]  = dof_handler.n_dofs();
      history.write_hdf5(directory + "/history.h5", text, numbers, true);
    }

    struct SpecimenPointState
    {
      SymmetricTensor<2, 3>              strain;
      std::vector<SymmetricTensor<2, 3>> internal;
    };

    // Displacement of the homogeneous strain eps_rr = eps_tt = a, eps_zz = b.
    class HomogeneousDisplacement : public Function<2>
    {
    public:
      HomogeneousDisplacement(const double a, const double b)
        : Function<2>(2)
        , a(a)
        , b(b)
      {}
      double
      value(const Point<2> &p, const unsigned int component) const override
      {
        return component == 0 ? a * p[0] : b * p[1];
      }

    private:
      double a, b;
    };


    // Boundary ids of hyper_rectangle: 0 axis, 1 side, 2 bottom, 3 top.
    // Rollers: u_r = 0 on the axis, u_z = 0 at the bottom (uniaxial stress,
    // the side free).
    void
    constrain_rollers(const DoFHandler<2>       &dof_handler,
                      const FESystem<2>         &fe,
                      AffineConstraints<double> &constraints)
    {
      VectorTools::interpolate_boundary_values(
        dof_handler,
        0,
        Functions::ZeroFunction<2>(2),
        constraints,
        fe.component_mask(FEValuesExtractors::Scalar(0)));
      VectorTools::interpolate_boundary_values(
        dof_handler,
        2,
        Functions::ZeroFunction<2>(2),
        constraints,
        fe.component_mask(FEValuesExtractors::Scalar(1)));
    }


    // The homogeneous strain eps_rr = eps_tt = a, eps_zz = b on the whole
    // boundary.
    void
    constrain_homogeneous_strain(const DoFHandler<2>       &dof_handler,
                                 const double               a,
                                 const double               b,
                                 AffineConstraints<double> &constraints)
    {
      const HomogeneousDisplacement boundary(a, b);
      for (const types::boundary_id id : {0, 1, 2, 3})
        VectorTools::interpolate_boundary_values(dof_handler,
                                                 id,
                                                 boundary,
                                                 constraints);
    }


    // Axial strain of the 'axial strain path' at time t: piecewise linear
    // from 0 through the points, one ramp time per segment, then held.
    double
    axial_strain(const std::vector<double> &path,
                 const double               ramp_time,
                 const double               t)
    {
      const double       x = t / ramp_time;
      const unsigned int i = static_cast<unsigned int>(std::floor(x));
      if (i >= path.size())
        return path.back();
      const double start = i == 0 ? 0. : path[i - 1];
      return start + (x - i) * (path[i] - start);
    }


    // The cylinder 0 <= r <= 1 mm, 0 <= z <= 1 mm of 2 x 2 cells and its
    // finite elements of degree @p degree; boundary ids of hyper_rectangle:
    // 0 axis, 1 side, 2 bottom, 3 top.
    struct SpecimenMesh
    {
      explicit SpecimenMesh(const unsigned int degree)
        : fe(FE_Q<2>(degree), 2)
        , quadrature(cell_quadrature(fe))
      {
        GridGenerator::hyper_rectangle(triangulation,
                                       Point<2>(0, 0),
                                       Point<2>(size, size),
                                       true);
        triangulation.refine_global(1);
        dof_handler.reinit(triangulation);
        dof_handler.distribute_dofs(fe);
        DynamicSparsityPattern dsp(dof_handler.n_dofs());
        DoFTools::make_sparsity_pattern(dof_handler, dsp);
        sparsity.copy_from(dsp);
      }

      static constexpr double size = 1e-3;
      Triangulation<2>        triangulation;
      const FESystem<2>       fe;
      DoFHandler<2>           dof_handler;
      const QGauss<2>         quadrature;
      SparsityPattern         sparsity;
    };


    // What the two specimens share: the loading, the mesh and its cell
    // values, the prescribed strain histories, the history of the means and
    // its file.
    class Specimen
    {
    protected:
      Specimen(const Loading &input, const unsigned int degree)
        : input(input)
        , material(*input.material)
        , strain_hat(input.strain_hat)
        , dt(input.dt)
        , mesh(degree)
        , fe_values(mesh.fe,
                    mesh.quadrature,
                    update_values | update_gradients |
                      update_quadrature_points | update_JxW_values)
        , u(0)
        , dofs_per_cell(mesh.fe.n_dofs_per_cell())
      {}

      // Every quadrature point unstrained, its internal variables relaxed.
      template <typename PointState>
      void
      initialize_states(CellDataStorage<Triangulation<2>::cell_iterator,
                                        PointState> &states) const
      {
        for (const auto &cell : mesh.triangulation.active_cell_iterators())
          {
            states.initialize(cell, mesh.quadrature.size());
            for (const auto &state : states.get_data(cell))
              state->internal.assign(material.n_internal_variables(),
                                     SymmetricTensor<2, 3>());
          }
      }

      // The strain history's homogeneous strain at time t on the whole
      // boundary (homogeneous: its zero, for the corrections).
      void
      constrain_strain_history(const double               t,
                               const bool                 homogeneous,
                               AffineConstraints<double> &constraints) const
      {
        const double factor = homogeneous ? 0. : strain_factor(input, t);
        constrain_homogeneous_strain(mesh.dof_handler,
                                     factor * strain_hat[0],
                                     factor * strain_hat[1],
                                     constraints);
      }

      // The strain history's rate at t = 0 as the velocity.
      void
      interpolate_initial_strain_rate(Vector<double> &velocity) const
      {
        const double rate = strain_factor_rate(input, 0);
        VectorTools::interpolate(mesh.dof_handler,
                                 HomogeneousDisplacement(rate * strain_hat[0],
                                                         rate * strain_hat[1]),
                                 velocity);
      }

      // The mean strain and stress and the inhomogeneity.
      void
      declare_mean_history()
      {
        declare_components(history, "mean ", " over the quadrature points");
        history.declare(
          "inhomogeneity",
          "1",
          "largest deviation of a quadrature point's stress from the "
          "mean, relative to the largest mean component");
      }

      unsigned int
      n_steps() const
      {
        return static_cast<unsigned int>(std::lround(input.duration / dt));
      }

      // history.h5 and its line on the console: "specimen (<loading>
      // <update>): ... steps of dt s<solves> -> ...".
      void
      write_results(const unsigned int steps,
                    const std::string &update,
                    const std::string &solves) const
      {
        const std::string &directory = input.directory;
        const std::string &loading   = input.loading;
        write_specimen_history(
          history, directory, loading, dt, mesh.dof_handler);
        std::cout << "specimen (" << loading << update
                  << "): " << mesh.triangulation.n_active_cells() << " cells, "
                  << mesh.dof_handler.n_dofs() << " dofs, " << steps
                  << " steps of " << dt << " s" << solves << " -> " << directory
                  << "/history.h5" << std::endl;
      }

      const Loading                   &input;
      const materials::Interface      &material;
      const std::vector<double>       &strain_hat;
      const double                     dt;
      SpecimenMesh                     mesh;
      FEValues<2>                      fe_values;
      const FEValuesExtractors::Vector u;
      const unsigned int               dofs_per_cell;
      History                          history;
    };


    // The specimen with the general constitutive update (an elastic-plastic
    // material, or any material under the axial strain path): at each step
    // Newton iterations on the quasi-static equilibrium
    //   r(u) = int B^T (sigma(eps(u)) + D : d eps/dt) dV = 0
    // on the free degrees of freedom, with the consistent tangent of the
    // material plus 2/dt D (the strain rate by the trapezoidal rule, as in
    // the linear specimen); the quadrature-point states are committed when
    // the step has converged. For a homogeneous specimen every quadrature
    // point follows the same path, so the mean stress is the material's
    // response to the mean strain and 'inhomogeneity' shows whether it
    // stayed homogeneous.
    class GeneralSpecimen : private Specimen
    {
    public:
      /// Refuses the loadings it cannot run, naming the entry.
      static void
      check(const Loading &input);

      GeneralSpecimen(const Loading &input, const unsigned int degree);

      void
      run();

    private:
      // Boundary ids of hyper_rectangle: 0 axis, 1 side, 2 bottom, 3 top.
      // Uniaxial: u_r = 0 on the axis, u_z = 0 at the bottom, u_z = eps h
      // at the top, the side free. Otherwise the homogeneous strain on the
      // whole boundary, as in the linear specimen.
      AffineConstraints<double>
      make_constraints(const double t, const bool homogeneous) const;
      // Assembles the tangent and the out-of-balance force -r(u) (condensed
      // with the homogeneous constraints) and the unconstrained internal
      // force (its norm scales the convergence test); with commit, stores
      // the updated states instead, and returns the step's plastic work [J]
      // (trapezoidal in the stress).
      double
      assemble(const AffineConstraints<double> &constraints, const bool commit);
      void
      declare_history();
      void
      record(const double t, const unsigned int iterations);
      // Initial strain rate (the trapezoidal rule needs it with a viscous
      // part): the prescribed one; under the axial path the elastic lateral
      // contraction -nu times the axial rate.
      void
      set_initial_rate();
      // The Newton iterations of step @p step; returns their number.
      unsigned int
      solve_step(const unsigned int step);

      const bool                  uniaxial;
      const unsigned int          n_q;
      const SymmetricTensor<4, 3> D;
      CellDataStorage<Triangulation<2>::cell_iterator,
                      materials::QuadraturePointState>
                           states;
      SparseMatrix<double> tangent_matrix;
      Vector<double>       displacement, velocity, previous, previous_velocity,
        residual, internal_force, increment;
      std::vector<SymmetricTensor<2, 3>> strains, stresses;
      std::vector<double>                plastic_strains;
      double                             plastic_work = 0;
    };


    GeneralSpecimen::GeneralSpecimen(const Loading     &input,
                                     const unsigned int degree)
      : Specimen(input, degree)
      , uniaxial(input.loading == "axial strain path")
      , n_q(mesh.quadrature.size())
      , D(material.damping_tangent())
      , tangent_matrix(mesh.sparsity)
    {
      initialize_states(states);
      const unsigned int n_dofs = mesh.dof_handler.n_dofs();
      for (auto *vector : {&displacement,
                           &velocity,
                           &previous,
                           &previous_velocity,
                           &residual,
                           &internal_force,
                           &increment})
        vector->reinit(n_dofs);
    }


    void
    GeneralSpecimen::check(const Loading &input)
    {
      AssertThrow(input.loading != "axial strain path" ||
                    !input.axial_path.empty(),
                  ExcMessage("Material point/Axial strain path is empty."));
      AssertThrow(input.loading != "stress step",
                  ExcMessage(
                    "Specimen: the 'stress step' (creep) loading "
                    "needs a linear viscous material (Kelvin-Voigt)."));
    }


    AffineConstraints<double>
    GeneralSpecimen::make_constraints(const double t,
                                      const bool   homogeneous) const
    {
      AffineConstraints<double> constraints;
      if (uniaxial)
        {
          const double top =
            homogeneous ?
              0. :
              axial_strain(input.axial_path, input.ramp_time, t) * mesh.size;
          constrain_rollers(mesh.dof_handler, mesh.fe, constraints);
          VectorTools::interpolate_boundary_values(
            mesh.dof_handler,
            3,
            Functions::ConstantFunction<2>(top, 2),
            constraints,
            mesh.fe.component_mask(FEValuesExtractors::Scalar(1)));
        }
      else
        constrain_strain_history(t, homogeneous, constraints);
      constraints.close();
      return constraints;
    }


    double
    GeneralSpecimen::assemble(const AffineConstraints<double> &constraints,
                              const bool                       commit)
    {
      tangent_matrix = 0;
      residual       = 0;
      internal_force = 0;
      strains.clear();
      stresses.clear();
      plastic_strains.clear();
      double             step_plastic_work = 0;
      FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell);
      Vector<double>     cell_rhs(dofs_per_cell);
      std::vector<types::global_dof_index> dofs(dofs_per_cell);
      std::vector<SymmetricTensor<2, 3>>   shape_strain(dofs_per_cell);
      std::vector<Tensor<1, 2>>            values(n_q), rates(n_q);
      std::vector<Tensor<2, 2>>            gradients(n_q), rate_gradients(n_q);
      const SymmetricTensor<4, 3>          C = material.stiffness_tangent();
      for (const auto &cell : mesh.dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_values(displacement, values);
          fe_values[u].get_function_gradients(displacement, gradients);
          fe_values[u].get_function_values(velocity, rates);
          fe_values[u].get_function_gradients(velocity, rate_gradients);
          cell_matrix             = 0;
          cell_rhs                = 0;
          const auto point_states = states.get_data(cell);
          for (unsigned int q = 0; q < n_q; ++q)
            {
              const double r  = fe_values.quadrature_point(q)[0];
              const double dV = 2 * M_PI * r * fe_values.JxW(q);
              materials::QuadraturePointState &start = *point_states[q];
              const SymmetricTensor<2, 3>      eps =
                axisymmetric_strain(values[q], gradients[q], r);
              materials::QuadraturePointState end;
              SymmetricTensor<4, 3>           tangent;
              const SymmetricTensor<2, 3>     elastic_plastic =
                material.stress_update(start, eps, dt, end, tangent);
              const SymmetricTensor<2, 3> sigma =
                elastic_plastic +
                D * axisymmetric_strain(rates[q], rate_gradients[q], r);
              const SymmetricTensor<4, 3> A = tangent + 2 / dt * D;
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                shape_strain[i] =
                  axisymmetric_strain(fe_values[u].value(i, q),
                                      fe_values[u].gradient(i, q),
                                      r);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  for (unsigned int j = 0; j < dofs_per_cell; ++j)
                    cell_matrix(i, j) +=
                      (A * shape_strain[j]) * shape_strain[i] * dV;
                  cell_rhs(i) -= (sigma * shape_strain[i]) * dV;
                }
              if (commit)
                {
                  const SymmetricTensor<2, 3> elastic_start =
                    C * (start.strain - start.plastic_strain);
                  step_plastic_work +=
                    0.5 *
                    ((elastic_start + elastic_plastic) *
                     (end.plastic_strain - start.plastic_strain)) *
                    dV;
                  start = end;
                }
              strains.push_back(eps);
              stresses.push_back(sigma);
              plastic_strains.push_back(end.accumulated_plastic_strain);
            }
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs_per_cell; ++i)
            internal_force(dofs[i]) -= cell_rhs(i);
          constraints.distribute_local_to_global(
            cell_matrix, cell_rhs, dofs, tangent_matrix, residual);
        }
      return step_plastic_work;
    }


    void
    GeneralSpecimen::declare_history()
    {
      declare_mean_history();
      history.declare(
        {{"accumulated_plastic_strain",
          "1",
          "mean accumulated plastic strain over the quadrature points"},
         {"plastic_work",
          "J",
          "cumulative plastic work in the specimen, trapezoidal in the stress"},
         {"newton_iterations", "1", "Newton iterations of the step"}});
    }


    void
    GeneralSpecimen::record(const double t, const unsigned int iterations)
    {
      double mean_plastic = 0;
      for (const double p : plastic_strains)
        mean_plastic += p / plastic_strains.size();
      append_specimen_means(history, t, strains, stresses);
      history.append("accumulated_plastic_strain", mean_plastic);
      history.append("plastic_work", plastic_work);
      history.append("newton_iterations", iterations);
    }


    void
    GeneralSpecimen::set_initial_rate()
    {
      const double nu = material.poissons_ratio();
      if (uniaxial)
        {
          const double rate = input.axial_path.front() / input.ramp_time;
          VectorTools::interpolate(mesh.dof_handler,
                                   HomogeneousDisplacement(-nu * rate, rate),
                                   velocity);
        }
      else
        interpolate_initial_strain_rate(velocity);
    }


    unsigned int
    GeneralSpecimen::solve_step(const unsigned int step)
    {
      // Convergence: the out-of-balance force on the free degrees of
      // freedom below 1e-10 of the internal force (whose constrained
      // entries are the reactions), or exactly zero.
      const double       tolerance      = 1e-10;
      const unsigned int max_iterations = 50;
      const double       t              = step * dt;
      previous                          = displacement;
      previous_velocity                 = velocity;
      // Start from the last step's displacement with the new boundary
      // values; the iterations then correct the free degrees of freedom.
      make_constraints(t, false).distribute(displacement);
      const AffineConstraints<double> homogeneous = make_constraints(t, true);
      unsigned int                    iteration   = 0;
      for (;; ++iteration)
        {
          // v_{n+1} = 2/dt (u_{n+1} - u_n) - v_n
          velocity = displacement;
          velocity -= previous;
          velocity *= 2 / dt;
          velocity -= previous_velocity;
          assemble(homogeneous, false);
          const double norm = residual.l2_norm();
          if (norm <= tolerance * internal_force.l2_norm() || norm == 0)
            break;
          AssertThrow(iteration < max_iterations,
                      ExcMessage("Specimen: the Newton iteration of step " +
                                 std::to_string(step) + " (t = " +
                                 as_written(t) + " s) did not converge in " +
                                 std::to_string(max_iterations) +
                                 " iterations: out-of-balance force " +
                                 as_written(norm) + " N, criterion 1e-10 of " +
                                 as_written(internal_force.l2_norm()) + " N."));
          SparseDirectUMFPACK solver;
          solver.initialize(tangent_matrix);
          solver.vmult(increment, residual);
          homogeneous.distribute(increment);
          displacement += increment;
        }
      plastic_work += assemble(homogeneous, true);
      record(t, iteration);
      return iteration;
    }


    void
    GeneralSpecimen::run()
    {
      declare_history();
      set_initial_rate();
      assemble(make_constraints(0, true), false);
      record(0, 0);
      const unsigned int steps            = n_steps();
      unsigned int       total_iterations = 0;
      for (unsigned int step = 1; step <= steps; ++step)
        total_iterations += solve_step(step);
      write_results(steps,
                    ", general constitutive update",
                    ", " + std::to_string(total_iterations) +
                      " Newton iterations");
    }


    // The specimen of a linear material: per step one solve of
    // K_eff u = rhs with the material's constant tangents, the Maxwell
    // arms' history as a right-hand side from the quadrature-point states,
    // updated after the step.
    class LinearSpecimen : private Specimen
    {
    public:
      /// Refuses the loadings it cannot run, naming the entry.
      static void
      check(const Loading &input);

      LinearSpecimen(const Loading &input, const unsigned int degree);

      void
      run();

    private:
      AffineConstraints<double>
      make_constraints(const double t, const bool homogeneous) const;
      // One assembly: K_eff = C + C_internal + c D (c = 2/dt, or 1 and no C
      // for the initial rate), rhs = traction - history + D (c u_n + v_n).
      void
      assemble(const AffineConstraints<double> &constraints,
               const bool                       initial_rate);
      void
      declare_history();
      // Evaluates the step's strain and stress at the quadrature points
      // (stress from the state at the start of the step), then updates the
      // states; appends the means to the history.
      void
      evaluate_and_update(const double t, const bool update);
      // Initial state: unstrained; the initial rate from D v_0 = load
      // (creep) or the prescribed rate.
      void
      set_initial_rate();
      // The step to time t.
      void
      step(const double t);

      const std::vector<double> &stress_hat;
      const bool                 stress_controlled;
      const QGauss<1>            face_rule;
      FEFaceValues<2>            fe_face_values;
      CellDataStorage<Triangulation<2>::cell_iterator, SpecimenPointState>
                                  states;
      const SymmetricTensor<4, 3> C, D, C_internal;
      SparseMatrix<double>        system_matrix, damping_matrix;
      Vector<double>              displacement, velocity, rhs;
      double                      dissipated = 0;
    };


    void
    LinearSpecimen::check(const Loading &input)
    {
      const bool  stress_controlled = input.loading == "stress step";
      const auto &strain_hat        = input.strain_hat;
      const auto &stress_hat        = input.stress_hat;
      AssertThrow(stress_controlled ||
                    (strain_hat[2] == strain_hat[0] && strain_hat[3] == 0),
                  ExcMessage("Specimen: a homogeneous axisymmetric strain has "
                             "theta-theta = rr and no rz component; set "
                             "Material point/Strain accordingly."));
      AssertThrow(!stress_controlled ||
                    (stress_hat[0] == 0 && stress_hat[2] == 0 &&
                     stress_hat[3] == 0),
                  ExcMessage("Specimen: the stress step is uniaxial, only the "
                             "zz component of Material point/Stress may be "
                             "non-zero."));
      AssertThrow(!stress_controlled ||
                    input.material->damping_tangent().norm() > 0,
                  ExcMessage("Specimen: the 'stress step' (creep) loading "
                             "needs a viscous material (Kelvin-Voigt)."));
    }


    LinearSpecimen::LinearSpecimen(const Loading     &input,
                                   const unsigned int degree)
      : Specimen(input, degree)
      , stress_hat(input.stress_hat)
      , stress_controlled(input.loading == "stress step")
      , face_rule(face_quadrature(mesh.fe))
      , fe_face_values(mesh.fe,
                       face_rule,
                       update_values | update_quadrature_points |
                         update_JxW_values)
      , C(material.stiffness_tangent())
      , D(material.damping_tangent())
      , C_internal(material.internal_tangent(dt))
      , system_matrix(mesh.sparsity)
      , damping_matrix(mesh.sparsity)
      , displacement(mesh.dof_handler.n_dofs())
      , velocity(mesh.dof_handler.n_dofs())
      , rhs(mesh.dof_handler.n_dofs())
    {
      initialize_states(states);
    }


    AffineConstraints<double>
    LinearSpecimen::make_constraints(const double t,
                                     const bool   homogeneous) const
    {
      AffineConstraints<double> constraints;
      if (stress_controlled)
        constrain_rollers(mesh.dof_handler, mesh.fe, constraints);
      else
        constrain_strain_history(t, homogeneous, constraints);
      constraints.close();
      return constraints;
    }


    void
    LinearSpecimen::assemble(const AffineConstraints<double> &constraints,
                             const bool                       initial_rate)
    {
      system_matrix  = 0;
      damping_matrix = 0;
      rhs            = 0;
      FullMatrix<double> cell_matrix(dofs_per_cell, dofs_per_cell),
        cell_damping(dofs_per_cell, dofs_per_cell);
      Vector<double>                       cell_rhs(dofs_per_cell);
      std::vector<types::global_dof_index> dofs(dofs_per_cell);
      std::vector<SymmetricTensor<2, 3>>   strain(dofs_per_cell);
      const SymmetricTensor<4, 3>          A =
        initial_rate ? D : C + C_internal + 2 / dt * D;
      for (const auto &cell : mesh.dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          cell_matrix             = 0;
          cell_damping            = 0;
          cell_rhs                = 0;
          const auto point_states = states.get_data(cell);
          for (unsigned int q = 0; q < mesh.quadrature.size(); ++q)
            {
              const double r  = fe_values.quadrature_point(q)[0];
              const double dV = 2 * M_PI * r * fe_values.JxW(q);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                strain[i] = axisymmetric_strain(fe_values[u].value(i, q),
                                                fe_values[u].gradient(i, q),
                                                r);
              const SymmetricTensor<2, 3> history =
                initial_rate ?
                  SymmetricTensor<2, 3>() :
                  material.internal_stress_predictor(point_states[q]->internal,
                                                     point_states[q]->strain,
                                                     dt);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  for (unsigned int j = 0; j < dofs_per_cell; ++j)
                    {
                      cell_matrix(i, j) += (A * strain[j]) * strain[i] * dV;
                      cell_damping(i, j) += (D * strain[j]) * strain[i] * dV;
                    }
                  cell_rhs(i) -= (history * strain[i]) * dV;
                }
            }
          if (stress_controlled)
            for (const auto face : cell->face_indices())
              if (cell->face(face)->at_boundary() &&
                  cell->face(face)->boundary_id() == 3)
                {
                  fe_face_values.reinit(cell, face);
                  for (unsigned int q = 0; q < face_rule.size(); ++q)
                    for (unsigned int i = 0; i < dofs_per_cell; ++i)
                      cell_rhs(i) +=
                        stress_hat[1] * fe_face_values[u].value(i, q)[1] * 2 *
                        M_PI * fe_face_values.quadrature_point(q)[0] *
                        fe_face_values.JxW(q);
                }
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(
            cell_matrix, cell_rhs, dofs, system_matrix, rhs);
          damping_matrix.add(dofs, cell_damping);
        }
    }


    void
    LinearSpecimen::declare_history()
    {
      declare_mean_history();
      history.declare("internal_energy",
                      "J",
                      "energy stored in the Maxwell arms of the specimen");
      history.declare("dissipated_energy",
                      "J",
                      "cumulative dissipation in the Maxwell arms");
    }


    void
    LinearSpecimen::evaluate_and_update(const double t, const bool update)
    {
      std::vector<SymmetricTensor<2, 3>> strains, stresses;
      std::vector<Tensor<1, 2>>          values(mesh.quadrature.size()),
        rates(mesh.quadrature.size());
      std::vector<Tensor<2, 2>> gradients(mesh.quadrature.size()),
        rate_gradients(mesh.quadrature.size());
      double stored = 0;
      for (const auto &cell : mesh.dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          fe_values[u].get_function_values(displacement, values);
          fe_values[u].get_function_gradients(displacement, gradients);
          fe_values[u].get_function_values(velocity, rates);
          fe_values[u].get_function_gradients(velocity, rate_gradients);
          const auto point_states = states.get_data(cell);
          for (unsigned int q = 0; q < mesh.quadrature.size(); ++q)
            {
              const double                r  = fe_values.quadrature_point(q)[0];
              const double                dV = 2 * M_PI * r * fe_values.JxW(q);
              SpecimenPointState         &state = *point_states[q];
              const SymmetricTensor<2, 3> eps =
                axisymmetric_strain(values[q], gradients[q], r);
              SymmetricTensor<2, 3> sigma =
                C * eps +
                D * axisymmetric_strain(rates[q], rate_gradients[q], r);
              if (update)
                {
                  sigma += C_internal * eps +
                           material.internal_stress_predictor(state.internal,
                                                              state.strain,
                                                              dt);
                  dissipated += material.update_internal_variables(
                                  state.internal, state.strain, eps, dt) *
                                dV;
                  state.strain = eps;
                }
              stored += material.internal_energy(state.internal) * dV;
              strains.push_back(eps);
              stresses.push_back(sigma);
            }
        }
      append_specimen_means(history, t, strains, stresses);
      history.append("internal_energy", stored);
      history.append("dissipated_energy", dissipated);
    }


    void
    LinearSpecimen::set_initial_rate()
    {
      if (stress_controlled)
        {
          const AffineConstraints<double> constraints =
            make_constraints(0, true);
          assemble(constraints, true);
          SparseDirectUMFPACK solver;
          solver.solve(system_matrix, rhs);
          velocity = rhs;
          constraints.distribute(velocity);
        }
      else
        interpolate_initial_strain_rate(velocity);
    }


    void
    LinearSpecimen::step(const double t)
    {
      Vector<double> previous(displacement.size()), tmp(displacement.size());
      const AffineConstraints<double> constraints = make_constraints(t, false);
      assemble(constraints, false);
      // + D (2/dt u_n + v_n) for the trapezoidal strain rate.
      tmp = displacement;
      tmp *= 2 / dt;
      tmp += velocity;
      Vector<double> damping_force(displacement.size());
      damping_matrix.vmult(damping_force, tmp);
      constraints.condense(damping_force);
      rhs += damping_force;
      SparseDirectUMFPACK solver;
      solver.initialize(system_matrix);
      previous = displacement;
      solver.vmult(displacement, rhs);
      constraints.distribute(displacement);
      // v_{n+1} = 2/dt (u_{n+1} - u_n) - v_n
      tmp = displacement;
      tmp -= previous;
      tmp *= 2 / dt;
      tmp -= velocity;
      velocity = tmp;
      evaluate_and_update(t, true);
    }


    void
    LinearSpecimen::run()
    {
      declare_history();
      set_initial_rate();
      evaluate_and_update(0, false);
      const unsigned int steps = n_steps();
      for (unsigned int step_number = 1; step_number <= steps; ++step_number)
        step(step_number * dt);
      write_results(steps, "", "");
    }
  } // namespace


  void
  SpecimenTest::run_on_first_rank(ParameterHandler &prm)
  {
    const Loading      input      = read_loading(prm);
    const auto        &material   = input.material;
    const std::string &loading    = input.loading;
    const auto        &strain_hat = input.strain_hat;
    prm.enter_subsection("Mesh");
    const unsigned int degree = prm.get_integer("Polynomial degree");
    prm.leave_subsection();
    const bool stress_controlled = loading == "stress step";
    AssertThrow(loading != "strain path",
                ExcMessage("Specimen: the 'strain path' loading is one of the "
                           "material point analysis."));
    if (!material->is_linear() || loading == "axial strain path")
      {
        AssertThrow(loading == "axial strain path" || stress_controlled ||
                      (strain_hat[2] == strain_hat[0] && strain_hat[3] == 0),
                    ExcMessage(
                      "Specimen: a homogeneous axisymmetric strain has "
                      "theta-theta = rr and no rz component; set "
                      "Material point/Strain accordingly."));
        GeneralSpecimen::check(input);
        GeneralSpecimen specimen(input, degree);
        specimen.run();
        return;
      }
    LinearSpecimen::check(input);
    LinearSpecimen specimen(input, degree);
    specimen.run();
  }


  IMPACT_FEM_REGISTER_ANALYSIS(
    SpecimenTest,
    "specimen",
    4,
    "the same history on a homogeneous cylinder of the sphere's material, "
    "finite elements, quasi-static.")
} // namespace impact_fem
