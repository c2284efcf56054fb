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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_LOCAL_MATRICES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_LOCAL_MATRICES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/section_integrals.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>

#include <complex>
#include <cstddef>

// The local 3x3 energy and mass matrices of one face (user manual, section
// "Energies"): the integrals over the face of the products of the
// piecewise-linear sections of its three vertices, in closed form through
// the kernels f1, f2 and the mass factor of section_integrals.h, which depend
// only on the face's curvature Omega.
//
// Placement and conjugation. The energy of a coefficient vector u is u^* A u
// (conjugate on the left), so the (row a, column b) entry of the local matrix
// of face t = (i, j, k) is the integral over t of <psi_a, psi_b>, antilinear in
// psi_a, where psi_a = b_a phi_a and phi_a is X_a transported along the rays
// from vertex a. Parallel transport around the sub-triangle (k, v, j) gives
// conj(phi_k(v)) phi_j(v) = r_jk exp(-i Omega b_i(v)), hence
//     (row k, column j) = r_jk |t| conj(mass_factor(Omega)),
// and likewise for the Dirichlet part, with conj(f1), conj(f2); the
// (row j, column k) entry is the conjugate. This is the paper's M_jk, D_jk
// with r_jk -> conj(r_jk) = r_kj, i.e. the printed formulas hold in the
// (row j, column k) position with the transport r_kj. With the formulas taken
// literally (r_jk together with exp(+i Omega)), the local matrices are no
// longer Gram matrices: they become indefinite once |Omega| is not small (the
// test compares them with a direct quadrature of the sections).
// The boundary term of E_s follows the same conjugation: +i r_jk / 2 inside
// s (...) at (row k, column j), for the counter-clockwise edge j -> k of t.
// In the flat case D_jk -> -r_jk cot(alpha_i) / 2 and the pair contributes
// (cot(alpha_i) / 2) |u_k - r_jk u_j|^2: a field that agrees with its
// transport costs nothing.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Local_matrices
{
  // Entries for the pair of vertices opposite corner c: (row k, column j) with
  // j = faces[f][c+1], k = faces[f][c+2]; and the diagonal entry of corner c.
  Complex energy_pair[3], mass_pair[3];
  double energy_diagonal[3], mass_diagonal[3];
};

// The factor of the transport in the off-diagonal local mass entries of face
// f, divided by its area (see the note on placement and conjugation above).
inline Complex conjugated_mass_kernel(const Connection& con, std::size_t f)
{
  return std::conj(mass_factor(con.holonomy[f]));
}

// The local matrices of face f for the energy E_s (s in [-1, 1]).
inline Local_matrices local_matrices(const Indexed_mesh& m, const Tangent_spaces& ts, const Connection& con,
                                     std::size_t f, double s)
{
  Local_matrices lm;
  const Face_geometry geometry = face_geometry(m, f, ts.mollification);
  const double area = ts.face_area[f];
  const double omega = con.holonomy[f];
  // conjugated kernels: see the note on placement and conjugation above
  const Complex f1 = std::conj(dirichlet_kernel_f1(omega));
  const Complex f2 = std::conj(dirichlet_kernel_f2(omega));
  const Complex mass_kernel = conjugated_mass_kernel(con, f);
  const Complex I(0., 1.);
  for(int c = 0; c < 3; ++c)
  {
    // Intrinsic: the sides from i = t[c] to j = t[c+1] and k = t[c+2], and the
    // opposite side j -> k, from the (possibly mollified) edge lengths.
    const double g11 = geometry.squared_length[c], g22 = geometry.squared_length[(c + 2) % 3];
    const double g12 = geometry.corner_dot[c];
    const double l_jk2 = geometry.squared_length[(c + 1) % 3];
    const Complex r_jk = con.transport[3 * f + (c + 1) % 3];  // j -> k runs counter-clockwise

    const Complex dirichlet = (r_jk / area) * ((g11 + g22) * f1 + g12 * f2);
    const Complex mass = r_jk * area * mass_kernel;
    lm.mass_pair[c] = mass;
    // j -> k is counter-clockwise in t. The boundary term cancels between the
    // two faces of an interior edge.
    lm.energy_pair[c] = dirichlet - s * ((omega / area) * mass + 0.5 * I * r_jk);

    const double dirichlet_diagonal =
      (l_jk2 + omega * omega * (g11 + g12 + g22) / 90.) / (4. * area);
    lm.mass_diagonal[c] = area / 6.;
    lm.energy_diagonal[c] = dirichlet_diagonal - s * omega / 6.;  // (Omega/|t|) * |t|/6
  }
  return lm;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_LOCAL_MATRICES_H
