#ifndef IMPACT_FEM_ANALYSIS_LOADING_HISTORY_H
#define IMPACT_FEM_ANALYSIS_LOADING_HISTORY_H

#include <impact_fem/analysis/interface.h>
#include <impact_fem/materials/interface.h>
#include <impact_fem/output/history.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <memory>
#include <string>
#include <vector>

namespace impact_fem
{
  using namespace dealii;

  /**
   * What the material-point and the specimen analyses share: the
   * prescribed history of subsection "Material point" (declared by
   * MaterialPointTest::declare_parameters), and the history.h5 columns of
   * a strain and a stress in the (r, z, theta) basis.
   */
  namespace loading_history
  {
    /**
     * (rr, zz, theta-theta, rz) -> the 3x3 symmetric tensor in (r, z,
     * theta); @p c must have 4 entries.
     */
    SymmetricTensor<2, 3>
    tensor_from(const std::vector<double> &c);

    /**
     * What both analyses read: the sphere's material, the output directory
     * and the prescribed history.
     */
    struct Loading
    {
      std::unique_ptr<materials::Interface> material;
      std::string                           directory;
      std::string                           loading;
      std::vector<double>                   strain_hat, stress_hat;
      std::vector<SymmetricTensor<2, 3>>    path;
      std::vector<double>                   axial_path;
      double ramp_time = 0, omega = 0, duration = 0, dt = 0;
    };

    /**
     * Reads subsections "Sphere", "Output" and "Material point"; refuses a
     * strain-path point without 4 components and a non-positive time step,
     * duration or ramp time, naming the entry.
     */
    Loading
    read_loading(ParameterHandler &prm);

    /**
     * The factor f(t) of Strain in the strain histories (dimensionless):
     * min(t / Ramp time, 1) for "strain ramp", sin(Angular frequency t) for
     * "strain oscillation"; t >= 0 in s.
     */
    double
    strain_factor(const Loading &loading, double t);

    /**
     * Its time derivative df/dt [1/s]: 1 / Ramp time before the end of the
     * ramp and 0 from then on; omega cos(omega t) for the oscillation.
     */
    double
    strain_factor_rate(const Loading &loading, double t);

    /**
     * Declares the history's time, strain_* and stress_* columns (rr, zz,
     * theta-theta, rz); the descriptions are "<before>strain rr<after>".
     */
    void
    declare_components(History           &history,
                       const std::string &before,
                       const std::string &after);

    /** Appends t and the components of the strain and the stress. */
    void
    append_components(History                     &history,
                      double                       t,
                      const SymmetricTensor<2, 3> &strain,
                      const SymmetricTensor<2, 3> &stress);


    /**
     * An analysis of a prescribed history (material point, specimen):
     * small and serial, it runs on the first rank alone; the other ranks
     * return at once.
     */
    class SerialAnalysis : public analysis::Interface
    {
    public:
      /// Keeps @p prm on the first rank.
      void
      parse_parameters(ParameterHandler           &prm,
                       const analysis::Invocation &invocation,
                       const MPI_Comm              comm) final;

      int
      run() final;

    protected:
      /// The run on the first rank, with the parameters as set.
      virtual void
      run_on_first_rank(ParameterHandler &prm) = 0;

    private:
      ParameterHandler *parameters = nullptr;
    };
  } // namespace loading_history
} // namespace impact_fem

#endif
