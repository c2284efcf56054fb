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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_VERTEX_NORMALS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_VERTEX_NORMALS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The package's vertex normals (user manual, section "Back to 3D Directions"): the unit
// normals of the faces around v weighted by v's corner angle in each, summed
// in the order corners_of(v) lists them, normalized. The library passes its
// (possibly mollified) corner angles and counter-clockwise fans; the file
// readers, which have no mesh, the Euclidean angles and the corners in face
// order.
template <typename Triangles, typename CornersOf, typename CornerAngle>
std::vector<Vec3> angle_weighted_vertex_normals(const std::vector<Vec3>& points, const Triangles& triangles,
                                                const CornersOf& corners_of, const CornerAngle& corner_angle)
{
  std::vector<Vec3> normals(points.size());
  parallel_for_each_index(points.size(), [&](std::size_t v) {
    Vec3 sum{0., 0., 0.};
    for(std::size_t corner : corners_of(v))  // a degenerate face has no normal and adds nothing
      sum = sum + corner_angle(corner) * triangle_unit_normal(points, triangles[corner / 3]);
    normals[v] = normalized(sum);
  });
  return normals;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_VERTEX_NORMALS_H
