// Kelvin-Voigt viscoelasticity: sigma = C : (eps + tau_r d eps/dt), with
// separate retardation times for the deviatoric and the volumetric parts.
#include <impact_fem/materials/body_material.h>
#include <impact_fem/materials/elastic.h>
#include <impact_fem/result_files.h>

namespace impact_fem
{
  namespace materials
  {
    /**
     * sigma = 2 G (e + tau_d de/dt) + K (theta + tau_v dtheta/dt) I, with
     * e the strain deviator and theta the volume strain: a spring and a
     * dashpot in parallel. Linear in the strain rate, so it enters the time
     * step as a constant damping matrix D = 2 G tau_d P_dev + 3 K tau_v P_vol.
     */
    class KelvinVoigt : public IsotropicElasticity
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        declare_elastic_constants(prm);
        prm.declare_entry(result_files::retardation_time.entry,
                          "",
                          ConstantPattern(0),
                          "Retardation time tau_r of the deviatoric "
                          "(shear) part [s], >= 0; 0 is elastic; no "
                          "default.");
        prm.declare_entry(result_files::volumetric_retardation_time.entry,
                          "-1",
                          Patterns::Double(-1),
                          "Retardation time of the volumetric part [s], "
                          ">= 0; a negative value (default) takes the "
                          "deviatoric 'Retardation time'.");
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        parse_elastic_constants(prm);
        const double tau_d =
          prm.get_double(result_files::retardation_time.entry);
        double tau_v =
          prm.get_double(result_files::volumetric_retardation_time.entry);
        AssertThrow(tau_d >= 0,
                    ExcMessage("Kelvin-voigt/Retardation time must not be "
                               "negative."));
        if (tau_v < 0)
          tau_v = tau_d;
        const double G = young / (2 * (1 + poisson));
        const double K = young / (3 * (1 - 2 * poisson));
        stiffness      = isotropic_tensor(G, K);
        damping        = isotropic_tensor(G * tau_d, K * tau_v);
      }

      SymmetricTensor<4, 3>
      damping_tangent() const override
      {
        return damping;
      }

    private:
      SymmetricTensor<4, 3> damping;
    };

    IMPACT_FEM_REGISTER_MATERIAL(
      KelvinVoigt,
      result_files::kelvin_voigt_model,
      "sigma = C : (eps + tau_r d eps/dt): E, nu, rho, deviatoric and "
      "volumetric retardation times")
  } // namespace materials
} // namespace impact_fem
