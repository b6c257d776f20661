#include <impact_fem/materials/elastic.h>
#include <impact_fem/result_files.h>

namespace impact_fem
{
  namespace materials
  {
    void
    Elastic::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry(result_files::youngs_modulus.entry,
                        "2e11",
                        Patterns::Double(0),
                        "Young's modulus E [Pa], > 0.");
      prm.declare_entry(result_files::poissons_ratio.entry,
                        "0.25",
                        Patterns::Double(-1, 0.5),
                        "Poisson's ratio nu [-], in (-1, 0.5): 0.5 (an "
                        "incompressible body) is not supported by this "
                        "displacement formulation.");
      prm.declare_entry(result_files::density.entry,
                        "7800",
                        Patterns::Double(0),
                        "Mass density rho [kg/m^3], > 0.");
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
