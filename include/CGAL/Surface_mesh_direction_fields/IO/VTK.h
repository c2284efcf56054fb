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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_VTK_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_VTK_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_data.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/number_writer.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>
#include <CGAL/Surface_mesh_direction_fields/IO/internal/VTK_reading.h>
#include <CGAL/Surface_mesh_direction_fields/IO/internal/VTK_writing.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <iomanip>
#include <istream>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

// The field and its singularities for ParaView, VTK and meshio.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace IO {

/// \name VTK
/// @{

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the field as a legacy VTK file (ASCII, an `UNSTRUCTURED_GRID`), which
ParaView, VTK and meshio open. Points: the vertices that belong to a face
(renumbered in their order; a vertex of no face is left out); cells: the
triangles. Data, chosen so that a viewer's defaults show the field:
- field data `degree` (the integer `n`);
- point data `normals` (the unit normals), `direction_0` (the active
  vectors: a glyph filter orients its arrows by it), `direction_1` ...
  `direction_{n-1}`, `directions` (the `n` directions of each point in one
  tuple of `3n` components), and `magnitude` (if known);
- cell data `singularity_index`: `k / n` on a singular triangle, 0 on the
  others.

No array is the active scalars: ParaView's Glyph filter takes them as its
scale array, so that its default settings would draw no arrows.

A field on faces (`make_face_direction_field_data()`) is written with the
same points and triangles and the same arrays as cell data: `normals` (the
face normals), `direction_0` (the active cell vectors: ParaView's Glyph
filter places its arrows at the triangles' centres), ... `direction_{n-1}`,
`directions`; its singular vertices are the point data `singularity_index`
(`k / n` at a singular vertex, 0 elsewhere).

The singularities as markers of their own are written by
`write_VTK_singularities()`. Coordinates are written with 17 significant
digits, so that reading back gives the same doubles.

\param os the output stream
\param data the field to write
*/
inline void write_VTK(std::ostream& os, const Direction_field_data& data)
{
  internal::write_legacy_grid(os, internal::field_grid(data));
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes what `write_VTK()` writes as a VTK XML UnstructuredGrid file (`.vtu`,
ASCII), which ParaView, VTK and meshio open: the same points, triangles and
arrays, with the same active attributes (and `normals` as the active normals).

\param os the output stream
\param data the field to write
*/
inline void write_VTU(std::ostream& os, const Direction_field_data& data)
{
  internal::write_XML_grid(os, internal::field_grid(data));
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the singularities as a legacy VTK file (an `UNSTRUCTURED_GRID`) of
markers a viewer shows as they are: around the barycentre of each singular
face (around each singular vertex of a field on faces) a small octahedron (of radius 1/100 of the bounding box's diagonal),
whose points and triangles carry its index `k / n` as `singularity_index`
(the active scalars, so that ParaView colours the markers by their index).
Field data `degree` is `n`. Opened together with the file of `write_VTK()`,
it shows the singularities at a size one sees on the whole mesh.

\param os the output stream
\param data the field whose singularities are written
*/
inline void write_VTK_singularities(std::ostream& os, const Direction_field_data& data)
{
  internal::write_legacy_grid(os, internal::singularity_marker_grid(data));
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes what `write_VTK_singularities()` writes as a VTK XML UnstructuredGrid
file (`.vtu`).

\param os the output stream
\param data the field whose singularities are written
*/
inline void write_VTU_singularities(std::ostream& os, const Direction_field_data& data)
{
  internal::write_XML_grid(os, internal::singularity_marker_grid(data));
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

reads a file written by `write_VTK()` back: the singular faces are the
triangles whose `singularity_index` is not 0; for a field on faces, the
per-face directions and the singular vertices (the points whose
`singularity_index` is not 0). The PolyData files of earlier
versions are read too (their singular faces recovered by matching each
singularity point to the barycentre of a face). The per-face directions are
recomputed by `face_directions()`.

\throws Invalid_input_error if the stream is not such a file
\param is the input stream
\returns the field read
*/
inline Direction_field_data read_VTK(std::istream& is)
{
  Direction_field_data data;
  data.degree = internal::read_VTK_degree(is);
  const internal::VTK_cells cells = internal::read_VTK_geometry(is, data);
  const internal::VTK_singularity_values singular = internal::read_VTK_data(is, cells, data);
  if(!data.face_directions.empty())  // a field on faces
  {
    data.directions.clear();
    internal::singular_vertices_from_points(singular.of_points, data);
    return data;
  }
  const std::vector<double>& singularity_values = singular.of_cells_or_markers;
  // the normals (not stored in the file): angle-weighted, orthogonal to d_0
  using internal::operator-;
  using internal::operator*;
  const std::vector<internal::Vec3> normal = internal::angle_weighted_normals(data.points, data.faces);
  data.normals.resize(data.points.size());
  for(std::size_t v = 0; v < data.points.size(); ++v)
  {
    const internal::Vec3& d = data.directions[v][0];
    data.normals[v] = internal::normalized(normal[v] - internal::dot(normal[v], d) * d);
  }
  if(cells.unstructured) internal::singular_faces_from_cells(singularity_values, data);
  else internal::match_singular_faces(singularity_values, data);
  data.face_directions = face_directions(data);
  return data;
}

/// @}

} // namespace IO
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_VTK_H
