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
  if(components > 3 * static_cast<std::size_t>(maximum_degree) || tuples > (std::size_t(1) << 32)) throw Invalid_input_error("VTK file: implausible array size");
  // grown as values are read: a count beyond the stream's end fails on the missing values, not on memory
  std::vector<double> values;
  values.reserve((std::min)(components * tuples, std::size_t(1) << 20));
  for(std::size_t i = 0; i < components * tuples; ++i) values.push_back(next_value<double>(is, kind));
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
  bool unstructured = false;  // this version's files: the singular triangles marked in the cell data
};

// The triangles of a legacy UNSTRUCTURED_GRID (CELLS, then CELL_TYPES).
inline void read_VTK_triangle_cells(std::istream& is, VTK_cells& cells, Direction_field_data& data)
{
  const char* kind = "VTK";
  expect(is, "CELLS", kind);
  cells.faces = next_value<std::size_t>(is, kind);
  next_value<std::size_t>(is, kind);
  if(cells.faces > (std::size_t(1) << 32)) throw Invalid_input_error("VTK file: implausible number of cells");
  data.faces.resize(cells.faces);
  for(auto& t : data.faces)
  {
    if(next_value<int>(is, kind) != 3) throw Invalid_input_error("VTK file: a cell is not a triangle");
    for(auto& c : t)
      if((c = next_value<std::size_t>(is, kind)) >= cells.points)
        throw Invalid_input_error("VTK file: a vertex index is out of range");
  }
  expect(is, "CELL_TYPES", kind);
  if(next_value<std::size_t>(is, kind) != cells.faces) throw Invalid_input_error("VTK file: CELL_TYPES miscounted");
  for(std::size_t f = 0; f < cells.faces; ++f)
    if(next_value<int>(is, kind) != 5) throw Invalid_input_error("VTK file: a cell is not a triangle");
}

// The VERTICES of the singularity points and the triangles (POLYGONS) of
// the PolyData files of earlier versions.
inline void read_VTK_polydata_cells(std::istream& is, VTK_cells& cells, std::vector<Vec3>& points,
                                    Direction_field_data& data)
{
  const char* kind = "VTK";
  std::string word = next_token(is, kind);
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
  data.singularity_points.assign(points.begin() + static_cast<std::ptrdiff_t>(nv), points.end());
  points.resize(nv);
  data.faces.resize(cells.faces);
  for(auto& t : data.faces)
  {
    if(next_value<int>(is, kind) != 3) throw Invalid_input_error("VTK file: a polygon is not a triangle");
    for(auto& c : t)
      if((c = next_value<std::size_t>(is, kind)) >= nv) throw Invalid_input_error("VTK file: a vertex index is out of range");
  }
}

// POINTS and the cells: data.points, data.faces (and, in PolyData files,
// data.singularity_points).
inline VTK_cells read_VTK_geometry(std::istream& is, Direction_field_data& data)
{
  const char* kind = "VTK";
  expect(is, "ASCII", kind);
  expect(is, "DATASET", kind);
  VTK_cells cells;
  const std::string type = next_token(is, kind);
  if(type != "UNSTRUCTURED_GRID" && type != "POLYDATA") throw Invalid_input_error("VTK file: unexpected " + type);
  cells.unstructured = type == "UNSTRUCTURED_GRID";
  std::string word = next_token(is, kind);
  if(word == "FIELD")  // the dataset's field data (the degree, already read from the title)
  {
    next_token(is, kind);
    const std::size_t arrays = next_value<std::size_t>(is, kind);
    for(std::size_t a = 0; a < arrays; ++a) skip_VTK_field_array(is);
    word = next_token(is, kind);
  }
  if(word != "POINTS") throw Invalid_input_error("VTK file: expected POINTS");
  cells.points = next_value<std::size_t>(is, kind);
  if(cells.points > (std::size_t(1) << 32)) throw Invalid_input_error("VTK file: implausible number of points");
  next_token(is, kind);  // type
  std::vector<Vec3> points(cells.points);
  for(auto& p : points) for(double& x : p) x = next_value<double>(is, kind);
  if(cells.unstructured) read_VTK_triangle_cells(is, cells, data);
  else read_VTK_polydata_cells(is, cells, points, data);
  data.points = std::move(points);
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
  else if(name == "singularity_index")  // per cell
  {
    std::vector<double> cell_values(cells.singularities + cells.faces);
    for(double& value : cell_values) value = next_value<double>(is, kind);
    if(cells.unstructured) singularity_values = std::move(cell_values);  // one per triangle
    else if(singularity_values.empty())  // PolyData files before the point data had it: the singularity cells first
      singularity_values.assign(cell_values.begin(), cell_values.begin() + static_cast<std::ptrdiff_t>(cells.singularities));
  }
  else throw Invalid_input_error("VTK file: unexpected data " + name);
}

// The k-th direction of every point, from the array "direction_k".
inline void read_VTK_direction(const std::string& name, const std::vector<double>& values, Direction_field_data& data)
{
  const int k = parse_value<int>(name.substr(name.find('_') + 1), "VTK");
  if(k < 0 || k >= data.degree) throw Invalid_input_error("VTK file: unexpected " + name);
  for(std::size_t v = 0; v < data.directions.size(); ++v)
    data.directions[v][static_cast<std::size_t>(k)] = {values[3 * v], values[3 * v + 1], values[3 * v + 2]};
}

// POINT_DATA and CELL_DATA: the directions, the magnitudes, and the
// singularity indices (returned): one per triangle in this version's files,
// one per singularity point in PolyData files.
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
    if(word == "VECTORS")  // direction_k of every point (a PolyData file's singularity points last, not kept)
    {
      const std::string name = next_token(is, kind);
      next_token(is, kind);
      std::vector<double> values(3 * cells.points);
      for(double& x : values) x = next_value<double>(is, kind);
      read_VTK_direction(name, values, data);
    }
    else if(word == "SCALARS")
      read_VTK_scalars(is, next_token(is, kind), cells, cell_data, data, singularity_values);
    else if(word == "NORMALS")  // recomputed below, as the reader of a file without them does
    {
      next_token(is, kind);
      next_token(is, kind);
      for(std::size_t i = 0; i < 3 * cells.points; ++i) next_value<double>(is, kind);
    }
    else if(word == "FIELD")  // the arrays that are not attributes: the magnitudes, the directions after the first
    {
      next_token(is, kind);
      const std::size_t arrays = next_value<std::size_t>(is, kind);
      for(std::size_t a = 0; a < arrays; ++a)
      {
        std::string name;
        const std::vector<double> values = read_VTK_field_array(is, name);
        if(cell_data && name == "singularity_index" && cells.unstructured && values.size() == cells.faces)
          singularity_values = values;  // one per triangle
        else if(cell_data) continue;
        else if(name == "magnitude" && values.size() == cells.points)
          data.magnitudes.assign(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(nv));
        else if(name.rfind("direction_", 0) == 0 && values.size() == 3 * cells.points)
          read_VTK_direction(name, values, data);
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

// The singular faces of this version's files: the triangles whose index is not 0.
inline void singular_faces_from_cells(const std::vector<double>& face_values, Direction_field_data& data)
{
  if(face_values.size() != data.faces.size()) throw Invalid_input_error("VTK file: no singularity_index per triangle");
  for(std::size_t f = 0; f < face_values.size(); ++f)
  {
    const double k = face_values[f] * data.degree;
    if(!(std::abs(k) < 1e9) || std::abs(k - std::round(k)) > 1e-6)
      throw Invalid_input_error("VTK file: a singularity_index is not a multiple of 1/n");
    if(std::lround(k) == 0) continue;
    data.singularities.emplace_back(f, static_cast<int>(std::lround(k)));
    data.singularity_points.push_back(barycentre(data.points, data.faces[f]));
  }
}

// The singular faces of PolyData files: the face whose barycentre is the
// singularity point (the writer wrote it from there).
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

// A dataset as both VTK formats write it: points, cells (flat
// connectivity, the end of each cell, its VTK type) and named arrays, the
// active ones named apart.
struct VTK_array
{
  std::string name;
  int components = 1;
  std::vector<double> values;  // tuple after tuple
};

struct VTK_grid
{
  std::string title;  // the legacy file's second line
  int degree = 1;     // field data "degree"
  std::vector<Vec3> points;
  std::vector<long long> connectivity, cell_ends;
  std::vector<int> cell_types;  // 1 vertex, 3 line, 4 poly-line, 5 triangle
  std::vector<VTK_array> point_arrays, cell_arrays;
  std::string point_scalars, point_vectors, point_normals, cell_scalars;  // active attributes ("" = none)

  void add_cell(std::initializer_list<long long> ids, int type)
  {
    connectivity.insert(connectivity.end(), ids.begin(), ids.end());
    cell_ends.push_back(static_cast<long long>(connectivity.size()));
    cell_types.push_back(type);
  }
  long long cell_count() const { return static_cast<long long>(cell_ends.size()); }
};

inline void write_VTK_values(Number_writer& w, const VTK_array& a)
{
  for(std::size_t i = 0; i < a.values.size(); ++i)
  {
    w.number(a.values[i]);
    if((i + 1) % static_cast<std::size_t>(a.components) == 0) w.end_line(); else w.space();
  }
}

inline void write_legacy_cells(Number_writer& w, const VTK_grid& g)
{
  w.text("CELLS ").integer(g.cell_count()).space()
    .integer(g.cell_count() + static_cast<long long>(g.connectivity.size())).end_line();
  long long begin = 0;
  for(long long end : g.cell_ends)
  {
    w.integer(end - begin);
    for(long long i = begin; i < end; ++i) w.space().integer(g.connectivity[static_cast<std::size_t>(i)]);
    w.end_line();
    begin = end;
  }
  w.text("CELL_TYPES ").integer(g.cell_count()).end_line();
  for(int type : g.cell_types) w.integer(type).end_line();
}

// One block of legacy data: the active attributes by their keywords, every
// other array in a FIELD block (which VTK's reader returns by default, as
// it does not the VECTORS after the first).
inline void write_legacy_data(Number_writer& w, const char* block, long long tuples,
                              const std::vector<VTK_array>& arrays, const std::string& scalars,
                              const std::string& vectors, const std::string& normals)
{
  if(arrays.empty()) return;
  w.text(block).space().integer(tuples).end_line();
  std::size_t plain = 0;
  for(const VTK_array& a : arrays)
  {
    if(a.name == scalars) w.text("SCALARS ").text(a.name).text(" double 1\nLOOKUP_TABLE default\n");
    else if(a.name == vectors) w.text("VECTORS ").text(a.name).text(" double\n");
    else if(a.name == normals) w.text("NORMALS ").text(a.name).text(" double\n");
    else { ++plain; continue; }
    write_VTK_values(w, a);
  }
  if(plain == 0) return;
  w.text("FIELD ").text(block[0] == 'P' ? "point_arrays " : "cell_arrays ").integer(static_cast<long long>(plain))
    .end_line();
  for(const VTK_array& a : arrays)
    if(a.name != scalars && a.name != vectors && a.name != normals)
    {
      w.text(a.name).space().integer(a.components).space().integer(tuples).text(" double\n");
      write_VTK_values(w, a);
    }
}

// The legacy format as an UNSTRUCTURED_GRID (ParaView, VTK and meshio read it).
inline void write_legacy_grid(std::ostream& os, const VTK_grid& g)
{
  Number_writer w(os);
  const long long np = static_cast<long long>(g.points.size());
  w.text("# vtk DataFile Version 3.0\n").text(g.title).text("\nASCII\nDATASET UNSTRUCTURED_GRID\n")
    .text("FIELD FieldData 1\ndegree 1 1 int\n").integer(g.degree).end_line();
  w.text("POINTS ").integer(np).text(" double\n");
  for(const Vec3& p : g.points) w.line(p[0], p[1], p[2]);
  write_legacy_cells(w, g);
  // the normals as a plain array: meshio's legacy reader refuses a NORMALS block
  write_legacy_data(w, "POINT_DATA", np, g.point_arrays, g.point_scalars, g.point_vectors, "");
  write_legacy_data(w, "CELL_DATA", g.cell_count(), g.cell_arrays, g.cell_scalars, "", "");
}

inline void write_XML_arrays(Number_writer& w, const char* block, const std::vector<VTK_array>& arrays,
                             const std::string& scalars, const std::string& vectors, const std::string& normals)
{
  w.text("<").text(block);
  if(!scalars.empty()) w.text(" Scalars=\"").text(scalars).text("\"");
  if(!vectors.empty()) w.text(" Vectors=\"").text(vectors).text("\"");
  if(!normals.empty()) w.text(" Normals=\"").text(normals).text("\"");
  w.text(">\n");
  for(const VTK_array& a : arrays)
  {
    w.text("<DataArray type=\"Float64\" Name=\"").text(a.name);
    if(a.components > 1) w.text("\" NumberOfComponents=\"").integer(a.components);  // else meshio adds an axis
    w.text("\" format=\"ascii\">\n");
    write_VTK_values(w, a);
    w.text("</DataArray>\n");
  }
  w.text("</").text(block).text(">\n");
}

// The XML UnstructuredGrid format (.vtu).
inline void write_XML_grid(std::ostream& os, const VTK_grid& g)
{
  Number_writer w(os);
  w.text("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "<UnstructuredGrid>\n<FieldData>\n"
         "<DataArray type=\"Int32\" Name=\"degree\" NumberOfTuples=\"1\" format=\"ascii\">")
    .integer(g.degree).text("</DataArray>\n</FieldData>\n<Piece NumberOfPoints=\"")
    .integer(static_cast<long long>(g.points.size())).text("\" NumberOfCells=\"").integer(g.cell_count()).text("\">\n");
  write_XML_arrays(w, "PointData", g.point_arrays, g.point_scalars, g.point_vectors, g.point_normals);
  write_XML_arrays(w, "CellData", g.cell_arrays, g.cell_scalars, "", "");
  w.text("<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for(const Vec3& p : g.points) w.line(p[0], p[1], p[2]);
  w.text("</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for(long long id : g.connectivity) w.integer(id).end_line();
  w.text("</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for(long long end : g.cell_ends) w.integer(end).end_line();
  w.text("</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for(int type : g.cell_types) w.integer(type).end_line();
  w.text("</DataArray>\n</Cells>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
}

// The field as a dataset: the vertices that belong to a face (renumbered in
// their order) and the triangles. Every point carries real directions (the
// singularities are marked on their triangles, not by extra points), and no
// array is the active scalars: ParaView's glyph filter takes them as its
// scale array (point scalars shrink the arrows to nothing, cell scalars make
// it draw none).
inline VTK_grid field_grid(const Direction_field_data& data)
{
  VTK_grid g;
  g.title = "direction field of degree " + std::to_string(data.degree) + " (CGAL Surface_mesh_direction_fields)";
  g.degree = data.degree;
  const std::size_t none = std::numeric_limits<std::size_t>::max(), n = static_cast<std::size_t>(data.degree);
  std::vector<std::size_t> number(data.points.size(), none), used;
  for(const auto& t : data.faces) for(std::size_t v : t) number[v] = 0;
  for(std::size_t v = 0; v < number.size(); ++v)
    if(number[v] != none) { number[v] = used.size(); used.push_back(v); }
  for(std::size_t v : used) g.points.push_back(data.points[v]);
  for(const auto& t : data.faces)
    g.add_cell({static_cast<long long>(number[t[0]]), static_cast<long long>(number[t[1]]),
                static_cast<long long>(number[t[2]])}, 5);
  VTK_array normals{"normals", 3, {}}, all{"directions", 3 * data.degree, {}}, magnitude{"magnitude", 1, {}};
  std::vector<VTK_array> direction(n);
  for(std::size_t k = 0; k < n; ++k) direction[k] = VTK_array{"direction_" + std::to_string(k), 3, {}};
  for(std::size_t v : used)
  {
    const Vec3 normal = data.normals.empty() ? Vec3{0., 0., 0.} : data.normals[v];
    normals.values.insert(normals.values.end(), normal.begin(), normal.end());
    for(std::size_t k = 0; k < n; ++k)
    {
      const Vec3& d = data.directions[v][k];
      direction[k].values.insert(direction[k].values.end(), d.begin(), d.end());
      all.values.insert(all.values.end(), d.begin(), d.end());
    }
    if(!data.magnitudes.empty()) magnitude.values.push_back(data.magnitudes[v]);
  }
  g.point_arrays.push_back(std::move(normals));
  for(VTK_array& a : direction) g.point_arrays.push_back(std::move(a));
  g.point_arrays.push_back(std::move(all));
  if(!data.magnitudes.empty()) g.point_arrays.push_back(std::move(magnitude));
  VTK_array index{"singularity_index", 1, std::vector<double>(data.faces.size(), 0.)};
  for(const auto& s : data.singularities) index.values[s.first] = static_cast<double>(s.second) / data.degree;
  g.cell_arrays.push_back(std::move(index));
  g.point_vectors = "direction_0";
  g.point_normals = "normals";
  return g;
}

// The singularities as markers a viewer shows without a filter: a small
// octahedron (radius 1/100 of the bounding box's diagonal) around each
// singular face's barycentre, its index k / n on its points and triangles
// (the active scalars, so that a viewer colours them by it).
inline VTK_grid singularity_marker_grid(const Direction_field_data& data)
{
  VTK_grid g;
  g.title = "singularities of a direction field of degree " + std::to_string(data.degree) +
            " (CGAL Surface_mesh_direction_fields)";
  g.degree = data.degree;
  const std::array<Vec3, 2> box = bounding_box(data.points);
  const Vec3 diagonal = box[1] - box[0];
  double length = norm(diagonal);
  if(!std::isfinite(length))  // its square overflowed (coordinates near 1e300)
    length = std::hypot(std::hypot(diagonal[0], diagonal[1]), diagonal[2]);
  const double radius = 0.01 * length;
  VTK_array point_index{"singularity_index", 1, {}}, cell_index{"singularity_index", 1, {}};
  for(std::size_t i = 0; i < data.singularities.size(); ++i)
  {
    const double index = static_cast<double>(data.singularities[i].second) / data.degree;
    const Vec3 centre = barycentre(data.points, data.faces[data.singularities[i].first]);
    const long long first = static_cast<long long>(g.points.size());
    for(int axis = 0; axis < 3; ++axis)
      for(double sign : {1., -1.})
      {
        Vec3 p = centre;
        p[axis] += sign * radius;
        g.points.push_back(p);
        point_index.values.push_back(index);
      }
    // corners 0/1: +x/-x, 2/3: +y/-y, 4/5: +z/-z; the eight faces outward
    for(const auto& t : {std::array<int, 3>{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5},
                         {0, 3, 5}})
    {
      g.add_cell({first + t[0], first + t[1], first + t[2]}, 5);
      cell_index.values.push_back(index);
    }
  }
  g.point_arrays.push_back(std::move(point_index));
  g.cell_arrays.push_back(std::move(cell_index));
  g.point_scalars = g.cell_scalars = "singularity_index";
  return g;
}

} // namespace internal

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
face a small octahedron (of radius 1/100 of the bounding box's diagonal),
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
triangles whose `singularity_index` is not 0. The PolyData files of earlier
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
  if(cells.unstructured) internal::singular_faces_from_cells(singularity_values, data);
  else internal::match_singular_faces(singularity_values, data);
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
