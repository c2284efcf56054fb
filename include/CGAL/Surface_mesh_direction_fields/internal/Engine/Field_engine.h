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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FIELD_ENGINE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FIELD_ENGINE_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_request.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <array>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

// The seam between the mesh plumbing and the method. The class
// Globally_optimal_direction_field reads the mesh and the named parameters
// into the index-based requests below and writes the answers into the
// user's property maps; the engine does everything in between (user manual,
// sections "The Smoothest Field" to "Placing Singularities"). This header
// declares the engine without its definitions (Field_engine_impl.h): with
// CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION a program compiles
// only the plumbing and links the engine of the default solver from the
// compiled library (see the README).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

template <typename SparseSolver>
class Field_engine
{
public:
  // The intrinsic geometry of the mesh (its coordinates normalized), its
  // components and normals: the given ones (one per vertex), or the
  // angle-weighted ones if `normals` is empty.
  Field_engine(Indexed_mesh mesh, double mollification, std::vector<Vec3> normals);
  ~Field_engine();
  Field_engine(const Field_engine&) = delete;
  Field_engine& operator=(const Field_engine&) = delete;

  // One field; `solver`, if not null, is the user's solver for this call
  // only (no factorization kept).
  Direction_field_result compute(const Field_request& request, const SparseSolver* solver, Field_answer& answer);

  std::vector<Corner_loop> prescription_loops();
  // The energy A and the mass M of degree n and parameter s on the whole
  // mesh (rows and columns by vertex index, no entry at isolated vertices),
  // in the user's units: A u = lambda M u for the smoothest field's u.
  std::pair<Complex_sparse_matrix, Complex_sparse_matrix> energy_and_mass(int degree, double s);
  void keep_factorizations(bool keep);
  std::size_t number_of_vertices() const;
  std::size_t number_of_faces() const;

private:
  class Impl;
  std::unique_ptr<Impl> m_impl;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FIELD_ENGINE_H
