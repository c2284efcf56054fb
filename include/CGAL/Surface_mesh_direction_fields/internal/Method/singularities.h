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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_SINGULARITIES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_SINGULARITIES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <cmath>
#include <complex>
#include <vector>

// Discrete Poincare-Hopf index of a vertex field per face (user manual, section "Singularities").
// For the halfedge i -> j, omega_ij in (-pi, pi] is the rotation from the
// transported coefficient r_ij u_i to u_j; around face t the rotations and the
// curvature Omega_t add up to 2 pi index_t. Because Omega_t = n kappa_t is
// unwrapped, the indices of a closed component sum to n chi exactly.
// A zero coefficient has no direction; it is taken as angle 0 (documented).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// omega_ij = theta_j - theta_i - rho_ij reduced to (-pi, pi], from the angle
// theta of each vertex coefficient, computed once per vertex. (The angle of
// u_j conj(r_ij u_i) would be the same for nonzero coefficients, but a zero
// coefficient would then give omega = 0 on both sides of an edge without a
// common angle, and the face sums would no longer be multiples of 2 pi.)
//
// The reduction (reduce_angle(), vector_math.h) is odd bit for bit, so
// omega_ji = -omega_ij holds exactly across an interior edge (r_ji =
// conj(r_ij) exactly, so rho_ji = -rho_ij), which is what makes the indices
// of a closed component sum to n chi.
// `rho(ci)` is the transport angle rho_ij of corner ci's side.
template <typename CornerAngle>
int face_index(const Indexed_mesh& m, const std::vector<double>& holonomy, const CornerAngle& rho,
               const std::vector<double>& theta, std::size_t f)
{
  double total = holonomy[f];
  for(int c = 0; c < 3; ++c)
    total += reduce_angle(theta[m.faces[f][(c + 1) % 3]] - theta[m.faces[f][c]] - rho(3 * f + c));
  return static_cast<int>(std::lround(total / (2. * CGAL_PI)));
}

template <typename CornerAngle>
std::vector<int> face_indices(const Indexed_mesh& m, const std::vector<double>& holonomy, const CornerAngle& rho,
                              const std::vector<std::complex<double> >& u)
{
  std::vector<double> theta(u.size());
  parallel_for_each_index(u.size(), [&](std::size_t v) { theta[v] = std::arg(u[v]); });  // arg(0) = 0
  std::vector<int> index(m.number_of_faces());
  parallel_for_each_index(m.number_of_faces(), [&](std::size_t f) { index[f] = face_index(m, holonomy, rho, theta, f); });
  return index;
}

// With the angles of the connection's transports (conjugate across an edge,
// so that rho_ji = -rho_ij).
inline std::vector<int> face_indices(const Indexed_mesh& m, const Connection& con,
                                     const std::vector<std::complex<double> >& u)
{
  return face_indices(m, con.holonomy, [&con](std::size_t ci) { return std::arg(con.transport[ci]); }, u);
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_SINGULARITIES_H
