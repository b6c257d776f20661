// Generalised Maxwell (standard linear solid): shear and bulk relaxation as
// Prony series, internal variables integrated exactly over each step.
#include <impact_fem/materials/body_material.h>
#include <impact_fem/materials/elastic.h>
#include <impact_fem/result_files.h>

#include <cmath>

namespace impact_fem
{
  namespace materials
  {
    /**
     * G(t) = G_inf + sum_i G_i exp(-t/tau_i), K(t) = K_inf + sum_j K_j
     * exp(-t/tau_j): a long-term spring in parallel with Maxwell arms
     * (spring and dashpot in series). The internal variable of an arm is the
     * strain of its spring, h (deviatoric for a shear arm, volumetric for a
     * bulk arm); its stress is M h with M = 2 G_i or 3 K_j, and
     *   h(t) = int_0^t exp(-(t - s)/tau) P d eps/ds ds,
     * P the deviatoric or volumetric projector. With the strain linear in
     * time over a step (as in the Newmark step) the hereditary integral is
     * exact:  h_{n+1} = A h_n + g P (eps_{n+1} - eps_n), A = exp(-dt/tau),
     * g = (1 - A) tau / dt, so the arms add the constant tangent M g P and
     * the history M (A h_n - g P eps_n) on the right-hand side. The arm
     * stores M/2 h:h and dissipates (M/tau) h:h per unit time, integrated
     * exactly over the step for the same linear strain path.
     */
    class Maxwell : public IsotropicElasticity
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm)
      {
        prm.declare_entry(result_files::density.entry,
                          "",
                          ConstantPattern(0),
                          "Mass density rho [kg/m^3], > 0; no default.");
        prm.declare_entry("Long-term shear modulus",
                          "",
                          ConstantPattern(0),
                          "G_inf, the relaxed shear modulus [Pa], >= 0; no "
                          "default.");
        prm.declare_entry("Long-term bulk modulus",
                          "",
                          ConstantPattern(0),
                          "K_inf, the relaxed bulk modulus [Pa], >= 0; no "
                          "default.");
        prm.declare_entry("Shear moduli",
                          "",
                          Patterns::List(Patterns::Double(0)),
                          "G_i of the shear Prony terms [Pa], comma "
                          "separated, > 0; empty: no shear relaxation.");
        prm.declare_entry("Shear relaxation times",
                          "",
                          Patterns::List(Patterns::Double(0)),
                          "tau_i of the shear Prony terms [s], > 0, one per "
                          "modulus.");
        prm.declare_entry("Bulk moduli",
                          "",
                          Patterns::List(Patterns::Double(0)),
                          "K_j of the bulk Prony terms [Pa], comma "
                          "separated, > 0; empty: no bulk relaxation.");
        prm.declare_entry("Bulk relaxation times",
                          "",
                          Patterns::List(Patterns::Double(0)),
                          "tau_j of the bulk Prony terms [s], > 0, one per "
                          "modulus.");
      }

      void
      parse_parameters(ParameterHandler &prm) override
      {
        mass_density = prm.get_double(result_files::density.entry);
        AssertThrow(mass_density > 0,
                    ExcMessage("Maxwell/Density must be positive."));
        shear_modulus_relaxed = prm.get_double("Long-term shear modulus");
        bulk_modulus_relaxed  = prm.get_double("Long-term bulk modulus");
        double G0 = shear_modulus_relaxed, K0 = bulk_modulus_relaxed;
        arms.clear();
        for (const bool deviatoric : {true, false})
          {
            const std::string kind   = deviatoric ? "Shear" : "Bulk";
            const auto        moduli = Utilities::string_to_double(
              Utilities::split_string_list(prm.get(kind + " moduli")));
            const auto times =
              Utilities::string_to_double(Utilities::split_string_list(
                prm.get(kind + " relaxation times")));
            AssertThrow(moduli.size() == times.size(),
                        ExcMessage("Maxwell/" + kind + " moduli has " +
                                   std::to_string(moduli.size()) +
                                   " entries but Maxwell/" + kind +
                                   " relaxation times has " +
                                   std::to_string(times.size()) +
                                   ": give one time per modulus."));
            for (unsigned int i = 0; i < moduli.size(); ++i)
              {
                AssertThrow(moduli[i] > 0 && times[i] > 0,
                            ExcMessage("Maxwell/" + kind +
                                       " moduli and relaxation times must "
                                       "be positive."));
                arms.push_back({deviatoric ? 2 * moduli[i] : 3 * moduli[i],
                                times[i],
                                deviatoric});
                (deviatoric ? G0 : K0) += moduli[i];
              }
          }
        AssertThrow(G0 > 0 && K0 > 0,
                    ExcMessage("Maxwell: the instantaneous shear and bulk "
                               "moduli (long-term plus Prony terms) must be "
                               "positive."));
        young   = 9 * K0 * G0 / (3 * K0 + G0);
        poisson = (3 * K0 - 2 * G0) / (2 * (3 * K0 + G0));
        stiffness =
          isotropic_tensor(shear_modulus_relaxed, bulk_modulus_relaxed);
      }

      unsigned int
      n_internal_variables() const override
      {
        return arms.size();
      }

      SymmetricTensor<4, 3>
      internal_tangent(const double dt) const override
      {
        SymmetricTensor<4, 3> tangent;
        for (const auto &arm : arms)
          tangent += arm.modulus * growth(dt / arm.relaxation_time) *
                     projector(arm.deviatoric);
        return tangent;
      }

      SymmetricTensor<2, 3>
      internal_stress_predictor(const std::vector<SymmetricTensor<2, 3>> &h,
                                const SymmetricTensor<2, 3> &strain_start,
                                const double                 dt) const override
      {
        SymmetricTensor<2, 3> stress;
        for (unsigned int i = 0; i < arms.size(); ++i)
          {
            const double x = dt / arms[i].relaxation_time;
            stress += arms[i].modulus *
                      (std::exp(-x) * h[i] -
                       growth(x) * project(strain_start, arms[i].deviatoric));
          }
        return stress;
      }

      double
      update_internal_variables(std::vector<SymmetricTensor<2, 3>> &h,
                                const SymmetricTensor<2, 3> &strain_start,
                                const SymmetricTensor<2, 3> &strain_end,
                                const double                 dt) const override
      {
        double dissipated = 0;
        for (unsigned int i = 0; i < arms.size(); ++i)
          {
            const double                x     = dt / arms[i].relaxation_time;
            const double                decay = std::exp(-x);
            const SymmetricTensor<2, 3> increment =
              project(strain_end - strain_start, arms[i].deviatoric);
            // (M / tau) int_0^dt h:h dt for h(s) = a(s) h_n + tau (1 - a(s))
            // r, a(s) = exp(-s/tau), r = increment / dt, in closed form; the
            // small-x series avoid the cancellation of the closed form.
            const double hh = h[i] * h[i], hr = h[i] * increment,
                         rr           = increment * increment;
            const double one_minus_a2 = -std::expm1(-2 * x);
            double       cross,
              square; // int a(1-a) / (tau x), int (1-a)^2 / (tau x^2)
            if (x < 1e-3)
              {
                cross  = x / 2 - x * x / 2 + 7 * x * x * x / 24;
                square = x / 3 - x * x / 4 + 7 * x * x * x / 60;
              }
            else
              {
                const double one_minus_a = -std::expm1(-x);
                cross                    = (one_minus_a - one_minus_a2 / 2) / x;
                square = (x - 2 * one_minus_a + one_minus_a2 / 2) / (x * x);
              }
            dissipated += arms[i].modulus * (hh * one_minus_a2 / 2 +
                                             2 * hr * cross + rr * square);
            h[i] = decay * h[i] + growth(x) * increment;
          }
        return dissipated;
      }

      SymmetricTensor<2, 3>
      internal_stress(
        const std::vector<SymmetricTensor<2, 3>> &h) const override
      {
        SymmetricTensor<2, 3> stress;
        for (unsigned int i = 0; i < arms.size(); ++i)
          stress += arms[i].modulus * h[i];
        return stress;
      }

      double
      internal_energy(
        const std::vector<SymmetricTensor<2, 3>> &h) const override
      {
        double energy = 0;
        for (unsigned int i = 0; i < arms.size(); ++i)
          energy += 0.5 * arms[i].modulus * (h[i] * h[i]);
        return energy;
      }

    private:
      struct Arm
      {
        double modulus;         // 2 G_i (shear) or 3 K_j (bulk) [Pa]
        double relaxation_time; // [s]
        bool   deviatoric;
      };

      // g = (1 - exp(-x)) / x, x = dt / tau.
      static double
      growth(const double x)
      {
        return x < 1e-8 ? 1 - x / 2 : -std::expm1(-x) / x;
      }

      static SymmetricTensor<4, 3>
      projector(const bool deviatoric)
      {
        const SymmetricTensor<2, 3> I = unit_symmetric_tensor<3>();
        return deviatoric ? deviator_tensor<3>() : outer_product(I, I) / 3.;
      }

      static SymmetricTensor<2, 3>
      project(const SymmetricTensor<2, 3> &strain, const bool deviatoric)
      {
        return deviatoric ? deviator(strain) :
                            trace(strain) / 3. * unit_symmetric_tensor<3>();
      }

      double           shear_modulus_relaxed = 0, bulk_modulus_relaxed = 0;
      std::vector<Arm> arms;
    };

    IMPACT_FEM_REGISTER_MATERIAL(
      Maxwell,
      "maxwell",
      "generalised Maxwell (Prony series in shear and bulk): rho, G_inf, "
      "K_inf, lists of G_i, tau_i and K_j, tau_j")
  } // namespace materials
} // namespace impact_fem
