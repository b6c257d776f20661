// The sections of the page on the verdict and the model to use (sections.hpp): status,
// verdict, ranking, parameters, velocity trend, the model for users.

#include "law_block.hpp"
#include "model_words.hpp"
#include "sections.hpp"
#include "impact_postprocess/report/verdict_words.hpp"
#include "impact_postprocess/models/model_keys.hpp"
#include "impact_postprocess/calibration/calibration_json.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace impact::postprocess::detail {

namespace {
constexpr double nan = std::numeric_limits<double>::quiet_NaN();
} // namespace

void status_section(Document& doc, const Report& report) {
  doc.heading("Status");
  std::vector<std::string> items, warnings;
  for (const auto& problem : report.problems)
    (is_warning(problem.kind) ? warnings : items)
        .push_back("[" + std::string(kind_name(problem.kind)) + "] " +
                   (problem.source.empty() ? "" : problem.source + ": ") + problem.message);
  if (items.empty() && warnings.empty()) {
    doc.paragraph("Complete: every run was read, every fit converged and every figure was drawn.");
    return;
  }
  if (items.empty()) {
    doc.warning("Complete, with " + std::to_string(warnings.size()) +
                " warning(s) on the FEM runs: the verdict below takes the quality of the "
                "histories into account as the FEM's uncertainty, and runs without rebound "
                "(no restitution) are findings it cannot judge.");
  } else {
    doc.warning("INCOMPLETE: " + std::to_string(items.size()) +
                " problem(s); the sections below leave out or mark what they affect.");
  }
  items.insert(items.end(), warnings.begin(), warnings.end());
  doc.list(items);
}

void verdict_section(Document& doc, const Report& report) {
  const ReportModel& calibrated = report.models.front();
  const std::size_t count = report.runs.size();
  doc.heading("Validity verdict");
  std::string bands;
  for (std::size_t i = 0; i < report.tolerances.size(); ++i)
    bands += (i ? (i + 1 == report.tolerances.size() ? " and " : ", ") : "") +
             short_number(report.tolerances[i] * 100) + " %";
  doc.paragraph("Where the calibrated Hunt–Crossley model (" +
                parameters_words(calibrated.basis, calibrated.parameters) +
                ") predicts the energy loss 1 - e^2, the contact time, the peak force and the "
                "peak approach all within " +
                bands + " of the FEM. " +
                (calibrated.out_of_sample
                     ? "The errors are out of sample: each velocity is predicted by the model "
                       "fitted to the other velocities only (leave one velocity out); the "
                       "in-sample errors of the fit to all runs are shown beside them."
                     : "The errors are in sample (the fit to all runs): out-of-sample errors "
                       "need at least three velocities.") +
                " The energy loss, not e, is judged: near e = 1 a small error in e is a large "
                "one in the energy the model takes.");
  const std::string summary = summary_sentence(report);
  if (!summary.empty()) doc.paragraph(summary);
  const ModelVerdict* verdict = report.verdict(calibrated.key);
  if (report.verdict_available && verdict) {
    std::vector<std::string> items;
    for (const auto& tolerance : verdict->tolerances)
      items.push_back(
          tolerance_sentence(report, tolerance, sample_basis(calibrated.out_of_sample)));
    doc.list(items);
  }
  doc.paragraph("Cause: " + cause_sentence(report));
  doc.paragraph(trend_sentence(report));
  const std::string family = family_sentence(report);
  if (!family.empty() && summary.find(family) == std::string::npos) doc.paragraph(family);
  doc.paragraph(plasticity_sentence(report));
  doc.paragraph(uncertainty_sentence(report));
  if (!report.verdict_available || !verdict) return;

  // Two tables rather than one of 15 columns: the errors with the decisions, then the FEM's
  // uncertainty of each quantity.
  Table table{{"V [m/s]"}, {}};
  for (Quantity quantity : verdict_quantities)
    table.header.push_back(std::string("error ") + quantity_symbol(quantity) +
                           (calibrated.out_of_sample ? " out of sample (in sample)" : ""));
  for (double tolerance : report.tolerances)
    table.header.push_back("within " + short_number(tolerance * 100) + " %");
  Table uncertainty{{"V [m/s]"}, {}};
  for (Quantity quantity : verdict_quantities)
    uncertainty.header.push_back(std::string("FEM uncertainty ") + quantity_symbol(quantity));
  for (std::size_t i = 0; i < count; ++i) {
    const ReportRun& run = report.runs[i];
    const ModelAtRun& at = calibrated.runs[i];
    std::vector<std::string> row{velocity_cell(run)};
    for (Quantity quantity : verdict_quantities)
      row.push_back(error_cell(at.judged(), run.fem, quantity) +
                    (calibrated.out_of_sample
                         ? " (" + error_cell(at.in_sample, run.fem, quantity) + ")"
                         : std::string()));
    for (const auto& tolerance : verdict->tolerances)
      row.push_back(decision_word(tolerance.decisions[i]));
    table.rows.push_back(row);
    std::vector<std::string> fem{velocity_cell(run)};
    for (Quantity quantity : verdict_quantities)
      fem.push_back(unsigned_percent(run.uncertainty[std::size_t(quantity)].relative));
    uncertainty.rows.push_back(fem);
  }
  doc.table(table);
  doc.paragraph("The FEM's numerical uncertainty of each judged quantity (relative):");
  doc.table(uncertainty);

  doc.paragraph("Every model compared, by the same rule (" +
                std::string("velocity ranges within each band; out of sample for the fitted "
                            "models with three or more velocities, and for the models that fit "
                            "nothing):"));
  Table models{{"model", "free parameters", "errors"}, {}};
  for (double tolerance : report.tolerances)
    models.header.push_back("within " + short_number(tolerance * 100) + " %");
  for (const auto& model : report.models) {
    const ModelVerdict* entry = report.verdict(model.key);
    if (!entry) continue;
    std::vector<std::string> row{model.label + not_converged(model),
                                 std::to_string(model.free_parameters),
                                 model.out_of_sample ? "out of sample" : "in sample"};
    for (const auto& tolerance : entry->tolerances) row.push_back(range_text(tolerance, report));
    models.rows.push_back(row);
  }
  doc.table(models);
}

namespace {

// Where the recommended law (the closest when none holds) is not within the loosest band, and
// why: the quantity that keeps it out, its error out of sample and in the fit to every
// velocity, the FEM's uncertainty, and the cause the assessment measured.
void breaks_table(Document& doc, const Report& report) {
  if (!report.recommendation) return;
  const LawRecommendation& recommendation = *report.recommendation;
  const auto chosen =
      recommendation.recommended ? recommendation.recommended : recommendation.closest;
  if (!chosen) return;
  const JudgedLaw& law = recommendation.laws[*chosen];
  if (law.breaks.empty()) return;
  const std::string band = band_name(recommendation.tolerance);
  doc.paragraph(
      "Where " + law_name(law) + " (" +
      (recommendation.recommended ? "recommended" : "the closest") + ") is not within " + band +
      ", and why. The cause is measured: the FEM's uncertainty, where the verdict cannot decide "
      "(the band lies between |error| - U and |error| + U, U the FEM's uncertainty); the law's "
      "shape, where even the fit to every velocity is beyond " +
      band +
      " (or nothing is fitted); held out, where the fit to every "
      "velocity is within " +
      band + " and the fit without this velocity is not (the parameter that moves most is given).");
  const std::string hardening = hardening_left_out_by(report, law);
  if (!hardening.empty() &&
      std::any_of(law.breaks.begin(), law.breaks.end(),
                  [](const BreakingRun& run) { return run.cause == BreakCause::law_shape; }))
    doc.paragraph("The runs' material hardens (" + hardening + "); the law's spring is " +
                  "elastic-perfectly-plastic and carries none of it.");
  Table table{{"V [m/s]", "quantity", "out of sample [%]", "U [%]", "fit to every velocity [%]",
               "cause"},
              {}};
  for (const auto& breaking : law.breaks) {
    std::string cause;
    switch (breaking.cause) {
      case BreakCause::fem_uncertainty:
        cause = "the FEM's uncertainty";
        break;
      case BreakCause::law_shape:
        cause = "the law's shape";
        break;
      case BreakCause::held_out:
        cause = "held out: " + breaking.parameter + " " + significant(breaking.fitted_value, 4) +
                " -> " + significant(breaking.held_out_value, 4) +
                (breaking.unit == "1" ? "" : " " + breaking.unit);
        break;
    }
    table.rows.push_back({short_number(report.runs[breaking.run].velocity),
                          quantity_symbol(breaking.quantity), cell(breaking.error * 100),
                          cell(breaking.uncertainty * 100), cell(breaking.in_sample_error * 100),
                          cause});
  }
  doc.table(table);
}

} // namespace

void ranking_section(Document& doc, const Report& report) {
  if (!report.calibration) return;
  const CampaignCalibration& campaign = report.calibration->campaign;
  if (campaign.ranking.empty()) return;
  doc.heading("Ranking of the models");
  doc.paragraph(
      "All models of the calibration (calibration JSON, campaign.ranking), ranked by "
      "the RMS of their relative errors in 1 - e^2, t_c, F_max and x_max over all "
      "runs, out of sample where the campaign allows it (models that fit nothing are "
      "out of sample by construction); a fitted model scored in sample (fewer than "
      "three velocities) ranks after every model scored out of sample. Scores within "
      "0.01 % count as equal, and among equals fewer free parameters rank first. The RMS residual "
      "of the force "
      "histories (in sample) is shown for comparison: it is what the fits minimise, "
      "not what the verdict judges.");
  Table table{{"rank", "model", "free parameters", "RMS error [%]", "errors", "worst error [%]",
               "in-sample RMS error [%]", "RMS residual [%]", "parameter", "value", "unit",
               "converged"},
              {}};
  int rank = 1;
  std::vector<std::string> families;
  for (const auto& entry : campaign.ranking) {
    // Every dissipation parameter (a damped elastic-plastic law has two), ", "-separated.
    std::vector<std::string> names, units;
    std::vector<double> values;
    if (const CampaignModelFit* fit = campaign.find(entry.key)) {
      names = {fit->fit.parameter_name};
      units = {fit->fit.parameter_unit};
      for (const auto& extra : fit->fit.extra) {
        names.push_back(extra.name);
        units.push_back(extra.unit);
      }
      values = fit->fit.dissipation();
    }
    for (const auto& reference : campaign.reference_models)
      if (reference.key == entry.key) {
        names = {reference.parameter_name};
        units = {reference.parameter_unit};
        names.insert(names.end(), reference.extra_names.begin(), reference.extra_names.end());
        units.insert(units.end(), reference.extra_units.begin(), reference.extra_units.end());
        values = reference.dissipation;
        if (values.empty()) values = {nan};
      }
    std::string name, value, unit;
    for (std::size_t i = 0; i < names.size(); ++i) {
      name += (i ? ", " : "") + names[i];
      value += (i ? ", " : "") + cell(i < values.size() ? values[i] : nan);
      unit += (i ? ", " : "") + (i < units.size() ? units[i] : std::string());
    }
    if (names.empty()) value = cell(nan);
    table.rows.push_back(
        {std::to_string(rank++), entry.key, std::to_string(entry.free_parameters),
         cell(entry.score * 100), entry.out_of_sample ? "out of sample" : "in sample",
         cell(entry.worst_error * 100), cell(entry.in_sample_score * 100),
         cell(entry.rms_residual * 100), name, value, unit, entry.converged ? "yes" : "no"});
    if (entry.family.size() > 1) {
      std::string members, fitted;
      for (std::size_t i = 0; i < entry.family.size(); ++i) {
        members += (i ? ", " : "") + entry.family[i];
        if (const CampaignModelFit* fit = campaign.find(entry.family[i]))
          fitted +=
              (i ? ", " : "") + entry.family[i] + " e = " + short_number(fit->fit.parameter.value);
      }
      families.push_back(
          entry.key + " stands for one family: " + members +
          " fitted with a constant e give one force history (beta = b V the same at every V: "
          "Hunt–Crossley with b ∝ 1/V); they differ only in the e they report (" +
          fitted +
          "). How far each map's restitution is from what it is given is in 'The laws as their "
          "users apply them'.");
    }
  }
  doc.table(table);
  doc.list(families);
  breaks_table(doc, report);
}

namespace {

void estimate_tables(Document& doc, const Report& report, const CampaignModelFit& fit,
                     const std::string& json_path) {
  const double level = report.calibration->confidence_level;
  const ModelFit& parameters = fit.fit;
  doc.paragraph(fit.label + " (" + fit.key + ", calibration JSON " + json_path +
                "): RMS residual " + short_number(parameters.quality.rms_residual * 100) +
                " % of the peak force, R^2 = " + cell(parameters.quality.r_squared) +
                ", converged: " + (parameters.converged ? "yes" : "NO") + ". Intervals at " +
                short_number(level * 100) +
                " % confidence. First the covariance intervals s^2 (J^T J)^-1, CONDITIONAL ON "
                "THE MODEL: they take the residuals as independent noise, while for FEM data "
                "they are mostly model error, correlated in time:");
  const std::vector<std::string> names = parameters.parameter_names();
  std::vector<Estimate> conditional{parameters.stiffness, parameters.exponent,
                                    parameters.parameter};
  std::vector<std::string> units{"N/m^n", "1", parameters.parameter_unit};
  for (const auto& extra : parameters.extra) {
    conditional.push_back(extra.estimate);
    units.push_back(extra.unit);
  }
  Table table{{"parameter", "value", "standard error", "interval lower", "interval upper", "unit"},
              {}};
  for (std::size_t i = 0; i < names.size(); ++i)
    table.rows.push_back({names[i], cell(conditional[i].value), cell(conditional[i].standard_error),
                          cell(conditional[i].lower), cell(conditional[i].upper), units[i]});
  doc.table(table);
  if (fit.jackknife.empty()) {
    doc.paragraph(
        "No jackknife intervals: they need fits with one velocity left out, and so "
        "at least three velocities.");
    return;
  }
  doc.paragraph("Jackknife over the " + std::to_string(fit.held_out.size()) +
                " fits with one velocity left out (standard error sqrt((g - 1)/g sum "
                "(theta_i - mean)^2), Student t with g - 1 degrees of freedom): these hold when "
                "the model itself is wrong.");
  Table jackknife{{"parameter", "value", "jackknife standard error", "jackknife interval lower",
                   "jackknife interval upper", "unit", "jackknife / conditional standard error"},
                  {}};
  for (std::size_t i = 0; i < names.size() && i < fit.jackknife.size(); ++i)
    jackknife.rows.push_back(
        {names[i], cell(fit.jackknife[i].value), cell(fit.jackknife[i].standard_error),
         cell(fit.jackknife[i].lower), cell(fit.jackknife[i].upper), units[i],
         cell(fit.jackknife[i].standard_error / conditional[i].standard_error)});
  doc.table(jackknife);
}

} // namespace

namespace {

// The law for a multibody code: a Hunt–Crossley form (what Simbody's HuntCrossleyForce and
// most multibody codes take as it is) offered only where it holds by the verdict's rule; else
// that none does, and which export comes closest with its error.
void multibody_block(Document& doc, const Report& report) {
  if (!report.recommendation) return;
  const LawRecommendation& recommendation = *report.recommendation;
  const std::string band = band_name(recommendation.tolerance);
  if (recommendation.multibody) {
    const JudgedLaw& law = recommendation.laws[*recommendation.multibody];
    const LawBlock block = law_block(report, law.key);
    if (block.found) {
      doc.code(law_block_text("For a multibody code, " + where_within(report, law) + " (within " +
                                  band +
                                  " there, out of sample, with the FEM's uncertainty; not "
                                  "judged elsewhere): ",
                              block));
      return;
    }
  }
  std::string text =
      "For a multibody code: no Hunt–Crossley law (F = c x^n (1 + b dx/dt)) holds "
      "within " +
      band +
      " at any tested velocity (out of sample, with the FEM's uncertainty), so "
      "none is offered here.";
  const JudgedLaw* closest = nullptr;
  for (const auto& law : recommendation.laws)
    if (law.hunt_crossley_form && law.out_of_sample && !closest) closest = &law;
  if (closest)
    text += " The Hunt–Crossley form ranked first, " + law_name(*closest) + " (RMS error " +
            unsigned_percent(closest->score) + "): " + largest_error(report, *closest) + ".";
  if (const auto& exported = recommendation.closest_export) {
    const SimulatorResult& result = report.simulators[exported->simulator];
    text += " Of the exports run in their simulators, " + simulator_tool_name(result.tool) +
            "'s (" + result.file + ", " + result.model +
            ") comes closest to the FEM: its largest error is " +
            percent_cell(exported->worst_error) + " (" + quantity_words(exported->worst_quantity) +
            " " + quantity_symbol(exported->worst_quantity) +
            " at V = " + short_number(exported->velocity) + " m/s; section In your simulator).";
  } else {
    text +=
        " The exports' own errors in their simulators are in section In your simulator "
        "(impact-report --simulators).";
  }
  doc.warning(text);
}

} // namespace

void parameters_section(Document& doc, const Report& report) {
  doc.heading("Calibrated parameters");
  if (!report.calibration || !report.campaign_fitted) {
    const std::string reason = campaign_reason(report);
    doc.paragraph(
        "No campaign fit: " + (reason.empty() ? std::string("the calibration has none") : reason) +
        ". The runs' own fits are in the table of runs.");
    doc.list(parameter_notes(report));
    return;
  }
  const CampaignCalibration& campaign = report.calibration->campaign;
  estimate_tables(doc, report, *campaign.hunt_crossley, "campaign.hunt_crossley");
  const ModelFit& hc = campaign.hunt_crossley->fit;
  const std::size_t k = hc.parameter_names().size();
  if (hc.correlation.size() == k * k)
    doc.paragraph("Correlations: c,n = " + cell(hc.correlation[1]) + "; c,b = " +
                  cell(hc.correlation[2]) + "; n,b = " + cell(hc.correlation[k + 2]) + ".");
  doc.list(parameter_notes(report));
  if (campaign.hunt_crossley_energy)
    estimate_tables(doc, report, *campaign.hunt_crossley_energy, "campaign.hunt_crossley_energy");
  if (campaign.hunt_crossley_velocity_damping)
    estimate_tables(doc, report, *campaign.hunt_crossley_velocity_damping,
                    "campaign.hunt_crossley_velocity_damping");
  if (const ReportModel* best = report.model(model_keys::best_law))
    if (const CampaignModelFit* law = campaign.find(best->calibration_key))
      estimate_tables(doc, report, *law, "campaign.comparison_laws (" + law->key + ")");
  multibody_block(doc, report);
}

void trend_section(Document& doc, const Report& report,
                   const std::function<void(FigureId)>& figure) {
  doc.heading("Velocity trend of the energy loss");
  doc.paragraph(trend_sentence(report) +
                " The reference slopes: Hunt–Crossley with a constant b, 1 - e = (2/3) b V + "
                "..., slope 1; the viscoelastic sphere (Kuwabara–Kono, Brilliantov), 1 - e = "
                "1.7302 A (c/m)^(2/5) V^(1/5) + ..., slope 1/5; a constant e, slope 0.");
  if (const std::string family = family_sentence(report); !family.empty()) doc.paragraph(family);
  figure(FigureId::energy_loss);
  Table table{{"V [m/s]", "FEM 1 - e", "power law a V^p"}, {}};
  for (const auto& model : report.models) table.header.push_back(model.label);
  for (std::size_t i = 0; i < report.runs.size(); ++i) {
    const ReportRun& run = report.runs[i];
    std::vector<std::string> row{velocity_cell(run), cell(1 - run.fem.restitution),
                                 report.trend ? cell(report.trend->prefactor *
                                                     std::pow(run.velocity, report.trend->exponent))
                                              : "n/a"};
    for (const auto& model : report.models)
      row.push_back(model.runs[i].judged()
                        ? cell(1 - model.runs[i].judged()->restitution) + not_converged(model)
                        : "n/a");
    table.rows.push_back(row);
  }
  doc.paragraph(
      "1 - e at each velocity: the FEM, the fitted power law, and each model as the "
      "verdict judges it (out of sample where it can be):");
  doc.table(table);
}

void users_section(Document& doc, const Report& report) {
  if (!report.calibration) return;
  const CampaignCalibration& campaign = report.calibration->campaign;
  doc.heading("The laws as their users apply them");
  doc.paragraph(
      "Multibody codes use the restitution-parametrised laws without fitting: c from "
      "Hertz (" +
      campaign.hertz_basis +
      "), n = 3/2 and the e to reproduce, here the "
      "FEM's e at each velocity. The restitution each law then really produces, and "
      "its errors (against the FEM):");
  Table table{{"law", "V [m/s]", "FEM e (given)", "produced e", "error e", "error 1 - e^2",
               "error t_c", "error F_max"},
              {}};
  for (const auto& map : campaign.restitution_maps)
    for (const auto& run : map.runs) {
      const ReportRun* fem = nullptr;
      for (const auto& candidate : report.runs)
        if (same_source(candidate.source, run.source)) fem = &candidate;
      const ImpactFigures produced = run.prediction;
      const ImpactFigures reference =
          fem ? fem->fem : ImpactFigures{run.target, nan, nan, nan, nan};
      table.rows.push_back(
          {map.law, fem ? velocity_cell(*fem) : cell(run.velocity), cell(run.target),
           cell(produced.restitution),
           percent_cell(relative_error(produced.restitution, run.target)),
           percent_cell(relative_error(produced, reference, Quantity::energy_loss)),
           percent_cell(relative_error(produced, reference, Quantity::contact_time)),
           percent_cell(relative_error(produced, reference, Quantity::force_max))});
    }
  doc.table(table);

  doc.paragraph(
      "Kuwabara–Kono without tension as a prediction from the material, with nothing "
      "fitted: c = c_Hertz, n = 3/2, and A from the retardation times, " +
      (campaign.material_dissipative_constant
           ? "A = " + short_number(*campaign.material_dissipative_constant) + " s (" +
                 campaign.material_basis + ")."
           : campaign.material_basis + ".") +
      " For a Kelvin–Voigt body with equal deviatoric and volumetric retardation times "
      "A = tau_r exactly; the theory has no wave radiation, so where the FEM plate "
      "radiates energy the prediction loses too little.");
  if (const ReportModel* material = report.model(model_keys::kuwabara_kono_material)) {
    Table errors{{"V [m/s]"}, {}};
    for (Quantity quantity : all_quantities)
      errors.header.push_back(std::string("error ") + quantity_symbol(quantity));
    errors.header.push_back("FEM: radiated share of the loss");
    for (std::size_t i = 0; i < report.runs.size(); ++i) {
      const ReportRun& run = report.runs[i];
      std::vector<std::string> row{velocity_cell(run)};
      for (Quantity quantity : all_quantities)
        row.push_back(error_cell(material->runs[i].in_sample, run.fem, quantity));
      const auto& radiated = run.record.radiated_energy_fraction;
      row.push_back(radiated ? unsigned_percent(*radiated / value(run.fem, Quantity::energy_loss))
                             : "not recorded");
      errors.rows.push_back(row);
    }
    doc.table(errors);
    doc.paragraph(
        "The last column is the FEM's radiated energy (absorbing plate boundaries) as "
        "a share of the kinetic energy lost: a loss the viscoelastic-sphere theory "
        "does not contain, so an energy-loss error of about minus that share is what "
        "the theory itself predicts.");
    if (const CampaignModelFit* fitted = campaign.find("kuwabara-kono-no-tension"))
      doc.paragraph("The fitted Kuwabara–Kono without tension has A = " +
                    short_number(fitted->fit.parameter.value) + " s (c = " +
                    short_number(fitted->fit.stiffness.value) + " N/m^1.5): A_fit / A_material = " +
                    short_number(fitted->fit.parameter.value /
                                 campaign.material_dissipative_constant.value_or(nan)) +
                    ".");
  }
}

} // namespace impact::postprocess::detail
