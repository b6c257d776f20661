#include "impact_postprocess/impact_quantities.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace impact::postprocess {

double value(const ImpactFigures& impact, Quantity quantity) {
  switch (quantity) {
    case Quantity::energy_loss:
      return 1 - impact.restitution * impact.restitution;
    case Quantity::restitution_deficit:
      return 1 - impact.restitution;
    case Quantity::restitution:
      return impact.restitution;
    case Quantity::contact_time:
      return impact.contact_time;
    case Quantity::force_max:
      return impact.force_max;
    case Quantity::time_force_max:
      return impact.time_force_max;
    case Quantity::approach_max:
      return impact.approach_max;
  }
  throw std::logic_error("unknown quantity");
}

const char* quantity_key(Quantity quantity) {
  static const std::array<const char*, quantity_count> keys = {"energy_loss", "restitution_deficit",
                                                               "restitution", "contact_time",
                                                               "force_max",   "time_force_max",
                                                               "approach_max"};
  return keys.at(static_cast<std::size_t>(quantity));
}

const char* quantity_symbol(Quantity quantity) {
  static const std::array<const char*, quantity_count> symbols = {"1 - e^2", "1 - e", "e",
                                                                  "t_c",     "F_max", "t(F_max)",
                                                                  "x_max"};
  return symbols.at(static_cast<std::size_t>(quantity));
}

const char* quantity_words(Quantity quantity) {
  static const std::array<const char*, quantity_count> words = {
      "energy loss",  "1 - e",      "restitution",
      "contact time", "peak force", "time of the peak force",
      "peak approach"};
  return words.at(static_cast<std::size_t>(quantity));
}

double relative_error(double model, double reference) {
  if (!std::isfinite(model) || !std::isfinite(reference) || reference == 0)
    return std::numeric_limits<double>::quiet_NaN();
  return (model - reference) / std::abs(reference);
}

double relative_error(const ImpactFigures& model, const ImpactFigures& reference,
                      Quantity quantity) {
  const double m = value(model, quantity), r = value(reference, quantity);
  const bool loss = quantity == Quantity::energy_loss || quantity == Quantity::restitution_deficit;
  if (loss && std::abs(m) < elastic_loss_resolution && std::abs(r) < elastic_loss_resolution)
    return 0; // both elastic
  return relative_error(m, r);
}

} // namespace impact::postprocess
