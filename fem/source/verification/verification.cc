#include <impact_fem/discretisation/automatic_discretisation.h>
#include <impact_fem/parameters.h>
#include <impact_fem/as_written.h>
#include <impact_fem/impact_problem.h>
#include <impact_fem/verification/grid_convergence.h>
#include <impact_fem/verification/verification.h>

#include <deal.II/base/utilities.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

namespace impact_fem
{
  namespace verification
  {
    namespace
    {
      // The quantities whose uncertainty is reported, with their units.
      const std::pair<const char *, const char *> quantities[] = {
        {"contact_time", "s"},
        {"force_max", "N"},
        {"time_force_max", "s"},
        {"approach_max", "m"},
        {"restitution", "1"}};

      // The time integration and the contact are second order.
      constexpr double formal_order = 2;

      nlohmann::json
      number(const double x)
      {
        return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
      }

      nlohmann::json
      read_json(const std::string &name)
      {
        std::ifstream in(name);
        AssertThrow(in, ExcMessage("Verification: cannot read " + name + "."));
        return nlohmann::json::parse(in);
      }

      /// Set "Section/Entry" to a number.
      void
      set_number(ParameterHandler  &prm,
                 const std::string &section,
                 const std::string &entry,
                 const double       value)
      {
        prm.enter_subsection(section);
        std::ostringstream text;
        text << std::setprecision(17) << value;
        prm.set(entry, text.str());
        prm.leave_subsection();
      }

      double
      get_number(ParameterHandler  &prm,
                 const std::string &section,
                 const std::string &entry)
      {
        prm.enter_subsection(section);
        const double value = prm.get_double(entry);
        prm.leave_subsection();
        return value;
      }
    } // namespace


    void
    declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Verification");
      prm.declare_entry("Verify",
                        "false",
                        Patterns::Bool(),
                        "Verify every run (the command-line option --verify): "
                        "two systematically coarser discretisations besides "
                        "the run, and verification.json with the observed "
                        "order, the Richardson extrapolation and the grid "
                        "convergence index of each result (fem/README.md).");
      prm.declare_entry("Refinement ratio",
                        "1.5",
                        Patterns::Double(),
                        "Ratio r of the element sizes and time steps of "
                        "neighbouring levels [-], in [1.5, 3] (Roache: at "
                        "least 1.3; 1.5 here).");
      prm.declare_entry("Meshes",
                        "remeshed",
                        Patterns::Selection("remeshed|nested"),
                        "How the coarser levels are meshed: 'remeshed' "
                        "(gmsh meshes each level anew with its sizes times "
                        "r: the meshes are not nested, so where the nodes "
                        "fall against the contact radius changes from level "
                        "to level) or 'nested' (each coarser level has one "
                        "Mesh/Contact refinement fewer: the levels are "
                        "nested within the contact surface radius; needs "
                        "Refinement ratio = 2 and Mesh/Contact refinements "
                        ">= 2; the mesh beyond the contact surface radius is "
                        "the same on all levels).");
      prm.leave_subsection();
    }


    bool
    enabled(ParameterHandler &prm)
    {
      prm.enter_subsection("Verification");
      const bool verify = prm.get_bool("Verify");
      prm.leave_subsection();
      return verify;
    }


    void
    verify(ParameterHandler &prm,
           const MPI_Comm    comm,
           std::ostream     &log,
           const bool        fine_done)
    {
      const bool   root = Utilities::MPI::this_mpi_process(comm) == 0;
      const double r    = get_number(prm, "Verification", "Refinement ratio");
      AssertThrow(r >= 1.5 && r <= 3,
                  ExcMessage("Verification/Refinement ratio must lie in [1.5, "
                             "3], got " +
                             as_written(r) + "."));
      prm.enter_subsection("Verification");
      const bool nested = prm.get("Meshes") == "nested";
      prm.leave_subsection();
      prm.enter_subsection("Mesh");
      const int refinements = prm.get_integer("Contact refinements");
      prm.leave_subsection();
      AssertThrow(!nested || r == 2,
                  ExcMessage("Verification/Refinement ratio must be 2 with "
                             "Verification/Meshes = nested (each coarser "
                             "level has one contact refinement fewer), got " +
                             as_written(r) + "."));
      AssertThrow(!nested || refinements >= 2,
                  ExcMessage("Verification/Meshes = nested needs Mesh/Contact "
                             "refinements >= 2 on the fine level (the coarsest "
                             "has two fewer), got " +
                             std::to_string(refinements) + "."));
      prm.enter_subsection("Output");
      const std::string directory = prm.get("Directory");
      prm.leave_subsection();

      // The fine level's contact element size and step count, "auto"
      // resolved as the run resolves them (the coarser levels scale them).
      const Parameters scenario(prm);
      double           hc = 0;
      {
        bool automatic = false;
        prm.enter_subsection("Mesh");
        hc = discretisation::number_or_auto(prm,
                                            "Contact element size",
                                            "Mesh/Contact element size",
                                            0,
                                            automatic);
        prm.leave_subsection();
        if (automatic)
          hc = discretisation::AutomaticDiscretisation(
                 scenario.expected_contact,
                 scenario.geometry.sphere_radius,
                 scenario.hertz.contact_time())
                 .contact_element_size;
      }
      const double hmax = get_number(prm, "Mesh", "Maximum element size");
      const double g    = get_number(prm, "Mesh", "Growth factor");
      const double across =
        get_number(prm, "Mesh", "Elements across the plate thickness");
      const double dt = get_number(prm, "Time integration", "Time step");
      const double n  = scenario.steps_per_contact_time;
      AssertThrow(dt > 0 || n / (r * r) >= 10,
                  ExcMessage("Verification: the coarsest level would have "
                             "fewer than 10 steps per contact time; raise "
                             "Time integration/Steps per contact time to at "
                             "least " +
                             as_written(10 * r * r) + "."));

      // The entries the levels change, as text, to restore them exactly.
      const std::pair<const char *, const char *> changed[] = {
        {"Mesh", "Contact element size"},
        {"Mesh", "Maximum element size"},
        {"Mesh", "Growth factor"},
        {"Mesh", "Elements across the plate thickness"},
        {"Mesh", "Contact refinements"},
        {"Time integration", "Time step"},
        {"Time integration", "Steps per contact time"},
        {"Output", "Directory"}};
      std::vector<std::string> original;
      for (const auto &[section, entry] : changed)
        {
          prm.enter_subsection(section);
          original.push_back(prm.get(entry));
          prm.leave_subsection();
        }
      auto restore = [&]() {
        for (unsigned int i = 0; i < original.size(); ++i)
          {
            prm.enter_subsection(changed[i].first);
            prm.set(changed[i].second, original[i]);
            prm.leave_subsection();
          }
      };

      std::vector<nlohmann::json> levels;
      for (unsigned int level = 0; level < 3; ++level)
        {
          const double      scale = std::pow(r, level);
          const std::string level_directory =
            level == 0 ?
              directory :
              directory + "/verification/level" + std::to_string(level);
          // The level's discretisation: nested levels drop contact
          // refinements of one mesh, remeshed ones scale the size field.
          const int level_refinements = refinements - static_cast<int>(level);
          const double level_hc =
            nested ? hc / std::pow(2., level_refinements) : hc * scale;
          const double level_hmax = nested ? hmax : hmax * scale;
          const double level_g    = nested ? g : 1 + (g - 1) * scale;
          if (!(level == 0 && fine_done))
            {
              if (level > 0)
                {
                  if (nested)
                    {
                      prm.enter_subsection("Mesh");
                      prm.set("Contact refinements",
                              std::to_string(level_refinements));
                      prm.leave_subsection();
                    }
                  else
                    {
                      set_number(prm, "Mesh", "Contact element size", level_hc);
                      set_number(prm,
                                 "Mesh",
                                 "Maximum element size",
                                 level_hmax);
                      set_number(prm, "Mesh", "Growth factor", level_g);
                      set_number(prm,
                                 "Mesh",
                                 "Elements across the plate thickness",
                                 std::max(1.0, across / scale));
                    }
                  if (dt > 0)
                    set_number(prm,
                               "Time integration",
                               "Time step",
                               dt * scale);
                  else
                    set_number(prm,
                               "Time integration",
                               "Steps per contact time",
                               n / scale);
                  prm.enter_subsection("Output");
                  prm.set("Directory", level_directory);
                  prm.leave_subsection();
                }
              if (root)
                log << "verification: level " << level
                    << (nested ?
                          " (contact refinements " +
                            std::to_string(level_refinements) + ", step x " :
                          std::string(" (sizes and step x "))
                    << scale << ") -> " << level_directory << std::endl;
              std::unique_ptr<ImpactProblem> problem;
              try
                {
                  problem = std::make_unique<ImpactProblem>(prm, comm, log);
                  problem->run();
                  problem.reset();
                }
              catch (...)
                {
                  problem.reset();
                  restore();
                  throw;
                }
              restore();
            }
          MPI_Barrier(comm);
          const nlohmann::json summary =
            read_json(level_directory + "/summary.json");
          levels.push_back(
            {{"name",
              level == 0 ? "fine" :
              level == 1 ? "medium" :
                           "coarse"},
             {"directory",
              level == 0 ? "." : "verification/level" + std::to_string(level)},
             {"scale", scale},
             {"contact_element_size", level_hc},
             {"maximum_element_size", level_hmax},
             {"growth_factor", level_g},
             {"time_step", summary["time_step"]},
             {"cells", summary["cells"]},
             {"dofs", summary["dofs"]},
             {"steps", summary["steps"]},
             {"wall_time", summary["wall_time"]},
             {"summary", summary}});
        }
      if (!root)
        return;

      nlohmann::json     result = {{"format", "impact-verification"},
                                   {"format_version", 1},
                                   {"refinement_ratio", r},
                                   {"meshes", nested ? "nested" : "remeshed"},
                                   {"formal_order", formal_order},
                                   {"levels", levels}};
      std::ostringstream table;
      table << "verification (r = " << r
            << "; GCI of the fine level, Fs = 1.25):\n"
            << std::setw(16) << "quantity" << std::setw(16) << "fine"
            << std::setw(16) << "medium" << std::setw(16) << "coarse"
            << std::setw(8) << "order" << std::setw(16) << "extrapolated"
            << std::setw(12) << "GCI"
            << "  convergence\n";
      for (const auto &[name, unit] : quantities)
        {
          nlohmann::json entry = {{"unit", unit}};
          double         f[3];
          bool           finite = true;
          for (unsigned int level = 0; level < 3; ++level)
            {
              const auto &value = levels[level]["summary"][name];
              finite &= value.is_number();
              f[level] = value.is_number() ? value.get<double>() : 0.;
            }
          entry["fine"]   = number(finite ? f[0] : NAN);
          entry["medium"] = number(finite ? f[1] : NAN);
          entry["coarse"] = number(finite ? f[2] : NAN);
          if (finite)
            {
              const GridConvergence c =
                grid_convergence(f[0], f[1], f[2], r, formal_order);
              entry["observed_order"]    = number(c.observed_order);
              entry["extrapolated"]      = number(c.extrapolated);
              entry["gci_fine"]          = number(c.gci_relative);
              entry["gci_fine_absolute"] = number(c.gci_absolute);
              entry["convergence"]       = c.convergence;
              table << std::setprecision(8) << std::setw(16) << name
                    << std::setw(16) << f[0] << std::setw(16) << f[1]
                    << std::setw(16) << f[2] << std::setprecision(3)
                    << std::setw(8) << c.observed_order << std::setprecision(8)
                    << std::setw(16) << c.extrapolated << std::setprecision(3)
                    << std::setw(11) << c.gci_relative * 100 << "%  "
                    << c.convergence << "\n";
            }
          else
            {
              for (const char *key : {"observed_order",
                                      "extrapolated",
                                      "gci_fine",
                                      "gci_fine_absolute"})
                entry[key] = nullptr;
              entry["convergence"] = "undefined";
              table << std::setw(16) << name
                    << "  not defined on every level\n";
            }
          result["quantities"][name] = entry;
        }
      const std::string file = directory + "/verification.json";
      {
        std::ofstream out(file + ".tmp");
        out << std::setw(2) << result << std::endl;
      }
      std::filesystem::rename(file + ".tmp", file);
      log << table.str() << "verification: " << file << std::endl;
    }
  } // namespace verification
} // namespace impact_fem
