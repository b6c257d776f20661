#include <impact_fem/discretisation/automatic_discretisation.h>
#include <impact_fem/parameters.h>
#include <impact_fem/as_written.h>
#include <impact_fem/campaign/run_identity.h>
#include <impact_fem/impact_problem.h>
#include <impact_fem/result_files.h>
#include <impact_fem/mesh/sphere_plate_mesh.h>
#include <impact_fem/verification/grid_convergence.h>
#include <impact_fem/verification/verification.h>

#include <deal.II/base/utilities.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>
#include <utility>
#include <vector>

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

      /// The text of a file, empty if it cannot be read.
      std::string
      text_of(const std::string &name)
      {
        std::ifstream      in(name);
        std::ostringstream text;
        text << in.rdbuf();
        return in ? text.str() : std::string();
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


      /// The discretisation of the fine level (the run itself), from which
      /// the coarser levels are derived.
      struct FineLevel
      {
        double       r;           ///< refinement ratio
        bool         nested;      ///< Verification/Meshes = nested
        int          refinements; ///< Mesh/Contact refinements
        std::string  directory;   ///< Output/Directory
        double       hc;          ///< contact element size, "auto" resolved
        unsigned int surface_refinements; ///< "auto" resolved
        double       hmax;
        double       g;             ///< growth factor
        double       across;        ///< elements across the plate thickness
        double       dt;            ///< time step, 0: steps per contact time
        double       n;             ///< steps per contact time, "auto" resolved
        double       sub_steps = 1; ///< sub-steps at contact entry, as run
      };


      // The fine level's mesh entries, "auto" resolved by the mesh itself as
      // the run resolves them. The coarser levels scale its contact element
      // size and keep its contact surface refinements, so that their contact
      // nodes lie r^k times the fine level's apart (left "auto", a level
      // whose size is given would not be refined: the rule refines only a
      // mesh it sized itself).
      SpherePlateMesh
      fine_mesh(ParameterHandler &prm, const Parameters &scenario)
      {
        SpherePlateMesh mesh;
        mesh.parse_parameters(prm, scenario.geometry, [&]() {
          return discretisation::AutomaticDiscretisation(
            scenario.expected_contact,
            scenario.geometry.sphere_radius,
            scenario.hertz.contact_time());
        });
        return mesh;
      }


      // Checked before any level runs: a coarse level that cannot be made
      // is known before the fine one is paid for.
      FineLevel
      read_fine_level(ParameterHandler &prm)
      {
        FineLevel fine;
        fine.r = get_number(prm, "Verification", "Refinement ratio");
        AssertThrow(fine.r >= 1.5 && fine.r <= 3,
                    ExcMessage("Verification/Refinement ratio must lie in "
                               "[1.5, 3], got " +
                               as_written(fine.r) + "."));
        prm.enter_subsection("Verification");
        fine.nested = prm.get("Meshes") == "nested";
        prm.leave_subsection();
        prm.enter_subsection("Mesh");
        fine.refinements = prm.get_integer("Contact refinements");
        prm.leave_subsection();
        AssertThrow(!fine.nested || fine.r == 2,
                    ExcMessage("Verification/Refinement ratio must be 2 with "
                               "Verification/Meshes = nested (each coarser "
                               "level has one contact refinement fewer), "
                               "got " +
                               as_written(fine.r) + "."));
        AssertThrow(!fine.nested || fine.refinements >= 2,
                    ExcMessage("Verification/Meshes = nested needs "
                               "Mesh/Contact refinements >= 2 on the fine "
                               "level (the coarsest has two fewer), got " +
                               std::to_string(fine.refinements) + "."));
        prm.enter_subsection("Output");
        fine.directory = prm.get("Directory");
        prm.leave_subsection();

        const Parameters      scenario(prm, ImpactProblem::expected_contact);
        const SpherePlateMesh mesh = fine_mesh(prm, scenario);
        fine.hc                    = mesh.contact_element_size;
        fine.surface_refinements   = mesh.contact_surface_refinements;
        fine.hmax = get_number(prm, "Mesh", "Maximum element size");
        fine.g    = get_number(prm, "Mesh", "Growth factor");
        fine.across =
          get_number(prm, "Mesh", "Elements across the plate thickness");
        fine.dt        = get_number(prm, "Time integration", "Time step");
        fine.n         = scenario.steps_per_contact_time;
        fine.sub_steps = scenario.entry_sub_steps;
        AssertThrow(fine.dt > 0 || fine.n / (fine.r * fine.r) >= 10,
                    ExcMessage("Verification: the coarsest level would have "
                               "fewer than 10 steps per contact time; raise "
                               "Time integration/Steps per contact time to "
                               "at least " +
                               as_written(10 * fine.r * fine.r) + "."));
        return fine;
      }


      /// The value of the discretisation entry @p path (e.g. "Mesh/Contact
      /// surface refinements") a run's summary records, or @p otherwise when
      /// it records none.
      double
      discretisation_entry_of(const nlohmann::json &summary,
                              const std::string    &path,
                              const double          otherwise)
      {
        // The entry's name is one reference token: the library escapes its
        // slashes (and any '~').
        const nlohmann::json::json_pointer value =
          nlohmann::json::json_pointer("/discretisation/entries") / path /
          "value";
        return summary.contains(value) && summary[value].is_number() ?
                 summary[value].get<double>() :
                 otherwise;
      }


      /// One level of the three: 0 fine (the run), 1 medium, 2 coarse.
      struct Level
      {
        unsigned int index;
        double       scale; ///< r^index
        std::string  relative_directory;
        std::string  directory;
        int          refinements; ///< contact refinements when nested
        double       hc;
        double       hmax;
        double       g;
      };


      // Nested levels drop contact refinements of one mesh, remeshed ones
      // scale the size field.
      Level
      level_of(const FineLevel &fine, const unsigned int index)
      {
        Level level;
        level.index = index;
        level.scale = std::pow(fine.r, index);
        level.relative_directory =
          index == 0 ? "." : "verification/level" + std::to_string(index);
        level.directory   = index == 0 ?
                              fine.directory :
                              fine.directory + "/" + level.relative_directory;
        level.refinements = fine.refinements - static_cast<int>(index);
        level.hc   = fine.nested ? fine.hc / std::pow(2., level.refinements) :
                                   fine.hc * level.scale;
        level.hmax = fine.nested ? fine.hmax : fine.hmax * level.scale;
        level.g    = fine.nested ? fine.g : 1 + (fine.g - 1) * level.scale;
        return level;
      }


      /// A coarser level's entries: its mesh, its time step, its directory.
      void
      set_level_parameters(ParameterHandler &prm,
                           const FineLevel  &fine,
                           const Level      &level)
      {
        prm.enter_subsection("Mesh");
        prm.set("Contact surface refinements",
                std::to_string(fine.surface_refinements));
        if (fine.nested)
          prm.set("Contact refinements", std::to_string(level.refinements));
        prm.leave_subsection();
        if (!fine.nested)
          {
            set_number(prm, "Mesh", "Contact element size", level.hc);
            set_number(prm, "Mesh", "Maximum element size", level.hmax);
            set_number(prm, "Mesh", "Growth factor", level.g);
            set_number(prm,
                       "Mesh",
                       "Elements across the plate thickness",
                       std::max(1.0, fine.across / level.scale));
          }
        if (fine.dt > 0)
          set_number(prm,
                     "Time integration",
                     "Time step",
                     fine.dt * level.scale);
        else
          set_number(prm,
                     "Time integration",
                     "Steps per contact time",
                     fine.n / level.scale);
        set_number(prm,
                   "Time integration",
                   "Sub-steps at contact entry",
                   fine.sub_steps);
        prm.enter_subsection("Output");
        prm.set("Directory", level.directory);
        prm.leave_subsection();
      }


      /// The entries the levels change, kept as text to restore them exactly
      /// after each level (the caller's handler is the fine level's).
      class ChangedEntries
      {
      public:
        explicit ChangedEntries(ParameterHandler &prm)
          : prm(prm)
        {
          for (const auto &[section, entry] : entries)
            {
              prm.enter_subsection(section);
              original.push_back(prm.get(entry));
              prm.leave_subsection();
            }
        }

        void
        restore()
        {
          for (unsigned int i = 0; i < original.size(); ++i)
            {
              prm.enter_subsection(entries[i].first);
              prm.set(entries[i].second, original[i]);
              prm.leave_subsection();
            }
        }

      private:
        static constexpr std::pair<const char *, const char *> entries[] = {
          {"Mesh", "Contact element size"},
          {"Mesh", "Maximum element size"},
          {"Mesh", "Growth factor"},
          {"Mesh", "Elements across the plate thickness"},
          {"Mesh", "Contact refinements"},
          {"Mesh", "Contact surface refinements"},
          {"Time integration", "Time step"},
          {"Time integration", "Steps per contact time"},
          {"Time integration", "Sub-steps at contact entry"},
          {"Output", "Directory"}};

        ParameterHandler        &prm;
        std::vector<std::string> original;
      };


      /// Runs one level into its directory; the entries are restored however
      /// the run ends.
      void
      run_level(ParameterHandler &prm,
                const MPI_Comm    comm,
                std::ostream     &log,
                const FineLevel  &fine,
                const Level      &level,
                ChangedEntries   &changed)
      {
        if (level.index > 0)
          set_level_parameters(prm, fine, level);
        // A coarser level made before with the same entries (its
        // parameters.prm, the run identity of a campaign run) and complete
        // is kept: a verification stopped in its last level keeps the
        // others, and its levels can be made in separate sessions.
        const bool         root = Utilities::MPI::this_mpi_process(comm) == 0;
        std::ostringstream parameters;
        prm.print_parameters(parameters, ParameterHandler::ShortPRM);
        const std::string prm_file = level.directory + "/parameters.prm";
        bool              kept     = false;
        if (level.index > 0 && root)
          try
            {
              kept = run_identity::of(text_of(prm_file)) ==
                       run_identity::of(parameters.str()) &&
                     read_json(level.directory + "/summary.json")
                       .value(result_files::complete_key, false);
            }
          catch (...)
            {
              kept = false;
            }
        kept = Utilities::MPI::broadcast(comm, kept, 0);
        if (kept)
          {
            if (root)
              log << "verification: level " << level.index
                  << " kept: made before with the same entries ("
                  << level.directory << ")" << std::endl;
            changed.restore();
            return;
          }
        if (level.index > 0 && root)
          {
            std::filesystem::create_directories(level.directory);
            std::filesystem::remove(level.directory + "/summary.json");
            const std::string temporary = prm_file + ".tmp";
            std::ofstream(temporary) << parameters.str();
            std::filesystem::rename(temporary, prm_file);
          }
        MPI_Barrier(comm);
        if (root)
          log << "verification: level " << level.index
              << (fine.nested ?
                    " (contact refinements " +
                      std::to_string(level.refinements) + ", step x " :
                    std::string(" (sizes and step x "))
              << level.scale << ") -> " << level.directory << std::endl;
        try
          {
            run_impact(prm, comm, log);
          }
        catch (...)
          {
            changed.restore();
            throw;
          }
        changed.restore();
      }


      /// The level's entry of verification.json: its discretisation and
      /// its summary.
      nlohmann::json
      level_record(const Level &level, const nlohmann::json &summary)
      {
        return {{"name",
                 level.index == 0 ? "fine" :
                 level.index == 1 ? "medium" :
                                    "coarse"},
                {"directory", level.relative_directory},
                {"scale", level.scale},
                {"contact_element_size", level.hc},
                {"maximum_element_size", level.hmax},
                {"growth_factor", level.g},
                {"time_step", summary["time_step"]},
                {"cells", summary["cells"]},
                {"dofs", summary["dofs"]},
                {"steps", summary["steps"]},
                {"wall_time", summary["wall_time"]},
                {"summary", summary}};
      }


      /// One quantity's grid convergence over the three levels, as its entry
      /// of verification.json and its row of the table; undefined unless
      /// every level has the quantity.
      nlohmann::json
      grid_convergence_of(const char                        *name,
                          const char                        *unit,
                          const std::vector<nlohmann::json> &levels,
                          const double                       r,
                          std::ostream                      &table)
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
            table << std::setw(16) << name << "  not defined on every level\n";
          }
        return entry;
      }


      /// verification.json and the grid-convergence table of the log.
      void
      write_verification(const FineLevel                   &fine,
                         const std::vector<nlohmann::json> &levels,
                         std::ostream                      &log)
      {
        nlohmann::json     result = {{"format", "impact-verification"},
                                     {"format_version", 1},
                                     {"refinement_ratio", fine.r},
                                     {"meshes",
                                  fine.nested ? "nested" : "remeshed"},
                                     {"formal_order", formal_order},
                                     {"levels", levels}};
        std::ostringstream table;
        table << "verification (r = " << fine.r
              << "; GCI of the fine level, Fs = 1.25):\n"
              << std::setw(16) << "quantity" << std::setw(16) << "fine"
              << std::setw(16) << "medium" << std::setw(16) << "coarse"
              << std::setw(8) << "order" << std::setw(16) << "extrapolated"
              << std::setw(12) << "GCI"
              << "  convergence\n";
        for (const auto &[name, unit] : quantities)
          result["quantities"][name] =
            grid_convergence_of(name, unit, levels, fine.r, table);
        const std::string file = fine.directory + "/verification.json";
        {
          std::ofstream out(file + ".tmp");
          out << std::setw(2) << result << std::endl;
        }
        std::filesystem::rename(file + ".tmp", file);
        log << table.str() << "verification: " << file << std::endl;
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
    verify(ParameterHandler            &prm,
           const MPI_Comm               comm,
           std::ostream                &log,
           const bool                   fine_done,
           const std::function<void()> &fine_level_finished)
    {
      FineLevel      fine = read_fine_level(prm);
      ChangedEntries changed(prm);

      std::vector<nlohmann::json> levels;
      for (unsigned int index = 0; index < 3; ++index)
        {
          const Level level = level_of(fine, index);
          if (!(index == 0 && fine_done))
            run_level(prm, comm, log, fine, level, changed);
          MPI_Barrier(comm);
          if (index == 0 && !fine_done && fine_level_finished)
            fine_level_finished();
          levels.push_back(
            level_record(level, read_json(level.directory + "/summary.json")));
          // The coarser levels' steps and contact surfaces follow the fine
          // level's as it ran: an automatic step count may have been raised,
          // and automatic contact nodes made denser, for its energy balance.
          if (index == 0 && fine.dt == 0)
            fine.n = discretisation_entry_of(levels[0]["summary"],
                                             "Time integration/Steps per "
                                             "contact time",
                                             fine.n);
          // The same sub-steps at contact entry (of each level's step).
          if (index == 0)
            fine.sub_steps =
              discretisation_entry_of(levels[0]["summary"],
                                      "Time integration/Sub-steps at "
                                      "contact entry",
                                      fine.sub_steps);
          if (index == 0)
            fine.surface_refinements = static_cast<unsigned int>(
              discretisation_entry_of(levels[0]["summary"],
                                      "Mesh/Contact surface refinements",
                                      fine.surface_refinements));
        }
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        write_verification(fine, levels, log);
    }
  } // namespace verification
} // namespace impact_fem
