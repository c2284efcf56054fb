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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CGAL_COMPATIBILITY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CGAL_COMPATIBILITY_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/version.h>

#include <optional>
#include <string>

// The one place where the package asks which CGAL it is built with: 5.5
// (Debian 12) and 6.x differ in the basic viewer (Basic_viewer_qt on Qt5,
// then Graphics_scene + Basic_viewer on Qt6) and in looking up a named
// property map of a Surface_mesh (a pair (map, found), then std::optional).
// Everything else the package uses is the same in both.

#if CGAL_VERSION_NR >= 1060000000
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_CGAL_6 1
#else
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_CGAL_6 0
#endif

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The property map `name` of `mesh` (a Surface_mesh) from `Key` to `Value`,
// if the mesh has one.
template <typename Key, typename Value, typename SurfaceMesh>
std::optional<typename SurfaceMesh::template Property_map<Key, Value> >
find_property_map(const SurfaceMesh& mesh, const std::string& name)
{
#if CGAL_SURFACE_MESH_DIRECTION_FIELDS_CGAL_6
  return mesh.template property_map<Key, Value>(name);
#else
  const auto found = mesh.template property_map<Key, Value>(name);
  if(!found.second) return std::nullopt;
  return found.first;
#endif
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_CGAL_COMPATIBILITY_H
