#include <impact_fem/campaign.h>
#include <impact_fem/impact_problem.h>
#include <impact_fem/verification/verification.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <unistd.h>

namespace impact_fem
{
  namespace
  {
    std::string
    read_file(const std::string &name)
    {
      std::ifstream     in(name);
      std::stringstream text;
      text << in.rdbuf();
      return in ? text.str() : std::string();
    }

    // Written under a temporary name and renamed: never seen half-written.
    void
    write_file_atomically(const std::string &name, const std::string &text)
    {
      const std::string temporary =
        name + ".tmp" + std::to_string(::getpid());
      {
        std::ofstream out(temporary);
        out << text;
      }
      std::filesystem::rename(temporary, name);
    }
  } // namespace


  void
  Campaign::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Campaign");
    prm.declare_entry("Impact velocities",
                      "",
                      Patterns::List(Patterns::Double(0)),
                      "Velocities of a campaign [m/s], comma separated "
                      "(or the command-line option --velocities): one run "
                      "per velocity into Output/Directory/v<V>, with an "
                      "index.json; Scenario/Impact velocity is then "
                      "ignored. Empty: a single run.");
    prm.declare_entry("Ranks per run",
                      "1",
                      Patterns::Integer(0),
                      "MPI ranks per run of a campaign: the ranks are split "
                      "into groups of this size that run velocities "
                      "concurrently; 0: every run on all ranks. 1 is the "
                      "faster on 2 cores (fem/README.md).");
    prm.leave_subsection();
  }


  std::vector<double>
  Campaign::velocities(ParameterHandler &prm, const std::string &command_line)
  {
    prm.enter_subsection("Campaign");
    const std::string list =
      command_line.empty() ? prm.get("Impact velocities") : command_line;
    prm.leave_subsection();
    std::vector<double> result;
    for (const auto &entry : Utilities::split_string_list(list))
      {
        std::size_t end = 0;
        double      v   = 0;
        try
          {
            v = std::stod(entry, &end);
          }
        catch (...)
          {
            end = 0;
          }
        AssertThrow(end == entry.size() && v > 0 && v <= 100,
                    ExcMessage("Campaign velocities: <" + entry +
                               "> is not a velocity in (0, 100] m/s."));
        for (const double w : result)
          AssertThrow(std::abs(w - v) > 1e-12 * v,
                      ExcMessage("Campaign velocities: " + entry +
                                 " m/s is given twice."));
        result.push_back(v);
      }
    return result;
  }


  Campaign::Campaign(ParameterHandler &prm, const std::vector<double> &velocities)
    : prm(prm)
    , impact_velocities(velocities)
  {
    prm.enter_subsection("Output");
    directory = prm.get("Directory");
    prm.leave_subsection();
    prm.enter_subsection("Campaign");
    ranks_per_run = prm.get_integer("Ranks per run");
    prm.leave_subsection();
    verify = verification::enabled(prm);
  }


  std::string
  Campaign::run_path(const double velocity) const
  {
    std::ostringstream name;
    name << 'v' << std::setprecision(6) << velocity;
    return name.str();
  }


  // The parameters of one run as text, the campaign entries left out (a
  // campaign extended by a velocity keeps its complete runs).
  std::string
  Campaign::expected_parameters(const double velocity)
  {
    prm.enter_subsection("Scenario");
    prm.set("Impact velocity", velocity);
    prm.leave_subsection();
    prm.enter_subsection("Output");
    prm.set("Directory", directory + "/" + run_path(velocity));
    prm.leave_subsection();
    prm.enter_subsection("Campaign");
    const std::string list  = prm.get("Impact velocities");
    const std::string ranks = prm.get("Ranks per run");
    prm.set("Impact velocities", "");
    prm.set("Ranks per run", "1");
    prm.leave_subsection();
    // Whether a run is verified does not change the run itself.
    prm.enter_subsection("Verification");
    const std::string verify_entry = prm.get("Verify");
    prm.set("Verify", "false");
    prm.leave_subsection();
    std::ostringstream text;
    prm.print_parameters(text, ParameterHandler::ShortPRM);
    prm.enter_subsection("Verification");
    prm.set("Verify", verify_entry);
    prm.leave_subsection();
    prm.enter_subsection("Campaign");
    prm.set("Impact velocities", list);
    prm.set("Ranks per run", ranks);
    prm.leave_subsection();
    return text.str();
  }


  bool
  Campaign::is_complete(const double velocity, const std::string &parameters) const
  {
    const std::string run_directory = directory + "/" + run_path(velocity);
    if (read_file(run_directory + "/parameters.prm") != parameters ||
        !std::filesystem::exists(run_directory + "/history.h5"))
      return false;
    try
      {
        const auto summary =
          nlohmann::json::parse(read_file(run_directory + "/summary.json"));
        return summary.value("complete", false);
      }
    catch (...)
      {
        return false;
      }
  }


  void
  Campaign::write_index() const
  {
    nlohmann::json runs = nlohmann::json::array();
    for (const double v : impact_velocities)
      {
        const std::string run_directory = directory + "/" + run_path(v);
        if (std::filesystem::exists(run_directory + "/summary.json") &&
            std::filesystem::exists(run_directory + "/history.h5"))
          {
            nlohmann::json run = {{"velocity", v}, {"path", run_path(v)}};
            if (std::filesystem::exists(run_directory + "/verification.json"))
              run["verification"] = run_path(v) + "/verification.json";
            runs.push_back(run);
          }
      }
    std::ostringstream text;
    text << std::setw(2) << nlohmann::json{{"runs", runs}} << std::endl;
    write_file_atomically(directory + "/index.json", text.str());
  }


  unsigned int
  Campaign::run(const MPI_Comm comm)
  {
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int group_size =
      ranks_per_run == 0 ? n_ranks : std::min(ranks_per_run, n_ranks);
    const unsigned int n_groups = n_ranks / group_size;
    // Ranks beyond the last full group stay idle.
    const unsigned int group = std::min(rank / group_size, n_groups);
    MPI_Comm           group_comm;
    MPI_Comm_split(comm, group, rank, &group_comm);
    const bool group_root = Utilities::MPI::this_mpi_process(group_comm) == 0;

    if (rank == 0)
      {
        std::filesystem::create_directories(directory);
        std::cout << "impact-fem campaign: " << impact_velocities.size()
                  << " velocities into " << directory << ", " << n_groups
                  << " group(s) of " << group_size << " rank(s)" << std::endl;
      }
    MPI_Barrier(comm);

    unsigned int failed = 0;
    for (unsigned int i = group; i < impact_velocities.size() && group < n_groups;
         i += n_groups)
      {
        const double      v          = impact_velocities[i];
        const std::string parameters = expected_parameters(v);
        const std::string run_directory = directory + "/" + run_path(v);
        std::ostringstream label;
        label << "  run " << i + 1 << "/" << impact_velocities.size()
              << "  V = " << v << " m/s  (" << run_path(v) << ")";
        // A signal received during an earlier run stops the campaign here
        // (a restart does the remaining runs).
        if (Utilities::MPI::max(ImpactProblem::interrupt_received(), group_comm) != 0)
          break;
        const bool complete = Utilities::MPI::broadcast(
          group_comm, group_root && is_complete(v, parameters), 0);
        const bool verified = Utilities::MPI::broadcast(
          group_comm,
          group_root &&
            std::filesystem::exists(run_directory + "/verification.json"),
          0);
        if (complete && (!verify || verified))
          {
            if (group_root)
              std::cout << label.str() << ": complete, skipped" << std::endl;
            continue;
          }
        if (group_root)
          {
            std::cout << label.str()
                      << (complete ? ": complete, verifying" : ": running")
                      << std::endl;
            std::filesystem::create_directories(run_directory);
            std::filesystem::remove(run_directory + "/verification.json");
            if (!complete)
              {
                std::filesystem::remove(run_directory + "/summary.json");
                write_file_atomically(run_directory + "/parameters.prm", parameters);
              }
          }
        MPI_Barrier(group_comm);
        const auto    start = std::chrono::steady_clock::now();
        std::ofstream log;
        if (group_root)
          log.open(run_directory + "/run.log", complete ? std::ios::app : std::ios::out);
        // The problem outlives the try block: its destructor (collective
        // over the group) must not run while an exception unwinds.
        std::unique_ptr<ImpactProblem> problem;
        try
          {
            if (verify)
              verification::verify(prm, group_comm, group_root ? log : std::cout, complete);
            else
              {
                problem = std::make_unique<ImpactProblem>(prm,
                                                          group_comm,
                                                          group_root ? log : std::cout);
                problem->run();
                problem.reset();
              }
          }
        catch (const std::exception &error)
          {
            problem.reset();
            if (group_root)
              {
                log << "\nimpact-fem: error: " << error.what() << std::endl;
                std::cout << label.str() << ": FAILED (" << run_directory
                          << "/run.log)" << std::endl;
              }
            ++failed;
            if (ImpactProblem::interrupt_received() != 0)
              break; // interrupted: stop; a restart redoes this run
            continue;
          }
        if (group_root)
          {
            const auto summary =
              nlohmann::json::parse(read_file(run_directory + "/summary.json"));
            std::cout << label.str() << ": done in " << std::setprecision(3)
                      << std::chrono::duration<double>(
                           std::chrono::steady_clock::now() - start)
                           .count()
                      << " s, restitution " << std::setprecision(6)
                      << summary["restitution"] << std::endl;
            write_index();
          }
      }
    MPI_Comm_free(&group_comm);
    failed = Utilities::MPI::sum(failed, comm);
    MPI_Barrier(comm);
    if (rank == 0)
      {
        write_index();
        std::cout << "impact-fem campaign: index " << directory
                  << "/index.json"
                  << (failed > 0 ? ", " + std::to_string(failed) +
                                     " run(s) failed or interrupted" :
                                   std::string())
                  << std::endl;
      }
    return failed;
  }
} // namespace impact_fem
