#include <impact_fem/parameter_path.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <nlohmann/json.hpp>

#include <sstream>

namespace impact_fem
{
  std::string
  ParameterPath::name() const
  {
    std::string result;
    for (const auto &section : sections)
      result += section + "/";
    return result + entry;
  }


  std::string
  ParameterPath::get(ParameterHandler &prm) const
  {
    for (const auto &section : sections)
      prm.enter_subsection(section);
    const std::string value = prm.get(entry);
    for (std::size_t i = 0; i < sections.size(); ++i)
      prm.leave_subsection();
    return value;
  }


  bool
  ParameterPath::set(ParameterHandler &prm, const std::string &value) const
  {
    for (const auto &section : sections)
      prm.enter_subsection(section);
    bool matches = true;
    try
      {
        prm.set(entry, value);
      }
    catch (const ExceptionBase &)
      {
        matches = false;
      }
    for (std::size_t i = 0; i < sections.size(); ++i)
      prm.leave_subsection();
    return matches;
  }


  std::optional<ParameterPath>
  find_parameter(ParameterHandler &prm, const std::string &path)
  {
    std::vector<std::string> parts = Utilities::split_string_list(path, '/');
    if (parts.empty())
      return std::nullopt;
    std::stringstream declared;
    prm.print_parameters(declared, ParameterHandler::JSON);
    nlohmann::json node = nlohmann::json::parse(declared.str());
    for (const auto &part : parts)
      {
        if (!node.is_object() || !node.contains(part))
          return std::nullopt;
        node = nlohmann::json(node[part]);
      }
    // An entry is an object with a value and a pattern; a subsection is not.
    if (!node.is_object() || !node.contains("value") ||
        !node.contains("pattern_description") || !node["value"].is_string())
      return std::nullopt;
    ParameterPath result;
    result.entry = parts.back();
    parts.pop_back();
    result.sections            = parts;
    result.pattern_description = node["pattern_description"].get<std::string>();
    return result;
  }
} // namespace impact_fem
