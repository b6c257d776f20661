// impact-fem: a sphere hitting a plate, axisymmetric elastodynamics with
// frictionless contact. Usage: see print_usage() or fem/README.md.
// Exit codes: 0 success; 2 bad input, found before the run starts (an option, a
// parameter file, an entry or its value: the message names it, nothing is
// written); 1 a failure of the run (or of a campaign's run).

#include <impact_fem/analysis/interface.h>
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
  /// What the command line asks for beyond the parameter entries.
  struct CommandLine
  {
    std::string                      parameter_file, shard_option;
    std::vector<std::string>         assignments;
    impact_fem::analysis::Invocation invocation;
    bool                             verify = false;
    /// --help or --print-parameters: print and exit.
    bool help = false, print_parameters = false;
  };


  // The value of an option that takes one ("--set X" or "--set=X"); @p i
  // moves past it.
  bool
  option_value(const std::string &option,
               int               &i,
               const int          argc,
               char              *argv[],
               const std::string &missing,
               std::string       &value)
  {
    const std::string arg = argv[i];
    if (arg == option)
      {
        AssertThrow(i + 1 < argc, dealii::ExcMessage(missing));
        value = argv[++i];
        return true;
      }
    if (arg.rfind(option + "=", 0) == 0)
      {
        value = arg.substr(option.size() + 1);
        return true;
      }
    return false;
  }


  CommandLine
  parse_command_line(const int argc, char *argv[])
  {
    using dealii::ExcMessage;
    CommandLine command;
    auto       &invocation = command.invocation;
    std::string value;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "--help" || arg == "-h")
          command.help = true;
        else if (arg == "--print-parameters")
          command.print_parameters = true;
        if (command.help || command.print_parameters)
          return command;
        if (option_value("--set",
                         i,
                         argc,
                         argv,
                         "--set needs an argument \"Section/Entry=value\".",
                         value))
          command.assignments.push_back(value);
        else if (arg == "--velocities")
          {
            option_value(arg,
                         i,
                         argc,
                         argv,
                         "--velocities needs a list, e.g. --velocities "
                         "0.5,1,2.",
                         invocation.velocity_list);
            AssertThrow(!invocation.velocity_list.empty(),
                        ExcMessage("--velocities: empty list."));
          }
        else if (option_value("--sweep",
                              i,
                              argc,
                              argv,
                              "--sweep needs an axis, e.g. --sweep "
                              "\"Scenario/Plate thickness=0.01,0.02\".",
                              value))
          invocation.sweep_items.push_back(value);
        else if (arg == "--verify")
          command.verify = true;
        else if (option_value("--shard",
                              i,
                              argc,
                              argv,
                              "--shard needs K/N, e.g. --shard 1/4 (share K "
                              "of a campaign split into N jobs, 1 <= K <= N).",
                              command.shard_option))
          {
            invocation.shard =
              impact_fem::CampaignShard::parse(command.shard_option, "--shard");
            invocation.sharded = true;
          }
        else if (arg.rfind("--velocities=", 0) == 0)
          invocation.velocity_list = arg.substr(13);
        else if (!arg.empty() && arg[0] == '-')
          {
            AssertThrow(false, ExcMessage("Unknown option <" + arg + ">."));
          }
        else
          {
            AssertThrow(command.parameter_file.empty(),
                        ExcMessage("Only one parameter file may be given."));
            command.parameter_file = arg;
          }
      }
    return command;
  }


  // The parameter file, then the --set assignments and --verify.
  void
  read_parameters(dealii::ParameterHandler &prm, const CommandLine &command)
  {
    if (!command.parameter_file.empty())
      {
        std::ifstream probe(command.parameter_file);
        AssertThrow(probe,
                    dealii::ExcMessage("Cannot open the parameter file <" +
                                       command.parameter_file + ">."));
        prm.parse_input(command.parameter_file);
      }
    for (const auto &assignment : command.assignments)
      set_entry(prm, assignment);
    if (command.verify)
      set_entry(prm, "Verification/Verify=true");
  }


  // The analysis Scenario/Analysis names; refuses --shard for one that
  // is not a campaign.
  std::unique_ptr<impact_fem::analysis::Interface>
  create_analysis(dealii::ParameterHandler &prm, const CommandLine &command)
  {
    prm.enter_subsection("Scenario");
    const std::string name = prm.get("Analysis");
    prm.leave_subsection();
    auto        analysis   = impact_fem::analysis::create(name);
    const auto &invocation = command.invocation;
    AssertThrow(!invocation.sharded ||
                  (analysis->runs_campaigns() &&
                   impact_fem::Campaign::requested(prm,
                                                   invocation.velocity_list,
                                                   invocation.sweep_items)),
                dealii::ExcMessage(
                  "--shard " + command.shard_option +
                  ": only a campaign of impacts is shared among "
                  "jobs (--velocities, --sweep, Campaign/Impact "
                  "velocities or Campaign/Sweep); this command "
                  "runs one " +
                  name + "."));
    return analysis;
  }
} // namespace


int
main(int argc, char *argv[])
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool is_root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  // The analysis outlives the try block, so that an error is reported before
  // its MPI-collective destructors run.
  std::unique_ptr<impact_fem::analysis::Interface> analysis;
  ParameterHandler                                 prm;
  // Until the run starts, an error is one of the input: the command line, the
  // parameter file and entries, their values as the analysis reads them.
  bool reading_input = true;
  try
    {
      impact_fem::ImpactProblem::declare_parameters(prm);
      impact_fem::analysis::declare_parameters(prm);
      impact_fem::Campaign::declare_parameters(prm);
      impact_fem::verification::declare_parameters(prm);

      const CommandLine command = parse_command_line(argc, argv);
      if (command.help || command.print_parameters)
        {
          if (is_root && command.help)
            print_usage(std::cout);
          else if (is_root)
            prm.print_parameters(std::cout, ParameterHandler::PRM);
          return 0;
        }
      read_parameters(prm, command);
      analysis = create_analysis(prm, command);
      analysis->parse_parameters(prm, command.invocation, MPI_COMM_WORLD);
      reading_input = false;
      return analysis->run();
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
