#include <impact_fem/materials/elastic.h>

namespace impact_fem
{
  namespace materials
  {
    void
    Elastic::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Young's modulus",
                        "2e11",
                        Patterns::Double(0),
                        "Young's modulus E [Pa], > 0.");
      prm.declare_entry("Poisson's ratio",
                        "0.25",
                        Patterns::Double(-1, 0.5),
                        "Poisson's ratio nu [-], in (-1, 0.5): 0.5 (an "
                        "incompressible body) is not supported by this "
                        "displacement formulation.");
      prm.declare_entry("Density",
                        "7800",
                        Patterns::Double(0),
                        "Mass density rho [kg/m^3], > 0.");
    }


    void
    IsotropicElasticity::parse_elastic_constants(ParameterHandler &prm)
    {
      young        = prm.get_double("Young's modulus");
      poisson      = prm.get_double("Poisson's ratio");
      mass_density = prm.get_double("Density");
      check_elastic_constants(young, poisson, mass_density);
    }


    void
    Elastic::parse_parameters(ParameterHandler &prm)
    {
      parse_elastic_constants(prm);
      stiffness = isotropic_stiffness(young, poisson);
    }

    IMPACT_FEM_REGISTER_MATERIAL(Elastic,
                                 "elastic",
                                 "isotropic linear elasticity (E, nu, rho)")
  } // namespace materials
} // namespace impact_fem
