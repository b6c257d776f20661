#pragma once
/// @file
/// The velocity-dependent restitution table of impact-export: for one calibrated damped
/// elastic-plastic law (damped_plastic_models.hpp: Hunt–Crossley or Kuwabara–Kono damping on
/// Thornton's or Jackson–Green's spring), e(V), t_c(V) and F_max(V) over the campaign's
/// velocity range, for
/// an impulse-based engine that takes a restitution per impact speed. Each row at a velocity
/// of the FEM carries the FEM's values, their numerical uncertainty (fem_uncertainty: the GCI
/// of the run's verification, else what its history shows; the interval the report's verdict
/// uses) and the law's error against them; at the velocities between, the error is not known.
/// Written as CSV and JSON (restitution_table_csv, restitution_table_json; columns and units in
/// postprocess/README.md, "Restitution table").

#include "impact_postprocess/calibration/calibration.hpp"
#include "impact_postprocess/impact_quantities.hpp"
#include "impact_postprocess/models/damped_plastic_models.hpp"
#include "impact_postprocess/run/fem_run.hpp"

#include <impact_reduced/elastic_plastic_impact.hpp>
#include <impact_reduced/impact_figures.hpp>

#include <nlohmann/json.hpp>

#include <array>
#include <stdexcept>
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace impact::postprocess {

/// How the table's law damps its spring F_s: the damping of its damped model.
using TableDamping = DampedPlasticDamping;

/// The law of the table and everything needed to evaluate it again with the reduced library.
struct RestitutionTableLaw {
  std::string key;   ///< the calibration's key (a damped model, or a "-material" reference)
  std::string model; ///< the damped model (hunt-crossley-thornton, ...-jackson-green-from-a, ...)
  std::string label, formula, reference, basis;
  std::size_t rank;   ///< 1-based place in the calibration's ranking (0: not ranked)
  double score;       ///< its ranking score (RMS relative error, out of sample where possible)
  std::string spring; ///< "thornton" or "jackson-green"
  double mass;        ///< m [kg]
  double radius;      ///< sphere radius R [m] (flat plate: the effective radius)
  double stiffness;   ///< c [N/m^1.5], the spring's Hertz stiffness
  /// The spring's yield parameter: x_y [m] (Thornton) or Y [Pa] (Jackson–Green).
  double yield_parameter;
  double poisson_ratio; ///< nu of the yielding body (Jackson–Green), NaN for Thornton
  /// b [s/m] (hunt_crossley), or A [s]: b(V) = (3/2) gamma_1 A (c/m)^(2/5) V^(-4/5)
  /// (hunt_crossley_of_velocity) or the Kuwabara–Kono constant (kuwabara_kono).
  double damping_parameter;
  TableDamping damping;
};

/// The spring of `law` as the reduced library builds it: reduced::ThorntonContact(R = 1 m,
/// E* = 3 c / 4, p_y = 3 c sqrt(x_y) / (2 pi)) (the law depends on R only through c and x_y,
/// plastic_models.hpp) or reduced::JacksonGreenContact({R, E* = 3 c / (4 sqrt R), Y, nu}).
std::shared_ptr<const reduced::ElasticPlasticContact> table_spring(const RestitutionTableLaw& law);

/// The Hunt–Crossley b [s/m] of `law` at impact velocity V [m/s]; NaN for Kuwabara–Kono
/// damping (its A does not depend on V).
double table_damping(const RestitutionTableLaw& law, double velocity);

/// The law's impact at one velocity: the reduced library's closed form for Hunt–Crossley
/// damping (HuntCrossleyElasticPlasticImpact), its integration for Kuwabara–Kono
/// (kuwabara_kono_elastic_plastic_impact, tolerance 1e-10).
struct RestitutionTableResponse {
  double restitution;         ///< e [1]
  double contact_time;        ///< t_c [s]
  double force_max;           ///< F_max [N]
  double time_force_max;      ///< t(F_max) [s]
  double approach_max;        ///< x_max [m]
  double separation_approach; ///< x_s [m], where the bodies part (0: elastic)
  reduced::ImpactFigures figures() const {
    return {restitution, contact_time, force_max, time_force_max, approach_max};
  }
};

/// The FEM at a row of the table.
struct RestitutionTableFem {
  std::string source;
  ImpactFigures figures; ///< measured (the calibration's numbers)
  /// Relative uncertainty of e, t_c, F_max (NaN: not known), and how it was obtained.
  std::array<double, 3> uncertainty;
  std::array<std::string, 3> uncertainty_source;
  /// The law's relative error law / FEM - 1 in e, t_c, F_max (the exported law, fitted to
  /// every run).
  std::array<double, 3> error;
  /// The same error of the fit without this velocity (leave-one-velocity-out; the law itself
  /// for a reference model, which fits nothing); NaN where the calibration has none.
  std::array<double, 3> out_of_sample_error;
};

struct RestitutionTableRow {
  double velocity; ///< V [m/s]
  double damping;  ///< b(V) [s/m] (NaN: Kuwabara–Kono damping)
  RestitutionTableResponse law;
  std::optional<RestitutionTableFem> fem; ///< at the FEM's velocities only
};

struct RestitutionTable {
  RestitutionTableLaw law;
  std::vector<RestitutionTableRow> rows; ///< by velocity
};

/// Thrown for a calibration without the law asked for (or without any damped elastic-plastic
/// law), or a law that cannot be evaluated; what() names the model and the keys available.
class RestitutionTableError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// The table of `model` (a damped elastic-plastic model or its "-material" reference;
/// none: the first of them in the calibration's ranking) over [V_min, V_max] of the runs:
/// `points` >= 2 velocities equally spaced in log V, both ends included, and the velocities of
/// the runs (each run matched to the calibration by velocity). Throws RestitutionTableError,
/// and reduced::InvalidInput for points < 2.
RestitutionTable restitution_table(const Calibration& calibration, const std::vector<FemRun>& runs,
                                   const std::optional<std::string>& model, std::size_t points);

/// The names of the damped elastic-plastic laws a table can be made of, in the calibration's
/// ranking order.
std::vector<std::string> restitution_table_laws(const Calibration& calibration);

/// The table as CSV: '#' comment lines (law, parameters, columns with units), one header line,
/// one line per row; not known numbers are empty fields.
std::string restitution_table_csv(const RestitutionTable& table);
/// The table as JSON (format "impact-restitution-table" 1): "law", "units", "columns" (the
/// meaning of each), "rows"; not known numbers are null.
nlohmann::json restitution_table_json(const RestitutionTable& table);

} // namespace impact::postprocess
