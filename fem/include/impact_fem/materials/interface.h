#ifndef IMPACT_FEM_MATERIALS_INTERFACE_H
#define IMPACT_FEM_MATERIALS_INTERFACE_H

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace impact_fem
{
  namespace materials
  {
    using namespace dealii;

    /**
     * Constitutive law of one body, small strain, axisymmetric.
     *
     * Strains and stresses are 3x3 symmetric tensors in the cylindrical basis
     * ordered (r, z, theta): the hoop component theta-theta is the third
     * diagonal entry, the only shear component is r-z.
     *
     * The model is linear in the strain and the strain rate, which keeps the
     * effective stiffness of the implicit time step constant:
     *   sigma = C : eps + D : d eps/dt + (history terms of the model),
     * where C = stiffness_tangent() and D = damping_tangent(). Models with
     * internal variables (generalised Maxwell) provide the history terms
     * through the quadrature-point interface that follows in issue 4; elastic
     * and Kelvin-Voigt materials need only C and D.
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


    /// Isotropic elasticity tensor from Young's modulus and Poisson's ratio.
    SymmetricTensor<4, 3>
    isotropic_stiffness(const double youngs_modulus, const double poissons_ratio);


    /// Everything the registry knows about one kind of material.
    struct Registration
    {
      std::string                                 name;
      std::string                                 description;
      std::function<void(ParameterHandler &)>     declare_parameters;
      std::function<std::unique_ptr<Interface>()> create;
    };

    /// Add a kind of material; called once per kind at static initialisation
    /// through IMPACT_FEM_REGISTER_MATERIAL. Returns true.
    bool
    register_material(const Registration &registration);

    /// Names of all registered kinds, sorted.
    std::vector<std::string>
    registered_names();

    /**
     * Declare, inside the current subsection (one per body), the entry
     * "Material model" and one subsection per registered kind.
     */
    void
    declare_parameters(ParameterHandler &prm, const std::string &default_model);

    /**
     * Create the material chosen by "Material model" in the current subsection
     * and let it parse its own subsection.
     */
    std::unique_ptr<Interface>
    create_material(ParameterHandler &prm);

  } // namespace materials
} // namespace impact_fem

/**
 * Register a material class under a name usable in the parameter file. The
 * class needs a default constructor and a static
 * declare_parameters(ParameterHandler &), which declares the entries of the
 * model's own subsection.
 */
#define IMPACT_FEM_REGISTER_MATERIAL(classname, name, description)          \
  namespace                                                                 \
  {                                                                         \
    const bool impact_fem_material_registered_##classname =                 \
      impact_fem::materials::register_material(                             \
        {name,                                                              \
         description,                                                       \
         &classname::declare_parameters,                                    \
         []() -> std::unique_ptr<impact_fem::materials::Interface> {        \
           return std::make_unique<classname>();                            \
         }});                                                               \
  }

#endif
