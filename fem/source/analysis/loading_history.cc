// The prescribed history of the material-point and specimen analyses, and
// their history columns (loading_history.h).

#include <impact_fem/analysis/loading_history.h>
#include <impact_fem/materials/body_material.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>

namespace impact_fem
{
  namespace loading_history
  {
    SymmetricTensor<2, 3>
    tensor_from(const std::vector<double> &c)
    {
      SymmetricTensor<2, 3> t;
      t[0][0] = c[0];
      t[1][1] = c[1];
      t[2][2] = c[2];
      t[0][1] = c[3];
      return t;
    }


    Loading
    read_loading(ParameterHandler &prm)
    {
      Loading l;
      l.material = materials::read_body_material(prm, "Sphere").material;
      AssertThrow(l.material,
                  ExcMessage("Sphere/Material model = rigid is not allowed: "
                             "the material point and the specimen are of "
                             "the sphere's material."));
      prm.enter_subsection("Output");
      l.directory = prm.get("Directory");
      prm.leave_subsection();
      prm.enter_subsection("Material point");
      l.loading    = prm.get("Loading");
      l.strain_hat = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Strain")));
      l.stress_hat = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Stress")));
      for (const auto &point :
           Utilities::split_string_list(prm.get("Strain path"), ';'))
        {
          const auto c =
            Utilities::string_to_double(Utilities::split_string_list(point));
          AssertThrow(c.size() == 4,
                      ExcMessage(
                        "Material point/Strain path: each point needs "
                        "4 components (rr, zz, theta-theta, rz), got '" +
                        point + "'."));
          l.path.push_back(tensor_from(c));
        }
      l.axial_path = Utilities::string_to_double(
        Utilities::split_string_list(prm.get("Axial strain path")));
      l.ramp_time = prm.get_double("Ramp time");
      l.omega     = prm.get_double("Angular frequency");
      l.duration  = prm.get_double("Duration");
      l.dt        = prm.get_double("Time step");
      prm.leave_subsection();
      AssertThrow(l.dt > 0 && l.duration > 0 && l.ramp_time > 0,
                  ExcMessage("Material point: Time step, Duration and Ramp "
                             "time must be positive."));
      return l;
    }


    double
    strain_factor(const Loading &loading, const double t)
    {
      return loading.loading == "strain ramp" ?
               std::min(t / loading.ramp_time, 1.) :
               std::sin(loading.omega * t);
    }


    double
    strain_factor_rate(const Loading &loading, const double t)
    {
      return loading.loading == "strain ramp" ?
               (t < loading.ramp_time ? 1. / loading.ramp_time : 0.) :
               loading.omega * std::cos(loading.omega * t);
    }


    void
    declare_components(History           &history,
                       const std::string &before,
                       const std::string &after)
    {
      const char *components[4] = {"rr", "zz", "thetatheta", "rz"};
      history.declare("time", "s", "time");
      for (const auto *c : components)
        history.declare(std::string("strain_") + c,
                        "1",
                        before + "strain " + c + after);
      for (const auto *c : components)
        history.declare(std::string("stress_") + c,
                        "Pa",
                        before + "stress " + c + after);
    }


    void
    append_components(History                     &history,
                      const double                 t,
                      const SymmetricTensor<2, 3> &strain,
                      const SymmetricTensor<2, 3> &stress)
    {
      history.append("time", t);
      const SymmetricTensor<2, 3> *tensors[2] = {&strain, &stress};
      for (unsigned int k = 0; k < 2; ++k)
        {
          const std::string prefix = k == 0 ? "strain_" : "stress_";
          history.append(prefix + "rr", (*tensors[k])[0][0]);
          history.append(prefix + "zz", (*tensors[k])[1][1]);
          history.append(prefix + "thetatheta", (*tensors[k])[2][2]);
          history.append(prefix + "rz", (*tensors[k])[0][1]);
        }
    }


    void
    SerialAnalysis::parse_parameters(ParameterHandler &prm,
                                     const analysis::Invocation &,
                                     const MPI_Comm comm)
    {
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        parameters = &prm;
    }


    int
    SerialAnalysis::run()
    {
      if (parameters != nullptr)
        run_on_first_rank(*parameters);
      return 0;
    }
  } // namespace loading_history
} // namespace impact_fem
