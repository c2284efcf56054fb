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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_INTERNAL_VTK_READING_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_INTERNAL_VTK_READING_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_data.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/number_writer.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>
#include <CGAL/Surface_mesh_direction_fields/IO/internal/file_tokens.h>

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

// The pieces of IO::read_VTK(), in the order of the file.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

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

// The values of the VTK file's data besides those stored in data: the
// singularity indices, one per triangle in this version's files of vertex
// fields, one per singularity point in PolyData files; one per point in the
// files of fields on faces.
struct VTK_singularity_values
{
  std::vector<double> of_cells_or_markers, of_points;
};

// POINT_DATA and CELL_DATA: the directions (per point, or per cell for a
// field on faces), the magnitudes, and the singularity indices.
inline VTK_singularity_values read_VTK_data(std::istream& is, const VTK_cells& cells, Direction_field_data& data)
{
  const char* kind = "VTK";
  const std::size_t nv = cells.points - cells.singularities;
  expect(is, "POINT_DATA", kind);
  next_value<std::size_t>(is, kind);
  data.directions.assign(nv, std::vector<Vec3>(static_cast<std::size_t>(data.degree)));
  VTK_singularity_values singular;
  std::vector<double>& singularity_values = singular.of_cells_or_markers;
  std::string word;
  bool cell_data = false;
  while(is >> word)
  {
    if(word == "VECTORS" && cell_data)  // a field on faces: direction_0 of every triangle
    {
      if(next_token(is, kind) != "direction_0") throw Invalid_input_error("VTK file: unexpected cell vectors");
      next_token(is, kind);
      data.face_directions.resize(cells.faces);
      for(Vec3& d : data.face_directions) for(double& x : d) x = next_value<double>(is, kind);
    }
    else if(word == "VECTORS")  // direction_k of every point (a PolyData file's singularity points last, not kept)
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
        else if(name == "singularity_index" && values.size() == cells.points)  // a field on faces
          singular.of_points = values;
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
  return singular;
}

// The integer k of a singularity_index k / n.
inline int integer_index(double value, int degree)
{
  const double k = value * degree;
  if(!(std::abs(k) < 1e9) || std::abs(k - std::round(k)) > 1e-6)
    throw Invalid_input_error("VTK file: a singularity_index is not a multiple of 1/n");
  return static_cast<int>(std::lround(k));
}

// The singular vertices of a field on faces: the points whose index is not 0.
inline void singular_vertices_from_points(const std::vector<double>& point_values, Direction_field_data& data)
{
  if(point_values.size() != data.points.size()) throw Invalid_input_error("VTK file: no singularity_index per point");
  for(std::size_t v = 0; v < point_values.size(); ++v)
    if(const int k = integer_index(point_values[v], data.degree)) data.vertex_singularities.emplace_back(v, k);
}

// The singular faces of this version's files: the triangles whose index is not 0.
inline void singular_faces_from_cells(const std::vector<double>& face_values, Direction_field_data& data)
{
  if(face_values.size() != data.faces.size()) throw Invalid_input_error("VTK file: no singularity_index per triangle");
  for(std::size_t f = 0; f < face_values.size(); ++f)
  {
    const int k = integer_index(face_values[f], data.degree);
    if(k == 0) continue;
    data.singularities.emplace_back(f, k);
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

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_INTERNAL_VTK_READING_H
