#ifndef IMPACT_FEM_MATERIALS_BODY_MATERIAL_H
#define IMPACT_FEM_MATERIALS_BODY_MATERIAL_H

#include <impact_fem/materials/interface.h>

#include <deal.II/base/parameter_handler.h>

#include <nlohmann/json.hpp>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace impact_fem
{
  namespace materials
  {
    using namespace dealii;

    /**
     * A material constant of the entry "Young's modulus", ... without a
     * default: the empty text means "not given", anything else must be a
     * number in [min, max] (as Patterns::Double). A body's constant is then
     * either the scenario's or the material table's, never a silent steel.
     */
    class ConstantPattern : public Patterns::PatternBase
    {
    public:
      ConstantPattern(const double min = Patterns::Double::min_double_value,
                      const double max = Patterns::Double::max_double_value);

      bool
      match(const std::string &value) const override;
      std::string
      description(const OutputStyle style = Machine) const override;
      std::unique_ptr<Patterns::PatternBase>
      clone() const override;

      /// The end of description(): how the entries without a default are
      /// told from the others.
      static constexpr const char *marker = " or empty (not given)";

    private:
      Patterns::Double number;
    };


    /// One published material of the table fem/materials/materials.json.
    struct TableMaterial
    {
      std::string name;        ///< as in 'set Material = <name>'
      std::string description; ///< grade and condition
      struct Constant
      {
        double      value;  ///< SI
        std::string source; ///< the page it was read from
        std::string note;   ///< which value of a range, and why
      };
      /// By parameter entry ("Young's modulus", "Yield strength", ...).
      std::map<std::string, Constant> constants;
    };

    /// The material table, read once from the text compiled into the
    /// program; by name.
    const std::map<std::string, TableMaterial> &
    material_table();

    /// "AISI 304, 6061-T6, ...": the names of the table, for messages.
    std::string
    material_table_names();


    /// A constant of a body's material as used by the run.
    struct UsedConstant
    {
      std::string parameter; ///< "Sphere/Elastic-plastic/Young's modulus"
      double      value;     ///< SI
      std::string unit;
      /// "scenario" (the entry was given) or "table" (from Material).
      std::string origin;
      std::string source; ///< the table's citation; empty for the scenario
    };

    /**
     * The material of one body as the run uses it: the model, the table
     * material named by the body's entry "Material" (if any), the
     * constitutive law created from both, the body's yield strength and,
     * for each constant the model has no default for, its value and origin.
     */
    struct BodyMaterial
    {
      std::string                body;               ///< "Sphere" or "Plate"
      std::string                model;              ///< "Material model"
      std::string                table_name;         ///< "Material", "" if none
      std::unique_ptr<Interface> material;           ///< null for a rigid plate
      double                     yield_strength = 0; ///< [Pa], 0: none
      std::vector<UsedConstant>  constants;

      /// For summary.json: {"material model", "material", "constants":
      /// {entry: {"parameter", "value", "unit", "origin", "source"}}}.
      nlohmann::json
      to_json() const;

      /// Lines for the start of a run's log, one per constant.
      std::string
      describe() const;
    };

    /// The body's own entries "Material" and "Yield strength" (inside the
    /// body's subsection, beside "Material model").
    void
    declare_body_entries(ParameterHandler &prm);

    /**
     * Read the material of @p body ("Sphere", "Plate"), entering its
     * subsection: the table material named by "Material" fills the
     * constants the scenario leaves empty (an explicit entry wins), the
     * model is created from them, and a constant neither gives is refused
     * with its full name. The handler is left as it was (the table's values
     * are set only while the model reads them), so that reading it again
     * gives the same origins.
     */
    BodyMaterial
    read_body_material(ParameterHandler &prm, const std::string &body);
  } // namespace materials
} // namespace impact_fem

#endif
