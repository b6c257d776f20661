#include "impact_postprocess/run/verification.hpp"

#include "impact_postprocess/run/fem_run_format.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <limits>

namespace impact::postprocess {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

[[noreturn]] void fail(const std::filesystem::path& file, const std::string& problem) {
  throw RunInputError("verification '" + file.string() + "': " + problem);
}

double number_or_null(const nlohmann::json& node, const std::string& key,
                      const std::filesystem::path& file, const std::string& where) {
  if (!node.contains(key)) fail(file, where + " has no '" + key + "'");
  if (node[key].is_null()) return nan;
  if (!node[key].is_number()) fail(file, where + "." + key + " is not a number");
  return node[key].get<double>();
}

} // namespace

std::optional<Verification> read_verification(const std::filesystem::path& run_source) {
  const auto file = run_source.parent_path() / fem_format::verification_file;
  if (!std::filesystem::exists(file)) return std::nullopt;
  nlohmann::json document;
  try {
    std::ifstream in(file);
    document = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    fail(file, std::string("it is not valid JSON (") + error.what() + ")");
  }
  if (!document.is_object() || document.value("format", "") != "impact-verification")
    fail(file, "it has no \"format\": \"impact-verification\"");
  if (!document.contains("format_version") || document["format_version"] != 1)
    fail(file, "its format_version is not 1");
  Verification verification;
  verification.source = file.string();
  verification.refinement_ratio = number_or_null(document, "refinement_ratio", file, "the file");
  if (!document.contains("quantities") || !document["quantities"].is_object())
    fail(file, "it has no object 'quantities'");
  for (const auto& [key, entry] : document["quantities"].items()) {
    const std::string where = "quantities." + key;
    if (!entry.is_object()) fail(file, where + " is not an object");
    VerifiedQuantity quantity;
    quantity.unit = entry.value("unit", "");
    quantity.fine = number_or_null(entry, "fine", file, where);
    quantity.medium = number_or_null(entry, "medium", file, where);
    quantity.coarse = number_or_null(entry, "coarse", file, where);
    quantity.observed_order = number_or_null(entry, "observed_order", file, where);
    quantity.extrapolated = number_or_null(entry, "extrapolated", file, where);
    quantity.gci_fine = number_or_null(entry, "gci_fine", file, where);
    quantity.gci_fine_absolute = number_or_null(entry, "gci_fine_absolute", file, where);
    if (!entry.contains("convergence") || !entry["convergence"].is_string())
      fail(file, where + " has no text 'convergence'");
    quantity.convergence = entry["convergence"].get<std::string>();
    verification.quantities[key] = quantity;
  }
  return verification;
}

} // namespace impact::postprocess
