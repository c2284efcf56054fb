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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_INTERNAL_VTK_WRITING_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_INTERNAL_VTK_WRITING_H

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

// The datasets of IO::write_VTK() and its siblings, and both VTK formats.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

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
  std::string point_scalars, point_vectors, point_normals, cell_scalars, cell_vectors;  // active ("" = none)

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
  write_legacy_data(w, "CELL_DATA", g.cell_count(), g.cell_arrays, g.cell_scalars, g.cell_vectors, "");
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
  write_XML_arrays(w, "CellData", g.cell_arrays, g.cell_scalars, g.cell_vectors, "");
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

// The vertices that belong to a face, in their order, and their new numbers
// (the points of the datasets below).
inline std::vector<std::size_t> vertices_of_faces(const Direction_field_data& data, std::vector<std::size_t>& number)
{
  const std::size_t none = std::numeric_limits<std::size_t>::max();
  number.assign(data.points.size(), none);
  std::vector<std::size_t> used;
  for(const auto& t : data.faces) for(std::size_t v : t) number[v] = 0;
  for(std::size_t v = 0; v < number.size(); ++v)
    if(number[v] != none) { number[v] = used.size(); used.push_back(v); }
  return used;
}

inline void add_mesh(const Direction_field_data& data, const std::vector<std::size_t>& used,
                     const std::vector<std::size_t>& number, VTK_grid& g)
{
  for(std::size_t v : used) g.points.push_back(data.points[v]);
  for(const auto& t : data.faces)
    g.add_cell({static_cast<long long>(number[t[0]]), static_cast<long long>(number[t[1]]),
                static_cast<long long>(number[t[2]])}, 5);
}

// A field on faces as a dataset: the same points and triangles, the
// directions and normals as cell data (direction_0 the active cell vectors:
// ParaView's Glyph filter then places its arrows at the triangles' centres),
// the singular vertices' k / n as the point data singularity_index.
inline VTK_grid face_field_grid(const Direction_field_data& data)
{
  VTK_grid g;
  g.title = "direction field of degree " + std::to_string(data.degree) +
            " on faces (CGAL Surface_mesh_direction_fields)";
  g.degree = data.degree;
  const std::size_t n = static_cast<std::size_t>(data.degree);
  std::vector<std::size_t> number;
  const std::vector<std::size_t> used = vertices_of_faces(data, number);
  add_mesh(data, used, number, g);
  VTK_array normals{"normals", 3, {}}, all{"directions", 3 * data.degree, {}};
  std::vector<VTK_array> direction(n);
  for(std::size_t k = 0; k < n; ++k) direction[k] = VTK_array{"direction_" + std::to_string(k), 3, {}};
  for(std::size_t f = 0; f < data.faces.size(); ++f)
  {
    const Vec3 normal = triangle_unit_normal(data.points, data.faces[f]);
    normals.values.insert(normals.values.end(), normal.begin(), normal.end());
    for(std::size_t k = 0; k < n; ++k)
    {
      const Vec3 d = rotated(data.face_directions[f], normal, 2. * CGAL_PI * static_cast<double>(k) / data.degree);
      direction[k].values.insert(direction[k].values.end(), d.begin(), d.end());
      all.values.insert(all.values.end(), d.begin(), d.end());
    }
  }
  g.cell_arrays.push_back(std::move(normals));
  for(VTK_array& a : direction) g.cell_arrays.push_back(std::move(a));
  g.cell_arrays.push_back(std::move(all));
  VTK_array index{"singularity_index", 1, std::vector<double>(used.size(), 0.)};
  for(const auto& s : data.vertex_singularities)
    if(s.first < number.size() && s.first < data.points.size() && number[s.first] < used.size())
      index.values[number[s.first]] = static_cast<double>(s.second) / data.degree;
  g.point_arrays.push_back(std::move(index));
  g.cell_vectors = "direction_0";
  return g;
}

// The field as a dataset: the vertices that belong to a face (renumbered in
// their order) and the triangles. Every point carries real directions (the
// singularities are marked on their triangles, not by extra points), and no
// array is the active scalars: ParaView's glyph filter takes them as its
// scale array (point scalars shrink the arrows to nothing, cell scalars make
// it draw none).
inline VTK_grid field_grid(const Direction_field_data& data)
{
  if(holds_field_on_faces(data)) return face_field_grid(data);
  VTK_grid g;
  g.title = "direction field of degree " + std::to_string(data.degree) + " (CGAL Surface_mesh_direction_fields)";
  g.degree = data.degree;
  const std::size_t n = static_cast<std::size_t>(data.degree);
  std::vector<std::size_t> number;
  const std::vector<std::size_t> used = vertices_of_faces(data, number);
  add_mesh(data, used, number, g);
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
  // the singular faces' barycentres, or a field on faces' singular vertices
  std::vector<std::pair<Vec3, int> > singular;
  for(const auto& s : data.singularities) singular.emplace_back(barycentre(data.points, data.faces[s.first]), s.second);
  for(const auto& s : data.vertex_singularities) singular.emplace_back(data.points[s.first], s.second);
  for(const auto& [centre, k] : singular)
  {
    const double index = static_cast<double>(k) / data.degree;
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
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_INTERNAL_VTK_WRITING_H
