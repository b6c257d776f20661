#include <impact_fem/campaign.h>
#include <impact_fem/campaign/checksums.h>
#include <impact_fem/campaign/run_identity.h>
#include <impact_fem/impact_problem.h>
#include <impact_fem/output/checkpoint.h>
#include <impact_fem/parameters.h>
#include <impact_fem/result_files.h>
#include <impact_fem/verification/verification.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <set>
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
    // The temporary name is the writer's own even when writers on several
    // machines share the directory (the shards of a campaign, the rank
    // groups of a job): a process id alone is not unique across machines,
    // host name and process id are.
    void
    write_file_atomically(const std::string &name, const std::string &text)
    {
      char host[256] = {};
      ::gethostname(host, sizeof(host) - 1);
      const std::string temporary =
        name + ".tmp." + host + "." + std::to_string(::getpid());
      {
        std::ofstream out(temporary);
        out << text;
        out.close();
        AssertThrow(out, ExcMessage("Cannot write " + temporary + "."));
      }
      std::filesystem::rename(temporary, name);
    }


    // The parameters.prm text as compared at restart: its run identity
    // (campaign/run_identity.h lists the entries left out, and why).
    std::string
    comparable_parameters(const std::string &text)
    {
      return run_identity::of(text);
    }


    std::vector<double>
    parse_velocities(const std::string &list, const std::string &option)
    {
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
                      ExcMessage(option + ": <" + entry +
                                 "> is not a velocity in (0, 100] m/s."));
          for (const double w : result)
            AssertThrow(velocity_name_component(w) !=
                          velocity_name_component(v),
                        ExcMessage(option + ": " + entry +
                                   " m/s is given twice (to 6 digits)."));
          result.push_back(v);
        }
      return result;
    }


    // Campaign/Sweep: one axis per ';'-separated item.
    std::vector<std::string>
    sweep_items_of_file(ParameterHandler &prm)
    {
      prm.enter_subsection("Campaign");
      const std::string text = prm.get("Sweep");
      prm.leave_subsection();
      std::vector<std::string> items;
      for (const auto &item : Utilities::split_string_list(text, ';'))
        if (!item.empty())
          items.push_back(item);
      return items;
    }


    const char *const velocity_parameter = "Scenario/Impact velocity";
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
                      "per velocity (and point of the Sweep) into "
                      "Output/Directory, with an index.json; Scenario/Impact "
                      "velocity is then ignored. Empty: a single run, or with "
                      "a Sweep the one velocity Scenario/Impact velocity.");
    prm.declare_entry("Sweep",
                      "",
                      Patterns::Anything(),
                      "Further axes of a campaign, one per ';'-separated item "
                      "\"Section/Entry=v1,v2,...\" (or the command-line "
                      "option --sweep, one axis each, which replaces this "
                      "entry): one run per point of the cartesian product of "
                      "the axes and the Impact velocities, in "
                      "Output/Directory/<entry>-<value>_..._v<V> "
                      "(fem/README.md, Campaigns). Empty: velocities only.");
    prm.declare_entry("Ranks per run",
                      "1",
                      Patterns::Integer(0),
                      "MPI ranks per run of a campaign: the ranks are split "
                      "into groups of this size that run points "
                      "concurrently; 0: every run on all ranks. 1 is the "
                      "faster on 2 cores (fem/README.md).");
    prm.leave_subsection();
  }


  bool
  Campaign::requested(ParameterHandler               &prm,
                      const std::string              &velocity_list,
                      const std::vector<std::string> &sweep_items)
  {
    prm.enter_subsection("Campaign");
    const bool file_velocities =
      !Utilities::trim(prm.get("Impact velocities")).empty();
    prm.leave_subsection();
    return !velocity_list.empty() || !sweep_items.empty() || file_velocities ||
           !sweep_items_of_file(prm).empty();
  }


  Campaign::Campaign(ParameterHandler               &prm,
                     const std::string              &velocity_list,
                     const std::vector<std::string> &sweep_items,
                     const CampaignShard            &shard)
    : prm(prm)
    , shard(shard)
  {
    prm.enter_subsection("Campaign");
    const std::string file_velocities = prm.get("Impact velocities");
    ranks_per_run                     = prm.get_integer("Ranks per run");
    prm.leave_subsection();
    velocities =
      velocity_list.empty() ?
        parse_velocities(file_velocities, "Campaign/Impact velocities") :
        parse_velocities(velocity_list, "--velocities");
    axes = sweep_items.empty() ?
             parse_sweep(prm, sweep_items_of_file(prm), "Campaign/Sweep") :
             parse_sweep(prm, sweep_items, "--sweep");
    const ParameterPath velocity_entry =
      *find_parameter(prm, velocity_parameter);
    const ParameterPath directory_entry =
      *find_parameter(prm, "Output/Directory");
    if (velocities.empty())
      velocities.push_back(std::stod(velocity_entry.get(prm)));
    directory = directory_entry.get(prm);
    verify    = verification::enabled(prm);

    enumerate_points();
    set_expected_parameters(velocity_entry, directory_entry);
  }


  // The points, the velocity the fastest-varying axis; each has a run
  // directory of its own.
  void
  Campaign::enumerate_points()
  {
    std::vector<unsigned int> indices(axes.size(), 0);
    std::set<std::string>     paths;
    while (true)
      {
        for (const double v : velocities)
          {
            Point point{indices, v, "", ""};
            for (unsigned int a = 0; a < axes.size(); ++a)
              point.path += axes[a].name_component(indices[a]) + "_";
            point.path += velocity_name_component(v);
            AssertThrow(paths.insert(point.path).second,
                        ExcMessage("Campaign: two points share the run "
                                   "directory " +
                                   point.path + "."));
            points.push_back(point);
          }
        unsigned int a = axes.size();
        while (a > 0 && ++indices[a - 1] == axes[a - 1].values.size())
          indices[--a] = 0;
        if (a == 0)
          break;
      }
  }


  // The parameters each run is to have, as text: the campaign's own
  // entries and Verify left out (a campaign extended by a velocity or
  // verified later keeps its complete runs). The handler is left as it was.
  void
  Campaign::set_expected_parameters(const ParameterPath &velocity_entry,
                                    const ParameterPath &directory_entry)
  {
    std::vector<std::string> original;
    for (const auto &axis : axes)
      original.push_back(axis.parameter.get(prm));
    const std::string original_velocity = velocity_entry.get(prm);

    const std::pair<const char *, const char *> normalised[] = {
      {"Campaign", "Impact velocities"},
      {"Campaign", "Sweep"},
      {"Campaign", "Ranks per run"},
      {"Verification", "Verify"}};
    const char *const        normal_value[] = {"", "", "1", "false"};
    std::vector<std::string> campaign_entries;
    for (unsigned int i = 0; i < 4; ++i)
      {
        prm.enter_subsection(normalised[i].first);
        campaign_entries.push_back(prm.get(normalised[i].second));
        prm.set(normalised[i].second, normal_value[i]);
        prm.leave_subsection();
      }
    for (auto &point : points)
      {
        apply(point);
        // Every point is checked as a run would check it (ranges beyond
        // the entries' patterns) before anything is written.
        try
          {
            const Parameters checked(prm, ImpactProblem::expected_contact);
          }
        catch (const ExceptionBase &error)
          {
            std::ostringstream message;
            error.print_info(message);
            AssertThrow(false,
                        ExcMessage("Campaign point " + label(point) + ": " +
                                   Utilities::trim(message.str())));
          }
        std::ostringstream text;
        prm.print_parameters(text, ParameterHandler::ShortPRM);
        point.parameters = text.str();
      }
    for (unsigned int i = 0; i < 4; ++i)
      {
        prm.enter_subsection(normalised[i].first);
        prm.set(normalised[i].second, campaign_entries[i]);
        prm.leave_subsection();
      }
    for (unsigned int a = 0; a < axes.size(); ++a)
      axes[a].parameter.set(prm, original[a]);
    velocity_entry.set(prm, original_velocity);
    directory_entry.set(prm, directory);
  }


  void
  Campaign::apply(const Point &point)
  {
    for (unsigned int a = 0; a < axes.size(); ++a)
      axes[a].parameter.set(prm, axes[a].values[point.value_indices[a]]);
    prm.enter_subsection("Scenario");
    prm.set("Impact velocity", point.velocity);
    prm.leave_subsection();
    prm.enter_subsection("Output");
    prm.set("Directory", directory + "/" + point.path);
    prm.leave_subsection();
  }


  std::string
  Campaign::label(const Point &point) const
  {
    std::ostringstream text;
    for (unsigned int a = 0; a < axes.size(); ++a)
      text << axes[a].parameter.entry << " = "
           << axes[a].values[point.value_indices[a]] << ", ";
    text << "V = " << point.velocity << " m/s  (" << point.path << ")";
    return text.str();
  }


  std::string
  Campaign::restart_status(const Point &point, bool &verified) const
  {
    verified                        = false;
    const std::string run_directory = directory + "/" + point.path;
    if (!std::filesystem::exists(run_directory + "/parameters.prm"))
      return "running";
    if (comparable_parameters(read_file(run_directory + "/parameters.prm")) !=
        comparable_parameters(point.parameters))
      return "parameters changed, running";
    if (!std::filesystem::exists(run_directory + "/" +
                                 checksums::manifest_name))
      return std::filesystem::exists(run_directory + "/summary.json") ?
               "no checksums (run before they were kept), redone" :
               "incomplete, running";
    std::vector<std::string> listed;
    std::string problem = checksums::check_manifest(run_directory, listed);
    for (const char *name : {"history.h5", "summary.json"})
      if (problem.empty() &&
          std::count(listed.begin(), listed.end(), name) == 0)
        problem = std::string(name) + ": not in " + checksums::manifest_name;
    int version = 0;
    if (problem.empty())
      try
        {
          const nlohmann::json summary =
            nlohmann::json::parse(read_file(run_directory + "/summary.json"));
          if (!summary.value(result_files::complete_key, false))
            problem = "summary.json: not complete";
          version = summary.value(result_files::summary_version_key, 1);
        }
      catch (...)
        {
          problem = "summary.json: unreadable";
        }
    if (!problem.empty())
      return "damaged, redone (" + problem + ")";
    // Not reused: its peaks were derived by another definition, and a
    // verification would compare them with its levels'.
    if (version != result_files::summary_version)
      return "summary version " + std::to_string(version) +
             ", this build's is " +
             std::to_string(result_files::summary_version) +
             " (another definition of the peak force), redone";
    verified =
      std::count(listed.begin(), listed.end(), "verification.json") > 0;
    return std::string();
  }


  // Cheap (no checksums): the run's files were certified when it finished
  // and are checked at every restart.
  bool
  Campaign::listed_in_index(const Point &point) const
  {
    const std::string run_directory = directory + "/" + point.path;
    return std::filesystem::exists(run_directory + "/" +
                                   checksums::manifest_name) &&
           std::filesystem::exists(run_directory + "/summary.json") &&
           std::filesystem::exists(run_directory + "/history.h5") &&
           comparable_parameters(
             read_file(run_directory + "/parameters.prm")) ==
             comparable_parameters(point.parameters);
  }


  std::string
  Campaign::index_text() const
  {
    nlohmann::ordered_json axes_json = nlohmann::ordered_json::array();
    for (const auto &axis : axes)
      {
        nlohmann::ordered_json values = nlohmann::ordered_json::array();
        for (const auto &value : axis.values)
          values.push_back(json_value(value));
        axes_json.push_back(
          {{"parameter", axis.parameter.name()}, {"values", values}});
      }
    axes_json.push_back(
      {{"parameter", velocity_parameter}, {"values", velocities}});

    nlohmann::ordered_json runs = nlohmann::ordered_json::array();
    for (const auto &point : points)
      if (listed_in_index(point))
        {
          nlohmann::ordered_json coordinates = nlohmann::ordered_json::object();
          for (unsigned int a = 0; a < axes.size(); ++a)
            coordinates[axes[a].parameter.name()] =
              json_value(axes[a].values[point.value_indices[a]]);
          coordinates[velocity_parameter] = point.velocity;
          nlohmann::ordered_json run      = {{"path", point.path},
                                             {"velocity", point.velocity},
                                             {"point", coordinates}};
          if (std::filesystem::exists(directory + "/" + point.path +
                                      "/verification.json"))
            run["verification"] = point.path + "/verification.json";
          runs.push_back(run);
        }
    std::ostringstream text;
    text << std::setw(2)
         << nlohmann::ordered_json{{"axes", axes_json}, {"runs", runs}}
         << std::endl;
    return text.str();
  }


  // Several writers may write index.json at once: the rank groups of a job
  // and the shards of a campaign, jobs of their own, perhaps on machines
  // that share the directory. None of them merges what it knows into the
  // index: each rebuilds it from the run directories (a run is listed once
  // its checksums.sha256 is there, written after its files are final), in
  // the campaign's order, so the index does not depend on which shard ran
  // which point or finished first, and equals that of one job.
  //
  // A torn index: never. Each writer writes a temporary file of its own and
  // renames it over index.json; rename is atomic on POSIX file systems
  // (NFS and the parallel ones included), so a reader sees one complete
  // index or the other.
  //
  // A stale index: a writer may rename an index it built before another
  // writer's run was certified over that writer's newer index. So each
  // writer looks again after its rename and writes again while the
  // directories show other runs than it wrote. The last rename of all is
  // then complete: every certified run was certified before its writer's
  // own rename, hence before the last one, and the last writer, looking
  // after that rename, saw it (had it seen other runs than it wrote, its
  // rename would not have been the last); this takes a file system that
  // shows a file to every machine once it is written (NFS clients may cache
  // lookups for a while: doc/guide/cluster.md says how to check the index).
  // No lock is needed, so none whose support depends on how a cluster
  // mounts its file system (Lustre's flock option, NFS's lock daemon).
  void
  Campaign::write_index() const
  {
    std::string written;
    do
      {
        written = index_text();
        write_file_atomically(directory + "/index.json", written);
    } while (index_text() != written);
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

    if (rank == 0)
      announce(n_groups, group_size);
    MPI_Barrier(comm);

    // The shard's points, taken by the rank groups in turn.
    std::vector<unsigned int> share;
    for (unsigned int i = 0; i < points.size(); ++i)
      if (shard.contains(i))
        share.push_back(i);
    unsigned int failed = 0;
    for (unsigned int j = group; j < share.size() && group < n_groups;
         j += n_groups)
      {
        // A signal received during an earlier run stops the campaign here
        // (a restart does the remaining runs).
        if (Utilities::MPI::max(ImpactProblem::interrupt_received(),
                                group_comm) != 0)
          break;
        const RunOutcome outcome = run_point(share[j], group_comm);
        if (outcome != RunOutcome::complete)
          ++failed;
        if (outcome == RunOutcome::interrupted)
          break; // a restart redoes this run
      }
    MPI_Comm_free(&group_comm);
    failed = Utilities::MPI::sum(failed, comm);
    MPI_Barrier(comm);
    if (rank == 0)
      finish_index(failed);
    return failed;
  }


  void
  Campaign::announce(const unsigned int n_groups,
                     const unsigned int group_size) const
  {
    std::filesystem::create_directories(directory);
    std::cout << "impact-fem campaign: ";
    if (axes.empty())
      std::cout << velocities.size()
                << (velocities.size() == 1 ? " velocity" : " velocities");
    else
      {
        std::cout << points.size() << " runs (";
        for (const auto &axis : axes)
          std::cout << axis.parameter.entry << " x " << axis.values.size()
                    << ", ";
        std::cout << "velocities x " << velocities.size() << ")";
      }
    std::cout << " into " << directory;
    if (!shard.whole())
      std::cout << ", shard " << shard.name() << ": "
                << shard.n_points(points.size()) << " of them";
    std::cout << ", " << n_groups << " group(s) of " << group_size << " rank(s)"
              << std::endl;
  }


  // A complete run is skipped, or only verified when the campaign verifies
  // and it was not; any other is (re)done from the start.
  Campaign::RunOutcome
  Campaign::run_point(const unsigned int i, const MPI_Comm group_comm)
  {
    const bool   group_root = Utilities::MPI::this_mpi_process(group_comm) == 0;
    const Point &point      = points[i];
    const std::string run_directory = directory + "/" + point.path;
    const std::string line          = "  run " + std::to_string(i + 1) + "/" +
                             std::to_string(points.size()) + "  " +
                             label(point);
    bool        verified = false;
    std::string status   = group_root ? restart_status(point, verified) : "";
    status               = Utilities::MPI::broadcast(group_comm, status, 0);
    verified             = Utilities::MPI::broadcast(group_comm, verified, 0);
    const bool complete  = status.empty();
    if (complete && (!verify || verified))
      {
        if (group_root)
          std::cout << line << ": complete, skipped" << std::endl;
        return RunOutcome::complete;
      }
    if (group_root)
      {
        std::cout << line << ": " << (complete ? "complete, verifying" : status)
                  << std::endl;
        prepare_run_directory(point, complete);
      }
    MPI_Barrier(group_comm);
    apply(point);
    const auto    start = std::chrono::steady_clock::now();
    std::ofstream log;
    if (group_root)
      // A run that goes on from its checkpoint keeps the log of its start.
      log.open(run_directory + "/run.log",
               complete || checkpoint::exists(run_directory) ? std::ios::app :
                                                               std::ios::out);
    try
      {
        if (verify)
          verification::verify(
            prm, group_comm, group_root ? log : std::cout, complete, [&]() {
              if (group_root)
                certify(point, line, start, true);
            });
        else
          {
            run_impact(prm, group_comm, group_root ? log : std::cout);
          }
      }
    catch (const std::exception &error)
      {
        if (group_root)
          {
            log << "\nimpact-fem: error: " << error.what() << std::endl;
            std::cout << line << ": FAILED (" << run_directory << "/run.log)"
                      << std::endl;
          }
        return ImpactProblem::interrupt_received() != 0 ?
                 RunOutcome::interrupted :
                 RunOutcome::failed;
      }
    if (group_root && !certify(point, line, start))
      return RunOutcome::failed;
    return RunOutcome::complete;
  }


  // A run (re)done from the start leaves nothing of its previous attempt
  // that could pass for its result; a verified one keeps its run.
  void
  Campaign::prepare_run_directory(const Point &point, const bool complete) const
  {
    const std::string run_directory = directory + "/" + point.path;
    std::filesystem::create_directories(run_directory);
    if (!complete)
      {
        // The checksums first: whatever stays behind is not certified.
        std::filesystem::remove(run_directory + "/" + checksums::manifest_name);
        for (const char *name : {"summary.json", "history.h5"})
          std::filesystem::remove(run_directory + "/" + name);
        write_file_atomically(run_directory + "/parameters.prm",
                              point.parameters);
      }
    std::filesystem::remove(run_directory + "/verification.json");
  }


  // The files are final: certify them, and list the run in the index. A
  // verified run's fine level is certified before its coarser levels are
  // made, so that a verification stopped there (a signal, a job's time
  // limit) keeps the fine level: the restart finds it complete and only
  // verifies it. Its checksums are written again, with verification.json,
  // once the verification is done.
  bool
  Campaign::certify(const Point                                 &point,
                    const std::string                           &line,
                    const std::chrono::steady_clock::time_point &start,
                    const bool fine_level_only) const
  {
    const std::string run_directory = directory + "/" + point.path;
    try
      {
        std::vector<std::string> files = {"parameters.prm",
                                          "history.h5",
                                          "summary.json"};
        if (verify && !fine_level_only)
          files.push_back("verification.json");
        checksums::write_manifest(run_directory, files);
        const auto summary =
          nlohmann::json::parse(read_file(run_directory + "/summary.json"));
        std::cout << line
                  << (fine_level_only ? ": fine level done in " : ": done in ")
                  << std::setprecision(3)
                  << std::chrono::duration<double>(
                       std::chrono::steady_clock::now() - start)
                       .count()
                  << " s, restitution " << std::setprecision(6)
                  << summary["restitution"]
                  << (fine_level_only ? ", its coarser levels next" : "")
                  << std::endl;
        write_index();
        return true;
      }
    catch (const std::exception &error)
      {
        std::cout << line << ": FAILED (" << error.what() << ")" << std::endl;
        return false;
      }
  }


  // With shards, the index is complete once the last shard ends.
  void
  Campaign::finish_index(const unsigned int failed) const
  {
    write_index();
    const auto listed =
      std::count_if(points.begin(), points.end(), [this](const Point &p) {
        return listed_in_index(p);
      });
    std::cout << "impact-fem campaign: index " << directory << "/index.json"
              << " (" << listed << " of " << points.size() << " runs)"
              << (failed > 0 ? ", " + std::to_string(failed) +
                                 " run(s) failed or interrupted" :
                               std::string())
              << std::endl;
  }
} // namespace impact_fem
