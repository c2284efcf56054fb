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
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
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

// The frame of the fit at v: the sum of the (area-weighted) normals of its
// faces. Unlike angle weights, area weights let a needle face, whose normal
// is dominated by rounding, or a folded one add (almost) nothing.
inline Vec3 area_weighted_normal(const Indexed_mesh& m, std::size_t v)
{
  Vec3 sum{0., 0., 0.};
  for(std::size_t corner : m.fan(v))
  {
    const auto& t = m.faces[corner / 3];
    sum = sum + cross(m.points[t[1]] - m.points[t[0]], m.points[t[2]] - m.points[t[0]]);
  }
  return normalized(sum);
}

// The second-order part of the height function over the tangent plane,
// a x^2 + b x y + c y^2 + d x + e y + f: what the shape operator needs.
typedef Eigen::Matrix<double, 6, 1> Jet;

// The vertices of the two-ring of v (v excluded, each once), into `ring`
// (a few dozen: a linear search finds the ones already taken).
inline void two_ring(const Indexed_mesh& m, std::size_t v, std::vector<std::size_t>& ring)
{
  ring.clear();
  auto add_neighbours = [&](std::size_t w) {
    for(std::size_t corner : m.fan(w))
    {
      const auto& t = m.faces[corner / 3];
      const int c = static_cast<int>(corner % 3);
      for(std::size_t u : {std::size_t(t[(c + 1) % 3]), std::size_t(t[(c + 2) % 3])})
        if(u != v && std::find(ring.begin(), ring.end(), u) == ring.end())
          ring.push_back(u);
    }
  };
  add_neighbours(v);
  const std::size_t first_ring = ring.size();
  for(std::size_t i = 0; i < first_ring; ++i) add_neighbours(ring[i]);
}

// The principal direction of maximum curvature at a point where the surface
// is the graph z = h(x, y) over an orthonormal frame (x_axis, y_axis,
// normal), with h = a x^2 + b x y + c y^2 + d x + e y + f fitted by least
// squares; its length is k_max - k_min (zero where the fit is degenerate).
inline Vec3 maximum_curvature_vector(const Jet& h, const Vec3& x_axis, const Vec3& y_axis,
                                     const Vec3& normal)
{
  const double a = h[0], b = h[1], c = h[2], d = h[3], e = h[4];
  // first and second fundamental forms of the graph at (0, 0)
  Eigen::Matrix2d first, second;
  first << 1. + d * d, d * e, d * e, 1. + e * e;
  const double w = std::sqrt(1. + d * d + e * e);
  second << 2. * a / w, b / w, b / w, 2. * c / w;
  // the shape operator first^{-1} second is self-adjoint for `first`: solve
  // the generalized symmetric problem second x = k first x
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> solver(second, first);
  if(solver.info() != Eigen::Success) return Vec3{0., 0., 0.};
  // Curvatures are positive where the surface bends away from its normal (a
  // convex edge has a positive dihedral angle, as for the Hopf differential):
  // the negated eigenvalues, so the maximum belongs to the smallest one.
  const double k_max = -solver.eigenvalues()[0], k_min = -solver.eigenvalues()[1];
  const Eigen::Vector2d p = solver.eigenvectors().col(0);
  // the parameter direction p lifted onto the graph's tangent plane
  const Vec3 direction = p[0] * x_axis + p[1] * y_axis + (d * p[0] + e * p[1]) * normal;
  return (k_max - k_min) * normalized(direction);
}

// The least-squares fit, by a polynomial of degree 3 (Terms = 10) or 2
// (Terms = 6), of the heights of `points` over the plane through `origin`
// with the frame (x_axis, y_axis, normal); false if the points do not
// determine it well: a two-ring stretched along one direction leaves the
// cubic terms nearly free, and their values then swamp the curvature.
template <int Terms>
bool fit_height_function(const std::vector<Vec3>& points, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis,
                         const Vec3& normal, double conditioning, Jet& h)
{
  typedef Eigen::Matrix<double, Terms, 1> Row;
  if(points.size() < std::size_t(Terms)) return false;
  Eigen::Matrix<double, Terms, Terms> normal_matrix = Eigen::Matrix<double, Terms, Terms>::Zero();
  Row rhs = Row::Zero();
  // lengths divided by the neighbourhood's radius: a well-scaled system
  double scale = 0.;
  for(const Vec3& q : points) scale = (std::max)(scale, norm(q - origin));
  if(!(scale > 0.)) return false;
  for(const Vec3& q : points)
  {
    const Vec3 r = (1. / scale) * (q - origin);
    const double x = dot(r, x_axis), y = dot(r, y_axis), z = dot(r, normal);
    Row row;
    row.template head<6>() << x * x, x * y, y * y, x, y, 1.;
    if constexpr(Terms == 10) row.template tail<4>() << x * x * x, x * x * y, x * y * y, y * y * y;
    normal_matrix.noalias() += row * row.transpose();
    rhs.noalias() += z * row;
  }
  const Eigen::LDLT<Eigen::Matrix<double, Terms, Terms> > ldlt(normal_matrix);
  const auto pivots = ldlt.vectorD();
  if(ldlt.info() != Eigen::Success || !(pivots.minCoeff() > conditioning * pivots.maxCoeff())) return false;
  const Row solution = ldlt.solve(rhs);
  h = solution.template head<6>();
  h.head<3>() /= scale;  // back to the mesh's lengths: the quadratic terms scale by 1 / scale
  return h.allFinite();
}

// The jet of vertex v from its two-ring: cubic where the ring determines
// one (its curvature is then second-order accurate, also on irregular
// triangulations), quadratic otherwise.
inline bool fit_jet(const Indexed_mesh& m, std::size_t v, const std::vector<std::size_t>& ring, const Vec3& x_axis,
                    const Vec3& y_axis, const Vec3& normal, std::vector<Vec3>& points, Jet& h)
{
  points.assign(1, m.points[v]);
  for(std::size_t u : ring) points.push_back(m.points[u]);
  return fit_height_function<10>(points, m.points[v], x_axis, y_axis, normal, 1e-6, h) ||
         fit_height_function<6>(points, m.points[v], x_axis, y_axis, normal, 1e-9, h);
}

// The coefficient (n = 2) of the maximum-curvature line field at every vertex
// with a face: (k_max - k_min) e^{2 i phi} in the vertex's tangent space.
inline std::vector<std::complex<double> > quadric_fit_line_field(const Indexed_mesh& m, const Tangent_spaces& ts,
                                                                 const std::vector<Vec3>& normals)
{
  std::vector<std::complex<double> > line(m.number_of_vertices(), std::complex<double>(0., 0.));
  parallel_for_each_range(m.number_of_vertices(), [&](std::size_t begin, std::size_t end) {
    std::vector<std::size_t> ring;
    std::vector<Vec3> points;
    for(std::size_t v = begin; v < end; ++v)
    {
      if(m.fan_size(v) == 0 || !(norm(normals[v]) > 0.)) continue;
      two_ring(m, v, ring);
      const Vec3 normal = area_weighted_normal(m, v);
      if(!(norm(normal) > 0.)) continue;
      const Vec3 helper = std::abs(normal[0]) < 0.9 ? Vec3{1., 0., 0.} : Vec3{0., 1., 0.};
      const Vec3 x_axis = normalized(cross(helper, normal));
      const Vec3 y_axis = cross(normal, x_axis);
      Jet h;
      if(!fit_jet(m, v, ring, x_axis, y_axis, normal, points, h)) continue;
      line[v] = tangent_coefficient(m, ts, v, maximum_curvature_vector(h, x_axis, y_axis, normal), 2, normals[v]);
    }
  });
  return line;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_PRINCIPAL_CURVATURES_H
