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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_GUIDANCE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_GUIDANCE_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/factored_matrix.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/linear_solves.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/assembly.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/extrinsic_directions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/folded_fans.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <cmath>
#include <complex>
#include <vector>

// Guidance fields, as coefficient vectors in the n-th power representation
// (user manual, section "Aligned and Constrained Fields"):
//  * the pairing vector of the discrete Hopf differential (principal curvature);
//  * a 3D tangent vector per vertex (user guidance), mapped to coefficients by
//    the exact inverse of the layout of extrinsic_directions.h;
//  * the directions tangent or normal to the boundary at boundary vertices.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Signed dihedral angle of the side of corner 3f+c: the angle between the
// normals of its two faces, positive on a convex edge; 0 on the border.
inline double dihedral_angle(const Indexed_mesh& m, std::size_t corner)
{
  const std::size_t twin = m.twin_corner[corner];
  if(twin == no_index) return 0.;
  auto face_normal = [&](std::size_t f) {
    const auto& t = m.faces[f];
    return normalized(cross(m.points[t[1]] - m.points[t[0]], m.points[t[2]] - m.points[t[0]]));
  };
  const Vec3 n1 = face_normal(corner / 3), n2 = face_normal(twin / 3);
  const Vec3 e = normalized(m.points[m.faces[corner / 3][(corner % 3 + 1) % 3]] - m.points[m.vertex_of_corner(corner)]);
  return std::atan2(dot(cross(n1, n2), e), dot(n1, n2));
}

// The pairing of the Hopf differential with the basis sections of a line field
// (n = 2): q~_i = -1/4 sum over the edges e at i of exp(2 i theta_i(e)) beta_e |e|.
// Each edge at i is the first side of exactly one corner at i, except a border
// edge, whose dihedral angle is zero anyway.
inline std::vector<std::complex<double> > hopf_differential_pairing(const Indexed_mesh& m, const Tangent_spaces& ts)
{
  std::vector<std::complex<double> > q(m.number_of_vertices(), std::complex<double>(0., 0.));
  for(std::size_t corner = 0; corner < 3 * m.number_of_faces(); ++corner)
  {
    const double beta = dihedral_angle(m, corner);
    if(beta == 0.) continue;
    const double length = std::sqrt(face_geometry(m, corner / 3, ts.mollification).squared_length[corner % 3]);
    q[m.vertex_of_corner(corner)] += -0.25 * beta * length * std::polar(1., 2. * ts.corner_theta[corner]);
  }
  return q;
}

// The principal-curvature line field (n = 2) of every component: the Hopf
// differential's coefficients q solve M_2 q = q~, with q~ its pairing above
// and M_2 the mass matrix of the degree-2 connection (user manual,
// section "Aligned and Constrained Fields").
template <typename SparseSolver>
std::vector<std::complex<double> > curvature_line_field(const Indexed_mesh& mesh, const Tangent_spaces& ts,
                                                        const Components& components, SparseSolver& solver)
{
  const std::vector<Complex> pairing = hopf_differential_pairing(mesh, ts);
  const Connection line_connection = compute_connection(mesh, ts, 2);
  std::vector<Complex> line(mesh.number_of_vertices(), Complex(0., 0.));
  const std::vector<Energy_and_mass> line_matrices = assemble_energy_and_mass(mesh, ts, line_connection, components, 0.);
  for(std::size_t c = 0; c < components.list.size(); ++c)
  {
    const Component& comp = components.list[c];
    const Energy_and_mass& em = line_matrices[c];
    Complex_vector rhs(static_cast<Eigen::Index>(comp.vertices.size()));
    for(std::size_t i = 0; i < comp.vertices.size(); ++i) rhs[static_cast<Eigen::Index>(i)] = pairing[comp.vertices[i]];
    Factored_matrix<SparseSolver> factored(solver);
    const Complex_vector solution = solve_shifted_system(em.mass, em.mass, 0., rhs, Constraints(), factored);
    for(std::size_t i = 0; i < comp.vertices.size(); ++i) line[comp.vertices[i]] = solution[static_cast<Eigen::Index>(i)];
  }
  return line;
}

// The rescaled angle phi whose layout by tangent_direction() has the direction
// of w (a nonzero tangent vector, orthogonal to the normal), and whether an
// exact preimage exists (otherwise the nearest corner side is used).
inline double rescaled_angle_of(const Indexed_mesh& m, const Tangent_spaces& ts, std::size_t v, const Vec3& w,
                                const Vec3& normal, double& error_out)
{
  Projected_frame frame;
  if(ts.projected_fan[v] && projected_frame(m, v, normal, frame))
  {
    // the projected layout (folded_fans.h): the angle of w about the normal
    error_out = 0.;
    const double phi = std::atan2(dot(w, frame.y), dot(w, frame.x));
    return phi < 0. ? phi + 2. * CGAL_PI : phi;
  }
  const Vec3 plane_normal = cross(w, normal);  // the vectors projecting onto the line of w lie in span(w, N)
  double best_phi = 0., best_error = 1e300;
  for(std::size_t k = m.fan_offsets[v]; k < m.fan_offsets[v + 1]; ++k)
  {
    const std::size_t corner = m.fan_corners[k];
    const auto& t = m.faces[corner / 3];
    const int c = static_cast<int>(corner % 3);
    const Vec3& p = m.points[t[c]];
    const Vec3 e1 = m.points[t[(c + 1) % 3]] - p, e2 = m.points[t[(c + 2) % 3]] - p;
    Vec3 d = cross(cross(e1, e2), plane_normal);  // in the face's plane and in span(w, N)
    if(!(norm(d) > 0.)) continue;
    if(dot(d, w) < 0.) d = -1. * d;
    const Vec3 x = normalized(e1);
    const Vec3 y = normalized(e2 - dot(e2, x) * x);
    const double psi = std::atan2(dot(d, y), dot(d, x));
    const double width = ts.corner_angle[corner];
    const double error = psi < 0. ? -psi : (psi > width ? psi - width : 0.);  // outside [0, width]
    if(error < best_error)
    {
      best_error = error;
      best_phi = ts.corner_theta[corner] + ts.angle_scale[v] * (std::min)((std::max)(psi, 0.), width);
      if(error == 0.) break;
    }
  }
  error_out = best_error;
  return best_phi;
}

// The coefficient (n-th power representation) of a 3D vector at vertex v,
// |w| exp(i n phi), consistent with the output convention: tangent_direction()
// lays out the root phi_0 = arg(u) / n in [0, 2 pi / n), and the other n - 1
// directions are its rotations by 2 pi k / n about the normal. So among the n
// rotations of w (projected to the tangent plane) the one whose rescaled angle
// falls in [0, 2 pi / n) is chosen: the output then contains w exactly.
//
// `chosen`, if given, receives that rotation of w (unit, tangent), the
// direction the output should show at v: where the angle rescaling at v
// squeezes the first sector to less than 2 pi / n of Euclidean angle, no
// rotation of w may lie exactly in it, and the layout of the coefficient is
// then only the nearest direction (see the class, which writes `chosen`
// itself at constrained vertices).
inline std::complex<double> tangent_coefficient(const Indexed_mesh& m, const Tangent_spaces& ts, std::size_t v,
                                                const Vec3& vector, int degree, const Vec3& normal,
                                                Vec3* chosen = nullptr)
{
  const Vec3 w = vector - dot(vector, normal) * normal;
  const double length = norm(w);
  if(m.fan_size(v) == 0 || !(length > 0.)) return std::complex<double>(0., 0.);
  const double sector = 2. * CGAL_PI / degree;
  const Vec3 w_perp = cross(normal, w);
  double best_phi = 0., best_distance = 1e300;
  for(int k = 0; k < degree; ++k)
  {
    const Vec3 wk = std::cos(k * sector) * w + std::sin(k * sector) * w_perp;
    double error;
    const double phi = rescaled_angle_of(m, ts, v, wk, normal, error);
    // distance of phi to the sector [0, 2 pi / n), and to an exact preimage
    const double distance = (phi < 0. ? -phi : (phi >= sector ? phi - sector : 0.)) + error;
    if(distance < best_distance)
    {
      best_distance = distance;
      best_phi = phi;
      if(chosen != nullptr) *chosen = (1. / length) * wk;
      if(distance == 0.) break;
    }
  }
  return std::polar(length, degree * best_phi);
}

// Unit coefficients of the direction tangent (or normal) to the boundary at a
// boundary vertex. The fan of a boundary vertex starts on the outgoing
// boundary edge (rescaled angle 0) and ends on the incoming one (angle Theta,
// its angle sum); the boundary continues at angle Theta - pi, and the tangent
// is the mean (Theta - pi) / 2 of the two, the inward normal Theta / 2.
inline std::complex<double> boundary_coefficient(const Indexed_mesh& m, const Tangent_spaces& ts, std::size_t v,
                                                 int degree, bool normal)
{
  double theta = 0.;
  for(std::size_t k = m.fan_offsets[v]; k < m.fan_offsets[v + 1]; ++k)
    theta += ts.corner_width[m.fan_corners[k]];  // s = 1 on the boundary
  const double phi = normal ? 0.5 * theta : 0.5 * (theta - CGAL_PI);
  return std::polar(1., degree * phi);
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_GUIDANCE_H
