#include <impact_fem/campaign/sweep.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <optional>
#include <set>
#include <sstream>

namespace impact_fem
{
  namespace
  {
    std::optional<double>
    as_number(const std::string &text)
    {
      if (text.empty())
        return std::nullopt;
      char        *end   = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      if (end != text.c_str() + text.size() || !std::isfinite(value))
        return std::nullopt;
      return value;
    }


    // Entry names: lower case, spaces -> '-'; values: characters other than
    // [A-Za-z0-9.+-] -> '-' (the contract with postprocess/, fem/README.md).
    std::string
    slug(const std::string &entry)
    {
      std::string result;
      for (const char c : entry)
        result +=
          c == ' ' ?
            '-' :
            static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return result;
    }


    std::string
    file_name_safe(const std::string &value)
    {
      std::string result;
      for (const char c : value)
        result += (std::isalnum(static_cast<unsigned char>(c)) || c == '.' ||
                   c == '+' || c == '-') ?
                    c :
                    '-';
      return result;
    }
  } // namespace


  std::string
  SweepAxis::name_component(const unsigned int i) const
  {
    return slug(parameter.entry) + "-" + file_name_safe(values[i]);
  }


  std::string
  velocity_name_component(const double velocity)
  {
    std::ostringstream name;
    name << 'v' << std::setprecision(6) << velocity;
    return name.str();
  }


  nlohmann::ordered_json
  json_value(const std::string &text)
  {
    if (const auto number = as_number(text))
      return *number;
    return text;
  }


  std::vector<SweepAxis>
  parse_sweep(ParameterHandler               &prm,
              const std::vector<std::string> &items,
              const std::string              &option)
  {
    const std::string form =
      std::string(" (allowed form: ") +
      (option.rfind("--", 0) == 0 ?
         option + " \"Section/Entry=v1,v2,...\"" :
         option + " = Section/Entry=v1,v2,...; Section/Entry=...") +
      " with entries of impact-fem --print-parameters and distinct values "
      "that fit them)";
    std::vector<SweepAxis> axes;
    for (const auto &item : items)
      {
        std::function<void()> restore = []() {};
        const auto            fail    = [&](const std::string &problem) {
          restore();
          AssertThrow(false,
                      ExcMessage(option + " \"" + item + "\": " + problem +
                                 form + "."));
        };
        const auto equal = item.find('=');
        if (equal == std::string::npos)
          fail("no '=' between the entry and its values");
        const std::string path      = Utilities::trim(item.substr(0, equal));
        const auto        parameter = find_parameter(prm, path);
        if (!parameter)
          fail("there is no entry <" + path + ">");
        const std::string name = parameter->name();
        if (name == "Scenario/Impact velocity")
          fail("the impact velocity is the campaign's last axis: give it as "
               "--velocities V1,V2,... (or Campaign/Impact velocities), not as "
               "a sweep");
        if (name == "Output/Directory" || name == "Verification/Verify" ||
            name == "Scenario/Analysis" ||
            parameter->sections.front() == "Campaign")
          fail("<" + name +
               "> belongs to the campaign itself and cannot be swept");
        for (const auto &axis : axes)
          if (axis.parameter.name() == name)
            fail("the entry <" + name +
                 "> is swept twice; give all its "
                 "values in one item");

        SweepAxis         axis{*parameter, {}};
        const std::string original = parameter->get(prm);
        restore                    = [&]() { parameter->set(prm, original); };
        std::set<std::string> names;
        for (const auto &value :
             Utilities::split_string_list(item.substr(equal + 1), ','))
          {
            if (value.empty())
              fail("an empty value");
            if (!parameter->set(prm, value))
              fail("the value <" + value + "> does not fit the entry <" + name +
                   ">, whose values are " + parameter->pattern_description);
            for (const auto &other : axis.values)
              {
                const auto a = as_number(value), b = as_number(other);
                if (a && b ? *a == *b : value == other)
                  fail("the value " + value + " is given twice");
              }
            axis.values.push_back(value);
            // Distinct values whose directory names coincide ("a b", "a-b").
            if (!names.insert(axis.name_component(axis.values.size() - 1))
                   .second)
              fail("the values give the same run directory name <" +
                   axis.name_component(axis.values.size() - 1) + ">");
          }
        parameter->set(prm, original);
        if (axis.values.empty())
          fail("no values");
        axes.push_back(axis);
      }
    return axes;
  }
} // namespace impact_fem
