#ifndef IMPACT_FEM_CAMPAIGN_H
#define IMPACT_FEM_CAMPAIGN_H

#include <impact_fem/campaign/shard.h>
#include <impact_fem/campaign/sweep.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <chrono>
#include <string>
#include <vector>

namespace impact_fem
{
  using namespace dealii;

  /**
   * A campaign: one impact per point of the cartesian product of the sweep
   * axes (--sweep "Section/Entry=v1,v2,..." or Campaign/Sweep) and the
   * velocities (--velocities or Campaign/Impact velocities; the last axis),
   * into one directory (Output/Directory). Each run has its subdirectory
   * named by its point (v<V> for a velocity-only campaign, else e.g.
   * plate-thickness-0.005_v0.5) with history.h5, summary.json,
   * parameters.prm, run.log and checksums.sha256; index.json lists the axes
   * and the complete runs with their points (fem/README.md, "Campaigns";
   * read by impact-calibrate --campaign).
   *
   * Restart: a run is complete, and skipped, when its parameters.prm equals
   * the parameters it would run with, Output/Directory left out (a moved or
   * copied campaign keeps its runs), and every file of its checksums.sha256
   * is intact (a truncated or edited history.h5 or summary.json is
   * "damaged, redone"). The ranks are split into groups of 'Ranks per run'
   * that take the points in turn (round robin).
   *
   * With Verification/Verify every run is verified (verification.h): its
   * verification.json is linked from the index entry ("verification") and
   * covered by the checksums; a complete run without one is verified at
   * restart, the run itself kept.
   *
   * With --shard K/N (campaign/shard.h) only the job's share of the points
   * is run; N such jobs, concurrent or not, on one machine or many sharing
   * the campaign directory, leave the same runs and the same index.json as
   * one job (write_index() says why two writers do no harm).
   */
  class Campaign
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /// Does the command line (--velocities @p velocity_list, --sweep
    /// @p sweep_items) or else the parameter file ask for a campaign.
    static bool
    requested(ParameterHandler               &prm,
              const std::string              &velocity_list,
              const std::vector<std::string> &sweep_items);

    /// The campaign of the command line's lists where given, else of the
    /// Campaign entries; checks them all (errors name the option) before
    /// anything is written. @p shard: the points this job runs.
    Campaign(ParameterHandler               &prm,
             const std::string              &velocity_list,
             const std::vector<std::string> &sweep_items,
             const CampaignShard            &shard = CampaignShard());

    /// Runs what is missing of the shard's points; returns the number of
    /// runs that failed.
    unsigned int
    run(const MPI_Comm comm);

  private:
    /// One run: a value index per sweep axis and a velocity.
    struct Point
    {
      std::vector<unsigned int> value_indices;
      double                    velocity;
      std::string               path;       ///< relative to the campaign
      std::string               parameters; ///< expected parameters.prm
    };

    /// How a point's turn ended: complete (skipped, done or verified),
    /// failed, or failed by an interrupt (the campaign stops).
    enum class RunOutcome
    {
      complete,
      failed,
      interrupted
    };

    /// The points of the axes and the velocities, in the campaign's order.
    void
    enumerate_points();
    /// Each point's expected parameters.prm, every point checked.
    void
    set_expected_parameters(const ParameterPath &velocity_entry,
                            const ParameterPath &directory_entry);

    /// The campaign's first line (rank 0), its directory made.
    void
    announce(const unsigned int n_groups, const unsigned int group_size) const;
    /// Point @p i on the rank group @p group_comm.
    RunOutcome
    run_point(const unsigned int i, const MPI_Comm group_comm);
    void
    prepare_run_directory(const Point &point, const bool complete) const;
    /// The checksums of the point's files and the index; false if either
    /// fails (reported on @p line's behalf). With @p fine_level_only the
    /// files of a verified run's fine level, before its coarser levels.
    bool
    certify(const Point                                 &point,
            const std::string                           &line,
            const std::chrono::steady_clock::time_point &start,
            const bool fine_level_only = false) const;
    /// The index once the job's points are done, and the campaign's last
    /// line.
    void
    finish_index(const unsigned int failed) const;

    /// Sets the point's values, velocity and run directory in prm.
    void
    apply(const Point &point);
    std::string
    label(const Point &point) const;
    /// Empty if the run is complete and intact, else why it is (re)done.
    std::string
    restart_status(const Point &point, bool &verified) const;
    bool
    listed_in_index(const Point &point) const;
    /// index.json's text as the run directories show it now.
    std::string
    index_text() const;
    void
    write_index() const;

    ParameterHandler      &prm;
    std::vector<SweepAxis> axes;
    std::vector<double>    velocities;
    std::vector<Point>     points;
    CampaignShard          shard;
    std::string            directory;
    unsigned int           ranks_per_run = 0;
    bool                   verify        = false; ///< Verification/Verify
  };
} // namespace impact_fem

#endif
