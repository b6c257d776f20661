#ifndef IMPACT_FEM_VERIFICATION_VERIFICATION_H
#define IMPACT_FEM_VERIFICATION_VERIFICATION_H

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <iostream>
#include <string>

namespace impact_fem
{
  namespace verification
  {
    using namespace dealii;

    /// The entries of the subsection "Verification".
    void
    declare_parameters(ParameterHandler &prm);

    /// Verification/Verify: is every run to be verified.
    bool
    enabled(ParameterHandler &prm);

    /**
     * The numerical uncertainty of the impact of @p prm: the run itself is
     * the fine level (Output/Directory), two systematically coarser ones go
     * to Output/Directory/verification/level1 and level2. Space and time are
     * coarsened together by the refinement ratio r per level: the mesh size
     * field h(d) = min(hmax, hc + (g - 1) max(0, d - rz)) becomes r h(d)
     * (Contact element size and Maximum element size times r, Growth factor
     * 1 + (g - 1) r, the uniform zone kept) and the time step r dt; with
     * Verification/Meshes = nested (r = 2) each coarser level has one
     * Mesh/Contact refinement fewer instead, so that the levels are nested
     * within the contact surface radius (gmsh's meshes of scaled sizes are
     * not: where the contact nodes fall moves from level to level, which
     * makes a plastic impact's restitution oscillate). For
     * contact_time, force_max, time_force_max, approach_max and restitution
     * it writes Output/Directory/verification.json (observed order,
     * Richardson extrapolation, GCI: grid_convergence.h) and prints the
     * table. With @p fine_done the fine run is taken from its summary.json
     * instead of being run again; otherwise @p fine_level_finished, if
     * given, is called on every rank of @p comm once the fine level's files
     * are final (a campaign certifies them then, so that a verification
     * stopped in a coarser level keeps the fine one).
     */
    void
    verify(ParameterHandler            &prm,
           const MPI_Comm               comm,
           std::ostream                &log,
           const bool                   fine_done           = false,
           const std::function<void()> &fine_level_finished = {});
  } // namespace verification
} // namespace impact_fem

#endif
