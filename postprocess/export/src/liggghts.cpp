// LIGGGHTS 3.8 (Debian liggghts): Thornton's elastic-plastic law as the normal model
// thornton_ning of a granular wall, the scenario's plastic contact read from the runs, and the
// input deck that drops the sphere on the wall (mapping in liggghts.hpp).

#include "impact_postprocess/export/liggghts.hpp"

#include "exporter.hpp"
#include "text.hpp"

#include <impact_reduced/liggghts_thornton.hpp>
#include <impact_reduced/thornton.hpp>
#include <impact_reduced/contact_formulas.hpp>

#include <cmath>
#include <ostream>
#include <sstream>

namespace impact::postprocess {

namespace {

constexpr double pi = 3.14159265358979323846;

reduced::ThorntonParameters thornton_parameters(const PlasticContact& contact, double mass,
                                                double radius) {
  return {mass, radius, contact.contact_modulus, contact.yield_pressure};
}

} // namespace

LiggghtsContact liggghts_contact(const PlasticContact& contact, double mass, double radius) {
  LiggghtsContact result;
  result.sphere_youngs_modulus = contact.sphere_youngs_modulus;
  result.sphere_poisson_ratio = contact.sphere_poisson_ratio;
  if (contact.plate_youngs_modulus) {
    result.wall_youngs_modulus = *contact.plate_youngs_modulus;
    result.wall_poisson_ratio = *contact.plate_poisson_ratio;
  } else {
    // One fictitious material on both sides with the rigid plate's E*.
    result.sphere_youngs_modulus = result.wall_youngs_modulus =
        2 * contact.contact_modulus *
        (1 - contact.sphere_poisson_ratio * contact.sphere_poisson_ratio);
    result.wall_poisson_ratio = contact.sphere_poisson_ratio;
  }
  try {
    result.yield_ratio =
        reduced::liggghts_yield_ratio(contact.yield_pressure, contact.contact_modulus);
  } catch (const std::exception& error) {
    throw ExportInputError(std::string("LIGGGHTS thornton_ning: ") + error.what());
  }
  result.density = mass / (4.0 / 3.0 * pi * radius * radius * radius);
  result.yield_velocity =
      reduced::yield_velocity(contact.yield_pressure, contact.contact_modulus, radius, mass);
  return result;
}

ImpactFigures liggghts_thornton_impact(const PlasticContact& contact, double mass, double radius,
                                       double velocity) {
  const auto response =
      reduced::LiggghtsThorntonImpact(thornton_parameters(contact, mass, radius), velocity)
          .response();
  return response.figures();
}

ImpactFigures thornton_impact(const PlasticContact& contact, double mass, double radius,
                              double velocity) {
  const auto response =
      reduced::ThorntonImpact(thornton_parameters(contact, mass, radius), velocity).response();
  return response.figures();
}

namespace {

// The deck's header: what it carries, the constants of the contact and how LIGGGHTS'
// thornton_ning differs from Thornton's paper, and both against the FEM.
void write_header(std::ostream& out, const ExportCampaign& campaign, const PlasticContact& plastic,
                  const LiggghtsContact& contact, const std::vector<ImpactFigures>& model,
                  const std::vector<ImpactFigures>& paper) {
  using export_text::rounded;
  out << "# LIGGGHTS 3.8 input: the sphere dropped on a granular wall with the elastic-plastic\n"
      << "# normal model thornton_ning (Thornton 1997 without adhesion).\n"
      << "# Written by impact-export from " << campaign.calibration_file << " and its runs.\n"
      << "# Run: liggghts -in thornton_ning.in -var V 1.0 -var out drop.txt   (V: impact velocity, "
         "m/s)\n"
      << "# The lines to reuse are the material properties and the 'fix ... wall/gran model\n"
      << "# thornton_ning' below, with the sphere's radius and density as here.\n#\n"
      << "# Contact: E* = " << rounded(plastic.contact_modulus)
      << " Pa, p_y = " << rounded(plastic.yield_pressure) << " Pa,\n# from " << plastic.yield_basis
      << ".\n"
      << "# Hardening does not enter Thornton's law (elastic-perfectly-plastic contact).\n"
      << "# LIGGGHTS yields when the contact radius sqrt(R x) reaches a_y = coefficientYieldRatio "
         "x R;\n"
      << "# Thornton's limiting contact radius a_y = pi p_y R / (2 E*) gives\n"
      << "# coefficientYieldRatio = pi p_y / (2 E*) = " << rounded(contact.yield_ratio, 8)
      << "; yield velocity V_y = " << rounded(contact.yield_velocity) << " m/s.\n"
      << "# LIGGGHTS unloads without surface energy along F* - (4/3) E* sqrt(R) (x_max^1.5 - "
         "x^1.5)\n"
      << "# (the Hertz curve of R through the peak), not Thornton's Hertz curve on the enlarged\n"
      << "# radius R_p: its restitution is lower than the paper's. Its force is integrated by\n"
      << "# explicit increments of the overlap (first order in the time step) and has no damping.\n"
      << (plastic.plate_youngs_modulus ? ""
                                       : "# E* is not split into two bodies (a rigid plate, or E* "
                                         "fitted): both atom types carry the one\n# fictitious "
                                         "material E = 2 E* (1 - nu^2), nu of the sphere, which "
                                         "gives LIGGGHTS the same E*.\n")
      << "# The law (as LIGGGHTS integrates it) and Thornton's paper against the FEM:\n"
      << export_text::error_table("#", campaign, model)
      << "#   V [m/s]  e (LIGGGHTS' law)  e (Thornton, R_p)\n";
  for (std::size_t i = 0; i < campaign.runs.size(); ++i)
    out << "#   " << rounded(campaign.runs[i].velocity, 4) << "  "
        << rounded(model[i].restitution, 5) << "  " << rounded(paper[i].restitution, 5) << "\n";
}

// The units, the velocity and the sphere as variables, the time step from Hertz's contact
// time, and the box.
void write_domain(std::ostream& out, const ExportCampaign& campaign, const PlasticContact& plastic,
                  const LiggghtsContact& contact) {
  using export_text::as_written;
  out << "\n"
      << "units           si\n"
      << "hard_particles  yes          # moduli above 1e9 Pa\n"
      << "atom_style      granular\n"
      << "atom_modify     map array\n"
      << "boundary        f f f\n"
      << "newton          off\n"
      << "communicate     single vel yes\n"
      << "variable        V index " << as_written(campaign.runs.front().velocity)
      << "     # impact velocity [m/s]\n"
      << "variable        out index liggghts_drop.txt\n"
      << "variable        N index 5000     # time steps per Hertz contact time (error in e about "
         "1.2 / N)\n"
      << "variable        mass equal " << as_written(campaign.mass) << "     # kg\n"
      << "variable        radius equal " << as_written(campaign.radius) << "   # m\n"
      << "variable        density equal " << as_written(contact.density)
      << "   # kg/m^3, m / (4/3 pi R^3)\n"
      << "variable        contact_modulus equal " << as_written(plastic.contact_modulus)
      << "   # E* [Pa]\n"
      << "# Hertz's contact time 2.94 (5 m / (4 c))^(2/5) V^(-1/5), c = (4/3) E* sqrt(R), sets the "
         "step;\n"
      << "# the run lasts 3 of them (the plastic contact lasts about one).\n"
      << "variable        hertz_time equal "
         "2.94*(15*v_mass/(16*v_contact_modulus*sqrt(v_radius)))^0.4*v_V^(-0.2)\n"
      << "variable        dt equal v_hertz_time/v_N\n"
      << "variable        top equal 4*v_radius\n"
      << "region          box block -0.05 0.05 -0.05 0.05 -0.01 ${top} units box\n"
      << "create_box      2 box\n"
      << "neighbor        0.002 bin\n"
      << "neigh_modify    delay 0\n";
}

// The two atom types' materials and the thornton_ning contact between them.
void write_contact(std::ostream& out, const LiggghtsContact& contact) {
  using export_text::as_written;
  out << "# Atom type 1: the sphere; type 2: the wall.\n"
      << "fix             m1 all property/global youngsModulus peratomtype "
      << as_written(contact.sphere_youngs_modulus) << " " << as_written(contact.wall_youngs_modulus)
      << "\n"
      << "fix             m2 all property/global poissonsRatio peratomtype "
      << as_written(contact.sphere_poisson_ratio) << " " << as_written(contact.wall_poisson_ratio)
      << "\n"
      << "fix             m3 all property/global coefficientYieldRatio peratomtype "
      << as_written(contact.yield_ratio) << " " << as_written(contact.yield_ratio) << "\n"
      << "fix             m4 all property/global surfaceEnergy peratomtypepair 2 0 0 0 0\n"
      << "# Required by thornton_ning's tangential part, without effect on a normal impact (no\n"
      << "# tangential motion): coefficientRestitution sets only the tangential damping.\n"
      << "fix             m5 all property/global coefficientRestitution peratomtypepair 2 0.5 0.5 "
         "0.5 0.5\n"
      << "fix             m6 all property/global coefficientFriction peratomtypepair 2 0 0 0 0\n"
      << "pair_style      gran model thornton_ning tangential history\n"
      << "pair_coeff      * *\n";
}

// The drop: the sphere above the wall at V, the record of its state at every step, the run.
void write_drop(std::ostream& out) {
  out << "# The sphere starts 10.5 steps of flight above the wall, so that the record shows the "
         "touch.\n"
      << "variable        z0 equal v_radius+10.5*v_V*v_dt\n"
      << "create_atoms    1 single 0 0 ${z0} units box\n"
      << "variable        diameter equal 2*v_radius\n"
      << "set             atom 1 diameter ${diameter} density ${density}\n"
      << "variable        down equal -v_V\n"
      << "velocity        all set 0 0 ${down} units box\n"
      << "fix             plate all wall/gran model thornton_ning tangential history primitive "
         "type 2 zplane 0.0\n"
      << "fix             move all nve/sphere\n"
      << "timestep        ${dt}\n"
      << "variable        time equal time\n"
      << "variable        approach equal v_radius-z[1]\n"
      << "variable        vz equal vz[1]\n"
      << "variable        fz equal fz[1]\n"
      << "fix             record all print 1 \"${time} ${approach} ${vz} ${fz}\" file ${out} "
         "screen no &\n"
      << "                title \"# time [s], approach = radius - z [m], vz [m/s], fz [N] of the "
         "sphere\"\n"
      << "variable        steps equal ceil(3*v_N)+10\n"
      << "run             ${steps}\n";
}

std::string liggghts_file(const ExportCampaign& campaign, const PlasticContact& plastic,
                          const LiggghtsContact& contact, const std::vector<ImpactFigures>& model,
                          const std::vector<ImpactFigures>& paper) {
  std::ostringstream out;
  write_header(out, campaign, plastic, contact, model, paper);
  write_domain(out, campaign, plastic, contact);
  write_contact(out, contact);
  write_drop(out);
  return out.str();
}

} // namespace

namespace exporters {

using json = nlohmann::json;

std::vector<ExportedFile> liggghts(const ExportCampaign& campaign, const CampaignImpact&) {
  if (!campaign.plastic) return {};
  const PlasticContact& plastic = *campaign.plastic;
  const LiggghtsContact contact = liggghts_contact(plastic, campaign.mass, campaign.radius);
  std::vector<ImpactFigures> model, paper;
  for (const auto& run : campaign.runs) {
    model.push_back(
        liggghts_thornton_impact(plastic, campaign.mass, campaign.radius, run.velocity));
    paper.push_back(thornton_impact(plastic, campaign.mass, campaign.radius, run.velocity));
  }
  const std::string file = "liggghts/thornton_ning.in";
  json thornton_paper = predictions_json(campaign, paper);
  json entry = {{"tool", "liggghts"},
                {"tool_version", "3.8.0"},
                {"file", file},
                {"model", "thornton"},
                {"basis", plastic.yield_basis},
                {"force_law",
                 "loading F = (4/3) E* sqrt(R) x^(3/2) to x_y = R (pi p_y / (2 E*))^2, then "
                 "dF/dx = pi p_y R; unloading (LIGGGHTS) F* - (4/3) E* sqrt(R) (x_max^(3/2) - "
                 "x^(3/2))"},
                {"calibrated",
                 {{"E*", value_unit(plastic.contact_modulus, "Pa")},
                  {"p_y", value_unit(plastic.yield_pressure, "Pa")},
                  {"V_y", value_unit(contact.yield_velocity, "m/s")}}},
                {"parameters",
                 {{"normal_model", "thornton_ning"},
                  {"youngsModulus",
                   {value_unit(contact.sphere_youngs_modulus, "Pa"),
                    value_unit(contact.wall_youngs_modulus, "Pa")}},
                  {"poissonsRatio", {contact.sphere_poisson_ratio, contact.wall_poisson_ratio}},
                  {"coefficientYieldRatio", value_unit(contact.yield_ratio, "1")},
                  {"surfaceEnergy", value_unit(0, "J/m^2")},
                  {"density", value_unit(contact.density, "kg/m^3")}}},
                {"mapping",
                 "coefficientYieldRatio = a_y / R = pi p_y / (2 E*) (Thornton's limiting contact "
                 "radius); density = m / (4/3 pi R^3)"},
                {"same_law", false},
                {"recommended", true},
                {"rms_residual", nullptr},
                {"note",
                 "the predictions are Thornton's law as LIGGGHTS integrates it (unloading on the "
                 "Hertz curve of R through the peak); thornton_paper gives the paper's law "
                 "(unloading on R_p)"},
                {"reference_velocity", nullptr},
                {"predictions", predictions_json(campaign, model)},
                {"thornton_paper", thornton_paper}};
  return {{file, liggghts_file(campaign, plastic, contact, model, paper), entry}};
}

} // namespace exporters
} // namespace impact::postprocess
