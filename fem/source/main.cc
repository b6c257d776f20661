// impact-fem: a sphere hitting a plate, axisymmetric elastodynamics with
// frictionless contact. Usage: see print_usage() or fem/README.md.
// Exit codes: 0 success; 2 bad input, found before the run starts (an option, a
// parameter file, an entry or its value: the message names it, nothing is
// written); 1 a failure of the run (or of a campaign's run).

#include <impact_fem/analysis/material_point.h>
#include <impact_fem/analysis/specimen.h>
#include <impact_fem/campaign.h>
#include <impact_fem/impact_problem.h>
#include <impact_fem/parameter_path.h>
#include <impact_fem/verification/verification.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>


#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace
{
  void
  print_usage(std::ostream &out)
  {
    out
      << "Usage: impact-fem [parameters.prm] [--set "
         "\"Section/Entry=value\"]...\n"
         "                  [--velocities V1,V2,...] [--sweep "
         "\"Section/Entry=v1,v2,...\"]...\n"
         "                  [--verify] [--shard K/N]\n"
         "       impact-fem --print-parameters\n"
         "Runs one impact; results go to Output/Directory (history.h5, "
         "summary.json).\n"
         "With --velocities (or Campaign/Impact velocities) a campaign: one "
         "run per velocity in Output/Directory/v<V>, plus index.json; "
         "started again, it skips the complete runs whose files are intact "
         "(checksums.sha256).\n"
         "With --sweep (repeatable; or Campaign/Sweep, items separated by ';') "
         "a campaign over the cartesian product of the swept entries and the "
         "velocities, one run per point in e.g. "
         "Output/Directory/plate-thickness-0.01_v1.\n"
         "With --verify (or Verification/Verify) every run is also run on two "
         "coarser discretisations and its numerical uncertainty (observed "
         "order, Richardson extrapolation, GCI) written to verification.json.\n"
         "With --shard K/N a campaign's share K of N (1 <= K <= N): the points "
         "i = 0, 1, ... of the campaign's order with i mod N = K - 1. N jobs, "
         "one per share, on one machine or several sharing Output/Directory, "
         "leave the runs and the index.json of one job (doc/guide/cluster.md)."
         "\n"
         "Exit codes: 0 success; 2 bad input (an option, the parameter file, "
         "an "
         "entry or its value, named in the message; nothing is written); 1 a "
         "failure of the run.\n";
  }


  // Apply "Section/Subsection/Entry=value" to the handler.
  void
  set_entry(dealii::ParameterHandler &prm, const std::string &assignment)
  {
    const auto equal = assignment.find('=');
    AssertThrow(equal != std::string::npos,
                dealii::ExcMessage(
                  "--set expects \"Section/Entry=value\", got <" + assignment +
                  ">."));
    const std::string path =
      dealii::Utilities::trim(assignment.substr(0, equal));
    const std::string value =
      dealii::Utilities::trim(assignment.substr(equal + 1));
    const auto  entry = impact_fem::find_parameter(prm, path);
    std::string problem;
    if (!entry)
      problem = "there is no entry <" + path + ">";
    else if (!entry->set(prm, value))
      problem =
        "the value <" + value + "> does not fit the entry <" + path + ">";
    AssertThrow(problem.empty(),
                dealii::ExcMessage("--set \"" + assignment + "\": " + problem +
                                   " (see impact-fem --print-parameters for "
                                   "entries, units and ranges)."));
  }
} // namespace


int
main(int argc, char *argv[])
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool is_root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  // The problem outlives the try block, so that an error is reported before
  // the problem's MPI-collective destructors run.
  std::unique_ptr<impact_fem::ImpactProblem> problem;
  ParameterHandler                           prm;
  // Until the run starts, an error is one of the input: the command line, the
  // parameter file and entries, their values as the problem reads them.
  bool reading_input = true;
  try
    {
      impact_fem::ImpactProblem::declare_parameters(prm);
      impact_fem::MaterialPointTest::declare_parameters(prm);
      impact_fem::Campaign::declare_parameters(prm);
      impact_fem::verification::declare_parameters(prm);

      std::string               parameter_file, velocity_list, shard_option;
      impact_fem::CampaignShard shard;
      std::vector<std::string>  assignments, sweep_items;
      bool                      verify = false;
      for (int i = 1; i < argc; ++i)
        {
          const std::string arg = argv[i];
          if (arg == "--help" || arg == "-h")
            {
              if (is_root)
                print_usage(std::cout);
              return 0;
            }
          else if (arg == "--print-parameters")
            {
              if (is_root)
                prm.print_parameters(std::cout, ParameterHandler::PRM);
              return 0;
            }
          else if (arg == "--set")
            {
              AssertThrow(i + 1 < argc,
                          ExcMessage("--set needs an argument "
                                     "\"Section/Entry=value\"."));
              assignments.push_back(argv[++i]);
            }
          else if (arg.rfind("--set=", 0) == 0)
            assignments.push_back(arg.substr(6));
          else if (arg == "--velocities")
            {
              AssertThrow(i + 1 < argc,
                          ExcMessage("--velocities needs a list, e.g. "
                                     "--velocities 0.5,1,2."));
              velocity_list = argv[++i];
              AssertThrow(!velocity_list.empty(),
                          ExcMessage("--velocities: empty list."));
            }
          else if (arg == "--sweep")
            {
              AssertThrow(i + 1 < argc,
                          ExcMessage(
                            "--sweep needs an axis, e.g. --sweep "
                            "\"Scenario/Plate thickness=0.01,0.02\"."));
              sweep_items.push_back(argv[++i]);
            }
          else if (arg.rfind("--sweep=", 0) == 0)
            sweep_items.push_back(arg.substr(8));
          else if (arg == "--verify")
            verify = true;
          else if (arg == "--shard" || arg.rfind("--shard=", 0) == 0)
            {
              AssertThrow(arg != "--shard" || i + 1 < argc,
                          ExcMessage("--shard needs K/N, e.g. --shard 1/4 "
                                     "(share K of a campaign split into N "
                                     "jobs, 1 <= K <= N)."));
              shard_option = arg == "--shard" ? argv[++i] : arg.substr(8);
              shard = impact_fem::CampaignShard::parse(shard_option, "--shard");
            }
          else if (arg.rfind("--velocities=", 0) == 0)
            velocity_list = arg.substr(13);
          else if (!arg.empty() && arg[0] == '-')
            {
              AssertThrow(false, ExcMessage("Unknown option <" + arg + ">."));
            }
          else
            {
              AssertThrow(parameter_file.empty(),
                          ExcMessage("Only one parameter file may be given."));
              parameter_file = arg;
            }
        }

      if (!parameter_file.empty())
        {
          std::ifstream probe(parameter_file);
          AssertThrow(probe,
                      ExcMessage("Cannot open the parameter file <" +
                                 parameter_file + ">."));
          prm.parse_input(parameter_file);
        }
      for (const auto &assignment : assignments)
        set_entry(prm, assignment);
      if (verify)
        set_entry(prm, "Verification/Verify=true");

      prm.enter_subsection("Scenario");
      const std::string analysis = prm.get("Analysis");
      prm.leave_subsection();
      const bool alone = analysis == "material point" ||
                         analysis == "specimen" || analysis == "indentation";
      AssertThrow(shard_option.empty() ||
                    (!alone && impact_fem::Campaign::requested(prm,
                                                               velocity_list,
                                                               sweep_items)),
                  ExcMessage("--shard " + shard_option +
                             ": only a campaign of impacts is shared among "
                             "jobs (--velocities, --sweep, Campaign/Impact "
                             "velocities or Campaign/Sweep); this command "
                             "runs one " +
                             analysis + "."));
      if (analysis == "material point")
        {
          if (is_root)
            {
              impact_fem::MaterialPointTest test(prm);
              reading_input = false;
              test.run();
            }
        }
      else if (analysis == "specimen")
        {
          if (is_root)
            {
              impact_fem::SpecimenTest test(prm);
              reading_input = false;
              test.run();
            }
        }
      else if (analysis == "indentation")
        {
          // One load program per run: campaigns and the verification's
          // grid-convergence study are built on impact results.
          AssertThrow(!impact_fem::Campaign::requested(prm,
                                                       velocity_list,
                                                       sweep_items) &&
                        !impact_fem::verification::enabled(prm),
                      ExcMessage("Scenario/Analysis = indentation runs alone: "
                                 "campaigns (--velocities, --sweep, Campaign/"
                                 "...) and --verify (Verification/Verify) are "
                                 "for impacts; run each indentation by "
                                 "itself (fem/bench/indentation.sh shows the "
                                 "mesh convergence)."));
          problem =
            std::make_unique<impact_fem::ImpactProblem>(prm, MPI_COMM_WORLD);
          reading_input = false;
          problem->run();
        }
      else if (impact_fem::Campaign::requested(prm, velocity_list, sweep_items))
        {
          impact_fem::Campaign campaign(prm, velocity_list, sweep_items, shard);
          reading_input = false;
          if (campaign.run(MPI_COMM_WORLD) > 0)
            return 1;
        }
      else if (impact_fem::verification::enabled(prm))
        {
          reading_input = false;
          impact_fem::verification::verify(prm, MPI_COMM_WORLD, std::cout);
        }
      else
        {
          problem =
            std::make_unique<impact_fem::ImpactProblem>(prm, MPI_COMM_WORLD);
          reading_input = false;
          problem->run();
        }
    }
  catch (ExceptionBase &exc)
    {
      // Errors are detected on all ranks alike (parameters, gmsh status,
      // contact and solver failures are collective), so every rank returns.
      if (is_root)
        {
          std::cerr << "\nimpact-fem: error: ";
          exc.print_info(std::cerr);
          std::cerr << std::flush;
        }
      return reading_input ? 2 : 1;
    }
  catch (std::exception &exc)
    {
      if (is_root)
        std::cerr << "\nimpact-fem: error: " << exc.what() << std::endl;
      return reading_input ? 2 : 1;
    }
  catch (...)
    {
      if (is_root)
        std::cerr << "\nimpact-fem: error: unknown exception" << std::endl;
      return 1;
    }
  return 0;
}
