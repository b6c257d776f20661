#ifndef IMPACT_FEM_CONTACT_MORTAR_CONTACT_H
#define IMPACT_FEM_CONTACT_MORTAR_CONTACT_H

#include <impact_fem/output/checkpoint.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <map>
#include <vector>

namespace impact_fem
{
  using namespace dealii;

  /**
   * Frictionless sphere-plate contact with Lagrange multipliers.
   *
   * Discretisation (mortar, plate = non-mortar side): the contact pressure
   * on the plate's contact surface is p(r) = sum_j lambda_j N_j(r), with N_j
   * the piecewise linear hat functions of the vertices of the plate's
   * contact surface (lambda_j is the pressure at vertex j). Linear, not the
   * quadratic traces: quadratic vertex functions change sign, and their
   * weight 2 pi int N_j r dr vanishes on the axis, which makes the weighted
   * gaps below meaningless. Non-penetration holds in the weighted sense
   *   g_j = int N_j(r) [ z_sphere(r) + u_z^sphere - z_plate(r) - u_z^plate ] 2 pi r dr >= 0,
   *   lambda_j >= 0,  lambda_j g_j = 0,
   * the sphere point paired with a plate point being the one at the same
   * radius (small sliding; with equal materials there is no relative slip).
   * In matrix form g = g_0 + B u and the contact force vector is B^T lambda.
   *
   * Time stepping is linear apart from contact, so the effective stiffness
   * K_eff of the step is constant. With the influence vectors
   * W = K_eff^{-1} B^T (one solve per contact node, once) and the dense
   * Delassus matrix G = B W, each step reduces to a small linear
   * complementarity problem for lambda, solved exactly by an active-set
   * method: the constraint is satisfied to round-off, no penalty parameter.
   *
   * Rigid flat (Plate/Material model = rigid): the plate is the fixed plane
   * z = 0 and only the sphere is meshed. The multipliers then live on the
   * sphere's contact surface: lambda_j is the pressure at the j-th vertex
   * of the sphere's contact faces, interpolated by hat functions N_j(r)
   * linear in the radius (the flat's coordinate), and
   *   g_j = int N_j(r) [ z_sphere(r) + u_z^sphere(r) ] 2 pi r dr >= 0.
   * Everything after setup (influence, Delassus matrix, active set,
   * force, contact radius) is the same.
   */
  namespace contact_faces
  {
    struct ContactFace;
  }

  class MortarContact
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm);

    /// Build B and g_0 from the contact faces of all ranks: sphere and
    /// plate, or (rigid_flat) the sphere and the plane z = 0.
    void
    setup(const DoFHandler<2>             &dof_handler,
          const Mapping<2>                &mapping,
          const AffineConstraints<double> &constraints,
          const bool                       rigid_flat = false);

    /**
     * Compute W = K_eff^{-1} B^T and G = B W; @p solve applies K_eff^{-1}.
     */
    void
    compute_influence(
      const std::function<void(TrilinosWrappers::MPI::Vector &,
                               const TrilinosWrappers::MPI::Vector &)> &solve,
      const IndexSet &locally_owned_dofs,
      const MPI_Comm  comm);

    /// Weighted gaps g_0 + B u [m^3] (identical on all ranks).
    Vector<double>
    weighted_gaps(const TrilinosWrappers::MPI::Vector &displacement) const;

    /**
     * Contact pressures at the nodes [Pa] that make the gaps
     * free_gaps + G lambda complementary to lambda. Throws when the
     * active-set iteration does not converge.
     */
    Vector<double>
    solve_complementarity(const Vector<double> &free_gaps);

    /// u += W lambda.
    void
    add_contact_response(const Vector<double>          &pressures,
                         TrilinosWrappers::MPI::Vector &displacement) const;

    /// f += B^T lambda (owned entries).
    void
    add_contact_forces(const Vector<double>          &pressures,
                       TrilinosWrappers::MPI::Vector &forces) const;

    /// Total normal force 2 pi int p r dr [N].
    double
    total_force(const Vector<double> &pressures) const;

    /**
     * Contact radius [m] (0 if no contact): between the outermost node
     * carrying pressure and the next node, where the Hertz-shaped
     * extrapolation of the two outermost nodal pressures (p^2 linear in
     * r^2) vanishes.
     */
    double
    contact_radius(const Vector<double> &pressures) const;

    unsigned int
    n_contact_nodes() const
    {
      return node_radius.size();
    }

    /// Radius of each contact node [m], ascending (vertices of the plate's
    /// contact surface; of the sphere's on a rigid flat).
    const std::vector<double> &
    node_radii() const
    {
      return node_radius;
    }

    /**
     * Deepest penetration [m]: the largest negative pointwise gap at the
     * nodes of both contact surfaces (of the sphere's on a rigid flat; 0 if
     * none).
     */
    double
    penetration(const TrilinosWrappers::MPI::Vector &displacement) const;

    /// The active set the next solve starts from, for a checkpoint.
    void
    save(checkpoint::Writer &writer) const;
    /// Reads what save() wrote (the same contact nodes).
    void
    load(checkpoint::Reader &reader);

  private:
    /// B, g_0 and the pointwise gaps of the rigid flat (rigid_flat.cc).
    void
    setup_rigid_flat(
      const std::vector<contact_faces::ContactFace> &sphere_faces);

    /// The contact nodes: the vertices of the non-mortar side's faces,
    /// ordered by radius into node_radius; returns each node's row of B by
    /// the global index of its vertical displacement.
    std::map<types::global_dof_index, unsigned int>
    number_contact_nodes(const std::vector<contact_faces::ContactFace> &faces);

    /// B, g_0 and the nodes' areas of the two-body mortar discretisation,
    /// up to the radius @p r_end where the shorter surface ends.
    void
    assemble_weighted_gaps(
      const std::vector<contact_faces::ContactFace>         &sphere_faces,
      const std::vector<contact_faces::ContactFace>         &plate_faces,
      const std::map<types::global_dof_index, unsigned int> &row_of,
      const double                                           r_end);

    /// The pointwise gaps at the nodes of both surfaces within @p r_end.
    void
    setup_pointwise_gaps(
      const std::vector<contact_faces::ContactFace> &sphere_faces,
      const std::vector<contact_faces::ContactFace> &plate_faces,
      const double                                   r_end);

    /// The gap between @p upper at its parameter @p s_upper and @p lower
    /// at @p s_lower joins the pointwise gaps.
    void
    add_pointwise_gap(const contact_faces::ContactFace &upper,
                      const double                      s_upper,
                      const contact_faces::ContactFace &lower,
                      const double                      s_lower);

    /// Sparse rows of B while they are assembled, by global dof index.
    using RowsUnderAssembly =
      std::vector<std::map<types::global_dof_index, double>>;

    /// Row @p row of B gains @p sign times the hat weight @p hat (the
    /// row's hat function times the area element at a point of the contact
    /// surface) times the vertical displacement of @p face at its parameter
    /// @p s: sign +1 for the upper (sphere) side, -1 for the lower side.
    static void
    add_face_to_row(RowsUnderAssembly                &rows,
                    const unsigned int                row,
                    const double                      hat,
                    const contact_faces::ContactFace &face,
                    const double                      s,
                    const double                      sign);

    /// row_dofs and row_values from the assembled rows.
    void
    store_rows(const RowsUnderAssembly &rows);

    unsigned int max_iterations = 1000;

    // Sparse rows of B: global dof indices and values.
    std::vector<std::vector<types::global_dof_index>> row_dofs;
    std::vector<std::vector<double>>                  row_values;
    Vector<double>                                    reference_gaps;
    std::vector<double>                               node_radius;
    std::vector<double>                               node_area;

    // Pointwise gaps at the nodes: rows and reference values.
    std::vector<std::vector<types::global_dof_index>> point_dofs;
    std::vector<std::vector<double>>                  point_values;
    std::vector<double>                               point_reference_gaps;

    std::vector<TrilinosWrappers::MPI::Vector> influence;
    FullMatrix<double>                         delassus;
    IndexSet                                   owned;
    MPI_Comm                                   communicator = MPI_COMM_SELF;
    std::vector<bool>                          active; // warm start
  };
} // namespace impact_fem

#endif
