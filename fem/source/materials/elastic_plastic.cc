// Small-strain J2 (von Mises) plasticity with isotropic hardening, radial
// return, optional Kelvin-Voigt viscosity in parallel.
#include <impact_fem/as_written.h>
#include <impact_fem/materials/elastic_plastic.h>
#include <impact_fem/result_files.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <sstream>

namespace impact_fem
{
  namespace materials
  {
    namespace
    {
      // "Elastic-plastic/<entry> must <range>, got <value>."
      void
      check_entry(const bool         valid,
                  const std::string &entry,
                  const std::string &range,
                  const double       value)
      {
        AssertThrow(valid,
                    ExcMessage("Elastic-plastic/" + entry + " must " + range +
                               ", got " + as_written(value) + "."));
      }
    } // namespace


    void
    ElasticPlastic::declare_parameters(ParameterHandler &prm)
    {
      declare_elastic_constants(prm);
      // Replaced by the body's own Yield strength (one per body, whatever
      // its model): declared only to refuse it with a message saying what
      // to write instead (body_material.cc).
      prm.declare_entry(result_files::yield_strength.entry,
                        "",
                        Patterns::Anything(),
                        "Replaced by the body's 'Yield strength' (beside "
                        "'Material model'); must not be set.");
      // Patterns without bounds: the ranges are checked in parse_parameters
      // with messages that give the entry, its range and the value.
      prm.declare_entry(result_files::hardening_law_entry,
                        "linear",
                        Patterns::Selection("linear|johnson-cook"),
                        "linear: sigma_y = Y + H eps_p; johnson-cook: "
                        "sigma_y = (Y + B eps_p^n)(1 + C ln(max(rate / "
                        "reference rate, 1))), eps_p the accumulated plastic "
                        "strain, rate its rate (no thermal term).");
      prm.declare_entry(result_files::hardening_modulus.entry,
                        "0",
                        Patterns::Double(),
                        "H of the linear law [Pa], >= 0; 0 is perfectly "
                        "plastic.");
      prm.declare_entry(result_files::johnson_cook_b.entry,
                        "0",
                        Patterns::Double(),
                        "Strain-hardening coefficient B [Pa], >= 0.");
      prm.declare_entry("Johnson-Cook n",
                        "1",
                        Patterns::Double(),
                        "Strain-hardening exponent n [-], in (0, 1].");
      prm.declare_entry(result_files::johnson_cook_c.entry,
                        "0",
                        Patterns::Double(),
                        "Strain-rate coefficient C [-], >= 0.");
      prm.declare_entry("Reference strain rate",
                        "1",
                        Patterns::Double(),
                        "Reference plastic strain rate of Johnson-Cook "
                        "[1/s], > 0.");
      prm.declare_entry(result_files::retardation_time.entry,
                        "0",
                        Patterns::Double(),
                        "Kelvin-Voigt retardation time tau_r [s], >= 0, of "
                        "a viscous stress C : tau_r d eps/dt in parallel "
                        "with the elastic-plastic one (0: none).");
    }


    void
    ElasticPlastic::parse_parameters(ParameterHandler &prm)
    {
      parse_elastic_constants(prm);
      stiffness     = isotropic_stiffness(young, poisson);
      shear_modulus = young / (2 * (1 + poisson));
      bulk_modulus  = young / (3 * (1 - 2 * poisson));

      // yield_strength: the body's, given by set_yield_strength() and
      // checked where it is read (body_material.cc).
      johnson_cook = prm.get(result_files::hardening_law_entry) ==
                     result_files::johnson_cook_law;
      hardening_modulus = prm.get_double(result_files::hardening_modulus.entry);
      check_entry(hardening_modulus >= 0,
                  "Hardening modulus",
                  "be >= 0 Pa (0: perfectly plastic)",
                  hardening_modulus);
      jc_b = prm.get_double(result_files::johnson_cook_b.entry);
      check_entry(jc_b >= 0, "Johnson-Cook B", "be >= 0 Pa", jc_b);
      jc_n = prm.get_double("Johnson-Cook n");
      check_entry(jc_n > 0 && jc_n <= 1,
                  "Johnson-Cook n",
                  "lie in (0, 1]",
                  jc_n);
      jc_c = prm.get_double(result_files::johnson_cook_c.entry);
      check_entry(jc_c >= 0, "Johnson-Cook C", "be >= 0", jc_c);
      reference_rate = prm.get_double("Reference strain rate");
      check_entry(reference_rate > 0,
                  "Reference strain rate",
                  "be > 0 1/s",
                  reference_rate);
      retardation_time = prm.get_double(result_files::retardation_time.entry);
      check_entry(retardation_time >= 0,
                  "Retardation time",
                  "be >= 0 s",
                  retardation_time);
      damping = isotropic_tensor(shear_modulus * retardation_time,
                                 bulk_modulus * retardation_time);
    }


    double
    ElasticPlastic::flow_stress(const double accumulated,
                                const double rate,
                                double      &slope,
                                const double time_step) const
    {
      if (!johnson_cook)
        {
          slope = hardening_modulus;
          return yield_strength + hardening_modulus * accumulated;
        }
      // (A + B eps^n)(1 + C ln(max(rate/rate_0, 1))), no rate effect below
      // the reference rate; slope is the derivative with respect to the
      // increment of eps over the step (rate = increment / dt).
      const double strain_part =
        yield_strength + jc_b * std::pow(accumulated, jc_n);
      const double strain_slope =
        accumulated > 0 ? jc_b * jc_n * std::pow(accumulated, jc_n - 1) :
                          (jc_n < 1 && jc_b > 0 ? 1e300 : jc_b);
      const double ratio     = rate / reference_rate;
      const double rate_part = ratio > 1 ? 1 + jc_c * std::log(ratio) : 1;
      const double rate_slope =
        ratio > 1 && rate > 0 ? jc_c / (rate * time_step) : 0;
      slope =
        std::min(strain_slope * rate_part + strain_part * rate_slope, 1e300);
      return strain_part * rate_part;
    }


    double
    ElasticPlastic::yield_stress(const double accumulated) const
    {
      double slope;
      return flow_stress(accumulated, 0, slope, 1);
    }


    SymmetricTensor<2, 3>
    ElasticPlastic::stress_update(const QuadraturePointState  &start,
                                  const SymmetricTensor<2, 3> &strain_end,
                                  const double                 dt,
                                  QuadraturePointState        &end,
                                  SymmetricTensor<4, 3>       &tangent) const
    {
      end        = start;
      end.strain = strain_end;
      // Elastic predictor.
      const SymmetricTensor<2, 3> elastic_trial =
        strain_end - start.plastic_strain;
      const SymmetricTensor<2, 3> s_trial =
        2 * shear_modulus * deviator(elastic_trial);
      const double q_trial = std::sqrt(1.5) * s_trial.norm();
      const double eps_n   = start.accumulated_plastic_strain;
      double       slope;
      if (q_trial - flow_stress(eps_n, 0, slope, dt) <= 0)
        {
          tangent = stiffness;
          return stiffness * elastic_trial;
        }

      // Plastic corrector: the consistency condition
      //   f(x) = q_trial - 3 G x - sigma_y(eps_n + x, x / dt) = 0
      // for the increment x of eps_p. f decreases strictly from f(0) > 0 to
      // f(q_trial / 3G) < 0: Newton safeguarded by bisection (closed form
      // for linear hardening).
      const double G3 = 3 * shear_modulus;
      double       x  = 0;
      double       H  = hardening_modulus;
      if (!johnson_cook)
        x = (q_trial - yield_strength - hardening_modulus * eps_n) / (G3 + H);
      else
        {
          double low = 0, high = q_trial / G3;
          x = 0.5 * (low + high);
          for (unsigned int it = 0; it < 200; ++it)
            {
              const double f =
                q_trial - G3 * x - flow_stress(eps_n + x, x / dt, H, dt);
              if (f > 0)
                low = x;
              else
                high = x;
              if (std::abs(f) <= 1e-14 * q_trial || high - low <= 1e-15 * high)
                break;
              const double newton = x + f / (G3 + H);
              x = newton > low && newton < high ? newton : 0.5 * (low + high);
            }
          flow_stress(eps_n + x, x / dt, H, dt);
        }

      // Radial return: the deviator is scaled back along the trial
      // direction, the volumetric part is untouched.
      const SymmetricTensor<2, 3> N = s_trial / s_trial.norm();
      end.plastic_strain = start.plastic_strain + std::sqrt(1.5) * x * N;
      end.accumulated_plastic_strain = eps_n + x;

      // Consistent tangent (Simo & Taylor 1985):
      //   C_alg = C - 2G (3G x / q_trial) (P_dev - N (x) N)
      //             - 2G (3G / (3G + H)) N (x) N,
      // H the slope of the flow stress at the converged increment.
      const double beta = G3 * x / q_trial;
      const double Hs   = std::min(H, 1e20 * G3); // an infinite slope: elastic
      tangent           = stiffness -
                2 * shear_modulus * beta *
                  (deviator_tensor<3>() - outer_product(N, N)) -
                2 * shear_modulus * G3 / (G3 + Hs) * outer_product(N, N);
      return stiffness * (strain_end - end.plastic_strain);
    }

    IMPACT_FEM_REGISTER_MATERIAL(
      ElasticPlastic,
      result_files::elastic_plastic_model,
      "J2 plasticity with isotropic hardening (linear or Johnson-Cook without "
      "the thermal term), optional Kelvin-Voigt viscosity in parallel: E, nu, "
      "rho, Y, hardening law and its constants, retardation time")
  } // namespace materials
} // namespace impact_fem
