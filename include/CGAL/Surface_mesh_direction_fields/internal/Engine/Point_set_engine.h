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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_POINT_SET_ENGINE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_POINT_SET_ENGINE_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_request.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <chrono>
#include <vector>

// The seam between compute_globally_optimal_point_set_directions() (the
// user's range and property maps) and the method on the points' local
// triangulations (user manual, section "Point Sets"), declared without its
// definition (Point_set_engine_impl.h), as Field_engine.h: with
// CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION a program links it
// from the compiled library, and the neighbour search, the local Delaunay
// triangulations and the fitting of the normals are compiled once there.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Point_set_field_request
{
  int degree = 4;
  double s = 0.;
  unsigned int number_of_neighbors = 12;
  double residual_tolerance = 1e-10;
  std::vector<Vec3> guidance;  // a vector per point, or empty: none
  Principal_curvature_alignment curvature = Principal_curvature_alignment::NONE;  // guidance too (even degree)
  std::vector<unsigned char> is_constrained;  // per point, or empty: no hard constraint
  std::vector<Vec3> constrained_directions;   // where constrained: a direction the field takes exactly
  Alignment_request alignment;
  double length_scale = 1.;    // of normalize_coordinates(): eigenvalues and lambda_t in the user's units
};

template <typename SparseSolver>
struct Point_set_engine
{
  // The direction of angle 0 at each point, of unit length (the other n - 1
  // are its rotations about the point's normal), zero at a point in no
  // triangle. `positions` are normalized (normalize_coordinates()), `normals`
  // of unit length, or empty to be estimated. Fills `result` but its total
  // time; its times count from `start`.
  static std::vector<Vec3> compute(const std::vector<Vec3>& positions, std::vector<Vec3> normals,
                                   const Point_set_field_request& request, std::chrono::steady_clock::time_point start,
                                   Point_set_direction_field_result& result);
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_POINT_SET_ENGINE_H
