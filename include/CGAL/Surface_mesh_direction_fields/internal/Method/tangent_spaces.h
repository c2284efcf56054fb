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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_TANGENT_SPACES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_TANGENT_SPACES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <complex>
#include <limits>
#include <string>
#include <vector>

// The tangent spaces (user manual, section "Tangent Spaces, Transport and
// Curvature"): corner angles and areas from the edge lengths (intrinsic, with
// mollification), the rescaling factors s_i, the rescaled angle theta of each
// halfedge from its vertex's reference direction, and each face's rescaled
// angle defect kappa_t. They do not depend on the degree n (connection.h does).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Tangent_spaces
{
  std::vector<double> angle_scale;        // s_i = 2 pi / (angle sum) inside, 1 on the boundary
  std::vector<double> corner_angle;       // Euclidean angle alpha of corner 3f+c
  std::vector<double> corner_theta;       // theta_i(i -> j) of the corner's first side, i = faces[f][c], j = faces[f][c+1]
  std::vector<double> corner_width;       // theta of the corner's second side minus corner_theta: s_i alpha, or
                                          // the signed angle in the vertex's tangent plane (folded_fans.h)
  std::vector<unsigned char> projected_fan;  // 1 where the layout is the fan projected onto the vertex's tangent
                                             // plane (folded_fans.h), 0 where it is the rescaled intrinsic one
  std::vector<double> face_area;          // |t|
  std::vector<double> face_angle_defect;  // kappa_t = sum of the rescaled corner angles - pi
  double mollification = 0.;              // the length added to every edge (0: none was needed)
};

// The squared side lengths and the scalar products of the corners of one
// face, computed when needed rather than stored (96 bytes per vertex, about
// a tenth of the memory of the whole computation besides the factor). The
// matrices need the lengths only squared, so without mollification this is a
// few products per face.
struct Face_geometry
{
  double squared_length[3];  // side c: faces[f][c] -> faces[f][c+1]
  double corner_dot[3];      // <p_ij, p_ik>: scalar product of corner c's two sides
};

inline double embedded_side_length(const Indexed_mesh& m, std::size_t f, int c)
{
  return norm(m.points[m.faces[f][(c + 1) % 3]] - m.points[m.faces[f][c]]);
}

// Areas and scalar products: from the 3D vectors when the lengths are the
// embedded ones (accurate for slivers), from the lengths when they were
// mollified (`mollification` added to each). The area is Heron's formula in
// Kahan's stable form then.
inline Face_geometry face_geometry(const Indexed_mesh& m, std::size_t f, double mollification, double* area = nullptr)
{
  Face_geometry g;
  const auto& t = m.faces[f];
  if(mollification == 0.)
  {
    for(int c = 0; c < 3; ++c)
    {
      const Vec3 first = m.points[t[(c + 1) % 3]] - m.points[t[c]];
      g.squared_length[c] = squared_norm(first);
      g.corner_dot[c] = dot(first, m.points[t[(c + 2) % 3]] - m.points[t[c]]);
    }
    if(area) *area = 0.5 * norm(cross(m.points[t[1]] - m.points[t[0]], m.points[t[2]] - m.points[t[0]]));
    return g;
  }
  double l[3];
  for(int c = 0; c < 3; ++c)
  {
    l[c] = embedded_side_length(m, f, c) + mollification;
    g.squared_length[c] = l[c] * l[c];
  }
  for(int c = 0; c < 3; ++c)
  {
    // corner c lies between its first side l[c] and the side l[c+2]; l[c+1] is opposite
    g.corner_dot[c] = 0.5 * (g.squared_length[c] + g.squared_length[(c + 2) % 3] - g.squared_length[(c + 1) % 3]);
  }
  if(area)
  {
    double x = l[0], y = l[1], z = l[2];  // sorted x >= y >= z
    if(x < y) std::swap(x, y);
    if(y < z) std::swap(y, z);
    if(x < y) std::swap(x, y);
    const double product = (x + (y + z)) * (z - (x - y)) * (z + (x - y)) * (x + (y - z));
    *area = 0.25 * std::sqrt((std::max)(0., product));
  }
  return g;
}

// The geometry is intrinsic: everything downstream of the mesh indexing uses
// edge lengths only (angles by the law of cosines, areas by Heron's formula).
// This is what makes the degenerate-triangle fix below possible.
//
// Intrinsic mollification (after Sharp and Crane, "A Laplacian for nonmanifold
// triangle meshes", 2020): with delta = relative_delta * (mean edge length),
// the smallest epsilon >= 0 is added to every edge length so that each face
// satisfies the triangle inequalities with margin delta:
//     l_a + l_b - l_c >= delta  for every corner.
// A mesh whose faces already have that margin is left exactly as it is; a
// mesh with zero-area or needle/cap faces gets a uniform, tiny change of all
// lengths (about relative_delta relative) instead of infinite cotangents.
// With relative_delta = 0 there is no mollification, and a face whose area is
// zero up to rounding (below 1e-14 times its longest edge squared) is rejected.
inline void compute_corner_angles_and_areas(const Indexed_mesh& m, Tangent_spaces& ts,
                                            double relative_delta = 0.)
{
  const std::size_t nf = m.number_of_faces();
  ts.corner_angle.resize(3 * nf);
  ts.face_area.resize(nf);

  ts.mollification = 0.;
  if(relative_delta > 0. && nf > 0)
  {
    // One pass for the total length and the smallest slack a + b - o of the
    // triangle inequalities: max(delta - slack) = delta - min(slack), also in
    // floating point (subtracting from delta is monotone).
    struct Lengths
    {
      double total, smallest_slack;
    };
    const Lengths lengths = parallel_reduce_in_order(
      nf, Lengths{0., std::numeric_limits<double>::infinity()},
      [&](std::size_t begin, std::size_t end) {
        Lengths chunk{0., std::numeric_limits<double>::infinity()};
        for(std::size_t f = begin; f < end; ++f)
        {
          if(f + prefetch_distance < end) prefetch_face_vertices(m, m.points, f + prefetch_distance);
          const double l[3] = {embedded_side_length(m, f, 0), embedded_side_length(m, f, 1),
                               embedded_side_length(m, f, 2)};
          for(int c = 0; c < 3; ++c)
          {
            chunk.total += l[c];
            chunk.smallest_slack = (std::min)(chunk.smallest_slack, l[c] + l[(c + 1) % 3] - l[(c + 2) % 3]);
          }
        }
        return chunk;
      },
      [](const Lengths& a, const Lengths& b) {
        return Lengths{a.total + b.total, (std::min)(a.smallest_slack, b.smallest_slack)};
      });
    const double delta = relative_delta * lengths.total / (3. * nf);
    ts.mollification = (std::max)(0., delta - lengths.smallest_slack);
  }

  std::vector<unsigned char> degenerate(nf, 0);
  parallel_for_each_face(m, [&](std::size_t f) {
    double area = 0.;
    const Face_geometry g = face_geometry(m, f, ts.mollification, &area);
    ts.face_area[f] = area;
    const double longest_squared = (std::max)({g.squared_length[0], g.squared_length[1], g.squared_length[2]});
    degenerate[f] = !(area > 1e-14 * longest_squared) || !std::isfinite(area);
    for(int c = 0; c < 3; ++c)
      ts.corner_angle[3 * f + c] = std::atan2(2. * area, g.corner_dot[c]);
  });
  for(std::size_t f = 0; f < nf; ++f)  // the first degenerate face, whatever the thread count
    if(degenerate[f])
      throw Invalid_input_error("face " + std::to_string(f) + " is degenerate (zero area)");
}

// The rescaled intrinsic layout of v's fan: s_v, and the angle theta of
// each corner's first side, swept counter-clockwise from the reference
// direction (the first side of the first corner) in steps of s_v alpha.
inline void lay_out_intrinsic_fan(const Indexed_mesh& m, std::size_t v, Tangent_spaces& ts)
{
  const std::size_t begin = m.fan_offsets[v], end = m.fan_offsets[v + 1];
  ts.angle_scale[v] = 1.;
  ts.projected_fan[v] = 0;
  if(begin == end) return;
  if(!m.is_border_vertex[v])
  {
    double angle_sum = 0.;
    for(std::size_t k = begin; k < end; ++k) angle_sum += ts.corner_angle[m.fan_corners[k]];
    ts.angle_scale[v] = 2. * CGAL_PI / angle_sum;
  }
  double theta = 0.;
  for(std::size_t k = begin; k < end; ++k)
  {
    const std::size_t corner = m.fan_corners[k];
    ts.corner_theta[corner] = theta;
    ts.corner_width[corner] = ts.angle_scale[v] * ts.corner_angle[corner];
    theta += ts.corner_width[corner];
  }
}

// kappa_t: the sum of the face's corner widths minus pi.
inline double face_angle_defect(const Tangent_spaces& ts, std::size_t f)
{
  return ts.corner_width[3 * f] + ts.corner_width[3 * f + 1] + ts.corner_width[3 * f + 2] - CGAL_PI;
}

inline Tangent_spaces compute_tangent_spaces(const Indexed_mesh& m, double relative_mollification = 0.)
{
  Tangent_spaces ts;
  compute_corner_angles_and_areas(m, ts, relative_mollification);

  const std::size_t nv = m.number_of_vertices();
  ts.angle_scale.assign(nv, 1.);
  ts.projected_fan.assign(nv, 0);
  ts.corner_theta.assign(3 * m.number_of_faces(), 0.);
  ts.corner_width.assign(3 * m.number_of_faces(), 0.);
  parallel_for_each_index(nv, [&](std::size_t v) { lay_out_intrinsic_fan(m, v, ts); });
  ts.face_angle_defect.resize(m.number_of_faces());
  parallel_for_each_index(m.number_of_faces(), [&](std::size_t f) { ts.face_angle_defect[f] = face_angle_defect(ts, f); });
  return ts;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_TANGENT_SPACES_H
