// LAMMPS (29 Sep 2021, GRANULAR package): Kuwabara–Kono and Tsuji as fix wall/gran granular
// with the hertz normal model (mapping in simulator_export.hpp), and the input deck that drops
// the sphere on the wall.

#include "impact_postprocess/export/simulator_export.hpp"

#include "exporter.hpp"
#include "text.hpp"

#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <cstdint>
#include <sstream>

namespace impact::postprocess {

double lammps_tsuji_alpha(double e) {
  return 1.2728 - 4.2783 * e + 11.087 * e * e - 22.348 * std::pow(e, 3) + 27.467 * std::pow(e, 4) -
         18.022 * std::pow(e, 5) + 4.8218 * std::pow(e, 6);
}

double lammps_tsuji_restitution_input(double alpha) {
  const double lower = lammps_tsuji_alpha(1), upper = lammps_tsuji_alpha(0);
  if (!(alpha >= lower && alpha <= upper))
    throw ExportInputError(
        "LAMMPS tsuji damping: alpha = eta / sqrt(m c) = " + std::to_string(alpha) +
        " is outside the range [" + std::to_string(lower) + ", " + std::to_string(upper) +
        "] of LAMMPS's Tsuji polynomial");
  const auto gap = [=](double e) { return lammps_tsuji_alpha(e) - alpha; };
  std::uintmax_t iterations = 200;
  const auto root =
      boost::math::tools::toms748_solve(gap, 0.0, 1.0, upper - alpha, lower - alpha,
                                        boost::math::tools::eps_tolerance<double>(52), iterations);
  return 0.5 * (root.first + root.second);
}

LammpsContact lammps_contact(const HertzLawFit& law, double mass, double radius) {
  const double normal_stiffness = law.stiffness / std::sqrt(radius);
  if (law.model == "kuwabara-kono")
    return {law.model, "viscoelastic", normal_stiffness,
            1.5 * law.damping * law.stiffness / (mass * std::sqrt(radius))};
  if (law.model == "tsuji")
    return {law.model, "tsuji", normal_stiffness,
            lammps_tsuji_restitution_input(law.damping / std::sqrt(mass * law.stiffness))};
  throw ExportInputError("LAMMPS has no granular damping model for the law '" + law.model + "'");
}

namespace export_text {

std::string lammps_file(const ExportCampaign& campaign, const HertzLawFit& law,
                        const LammpsContact& contact, const std::vector<ImpactFigures>& model,
                        bool recommended) {
  const bool kuwabara_kono = law.model == "kuwabara-kono";
  std::ostringstream out;
  out << "# LAMMPS (29 Sep 2021, GRANULAR) input: the calibrated sphere dropped on a granular "
         "wall.\n"
      << "# Written by impact-export from " << campaign.calibration_file << ".\n"
      << "# Run: lmp -in " << (kuwabara_kono ? "kuwabara_kono.in" : "tsuji.in")
      << " -var V 1.0 -var out drop.txt   (V: impact velocity, m/s)\n"
      << "# The line to reuse is the 'fix ... wall/gran granular' below, with the sphere's radius\n"
      << "# and mass as here (LAMMPS's damping uses the particle's mass).\n#\n";
  if (kuwabara_kono)
    out << "# Model: Kuwabara-Kono / Brilliantov viscoelastic sphere, the campaign fit\n"
        << "#   F = c x^(3/2) + (3/2) A c x^(1/2) dx/dt,  c = " << rounded(law.stiffness)
        << " N/m^1.5, A = " << rounded(law.damping) << " s.\n"
        << "# LAMMPS: hertz F = k_n a x with a = sqrt(R x), so k_n = c / sqrt(R); damping\n"
        << "# viscoelastic F_d = eta_n0 m a dx/dt, so eta_n0 = (3/2) A c / (m sqrt(R)). The same "
           "law.\n";
  else
    out << "# Model: Hertz with Tsuji damping, the campaign fit\n"
        << "#   F = c x^(3/2) + eta x^(1/4) dx/dt,  c = " << rounded(law.stiffness)
        << " N/m^1.5, eta = " << rounded(law.damping) << " N s/m^(5/4).\n"
        << "# LAMMPS: hertz F = k_n a x with a = sqrt(R x), so k_n = c / sqrt(R); damping tsuji\n"
        << "# F_d = alpha(e_in) sqrt(m k_n a) dx/dt with LAMMPS's polynomial alpha(e_in), so\n"
        << "# alpha(e_in) = eta / sqrt(m c) = "
        << rounded(law.damping / std::sqrt(campaign.mass * law.stiffness))
        << ": e_in = " << rounded(contact.damping_coefficient, 8)
        << " is LAMMPS's input, not the restitution\n"
        << "# the law produces (the table below gives that). The same law.\n";
  out << "# RMS force-history residual of the fit: " << rounded(100 * law.rms_residual, 3)
      << " % of the peak force (Hunt-Crossley, free n: "
      << rounded(100 * campaign.free_rms_residual, 3) << " %).\n"
      << "# LAMMPS's granular damping (velocity, mass_velocity, viscoelastic, tsuji) has no\n"
      << "# Hunt-Crossley form c x^n b dx/dt, so the closest laws of the calibration are "
         "exported:\n"
      << "# kuwabara_kono.in and tsuji.in; " << (recommended ? "this one" : "the other one")
      << " has the smaller residual against the FEM.\n"
      << "# Neither law is clamped: near separation the damping pulls (F < 0), as in the fit,\n"
      << "# so LAMMPS's limit_damping keyword (which cuts the pull) is not used.\n"
      << "# Velocities of the campaign: " << rounded(campaign.runs.front().velocity) << " to "
      << rounded(campaign.runs.back().velocity) << " m/s. The law against the FEM:\n"
      << error_table("#", campaign, model) << "\n"
      << "units           si\n"
      << "atom_style      sphere\n"
      << "atom_modify     map array\n"
      << "boundary        f f f\n"
      << "variable        V index " << as_written(campaign.runs.front().velocity)
      << "     # impact velocity [m/s]\n"
      << "variable        out index lammps_drop.txt\n"
      << "variable        mass equal " << as_written(campaign.mass) << "     # kg\n"
      << "variable        radius equal " << as_written(campaign.radius) << "   # m\n"
      << "variable        kn equal " << as_written(contact.normal_stiffness) << "       # Pa\n"
      << "variable        damping equal " << as_written(contact.damping_coefficient)
      << (kuwabara_kono ? "  # eta_n0 [1/(m s)]\n" : "  # e_in [-] of LAMMPS's Tsuji polynomial\n")
      << "# Hertz's contact time 2.94 (5 m / (4 c))^(2/5) V^(-1/5) sets the step (1/2000 of it).\n"
      << "variable        hertz_time equal 2.94*(5*v_mass/(4*v_kn*sqrt(v_radius)))^0.4*v_V^(-0.2)\n"
      << "variable        dt equal v_hertz_time/2000\n"
      << "region          box block -0.05 0.05 -0.05 0.05 0 $(4*v_radius)\n"
      << "create_box      1 box\n"
      << "create_atoms    1 single 0 0 $(v_radius+0.5*v_V*v_dt)\n"
      << "set             atom 1 diameter $(2*v_radius) mass ${mass}\n"
      << "velocity        all set 0 0 $(-v_V)\n"
      << "fix             plate all wall/gran granular hertz ${kn} ${damping} damping "
      << contact.damping_model << " tangential linear_nohistory 0 0 zplane 0.0 NULL\n"
      << "fix             move all nve/sphere\n"
      << "timestep        ${dt}\n"
      << "variable        time equal time\n"
      << "variable        z equal z[1]\n"
      << "variable        vz equal vz[1]\n"
      << "variable        fz equal fz[1]\n"
      << "fix             record all print 1 \"${time} ${z} ${vz} ${fz}\" file ${out} screen no &\n"
      << "                title \"# time [s], z [m], vz [m/s], fz [N] of the sphere; overlap = "
         "radius - z\"\n"
      << "run             $(ceil(1.5*v_hertz_time/v_dt))\n";
  return out.str();
}

} // namespace export_text
namespace exporters {

using json = nlohmann::json;

std::vector<ExportedFile> lammps(const ExportCampaign& campaign, const CampaignImpact&) {
  ExportList list;
  std::vector<const HertzLawFit*> lammps_laws;
  if (campaign.kuwabara_kono) lammps_laws.push_back(&*campaign.kuwabara_kono);
  if (campaign.tsuji) lammps_laws.push_back(&*campaign.tsuji);
  const HertzLawFit* best = lammps_laws.front();
  for (const auto* law : lammps_laws)
    if (law->rms_residual < best->rms_residual) best = law;
  for (const auto* law : lammps_laws) {
    const bool kk = law->model == "kuwabara-kono";
    const LammpsContact lammps = lammps_contact(*law, campaign.mass, campaign.radius);
    const auto figures = law_on_campaign(campaign, *law);
    const std::string file = kk ? "lammps/kuwabara_kono.in" : "lammps/tsuji.in";
    list.files.emplace_back(file,
                            export_text::lammps_file(campaign, *law, lammps, figures, law == best));
    list.exports.push_back(
        {{"tool", "lammps"},
         {"tool_version", "29 Sep 2021"},
         {"file", file},
         {"model", law->model},
         {"basis", "campaign.comparison_laws[" + law->model + "]"},
         {"force_law",
          kk ? "F = c x^(3/2) + (3/2) A c x^(1/2) dx/dt" : "F = c x^(3/2) + eta x^(1/4) dx/dt"},
         {"calibrated",
          {{"c", value_unit(law->stiffness, "N/m^1.5")},
           {kk ? "A" : "eta", value_unit(law->damping, kk ? "s" : "N s/m^(5/4)")}}},
         {"parameters",
          {{"normal_model", "hertz"},
           {"damping_model", lammps.damping_model},
           {"k_n", value_unit(lammps.normal_stiffness, "Pa")},
           {kk ? "eta_n0" : "e_in", value_unit(lammps.damping_coefficient, kk ? "1/(m s)" : "1")}}},
         {"mapping", kk ? "hertz k_n = c / sqrt(R); damping viscoelastic eta_n0 = (3/2) A c / "
                          "(m sqrt(R))"
                        : "hertz k_n = c / sqrt(R); damping tsuji with e_in solving LAMMPS's "
                          "alpha(e_in) = eta / sqrt(m c)"},
         {"same_law", true},
         {"recommended", law == best},
         {"rms_residual", law->rms_residual},
         {"note",
          "LAMMPS's granular damping has no Hunt-Crossley form; the law with the smaller "
          "force-history residual is recommended"},
         {"reference_velocity", nullptr},
         {"predictions", predictions_json(campaign, figures)}});
  }

  return list.zipped();
}

} // namespace exporters
} // namespace impact::postprocess
