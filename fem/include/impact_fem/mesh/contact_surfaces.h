#ifndef IMPACT_FEM_MESH_CONTACT_SURFACES_H
#define IMPACT_FEM_MESH_CONTACT_SURFACES_H

#include <impact_fem/mesh/sphere_plate_mesh.h>

namespace impact_fem
{
  /// Whether @p face lies on a contact surface, the sphere's or the
  /// plate's: the faces the mortar contact conditions are built on, and the
  /// ones Mesh/Contact surface refinements refines (so that the refined
  /// cells are exactly those that carry contact nodes).
  template <typename FaceIterator>
  bool
  on_contact_surface(const FaceIterator &face)
  {
    return face->at_boundary() &&
           (face->boundary_id() == boundary_ids::sphere_contact ||
            face->boundary_id() == boundary_ids::plate_contact);
  }
} // namespace impact_fem

#endif
