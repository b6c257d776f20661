#include <impact_fem/materials/body_material.h>
#include <impact_fem/materials/elastic.h>
#include <impact_fem/result_files.h>

namespace impact_fem
{
  namespace materials
  {
    void
    Elastic::declare_parameters(ParameterHandler &prm)
    {
      declare_elastic_constants(prm);
    }


    void
    IsotropicElasticity::declare_elastic_constants(ParameterHandler &prm)
    {
      // No defaults: a constant left out is refused, or taken from the
      // body's Material (body_material.h), never a silent steel.
      prm.declare_entry(result_files::youngs_modulus.entry,
                        "",
                        ConstantPattern(0),
                        "Young's modulus E [Pa], > 0; no default.");
      prm.declare_entry(result_files::poissons_ratio.entry,
                        "",
                        ConstantPattern(-1, 0.5),
                        "Poisson's ratio nu [-], in (-1, 0.5): 0.5 (an "
                        "incompressible body) is not supported by this "
                        "displacement formulation; no default.");
      prm.declare_entry(result_files::density.entry,
                        "",
                        ConstantPattern(0),
                        "Mass density rho [kg/m^3], > 0; no default.");
    }


    void
    IsotropicElasticity::parse_elastic_constants(ParameterHandler &prm)
    {
      young        = prm.get_double(result_files::youngs_modulus.entry);
      poisson      = prm.get_double(result_files::poissons_ratio.entry);
      mass_density = prm.get_double(result_files::density.entry);
      check_elastic_constants(young, poisson, mass_density);
    }


    void
    Elastic::parse_parameters(ParameterHandler &prm)
    {
      parse_elastic_constants(prm);
      stiffness = isotropic_stiffness(young, poisson);
    }

    IMPACT_FEM_REGISTER_MATERIAL(Elastic,
                                 result_files::elastic_model,
                                 "isotropic linear elasticity (E, nu, rho)")
  } // namespace materials
} // namespace impact_fem
