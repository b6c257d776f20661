#include <impact_fem/as_written.h>
#include <impact_fem/materials/interface.h>
#include <impact_fem/result_files.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string_view>

namespace impact_fem
{
  namespace materials
  {
    namespace
    {
      using Kinds = Registry<Interface>;

      // The subsection of a kind ("elastic" -> "Elastic"): the result files'
      // reader finds the constants by the same rule.
      std::string
      subsection_name(const std::string &name)
      {
        return result_files::material_subsection(name);
      }

      static_assert(
        std::string_view(rigid_model_name) == result_files::rigid_model,
        "the rigid plate's name differs from the result files' one");
    } // namespace


    double
    Interface::p_wave_speed() const
    {
      const double E = youngs_modulus(), nu = poissons_ratio();
      const double constrained_modulus =
        E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
      return std::sqrt(constrained_modulus / density());
    }


    double
    Interface::s_wave_speed() const
    {
      const double shear_modulus =
        youngs_modulus() / (2 * (1 + poissons_ratio()));
      return std::sqrt(shear_modulus / density());
    }


    SymmetricTensor<2, 3>
    Interface::stress_update(const QuadraturePointState  &start,
                             const SymmetricTensor<2, 3> &strain_end,
                             const double                 time_step,
                             QuadraturePointState        &end,
                             SymmetricTensor<4, 3>       &tangent) const
    {
      end        = start;
      end.strain = strain_end;
      update_internal_variables(end.internal,
                                start.strain,
                                strain_end,
                                time_step);
      tangent = stiffness_tangent() + internal_tangent(time_step);
      return stiffness_tangent() * strain_end + internal_stress(end.internal);
    }


    double
    von_mises(const SymmetricTensor<2, 3> &stress)
    {
      const SymmetricTensor<2, 3> s = deviator(stress);
      return std::sqrt(1.5 * scalar_product(s, s));
    }


    SymmetricTensor<4, 3>
    isotropic_stiffness(const double E, const double nu)
    {
      const double          lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
      const double          mu     = E / (2 * (1 + nu));
      SymmetricTensor<4, 3> C;
      for (unsigned int i = 0; i < 3; ++i)
        for (unsigned int j = 0; j < 3; ++j)
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = 0; l < 3; ++l)
              C[i][j][k][l] = lambda * (i == j) * (k == l) +
                              mu * ((i == k) * (j == l) + (i == l) * (j == k));
      return C;
    }


    SymmetricTensor<4, 3>
    isotropic_tensor(const double G, const double K)
    {
      const SymmetricTensor<2, 3> I = unit_symmetric_tensor<3>();
      return 2 * G * deviator_tensor<3>() + K * outer_product(I, I);
    }


    void
    check_elastic_constants(const double young,
                            const double poisson,
                            const double mass_density)
    {
      AssertThrow(young > 0,
                  ExcMessage("Young's modulus must be positive, got " +
                             as_written(young) + " Pa."));
      AssertThrow(poisson > -1 && poisson < 0.5,
                  ExcMessage("Poisson's ratio must lie in (-1, 0.5), got " +
                             as_written(poisson) +
                             ": nu >= 0.5 is an incompressible material, "
                             "which this displacement formulation cannot "
                             "represent."));
      AssertThrow(mass_density > 0,
                  ExcMessage("Density must be positive, got " +
                             as_written(mass_density) + " kg/m^3."));
    }


    void
    declare_parameters(ParameterHandler &prm, const std::string &default_model)
    {
      // 'rigid' is no constitutive law (nothing is meshed): the scenario
      // reads it before creating a material and allows it for the plate only.
      prm.declare_entry(result_files::material_model_entry,
                        default_model,
                        Patterns::Selection(Kinds::selection() + "|" +
                                            rigid_model_name),
                        "Constitutive law of this body; its constants are in "
                        "the subsection of the same name. Known models:" +
                          Kinds::descriptions() + "\n  " + rigid_model_name +
                          ": the plate only: a fixed rigid plane z = 0, not "
                          "meshed (the sphere's own E* in Hertz's theory).");
      for (const auto &kind : Kinds::all())
        {
          prm.enter_subsection(subsection_name(kind.first));
          kind.second.declare_parameters(prm);
          prm.leave_subsection();
        }
    }

  } // namespace materials
} // namespace impact_fem
