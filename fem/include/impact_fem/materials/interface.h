#ifndef IMPACT_FEM_MATERIALS_INTERFACE_H
#define IMPACT_FEM_MATERIALS_INTERFACE_H

#include <impact_fem/registry.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace impact_fem
{
  namespace materials
  {
    using namespace dealii;

    /**
     * What a quadrature point remembers from one step to the next: the
     * strain at the end of the last completed step, the internal variables
     * of a linear model with memory (the spring strains of the Maxwell arms)
     * and the plastic state of an elastic-plastic model (plastic strain,
     * accumulated plastic strain eps_p = int sqrt(2/3 deps_p : deps_p)).
     */
    struct QuadraturePointState
    {
      SymmetricTensor<2, 3>              strain;
      std::vector<SymmetricTensor<2, 3>> internal;
      SymmetricTensor<2, 3>              plastic_strain;
      double                             accumulated_plastic_strain = 0;
    };


    /**
     * Constitutive law of one body, small strain, axisymmetric.
     *
     * Strains and stresses are 3x3 symmetric tensors in the cylindrical basis
     * ordered (r, z, theta): the hoop component theta-theta is the third
     * diagonal entry, the only shear component is r-z.
     *
     * The general contract is stress_update(): from the state of a
     * quadrature point at the start of a step and the strain at its end, the
     * stress, the consistent (algorithmic) tangent and the new state. The
     * viscous stress D : d eps/dt (D = damping_tangent()) acts in parallel
     * and is left to the time stepper, which sees it through the damping
     * matrix.
     *
     * Linear models (is_linear()) are in addition affine in the strain and
     * the strain rate, which keeps the effective stiffness of the implicit
     * time step constant and the step one solve:
     *   sigma = C : eps + D : d eps/dt + sigma_internal(h),
     * where C = stiffness_tangent(), D = damping_tangent() and h are the
     * internal variables of the model at a quadrature point (the spring
     * strains of the Maxwell arms). Elastic and Kelvin-Voigt materials have
     * no internal variables. For a model with internal variables the stress
     * they carry at the end of a step of constant length dt is affine in the
     * strain at the end of the step,
     *   sigma_internal_{n+1} = internal_tangent(dt) : eps_{n+1}
     *                          + internal_stress_predictor(h_n, eps_n, dt),
     * so the algorithmic tangent is constant and the history enters the
     * right-hand side only.
     *
     * A nonlinear model (is_linear() false, elastic-plastic) writes its
     * stress as sigma = C : eps - C : eps_p(eps) with C = stiffness_tangent()
     * its elastic stiffness: the time step keeps the elastic effective
     * stiffness and iterates on the plastic force int B^T C : eps_p dV.
     *
     * A new kind is one new file: a class derived from Interface with a static
     * declare_parameters(ParameterHandler&) and IMPACT_FEM_REGISTER_MATERIAL.
     */
    class Interface
    {
    public:
      virtual ~Interface() = default;

      /// Read the model's own subsection (the handler is already inside it).
      virtual void
      parse_parameters(ParameterHandler &prm) = 0;

      /// The body's yield strength [Pa] (its entry "Yield strength", 0:
      /// none), given before parse_parameters(): the initial flow stress of
      /// a model that yields; a model that never yields ignores it (the
      /// summary's yield check uses it).
      virtual void
      set_yield_strength(const double /*yield_strength*/)
      {}

      /// Mass density [kg/m^3].
      virtual double
      density() const = 0;

      /// d sigma / d eps at fixed strain rate [Pa].
      virtual SymmetricTensor<4, 3>
      stiffness_tangent() const = 0;

      /// d sigma / d (d eps/dt) [Pa s]; zero for an elastic body.
      virtual SymmetricTensor<4, 3>
      damping_tangent() const
      {
        return SymmetricTensor<4, 3>();
      }

      /// Number of internal-variable tensors per quadrature point (0: none).
      virtual unsigned int
      n_internal_variables() const
      {
        return 0;
      }

      /// d sigma_internal_{n+1} / d eps_{n+1} for a step of length dt [Pa].
      virtual SymmetricTensor<4, 3>
      internal_tangent(const double /*time_step*/) const
      {
        return SymmetricTensor<4, 3>();
      }

      /// sigma_internal_{n+1} - internal_tangent(dt) : eps_{n+1}, from the
      /// internal variables and the strain at the start of the step [Pa].
      virtual SymmetricTensor<2, 3>
      internal_stress_predictor(
        const std::vector<SymmetricTensor<2, 3>> & /*internal*/,
        const SymmetricTensor<2, 3> & /*strain_start*/,
        const double /*time_step*/) const
      {
        return SymmetricTensor<2, 3>();
      }

      /// Advance the internal variables over a step in which the strain
      /// goes linearly in time from strain_start to strain_end (exact for
      /// that path). Returns the energy dissipated per unit volume over the
      /// step [J/m^3], also exact for that path.
      virtual double
      update_internal_variables(
        std::vector<SymmetricTensor<2, 3>> & /*internal*/,
        const SymmetricTensor<2, 3> & /*strain_start*/,
        const SymmetricTensor<2, 3> & /*strain_end*/,
        const double /*time_step*/) const
      {
        return 0;
      }

      /// Stress carried by the internal variables [Pa].
      virtual SymmetricTensor<2, 3>
      internal_stress(
        const std::vector<SymmetricTensor<2, 3>> & /*internal*/) const
      {
        return SymmetricTensor<2, 3>();
      }

      /// Elastic energy stored with the internal variables (in the springs
      /// of the Maxwell arms) per unit volume [J/m^3].
      virtual double
      internal_energy(
        const std::vector<SymmetricTensor<2, 3>> & /*internal*/) const
      {
        return 0;
      }

      /// The stress is affine in the strain, the strain rate and the
      /// internal variables (the members above describe it completely).
      virtual bool
      is_linear() const
      {
        return true;
      }

      /**
       * The constitutive update of one quadrature point over a step of
       * length @p time_step: from the state at the start of the step
       * (@p start, its strain included) and the strain at the end,
       * @p strain_end, the stress at the end without the viscous part
       * D : d eps/dt [Pa], the consistent tangent d sigma / d strain_end
       * [Pa] in @p tangent, and the state at the end in @p end (its strain
       * is strain_end). The default is the linear model: C : eps plus the
       * stress of the internal variables advanced exactly over the step.
       */
      virtual SymmetricTensor<2, 3>
      stress_update(const QuadraturePointState  &start,
                    const SymmetricTensor<2, 3> &strain_end,
                    const double                 time_step,
                    QuadraturePointState        &end,
                    SymmetricTensor<4, 3>       &tangent) const;

      /// The von Mises stress at which a point with accumulated plastic
      /// strain @p accumulated_plastic_strain [-] yields at a vanishing
      /// plastic strain rate [Pa]; infinite for a material that never yields.
      virtual double
      yield_stress(const double /*accumulated_plastic_strain*/) const
      {
        return std::numeric_limits<double>::infinity();
      }

      /// Instantaneous Young's modulus [Pa] and Poisson's ratio [-]: they
      /// define the Hertz estimates (time step, contact time) and the wave
      /// speeds of the absorbing boundaries.
      virtual double
      youngs_modulus() const = 0;
      virtual double
      poissons_ratio() const = 0;

      /// Dilatational and shear wave speeds [m/s] of the instantaneous response.
      double
      p_wave_speed() const;
      double
      s_wave_speed() const;
    };


    /// The von Mises equivalent sqrt(3/2 s:s) of a stress [Pa].
    double
    von_mises(const SymmetricTensor<2, 3> &stress);

    /// Isotropic elasticity tensor from Young's modulus and Poisson's ratio.
    SymmetricTensor<4, 3>
    isotropic_stiffness(const double youngs_modulus,
                        const double poissons_ratio);

    /// Isotropic tensor 2 G P_dev + 3 K P_vol from a shear and a bulk
    /// modulus (P_dev, P_vol: the deviatoric and volumetric projectors).
    SymmetricTensor<4, 3>
    isotropic_tensor(const double shear_modulus, const double bulk_modulus);

    /// Checks shared by the models: E > 0, nu in (-1, 0.5), rho > 0, with
    /// messages that name the entry.
    void
    check_elastic_constants(const double youngs_modulus,
                            const double poissons_ratio,
                            const double density);


    /// The value of "Material model" that makes a body a fixed rigid
    /// plane instead of a material (allowed for the plate only).
    inline constexpr const char *rigid_model_name = "rigid";

    /**
     * Declare, inside the current subsection (one per body), the entry
     * "Material model" (the registered kinds and 'rigid') and one
     * subsection per registered kind.
     */
    void
    declare_parameters(ParameterHandler &prm, const std::string &default_model);

  } // namespace materials
} // namespace impact_fem

/**
 * Register a material class under a name usable in the parameter file. The
 * class needs a default constructor and a static
 * declare_parameters(ParameterHandler &), which declares the entries of the
 * model's own subsection.
 */
#define IMPACT_FEM_REGISTER_MATERIAL(classname, name, description) \
  IMPACT_FEM_REGISTER(impact_fem::materials::Interface,            \
                      classname,                                   \
                      name,                                        \
                      description)

#endif
