#include <impact_fem/as_written.h>
#include <impact_fem/impact_problem.h>
#include <impact_fem/postprocess/cell_stress.h>
#include <impact_fem/postprocess/interface.h>

#include <deal.II/numerics/data_out.h>

#include <filesystem>
#include <fstream>
#include <optional>

namespace impact_fem
{
  namespace postprocess
  {
    /**
     * ParaView snapshots (.pvtu per snapshot, snapshots.pvd for the series)
     * of displacement, velocity and the cell-averaged stress (r, z, theta
     * components and von Mises) every 'Output/Snapshot interval' of
     * simulated time; none by default. With an elastic-plastic body also
     * the accumulated plastic strain (largest of the cell's quadrature
     * points: the plastic zone is not smeared out by averaging).
     */
    class Snapshots : public Interface
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.enter_subsection("Output");
        prm.declare_entry("Snapshot interval",
                          "0",
                          Patterns::Double(),
                          "Simulated time between ParaView snapshots [s], "
                          ">= 0; 0 writes none.");
        prm.leave_subsection();
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        prm.enter_subsection("Output");
        interval = prm.get_double("Snapshot interval");
        prm.leave_subsection();
        AssertThrow(interval >= 0,
                    ExcMessage("Output/Snapshot interval must not be negative, "
                               "got " +
                               as_written(interval) + " s."));
      }

      void
      initialize(const ImpactProblem &problem, History &) override
      {
        next = problem.stepper().time();
        if (interval > 0 &&
            Utilities::MPI::this_mpi_process(problem.communicator()) == 0)
          std::filesystem::create_directories(
            problem.scenario().output_directory + "/snapshots");
      }

      void
      execute(const ImpactProblem &problem, History &) override
      {
        const double time = problem.stepper().time();
        if (interval <= 0 || time < next - 1e-3 * problem.stepper().time_step())
          return;
        next += interval;
        write(problem, time);
      }

      void
      save(checkpoint::Writer &writer) const override
      {
        writer &next &records;
      }

      void
      load(checkpoint::Reader &reader, const ImpactProblem &) override
      {
        reader &next &records;
      }

    private:
      void
      write(const ImpactProblem &problem, const double time)
      {
        const auto &dof_handler = problem.dofs();
        std::vector<DataComponentInterpretation::DataComponentInterpretation>
          vector_field(
            2, DataComponentInterpretation::component_is_part_of_vector);
        DataOut<2> data_out;
        data_out.attach_dof_handler(dof_handler);
        data_out.add_data_vector(problem.ghosted_displacement(),
                                 std::vector<std::string>(2, "displacement"),
                                 DataOut<2>::type_dof_data,
                                 vector_field);
        data_out.add_data_vector(problem.ghosted_velocity(),
                                 std::vector<std::string>(2, "velocity"),
                                 DataOut<2>::type_dof_data,
                                 vector_field);
        const unsigned int n_cells =
          dof_handler.get_triangulation().n_active_cells();
        Vector<float>              body(n_cells);
        std::vector<Vector<float>> stress(5, Vector<float>(n_cells));
        if (!cell_stress)
          cell_stress.emplace(problem, [](const auto &) { return true; });
        cell_stress->evaluate(
          problem,
          [&](const CellStress::CellIterator &cell,
              const std::vector<Point<2>> &,
              const std::vector<SymmetricTensor<2, 3>> &sigmas) {
            const unsigned int index = cell->active_cell_index();
            body[index]              = cell->material_id();
            for (const auto &sigma : sigmas)
              {
                const double weight = 1. / sigmas.size();
                stress[0][index] += weight * sigma[0][0];
                stress[1][index] += weight * sigma[1][1];
                stress[2][index] += weight * sigma[2][2];
                stress[3][index] += weight * sigma[0][1];
                stress[4][index] += weight * materials::von_mises(sigma);
              }
          });
        data_out.add_data_vector(body, "body");
        Vector<float> plastic_strain(n_cells);
        const auto   &history = problem.internal_variables();
        if (history.nonlinear())
          {
            for (const auto &cell : dof_handler.active_cell_iterators())
              if (cell->is_locally_owned())
                for (const auto &state : history.states(cell))
                  plastic_strain[cell->active_cell_index()] =
                    std::max<float>(plastic_strain[cell->active_cell_index()],
                                    state->accumulated_plastic_strain);
            data_out.add_data_vector(plastic_strain,
                                     "accumulated_plastic_strain");
          }
        const char *names[5] = {"stress_rr",
                                "stress_zz",
                                "stress_thetatheta",
                                "stress_rz",
                                "von_mises"};
        for (unsigned int c = 0; c < 5; ++c)
          data_out.add_data_vector(stress[c], names[c]);
        data_out.build_patches(problem.geometric_mapping(),
                               dof_handler.get_fe().degree,
                               DataOut<2>::curved_inner_cells);

        const std::string &directory = problem.scenario().output_directory;
        records.emplace_back(time,
                             "snapshots/" + data_out.write_vtu_with_pvtu_record(
                                              directory + "/snapshots/",
                                              "solution",
                                              records.size(),
                                              problem.communicator(),
                                              4));
        if (Utilities::MPI::this_mpi_process(problem.communicator()) == 0)
          {
            std::ofstream pvd(directory + "/snapshots.pvd");
            DataOutBase::write_pvd_record(pvd, records);
          }
      }

      double                                      interval = 0, next = 0;
      std::vector<std::pair<double, std::string>> records; // (time, .pvtu)
      std::optional<CellStress>                   cell_stress;
    };
    IMPACT_FEM_REGISTER_POSTPROCESSOR(
      Snapshots,
      "snapshots",
      "ParaView snapshots every Output/Snapshot "
      "interval")
  } // namespace postprocess
} // namespace impact_fem
