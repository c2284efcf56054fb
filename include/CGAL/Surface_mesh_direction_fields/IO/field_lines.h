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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_FIELD_LINES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_FIELD_LINES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/IO/internal/VTK_writing.h>
#include <CGAL/Surface_mesh_direction_fields/internal/number_writer.h>
#include <CGAL/Surface_mesh_direction_fields/streamlines.h>

#include <cstddef>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

// The field lines of trace_streamlines() in the formats viewers open.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// VTK XML cells of field lines: point coordinates, then the cells.
inline void write_field_line_points(std::ostream& os, const std::vector<Streamline>& lines)
{
  os << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  Number_writer w(os);
  for(const Streamline& l : lines)
    for(const auto& p : l.points) w.line(p[0], p[1], p[2]);
  w.flush();
  os << "</DataArray>\n</Points>\n";
}

inline void write_field_line_connectivity(std::ostream& os, const std::vector<Streamline>& lines)
{
  Number_writer w(os);
  w.text("<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  std::size_t point = 0;
  for(const Streamline& l : lines)
  {
    for(std::size_t i = 0; i < l.points.size(); ++i) w.integer(static_cast<long long>(point++)).space();
    w.end_line();
  }
  w.text("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  point = 0;
  for(const Streamline& l : lines) w.integer(static_cast<long long>(point += l.points.size())).end_line();
  w.text("</DataArray>\n");
}

// The field lines as an unstructured grid of line segments (VTK_LINE); the
// cell data "line" numbers the field line of each segment.
inline VTK_grid field_line_segments(const std::vector<Streamline>& lines, int degree)
{
  VTK_grid g;
  g.title = "field lines of a direction field of degree " + std::to_string(degree) +
            " (CGAL Surface_mesh_direction_fields)";
  g.degree = degree;
  VTK_array line{"line", 1, {}};
  for(std::size_t i = 0; i < lines.size(); ++i)
  {
    const long long first = static_cast<long long>(g.points.size());
    g.points.insert(g.points.end(), lines[i].points.begin(), lines[i].points.end());
    for(long long j = 1; j < static_cast<long long>(lines[i].points.size()); ++j)
    {
      g.add_cell({first + j - 1, first + j}, 3);
      line.values.push_back(static_cast<double>(i));
    }
  }
  g.cell_arrays.push_back(std::move(line));
  return g;
}

} // namespace internal

namespace IO {

/// \name Field lines
/// @{

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes field lines (`trace_streamlines()`) as a VTK XML PolyData file
(`.vtp`), one poly-line per field line, as ParaView and VTK read it.

\param os the output stream
\param lines the field lines, as `trace_streamlines()` gives them
*/
inline void write_field_lines_VTP(std::ostream& os, const std::vector<Streamline>& lines)
{
  std::size_t points = 0;
  for(const Streamline& l : lines) points += l.points.size();
  os << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
     << "<PolyData>\n<Piece NumberOfPoints=\"" << points << "\" NumberOfLines=\"" << lines.size() << "\">\n";
  internal::write_field_line_points(os, lines);
  os << "<Lines>\n";
  internal::write_field_line_connectivity(os, lines);
  os << "</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n";
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes field lines as a legacy VTK file of line segments (an
`UNSTRUCTURED_GRID`, which meshio keeps: it drops poly-lines), the cell data
`line` numbering the field line of each segment and `degree` the field's `n`.

\param os the output stream
\param lines the field lines, as `trace_streamlines()` gives them
\param degree the degree `n` of the field, written as field data
*/
inline void write_field_lines_VTK(std::ostream& os, const std::vector<Streamline>& lines, int degree)
{
  internal::write_legacy_grid(os, internal::field_line_segments(lines, degree));
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes what `write_field_lines_VTK()` writes as a VTK XML UnstructuredGrid
file (`.vtu`).

\param os the output stream
\param lines the field lines, as `trace_streamlines()` gives them
\param degree the degree `n` of the field, written as field data
*/
inline void write_field_lines_VTU(std::ostream& os, const std::vector<Streamline>& lines, int degree)
{
  internal::write_XML_grid(os, internal::field_line_segments(lines, degree));
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes field lines as an OBJ file: the points as `v` lines, each field line
as an `l i j k ...` line.

\param os the output stream
\param lines the field lines, as `trace_streamlines()` gives them
*/
inline void write_field_lines_OBJ(std::ostream& os, const std::vector<Streamline>& lines)
{
  internal::Number_writer w(os);
  w.text("# field lines of a direction field (CGAL Surface_mesh_direction_fields)\n");
  for(const Streamline& l : lines)
    for(const auto& p : l.points) w.text("v ").number(p[0]).space().number(p[1]).space().number(p[2]).end_line();
  long long next = 1;
  for(const Streamline& l : lines)
  {
    w.text("l");
    for(std::size_t i = 0; i < l.points.size(); ++i) w.space().integer(next++);
    w.end_line();
  }
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes field lines in \cgal's polylines text format: one line
`N x1 y1 z1 ... xN yN zN` per field line (17 significant digits).

\param os the output stream
\param lines the field lines, as `trace_streamlines()` gives them
*/
inline void write_field_lines_polylines(std::ostream& os, const std::vector<Streamline>& lines)
{
  internal::Number_writer w(os);
  for(const Streamline& l : lines)
  {
    w.integer(static_cast<long long>(l.points.size()));
    for(const auto& p : l.points) w.space().number(p[0]).space().number(p[1]).space().number(p[2]);
    w.end_line();
  }
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes one `x y z` line per vector (17 significant digits, exact when read
back), as the command-line program's `--directions` does.

\tparam Vector3Range a range of elements `v` with `v[0]`, `v[1]`, `v[2]` convertible to `double`

\param os the output stream
\param vectors the vectors
*/
template <typename Vector3Range>
void write_vectors(std::ostream& os, const Vector3Range& vectors)
{
  internal::Number_writer w(os);
  for(const auto& v : vectors) w.line(v[0], v[1], v[2]);
}

/// @}

} // namespace IO
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_FIELD_LINES_H
