#ifndef IMPACT_FEM_CAMPAIGN_RUN_IDENTITY_H
#define IMPACT_FEM_CAMPAIGN_RUN_IDENTITY_H

#include <string>

namespace impact_fem
{
  /**
   * What makes a campaign run the same run: its parameters.prm text
   * (ParameterHandler's ShortPRM print) without the entries that cannot
   * change its results beyond the solvers' tolerances. A complete run whose
   * identity equals the point's is kept at a restart; any other change
   * runs it again. The entries left out, each with its reason, are listed
   * in run_identity.cc (and in fem/README.md, "Campaigns").
   */
  namespace run_identity
  {
    /// @p parameters_text without the lines of the entries left out.
    std::string
    of(const std::string &parameters_text);

    /// Whether "<subsection path>/<entry>" (e.g. "Nonlinear solver/Maximum
    /// iterations") is left out of a run's identity.
    bool
    left_out(const std::string &parameter);
  } // namespace run_identity
} // namespace impact_fem

#endif
