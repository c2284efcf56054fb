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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_POINT_SET_CONNECTION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_POINT_SET_CONNECTION_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/local_triangulations.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/local_matrices.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <cmath>
#include <complex>
#include <cstddef>
#include <vector>

// The method on the triangles of a point set (user manual, "Point Sets").
// Each point's tangent plane is the plane normal to its normal, and its
// reference direction X_i the projection of the direction to its nearest
// point (what a rigid motion or a scaling does not change). The angle
// theta_i(i -> j) of a neighbour is that of the projection of p_j - p_i onto
// the plane. From there everything is as on a mesh: the transport of a side
// depends on the side alone (so every triangle holding the side agrees), the
// curvature of a triangle is the sum of its three corner angles, measured in
// the planes of their points, minus pi, and the local matrices are the
// mesh's. A triangle counts with the weight (holders / 3): a triangle that
// all three local triangulations share counts once, as on a mesh.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Point_set_domain
{
  Indexed_mesh triangles;  // points and faces only: no fans, no twins
  std::vector<unsigned char> holders;
  std::vector<Vec3> normals, reference;  // per point: unit normal, X_i
  Tangent_spaces tangent;                // corner angles, widths, areas, curvatures
  Connection connection;
};

inline double tangent_angle(const Point_set_domain& d, std::size_t i, std::size_t j)
{
  const Vec3 e = d.triangles.points[j] - d.triangles.points[i];
  const Vec3& x = d.reference[i];
  return std::atan2(dot(e, cross(d.normals[i], x)), dot(e, x));
}

inline void set_reference_directions(Point_set_domain& d, const std::vector<std::size_t>& nearest)
{
  const std::size_t np = d.normals.size();
  d.reference.resize(np);
  parallel_for_each_index(np, [&](std::size_t i) {
    const Vec3& n = d.normals[i];
    d.reference[i] = some_orthogonal(n);
    if(nearest[i] == no_point) return;
    const Vec3 e = d.triangles.points[nearest[i]] - d.triangles.points[i];
    const Vec3 x = e - dot(e, n) * n;
    if(squared_norm(x) > 1e-24 * squared_norm(e)) d.reference[i] = normalized(x);
  });
}

// Whether a triangle seen from its three points is a triangle: each corner
// opens counter-clockwise, and the three make pi within pi / 8 (its
// curvature). A triangle that a point's plane sees folded, flat or wrapped
// around, or whose points' normals disagree that much, would add a curvature
// the surface does not have, and singularities with it (user manual, "Point
// Sets": on camelhead's vertices, 1280 singular triangles without the test,
// 38 with it, against 33 singular faces on the mesh).
inline bool is_regular_triangle(const double width[3], double total)
{
  for(int c = 0; c < 3; ++c)
    if(!(width[c] > 0.)) return false;
  return std::abs(total - CGAL_PI) < 0.125 * CGAL_PI;
}

// Corner angles and widths, areas and curvatures; a triangle whose corners
// turn clockwise in their planes (normals that disagree) is reversed, and a
// degenerate one (no area) is dropped.
inline void lay_out_triangles(Point_set_domain& d, const Local_triangles& local)
{
  Indexed_mesh& m = d.triangles;
  Tangent_spaces& ts = d.tangent;
  for(std::size_t t = 0; t < local.triangles.size(); ++t)
  {
    std::array<std::size_t, 3> v = local.triangles[t];
    double theta[3], width[3], total = 0.;
    for(int pass = 0; pass < 2; ++pass)
    {
      total = 0.;
      for(int c = 0; c < 3; ++c)
      {
        theta[c] = tangent_angle(d, v[c], v[(c + 1) % 3]);
        width[c] = reduce_angle(tangent_angle(d, v[c], v[(c + 2) % 3]) - theta[c]);
        total += width[c];
      }
      if(total > 0.) break;
      std::swap(v[1], v[2]);
    }
    const Vec3 a = m.points[v[1]] - m.points[v[0]], b = m.points[v[2]] - m.points[v[0]];
    const double area = 0.5 * norm(scaled_cross(a, b));
    const double longest = (std::max)({squared_norm(a), squared_norm(b), squared_norm(m.points[v[2]] - m.points[v[1]])});
    if(!is_regular_triangle(width, total) || !(area > 1e-12 * longest)) continue;
    m.faces.push_back({v[0], v[1], v[2]});
    d.holders.push_back(local.holders[t]);
    for(int c = 0; c < 3; ++c)
    {
      ts.corner_theta.push_back(theta[c]);
      ts.corner_width.push_back(width[c]);
    }
    ts.face_area.push_back(area);
    ts.face_angle_defect.push_back(total - CGAL_PI);
  }
}

// The transport of every side and the curvature of every triangle, degree n.
inline void compute_point_set_connection(Point_set_domain& d, int degree)
{
  const Indexed_mesh& m = d.triangles;
  Connection& con = d.connection;
  con.degree = degree;
  const double n = static_cast<double>(degree);
  const std::size_t nf = m.number_of_faces();
  con.transport.resize(3 * nf);
  con.holonomy.resize(nf);
  parallel_for_each_index(nf, [&](std::size_t f) {
    for(int c = 0; c < 3; ++c)
    {
      // computed from the side's smaller point, conjugated from the other:
      // r_ji = conj(r_ij) exactly (singularities.h needs it)
      const std::size_t i = m.faces[f][c], j = m.faces[f][(c + 1) % 3];
      const std::size_t from = (std::min)(i, j), to = (std::max)(i, j);
      const double angle = reduce_angle(tangent_angle(d, to, from) - tangent_angle(d, from, to) + CGAL_PI);
      const Complex r = std::polar(1., reduce_angle(n * angle));
      con.transport[3 * f + c] = (i < j) ? r : std::conj(r);
    }
    con.holonomy[f] = n * d.tangent.face_angle_defect[f];
  });
}

inline Point_set_domain make_point_set_domain(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                              const Local_triangles& local, int degree)
{
  Point_set_domain d;
  d.triangles.points = points;
  d.normals = normals;
  set_reference_directions(d, local.nearest);
  lay_out_triangles(d, local);
  compute_point_set_connection(d, degree);
  return d;
}

// A (energy E_s) and M of the points listed in `points` (local index
// `local_index[p]`), each triangle of `faces` weighted by holders / 3.
inline void assemble_point_set(const Point_set_domain& d, const std::vector<std::size_t>& faces,
                               const std::vector<std::size_t>& local_index, Eigen::Index size, double s,
                               Complex_sparse_matrix& A, Complex_sparse_matrix& M)
{
  std::vector<Eigen::Triplet<Complex> > energy, mass;
  energy.reserve(9 * faces.size());
  mass.reserve(9 * faces.size());
  for(std::size_t f : faces)
  {
    const Local_matrices lm = local_matrices(d.triangles, d.tangent, d.connection, f, s);
    const double w = d.holders[f] / 3.;
    const auto& t = d.triangles.faces[f];
    for(int p = 0; p < 3; ++p)
    {
      const auto i = static_cast<Eigen::Index>(local_index[t[p]]);
      const auto j = static_cast<Eigen::Index>(local_index[t[(p + 1) % 3]]);
      const auto k = static_cast<Eigen::Index>(local_index[t[(p + 2) % 3]]);
      energy.emplace_back(i, i, w * lm.energy_diagonal[p]);
      mass.emplace_back(i, i, w * lm.mass_diagonal[p]);
      energy.emplace_back(k, j, w * lm.energy_pair[p]);
      energy.emplace_back(j, k, w * std::conj(lm.energy_pair[p]));
      mass.emplace_back(k, j, w * lm.mass_pair[p]);
      mass.emplace_back(j, k, w * std::conj(lm.mass_pair[p]));
    }
  }
  A.resize(size, size);
  M.resize(size, size);
  A.setFromTriplets(energy.begin(), energy.end());
  M.setFromTriplets(mass.begin(), mass.end());
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_POINT_SET_CONNECTION_H
