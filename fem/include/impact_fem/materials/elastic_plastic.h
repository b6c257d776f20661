#ifndef IMPACT_FEM_MATERIALS_ELASTIC_PLASTIC_H
#define IMPACT_FEM_MATERIALS_ELASTIC_PLASTIC_H

#include <impact_fem/materials/elastic.h>

namespace impact_fem
{
  namespace materials
  {
    /**
     * Small-strain J2 (von Mises) plasticity with isotropic hardening
     * (Simo & Hughes 1998, Computational Inelasticity, ch. 2-3), on the full
     * axisymmetric strain (r, z, theta, the hoop strain included):
     *   sigma = C : (eps - eps^p),  f = q - sigma_y(eps_p, d eps_p/dt) <= 0,
     * q = sqrt(3/2 s:s) the von Mises stress of the deviator s, associated
     * flow d eps^p = sqrt(3/2) d eps_p s/|s|, eps_p the accumulated plastic
     * strain. The flow stress is linear, sigma_y = Y + H eps_p (H = 0:
     * perfectly plastic), or Johnson-Cook's without the thermal term
     * (Johnson & Cook 1983),
     *   sigma_y = (Y + B eps_p^n) (1 + C ln(max(rate / rate_0, 1))),
     * no rate effect below the reference rate (as in Altair OptiStruct's
     * MATX02 Johnson-Cook entry). The step is integrated by the radial
     * return (backward Euler: Wilkins 1964; Simo & Hughes 1998, box 3.1),
     * the tangent is the consistent one of Simo & Taylor (1985, CMAME 48,
     * 101-118). An optional Kelvin-Voigt viscosity C : tau_r d eps/dt acts
     * in parallel (damping_tangent()); yielding is judged on the
     * elastic-plastic stress alone.
     */
    class ElasticPlastic : public Elastic
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      /// The initial flow stress Y [Pa]: the body's Yield strength.
      void
      set_yield_strength(const double yield) override
      {
        yield_strength = yield;
      }

      bool
      is_linear() const override
      {
        return false;
      }

      SymmetricTensor<4, 3>
      damping_tangent() const override
      {
        return damping;
      }

      SymmetricTensor<2, 3>
      stress_update(const QuadraturePointState  &start,
                    const SymmetricTensor<2, 3> &strain_end,
                    const double                 time_step,
                    QuadraturePointState        &end,
                    SymmetricTensor<4, 3>       &tangent) const override;

      /// Quasi-static flow stress sigma_y(eps_p) (rate below the
      /// reference) [Pa].
      double
      yield_stress(const double accumulated_plastic_strain) const override;

    private:
      /// sigma_y(eps_p, rate) [Pa]; @p slope its derivative with respect
      /// to the step's increment of eps_p (rate = increment / time_step).
      double
      flow_stress(const double accumulated,
                  const double rate,
                  double      &slope,
                  const double time_step) const;

      double                shear_modulus = 0, bulk_modulus = 0;
      double                yield_strength = 0, hardening_modulus = 0;
      bool                  johnson_cook = false;
      double                jc_b = 0, jc_n = 1, jc_c = 0, reference_rate = 1;
      double                retardation_time = 0;
      SymmetricTensor<4, 3> damping;
    };
  } // namespace materials
} // namespace impact_fem

#endif
