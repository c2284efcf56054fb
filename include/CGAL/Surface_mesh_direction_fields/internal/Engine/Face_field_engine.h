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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FACE_FIELD_ENGINE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FACE_FIELD_ENGINE_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_request.h>

#include <cstddef>
#include <memory>
#include <vector>

// The seam between the mesh plumbing of
// compute_globally_optimal_face_directions() and the method on the dual mesh
// (user manual, section "Fields on Faces"), declared without its definitions
// (Face_field_engine_impl.h), as Field_engine.h: with
// CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION a program links the
// engine of the default solver from the compiled library.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

template <typename SparseSolver>
class Face_field_engine
{
public:
  // The intrinsic geometry of the mesh (its coordinates normalized), its
  // components and the dual connection. `point_of_vertex` (empty, or one
  // number per vertex): vertices of one number are copies of one point, and
  // the faces around an edge of three sides or more between such points are
  // glued there (user manual, section "Fields on Faces").
  Face_field_engine(Indexed_mesh mesh, double mollification, std::vector<std::size_t> point_of_vertex = {});
  ~Face_field_engine();
  Face_field_engine(const Face_field_engine&) = delete;
  Face_field_engine& operator=(const Face_field_engine&) = delete;

  // One field; `solver`, if not null, is the user's solver (else a default one).
  Face_direction_field_result compute(const Face_field_request& request, const SparseSolver* solver,
                                      Face_field_answer& answer) const;

  // The indexed mesh the corners of the answer's matching refer to.
  const Indexed_mesh& mesh() const;

private:
  class Impl;
  std::unique_ptr<Impl> m_impl;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FACE_FIELD_ENGINE_H
