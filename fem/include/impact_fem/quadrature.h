#ifndef IMPACT_FEM_QUADRATURE_H
#define IMPACT_FEM_QUADRATURE_H

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe.h>

namespace impact_fem
{
  /**
   * The one quadrature of the model: matrices, Maxwell arms' states and the
   * stresses of the yield check and the snapshots live on the same points,
   * so they must agree. Gauss with degree + 1 points per direction integrates
   * the mass matrix of the undistorted element exactly.
   */
  inline dealii::QGauss<2>
  cell_quadrature(const dealii::FiniteElement<2> &fe)
  {
    return dealii::QGauss<2>(fe.degree + 1);
  }

  /// The matching rule on faces (absorbing boundaries, bottom mean).
  inline dealii::QGauss<1>
  face_quadrature(const dealii::FiniteElement<2> &fe)
  {
    return dealii::QGauss<1>(fe.degree + 1);
  }
} // namespace impact_fem

#endif
