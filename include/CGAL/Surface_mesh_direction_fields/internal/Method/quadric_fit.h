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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_QUADRIC_FIT_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_QUADRIC_FIT_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

// The local quadric fit (user manual, section "Aligned and Constrained
// Fields"): the height of the vertices of a two-ring over a vertex's tangent
// plane, fitted by least squares with a quadric. It only samples the surface,
// so it does not depend on how the triangles between the vertices are laid
// out: principal_curvatures.h takes the principal directions from it and
// folded_fans.h the normal where triangles are folded over.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The frame of the fit at v: the sum of the (area-weighted) normals of the
// faces around v and around its neighbours. Unlike angle weights, area
// weights let a needle face, whose normal is dominated by rounding, add
// (almost) nothing; the neighbours' faces keep the side right where v's own
// fan is folded over (a vertex pushed over the opposite side of a face has a
// fan whose normals nearly cancel), which decides which principal curvature
// is the larger.
inline Vec3 neighbourhood_normal(const Indexed_mesh& m, std::size_t v)
{
  Vec3 sum{0., 0., 0.};
  auto add_fan = [&](std::size_t u) {
    for(std::size_t corner : m.fan(u))
    {
      const auto& t = m.faces[corner / 3];
      sum = sum + cross(m.points[t[1]] - m.points[t[0]], m.points[t[2]] - m.points[t[0]]);
    }
  };
  add_fan(v);
  m.for_each_neighbour(v, add_fan);
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

// An orthonormal basis (x_axis, y_axis) of the plane orthogonal to the unit
// vector `normal`, with (x_axis, y_axis, normal) right-handed.
inline void tangent_axes(const Vec3& normal, Vec3& x_axis, Vec3& y_axis)
{
  const Vec3 helper = std::abs(normal[0]) < 0.9 ? Vec3{1., 0., 0.} : Vec3{0., 1., 0.};
  x_axis = normalized(cross(helper, normal));
  y_axis = cross(normal, x_axis);
}

// The buffers of the fits of one thread.
struct Fit_workspace
{
  std::vector<std::size_t> ring;
  std::vector<Vec3> points;
  Ring_set taken;
};

// The quadric fitted to the two-ring of v over the plane orthogonal to v's
// neighbourhood normal, and that frame.
struct Vertex_fit
{
  Vec3 x_axis, y_axis, normal;
  Jet h;
};

// false where v has no face, no normal, or a two-ring that does not determine
// the quadric.
inline bool fit_quadric_at(const Indexed_mesh& m, std::size_t v, Fit_workspace& work, Vertex_fit& fit)
{
  if(m.fan_size(v) == 0) return false;
  fit.normal = neighbourhood_normal(m, v);
  if(!(norm(fit.normal) > 0.)) return false;
  tangent_axes(fit.normal, fit.x_axis, fit.y_axis);
  two_ring(m, v, work.ring, work.taken);
  work.points.assign(1, m.points[v]);
  for(std::size_t u : work.ring) work.points.push_back(m.points[u]);
  return fit_quadric(work.points, m.points[v], fit.x_axis, fit.y_axis, fit.normal, fit.h);
}

// The root mean square of the fit's residual heights divided by the radius
// of the two-ring: a few thousandths where the two-ring samples a smooth
// surface finely, more where it spans a crease, a thin part or a tip whose
// surface is no graph over the frame.
inline double relative_fit_residual(const Vertex_fit& fit, const std::vector<Vec3>& points)
{
  const Vec3& origin = points.front();
  double squares = 0., radius = 0.;
  for(const Vec3& q : points)
  {
    const Vec3 r = q - origin;
    const double x = dot(r, fit.x_axis), y = dot(r, fit.y_axis);
    const double h = fit.h[0] * x * x + fit.h[1] * x * y + fit.h[2] * y * y + fit.h[3] * x + fit.h[4] * y + fit.h[5];
    squares += (dot(r, fit.normal) - h) * (dot(r, fit.normal) - h);
    radius = (std::max)(radius, norm(r));
  }
  return std::sqrt(squares / static_cast<double>(points.size())) / radius;
}

// The unit normal of the fitted surface at v: the graph z = h(x, y) has the
// normal (-h_x, -h_y, 1) at the origin.
inline Vec3 fitted_normal(const Vertex_fit& fit)
{
  return normalized(fit.normal - fit.h[3] * fit.x_axis - fit.h[4] * fit.y_axis);
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_QUADRIC_FIT_H
