#ifndef IMPACT_FEM_CELL_STRAIN_OPERATOR_H
#define IMPACT_FEM_CELL_STRAIN_OPERATOR_H

#include <impact_fem/axisymmetric_strain.h>

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <Epetra_MultiVector.h>

#include <cmath>
#include <vector>

namespace impact_fem
{
  /**
   * The strain-displacement operator B of one cell at its quadrature
   * points, evaluated once with FEValues and then applied to the cell's
   * nodal values by dot products. The higher-order mapping is costly to
   * re-evaluate, and the plastic iterations and the per-step yield check
   * apply B many times to the same cells: this is what makes them cheap.
   *
   * Strains are 3x3 tensors ordered (r, z, theta) (axisymmetric_strain()).
   */
  class CellStrainOperator
  {
  public:
    using VectorType = dealii::TrilinosWrappers::MPI::Vector;

    /// @p fe_values reinitialised on the cell (values, gradients,
    /// quadrature points, JxW); @p dofs the cell's global dof indices;
    /// @p ghosted_layout a vector with the owned and ghost entries of the
    /// vectors the operator will read.
    CellStrainOperator(const dealii::FEValues<2> &fe_values,
                       const std::vector<dealii::types::global_dof_index> &dofs,
                       const VectorType &ghosted_layout)
      : dofs(dofs)
      , points(fe_values.get_quadrature_points())
    {
      const unsigned int n           = dofs.size();
      const auto        &partitioner = ghosted_layout.trilinos_partitioner();
      for (const auto dof : dofs)
        local_index.push_back(partitioner.LID(
          static_cast<dealii::TrilinosWrappers::types::int_type>(dof)));
      const dealii::FEValuesExtractors::Vector u(0);
      rows.resize(points.size() * 4 * n);
      for (unsigned int q = 0; q < points.size(); ++q)
        {
          const double r = points[q][0];
          volumes.push_back(2 * M_PI * r * fe_values.JxW(q));
          double *row = &rows[4 * q * n];
          for (unsigned int i = 0; i < n; ++i)
            {
              const dealii::SymmetricTensor<2, 3> e =
                axisymmetric_strain(fe_values[u].value(i, q),
                                    fe_values[u].gradient(i, q),
                                    r);
              row[i]         = e[0][0];
              row[n + i]     = e[1][1];
              row[2 * n + i] = e[2][2];
              row[3 * n + i] = e[0][1];
            }
        }
    }

    /// The cell's nodal values of a ghosted vector (direct reads of its
    /// local storage, no global-to-local lookup).
    void
    gather(const VectorType &ghosted, std::vector<double> &values) const
    {
      // Vector 0 of the Epetra multivector: the owned and ghost values.
      const double *data = ghosted.trilinos_vector()[0];
      values.resize(local_index.size());
      for (unsigned int i = 0; i < values.size(); ++i)
        values[i] = data[local_index[i]];
    }

    /// The strain at point @p q of the nodal values @p values.
    dealii::SymmetricTensor<2, 3>
    strain(const unsigned int q, const std::vector<double> &values) const
    {
      const unsigned int n    = dofs.size();
      const double      *row  = &rows[4 * q * n];
      double             e[4] = {0, 0, 0, 0};
      for (unsigned int k = 0; k < 4; ++k)
        for (unsigned int i = 0; i < n; ++i)
          e[k] += row[k * n + i] * values[i];
      dealii::SymmetricTensor<2, 3> strain;
      strain[0][0] = e[0];
      strain[1][1] = e[1];
      strain[2][2] = e[2];
      strain[0][1] = e[3];
      return strain;
    }

    /// cell_force += B_q^T @p stress (a stress already weighted by the
    /// volume); the shear counts twice (sigma : eps = ... + 2 s_rz e_rz).
    void
    add_transpose(const unsigned int                   q,
                  const dealii::SymmetricTensor<2, 3> &stress,
                  dealii::Vector<double>              &cell_force) const
    {
      const unsigned int n    = dofs.size();
      const double      *row  = &rows[4 * q * n];
      const double       s[4] = {stress[0][0],
                                 stress[1][1],
                                 stress[2][2],
                                 2 * stress[0][1]};
      for (unsigned int k = 0; k < 4; ++k)
        for (unsigned int i = 0; i < n; ++i)
          cell_force(i) += s[k] * row[k * n + i];
    }

    unsigned int
    n_points() const
    {
      return points.size();
    }

    /// The cell's global dof indices.
    const std::vector<dealii::types::global_dof_index> &
    dof_indices() const
    {
      return dofs;
    }

    /// The quadrature points (r, z) [m].
    const std::vector<dealii::Point<2>> &
    quadrature_points() const
    {
      return points;
    }

    /// The volume 2 pi r JxW of point @p q [m^3].
    double
    volume(const unsigned int q) const
    {
      return volumes[q];
    }

  private:
    std::vector<dealii::types::global_dof_index> dofs;
    std::vector<dealii::Point<2>>                points;
    std::vector<double>                          volumes;
    std::vector<int>                             local_index;
    // rows[(4 q + c) n + i]: component c (rr, zz, theta-theta, rz) of the
    // strain of shape function i (of n) at point q.
    std::vector<double> rows;
  };
} // namespace impact_fem

#endif
