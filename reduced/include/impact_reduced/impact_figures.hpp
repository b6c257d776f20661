#pragma once
/// @file
/// The figures of one impact: the one struct by which an impact is described wherever two
/// impacts are compared — a reduced model's prediction against a FEM run, one law against
/// another, a simulator's contact against the calibration. SI units; times from first
/// contact.
///
/// The solvers' own results carry more than the figures, because they know more about the
/// impact than a comparison uses: HuntCrossleyImpact::response (ImpactResponse) adds the
/// compression time, the signed rebound velocity and the lost energy; integrate_impact
/// (OdeImpactResult) adds the force and the approach at separation and the step count;
/// elastic_plastic_impact adds the residual approach; ThinPlateImpact adds the plate's
/// share of the energy and its deflection. Each gives its figures by `figures()`.

namespace impact::reduced {

struct ImpactFigures {
  double restitution;    ///< e = rebound speed / impact speed [1]
  double contact_time;   ///< t_c: first contact to separation [s]
  double force_max;      ///< F_max: peak contact force [N]
  double time_force_max; ///< t(F_max) [s since first contact]
  double approach_max;   ///< x_max: peak approach [m]
};

} // namespace impact::reduced
