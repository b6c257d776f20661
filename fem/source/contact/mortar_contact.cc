#include <impact_fem/contact/contact_face.h>
#include <impact_fem/contact/mortar_contact.h>
#include <impact_fem/mesh/sphere_plate_mesh.h>
#include <impact_fem/mesh/contact_surfaces.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace impact_fem
{
  using namespace contact_faces;


  void
  MortarContact::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    prm.declare_entry("Maximum active set iterations",
                      "1000",
                      Patterns::Integer(1),
                      "Limit of the active-set iterations that solve the "
                      "contact conditions of one time step [-], >= 1.");
    prm.leave_subsection();
  }


  void
  MortarContact::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    max_iterations = prm.get_integer("Maximum active set iterations");
    prm.leave_subsection();
  }


  std::map<types::global_dof_index, unsigned int>
  MortarContact::number_contact_nodes(const std::vector<ContactFace> &faces)
  {
    std::map<types::global_dof_index, double> vertex_radius;
    for (const auto &face : faces)
      for (unsigned int i = 0; i < face.xi.size(); ++i)
        if (face.xi[i] == 0 || face.xi[i] == 1)
          vertex_radius[face.z_dofs[i]] = face.x[i][0];
    std::vector<std::pair<double, types::global_dof_index>> nodes;
    for (const auto &[dof, r] : vertex_radius)
      nodes.emplace_back(r, dof);
    std::sort(nodes.begin(), nodes.end());
    std::map<types::global_dof_index, unsigned int> row_of;
    node_radius.clear();
    for (const auto &[r, dof] : nodes)
      {
        row_of[dof] = node_radius.size();
        node_radius.push_back(r);
      }
    return row_of;
  }


  namespace
  {
    /// The faces of both contact surfaces, gathered from all ranks.
    struct ContactSurfaces
    {
      std::vector<ContactFace> sphere;
      std::vector<ContactFace> plate;
    };


    // Each face as a 1D element of the vertical displacement: the nodes'
    // parameters, their mapped positions, their global dofs.
    ContactSurfaces
    gather_contact_surfaces(const DoFHandler<2>             &dof_handler,
                            const Mapping<2>                &mapping,
                            const AffineConstraints<double> &constraints)
    {
      const auto &fe = dof_handler.get_fe();

      std::map<types::global_dof_index, Point<2>> support_points;
      DoFTools::map_dofs_to_support_points(mapping,
                                           dof_handler,
                                           support_points);

      const auto &unit_points = fe.get_unit_face_support_points();
      std::vector<types::global_dof_index> face_dofs(fe.n_dofs_per_face());

      std::vector<double> sphere_buffer, plate_buffer;
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &face : cell->face_iterators())
            if (on_contact_surface(face))
              {
                face->get_dof_indices(face_dofs);
                ContactFace contact_face;
                for (unsigned int i = 0; i < face_dofs.size(); ++i)
                  if (fe.face_system_to_component_index(i).first == 1)
                    {
                      AssertThrow(!constraints.is_constrained(face_dofs[i]),
                                  ExcMessage("A contact node is constrained "
                                             "(hanging node on a contact "
                                             "surface)."));
                      contact_face.xi.push_back(unit_points[i][0]);
                      contact_face.x.push_back(support_points.at(face_dofs[i]));
                      contact_face.z_dofs.push_back(face_dofs[i]);
                    }
                pack(contact_face,
                     face->boundary_id() == boundary_ids::sphere_contact ?
                       sphere_buffer :
                       plate_buffer);
              }

      const MPI_Comm comm = dof_handler.get_communicator();
      return {unpack(Utilities::MPI::all_gather(comm, sphere_buffer)),
              unpack(Utilities::MPI::all_gather(comm, plate_buffer))};
    }


    /// The ends of the mortar segments: the face ends of both surfaces, in
    /// ascending radius; within a segment both sides are one face each.
    std::vector<double>
    segment_ends(const std::vector<ContactFace> &sphere_faces,
                 const std::vector<ContactFace> &plate_faces)
    {
      std::vector<double> breaks;
      for (const auto *faces : {&sphere_faces, &plate_faces})
        for (const auto &face : *faces)
          {
            breaks.push_back(face.r_min());
            breaks.push_back(face.r_max());
          }
      std::sort(breaks.begin(), breaks.end());
      return breaks;
    }
  } // namespace


  void
  MortarContact::setup(const DoFHandler<2>             &dof_handler,
                       const Mapping<2>                &mapping,
                       const AffineConstraints<double> &constraints,
                       const bool                       rigid_flat)
  {
    const ContactSurfaces surfaces =
      gather_contact_surfaces(dof_handler, mapping, constraints);
    if (rigid_flat)
      {
        AssertThrow(!surfaces.sphere.empty() && surfaces.plate.empty(),
                    ExcMessage("A rigid plate needs a mesh of the sphere "
                               "alone (no physical group 4), with its contact "
                               "surface (physical group 2)."));
        setup_rigid_flat(surfaces.sphere);
        return;
      }
    AssertThrow(!surfaces.sphere.empty() && !surfaces.plate.empty(),
                ExcMessage("The mesh has no sphere or no plate contact "
                           "surface (physical groups 2 and 4)."));

    // Contact nodes: the vertices of the plate's contact surface, ordered by
    // radius. The pressure is interpolated linearly between them: with
    // quadratic elements the weights of the vertex functions of the trace
    // would change sign (and vanish on the axis), and weighted gaps with
    // such weights do not keep the bodies apart.
    const std::map<types::global_dof_index, unsigned int> row_of =
      number_contact_nodes(surfaces.plate);
    // The contact surface ends where the shorter of the two ends.
    const double r_end =
      std::min(surfaces.sphere.back().r_max(), surfaces.plate.back().r_max());
    assemble_weighted_gaps(surfaces.sphere, surfaces.plate, row_of, r_end);
    setup_pointwise_gaps(surfaces.sphere, surfaces.plate, r_end);
    active.assign(n_contact_nodes(), false);
  }


  // Segment by segment, a Gauss rule in r integrates the plate's hat
  // functions times the gap between the sphere and the plate face over it.
  void
  MortarContact::assemble_weighted_gaps(
    const std::vector<ContactFace>                        &sphere_faces,
    const std::vector<ContactFace>                        &plate_faces,
    const std::map<types::global_dof_index, unsigned int> &row_of,
    const double                                           r_end)
  {
    const unsigned int n_nodes = n_contact_nodes();
    RowsUnderAssembly  rows(n_nodes);
    reference_gaps.reinit(n_nodes);
    node_area.assign(n_nodes, 0.);

    const std::vector<double> breaks = segment_ends(sphere_faces, plate_faces);
    const QGauss<1> quadrature(2 * sphere_faces.front().xi.size() + 2);
    for (unsigned int b = 0; b + 1 < breaks.size(); ++b)
      {
        const double a = breaks[b], c = std::min(breaks[b + 1], r_end);
        if (c - a <= 1e-12 * r_end)
          continue;
        const double       middle = 0.5 * (a + c);
        const ContactFace &sphere = face_containing(sphere_faces, middle);
        const ContactFace &plate  = face_containing(plate_faces, middle);
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            const double r      = a + (c - a) * quadrature.point(q)[0];
            const double weight = 2 * M_PI * r * (c - a) * quadrature.weight(q);
            const double s_sphere = sphere.parameter_at_radius(r);
            const double s_plate  = plate.parameter_at_radius(r);
            const double gap =
              sphere.position(s_sphere)[1] - plate.position(s_plate)[1];
            for (unsigned int j = 0; j < plate.xi.size(); ++j)
              if (plate.xi[j] == 0 || plate.xi[j] == 1)
                {
                  const unsigned int row = row_of.at(plate.z_dofs[j]);
                  const double       Nj =
                    (plate.xi[j] == 0 ? 1 - s_plate : s_plate) * weight;
                  reference_gaps[row] += Nj * gap;
                  node_area[row] += Nj;
                  add_face_to_row(rows, row, Nj, sphere, s_sphere, 1.);
                  add_face_to_row(rows, row, Nj, plate, s_plate, -1.);
                }
          }
      }

    store_rows(rows);
  }


  // Pointwise gaps at all nodes of both contact surfaces: the measure of
  // penetration (the constraint itself is imposed in the weighted sense).
  // Each node is paired with the point of the other surface at its radius.
  void
  MortarContact::setup_pointwise_gaps(
    const std::vector<ContactFace> &sphere_faces,
    const std::vector<ContactFace> &plate_faces,
    const double                    r_end)
  {
    point_dofs.clear();
    point_values.clear();
    point_reference_gaps.clear();
    for (const auto &plate : plate_faces)
      for (unsigned int i = 0; i < plate.xi.size(); ++i)
        if (plate.x[i][0] <= r_end)
          {
            const ContactFace &sphere =
              face_containing(sphere_faces, plate.x[i][0]);
            add_pointwise_gap(sphere,
                              sphere.parameter_at_radius(plate.x[i][0]),
                              plate,
                              plate.xi[i]);
          }
    for (const auto &sphere : sphere_faces)
      for (unsigned int i = 0; i < sphere.xi.size(); ++i)
        if (sphere.x[i][0] <= r_end)
          {
            const ContactFace &plate =
              face_containing(plate_faces, sphere.x[i][0]);
            add_pointwise_gap(sphere,
                              sphere.xi[i],
                              plate,
                              plate.parameter_at_radius(sphere.x[i][0]));
          }
  }


  void
  MortarContact::add_pointwise_gap(const ContactFace &upper,
                                   const double       s_upper,
                                   const ContactFace &lower,
                                   const double       s_lower)
  {
    std::vector<types::global_dof_index> dofs;
    std::vector<double>                  values;
    for (unsigned int k = 0; k < upper.xi.size(); ++k)
      {
        dofs.push_back(upper.z_dofs[k]);
        values.push_back(upper.shape(k, s_upper));
      }
    for (unsigned int k = 0; k < lower.xi.size(); ++k)
      {
        dofs.push_back(lower.z_dofs[k]);
        values.push_back(-lower.shape(k, s_lower));
      }
    point_dofs.push_back(dofs);
    point_values.push_back(values);
    point_reference_gaps.push_back(upper.position(s_upper)[1] -
                                   lower.position(s_lower)[1]);
  }


  void
  MortarContact::compute_influence(
    const std::function<void(TrilinosWrappers::MPI::Vector &,
                             const TrilinosWrappers::MPI::Vector &)> &solve,
    const IndexSet &locally_owned_dofs,
    const MPI_Comm  comm)
  {
    owned                = locally_owned_dofs;
    communicator         = comm;
    const unsigned int n = n_contact_nodes();
    influence.resize(n);
    TrilinosWrappers::MPI::Vector load(owned, comm);
    for (unsigned int j = 0; j < n; ++j)
      {
        load = 0;
        for (unsigned int k = 0; k < row_dofs[j].size(); ++k)
          if (owned.is_element(row_dofs[j][k]))
            load[row_dofs[j][k]] = row_values[j][k];
        load.compress(VectorOperation::insert);
        influence[j].reinit(owned, comm);
        solve(influence[j], load);
      }

    // G_ij = B_i . W_j, summed over the owned entries of every rank.
    std::vector<double> local(n * n, 0.);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int k = 0; k < row_dofs[i].size(); ++k)
        if (owned.is_element(row_dofs[i][k]))
          for (unsigned int j = 0; j < n; ++j)
            local[i * n + j] += row_values[i][k] * influence[j][row_dofs[i][k]];
    std::vector<double> global(n * n);
    MPI_Allreduce(
      local.data(), global.data(), n * n, MPI_DOUBLE, MPI_SUM, comm);
    delassus.reinit(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        delassus(i, j) = 0.5 * (global[i * n + j] + global[j * n + i]);
  }


  Vector<double>
  MortarContact::weighted_gaps(
    const TrilinosWrappers::MPI::Vector &displacement) const
  {
    const unsigned int  n = n_contact_nodes();
    std::vector<double> local(n, 0.);
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int k = 0; k < row_dofs[j].size(); ++k)
        if (owned.is_element(row_dofs[j][k]))
          local[j] += row_values[j][k] * displacement[row_dofs[j][k]];
    std::vector<double> global(n);
    MPI_Allreduce(
      local.data(), global.data(), n, MPI_DOUBLE, MPI_SUM, communicator);
    Vector<double> gaps(reference_gaps);
    for (unsigned int j = 0; j < n; ++j)
      gaps[j] += global[j];
    return gaps;
  }


  Vector<double>
  MortarContact::solve_complementarity(const Vector<double> &free_gaps)
  {
    // Convex QP  min 1/2 l.G l + l.g_free, l >= 0, by a primal active-set
    // method (Lawson-Hanson): exact in finitely many steps, warm-started
    // with the previous step's contact set.
    const unsigned int n = n_contact_nodes();
    Vector<double>     lambda(n);
    const double tolerance = 1e-12 * std::max(free_gaps.linfty_norm(), 1e-300);

    auto gaps_of = [&](const Vector<double> &l) {
      Vector<double> g(free_gaps);
      delassus.vmult_add(g, l);
      return g;
    };
    // Solve G_PP z_P = -g_free_P on the passive (loaded) set P.
    auto solve_on = [&](const std::vector<bool> &passive) {
      std::vector<unsigned int> index;
      for (unsigned int j = 0; j < n; ++j)
        if (passive[j])
          index.push_back(j);
      Vector<double> z(n);
      if (index.empty())
        return z;
      FullMatrix<double> G(index.size(), index.size());
      Vector<double>     rhs(index.size()), solution(index.size());
      for (unsigned int a = 0; a < index.size(); ++a)
        {
          rhs[a] = -free_gaps[index[a]];
          for (unsigned int b = 0; b < index.size(); ++b)
            G(a, b) = delassus(index[a], index[b]);
        }
      G.gauss_jordan();
      G.vmult(solution, rhs);
      for (unsigned int a = 0; a < index.size(); ++a)
        z[index[a]] = solution[a];
      return z;
    };

    std::vector<bool> passive   = active;
    unsigned int      iteration = 0;
    // Inner loop: from a feasible lambda, move towards the unconstrained
    // solution on P, dropping nodes whose pressure would turn negative.
    auto restore_feasibility = [&]() {
      while (true)
        {
          AssertThrow(++iteration <= max_iterations,
                      ExcMessage("The contact active-set iteration did not "
                                 "converge in Contact/Maximum active set "
                                 "iterations = " +
                                 std::to_string(max_iterations) + "."));
          const Vector<double> z    = solve_on(passive);
          double               step = 1;
          for (unsigned int j = 0; j < n; ++j)
            if (passive[j] && z[j] <= 0)
              {
                const double distance = lambda[j] - z[j];
                step = std::min(step, distance > 0 ? lambda[j] / distance : 0.);
              }
          for (unsigned int j = 0; j < n; ++j)
            lambda[j] += step * (z[j] - lambda[j]);
          if (step == 1)
            return;
          // Nodes blocked at zero pressure leave P.
          const double zero = 1e-14 * lambda.linfty_norm();
          for (unsigned int j = 0; j < n; ++j)
            if (passive[j] && z[j] <= 0 && lambda[j] <= zero)
              {
                passive[j] = false;
                lambda[j]  = 0;
              }
        }
    };

    restore_feasibility();
    while (true)
      {
        const Vector<double> g = gaps_of(lambda);
        // The most violated constraint outside P enters.
        unsigned int entering  = n;
        double       violation = tolerance;
        for (unsigned int j = 0; j < n; ++j)
          if (!passive[j] && -g[j] > violation)
            {
              violation = -g[j];
              entering  = j;
            }
        if (entering == n)
          break;
        passive[entering] = true;
        restore_feasibility();
      }

    for (unsigned int j = 0; j < n; ++j)
      active[j] = lambda[j] > 0;

    for (unsigned int j = 0; j < n; ++j)
      lambda[j] = std::max(lambda[j], 0.);
    return lambda;
  }


  void
  MortarContact::add_contact_response(
    const Vector<double>          &pressures,
    TrilinosWrappers::MPI::Vector &displacement) const
  {
    for (unsigned int j = 0; j < n_contact_nodes(); ++j)
      if (pressures[j] != 0)
        displacement.add(pressures[j], influence[j]);
  }


  void
  MortarContact::add_contact_forces(const Vector<double>          &pressures,
                                    TrilinosWrappers::MPI::Vector &forces) const
  {
    for (unsigned int j = 0; j < n_contact_nodes(); ++j)
      if (pressures[j] != 0)
        for (unsigned int k = 0; k < row_dofs[j].size(); ++k)
          if (owned.is_element(row_dofs[j][k]))
            forces[row_dofs[j][k]] += pressures[j] * row_values[j][k];
    forces.compress(VectorOperation::add);
  }


  double
  MortarContact::penetration(
    const TrilinosWrappers::MPI::Vector &displacement) const
  {
    const unsigned int  n = point_dofs.size();
    std::vector<double> local(n, 0.), global(n);
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int k = 0; k < point_dofs[j].size(); ++k)
        if (owned.is_element(point_dofs[j][k]))
          local[j] += point_values[j][k] * displacement[point_dofs[j][k]];
    MPI_Allreduce(
      local.data(), global.data(), n, MPI_DOUBLE, MPI_SUM, communicator);
    double deepest = 0;
    for (unsigned int j = 0; j < n; ++j)
      deepest = std::max(deepest, -(point_reference_gaps[j] + global[j]));
    return deepest;
  }


  double
  MortarContact::total_force(const Vector<double> &pressures) const
  {
    double force = 0;
    for (unsigned int j = 0; j < n_contact_nodes(); ++j)
      force += pressures[j] * node_area[j];
    return force;
  }


  double
  MortarContact::contact_radius(const Vector<double> &pressures) const
  {
    // The edge lies between the outermost loaded node and the next one.
    // Within that interval it is placed where p^2, linear in r^2 for the
    // Hertz profile p0^2 (1 - r^2/a^2), extrapolated from the two outermost
    // loaded nodes, vanishes.
    const unsigned int n    = n_contact_nodes();
    unsigned int       last = n;
    for (unsigned int j = 0; j < n; ++j)
      if (pressures[j] > 0)
        last = j;
    if (last == n)
      return 0;
    if (last == 0 || last + 1 == n || !(pressures[last - 1] > pressures[last]))
      return node_radius[last];
    const double r1 = node_radius[last - 1], r2 = node_radius[last];
    const double q1           = pressures[last - 1] * pressures[last - 1],
                 q2           = pressures[last] * pressures[last];
    const double edge_squared = r2 * r2 + q2 * (r2 * r2 - r1 * r1) / (q1 - q2);
    return std::clamp(std::sqrt(edge_squared), r2, node_radius[last + 1]);
  }


  void
  MortarContact::add_face_to_row(RowsUnderAssembly                &rows,
                                 const unsigned int                row,
                                 const double                      hat,
                                 const contact_faces::ContactFace &face,
                                 const double                      s,
                                 const double                      sign)
  {
    for (unsigned int k = 0; k < face.xi.size(); ++k)
      rows[row][face.z_dofs[k]] += sign * hat * face.shape(k, s);
  }


  void
  MortarContact::store_rows(const RowsUnderAssembly &rows)
  {
    row_dofs.assign(rows.size(), {});
    row_values.assign(rows.size(), {});
    for (unsigned int j = 0; j < rows.size(); ++j)
      for (const auto &[dof, value] : rows[j])
        {
          row_dofs[j].push_back(dof);
          row_values[j].push_back(value);
        }
  }


  void
  MortarContact::save(checkpoint::Writer &writer) const
  {
    writer &active;
  }


  void
  MortarContact::load(checkpoint::Reader &reader)
  {
    std::vector<bool> saved;
    reader           &saved;
    AssertThrow(saved.size() == active.size(),
                ExcMessage("The checkpoint's contact nodes do not fit the "
                           "run's."));
    active = saved;
  }
} // namespace impact_fem
