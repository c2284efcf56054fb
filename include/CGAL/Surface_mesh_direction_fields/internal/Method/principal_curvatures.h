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

// The height function over the tangent plane, a x^2 + b x y + c y^2 + d x +
// e y + f.
typedef Eigen::Matrix<double, 6, 1> Jet;

// The most points a fit uses (a two-ring has about 18; a vertex of very high
// valence keeps the nearest ones: the one-ring comes first).
constexpr int max_fit_points = 64;

// The vertex indices already taken into one two-ring: an open-addressing
// set of a few hundred slots, cleared for each vertex (a two-ring is capped
// below, so it never fills up).
class Ring_set
{
  static constexpr std::size_t slots = 256;
  std::array<std::size_t, slots> m_slot;

public:
  void clear() { m_slot.fill(no_index); }
  // true if u was not in the set (and is now)
  bool insert(std::size_t u)
  {
    for(std::size_t h = (u * 0x9E3779B97F4A7C15ull) >> 56;; h = (h + 1) % slots)
    {
      if(m_slot[h] == u) return false;
      if(m_slot[h] == no_index)
      {
        m_slot[h] = u;
        return true;
      }
    }
  }
};

// The vertices of the two-ring of v (v excluded, each once, at most
// max_fit_points - 1 of them, the one-ring first), into `ring`.
inline void two_ring(const Indexed_mesh& m, std::size_t v, std::vector<std::size_t>& ring, Ring_set& taken)
{
  ring.clear();
  taken.clear();
  taken.insert(v);
  auto add = [&](std::size_t u) {
    if(ring.size() + 1 < std::size_t(max_fit_points) && taken.insert(u)) ring.push_back(u);
  };
  auto add_neighbours = [&](std::size_t w) { m.for_each_neighbour(w, add); };
  add_neighbours(v);
  const std::size_t first_ring = ring.size();
  for(std::size_t i = 0; i < first_ring; ++i) add_neighbours(ring[i]);
}

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

// The least-squares quadric h over the plane through `origin` with the frame
// (x_axis, y_axis, normal) fitted to the heights of `points`; false if the
// points do not determine it well (all of them nearly on one line).
inline bool fit_quadric(const std::vector<Vec3>& points, const Vec3& origin, const Vec3& x_axis, const Vec3& y_axis,
                        const Vec3& normal, Jet& h)
{
  if(points.size() < 6) return false;
  // lengths divided by the neighbourhood's radius: a well-scaled system
  double scale = 0.;
  for(const Vec3& q : points) scale = (std::max)(scale, norm(q - origin));
  if(!(scale > 0.)) return false;
  // the normal equations, accumulated point by point in the lower triangle
  // (a few dozen points: plain loops beat a general matrix product here)
  Eigen::Matrix<double, 6, 6> normal_matrix = Eigen::Matrix<double, 6, 6>::Zero();
  Jet rhs = Jet::Zero();
  for(const Vec3& q : points)
  {
    const Vec3 r = (1. / scale) * (q - origin);
    const double x = dot(r, x_axis), y = dot(r, y_axis), z = dot(r, normal);
    const double row[6] = {x * x, x * y, y * y, x, y, 1.};
    for(int i = 0; i < 6; ++i)
    {
      rhs[i] += z * row[i];
      for(int j = 0; j <= i; ++j) normal_matrix(i, j) += row[i] * row[j];
    }
  }
  const Eigen::LLT<Eigen::Matrix<double, 6, 6>, Eigen::Lower> llt(normal_matrix);
  if(llt.info() != Eigen::Success) return false;
  const auto pivots = llt.matrixLLT().diagonal().array().square();  // the pivots of the elimination
  if(!(pivots.minCoeff() > 1e-9 * pivots.maxCoeff())) return false;
  h = llt.solve(rhs);
  h.head<3>() /= scale;  // back to the mesh's lengths: the quadratic terms scale by 1 / scale
  return h.allFinite();
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
    Ring_set taken;
    for(std::size_t v = begin; v < end; ++v)
    {
      if(m.fan_size(v) == 0 || !(norm(normals[v]) > 0.)) continue;
      two_ring(m, v, ring, taken);
      const Vec3 normal = area_weighted_normal(m, v);
      if(!(norm(normal) > 0.)) continue;
      const Vec3 helper = std::abs(normal[0]) < 0.9 ? Vec3{1., 0., 0.} : Vec3{0., 1., 0.};
      const Vec3 x_axis = normalized(cross(helper, normal));
      const Vec3 y_axis = cross(normal, x_axis);
      points.assign(1, m.points[v]);
      for(std::size_t u : ring) points.push_back(m.points[u]);
      Jet h;
      if(!fit_quadric(points, m.points[v], x_axis, y_axis, normal, h)) continue;
      line[v] = tangent_coefficient(m, ts, v, maximum_curvature_vector(h, x_axis, y_axis, normal), 2, normals[v]);
    }
  });
  return line;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_PRINCIPAL_CURVATURES_H
