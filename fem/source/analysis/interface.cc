#include <impact_fem/analysis/interface.h>
#include <impact_fem/campaign.h>
#include <impact_fem/result_files.h>
#include <impact_fem/verification/verification.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <map>

namespace impact_fem::analysis
{
  namespace
  {
    // Function-local static: safe to use from other translation units'
    // static initialisers (the registrations).
    std::map<std::string, Entry> &
    entries()
    {
      static std::map<std::string, Entry> kinds;
      return kinds;
    }
  } // namespace


  bool
  add(const Entry &entry)
  {
    entries()[entry.name] = entry;
    return true;
  }


  std::vector<Entry>
  all()
  {
    std::vector<Entry> kinds;
    for (const auto &kind : entries())
      kinds.push_back(kind.second);
    std::stable_sort(kinds.begin(),
                     kinds.end(),
                     [](const Entry &a, const Entry &b) {
                       return a.position < b.position;
                     });
    return kinds;
  }


  std::unique_ptr<Interface>
  create(const std::string &name)
  {
    const auto kind = entries().find(name);
    AssertThrow(kind != entries().end(),
                ExcMessage("Unknown analysis <" + name +
                           ">; known: " + selection() + "."));
    return kind->second.create();
  }


  std::string
  selection()
  {
    std::string names;
    for (const auto &kind : all())
      names += (names.empty() ? "" : "|") + kind.name;
    return names;
  }


  std::string
  descriptions()
  {
    std::string help;
    for (const auto &kind : all())
      help +=
        (help.empty() ? "'" : " '") + kind.name + "': " + kind.description;
    return help;
  }


  void
  declare_parameters(ParameterHandler &prm)
  {
    // The analyses registered, in their order.
    prm.enter_subsection(result_files::scenario_subsection);
    prm.declare_entry("Analysis",
                      "impact",
                      Patterns::Selection(selection()),
                      descriptions());
    prm.leave_subsection();
    for (const auto &kind : all())
      kind.declare_parameters(prm);
  }


  void
  require_single_run(ParameterHandler  &prm,
                     const Invocation  &invocation,
                     const std::string &name,
                     const std::string &advice)
  {
    AssertThrow(!Campaign::requested(prm,
                                     invocation.velocity_list,
                                     invocation.sweep_items) &&
                  !verification::enabled(prm),
                ExcMessage("Scenario/Analysis = " + name +
                           " runs alone: campaigns (--velocities, --sweep, "
                           "Campaign/...) and --verify (Verification/Verify) "
                           "are for impacts" +
                           advice + "."));
  }
} // namespace impact_fem::analysis
