#include <impact_fem/impact_problem.h>
#include <impact_fem/postprocess/cell_stress.h>
#include <impact_fem/postprocess/interface.h>
#include <impact_fem/result_files.h>

#include <deal.II/base/mpi.h>

#include <iomanip>
#include <optional>
#include <sstream>

namespace impact_fem
{
  namespace postprocess
  {
    /**
     * The yield check: the largest von Mises stress of each body (total
     * stress: elastic, viscous, Maxwell arms) and where it is, per step;
     * over the run its peak and the first time and place the body's yield
     * strength was exceeded. Only the cells within two contact surface radii
     * of the contact point are looked at: the stress peaks there (Hertz:
     * 0.48 a below the surface), the rest of the bodies only carries the
     * much weaker radiated waves.
     */
    class Stress : public Interface
    {
    public:
      static void
      declare_parameters(ParameterHandler &)
      {}

      void
      initialize(const ImpactProblem &problem, History &history) override
      {
        std::vector<History::Column> quantities = {
          {"max_von_mises",
           "Pa",
           "largest von Mises stress in both bodies within 2 contact surface "
           "radii of the contact point"},
          {"max_von_mises_r", "m", "radial position of max_von_mises"},
          {"max_von_mises_z",
           "m",
           "axial position of max_von_mises (reference configuration)"}};
        for (const unsigned int body : {sphere, plate})
          {
            const std::string name =
              std::string("max_von_mises_") + body_name(body);
            quantities.push_back(
              {name,
               "Pa",
               std::string("largest von Mises stress in the ") +
                 body_name(body) + " (same zone)"});
            quantities.push_back(
              {name + "_r", "m", "radial position of " + name});
            quantities.push_back(
              {name + "_z",
               "m",
               "axial position of " + name + " (reference configuration)"});
          }
        history.declare(quantities);

        const double zone =
          2 * problem.mesh_parameters().contact_surface_radius;
        const Point<2> contact_points[2] = {
          Point<2>(0, 0), Point<2>(0, problem.scenario().geometry.initial_gap)};
        cell_stress.emplace(problem, [&](const CellStress::CellIterator &cell) {
          return std::min(cell->center().distance(contact_points[0]),
                          cell->center().distance(contact_points[1])) < zone;
        });
      }

      void
      execute(const ImpactProblem &problem, History &history) override
      {
        double   body_max[2] = {0, 0};
        Point<2> body_location[2];
        cell_stress->evaluate(
          problem,
          [&](const CellStress::CellIterator           &cell,
              const std::vector<Point<2>>              &points,
              const std::vector<SymmetricTensor<2, 3>> &stress) {
            const unsigned int body =
              cell->material_id() == body_ids::sphere ? sphere : plate;
            for (unsigned int q = 0; q < stress.size(); ++q)
              {
                const double s = materials::von_mises(stress[q]);
                if (s > body_max[body])
                  {
                    body_max[body]      = s;
                    body_location[body] = points[q];
                  }
              }
          });
        const MPI_Comm comm = problem.communicator();
        const double   time = problem.stepper().time();
        for (const unsigned int body : {sphere, plate})
          {
            // The location travels with the rank that holds the maximum.
            const double global = Utilities::MPI::max(body_max[body], comm);
            const unsigned int holder =
              Utilities::MPI::min(body_max[body] == global ?
                                    Utilities::MPI::this_mpi_process(comm) :
                                    Utilities::MPI::n_mpi_processes(comm),
                                  comm);
            body_location[body] =
              Utilities::MPI::broadcast(comm, body_location[body], holder);
            body_max[body] = global;
            Peak &p        = peak[body];
            if (global > p.value)
              {
                p.value    = global;
                p.time     = time;
                p.location = body_location[body];
              }
            const double limit = problem.scenario().yield_strength[body];
            if (limit > 0 && global > limit && p.first_yield_time < 0)
              {
                p.first_yield_time     = time;
                p.first_yield_location = body_location[body];
              }
          }
        const unsigned int larger =
          body_max[plate] > body_max[sphere] ? plate : sphere;
        history.append("max_von_mises", body_max[larger]);
        history.append("max_von_mises_r", body_location[larger][0]);
        history.append("max_von_mises_z", body_location[larger][1]);
        for (const unsigned int body : {sphere, plate})
          {
            const std::string name =
              std::string("max_von_mises_") + body_name(body);
            history.append(name, body_max[body]);
            history.append(name + "_r", body_location[body][0]);
            history.append(name + "_z", body_location[body][1]);
          }
      }

      void
      finalize(const ImpactProblem &problem,
               const History &,
               nlohmann::json &summary,
               std::ostream   &report) override
      {
        // The viscoelastic model holds only below the elastic limit.
        bool any_limit = false, exceeded_any = false;
        auto optional = [](const bool has, const auto value) {
          return has ? nlohmann::json(value) : nlohmann::json(nullptr);
        };
        for (const unsigned int body : {sphere, plate})
          {
            const std::string name  = body_name(body);
            const Peak       &p     = peak[body];
            const double      limit = problem.scenario().yield_strength[body];
            const bool        has_limit = limit > 0;
            const bool        exceeded  = has_limit && p.first_yield_time >= 0;
            any_limit |= has_limit;
            exceeded_any |= exceeded;
            summary[result_files::von_mises_max_prefix + name] = p.value;
            summary["von_mises_max_" + name + "_time"]         = p.time;
            summary["von_mises_max_" + name + "_r"]            = p.location[0];
            summary["von_mises_max_" + name + "_z"]            = p.location[1];
            summary[result_files::yield_strength_prefix + name] =
              optional(has_limit, limit);
            summary["yield_exceeded_" + name] = optional(has_limit, exceeded);
            summary["yield_time_" + name] =
              optional(exceeded, p.first_yield_time);
            summary["yield_r_" + name] =
              optional(exceeded, p.first_yield_location[0]);
            summary["yield_z_" + name] =
              optional(exceeded, p.first_yield_location[1]);
            std::ostringstream line;
            line << std::setprecision(4) << "  von Mises " << name << " max "
                 << p.value / 1e9 << " GPa at t = " << p.time * 1e6
                 << " us, (r, z) = (" << p.location[0] * 1e3 << ", "
                 << p.location[1] * 1e3 << ") mm";
            if (exceeded)
              line << "; YIELD STRENGTH " << limit / 1e9
                   << " GPa EXCEEDED from t = " << p.first_yield_time * 1e6
                   << " us at (" << p.first_yield_location[0] * 1e3 << ", "
                   << p.first_yield_location[1] * 1e3 << ") mm";
            else if (has_limit)
              line << " (below the yield strength " << limit / 1e9 << " GPa)";
            report << line.str() << "\n";
          }
        summary[result_files::yield_exceeded_key] =
          optional(any_limit, exceeded_any);
        summary[result_files::max_von_mises_key] =
          std::max(peak[sphere].value, peak[plate].value);
      }

      void
      save(checkpoint::Writer &writer) const override
      {
        for (const auto &p : peak)
          {
            std::vector<double> values = {p.value,
                                          p.time,
                                          p.location[0],
                                          p.location[1],
                                          p.first_yield_time,
                                          p.first_yield_location[0],
                                          p.first_yield_location[1]};
            writer             &values;
          }
      }

      void
      load(checkpoint::Reader &reader, const ImpactProblem &) override
      {
        for (auto &p : peak)
          {
            std::vector<double> values;
            reader             &values;
            AssertThrow(values.size() == 7,
                        ExcMessage("The checkpoint's stress peaks are "
                                   "damaged."));
            p.value                = values[0];
            p.time                 = values[1];
            p.location             = Point<2>(values[2], values[3]);
            p.first_yield_time     = values[4];
            p.first_yield_location = Point<2>(values[5], values[6]);
          }
      }

    private:
      struct Peak
      {
        double   value = 0, time = 0;
        Point<2> location;
        double   first_yield_time = -1;
        Point<2> first_yield_location;
      };
      Peak                      peak[2];
      std::optional<CellStress> cell_stress;
    };
    IMPACT_FEM_REGISTER_POSTPROCESSOR(Stress,
                                      "stress",
                                      "von Mises stress of each body near the "
                                      "contact and the yield check")
  } // namespace postprocess
} // namespace impact_fem
