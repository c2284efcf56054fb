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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_PLY_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_PLY_H

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

// The field in an ASCII PLY file: per vertex its direction, per face its index.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace IO {

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

} // namespace IO
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_PLY_H
