// A body's material from the scenario and the material table: which
// constants a model needs, where each came from (body_material.h).
#include <impact_fem/as_written.h>
#include <impact_fem/materials/body_material.h>
#include <impact_fem/result_files.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace impact_fem
{
  namespace materials
  {
    /// The text of fem/materials/materials.json, compiled in by CMake.
    extern const char *const material_table_json;

    namespace
    {
      using Kinds = Registry<Interface>;

      inline constexpr const char *material_entry = "Material";

      // Where a body's yield strength was before it was one per body.
      inline constexpr const char *replaced_yield_subsection =
        "Elastic-plastic";

      std::string
      unit_of(const std::string &entry)
      {
        namespace contract = result_files;
        for (const auto &constant : {contract::youngs_modulus,
                                     contract::poissons_ratio,
                                     contract::density,
                                     contract::retardation_time,
                                     contract::volumetric_retardation_time,
                                     contract::yield_strength,
                                     contract::hardening_modulus})
          if (entry == constant.entry)
            return constant.unit;
        // The Maxwell model's relaxed moduli.
        return entry.find("modulus") != std::string::npos ? "Pa" : "";
      }

      /**
       * The entries of @p model's subsection declared without a default
       * (a ConstantPattern): the constants a scenario or the table must
       * give. Found by declaring the model alone in a scratch handler, so
       * that a new model needs no list here.
       */
      std::vector<std::string>
      constants_without_default(const std::string &model)
      {
        ParameterHandler scratch;
        Kinds::get(model).declare_parameters(scratch);
        std::ostringstream text;
        scratch.print_parameters(text, ParameterHandler::JSON);
        const std::string        marker = ConstantPattern::marker;
        std::vector<std::string> names;
        const nlohmann::json     entries = nlohmann::json::parse(text.str());
        for (const auto &[name, node] : entries.items())
          if (node.is_object() && node.contains("pattern_description"))
            {
              const std::string pattern = node["pattern_description"];
              if (pattern.size() >= marker.size() &&
                  pattern.compare(pattern.size() - marker.size(),
                                  marker.size(),
                                  marker) == 0)
                names.push_back(name);
            }
        return names;
      }

      std::string
      how_to_give(const std::string &body)
      {
        return "set the entry in the scenario, or name a material of the "
               "table for this body ('set Material = <name>' in subsection " +
               body + "; known: " + material_table_names() +
               "; fem/materials/materials.json)";
      }
    } // namespace


    ConstantPattern::ConstantPattern(const double min, const double max)
      : number(min, max)
    {}


    bool
    ConstantPattern::match(const std::string &value) const
    {
      return Utilities::trim(value).empty() || number.match(value);
    }


    std::string
    ConstantPattern::description(const OutputStyle style) const
    {
      return number.description(style) + marker;
    }


    std::unique_ptr<Patterns::PatternBase>
    ConstantPattern::clone() const
    {
      return std::make_unique<ConstantPattern>(*this);
    }


    const std::map<std::string, TableMaterial> &
    material_table()
    {
      static const std::map<std::string, TableMaterial> table = [] {
        std::map<std::string, TableMaterial> materials;
        const auto json = nlohmann::json::parse(material_table_json);
        for (const auto &[name, entry] : json.at("materials").items())
          {
            TableMaterial material{name,
                                   entry.at("description").get<std::string>(),
                                   {}};
            for (const auto &[constant, data] : entry.at("constants").items())
              material.constants[constant] = {
                data.at("value").get<double>(),
                data.at("source").get<std::string>(),
                data.value("note", std::string())};
            materials[name] = material;
          }
        return materials;
      }();
      return table;
    }


    std::string
    material_table_names()
    {
      std::string names;
      for (const auto &[name, material] : material_table())
        names += (names.empty() ? "" : ", ") + name;
      return names;
    }


    void
    declare_body_entries(ParameterHandler &prm)
    {
      prm.declare_entry(material_entry,
                        "",
                        Patterns::Anything(),
                        "A published material whose constants (Young's "
                        "modulus, Poisson's ratio, Density, Yield strength) "
                        "fill the ones this body's scenario leaves empty; an "
                        "entry set in the scenario wins. Empty: none, every "
                        "constant of the model must be given. Known: " +
                          material_table_names() +
                          " (fem/materials/materials.json, with the source of "
                          "each constant).");
      prm.declare_entry(
        result_files::yield_strength.entry,
        "",
        ConstantPattern(0),
        "Yield strength Y of the body [Pa], > 0; empty: none. For the "
        "elastic-plastic model its initial flow stress in uniaxial tension "
        "(Johnson-Cook's A), required; for the other models the yield check "
        "of the summary (whether, when and where the von Mises stress "
        "exceeded it: the model is not valid beyond).");
    }


    namespace
    {
      /// The table's material of the body's Material entry; null if none.
      const TableMaterial *
      table_material(const std::string &body, const std::string &table_name)
      {
        if (table_name.empty())
          return nullptr;
        const auto found = material_table().find(table_name);
        AssertThrow(found != material_table().end(),
                    ExcMessage(body + "/Material = " + table_name +
                               " is not in the material table; known: " +
                               material_table_names() +
                               " (fem/materials/materials.json)."));
        return &found->second;
      }


      /// The table's value of @p entry; null without a table or without the
      /// constant in it.
      const TableMaterial::Constant *
      table_constant(const TableMaterial *table, const std::string &entry)
      {
        if (table == nullptr)
          return nullptr;
        const auto constant = table->constants.find(entry);
        return constant == table->constants.end() ? nullptr : &constant->second;
      }


      // A fixed rigid plane has no constants: a material or a yield strength
      // given for it is a mistake, not something to ignore.
      void
      check_rigid(const BodyMaterial &result, const std::string &yield_text)
      {
        const std::string &body = result.body;
        AssertThrow(result.table_name.empty(),
                    ExcMessage(body + "/Material = " + result.table_name +
                               " has no meaning with " + body +
                               "/Material model = rigid (a fixed rigid "
                               "plane has no constants); leave it empty."));
        AssertThrow(yield_text.empty() || std::stod(yield_text) == 0,
                    ExcMessage(body + "/Yield strength = " + yield_text +
                               " has no meaning with " + body +
                               "/Material model = rigid (the plate is a "
                               "fixed rigid plane, not meshed); leave it at "
                               "its default."));
      }


      /// The yield strength: the scenario's, else the table's; required by
      /// the elastic-plastic model.
      void
      read_yield_strength(BodyMaterial        &result,
                          const std::string   &yield_text,
                          const TableMaterial *table)
      {
        const std::string yield_parameter =
          result_files::body_parameter(result.body,
                                       result_files::yield_strength);
        if (!yield_text.empty())
          {
            result.yield_strength = std::stod(yield_text);
            result.constants.push_back(
              {yield_parameter, result.yield_strength, "Pa", "scenario", ""});
          }
        else if (const auto *constant =
                   table_constant(table, result_files::yield_strength.entry))
          {
            result.yield_strength = constant->value;
            result.constants.push_back({yield_parameter,
                                        constant->value,
                                        "Pa",
                                        "table",
                                        constant->source});
          }
        AssertThrow(result.model != result_files::elastic_plastic_model ||
                      result.yield_strength > 0,
                    ExcMessage(
                      yield_parameter +
                      (yield_text.empty() ?
                         " is not given: the elastic-plastic model needs it "
                         "[Pa], > 0; " +
                           how_to_give(result.body) + "." :
                         " must be > 0 Pa for the elastic-plastic model, "
                         "got " +
                           yield_text + ".")));
      }


      /**
       * The model's constants: the scenario's, else the table's; the model
       * is created only when none is missing (the caller says which are).
       * The table's values are written into the model's subsection for its
       * parse_parameters() and taken out again, whatever happens, so that
       * the handler stays the scenario's.
       */
      std::vector<std::string>
      read_model_constants(ParameterHandler    &prm,
                           BodyMaterial        &result,
                           const TableMaterial *table)
      {
        const std::string subsection =
          result_files::material_subsection(result.model);
        std::vector<std::string> filled, missing;
        prm.enter_subsection(result.body);
        prm.enter_subsection(subsection);
        const auto leave = [&]() {
          for (const auto &entry : filled)
            prm.set(entry, "");
          prm.leave_subsection();
          prm.leave_subsection();
        };
        for (const auto &entry : constants_without_default(result.model))
          {
            const std::string parameter =
              result.body + "/" + subsection + "/" + entry;
            const std::string text = Utilities::trim(prm.get(entry));
            if (!text.empty())
              result.constants.push_back(
                {parameter, std::stod(text), unit_of(entry), "scenario", ""});
            else if (const auto *constant = table_constant(table, entry))
              {
                prm.set(entry, as_written(constant->value));
                filled.push_back(entry);
                result.constants.push_back({parameter,
                                            constant->value,
                                            unit_of(entry),
                                            "table",
                                            constant->source});
              }
            else
              missing.push_back(parameter);
          }
        if (missing.empty())
          {
            result.material = Kinds::get(result.model).create();
            result.material->set_yield_strength(result.yield_strength);
            try
              {
                result.material->parse_parameters(prm);
              }
            catch (...)
              {
                leave();
                throw;
              }
          }
        leave();
        return missing;
      }
    } // namespace


    BodyMaterial
    read_body_material(ParameterHandler &prm, const std::string &body)
    {
      BodyMaterial result;
      result.body = body;
      prm.enter_subsection(body);
      result.model      = prm.get(result_files::material_model_entry);
      result.table_name = Utilities::trim(prm.get(material_entry));
      const std::string yield_text =
        Utilities::trim(prm.get(result_files::yield_strength.entry));
      prm.enter_subsection(replaced_yield_subsection);
      const std::string replaced_yield =
        Utilities::trim(prm.get(result_files::yield_strength.entry));
      prm.leave_subsection();
      prm.leave_subsection();

      AssertThrow(replaced_yield.empty(),
                  ExcMessage(
                    body + "/Elastic-plastic/Yield strength was replaced by " +
                    body +
                    "/Yield strength (one yield strength per body, for "
                    "every material model): write 'set Yield strength = " +
                    replaced_yield + "' in subsection " + body +
                    ", outside its subsection Elastic-plastic."));
      const TableMaterial *table = table_material(body, result.table_name);
      if (result.model == rigid_model_name)
        {
          check_rigid(result, yield_text);
          return result;
        }
      read_yield_strength(result, yield_text, table);

      const std::vector<std::string> missing =
        read_model_constants(prm, result, table);
      std::string list;
      for (const auto &parameter : missing)
        list += (list.empty() ? "" : ", ") + parameter;
      AssertThrow(missing.empty(),
                  ExcMessage(list + (missing.size() == 1 ? " is" : " are") +
                             " not given: the " + result.model +
                             " model has no default for " +
                             (missing.size() == 1 ? "it" : "them") + "; " +
                             how_to_give(body) + "."));
      return result;
    }


    nlohmann::json
    BodyMaterial::to_json() const
    {
      nlohmann::json json;
      json["material model"] = model;
      json["material"]       = table_name.empty() ? nlohmann::json(nullptr) :
                                                    nlohmann::json(table_name);
      nlohmann::json list    = nlohmann::json::object();
      for (const auto &constant : constants)
        {
          const std::string entry =
            constant.parameter.substr(constant.parameter.rfind('/') + 1);
          list[entry] = {{"parameter", constant.parameter},
                         {"value", constant.value},
                         {"unit", constant.unit},
                         {"origin", constant.origin}};
          if (!constant.source.empty())
            list[entry]["source"] = constant.source;
        }
      json["constants"] = list;
      return json;
    }


    std::string
    BodyMaterial::describe() const
    {
      std::ostringstream text;
      text << "  " << body << ": " << model;
      if (!table_name.empty())
        text << ", Material = " << table_name;
      text << "\n";
      for (const auto &constant : constants)
        {
          // Six digits as a reader writes them (8000, not 8e+03), more only
          // where six would not read back as the value used.
          std::ostringstream value;
          value << constant.value;
          const bool exact =
            std::strtod(value.str().c_str(), nullptr) == constant.value;
          text << "    " << constant.parameter << " = "
               << (exact ? value.str() : as_written(constant.value))
               << (constant.unit.empty() || constant.unit == "1" ?
                     "" :
                     " " + constant.unit)
               << "  ("
               << (constant.origin == "table" ? "table: " + table_name :
                                                "scenario entry")
               << ")\n";
        }
      return text.str();
    }
  } // namespace materials
} // namespace impact_fem
