#ifndef IMPACT_FEM_ANALYSIS_INDENTATION_H
#define IMPACT_FEM_ANALYSIS_INDENTATION_H

#include <impact_fem/sphere_plate_setup.h>

#include <deal.II/base/parameter_handler.h>

#include <nlohmann/json.hpp>

#include <iostream>

#include <vector>

namespace impact_fem
{
  using namespace dealii;

  /**
   * The load program of the quasi-static indentation (Scenario/Analysis =
   * indentation, subsection "Indentation"): the base of the hemisphere is
   * moved towards the plate in equal steps up to the maximum approach and
   * back in the same steps until the contact force vanishes.
   *
   * The geometry is that of the finite-element studies of elastic-plastic
   * sphere-flat contact (Kogut & Etsion 2002, J. Appl. Mech. 69:657;
   * Jackson & Green 2005, J. Tribol. 127:343): a deformable hemisphere
   * whose base, the equatorial plane, is displaced by the interference
   * towards a flat (fem/README.md, "Indentation").
   */
  struct IndentationControl
  {
    static void
    declare_parameters(ParameterHandler &prm);

    /// Read and check the subsection; the errors name the entry.
    void
    parse_parameters(ParameterHandler &prm);

    /// Approaches of all steps [m]: 0, loading to the maximum, unloading
    /// back to 0 (the run stops earlier when the force vanishes).
    std::vector<double>
    approaches() const;

    double       maximum_approach = 0; ///< [m]
    unsigned int steps            = 0; ///< load steps, each way [-]
    /// The base also held radially (u_r = 0), not only moved vertically.
    bool base_fixed_radially = false;
  };


  /**
   * `Scenario/Analysis = indentation`: the load program of
   * IndentationControl on the bodies of SpherePlateSetup (a hemisphere,
   * Geometry::hemisphere), quasi-static: per step the equilibrium with the
   * base displaced by the step's approach and the contact (iterated on the
   * plastic force of elastic-plastic bodies), then the plastic state
   * committed. Writes history.h5 and summary.json to Output/Directory.
   */
  class IndentationProblem : public SpherePlateSetup
  {
  public:
    /// Progress and results go to `log` on the first rank of `comm`.
    IndentationProblem(ParameterHandler &prm,
                       const MPI_Comm    comm,
                       std::ostream     &log = std::cout);

    void
    run();

  private:
    struct PlasticZonePeak;
    struct PlasticIndentation;
    /// What the load program found so far.
    struct Outcome;

    /// The base's rows eliminated from K and factorised, the response to
    /// a unit approach.
    void
    setup_indentation();
    void
    declare_history(const bool plastic);
    /// One displacement-controlled step of elastic bodies.
    void
    solve_indentation_step(const double approach, VectorType &displacement);
    /// The step with elastic-plastic bodies: iterations of the elastic step
    /// on the plastic force from the committed state (nothing committed).
    time_integration::NonlinearStep::Result
    solve_plastic_indentation_step(const double      approach,
                                   const VectorType &committed_displacement,
                                   VectorType       &displacement);
    /// Solve one step, prepared for its commit or not (a bisection's trial).
    void
    solve_step(const std::size_t step,
               const double      approach,
               VectorType       &displacement,
               const bool        prepare,
               Outcome          &outcome);
    /// The plastic state of the step's displacement committed.
    void
    commit(const VectorType &displacement, Outcome &outcome);
    /// The largest accumulated plastic strain and where it is (all ranks).
    PlasticZonePeak
    plastic_zone_peak(const double lowest) const;
    /// The steps of the load program until the force vanishes unloading.
    void
    run_load_program(Outcome &outcome);
    /// The step at which the force vanished unloading: the permanent
    /// approach bisected between it and the step before.
    void
    bisect_release(const std::size_t step,
                   const VectorType &displacement,
                   Outcome          &outcome);
    /// The history of the step just solved.
    void
    record_step(const std::size_t step,
                const VectorType &displacement,
                Outcome          &outcome);
    /// summary.json, history.h5 and the result on the log.
    void
    write_results(const Outcome &outcome);
    void
    print_result(const Outcome        &outcome,
                 const nlohmann::json &result,
                 const double          wall_time) const;

    IndentationControl indentation_control;
    // The displacement for a unit approach of the base, the load that
    // prescribes it and the rows it holds (owned).
    VectorType                           unit_approach_response;
    VectorType                           unit_approach_load;
    std::vector<types::global_dof_index> indentation_held_rows;
  };
} // namespace impact_fem

#endif
