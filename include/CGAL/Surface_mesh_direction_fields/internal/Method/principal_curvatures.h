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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_PRINCIPAL_CURVATURES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_PRINCIPAL_CURVATURES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/guidance.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/quadric_fit.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <array>
#include <vector>

// The principal-curvature line field from a local quadric fit (user manual,
// section "Aligned and Constrained Fields"): at each vertex, the height of
// the vertices of its two-ring over the tangent plane is fitted by least
// squares with a quadric; the shape operator of the fitted surface gives the
// principal curvatures k_max >= k_min and the direction of k_max, and the
// line field's coefficient is (k_max - k_min) e^{2 i phi}, phi the rescaled
// angle of that direction at the vertex. Unlike the edge-based Hopf
// differential, whose value at a vertex depends on how the edges around it
// happen to be laid out, the fit only samples the surface: on an irregular
// triangulation of a smooth surface it stays close to the surface's own
// principal directions, which is what keeps near-pure curvature guidance free
// of spurious singularities.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The principal direction of maximum curvature at a point where the surface
// is the graph z = h(x, y) over an orthonormal frame (x_axis, y_axis,
// normal), with h = a x^2 + b x y + c y^2 + d x + e y + f fitted by least
// squares; its length is k_max - k_min (zero where the fit is degenerate).
inline Vec3 maximum_curvature_vector(const Jet& h, const Vec3& x_axis, const Vec3& y_axis, const Vec3& normal)
{
  const double a = h[0], b = h[1], c = h[2], d = h[3], e = h[4];
  // first (E, F, G) and second (L, N, P) fundamental forms of the graph at (0, 0)
  const double E = 1. + d * d, F = d * e, G = 1. + e * e;
  const double w = std::sqrt(1. + d * d + e * e);
  const double L = 2. * a / w, N = b / w, P = 2. * c / w;
  // The principal curvatures solve det(second - k first) = 0. Curvatures are
  // positive where the surface bends away from its normal (a convex edge has
  // a positive dihedral angle, as for the Hopf differential): k = -root, so
  // the maximum curvature belongs to the smaller root.
  const double quadratic = E * G - F * F, linear = L * G + P * E - 2. * N * F, constant = L * P - N * N;
  const double discriminant = std::sqrt((std::max)(0., linear * linear - 4. * quadratic * constant));
  const double root = (linear - discriminant) / (2. * quadratic);
  // its direction (x, y) in the kernel of second - root first: the longer of
  // the two rows turned by a right angle
  const double r11 = L - root * E, r12 = N - root * F, r22 = P - root * G;
  double x = r12, y = -r11;
  if(r22 * r22 + r12 * r12 > r11 * r11 + r12 * r12) { x = r22; y = -r12; }
  const Vec3 direction = x * x_axis + y * y_axis + (d * x + e * y) * normal;  // lifted onto the graph's tangent plane
  const double length = norm(direction);
  if(!(length > 0.) || !std::isfinite(discriminant)) return Vec3{0., 0., 0.};
  return (discriminant / quadratic / length) * direction;  // k_max - k_min = discriminant / quadratic
}

// The coefficient (n = 2) of the maximum-curvature line field at every vertex
// with a face: (k_max - k_min) e^{2 i phi} in the vertex's tangent space.
inline std::vector<std::complex<double> > quadric_fit_line_field(const Indexed_mesh& m, const Tangent_spaces& ts,
                                                                 const std::vector<Vec3>& normals)
{
  std::vector<std::complex<double> > line(m.number_of_vertices(), std::complex<double>(0., 0.));
  parallel_for_each_range(m.number_of_vertices(), [&](std::size_t begin, std::size_t end) {
    Fit_workspace work;
    Vertex_fit fit;
    for(std::size_t v = begin; v < end; ++v)
      if(norm(normals[v]) > 0. && fit_quadric_at(m, v, work, fit))
        line[v] = tangent_coefficient(m, ts, v, maximum_curvature_vector(fit.h, fit.x_axis, fit.y_axis, fit.normal), 2,
                                      normals[v]);
  });
  return line;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_PRINCIPAL_CURVATURES_H
