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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_MESH_GEOMETRY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_MESH_GEOMETRY_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/extrinsic_directions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_inputs.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/folded_fans.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <cstddef>
#include <utility>
#include <vector>

// What the engine knows of the mesh, computed once at
// construction and never changed by a field computation.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Mesh_geometry
{
  // The intrinsic geometry (the rescaled tangent spaces), the components, the
  // vertex normals (the given ones, or the angle-weighted ones if `given` is
  // empty) and the layout at folded triangles.
  Mesh_geometry(Indexed_mesh indexed_mesh, double mollification, std::vector<Vec3> given)
    : mesh(std::move(indexed_mesh)), normals(std::move(given))
  {
    length_scale = normalize_coordinates(mesh);
    const bool default_normals = normals.empty();
    // The components (a sequential breadth-first search) on one thread, while
    // the other computes the tangent spaces and the normals.
    auto find_components = [&] { components = split_into_components(mesh); };
    auto compute_tangent_planes = [&] {
      tangent_spaces = compute_tangent_spaces(mesh, mollification);
      // the tangent planes of the outputs and of the guidance vectors
      if(default_normals) normals = angle_weighted_vertex_normals(mesh, tangent_spaces);
      tangent_plane_vertices = lay_out_folded_fans(mesh, normals, default_normals, tangent_spaces);
    };
    parallel_invoke(find_components, compute_tangent_planes);
    check_components_have_area(mesh, components, tangent_spaces.mollification);
  }

  // Eigenvalues and lambda_t between the user's units and those of the
  // normalized coordinates (normalize_coordinates(): lengths times
  // length_scale, eigenvalues divided by its square).
  double eigenvalue_to_user(double lambda) const { return lambda * length_scale * length_scale; }
  double eigenvalue_from_user(double lambda) const { return lambda / length_scale / length_scale; }

  // The area of component c.
  double area_of(std::size_t c) const
  {
    double area = 0.;
    for(std::size_t f : components.list[c].faces) area += tangent_spaces.face_area[f];
    return area;
  }

  Indexed_mesh mesh;  // its coordinates times length_scale
  std::vector<Vec3> normals;
  double length_scale = 1.;
  std::size_t tangent_plane_vertices = 0;  // laid out at folded triangles (folded_fans.h)
  Tangent_spaces tangent_spaces;
  Components components;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_MESH_GEOMETRY_H
