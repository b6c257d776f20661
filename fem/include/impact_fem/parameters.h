#ifndef IMPACT_FEM_PARAMETERS_H
#define IMPACT_FEM_PARAMETERS_H

#include <impact_fem/discretisation/expected_contact.h>
#include <impact_fem/hertz.h>
#include <impact_fem/materials/body_material.h>
#include <impact_fem/materials/interface.h>
#include <impact_fem/mesh/sphere_plate_mesh.h>

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <memory>
#include <string>

namespace impact_fem
{
  using namespace dealii;

  /// Index of a body in per-body arrays.
  enum Body : unsigned int
  {
    sphere = 0,
    plate  = 1
  };

  /**
   * What holds a face of the plate (its side or its bottom): nothing
   * ('free': traction-free), zero displacement ('clamped'), viscous dashpots
   * rho c_p on the normal and rho c_s on the tangential velocity ('absorbing',
   * Lysmer-Kuhlemeyer: the finite plate stands in for a half-space), or, for
   * the bottom, an elastic foundation of normal stiffness k per area
   * ('support', Winkler: t = -k u_n n; a plate lying on something soft).
   */
  enum class FaceCondition
  {
    free,
    clamped,
    absorbing,
    support
  };

  /// The conditions of the plate's side and bottom faces.
  struct PlateFaces
  {
    FaceCondition side       = FaceCondition::absorbing;
    FaceCondition bottom     = FaceCondition::absorbing;
    double support_stiffness = 0; ///< k of a 'support' bottom [N/m^3 = Pa/m]

    /// The condition of the face plate_side or plate_bottom.
    FaceCondition
    of(const types::boundary_id face) const
    {
      return face == boundary_ids::plate_bottom ? bottom : side;
    }
  };

  /// "sphere" or "plate": the names used in result keys.
  inline const char *
  body_name(const unsigned int body)
  {
    return body == sphere ? "sphere" : "plate";
  }


  /**
   * The scenario of a run of the two bodies, read and checked in one place:
   * geometry, materials and yield strengths of both bodies, time control,
   * solver and output directory, and the Hertz estimates derived from them.
   * Which analysis runs is not its concern: an analysis declares and checks
   * its own entries and gives the contact it expects (ExpectedContactOf).
   * The components (mesh, contact, time stepper, postprocessors) declare and
   * read their own entries.
   */
  struct Parameters
  {
    /// The entries of this struct (Scenario, Sphere, Plate, Time
    /// integration, Solver, Output) and of the materials and time steppers
    /// it reads.
    static void
    declare_parameters(ParameterHandler &prm);

    /// The contact the mesh and the step left "auto" are sized for, given
    /// by the analysis from the scenario read so far (the Hertz estimates);
    /// it may read and check the analysis's own entries.
    using ExpectedContactOf =
      std::function<discretisation::ExpectedContact(const Parameters &)>;

    /// Read and check; an ExcMessage names the entry and its allowed range.
    Parameters(ParameterHandler &prm, const ExpectedContactOf &expected);

    /// The time step of an impact [s]: the prescribed Time step, or Hertz
    /// contact time / Steps per contact time.
    double
    time_step() const;

    /// Hard end of an impact [s] (before the end after separation).
    double
    end_time() const;

    // Scenario
    double     impact_velocity = 0; ///< [m/s]
    double     gravity         = 0; ///< on the sphere [m/s^2]
    Geometry   geometry;
    PlateFaces plate_faces;

    // Bodies, indexed by Body. A rigid plate (Plate/Material model = rigid)
    // is the fixed plane z = 0: no material, no mesh, no faces.
    std::unique_ptr<materials::Interface> material[2];
    bool                                  rigid_plate = false;
    /// [Pa] of the summary's yield check, 0: none (elastic-plastic bodies
    /// yield by themselves).
    double yield_strength[2] = {0, 0};
    /// What each body is made of and where each constant came from (the
    /// model itself moved to material[]).
    materials::BodyMaterial material_used[2];

    // Time control
    std::string scheme;                     ///< Time integration/Scheme
    double      steps_per_contact_time = 0; ///< [-], "auto" resolved
    /// Whether Steps per contact time was "auto" (sized from the expected
    /// contact, discretisation/automatic_discretisation.h).
    bool   steps_per_contact_time_automatic = false;
    double prescribed_time_step  = 0; ///< [s], 0: from steps_per_contact_time
    double time_after_separation = 0; ///< fraction of the contact time [-]
    /// Time integration/Sub-steps at contact entry [-], 1: none
    unsigned int entry_sub_steps = 1;
    /// Whether it was "auto" (the energy balance's rule may raise it).
    bool   entry_sub_steps_automatic = true;
    double maximum_time              = 0; ///< [s], 0: automatic

    std::string direct_solver;
    std::string output_directory;

    // Derived
    double      sphere_mass = 0; ///< [kg]
    HertzImpact hertz;           ///< estimates: step, run length, contact zone
    /// The contact the mesh and the step are sized for, as the analysis
    /// expects it (ExpectedContactOf).
    discretisation::ExpectedContact expected_contact;

    /// Any viscous (Kelvin-Voigt) body, any body with internal variables.
    bool
    has_material_damping() const;
    bool
    has_internal_variables() const;

  private:
    // The steps of the constructor, in their order.
    void
    read_scenario(ParameterHandler &prm);
    void
    check_scenario();
    void
    read_bodies(ParameterHandler &prm);
    void
    read_run_control(ParameterHandler &prm);
    void
    derive_estimates(ParameterHandler &prm, const ExpectedContactOf &expected);
  };
} // namespace impact_fem

#endif
