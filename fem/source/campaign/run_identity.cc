#include <impact_fem/campaign/run_identity.h>

#include <deal.II/base/utilities.h>

#include <sstream>
#include <vector>

namespace impact_fem
{
  namespace run_identity
  {
    namespace
    {
      /**
       * The entries that do not make a run another one. A subsection
       * ending in "/" stands for all its entries. Everything else, the
       * solvers' tolerances included, is part of the identity: a changed
       * tolerance changes the result by up to that tolerance.
       */
      const std::vector<std::string> &
      left_out_entries()
      {
        static const std::vector<std::string> entries = {
          // The campaign's own entries: a point's values are written into
          // the entries they vary (Scenario/Impact velocity, the swept
          // ones); the rest says how many runs there are and how they are
          // spread over the ranks.
          "Campaign/",
          // Where a campaign lies is not a parameter of its runs: a moved or
          // copied campaign keeps them.
          "Output/Directory",
          // Files written beside the results (ParaView snapshots) and
          // progress lines of the log: they do not enter history.h5 or
          // summary.json.
          "Output/Snapshot interval",
          "Output/Progress interval",
          // Iteration limits: a complete run converged in every step to the
          // tolerances (which stay in the identity) within the limit it
          // had; another limit would end in the same iterate or stop the
          // run with an error, never give another result.
          "Nonlinear solver/Maximum iterations",
          "Contact/Maximum active set iterations",
          // How a step iterates to its tolerances: another strategy or
          // Anderson depth ends in another iterate that meets the same
          // tolerances, so its results differ by less than they allow.
          "Nonlinear solver/Strategy",
          "Nonlinear solver/Anderson depth",
          // A sparse direct solver solves to round-off, far below the
          // nonlinear and contact tolerances.
          "Solver/Direct solver",
          // A verified run is the same run with two coarser ones beside it
          // (verification.json).
          "Verification/Verify"};
        return entries;
      }
    } // namespace


    bool
    left_out(const std::string &parameter)
    {
      for (const auto &entry : left_out_entries())
        if (entry.back() == '/' ? parameter.rfind(entry, 0) == 0 :
                                  parameter == entry)
          return true;
      return false;
    }


    std::string
    of(const std::string &parameters_text)
    {
      std::istringstream       in(parameters_text);
      std::ostringstream       out;
      std::vector<std::string> sections;
      std::string              line;
      while (std::getline(in, line))
        {
          const std::string trimmed = dealii::Utilities::trim(line);
          std::string       path;
          for (const auto &section : sections)
            path += section + "/";
          if (trimmed.rfind("subsection ", 0) == 0)
            {
              sections.push_back(dealii::Utilities::trim(trimmed.substr(11)));
              if (left_out(path + sections.back() + "/"))
                continue;
            }
          else if (trimmed == "end" && !sections.empty())
            {
              const bool inside_left_out = left_out(path);
              sections.pop_back();
              if (inside_left_out)
                continue;
            }
          else if (trimmed.rfind("set ", 0) == 0)
            {
              const auto        equal = trimmed.find('=');
              const std::string entry =
                dealii::Utilities::trim(trimmed.substr(4, equal - 4));
              if (left_out(path + entry))
                continue;
            }
          else if (left_out(path))
            continue;
          out << line << '\n';
        }
      return out.str();
    }
  } // namespace run_identity
} // namespace impact_fem
