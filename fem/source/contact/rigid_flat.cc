#include <impact_fem/contact/contact_face.h>
#include <impact_fem/contact/mortar_contact.h>

#include <deal.II/base/quadrature_lib.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace impact_fem
{
  using namespace contact_faces;

  // The sphere against the fixed rigid plane z = 0: the sphere's contact
  // surface is the non-mortar side (the flat has no degrees of freedom), the
  // multipliers are the pressures at its vertices, interpolated linearly in
  // the radius, and the gap of a sphere point is its height z + u_z.
  void
  MortarContact::setup_rigid_flat(const std::vector<ContactFace> &sphere_faces)
  {
    // Contact nodes: the vertices of the sphere's contact faces by radius.
    const std::map<types::global_dof_index, unsigned int> row_of =
      number_contact_nodes(sphere_faces);
    const unsigned int n_nodes = node_radius.size();

    RowsUnderAssembly rows(n_nodes);
    reference_gaps.reinit(n_nodes);
    node_area.assign(n_nodes, 0.);

    // Each face is one segment [r_min, r_max] of the flat; a Gauss rule in
    // r integrates the hat functions times the face's shape functions.
    const QGauss<1> quadrature(2 * sphere_faces.front().xi.size() + 2);
    for (const auto &face : sphere_faces)
      {
        std::vector<unsigned int> ends;
        for (unsigned int i = 0; i < face.xi.size(); ++i)
          if (face.xi[i] == 0 || face.xi[i] == 1)
            ends.push_back(i);
        AssertThrow(ends.size() == 2,
                    ExcMessage("Internal error: a contact face without two "
                               "vertices."));
        const double a = face.r_min(), c = face.r_max();
        for (unsigned int q = 0; q < quadrature.size(); ++q)
          {
            const double r      = a + (c - a) * quadrature.point(q)[0];
            const double weight = 2 * M_PI * r * (c - a) * quadrature.weight(q);
            const double s      = face.parameter_at_radius(r);
            const double height = face.position(s)[1];
            for (unsigned int e = 0; e < 2; ++e)
              {
                const unsigned int j = ends[e], other = ends[1 - e];
                const double       Nj = (r - face.x[other][0]) /
                                  (face.x[j][0] - face.x[other][0]) * weight;
                const unsigned int row = row_of.at(face.z_dofs[j]);
                reference_gaps[row] += Nj * height;
                node_area[row] += Nj;
                add_face_to_row(rows, row, Nj, face, s, 1.);
              }
          }
      }

    store_rows(rows);

    // Pointwise gaps: the height of every node of the contact surface.
    point_dofs.clear();
    point_values.clear();
    point_reference_gaps.clear();
    for (const auto &face : sphere_faces)
      for (unsigned int i = 0; i < face.xi.size(); ++i)
        {
          point_dofs.push_back({face.z_dofs[i]});
          point_values.push_back({1.});
          point_reference_gaps.push_back(face.x[i][1]);
        }
    active.assign(n_nodes, false);
  }
} // namespace impact_fem
