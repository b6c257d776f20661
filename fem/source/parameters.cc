#include <impact_fem/discretisation/automatic_discretisation.h>
#include <impact_fem/materials/body_material.h>
#include <impact_fem/parameters.h>
#include <impact_fem/result_files.h>
#include <impact_fem/time_integration/interface.h>

#include <cmath>
#include <limits>

namespace impact_fem
{
  namespace
  {
    std::string
    text(const double x)
    {
      std::ostringstream s;
      s << x;
      return s.str();
    }

    std::string
    face_name(const FaceCondition condition)
    {
      return condition == FaceCondition::free      ? "free" :
             condition == FaceCondition::clamped   ? "clamped" :
             condition == FaceCondition::absorbing ? "absorbing" :
                                                     "support";
    }


    // The entries of subsection Scenario.
    void
    declare_scenario(ParameterHandler &prm)
    {
      // The entries the result files' reader interprets carry the
      // contract's names and units.
      namespace contract = result_files;
      const auto unit    = [](const contract::Parameter &parameter) {
        return std::string(" [") + parameter.unit + "]";
      };
      // Scenario/Analysis and the entries of each analysis are the
      // analyses' own (analysis/interface.h).
      prm.enter_subsection(contract::scenario_subsection);
      prm.declare_entry(contract::impact_velocity.entry,
                        "1",
                        Patterns::Double(),
                        "Speed of the sphere towards the plate at t = 0" +
                          unit(contract::impact_velocity) +
                          ", in [1e-6, 100].");
      prm.declare_entry(contract::initial_gap.entry,
                        "0",
                        Patterns::Double(),
                        "Distance between sphere and plate at t = 0" +
                          unit(contract::initial_gap) + ", in [0, 10 R].");
      prm.declare_entry(contract::sphere_radius.entry,
                        "0.01452",
                        Patterns::Double(),
                        "Radius R of the sphere" +
                          unit(contract::sphere_radius) +
                          ", > 0 (0.01452 m: a 0.1 kg steel ball).");
      prm.declare_entry(contract::plate_radius.entry,
                        "0.35",
                        Patterns::Double(),
                        "Radius Rp of the plate" +
                          unit(contract::plate_radius) +
                          ", in (2 R, 1000 R] (not used with a rigid plate).");
      prm.declare_entry(contract::plate_thickness.entry,
                        "0.35",
                        Patterns::Double(),
                        "Thickness H of the plate" +
                          unit(contract::plate_thickness) +
                          ", in (0, 1000 R] (not used with a rigid plate).");
      prm.declare_entry(
        "Plate side",
        "absorbing",
        Patterns::Selection("free|clamped|absorbing"),
        "Condition on the plate's side face r = Rp: 'free' "
        "(traction-free), 'clamped' (zero displacement) or "
        "'absorbing' (Lysmer-Kuhlemeyer dashpots rho c_p on the "
        "normal and rho c_s on the tangential velocity: the "
        "finite plate stands in for an infinite one).");
      prm.declare_entry("Plate bottom",
                        "absorbing",
                        Patterns::Selection("free|clamped|absorbing|support"),
                        "Condition on the plate's bottom face z = -H: 'free', "
                        "'clamped', 'absorbing' (as Plate side: the plate "
                        "stands in for a half-space) or 'support' (an elastic "
                        "foundation pushing back on the normal displacement "
                        "with Support stiffness per area).");
      prm.declare_entry(
        "Support stiffness",
        "0",
        Patterns::Double(0),
        "Normal stiffness per area k of a Plate bottom = "
        "support [N/m^3 = Pa/m], > 0 (read only then): traction -k u_z on "
        "the bottom (Winkler foundation; e.g. E/t of a soft "
        "layer of modulus E and thickness t on a rigid floor).");
      // Replaced by Plate side and Plate bottom: declared only to
      // refuse it with a message saying what to write instead.
      prm.declare_entry("Far boundary",
                        "",
                        Patterns::Anything(),
                        "Replaced by 'Plate side' and 'Plate bottom'; must not "
                        "be set.");
      prm.declare_entry("Gravity",
                        "0",
                        Patterns::Double(),
                        "Gravitational acceleration acting on the sphere "
                        "[m/s^2], >= 0 (the plate is taken as pre-stressed "
                        "by its own weight).");
      prm.leave_subsection();
    }
  } // namespace


  void
  Parameters::declare_parameters(ParameterHandler &prm)
  {
    namespace contract = result_files;
    declare_scenario(prm);

    for (const auto *body : {contract::sphere_body, contract::plate_body})
      {
        prm.enter_subsection(body);
        materials::declare_parameters(prm, contract::elastic_model);
        materials::declare_body_entries(prm);
        prm.leave_subsection();
      }

    prm.enter_subsection("Time integration");
    prm.declare_entry("Steps per contact time",
                      "auto",
                      *discretisation::number_or_auto_pattern(),
                      "Time step = Hertz contact time / this number [-], "
                      "in [10, 1e6]; 'auto': 300 steps per expected contact "
                      "time (Hertz, or Jackson-Green's elastic-plastic "
                      "impact if a body can yield; the run's log and "
                      "summary.json say which), and if the run's energy "
                      "balance then misses 1e-4 mostly by the contact "
                      "activation's work, the run is made once more with "
                      "(|error| / 8e-5)^(1/1.2) times the steps, at most 8 "
                      "times (where capped, with 'Sub-steps at contact "
                      "entry'; and if it still misses, mostly by the rest of "
                      "the error, once more with automatic contact nodes "
                      "twice as dense, unless a contact node's force at the "
                      "peak made them so already: Mesh/Contact surface "
                      "refinements).");
    prm.declare_entry("Time step",
                      "0",
                      Patterns::Double(),
                      "Fixed time step [s], 0 or in [t_c / 1e6, t_c / 10], "
                      "t_c the Hertz contact time; 0 takes it from "
                      "'Steps per contact time'.");
    prm.declare_entry("Sub-steps at contact entry",
                      "auto",
                      *discretisation::number_or_auto_pattern(),
                      "A step in which a contact node starts or stops "
                      "carrying pressure is taken again as this many "
                      "sub-steps, and so is the step after it [-], an "
                      "integer in [1, 64] (1: never): the work the node's "
                      "pressure does over the gap it closes within the step, "
                      "lost to the contact activation, falls with the "
                      "sub-step. 'auto': 1, unless the automatic step's "
                      "refinement for the energy balance is capped at 8 "
                      "times: then as many as take the activation's work to "
                      "0.4 of the balance's target (the run's log and "
                      "summary say how many). Not with Maxwell arms, whose "
                      "tangent is made for one step length.");
    prm.declare_entry("Time after separation",
                      "0.1",
                      Patterns::Double(),
                      "How long the run continues after the bodies separate, "
                      "as a fraction of the contact time [-], in [0, 10]; "
                      "the rebound velocity is read at the end.");
    prm.declare_entry("Maximum time",
                      "0",
                      Patterns::Double(),
                      "Hard end of the run [s], >= 0; 0 means the time of "
                      "flight to the plate plus three Hertz contact times.");
    prm.leave_subsection();

    prm.enter_subsection("Solver");
    prm.declare_entry("Direct solver",
                      "auto",
                      Patterns::Selection("auto|Amesos_Mumps|Amesos_Klu"),
                      "Trilinos/Amesos sparse direct solver of the "
                      "effective stiffness (factorised once per run): "
                      "Amesos_Mumps (parallel) or Amesos_Klu (serial); "
                      "auto: Amesos_Klu on one rank with an elastic-plastic "
                      "body, whose steps back-substitute tens of times "
                      "(KLU's back-substitution measured 1.4-2.1 times "
                      "faster there), Amesos_Mumps otherwise (faster on the "
                      "elastic runs measured); doc/results/fem-model.md.");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Directory",
                      "results/default",
                      Patterns::Anything(),
                      "Directory of the run's files (history.h5, "
                      "summary.json, mesh, snapshots); created if needed.");
    prm.leave_subsection();

    // Time integration/Scheme is read here (the log and the summary name
    // it).
    time_integration::declare_parameters(prm);
  }


  Parameters::Parameters(ParameterHandler        &prm,
                         const ExpectedContactOf &expected)
  {
    read_scenario(prm);
    check_scenario();
    read_bodies(prm);
    read_run_control(prm);
    derive_estimates(prm, expected);
  }


  // Subsection Scenario.
  void
  Parameters::read_scenario(ParameterHandler &prm)
  {
    namespace contract = result_files;
    prm.enter_subsection(contract::scenario_subsection);
    impact_velocity          = prm.get_double(contract::impact_velocity.entry);
    geometry.initial_gap     = prm.get_double(contract::initial_gap.entry);
    geometry.sphere_radius   = prm.get_double(contract::sphere_radius.entry);
    geometry.plate_radius    = prm.get_double(contract::plate_radius.entry);
    geometry.plate_thickness = prm.get_double(contract::plate_thickness.entry);
    const std::string far_boundary = prm.get("Far boundary");
    AssertThrow(far_boundary.empty(),
                ExcMessage("Scenario/Far boundary was replaced by Scenario/"
                           "Plate side and Scenario/Plate bottom: write 'set "
                           "Plate side = " +
                           far_boundary +
                           "' and 'set Plate "
                           "bottom = " +
                           far_boundary + "' instead."));
    const auto condition = [](const std::string &name) {
      return name == "free"      ? FaceCondition::free :
             name == "clamped"   ? FaceCondition::clamped :
             name == "absorbing" ? FaceCondition::absorbing :
                                   FaceCondition::support;
    };
    plate_faces.side              = condition(prm.get("Plate side"));
    plate_faces.bottom            = condition(prm.get("Plate bottom"));
    plate_faces.support_stiffness = prm.get_double("Support stiffness");
    gravity                       = prm.get_double("Gravity");
    prm.leave_subsection();
  }


  // The bounds of the scenario.
  void
  Parameters::check_scenario()
  {
    // The bounds keep a run finite: below 1e-6 m/s the Hertz contact time,
    // and with it the time step, grows without bound (the solver fails at
    // 1e-300 m/s); a gap, plate or step count far beyond the sphere's scale
    // means a mesh or a number of steps no run can finish.
    AssertThrow(impact_velocity >= 1e-6 && impact_velocity <= 100,
                ExcMessage("Scenario/Impact velocity must lie in [1e-6, 100] "
                           "m/s, got " +
                           text(impact_velocity) + "."));
    AssertThrow(geometry.initial_gap >= 0,
                ExcMessage("Scenario/Initial gap must not be negative, got " +
                           text(geometry.initial_gap) + " m."));
    AssertThrow(geometry.sphere_radius > 0,
                ExcMessage("Scenario/Sphere radius must be positive, got " +
                           text(geometry.sphere_radius) + " m."));
    AssertThrow(geometry.plate_thickness > 0,
                ExcMessage("Scenario/Plate thickness must be positive, got " +
                           text(geometry.plate_thickness) + " m."));
    AssertThrow(geometry.plate_radius > 2 * geometry.sphere_radius,
                ExcMessage("Scenario/Plate radius must exceed twice the "
                           "sphere radius, got " +
                           text(geometry.plate_radius) + " m."));
    AssertThrow(geometry.initial_gap <= 10 * geometry.sphere_radius,
                ExcMessage("Scenario/Initial gap must be at most 10 sphere "
                           "radii (" +
                           text(10 * geometry.sphere_radius) + " m), got " +
                           text(geometry.initial_gap) + " m."));
    AssertThrow(gravity >= 0,
                ExcMessage("Scenario/Gravity must not be negative, got " +
                           text(gravity) + " m/s^2."));
    AssertThrow(plate_faces.bottom != FaceCondition::support ||
                  plate_faces.support_stiffness > 0,
                ExcMessage("Scenario/Support stiffness must be positive for "
                           "Plate bottom = support, got " +
                           text(plate_faces.support_stiffness) + " N/m^3."));
  }


  // Sphere and Plate: the materials and a rigid plate.
  void
  Parameters::read_bodies(ParameterHandler &prm)
  {
    namespace contract = result_files;
    for (const unsigned int body : {sphere, plate})
      {
        materials::BodyMaterial read = materials::read_body_material(
          prm, body == sphere ? contract::sphere_body : contract::plate_body);
        const bool rigid = read.model == materials::rigid_model_name;
        // The elastic-plastic model yields by itself (its plastic strain is
        // reported); the summary's yield check is for the models that
        // cannot.
        yield_strength[body] = read.model == contract::elastic_plastic_model ?
                                 0 :
                                 read.yield_strength;
        material[body]       = std::move(read.material);
        material_used[body]  = std::move(read);
        AssertThrow(!rigid || body == plate,
                    ExcMessage("Sphere/Material model = rigid is not allowed: "
                               "the sphere is the deformable body (only the "
                               "plate can be rigid); choose one of the "
                               "material models."));
        rigid_plate = rigid;
      }
    geometry.plate_meshed = !rigid_plate;
    // A meshed plate far larger than the sphere is a mesh no run can finish.
    AssertThrow(!geometry.plate_meshed ||
                  (geometry.plate_radius <= 1000 * geometry.sphere_radius &&
                   geometry.plate_thickness <= 1000 * geometry.sphere_radius),
                ExcMessage("Scenario/Plate radius and Scenario/Plate thickness "
                           "must be at most 1000 sphere radii (" +
                           text(1000 * geometry.sphere_radius) + " m), got " +
                           text(geometry.plate_radius) + " m and " +
                           text(geometry.plate_thickness) + " m."));
    if (rigid_plate)
      {
        // A rigid plate has no faces and no stresses: entries that describe
        // them would silently mean nothing, so anything but their defaults
        // is refused.
        const auto refuse = [](const bool         set,
                               const std::string &entry,
                               const std::string &value) {
          AssertThrow(!set,
                      ExcMessage(entry + " = " + value +
                                 " has no meaning "
                                 "with Plate/Material model = rigid (the "
                                 "plate is a fixed rigid plane, not meshed); "
                                 "leave it at its default."));
        };
        refuse(plate_faces.side != FaceCondition::absorbing,
               "Scenario/Plate side",
               face_name(plate_faces.side));
        refuse(plate_faces.bottom != FaceCondition::absorbing,
               "Scenario/Plate bottom",
               face_name(plate_faces.bottom));
        refuse(plate_faces.support_stiffness != 0,
               "Scenario/Support stiffness",
               text(plate_faces.support_stiffness));
      }
  }


  // Time integration, Solver, Output.
  void
  Parameters::read_run_control(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    scheme                = prm.get("Scheme");
    prescribed_time_step  = prm.get_double("Time step");
    time_after_separation = prm.get_double("Time after separation");
    const double sub_steps =
      discretisation::number_or_auto(prm,
                                     "Sub-steps at contact entry",
                                     "Time integration/Sub-steps at contact "
                                     "entry",
                                     1,
                                     entry_sub_steps_automatic);
    maximum_time = prm.get_double("Maximum time");
    prm.leave_subsection();
    AssertThrow(prescribed_time_step >= 0,
                ExcMessage("Time integration/Time step must not be negative, "
                           "got " +
                           text(prescribed_time_step) + " s."));
    AssertThrow(sub_steps >= 1 && sub_steps <= 64 &&
                  sub_steps == std::floor(sub_steps),
                ExcMessage("Time integration/Sub-steps at contact entry must "
                           "be 'auto' or an integer in [1, 64], got " +
                           text(sub_steps) + "."));
    entry_sub_steps = static_cast<unsigned int>(sub_steps);
    AssertThrow(time_after_separation >= 0 && time_after_separation <= 10,
                ExcMessage("Time integration/Time after separation must lie "
                           "in [0, 10], got " +
                           text(time_after_separation) + "."));
    AssertThrow(maximum_time >= 0,
                ExcMessage("Time integration/Maximum time must not be "
                           "negative, got " +
                           text(maximum_time) + " s."));

    prm.enter_subsection("Solver");
    direct_solver = prm.get("Direct solver");
    prm.leave_subsection();
    prm.enter_subsection("Output");
    output_directory = prm.get("Directory");
    prm.leave_subsection();
    AssertThrow(!output_directory.empty(),
                ExcMessage("Output/Directory must not be empty."));
  }


  // The sphere's mass, the Hertz estimates and the contact the sizes and
  // the step left "auto" are made for.
  void
  Parameters::derive_estimates(ParameterHandler        &prm,
                               const ExpectedContactOf &expected)
  {
    const double R = geometry.sphere_radius;
    sphere_mass    = material[sphere]->density() * 4. / 3. * M_PI * R * R * R;
    // A rigid plate has no compliance (an infinite modulus): E* is the
    // sphere's E/(1 - nu^2).
    const materials::Interface *plate_material = material[plate].get();
    hertz =
      HertzImpact{impact::reduced::contact_modulus(
                    material[sphere]->youngs_modulus(),
                    material[sphere]->poissons_ratio(),
                    plate_material ? plate_material->youngs_modulus() :
                                     std::numeric_limits<double>::infinity(),
                    plate_material ? plate_material->poissons_ratio() : 0.),
                  R,
                  sphere_mass,
                  impact_velocity};
    // What the contact will be, for the sizes and the step left "auto".
    expected_contact = expected(*this);
    {
      prm.enter_subsection("Time integration");
      const double automatic_steps =
        discretisation::AutomaticDiscretisation::
          steps_per_expected_contact_time *
        (expected_contact.contact_time > 0 ?
           hertz.contact_time() / expected_contact.contact_time :
           1.);
      steps_per_contact_time =
        discretisation::number_or_auto(prm,
                                       "Steps per contact time",
                                       "Time integration/Steps per contact "
                                       "time",
                                       automatic_steps,
                                       steps_per_contact_time_automatic);
      prm.leave_subsection();
    }
    AssertThrow(steps_per_contact_time >= 10 && steps_per_contact_time <= 1e6,
                ExcMessage("Time integration/Steps per contact time must lie "
                           "in [10, 1e6], got " +
                           text(steps_per_contact_time) + "."));

    // The same bounds as for 'Steps per contact time'.
    const double contact_time = hertz.contact_time();
    AssertThrow(prescribed_time_step == 0 ||
                  (prescribed_time_step >= contact_time / 1e6 &&
                   prescribed_time_step <= contact_time / 10),
                ExcMessage("Time integration/Time step must be 0 or lie in "
                           "[t_c / 1e6, t_c / 10] = [" +
                           text(contact_time / 1e6) + ", " +
                           text(contact_time / 10) +
                           "] s (t_c the Hertz "
                           "contact time), got " +
                           text(prescribed_time_step) + " s."));
  }


  double
  Parameters::time_step() const
  {
    return prescribed_time_step > 0 ?
             prescribed_time_step :
             hertz.contact_time() / steps_per_contact_time;
  }


  double
  Parameters::end_time() const
  {
    return maximum_time > 0 ?
             maximum_time :
             geometry.initial_gap / impact_velocity + 3 * hertz.contact_time();
  }


  bool
  Parameters::has_material_damping() const
  {
    for (const auto &m : material)
      if (m && m->damping_tangent().norm() > 0)
        return true;
    return false;
  }


  bool
  Parameters::has_internal_variables() const
  {
    for (const auto &m : material)
      if (m && m->n_internal_variables() > 0)
        return true;
    return false;
  }
} // namespace impact_fem
