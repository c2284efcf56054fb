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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_DIRECTION_FIELD_FILES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_DIRECTION_FIELD_FILES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_data.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/number_writer.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

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

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Reads the next token, or throws with the file kind in the message.
inline std::string next_token(std::istream& is, const char* kind)
{
  std::string t;
  if(!(is >> t)) throw Invalid_input_error(std::string("truncated ") + kind + " file");
  return t;
}

// A number from a whole string, or Invalid_input_error.
template <typename T>
T parse_value(const std::string& t, const char* kind)
{
  std::istringstream ts(t);
  T value;
  if(!(ts >> value) || !ts.eof())
    throw Invalid_input_error(std::string("unexpected '") + t + "' in " + kind + " file");
  return value;
}

template <typename T>
T next_value(std::istream& is, const char* kind)
{
  const std::string t = next_token(is, kind);
  std::istringstream ts(t);
  T value;
  if(!(ts >> value) || !ts.eof())
    throw Invalid_input_error(std::string("unexpected '") + t + "' in " + kind + " file");
  return value;
}

inline void expect(std::istream& is, const std::string& word, const char* kind)
{
  const std::string t = next_token(is, kind);
  if(t != word)
    throw Invalid_input_error(std::string(kind) + " file: expected '" + word + "', found '" + t + "'");
}

// The pieces of IO::read_VTK(), in the order of the file.

inline int read_VTK_degree(std::istream& is)
{
  std::string line;
  std::getline(is, line);
  if(line.rfind("# vtk DataFile", 0) != 0) throw Invalid_input_error("not a legacy VTK file");
  std::getline(is, line);
  const std::string key = "direction field of degree ";
  if(line.rfind(key, 0) != 0) throw Invalid_input_error("VTK file: not written by write_VTK()");
  std::istringstream ls(line.substr(key.size()));
  std::string word;
  ls >> word;
  const int degree = parse_value<int>(word, "VTK");
  check_degree(degree);
  return degree;
}

// One array of a FIELD block: "name components tuples type", then the values.
inline std::vector<double> read_VTK_field_array(std::istream& is, std::string& name)
{
  const char* kind = "VTK";
  name = next_token(is, kind);
  const std::size_t components = next_value<std::size_t>(is, kind), tuples = next_value<std::size_t>(is, kind);
  next_token(is, kind);  // type
  if(components > 64 || tuples > (std::size_t(1) << 32)) throw Invalid_input_error("VTK file: implausible array size");
  std::vector<double> values(components * tuples);
  for(double& v : values) v = next_value<double>(is, kind);
  return values;
}

inline void skip_VTK_field_array(std::istream& is)
{
  std::string name;
  read_VTK_field_array(is, name);
}

struct VTK_cells
{
  std::size_t points = 0, singularities = 0, faces = 0;
};

// POINTS, the VERTICES of the singularities and the triangles (POLYGONS):
// data.points, data.singularity_points and data.faces.
inline VTK_cells read_VTK_geometry(std::istream& is, Direction_field_data& data)
{
  const char* kind = "VTK";
  expect(is, "ASCII", kind);
  expect(is, "DATASET", kind);
  expect(is, "POLYDATA", kind);
  std::string word = next_token(is, kind);
  if(word == "FIELD")  // the dataset's field data (the degree, already read from the title)
  {
    next_token(is, kind);
    const std::size_t arrays = next_value<std::size_t>(is, kind);
    for(std::size_t a = 0; a < arrays; ++a) skip_VTK_field_array(is);
    word = next_token(is, kind);
  }
  if(word != "POINTS") throw Invalid_input_error("VTK file: expected POINTS");
  VTK_cells cells;
  cells.points = next_value<std::size_t>(is, kind);
  if(cells.points > (std::size_t(1) << 32)) throw Invalid_input_error("VTK file: implausible number of points");
  next_token(is, kind);  // type
  std::vector<Vec3> points(cells.points);
  for(auto& p : points) for(double& x : p) x = next_value<double>(is, kind);
  word = next_token(is, kind);
  if(word == "VERTICES")
  {
    cells.singularities = next_value<std::size_t>(is, kind);
    next_value<std::size_t>(is, kind);
    for(std::size_t i = 0; i < 2 * cells.singularities; ++i) next_value<std::size_t>(is, kind);
    word = next_token(is, kind);
  }
  if(word != "POLYGONS") throw Invalid_input_error("VTK file: expected POLYGONS");
  cells.faces = next_value<std::size_t>(is, kind);
  next_value<std::size_t>(is, kind);
  if(cells.singularities > cells.points) throw Invalid_input_error("VTK file: more singularities than points");
  const std::size_t nv = cells.points - cells.singularities;
  data.points.assign(points.begin(), points.begin() + static_cast<std::ptrdiff_t>(nv));
  data.singularity_points.assign(points.begin() + static_cast<std::ptrdiff_t>(nv), points.end());
  data.faces.resize(cells.faces);
  for(auto& t : data.faces)
  {
    if(next_value<int>(is, kind) != 3) throw Invalid_input_error("VTK file: a polygon is not a triangle");
    for(auto& c : t)
    {
      c = next_value<std::size_t>(is, kind);
      if(c >= nv) throw Invalid_input_error("VTK file: a vertex index is out of range");
    }
  }
  return cells;
}

// The SCALARS block named `name` (its header read up to the name): the
// magnitudes of the mesh's points, or the indices of the singularity cells.
inline void read_VTK_scalars(std::istream& is, const std::string& name, const VTK_cells& cells, bool cell_data,
                             Direction_field_data& data, std::vector<double>& singularity_values)
{
  const char* kind = "VTK";
  const std::size_t nv = cells.points - cells.singularities;
  next_token(is, kind);
  next_token(is, kind);
  expect(is, "LOOKUP_TABLE", kind);
  next_token(is, kind);
  if(name == "magnitude")
  {
    data.magnitudes.resize(nv);
    for(std::size_t v = 0; v < cells.points; ++v)
    {
      const double m = next_value<double>(is, kind);
      if(v < nv) data.magnitudes[v] = m;
    }
  }
  else if(name == "singularity_index" && !cell_data)  // per point: the singularity points are last
  {
    for(std::size_t v = 0; v < cells.points; ++v)
    {
      const double value = next_value<double>(is, kind);
      if(v >= nv) singularity_values.push_back(value);
    }
  }
  else if(name == "singularity_index")  // per cell (files before the point data had it): the same values
  {
    std::vector<double> cell_values;
    for(std::size_t c = 0; c < cells.singularities + cells.faces; ++c)
    {
      const double value = next_value<double>(is, kind);
      if(c < cells.singularities) cell_values.push_back(value);
    }
    if(singularity_values.empty()) singularity_values = cell_values;
  }
  else throw Invalid_input_error("VTK file: unexpected data " + name);
}

// POINT_DATA and CELL_DATA: the directions, the magnitudes, and the index of
// each singularity cell (returned).
inline std::vector<double> read_VTK_data(std::istream& is, const VTK_cells& cells, Direction_field_data& data)
{
  const char* kind = "VTK";
  const std::size_t nv = cells.points - cells.singularities;
  expect(is, "POINT_DATA", kind);
  next_value<std::size_t>(is, kind);
  data.directions.assign(nv, std::vector<Vec3>(static_cast<std::size_t>(data.degree)));
  std::vector<double> singularity_values;
  std::string word;
  bool cell_data = false;
  while(is >> word)
  {
    if(word == "VECTORS")
    {
      const std::string name = next_token(is, kind);
      next_token(is, kind);
      const int k = parse_value<int>(name.substr(name.find('_') + 1), kind);
      if(k < 0 || k >= data.degree) throw Invalid_input_error("VTK file: unexpected " + name);
      for(std::size_t v = 0; v < cells.points; ++v)
      {
        Vec3 d;
        for(double& x : d) x = next_value<double>(is, kind);
        if(v < nv) data.directions[v][static_cast<std::size_t>(k)] = d;
      }
    }
    else if(word == "SCALARS")
      read_VTK_scalars(is, next_token(is, kind), cells, cell_data, data, singularity_values);
    else if(word == "NORMALS")  // recomputed below, as the reader of a file without them does
    {
      next_token(is, kind);
      next_token(is, kind);
      for(std::size_t i = 0; i < 3 * cells.points; ++i) next_value<double>(is, kind);
    }
    else if(word == "FIELD")  // the point data that is not an attribute: the magnitudes
    {
      next_token(is, kind);
      const std::size_t arrays = next_value<std::size_t>(is, kind);
      for(std::size_t a = 0; a < arrays; ++a)
      {
        std::string name;
        const std::vector<double> values = read_VTK_field_array(is, name);
        if(name == "magnitude" && !cell_data && values.size() == cells.points)
          data.magnitudes.assign(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(nv));
      }
    }
    else if(word == "CELL_DATA")
    {
      next_value<std::size_t>(is, kind);
      cell_data = true;
    }
    else
      throw Invalid_input_error("VTK file: unexpected '" + word + "'");
  }
  return singularity_values;
}

// The singular faces: the face whose barycentre is the singularity point
// (write_VTK() writes it from there).
inline void match_singular_faces(const std::vector<double>& singularity_values, Direction_field_data& data)
{
  const std::size_t ns = data.singularity_points.size();
  std::vector<Vec3> centres;
  if(ns > 0)
    for(const auto& t : data.faces) centres.push_back(barycentre(data.points, t));
  for(std::size_t i = 0; i < ns; ++i)
  {
    std::size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for(std::size_t f = 0; f < data.faces.size(); ++f)
    {
      const Vec3 d = centres[f] - data.singularity_points[i];
      if(dot(d, d) < best_distance) { best_distance = dot(d, d); best = f; }
    }
    if(i >= singularity_values.size()) throw Invalid_input_error("VTK file: no singularity_index for a singularity point");
    data.singularities.emplace_back(best, static_cast<int>(std::lround(singularity_values[i] * data.degree)));
  }
}

// What the VTK files show: the vertices that belong to a face (in order),
// then the barycentre of each singular face.
struct VTK_layout
{
  std::vector<std::size_t> used;                     // the vertex of `data` of each written vertex
  std::vector<std::array<std::size_t, 3> > faces;    // the triangles, renumbered

  explicit VTK_layout(const Direction_field_data& data)
  {
    const std::size_t none = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> number(data.points.size(), none);
    for(const auto& t : data.faces) for(std::size_t v : t) number[v] = 0;
    for(std::size_t v = 0; v < number.size(); ++v)
      if(number[v] != none) { number[v] = used.size(); used.push_back(v); }
    faces.reserve(data.faces.size());
    for(const auto& t : data.faces) faces.push_back({number[t[0]], number[t[1]], number[t[2]]});
  }

  long long vertices() const { return static_cast<long long>(used.size()); }
  long long triangles() const { return static_cast<long long>(faces.size()); }
  static long long singular_points(const Direction_field_data& data)
  {
    return static_cast<long long>(data.singularities.size());
  }

  // f(point, normal, singularity index, i) for every written point.
  template <typename F>
  void for_each_point(const Direction_field_data& data, const F& f) const
  {
    const Vec3 zero = {0., 0., 0.};
    for(std::size_t i = 0; i < used.size(); ++i)
      f(data.points[used[i]], data.normals.empty() ? zero : data.normals[used[i]], 0., i);
    for(std::size_t i = 0; i < data.singularities.size(); ++i)
    {
      const auto& face = data.faces[data.singularities[i].first];
      f(data.singularity_points[i], triangle_unit_normal(data.points, face),
        static_cast<double>(data.singularities[i].second) / data.degree, used.size() + i);
    }
  }
};

// The k-th direction of every written point (zero on the singularity points).
inline void write_directions(Number_writer& w, const Direction_field_data& data, const VTK_layout& layout, int k)
{
  for(std::size_t v : layout.used)
  {
    const auto& d = data.directions[v][static_cast<std::size_t>(k)];
    w.line(d[0], d[1], d[2]);
  }
  for(std::size_t i = 0; i < data.singularities.size(); ++i) w.text("0 0 0\n");
}

inline void write_magnitudes(Number_writer& w, const Direction_field_data& data, const VTK_layout& layout)
{
  for(std::size_t v : layout.used) w.number(data.magnitudes[v]).end_line();
  for(std::size_t i = 0; i < data.singularities.size(); ++i) w.text("0\n");
}

// The index k / n of the singularity cells, then 0 for every triangle.
inline void write_cell_indices(Number_writer& w, const Direction_field_data& data, const VTK_layout& layout)
{
  for(const auto& s : data.singularities) w.number(static_cast<double>(s.second) / data.degree).end_line();
  for(std::size_t f = 0; f < layout.faces.size(); ++f) w.text("0\n");
}

inline void write_VTU_array_header(Number_writer& w, const std::string& name, int components)
{
  w.text("<DataArray type=\"Float64\" Name=\"").text(name).text("\" NumberOfComponents=\"").integer(components)
    .text("\" format=\"ascii\">\n");
}

// The point data of write_VTU().
inline void write_VTU_point_arrays(Number_writer& w, const Direction_field_data& data, const VTK_layout& layout)
{
  write_VTU_array_header(w, "singularity_index", 1);
  layout.for_each_point(data, [&](const Vec3&, const Vec3&, double index, std::size_t) { w.number(index).end_line(); });
  w.text("</DataArray>\n");
  write_VTU_array_header(w, "normals", 3);
  layout.for_each_point(data, [&](const Vec3&, const Vec3& n, double, std::size_t) { w.line(n[0], n[1], n[2]); });
  w.text("</DataArray>\n");
  for(int k = 0; k < data.degree; ++k)
  {
    write_VTU_array_header(w, "direction_" + std::to_string(k), 3);
    write_directions(w, data, layout, k);
    w.text("</DataArray>\n");
  }
  if(data.magnitudes.empty()) return;
  write_VTU_array_header(w, "magnitude", 1);
  write_magnitudes(w, data, layout);
  w.text("</DataArray>\n");
}

} // namespace internal

namespace IO {

/// \name VTK
/// @{

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the field as a legacy VTK PolyData file (ASCII), which ParaView and
VTK open. Points: the vertices that belong to a face (renumbered in their
order; a vertex of no face is left out), then the barycentre of each singular
face, with one `VERTICES` cell each; cells: those vertices, then the
triangles (`POLYGONS`). Data:
- field data `degree` (the integer `n`);
- point data `singularity_index` (the active scalars: the index `k / n` on the
  singularity points, 0 on the vertices), `normals` (the active normals),
  `direction_0` ... `direction_{n-1}` (`direction_0` is the active vectors;
  zero on the singularity points), and `magnitude` (if known) as a plain
  array, so that it is not taken for the glyphs' scale;
- cell data `singularity_index` (the same index on the singularity cells, 0 on
  the triangles).

Coordinates are written with 17 significant digits, so that reading back gives
the same doubles.

\param os the output stream
\param data the field to write
*/
inline void write_VTK(std::ostream& os, const Direction_field_data& data)
{
  const internal::VTK_layout layout(data);
  const long long nv = layout.vertices(), ns = layout.singular_points(data), nf = layout.triangles();
  internal::Number_writer w(os);
  w.text("# vtk DataFile Version 3.0\ndirection field of degree ").integer(data.degree)
    .text(" (CGAL Surface_mesh_direction_fields)\nASCII\nDATASET POLYDATA\nFIELD FieldData 1\ndegree 1 1 int\n")
    .integer(data.degree).end_line();
  w.text("POINTS ").integer(nv + ns).text(" double\n");
  layout.for_each_point(data, [&](const internal::Vec3& p, const internal::Vec3&, double, std::size_t) {
    w.line(p[0], p[1], p[2]);
  });
  if(ns > 0)
  {
    w.text("VERTICES ").integer(ns).space().integer(2 * ns).end_line();
    for(long long i = 0; i < ns; ++i) w.text("1 ").integer(nv + i).end_line();
  }
  w.text("POLYGONS ").integer(nf).space().integer(4 * nf).end_line();
  for(const auto& t : layout.faces)
    w.text("3 ").integer(static_cast<long long>(t[0])).space().integer(static_cast<long long>(t[1])).space()
      .integer(static_cast<long long>(t[2])).end_line();
  w.text("POINT_DATA ").integer(nv + ns).text("\nSCALARS singularity_index double 1\nLOOKUP_TABLE default\n");
  layout.for_each_point(data, [&](const internal::Vec3&, const internal::Vec3&, double index, std::size_t) {
    w.number(index).end_line();
  });
  w.text("NORMALS normals double\n");
  layout.for_each_point(data, [&](const internal::Vec3&, const internal::Vec3& n, double, std::size_t) {
    w.line(n[0], n[1], n[2]);
  });
  for(int k = 0; k < data.degree; ++k)
  {
    w.text("VECTORS direction_").integer(k).text(" double\n");
    internal::write_directions(w, data, layout, k);
  }
  if(!data.magnitudes.empty())
  {
    w.text("FIELD point_arrays 1\nmagnitude 1 ").integer(nv + ns).text(" double\n");
    internal::write_magnitudes(w, data, layout);
  }
  // cells are ordered vertices first, then polygons
  w.text("CELL_DATA ").integer(ns + nf).text("\nSCALARS singularity_index double 1\nLOOKUP_TABLE default\n");
  internal::write_cell_indices(w, data, layout);
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the field as a VTK XML UnstructuredGrid file (`.vtu`, ASCII), which
ParaView, VTK and meshio open. It holds what `write_VTK()` writes, the same
points, cells (VTK_VERTEX cells for the singularities, VTK_TRIANGLE cells for
the faces) and arrays, with `singularity_index`, `direction_0` and `normals` as
the active scalars, vectors and normals.

\param os the output stream
\param data the field to write
*/
inline void write_VTU(std::ostream& os, const Direction_field_data& data)
{
  const internal::VTK_layout layout(data);
  const long long nv = layout.vertices(), ns = layout.singular_points(data), nf = layout.triangles();
  internal::Number_writer w(os);
  w.text("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "<UnstructuredGrid>\n<FieldData>\n"
         "<DataArray type=\"Int32\" Name=\"degree\" NumberOfTuples=\"1\" format=\"ascii\">")
    .integer(data.degree).text("</DataArray>\n</FieldData>\n<Piece NumberOfPoints=\"").integer(nv + ns)
    .text("\" NumberOfCells=\"").integer(ns + nf)
    .text("\">\n<PointData Scalars=\"singularity_index\" Vectors=\"direction_0\" Normals=\"normals\">\n");
  internal::write_VTU_point_arrays(w, data, layout);
  w.text("</PointData>\n<CellData Scalars=\"singularity_index\">\n"
         "<DataArray type=\"Float64\" Name=\"singularity_index\" format=\"ascii\">\n");
  internal::write_cell_indices(w, data, layout);
  w.text("</DataArray>\n</CellData>\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  layout.for_each_point(data, [&](const internal::Vec3& p, const internal::Vec3&, double, std::size_t) {
    w.line(p[0], p[1], p[2]);
  });
  w.text("</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for(long long i = 0; i < ns; ++i) w.integer(nv + i).end_line();
  for(const auto& t : layout.faces)
    w.integer(static_cast<long long>(t[0])).space().integer(static_cast<long long>(t[1])).space()
      .integer(static_cast<long long>(t[2])).end_line();
  w.text("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for(long long i = 1; i <= ns; ++i) w.integer(i).end_line();
  for(long long f = 1; f <= nf; ++f) w.integer(ns + 3 * f).end_line();
  w.text("</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for(long long i = 0; i < ns; ++i) w.text("1\n");  // VTK_VERTEX
  for(long long f = 0; f < nf; ++f) w.text("5\n");  // VTK_TRIANGLE
  w.text("</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

reads a file written by `write_VTK()` back. The singular faces are recovered
by matching each singularity point to the barycentre of a face (they are
written from it); the per-face directions are recomputed by
`face_directions()`.

\throws Invalid_input_error if the stream is not such a file
\param is the input stream
\returns the field read
*/
inline Direction_field_data read_VTK(std::istream& is)
{
  Direction_field_data data;
  data.degree = internal::read_VTK_degree(is);
  const internal::VTK_cells cells = internal::read_VTK_geometry(is, data);
  const std::vector<double> singularity_values = internal::read_VTK_data(is, cells, data);
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
  internal::match_singular_faces(singularity_values, data);
  data.face_directions = face_directions(data);
  return data;
}

/// @}

/// \name PLY
/// @{

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the field as an ASCII PLY file: per vertex `x y z`, the first
direction `dx dy dz`, and `magnitude` (if known); per face its
`vertex_indices` and `singularity` (the integer `k` of its index `k / n`).
The degree is in the comment `direction_field_degree n`. Readers that do not
know the extra properties (e.g. `CGAL::IO::read_PLY()` into a
`Surface_mesh`, which keeps them as property maps `v:dx`, ...) still read the mesh.

\param os the output stream
\param data the field to write
*/
inline void write_PLY(std::ostream& os, const Direction_field_data& data)
{
  const bool has_magnitude = !data.magnitudes.empty();
  std::vector<int> singularity(data.faces.size(), 0);
  for(const auto& s : data.singularities) singularity[s.first] = s.second;
  os << std::setprecision(17);
  os << "ply\nformat ascii 1.0\ncomment CGAL Surface_mesh_direction_fields\n"
     << "comment direction_field_degree " << data.degree << "\n"
     << "element vertex " << data.points.size() << "\n"
     << "property double x\nproperty double y\nproperty double z\n"
     << "property double dx\nproperty double dy\nproperty double dz\n";
  if(has_magnitude) os << "property double magnitude\n";
  os << "element face " << data.faces.size() << "\n"
     << "property list uchar int vertex_indices\nproperty int singularity\nend_header\n";
  internal::Number_writer w(os);
  for(std::size_t v = 0; v < data.points.size(); ++v)
  {
    const auto& p = data.points[v];
    const auto& d = data.directions[v][0];
    w.number(p[0]).space().number(p[1]).space().number(p[2]).space();
    w.number(d[0]).space().number(d[1]).space().number(d[2]);
    if(has_magnitude) w.space().number(data.magnitudes[v]);
    w.end_line();
  }
  for(std::size_t f = 0; f < data.faces.size(); ++f)
    w.text("3 ").integer(static_cast<long long>(data.faces[f][0])).space().integer(static_cast<long long>(data.faces[f][1]))
      .space().integer(static_cast<long long>(data.faces[f][2])).space().integer(singularity[f]).end_line();
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

reads a file written by `write_PLY()` back; the `n` directions of each vertex
are rebuilt from the first one by rotation about the angle-weighted vertex
normal of the file's mesh (as `make_direction_field_data()` does).

\throws Invalid_input_error if the stream is not such a file
\param is the input stream
\returns the field read
*/
inline Direction_field_data read_PLY(std::istream& is)
{
  using internal::next_value;
  using internal::parse_value;
  const char* kind = "PLY";
  Direction_field_data data;
  std::string line;
  std::size_t nv = 0, nf = 0;
  bool has_magnitude = false, degree_found = false;
  if(!std::getline(is, line) || line.rfind("ply", 0) != 0) throw Invalid_input_error("not a PLY file");
  while(std::getline(is, line))
  {
    std::istringstream ls(line);
    std::string a, b, c;
    ls >> a >> b >> c;
    if(a == "format" && b != "ascii") throw Invalid_input_error("PLY file: only ASCII is read");
    if(a == "comment" && b == "direction_field_degree") { data.degree = parse_value<int>(c, kind); degree_found = true; }
    if(a == "element" && b == "vertex") nv = parse_value<std::size_t>(c, kind);
    if(a == "element" && b == "face") nf = parse_value<std::size_t>(c, kind);
    if(a == "property" && c == "magnitude") has_magnitude = true;
    if(a == "end_header") break;
  }
  if(!degree_found) throw Invalid_input_error("PLY file: no 'comment direction_field_degree'");
  if(nv > (std::size_t(1) << 32) || nf > (std::size_t(1) << 32))
    throw Invalid_input_error("PLY file: implausible element count");
  internal::check_degree(data.degree);
  data.points.resize(nv);
  std::vector<internal::Vec3> first(nv);
  if(has_magnitude) data.magnitudes.resize(nv);
  for(std::size_t v = 0; v < nv; ++v)
  {
    for(double& x : data.points[v]) x = next_value<double>(is, kind);
    for(double& x : first[v]) x = next_value<double>(is, kind);
    if(has_magnitude) data.magnitudes[v] = next_value<double>(is, kind);
  }
  data.faces.resize(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(next_value<int>(is, kind) != 3) throw Invalid_input_error("PLY file: a face is not a triangle");
    for(auto& c : data.faces[f])
    {
      c = next_value<std::size_t>(is, kind);
      if(c >= nv) throw Invalid_input_error("PLY file: a vertex index is out of range");
    }
    const int k = next_value<int>(is, kind);
    if(k != 0)
    {
      data.singularities.emplace_back(f, k);
      data.singularity_points.push_back(internal::barycentre(data.points, data.faces[f]));
    }
  }
  // the other directions: rotations about the angle-weighted normal
  internal::complete_directions(data, internal::angle_weighted_normals(data.points, data.faces), first);
  data.face_directions = face_directions(data);
  return data;
}

/// @}

/// \name Per-face formats for quad meshing
/// @{

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the per-face field (`data.face_directions`) as a `.rosy` file as read by
vcglib's `ImporterFIELD::Load4ROSY()` (and QuadWild): the number of faces,
the degree `n`, then one direction `x y z` per face. vcglib reads `n = 4` only.

\param os the output stream
\param data the field to write
*/
inline void write_rosy(std::ostream& os, const Direction_field_data& data)
{
  os << std::setprecision(17);
  os << data.faces.size() << "\n" << data.degree << "\n";
  internal::Number_writer w(os);
  for(const auto& d : data.face_directions) w.line(d[0], d[1], d[2]);
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

reads a `.rosy` file: sets `degree` and `face_directions` of `data` (whose
mesh must have as many faces as the file).

\throws Invalid_input_error if the file does not match
\param is the input stream
\param data receives what the file holds
*/
inline void read_rosy(std::istream& is, Direction_field_data& data)
{
  using internal::next_value;
  const std::size_t nf = next_value<std::size_t>(is, "rosy");
  if(!data.faces.empty() && nf != data.faces.size())
    throw Invalid_input_error("rosy file: " + std::to_string(nf) + " faces for a mesh of " +
                              std::to_string(data.faces.size()));
  if(nf > (std::size_t(1) << 32)) throw Invalid_input_error("rosy file: implausible face count");
  data.degree = next_value<int>(is, "rosy");
  internal::check_degree(data.degree);
  data.face_directions.resize(nf);
  for(auto& d : data.face_directions) for(double& x : d) x = next_value<double>(is, "rosy");
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the per-face field as an `.ffield` file as read by vcglib's
`ImporterFIELD::LoadFFIELD()` (a cross per face, given by two orthogonal
unit vectors): a comment line, `target frame`, the number of faces, a header
line, then per face `1 1` and the two vectors: the face's direction and its
rotation by \f$ 90^\circ \f$ in the face plane. This describes the field exactly for
`n = 4` (and the line or vector field's cross otherwise).

\param os the output stream
\param data the field to write
*/
inline void write_ffield(std::ostream& os, const Direction_field_data& data)
{
  using internal::Vec3;
  os << std::setprecision(17);
  os << "# frame generated by CGAL Surface_mesh_direction_fields, degree " << data.degree << "\n"
     << "target frame\n" << data.faces.size() << "\n"
     << "k1 k2 k1v_x k1v_y k1v_z k2v_x k2v_y k2v_z\n";
  internal::Number_writer out(os);
  for(std::size_t f = 0; f < data.faces.size(); ++f)
  {
    const auto& t = data.faces[f];
    const Vec3 normal = internal::triangle_unit_normal(data.points, t);
    const Vec3& u = data.face_directions[f];
    const Vec3 w = internal::cross(normal, u);
    out.text("1 1 ").number(u[0]).space().number(u[1]).space().number(u[2]).space();
    out.line(w[0], w[1], w[2]);
  }
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

reads an `.ffield` file: sets `face_directions` of `data` to the first vector
of each face (normalized).

\throws Invalid_input_error if the file does not match
\param is the input stream
\param data receives what the file holds
*/
inline void read_ffield(std::istream& is, Direction_field_data& data)
{
  using internal::next_value;
  std::string line;
  if(!std::getline(is, line) || line.empty() || line[0] != '#') throw Invalid_input_error("not an ffield file");
  std::getline(is, line);  // "target frame"
  const std::size_t nf = next_value<std::size_t>(is, "ffield");
  if(nf > (std::size_t(1) << 32)) throw Invalid_input_error("ffield file: implausible face count");
  if(!data.faces.empty() && nf != data.faces.size())
    throw Invalid_input_error("ffield file: " + std::to_string(nf) + " faces for a mesh of " +
                              std::to_string(data.faces.size()));
  std::getline(is, line);
  std::getline(is, line);  // the header line
  data.face_directions.resize(nf);
  for(auto& d : data.face_directions)
  {
    next_value<double>(is, "ffield");
    next_value<double>(is, "ffield");
    for(double& x : d) x = next_value<double>(is, "ffield");
    for(int i = 0; i < 3; ++i) next_value<double>(is, "ffield");
    d = internal::normalized(d);
  }
}

/// @}

/// \name Singularities
/// @{

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the singularities as text: a comment line, then one line per singular
face: `face k n x y z` (its index is `k / n`; `x y z` is its barycentre).

\param os the output stream
\param data the field to write
*/
inline void write_singularities(std::ostream& os, const Direction_field_data& data)
{
  os << std::setprecision(17);
  os << "# face k n x y z   (index k/n at the barycentre x y z)\n";
  for(std::size_t i = 0; i < data.singularities.size(); ++i)
  {
    const auto& p = data.singularity_points[i];
    os << data.singularities[i].first << " " << data.singularities[i].second << " " << data.degree << " " << p[0]
       << " " << p[1] << " " << p[2] << "\n";
  }
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

reads a file written by `write_singularities()`: sets `singularities`,
`singularity_points` and `degree` of `data`.

\throws Invalid_input_error on a malformed line
\param is the input stream
\param data receives what the file holds
*/
inline void read_singularities(std::istream& is, Direction_field_data& data)
{
  data.singularities.clear();
  data.singularity_points.clear();
  std::string line;
  std::size_t number = 0;
  while(std::getline(is, line))
  {
    ++number;
    if(line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::size_t f;
    int k, n;
    std::array<double, 3> p;
    if(!(ls >> f >> k >> n >> p[0] >> p[1] >> p[2]))
      throw Invalid_input_error("singularities file: line " + std::to_string(number) + " is malformed");
    data.degree = n;
    data.singularities.emplace_back(f, k);
    data.singularity_points.push_back(p);
  }
}

/// @}

} // namespace IO
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_DIRECTION_FIELD_FILES_H
