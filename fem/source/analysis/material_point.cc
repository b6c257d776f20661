// Scenario/Analysis = material point: one quadrature point under a prescribed history.

#include <impact_fem/analysis/loading_history.h>
#include <impact_fem/analysis/material_point.h>
#include <impact_fem/quadrature.h>
#include <impact_fem/axisymmetric_strain.h>
#include <impact_fem/materials/interface.h>
#include <impact_fem/output/history.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/symmetric_tensor.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>

namespace impact_fem
{
  using namespace loading_history;


  void
  MaterialPointTest::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material point");
    prm.declare_entry(
      "Loading",
      "strain ramp",
      Patterns::Selection(
        "strain ramp|strain oscillation|stress step|strain path|"
        "axial strain path"),
      "Prescribed history at the material point (Scenario/"
      "Analysis = material point, sphere material): "
      "'strain ramp' min(t/t_ramp, 1) eps_hat, 'strain "
      "oscillation' sin(omega t) eps_hat, 'stress step' "
      "sigma_hat for t > 0, 'strain path' piecewise linear "
      "from 0 through the points of 'Strain path', one "
      "Ramp time per segment, then held; 'axial strain path' "
      "(specimen only) the axial strain zz piecewise linear "
      "from 0 through the values of 'Axial strain path', one "
      "Ramp time per segment, then held, the lateral faces "
      "free: uniaxial stress, a tension or compression test.");
    prm.declare_entry("Axial strain path",
                      "2e-2",
                      Patterns::List(Patterns::Double(), 1),
                      "Points of the 'axial strain path' loading: the axial "
                      "strain zz [-] at the end of each segment.");
    prm.declare_entry("Strain path",
                      "1e-3, 0, 0, 0; 1e-3, 0, 0, 1e-3",
                      Patterns::Anything(),
                      "Points of the 'strain path' loading, separated by ';', "
                      "each with the components rr, zz, theta-theta, rz [-].");
    prm.declare_entry("Strain",
                      "1e-3, -2e-4, 5e-4, 3e-4",
                      Patterns::List(Patterns::Double(), 4, 4),
                      "eps_hat: components rr, zz, theta-theta, rz [-].");
    prm.declare_entry("Stress",
                      "1e8, 0, 0, 5e7",
                      Patterns::List(Patterns::Double(), 4, 4),
                      "sigma_hat: components rr, zz, theta-theta, rz [Pa].");
    prm.declare_entry("Ramp time",
                      "1e-6",
                      Patterns::Double(0),
                      "t_ramp of the strain ramp [s], > 0.");
    prm.declare_entry("Angular frequency",
                      "1e6",
                      Patterns::Double(0),
                      "omega of the strain oscillation [rad/s].");
    prm.declare_entry("Duration",
                      "1e-5",
                      Patterns::Double(0),
                      "Length of the history [s], > 0.");
    prm.declare_entry("Time step",
                      "1e-8",
                      Patterns::Double(0),
                      "Constant time step [s], > 0.");
    prm.leave_subsection();
  }


  namespace
  {
    /**
     * One run of the material point: the checked loading, the material's
     * constant tangents and the state (strain, its rate, stress, internal
     * variables or the plastic quadrature-point state) with its history.
     */
    class MaterialPointRun
    {
    public:
      explicit MaterialPointRun(ParameterHandler &prm);

      /// The steps of the loading; returns their number.
      unsigned int
      run();

      /// history.h5 in Output/Directory, and the line on the console.
      void
      write(const unsigned int n_steps) const;

    private:
      /// The segment of the strain path at time t and the position w in it.
      unsigned int
      path_segment(const double t, double &w) const;
      SymmetricTensor<2, 3>
      prescribed_strain(const double t) const;
      SymmetricTensor<2, 3>
      prescribed_strain_rate(const double t) const;
      void
      declare_history();
      void
      record(const double t);
      /// The step to time t.
      void
      step(const double t);

      const Loading               input;
      const materials::Interface &material;
      const std::string          &loading;
      const SymmetricTensor<2, 3> strain_hat, stress_hat;
      const double                ramp_time, dt;
      const SymmetricTensor<4, 3> C, D, C_internal;
      const bool                  stress_controlled;
      // A nonlinear (elastic-plastic) material goes through the general
      // constitutive update; the linear ones keep their closed algebra.
      const bool                         nonlinear;
      std::vector<SymmetricTensor<2, 3>> internal;
      materials::QuadraturePointState    point, point_end;
      SymmetricTensor<4, 3>              tangent;
      History                            history;
      double                             plastic_work = 0, dissipated = 0;
      SymmetricTensor<2, 3>              strain, strain_rate, stress;
    };


    MaterialPointRun::MaterialPointRun(ParameterHandler &prm)
      : input(read_loading(prm))
      , material(*input.material)
      , loading(input.loading)
      , strain_hat(tensor_from(input.strain_hat))
      , stress_hat(tensor_from(input.stress_hat))
      , ramp_time(input.ramp_time)
      , dt(input.dt)
      , C(material.stiffness_tangent())
      , D(material.damping_tangent())
      , C_internal(material.internal_tangent(dt))
      , stress_controlled(loading == "stress step")
      , nonlinear(!material.is_linear())
      , internal(material.n_internal_variables())
    {
      AssertThrow(loading != "axial strain path",
                  ExcMessage(
                    "Material point: the 'axial strain path' loading "
                    "(uniaxial stress, lateral faces free) is one of "
                    "Scenario/Analysis = specimen; at a material point "
                    "prescribe the lateral strains with 'strain path'."));
      AssertThrow(!stress_controlled || D.norm() > 0,
                  ExcMessage("Material point: the 'stress step' (creep) "
                             "loading needs a viscous material (Kelvin-Voigt), "
                             "whose strain starts continuous."));
      AssertThrow(loading != "strain path" || !input.path.empty(),
                  ExcMessage("Material point/Strain path is empty."));
      AssertThrow(!nonlinear || !stress_controlled,
                  ExcMessage("Material point: the 'stress step' loading needs "
                             "a linear viscous material."));
    }


    unsigned int
    MaterialPointRun::path_segment(const double t, double &w) const
    {
      const auto        &path = input.path;
      const double       x    = t / ramp_time;
      const unsigned int i    = static_cast<unsigned int>(std::floor(x));
      if (i >= path.size())
        {
          w = 1;
          return static_cast<unsigned int>(path.size()) - 1;
        }
      w = x - i;
      return i;
    }


    SymmetricTensor<2, 3>
    MaterialPointRun::prescribed_strain(const double t) const
    {
      const auto &path = input.path;
      if (loading == "strain path")
        {
          double             w;
          const unsigned int i = path_segment(t, w);
          const auto start     = i == 0 ? SymmetricTensor<2, 3>() : path[i - 1];
          return start + w * (path[i] - start);
        }
      return strain_factor(input, t) * strain_hat;
    }


    SymmetricTensor<2, 3>
    MaterialPointRun::prescribed_strain_rate(const double t) const
    {
      const auto &path = input.path;
      if (loading == "strain path")
        {
          if (t >= path.size() * ramp_time)
            return SymmetricTensor<2, 3>();
          double             w;
          const unsigned int i = path_segment(t, w);
          const auto start     = i == 0 ? SymmetricTensor<2, 3>() : path[i - 1];
          return (path[i] - start) / ramp_time;
        }
      return strain_factor_rate(input, t) * strain_hat;
    }


    void
    MaterialPointRun::declare_history()
    {
      declare_components(history, "", "");
      history.declare("internal_energy",
                      "J/m^3",
                      "energy stored in the Maxwell arms");
      history.declare("dissipated_energy",
                      "J/m^3",
                      "cumulative dissipation in the Maxwell arms");
      if (nonlinear)
        history.declare(
          {{"accumulated_plastic_strain", "1", "accumulated plastic strain"},
           {"plastic_work",
            "J/m^3",
            "cumulative plastic work, trapezoidal in the stress"}});
    }


    void
    MaterialPointRun::record(const double t)
    {
      append_components(history, t, strain, stress);
      history.append("internal_energy", material.internal_energy(internal));
      history.append("dissipated_energy", dissipated);
      if (nonlinear)
        {
          history.append("accumulated_plastic_strain",
                         point.accumulated_plastic_strain);
          history.append("plastic_work", plastic_work);
        }
    }


    void
    MaterialPointRun::step(const double t)
    {
      const SymmetricTensor<2, 3> predictor =
        material.internal_stress_predictor(internal, strain, dt);
      SymmetricTensor<2, 3> new_strain, new_rate;
      if (stress_controlled)
        {
          // C eps + D d eps/dt + C_int eps + predictor = sigma_hat with the
          // trapezoidal rule of the Newmark step for d eps/dt.
          new_strain =
            invert(C + 2 / dt * D + C_internal) *
            (stress_hat + D * (2 / dt * strain + strain_rate) - predictor);
          new_rate = 2 / dt * (new_strain - strain) - strain_rate;
        }
      else
        {
          new_strain = prescribed_strain(t);
          new_rate   = prescribed_strain_rate(t);
        }
      if (nonlinear)
        {
          const SymmetricTensor<2, 3> elastic_start =
            C * (strain - point.plastic_strain);
          const SymmetricTensor<2, 3> elastic_end =
            material.stress_update(point, new_strain, dt, point_end, tangent);
          plastic_work += 0.5 * (elastic_start + elastic_end) *
                          (point_end.plastic_strain - point.plastic_strain);
          point  = point_end;
          stress = elastic_end + D * new_rate;
        }
      else
        {
          stress =
            C * new_strain + D * new_rate + C_internal * new_strain + predictor;
          dissipated += material.update_internal_variables(internal,
                                                           strain,
                                                           new_strain,
                                                           dt);
        }
      strain      = new_strain;
      strain_rate = new_rate;
      record(t);
    }


    unsigned int
    MaterialPointRun::run()
    {
      declare_history();
      // Initial state: unstrained; under a stress step the dashpot takes the
      // load at t = 0+, d eps/dt = D^-1 sigma_hat.
      if (stress_controlled)
        {
          strain_rate = invert(D) * stress_hat;
          stress      = stress_hat;
        }
      record(0);
      const unsigned int n_steps =
        static_cast<unsigned int>(std::lround(input.duration / dt));
      for (unsigned int step_number = 1; step_number <= n_steps; ++step_number)
        step(step_number * dt);
      return n_steps;
    }


    void
    MaterialPointRun::write(const unsigned int n_steps) const
    {
      const std::string &directory = input.directory;
      std::filesystem::create_directories(directory);
      std::map<std::string, std::string> text;
      text["Scenario/Analysis"]      = "material point";
      text["Material point/Loading"] = loading;
      std::map<std::string, double> numbers;
      numbers["time_step [s]"] = dt;
      history.write_hdf5(directory + "/history.h5", text, numbers, true);
      std::cout << "material point (" << loading << "): " << n_steps
                << " steps of " << dt << " s, final stress zz " << stress[1][1]
                << " Pa -> " << directory << "/history.h5" << std::endl;
    }
  } // namespace


  void
  MaterialPointTest::run_on_first_rank(ParameterHandler &prm)
  {
    MaterialPointRun   point(prm);
    const unsigned int n_steps = point.run();
    point.write(n_steps);
  }


  IMPACT_FEM_REGISTER_ANALYSIS(
    MaterialPointTest,
    "material point",
    3,
    "the sphere's material at one point under the history of the subsection "
    "'Material point' (no mesh, no contact).")
} // namespace impact_fem
