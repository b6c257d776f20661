// MuJoCo 2.2.2: the contact as the clamped linear spring-damper that MuJoCo's soft contact
// is for one body on a plane (direct solref, flat solimp; simulator_export.hpp), matched to
// the FEM restitution and contact time at one reference velocity, and the MJCF that holds it.
//
// The spring-damper x'' + 2 zeta omega x' + omega^2 x = 0, x(0) = 0, x'(0) = V gives
//   x = (V / omega_d) exp(-sigma t) sin(omega_d t),  sigma = zeta omega,
//   F / m = omega^2 x + 2 sigma x' = V exp(-sigma t) M sin(omega_d t + phi),
//   M sin(phi) = 2 sigma, M cos(phi) = (omega^2 - 2 sigma^2) / omega_d.
// The contact cannot pull, so it ends when F = 0, at omega_d t_c = pi - phi, with
// restitution e = -x'(t_c) / V; e depends on zeta alone, t_c then fixes omega.

#include "impact_postprocess/export/simulator_export.hpp"

#include "exporter.hpp"
#include "text.hpp"

#include <impact_reduced/invalid_input.hpp>

#include <boost/math/constants/constants.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace impact::postprocess {

namespace {

constexpr double pi = boost::math::constants::pi<double>();

// The impedance d of the flat solimp: the dynamics of one free body do not depend on it
// (MuJoCo divides K by d^2 and B by d and scales the reference acceleration by d), but with
// other forces on the body a fraction 1 - d of their acceleration passes the contact, so d
// is close to MuJoCo's maximum 0.9999.
constexpr double contact_impedance = 0.99;

// Steps per contact time of the exported model: the test measures e and t_c within 0.2 % of
// the closed form with MuJoCo's Euler integrator at this step (tests/consumers).
constexpr double steps_per_contact = 1000;

struct Oscillator {
  double sigma, omega_d, phi, magnitude;
};

Oscillator oscillator(double stiffness, double damping) {
  const double omega = std::sqrt(stiffness);
  const double sigma = damping / 2;
  if (!(sigma < omega))
    throw ExportInputError("MuJoCo contact: damping ratio B / (2 sqrt(K)) = " +
                           std::to_string(sigma / omega) + " must be below 1");
  const double omega_d = std::sqrt((omega - sigma) * (omega + sigma));
  const double p = (omega * omega - 2 * sigma * sigma) / omega_d, q = 2 * sigma;
  return {sigma, omega_d, std::atan2(q, p), std::hypot(p, q)};
}

// Restitution of the unit oscillator (omega = 1) with damping ratio zeta in [0, 1).
double restitution_at_damping_ratio(double zeta) {
  const Oscillator o = oscillator(1, 2 * zeta);
  const double t = (pi - o.phi) / o.omega_d;
  return -std::exp(-o.sigma * t) *
         (std::cos(o.omega_d * t) - o.sigma / o.omega_d * std::sin(o.omega_d * t));
}

} // namespace

ImpactFigures linear_contact_impact(double stiffness, double damping, double mass,
                                    double velocity) {
  reduced::require_positive("stiffness", stiffness);
  reduced::require_non_negative("damping", damping);
  reduced::require_positive("mass", mass);
  reduced::require_positive("velocity", velocity);
  const Oscillator o = oscillator(stiffness, damping);
  const double contact_time = (pi - o.phi) / o.omega_d;
  const double rebound = std::exp(-o.sigma * contact_time) *
                         (std::cos(o.omega_d * contact_time) -
                          o.sigma / o.omega_d * std::sin(o.omega_d * contact_time));
  // dF/dt = 0 where tan(omega_d t + phi) = omega_d / sigma; before t = 0 the peak is F(0).
  const double peak_phase = std::atan2(o.omega_d, o.sigma);
  const double peak_time = std::max(0.0, (peak_phase - o.phi) / o.omega_d);
  const double force_max = mass * velocity * o.magnitude * std::exp(-o.sigma * peak_time) *
                           std::sin(o.omega_d * peak_time + o.phi);
  // x_max is not computed: the exports compare e, t_c and F_max only.
  return {-rebound, contact_time, force_max, peak_time, std::numeric_limits<double>::quiet_NaN()};
}

MujocoContact mujoco_contact(double restitution, double contact_time, double velocity) {
  const double lowest = std::exp(-2.0);
  if (!(restitution > lowest && restitution < 1))
    throw ExportInputError("MuJoCo contact: the restitution " + std::to_string(restitution) +
                           " at the reference velocity is outside (" + std::to_string(lowest) +
                           ", 1), the range of the clamped linear spring-damper");
  if (!(std::isfinite(contact_time) && contact_time > 0))
    throw ExportInputError("MuJoCo contact: the contact time must be positive (got " +
                           std::to_string(contact_time) + " s)");
  const auto gap = [=](double zeta) { return restitution_at_damping_ratio(zeta) - restitution; };
  std::uintmax_t iterations = 200;
  const double upper = 1 - 1e-12;
  const auto root =
      boost::math::tools::toms748_solve(gap, 0.0, upper, 1 - restitution, gap(upper),
                                        boost::math::tools::eps_tolerance<double>(52), iterations);
  const double zeta = 0.5 * (root.first + root.second);
  const Oscillator unit = oscillator(1, 2 * zeta);
  const double omega = (pi - unit.phi) / (unit.omega_d * contact_time);
  // A round step, at most contact_time / steps_per_contact.
  const double step = contact_time / steps_per_contact;
  const double decade = std::pow(10.0, std::floor(std::log10(step)) - 2);
  return {
      omega * omega, 2 * zeta * omega, zeta, contact_impedance, std::floor(step / decade) * decade,
      velocity};
}

namespace export_text {

std::string mujoco_file(const ExportCampaign& campaign, const MujocoContact& contact,
                        const std::vector<ImpactFigures>& model) {
  const std::string d = as_written(contact.impedance);
  const std::string solref =
      "-" + as_written(contact.stiffness) + " -" + as_written(contact.damping);
  const std::string solimp = d + " " + d + " 0.001 0.5 2";
  std::ostringstream out;
  out << "<!--\n"
      << "  MuJoCo 2.2.2 contact of the calibrated sphere-plate impact: a drop-test model.\n"
      << "  Written by impact-export from " << campaign.calibration_file << ".\n\n"
      << "  To use: give both geoms of the contact the class \"impact_contact\" (or put solref,\n"
      << "  solimp and condim on a contact pair), and keep the option timestep at most the\n"
      << "  one below: the contact lasts " << rounded(model.front().contact_time, 4)
      << " s, MuJoCo's default 2 ms step cannot resolve it.\n\n"
      << "  Model: MuJoCo's contact is a linear spring-damper. For one free body on a plane\n"
      << "  with solref = (-K, -B) and solimp d_min = d_max = d, MuJoCo takes K / d^2 and B / d\n"
      << "  and the body's acceleration is d times the reference acceleration, so\n"
      << "      x'' = -(K x + B dx/dt)  while K x + B dx/dt > 0, no force after (no pull);\n"
      << "  K [1/s^2], B [1/s] are per unit mass: the force is m (K x + B dx/dt).\n"
      << "  K = " << rounded(contact.stiffness) << " 1/s^2 and B = " << rounded(contact.damping)
      << " 1/s (damping ratio " << rounded(contact.damping_ratio, 4)
      << ") give the FEM restitution\n"
      << "  and contact time at the reference velocity " << rounded(contact.reference_velocity)
      << " m/s exactly (closed form of the clamped\n"
      << "  spring-damper). A linear contact has the same restitution and contact time at every\n"
      << "  velocity, and its peak force grows as V (Hertz: V^1.2), so away from the reference\n"
      << "  velocity it has the FEM's own variation as error. Campaign: "
      << rounded(campaign.runs.front().velocity) << " to " << rounded(campaign.runs.back().velocity)
      << " m/s.\n"
      << "  The linear model against the FEM:\n"
      << error_table("   ", campaign, model) << "-->\n"
      << "<mujoco model=\"impact_drop\">\n"
      << "  <!-- no gravity, as in the FEM: the sphere arrives with the impact velocity -->\n"
      << "  <option timestep=\"" << as_written(contact.timestep)
      << "\" gravity=\"0 0 0\" integrator=\"Euler\"/>\n"
      << "  <default>\n"
      << "    <default class=\"impact_contact\">\n"
      << "      <geom condim=\"1\" solref=\"" << solref << "\" solimp=\"" << solimp
      << "\" margin=\"0\"/>\n"
      << "    </default>\n"
      << "  </default>\n"
      << "  <worldbody>\n"
      << "    <geom name=\"plate\" class=\"impact_contact\" type=\"plane\" size=\"0.1 0.1 "
         "0.01\"/>\n"
      << "    <body name=\"sphere\" pos=\"0 0 " << as_written(campaign.radius) << "\">\n"
      << "      <freejoint name=\"sphere\"/>\n"
      << "      <geom name=\"sphere\" class=\"impact_contact\" type=\"sphere\" size=\""
      << as_written(campaign.radius) << "\" mass=\"" << as_written(campaign.mass) << "\"/>\n"
      << "    </body>\n"
      << "  </worldbody>\n"
      << "</mujoco>\n";
  return out.str();
}

} // namespace export_text
namespace exporters {

using json = nlohmann::json;

std::vector<ExportedFile> mujoco(const ExportCampaign& campaign, const CampaignImpact& reference) {
  ExportList list;
  const MujocoContact mujoco =
      mujoco_contact(reference.fem.restitution, reference.fem.contact_time, reference.velocity);
  std::vector<ImpactFigures> linear;
  for (const auto& run : campaign.runs)
    linear.push_back(
        linear_contact_impact(mujoco.stiffness, mujoco.damping, campaign.mass, run.velocity));
  list.files.emplace_back("mujoco/impact_contact.xml",
                          export_text::mujoco_file(campaign, mujoco, linear));
  list.exports.push_back(
      {{"tool", "mujoco"},
       {"tool_version", "2.2.2"},
       {"file", "mujoco/impact_contact.xml"},
       {"model", "linear-spring-damper"},
       {"basis", "the FEM restitution and contact time at the reference velocity"},
       {"force_law", "F = m (K x + B dx/dt) while positive, else 0"},
       {"calibrated",
        {{"K", value_unit(mujoco.stiffness, "1/s^2")},
         {"B", value_unit(mujoco.damping, "1/s")},
         {"damping_ratio", value_unit(mujoco.damping_ratio, "1")}}},
       {"parameters",
        {{"solref", {-mujoco.stiffness, -mujoco.damping}},
         {"solimp", {mujoco.impedance, mujoco.impedance, 0.001, 0.5, 2}},
         {"condim", 1},
         {"timestep", value_unit(mujoco.timestep, "s")}}},
       {"mapping",
        "direct solref (-K, -B) with flat solimp d: MuJoCo uses K / d^2, B / d and "
        "the impedance d, so one free body obeys x'' = -(K x + B dx/dt), no pull"},
       {"same_law", true},
       {"note", "a linear contact: restitution and contact time do not depend on the velocity"},
       {"reference_velocity", reference.velocity},
       {"predictions", predictions_json(campaign, linear)}});

  return list.zipped();
}

} // namespace exporters
} // namespace impact::postprocess
