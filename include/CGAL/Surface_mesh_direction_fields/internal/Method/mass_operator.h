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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_MASS_OPERATOR_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_MASS_OPERATOR_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/local_matrices.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>

#include <complex>
#include <cstddef>
#include <vector>

// Products with the mass matrix M of a component, computed from its faces
// without M (user manual, section "Energies"). An aligned field computed in a
// single call needs M only for two products once A - lambda_t M is formed
// (M q, with the norm of q, and the norm of u), and the factorization is the
// moment of peak memory: with the products taken from the faces, A and M are
// freed before it (developer notes, "Performance and Repeated Work").

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

class Mass_operator
{
  const Indexed_mesh& m_mesh;
  const Tangent_spaces& m_ts;
  const Connection& m_con;
  std::vector<Complex> m_face_kernel;  // |t| conj(mass_factor(Omega_t)) per face

public:
  // Computes the kernel of every face (in parallel).
  Mass_operator(const Indexed_mesh& m, const Tangent_spaces& ts, const Connection& con)
    : m_mesh(m), m_ts(ts), m_con(con), m_face_kernel(m.number_of_faces())
  {
    parallel_for_each_index(m_face_kernel.size(), [&](std::size_t f) {
      m_face_kernel[f] = m_ts.face_area[f] * conjugated_mass_kernel(m_con, f);
    });
  }

  // M x for the component `comp` (x and the result in its local vertex order).
  // Row v of M gathers from the faces around v, as the assembly gathers
  // column v (assembly.h): in face t with v = t[c], the row has
  // conj(r_{v t[c+1]} m_t) in column t[c+1] and r_{t[c+2] v} m_t in column
  // t[c+2], m_t = |t| conj(mass_factor(Omega_t)), and the diagonal adds
  // |t| / 6 (local_matrices.h).
  Complex_vector times(const Component& comp, const std::vector<Compact_index>& local_index,
                       const Complex_vector& x) const
  {
    Complex_vector y(x.size());
    auto at = [&](std::size_t w) { return x[static_cast<Eigen::Index>(local_index[w])]; };
    parallel_for_each_index(comp.vertices.size(), [&](std::size_t i) {
      const std::size_t v = comp.vertices[i];
      Complex sum(0., 0.);
      double diagonal = 0.;
      for(std::size_t k = m_mesh.fan_offsets[v]; k < m_mesh.fan_offsets[v + 1]; ++k)
      {
        const std::size_t corner = m_mesh.fan_corners[k], f = corner / 3;
        const int c = static_cast<int>(corner % 3);
        const auto& t = m_mesh.faces[f];
        const Complex kernel = m_face_kernel[f];
        sum += std::conj(m_con.transport[corner] * kernel) * at(t[(c + 1) % 3]);
        sum += m_con.transport[3 * f + (c + 2) % 3] * kernel * at(t[(c + 2) % 3]);
        diagonal += m_ts.face_area[f] / 6.;
      }
      y[static_cast<Eigen::Index>(i)] = sum + diagonal * x[static_cast<Eigen::Index>(i)];
    });
    return y;
  }
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_MASS_OPERATOR_H
