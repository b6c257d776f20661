#pragma once
/// @file
/// The quantities by which a reduced model is compared with the FEM, in one place: the
/// figures of an impact, the derived energy loss, their names, the relative error and the
/// tolerance bands of the validity verdict.
///
/// The energy loss 1 - e^2 is the fraction of the kinetic energy that the impact takes. Near
/// e = 1 it, not e, is what a model must get right: e = 0.9907 against 0.9461 is +4.7 % in e
/// but -83 % in 1 - e^2.

#include <impact_reduced/impact_figures.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace impact::postprocess {

/// The figures of one impact (FEM or model): the reduced library's one struct.
using reduced::ImpactFigures;

/// What a model predicts for one impact: its figures and, beyond them, the law's damping
/// constant at this velocity (what the calibration JSON records with each prediction).
struct ImpactPrediction : ImpactFigures {
  double damping; ///< the law's damping constant at this velocity
};

/// Everything the report compares, in the order of its tables.
enum class Quantity : std::size_t {
  energy_loss,         ///< 1 - e^2 [1]
  restitution_deficit, ///< 1 - e [1]
  restitution,         ///< e [1]
  contact_time,        ///< t_c [s]
  force_max,           ///< F_max [N]
  time_force_max,      ///< t(F_max) [s]
  approach_max,        ///< x_max [m]
};
inline constexpr std::size_t quantity_count = 7;
inline constexpr std::array<Quantity, quantity_count> all_quantities = {
    Quantity::energy_loss,  Quantity::restitution_deficit, Quantity::restitution,
    Quantity::contact_time, Quantity::force_max,           Quantity::time_force_max,
    Quantity::approach_max};
/// The quantities the validity verdict judges together (energy loss, not e).
inline constexpr std::array<Quantity, 4> verdict_quantities = {Quantity::energy_loss,
                                                               Quantity::contact_time,
                                                               Quantity::force_max,
                                                               Quantity::approach_max};

/// The quantities a validity map judges (energy loss, contact time, peak force): not x_max,
/// because the FEM's approach on a thin plate includes the plate's bending under the ball
/// (it is measured from the mean of the plate's bottom), which the massive-plate laws do not
/// have and Zener's indentation x leaves out.
inline constexpr std::array<Quantity, 3> map_quantities = {Quantity::energy_loss,
                                                           Quantity::contact_time,
                                                           Quantity::force_max};

/// The value of `quantity` for an impact (1 - e^2 and 1 - e derived from e).
double value(const ImpactFigures& impact, Quantity quantity);
/// "energy_loss", "restitution_deficit", "restitution", "contact_time", "force_max",
/// "time_force_max", "approach_max".
const char* quantity_key(Quantity quantity);
/// "1 - e^2", "1 - e", "e", "t_c", "F_max", "t(F_max)", "x_max".
const char* quantity_symbol(Quantity quantity);
/// "energy loss", "1 - e", "restitution", "contact time", "peak force", "time of the peak
/// force", "peak approach".
const char* quantity_words(Quantity quantity);

/// (model - reference) / |reference|: the one relative error of the project's comparisons.
/// NaN when either value is not finite or the reference is 0.
double relative_error(double model, double reference);

/// The losses 1 - e^2 and 1 - e below which an impact counts as elastic: a restitution read
/// from velocities (or an integrated history) carries round-off of about 1e-12, so two losses
/// under 1e-9 are both "none" and their ratio is noise (a synthetic elastic run at 1 - e^2 =
/// 2.5e-11 against a model's exact 0 would be a -100 % error).
inline constexpr double elastic_loss_resolution = 1e-9;

/// relative_error of a quantity; 0 for the losses 1 - e^2 and 1 - e when the model's and the
/// reference's are both below elastic_loss_resolution (both elastic).
double relative_error(const ImpactFigures& model, const ImpactFigures& reference,
                      Quantity quantity);

/// The tolerance bands of the verdict (fractions, increasing): 2 % and 5 % unless
/// impact-report is told otherwise (--tolerances).
inline const std::vector<double> default_tolerances = {0.02, 0.05};

/// The step-to-step oscillation of the FEM force (a fraction of the peak force) above which
/// the report warns that the FEM history is not clean.
inline constexpr double force_oscillation_warning = 0.005;

} // namespace impact::postprocess
