#ifndef IMPACT_FEM_CAMPAIGN_H
#define IMPACT_FEM_CAMPAIGN_H

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace impact_fem
{
  using namespace dealii;

  /**
   * A velocity campaign: one impact per velocity into one directory
   * (Output/Directory), run i in the subdirectory v<V> (e.g. v0.5, v1) with
   * its history.h5, summary.json, parameters.prm and run.log, and the index
   * index.json = {"runs": [{"velocity": V, "path": "v<V>"}, ...]} of the
   * complete runs, in the order given (the format read by
   * impact-calibrate --campaign).
   *
   * Restart: a run whose directory holds a summary.json and a parameters.prm
   * equal to the parameters it would run with is complete and skipped; any
   * other is (re)computed. The ranks are split into groups of 'Ranks per
   * run' that take the velocities in turn (round robin).
   *
   * With Verification/Verify every run is verified (verification.h): its
   * verification.json is linked from the index entry ("verification"), and
   * a complete run without one is verified at restart, the run itself kept.
   */
  class Campaign
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /// The velocities of the campaign: `command_line` (from --velocities)
    /// if not empty, else Campaign/Impact velocities; empty: no campaign.
    static std::vector<double>
    velocities(ParameterHandler &prm, const std::string &command_line);

    Campaign(ParameterHandler &prm, const std::vector<double> &velocities);

    /// Runs what is missing; returns the number of runs that failed.
    unsigned int
    run(const MPI_Comm comm);

  private:
    std::string
    run_path(const double velocity) const;
    std::string
    expected_parameters(const double velocity);
    bool
    is_complete(const double velocity, const std::string &parameters) const;
    void
    write_index() const;

    ParameterHandler   &prm;
    std::vector<double> impact_velocities;
    std::string         directory;
    unsigned int        ranks_per_run = 0;
    bool                verify        = false; ///< Verification/Verify
  };
} // namespace impact_fem

#endif
