// Copyright (c) 2026  The Surface_mesh_direction_fields authors.
// All rights reserved.
//
// This file is part of CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s)     : The Surface_mesh_direction_fields authors

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_EXTRINSIC_DIRECTIONS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_EXTRINSIC_DIRECTIONS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/folded_fans.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vertex_normals.h>

#include <cmath>
#include <complex>
#include <vector>

// Back to 3D (user manual, section "Back to 3D Directions"): the coefficient u_i (n-th power, rescaled
// angles from X_i) becomes a unit vector orthogonal to the vertex normal.
//
// 1. phi = arg(u_i) / n, taken in [0, 2 pi / n), is a rescaled angle from X_i;
//    the other n - 1 directions are the rotations of the result by 2 pi k / n
//    about the normal (documented convention; guidance.h inverts it exactly).
// 2. The fan of corners covers the rescaled angles [0, s_i * angle sum); the
//    corner containing phi is found and the vector is laid out in that face's
//    plane, at the Euclidean angle (phi - theta_corner) / s_i from the corner's
//    first side. At a boundary vertex whose corners do not reach phi, the
//    vector is laid out in the plane of the nearest end face, beyond its edge.
// 3. The in-face vector is projected onto the plane orthogonal to the vertex
//    normal and normalized.
// Vertex normals are the angle-weighted means of the face normals unless the
// user gives them.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The package's vertex normals (vertex_normals.h) over the mesh's fans, with
// the (possibly mollified) corner angles of the tangent spaces.
inline std::vector<Vec3> angle_weighted_vertex_normals(const Indexed_mesh& m, const Tangent_spaces& ts)
{
  return angle_weighted_vertex_normals(m.points, m.faces, [&m](std::size_t v) { return m.fan(v); },
                                       [&ts](std::size_t corner) { return ts.corner_angle[corner]; });
}

// Unit vector in the plane of corner `corner`, at Euclidean angle `psi` from
// its first side, turning towards its second side. In a face that is
// degenerate in 3D (its sides parallel or of zero length: only possible with
// mollification), the turn is taken about the vertex normal instead.
inline Vec3 vector_in_corner(const Indexed_mesh& m, std::size_t corner, double psi, const Vec3& normal)
{
  const auto& t = m.faces[corner / 3];
  const int c = static_cast<int>(corner % 3);
  const Vec3& p = m.points[t[c]];
  const Vec3 e1 = m.points[t[(c + 1) % 3]] - p;
  const Vec3 e2 = m.points[t[(c + 2) % 3]] - p;
  Vec3 x = normalized(e1);
  if(norm(x) == 0.) x = normalized(e2);
  Vec3 y = e2 - dot(e2, x) * x;
  if(!(norm(y) > 1e-12 * norm(e2)))
    y = cross(normal, x);
  y = normalized(y);
  return std::cos(psi) * x + std::sin(psi) * y;
}

inline Vec3 tangent_direction(const Indexed_mesh& m, const Tangent_spaces& ts, std::size_t v,
                              std::complex<double> u, int degree, const Vec3& normal)
{
  const double two_pi = 2. * CGAL_PI;
  const std::size_t begin = m.fan_offsets[v], end = m.fan_offsets[v + 1];
  if(begin == end)
    return Vec3{0., 0., 0.};  // isolated vertex
  // the root in the first sector [0, 2 pi / n) from the reference direction
  double phi = std::arg(u) / degree;
  if(phi < 0.) phi += two_pi / degree;
  const double s = ts.angle_scale[v];

  Vec3 w{0., 0., 0.};
  bool placed = false;
  Projected_frame frame;
  if(ts.projected_fan[v] && projected_frame(m, v, normal, frame))
  {
    // the projected layout (folded_fans.h): a rotation about the normal
    w = std::cos(phi) * frame.x + std::sin(phi) * frame.y;
    placed = true;
  }
  for(std::size_t k = begin; k < end && !placed; ++k)
  {
    const std::size_t corner = m.fan_corners[k];
    const double theta0 = ts.corner_theta[corner];
    const double width = ts.corner_width[corner];  // s * alpha
    if(phi < theta0 + width || k + 1 == end)
    {
      if(phi >= theta0 + width && m.is_border_vertex[v])
      {
        // Beyond the last corner of a boundary fan: use the nearer end face.
        const double past_end = phi - (theta0 + width);
        const double before_start = two_pi - phi;
        if(before_start < past_end)
          w = vector_in_corner(m, m.fan_corners[begin], -before_start, normal);
        else
          w = vector_in_corner(m, corner, ts.corner_angle[corner] + past_end, normal);
      }
      else
        w = vector_in_corner(m, corner, (phi - theta0) / s, normal);
      placed = true;
    }
  }

  Vec3 projected = w - dot(w, normal) * normal;
  if(!(norm(projected) > 1e-8))
  {
    // The in-face vector is (nearly) parallel to the normal: fall back to the
    // projected sides of the fan, the first one that is not.
    for(std::size_t k = begin; k < end && !(norm(projected) > 1e-8); ++k)
    {
      const std::size_t corner = m.fan_corners[k];
      const Vec3 e = normalized(m.points[m.faces[corner / 3][(corner % 3 + 1) % 3]] - m.points[v]);
      projected = e - dot(e, normal) * normal;
    }
    if(!(norm(projected) > 1e-8))
    {
      // every side is parallel to the normal (or of zero length): any tangent vector
      const Vec3 axis = std::abs(normal[0]) < 0.9 ? Vec3{1., 0., 0.} : Vec3{0., 1., 0.};
      projected = cross(normal, axis);
      if(!(norm(projected) > 0.)) projected = axis;  // no normal at all
    }
  }
  return normalized(projected);
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_EXTRINSIC_DIRECTIONS_H
