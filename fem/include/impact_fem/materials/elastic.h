#ifndef IMPACT_FEM_MATERIALS_ELASTIC_H
#define IMPACT_FEM_MATERIALS_ELASTIC_H

#include <impact_fem/materials/interface.h>

namespace impact_fem
{
  namespace materials
  {
    /**
     * What the isotropic models share: the density, the stiffness C and the
     * instantaneous Young's modulus and Poisson's ratio, set by the derived
     * class's parse_parameters.
     */
    class IsotropicElasticity : public Interface
    {
    public:
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

    protected:
      /// Declare "Young's modulus", "Poisson's ratio" and "Density", without
      /// defaults.
      static void
      declare_elastic_constants(ParameterHandler &prm);

      /// Read "Young's modulus", "Poisson's ratio" and "Density" of the
      /// current subsection into young, poisson and mass_density, and check
      /// them (check_elastic_constants).
      void
      parse_elastic_constants(ParameterHandler &prm);

      double                young        = 0;
      double                poisson      = 0;
      double                mass_density = 0;
      SymmetricTensor<4, 3> stiffness;
    };


    /// Isotropic linear elasticity: sigma = lambda tr(eps) I + 2 mu eps.
    class Elastic : public IsotropicElasticity
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;
    };
  } // namespace materials
} // namespace impact_fem

#endif
