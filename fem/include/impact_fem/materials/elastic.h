#ifndef IMPACT_FEM_MATERIALS_ELASTIC_H
#define IMPACT_FEM_MATERIALS_ELASTIC_H

#include <impact_fem/materials/interface.h>

namespace impact_fem
{
  namespace materials
  {
    /// Isotropic linear elasticity: sigma = lambda tr(eps) I + 2 mu eps.
    class Elastic : public Interface
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      double
      density() const override
      {
        return mass_density;
      }

      SymmetricTensor<4, 3>
      stiffness_tangent() const override
      {
        return stiffness;
      }

      double
      youngs_modulus() const override
      {
        return young;
      }

      double
      poissons_ratio() const override
      {
        return poisson;
      }

    private:
      double                young        = 0;
      double                poisson      = 0;
      double                mass_density = 0;
      SymmetricTensor<4, 3> stiffness;
    };
  } // namespace materials
} // namespace impact_fem

#endif
