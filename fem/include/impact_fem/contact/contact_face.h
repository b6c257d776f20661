#ifndef IMPACT_FEM_CONTACT_CONTACT_FACE_H
#define IMPACT_FEM_CONTACT_CONTACT_FACE_H

#include <impact_fem/as_written.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

// The faces of a contact surface gathered from all ranks: shared by the
// two-body mortar discretisation and the rigid flat (contact/).
namespace impact_fem
{
  using namespace dealii;

  namespace contact_faces
  {
    /**
     * One face of a contact surface as a 1D Lagrange element: the nodes at
     * parameters xi_i, their mapped positions x_i (so that the face geometry
     * is that of the higher-order mapping) and the global indices of the
     * vertical displacement at these nodes.
     */
    struct ContactFace
    {
      std::vector<double>                  xi;
      std::vector<Point<2>>                x;
      std::vector<types::global_dof_index> z_dofs;

      double
      shape(const unsigned int i, const double s) const
      {
        double value = 1;
        for (unsigned int m = 0; m < xi.size(); ++m)
          if (m != i)
            value *= (s - xi[m]) / (xi[i] - xi[m]);
        return value;
      }

      double
      shape_derivative(const unsigned int i, const double s) const
      {
        double sum = 0;
        for (unsigned int k = 0; k < xi.size(); ++k)
          if (k != i)
            {
              double term = 1 / (xi[i] - xi[k]);
              for (unsigned int m = 0; m < xi.size(); ++m)
                if (m != i && m != k)
                  term *= (s - xi[m]) / (xi[i] - xi[m]);
              sum += term;
            }
        return sum;
      }

      Point<2>
      position(const double s) const
      {
        Point<2> p;
        for (unsigned int i = 0; i < xi.size(); ++i)
          p += shape(i, s) * x[i];
        return p;
      }

      double
      r_min() const
      {
        return std::min(position(0)[0], position(1)[0]);
      }

      double
      r_max() const
      {
        return std::max(position(0)[0], position(1)[0]);
      }

      /// The parameter at which the face reaches radius r (Newton).
      double
      parameter_at_radius(const double r) const
      {
        const double r0 = position(0)[0], r1 = position(1)[0];
        double       s = (r - r0) / (r1 - r0);
        for (unsigned int it = 0; it < 50; ++it)
          {
            double value = -r, slope = 0;
            for (unsigned int i = 0; i < xi.size(); ++i)
              {
                value += shape(i, s) * x[i][0];
                slope += shape_derivative(i, s) * x[i][0];
              }
            const double step = value / slope;
            s -= step;
            if (std::abs(step) < 1e-15)
              break;
          }
        return std::clamp(s, 0.0, 1.0);
      }
    };


    // Flat form for the exchange between ranks: [n, xi..., r..., z..., dofs...].
    inline void
    pack(const ContactFace &face, std::vector<double> &buffer)
    {
      buffer.push_back(face.xi.size());
      for (const double s : face.xi)
        buffer.push_back(s);
      for (const auto &p : face.x)
        buffer.push_back(p[0]);
      for (const auto &p : face.x)
        buffer.push_back(p[1]);
      for (const auto dof : face.z_dofs)
        buffer.push_back(static_cast<double>(dof));
    }


    inline std::vector<ContactFace>
    unpack(const std::vector<std::vector<double>> &buffers)
    {
      std::vector<ContactFace> faces;
      for (const auto &buffer : buffers)
        for (std::size_t pos = 0; pos < buffer.size();)
          {
            const unsigned int n = static_cast<unsigned int>(buffer[pos++]);
            ContactFace        face;
            face.xi.assign(buffer.begin() + pos, buffer.begin() + pos + n);
            pos += n;
            for (unsigned int i = 0; i < n; ++i)
              face.x.emplace_back(buffer[pos + i], buffer[pos + n + i]);
            pos += 2 * n;
            for (unsigned int i = 0; i < n; ++i)
              face.z_dofs.push_back(
                static_cast<types::global_dof_index>(buffer[pos + i]));
            pos += n;
            faces.push_back(face);
          }
      // A canonical order makes B independent of the partition.
      std::sort(faces.begin(), faces.end(), [](const auto &a, const auto &b) {
        return a.r_min() < b.r_min();
      });
      return faces;
    }


    inline const ContactFace &
    face_containing(const std::vector<ContactFace> &faces, const double r)
    {
      for (const auto &face : faces)
        if (face.r_min() <= r && r <= face.r_max())
          return face;
      AssertThrow(false,
                  ExcMessage("Internal error: no contact face at radius " +
                             as_written(r)));
      return faces.front();
    }
  } // namespace contact_faces
} // namespace impact_fem

#endif
