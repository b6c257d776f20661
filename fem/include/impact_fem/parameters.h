#ifndef IMPACT_FEM_PARAMETERS_H
#define IMPACT_FEM_PARAMETERS_H

#include <impact_fem/discretisation/expected_contact.h>
#include <impact_fem/hertz.h>
#include <impact_fem/materials/body_material.h>
#include <impact_fem/materials/interface.h>
#include <impact_fem/mesh/sphere_plate_mesh.h>

#include <deal.II/base/parameter_handler.h>

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
   * The scenario of an impact run, read and checked in one place: analysis,
   * geometry, materials and yield strengths of both bodies, time control,
   * solver and output directory, and the Hertz estimates derived from them.
   * The components (mesh, contact, time stepper, postprocessors) declare and
   * read their own entries; declare_parameters() declares them all.
   */
  struct Parameters
  {
    /// Every entry of an impact run (of this struct and of the components).
    static void
    declare_parameters(ParameterHandler &prm);

    /// Read and check; an ExcMessage names the entry and its allowed range.
    explicit Parameters(ParameterHandler &prm);

    /**
     * The time step for a scheme whose effective mass coefficient is
     * mass_weight / dt^2 [s]: Hertz contact time / Steps per contact time,
     * or the prescribed Time step; for the static press the step that ties
     * the free sphere to the ground by soft springs (see the .cc).
     */
    double
    time_step(const double mass_weight) const;

    /// Hard end of the run [s] (before the end after separation).
    double
    end_time(const double time_step) const;

    // Scenario
    bool static_press = false; ///< quasi-static press, no impact
    bool indentation =
      false; ///< quasi-static displacement-controlled indentation
    double     static_force    = 0; ///< [N]
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
    double maximum_time          = 0; ///< [s], 0: automatic

    std::string direct_solver;
    std::string output_directory;

    // Derived
    double      sphere_mass = 0; ///< [kg]
    HertzImpact hertz;           ///< estimates: step, run length, contact zone
    /// The contact the mesh and the step are sized for (an impact: Hertz,
    /// or Jackson-Green if a body can yield; the static press: Hertz under
    /// the static force; the indentation: set by its analysis).
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
    derive_estimates(ParameterHandler &prm);
  };
} // namespace impact_fem

#endif
