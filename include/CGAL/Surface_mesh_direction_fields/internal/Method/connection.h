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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_CONNECTION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_CONNECTION_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/cycles.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <complex>
#include <cstddef>
#include <vector>

// The discrete connection of degree n (user manual, section "Tangent Spaces,
// Transport and Curvature"): the transport r_ij = exp(i rho_ij) of every
// halfedge and the curvature Omega_t = n kappa_t of every face, unwrapped.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Connection
{
  int degree = 1;
  // transport[3f+c] = r_ij for the halfedge i -> j with i = faces[f][c], j = faces[f][c+1]
  std::vector<std::complex<double> > transport;
  std::vector<double> holonomy;  // Omega_t = n kappa_t (unwrapped)
};

// rho_ij = n (theta_j(j -> i) - theta_i(i -> j) + pi). Inside face (i, j, k),
// the halfedge j -> i is the second side of j's corner, so
// theta_j(j -> i) = theta_j(j -> k) + s_j alpha_j (the corner's width).
// rho_ji = -rho_ij (mod 2 pi), so an interior edge's transport is computed
// once, on the side of the smaller corner, and the other side gets its
// conjugate: half the sines and cosines, and r_ji = conj(r_ij) exactly.
inline Connection compute_connection(const Indexed_mesh& m, const Tangent_spaces& ts, int degree)
{
  Connection con;
  con.degree = degree;
  const std::size_t nf = m.number_of_faces();
  con.transport.resize(3 * nf);
  con.holonomy.resize(nf);
  const double n = static_cast<double>(degree);
  auto is_computed_side = [&m](std::size_t ci) { return is_representative_side(m, ci); };
  parallel_for_each_index(nf, [&](std::size_t f) {
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t ci = 3 * f + c, cj = 3 * f + (c + 1) % 3;
      if(!is_computed_side(ci)) continue;
      const double theta_ij = ts.corner_theta[ci];
      const double theta_ji = ts.corner_theta[cj] + ts.corner_width[cj];
      // Reduce before multiplying by n so that large degrees keep their accuracy.
      const double angle = reduce_angle(theta_ji - theta_ij + CGAL_PI);
      con.transport[ci] = std::polar(1., reduce_angle(n * angle));
    }
    con.holonomy[f] = n * ts.face_angle_defect[f];
  });
  parallel_for_each_index(3 * nf, [&](std::size_t ci) {
    if(!is_computed_side(ci)) con.transport[ci] = std::conj(con.transport[m.twin_corner[ci]]);
  });
  return con;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_CONNECTION_H
