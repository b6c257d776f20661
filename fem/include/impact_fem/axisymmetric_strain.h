#ifndef IMPACT_FEM_AXISYMMETRIC_STRAIN_H
#define IMPACT_FEM_AXISYMMETRIC_STRAIN_H

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

namespace impact_fem
{
  /**
   * Small strain of a vector-valued shape function (or field) in the
   * meridian plane, as a 3x3 tensor ordered (r, z, theta); the hoop strain
   * is u_r / r. Used by the impact and the specimen analysis.
   */
  inline dealii::SymmetricTensor<2, 3>
  axisymmetric_strain(const dealii::Tensor<1, 2> &value,
                      const dealii::Tensor<2, 2> &gradient,
                      const double                r)
  {
    dealii::SymmetricTensor<2, 3> strain;
    strain[0][0] = gradient[0][0];
    strain[1][1] = gradient[1][1];
    strain[2][2] = value[0] / r;
    strain[0][1] = 0.5 * (gradient[0][1] + gradient[1][0]);
    return strain;
  }
} // namespace impact_fem

#endif
