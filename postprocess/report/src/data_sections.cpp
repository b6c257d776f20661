// The sections of the page on the data behind the verdict (sections.hpp): the FEM's
// quality, the runs, the models, the quantities, the errors, the energy balance.

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

namespace fs = std::filesystem;

void quality_section(Document& doc, const Report& report) {
  doc.heading("FEM quality per run");
  doc.paragraph(
      "The numerical uncertainty of each FEM quantity, as the verdict uses it "
      "(relative to the value): the grid convergence index of the run's verification "
      "(verification.json) where there is one, else what the force history shows. "
      "Step-to-step oscillation: max |F_i - (F_(i-1) + F_(i+1))/2| / F_max inside the "
      "contact (5 steps at each end excluded); a warning above " +
      unsigned_percent(force_oscillation_warning) +
      ". Force after release: the largest force after the first zero that follows "
      "the peak, / F_max. Energy balance: a warning when the balance error at the end of the "
      "run exceeds " +
      unsigned_percent(energy_balance_target) +
      " of the impact energy (section Energy balance and yield check).");
  Table table{{"V [m/s]", "force oscillation [%]", "force after release [%]", "time step [µs]",
               "verification"},
              {}};
  for (Quantity quantity : {Quantity::energy_loss, Quantity::contact_time, Quantity::force_max,
                            Quantity::time_force_max, Quantity::approach_max})
    table.header.push_back(std::string("U(") + quantity_symbol(quantity) + ")");
  table.header.push_back("warning");
  for (const auto& run : report.runs) {
    const auto& record = run.record;
    std::vector<std::string> row{velocity_cell(run), cell(record.smoothness.oscillation * 100),
                                 cell(record.smoothness.after_release * 100),
                                 cell(record.time_step * 1e6),
                                 record.verification
                                     ? "yes (ratio " +
                                           short_number(record.verification->refinement_ratio) + ")"
                                     : "none"};
    for (Quantity quantity : {Quantity::energy_loss, Quantity::contact_time, Quantity::force_max,
                              Quantity::time_force_max, Quantity::approach_max})
      row.push_back(unsigned_percent(run.uncertainty[std::size_t(quantity)].relative));
    std::string warning;
    if (record.smoothness.oscillation > force_oscillation_warning) warning = "FORCE OSCILLATES";
    if (record.energy_error_final && std::abs(*record.energy_error_final) > energy_balance_target)
      warning += (warning.empty() ? "" : "; ") + std::string("ENERGY BALANCE OFF");
    row.push_back(warning.empty() ? "none" : warning);
    table.rows.push_back(row);
  }
  doc.table(table);
  std::vector<std::string> sources;
  if (!report.runs.empty())
    for (Quantity quantity : all_quantities)
      sources.push_back(std::string(quantity_symbol(quantity)) + ": " +
                        report.runs.front().uncertainty[std::size_t(quantity)].source);
  doc.paragraph("Where the uncertainties come from (first run):");
  doc.list(sources);
  for (const auto& run : report.runs)
    if (run.record.verification) {
      Table verified{{"quantity", "fine", "medium", "coarse", "observed order", "extrapolated",
                      "GCI fine", "convergence"},
                     {}};
      for (const auto& [key, quantity] : run.record.verification->quantities)
        verified.rows.push_back({key, cell(quantity.fine), cell(quantity.medium),
                                 cell(quantity.coarse), cell(quantity.observed_order),
                                 cell(quantity.extrapolated), unsigned_percent(quantity.gci_fine),
                                 quantity.convergence});
      doc.paragraph("Verification of " + velocity_label(run.velocity) + " (" +
                    run.record.verification->source + "):");
      doc.table(verified);
    }
}

void runs_section(Document& doc, const Report& report) {
  doc.heading("Runs");
  doc.paragraph(
      "FEM quantities (the calibration's 'measured' numbers) and the per-run "
      "calibration: b from the restitution through the exact inverse of k(bV), and "
      "c, n, b of the run's force-history fit with its interval.");
  Table table{{"V [m/s]", "mass [kg]", "e [1]", "(1 - e)/V [s/m]", "t_c [µs]", "F_max [kN]",
               "x_max [µm]", "b from e [s/m]", "b history fit [s/m]", "b interval [s/m]",
               "n history fit", "c history fit [N/m^n]", "source"},
              {}};
  const auto shown_source = [&](const std::string& source) {
    if (report.campaign_source.empty()) return source;
    const fs::path relative = fs::path(source).lexically_relative(report.campaign_source);
    if (relative.empty() || *relative.begin() == "..") return source;
    return relative.string();
  };
  for (const auto& run : report.runs)
    table.rows.push_back(
        {velocity_cell(run), cell(run.mass), cell(run.fem.restitution), cell(effective_alpha(run)),
         cell(run.fem.contact_time * 1e6), cell(run.fem.force_max * 1e-3),
         cell(run.fem.approach_max * 1e6), cell(run.damping_from_restitution),
         cell(run.history_damping.value),
         std::isfinite(run.history_damping.lower)
             ? cell(run.history_damping.lower) + " to " + cell(run.history_damping.upper)
             : "n/a",
         cell(run.history_exponent.value), cell(run.history_stiffness.value),
         shown_source(run.source) + (run.calibrated ? "" : " (not in the calibration)")});
  doc.table(table);
  if (const std::string alpha = alpha_sentence(report); !alpha.empty()) doc.paragraph(alpha);
}

void models_section(Document& doc, const Report& report) {
  doc.heading("Reduced models compared");
  std::vector<std::string> items;
  // A fit without held-out fits (fewer than three velocities) is judged on the runs it was
  // fitted to: said at the model, since its errors then look better than a prediction's.
  for (const auto& model : report.models)
    items.push_back(model.label + ": " + parameters_words(model.basis, model.parameters) + ". " +
                    basis_words(model, report.calibration) + " (" +
                    std::to_string(model.free_parameters) + " free parameters" +
                    (model.free_parameters == 0 ? "; nothing fitted: its errors are predictions"
                     : model.out_of_sample
                         ? "; errors out of sample"
                         : "; IN SAMPLE: its errors are those of the runs it was fitted to, "
                           "out-of-sample errors need three velocities") +
                    ")" + (model.converged ? "" : " (NOT CONVERGED)"));
  doc.list(items);
}

void quantities_section(Document& doc, const Report& report,
                        const std::function<void(FigureId)>& figure) {
  doc.heading("Restitution, energy loss, contact time, peak force and peak approach against V");
  doc.paragraph(
      "FEM (with its numerical uncertainty where known) and the models; the shaded "
      "bands are the jackknife prediction bands of the fitted models. The tables hold "
      "each model's prediction by its fit to all runs (in sample).");
  figure(FigureId::quantities);
  for (Quantity quantity : all_quantities) {
    if (quantity == Quantity::restitution_deficit) continue;
    const std::size_t q = std::size_t(quantity);
    Table table{{"V [m/s]", std::string("FEM ") + page_name[q]}, {}};
    for (const auto& model : report.models) table.header.push_back(model.label);
    for (std::size_t i = 0; i < report.runs.size(); ++i) {
      std::vector<std::string> row{velocity_cell(report.runs[i]),
                                   cell(value(report.runs[i].fem, quantity) * page_scale[q])};
      for (const auto& model : report.models)
        row.push_back(model.runs[i].in_sample
                          ? cell(value(*model.runs[i].in_sample, quantity) * page_scale[q]) +
                                not_converged(model)
                          : "n/a");
      table.rows.push_back(row);
    }
    doc.paragraph(page_name[q]);
    doc.table(table);
  }
}

void errors_section(Document& doc, const Report& report) {
  doc.heading("Errors of the reduced models against the FEM");
  doc.paragraph(
      "Relative error (model - FEM) / |FEM| of each quantity at each velocity: out of "
      "sample, with the in-sample error in brackets, for the fitted models; once for "
      "the models that fit nothing. The figure at the top of the page shows the "
      "errors the verdict judges.");
  Table table{{"model", "quantity"}, {}};
  for (const auto& run : report.runs)
    table.header.push_back(velocity_label(run.velocity) + (run.yields ? " (yields)" : ""));
  for (const auto& model : report.models)
    for (Quantity quantity : all_quantities) {
      std::vector<std::string> row{model.label, quantity_symbol(quantity)};
      for (std::size_t i = 0; i < report.runs.size(); ++i) {
        const ModelAtRun& at = model.runs[i];
        std::string text = error_cell(at.judged(), report.runs[i].fem, quantity);
        if (at.out_of_sample && at.in_sample && model.free_parameters > 0)
          text += " (" + error_cell(at.in_sample, report.runs[i].fem, quantity) + ")";
        row.push_back(text + (at.judged() ? not_converged(model) : ""));
      }
      table.rows.push_back(row);
    }
  doc.table(table);
  std::vector<std::string> missing;
  for (const auto& model : report.models)
    for (std::size_t i = 0; i < report.runs.size(); ++i)
      if (!model.runs[i].in_sample)
        missing.push_back(model.label + " at " + velocity_label(report.runs[i].velocity) + ": " +
                          no_value_words(model.runs[i].missing));
  if (!missing.empty()) {
    doc.paragraph("Missing predictions (n/a above):");
    doc.list(missing);
  }
}

namespace {

// "908 of 2030 MPa (44.7 %)": one body's stress against its own yield strength.
std::string body_stress_cell(const BodyStress& body) {
  if (!body.max_von_mises) return "not recorded";
  if (!body.yield_strength)
    return short_number(*body.max_von_mises * 1e-6) + " (no yield strength)";
  return short_number(*body.max_von_mises * 1e-6) + " of " +
         short_number(*body.yield_strength * 1e-6) + " (" + short_number(body.ratio() * 100) +
         " %)";
}

// The yield check of a run: each body against its own strength, the bodies that yield named.
std::string yield_check(const ReportRun& run) {
  const FemRunRecord& record = run.record;
  std::vector<const BodyStress*> checked, yielding;
  for (const auto& body : record.bodies)
    if (body.max_von_mises && body.yield_strength) {
      checked.push_back(&body);
      if (body.yields.value_or(false)) yielding.push_back(&body);
    }
  if (checked.empty())
    return record.max_von_mises ? "yield strength not recorded"
                                : "not recorded (no von Mises stress)";
  std::string names;
  for (const BodyStress* body : yielding)
    names += (names.empty() ? "" : "; ") +
             (body->body == both_bodies
                  ? "the largest stress of both bodies at " + short_number(body->ratio() * 100) +
                        " % of the smallest yield strength"
                  : body->body + " at " + short_number(body->ratio() * 100) +
                        " % of its yield strength") +
             " (" + body->yield_source + ")";
  if (record.plastic_material)
    return yielding.empty() ? "below yield" : "yields (elastic-plastic material, valid): " + names;
  return yielding.empty() ? "elastic" : "YIELDS: " + names;
}

} // namespace

void energy_section(Document& doc, const Report& report) {
  doc.heading("Energy balance and yield check");
  doc.paragraph(
      "Energy balance: (kinetic + strain + dissipated + radiated energy - initial energy) / "
      "initial energy, the largest |error| over the run and the error at its end "
      "(energy_error, energy_error_final of summary.json); the end is judged against the "
      "target " +
      unsigned_percent(energy_balance_target) +
      " (OFF above it). Lost: 1 - e^2 of the FEM restitution. Yield: each body's largest von "
      "Mises stress against that body's own yield strength [MPa], and the bodies that exceed "
      "theirs. " +
      plasticity_sentence(report));
  Table table{{"V [m/s]", "largest energy error [%]", "energy error at the end [%]",
               "lost 1-e^2 [%]", "dissipated [%]", "radiated [%]"},
              {}};
  // The bodies whose stress some run records (per body, or the largest stress over both).
  std::vector<std::string> bodies;
  for (const auto& run : report.runs)
    for (const auto& body : run.record.bodies)
      if (body.max_von_mises && std::find(bodies.begin(), bodies.end(), body.body) == bodies.end())
        bodies.push_back(body.body);
  for (const auto& body : bodies)
    table.header.push_back(body + ": max von Mises of yield strength");
  table.header.push_back("yield check");
  const auto optional_cell = [](const std::optional<double>& value, double scale) {
    return value ? cell(*value * scale) : std::string("not recorded");
  };
  for (const auto& run : report.runs) {
    const auto& record = run.record;
    std::string final_error = optional_cell(record.energy_error_final, 100);
    if (record.energy_error_final && std::abs(*record.energy_error_final) > energy_balance_target)
      final_error += " (OFF)";
    std::vector<std::string> row{velocity_cell(run),
                                 optional_cell(record.energy_error, 100),
                                 final_error,
                                 cell((1 - run.fem.restitution * run.fem.restitution) * 100),
                                 optional_cell(record.dissipated_energy_fraction, 100),
                                 optional_cell(record.radiated_energy_fraction, 100)};
    for (const auto& name : bodies) {
      const auto body = std::find_if(record.bodies.begin(), record.bodies.end(),
                                     [&](const BodyStress& entry) { return entry.body == name; });
      row.push_back(body == record.bodies.end() ? "not recorded" : body_stress_cell(*body));
    }
    row.push_back(yield_check(run));
    table.rows.push_back(row);
  }
  doc.table(table);
}

} // namespace impact::postprocess::detail
