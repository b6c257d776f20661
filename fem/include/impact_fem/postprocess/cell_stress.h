#ifndef IMPACT_FEM_POSTPROCESS_CELL_STRESS_H
#define IMPACT_FEM_POSTPROCESS_CELL_STRESS_H

#include <impact_fem/cell_strain_operator.h>

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_handler.h>

#include <functional>
#include <vector>

namespace impact_fem
{
  class ImpactProblem;

  namespace postprocess
  {
    using namespace dealii;

    /**
     * The total stress (elastic with the plastic strain of the last
     * completed step, Kelvin-Voigt viscous, Maxwell arms) at the
     * quadrature points of a fixed set of locally owned cells, for the yield
     * check and the snapshots. The strain-displacement operators of the
     * cells are computed once (one FEValues pass with the higher-order
     * mapping); each evaluation is then a product with the cell's nodal
     * values, which is what makes the per-step yield check cheap.
     */
    class CellStress
    {
    public:
      using CellIterator = DoFHandler<2>::active_cell_iterator;

      /// The operators of the owned cells for which @p selected is true.
      CellStress(const ImpactProblem                             &problem,
                 const std::function<bool(const CellIterator &)> &selected);

      /// The stresses of every selected cell at its quadrature points, in
      /// the state of the problem now; @p visit(cell, points, stresses).
      void
      evaluate(
        const ImpactProblem &problem,
        const std::function<void(const CellIterator &,
                                 const std::vector<Point<2>> &,
                                 const std::vector<SymmetricTensor<2, 3>> &)>
          &visit) const;

    private:
      struct CellOperator
      {
        CellIterator       cell;
        CellStrainOperator strain;
      };
      std::vector<CellOperator> cells;
    };
  } // namespace postprocess
} // namespace impact_fem

#endif
