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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_FACE_FIELD_FILES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_FACE_FIELD_FILES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_data.h>
#include <CGAL/Surface_mesh_direction_fields/internal/number_writer.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <map>
#include <ostream>
#include <set>
#include <utility>
#include <vector>

// The files of a field on faces that quad meshers and Directional read:
// QuadWild's feature edges (.sharp) and Directional's raw field, vertex
// singularities and matching (.rawfield, .sing, .matching).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The sides (face, c) of every edge, keyed by its two vertices in increasing order.
inline std::map<std::pair<std::size_t, std::size_t>, std::vector<std::pair<std::size_t, int> > >
sides_of_edges(const Direction_field_data& data)
{
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::pair<std::size_t, int> > > sides;
  for(std::size_t f = 0; f < data.faces.size(); ++f)
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t a = data.faces[f][c], b = data.faces[f][(c + 1) % 3];
      sides[{(std::min)(a, b), (std::max)(a, b)}].emplace_back(f, c);
    }
  return sides;
}

// Whether the edge of side c of face f bends outwards (its two faces meet convexly).
inline bool is_convex_side(const Direction_field_data& data, std::size_t f, int c, std::size_t g)
{
  const Vec3 nf = triangle_unit_normal(data.points, data.faces[f]);
  const Vec3 ng = triangle_unit_normal(data.points, data.faces[g]);
  const Vec3 along = data.points[data.faces[f][(c + 1) % 3]] - data.points[data.faces[f][c]];
  return dot(cross(nf, ng), along) >= 0.;
}

} // namespace internal

namespace IO {

/// \name Per-face formats for quad meshing
/// @{

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the feature edges and the boundary edges of `data`'s mesh as a `.sharp` file as QuadWild reads
it (`LoadSharpFeatures()`): the number of lines, then one `type,face,edge` line per side of such an edge
in each of its faces (face `f`, edge `c` from `faces[f][c]` to `faces[f][(c+1)%3]`, as vcglib numbers
the edges of a face read from the same mesh file), with type `1` for a convex edge and `0` for a
concave one; a boundary edge has one side and type `1`.

\param os the output stream
\param data the mesh (`points`, `faces`)
\param feature_edges the feature edges, each as its two vertex indices
*/
inline void write_sharp(std::ostream& os, const Direction_field_data& data,
                        const std::vector<std::array<std::size_t, 2> >& feature_edges)
{
  std::set<std::pair<std::size_t, std::size_t> > features;
  for(const auto& e : feature_edges) features.insert({(std::min)(e[0], e[1]), (std::max)(e[0], e[1])});
  std::vector<std::array<std::size_t, 3> > lines;  // type, face, edge
  for(const auto& edge : internal::sides_of_edges(data))
  {
    const auto& sides = edge.second;
    if(sides.size() == 1) lines.push_back({1, sides[0].first, static_cast<std::size_t>(sides[0].second)});
    else if(sides.size() == 2 && features.count(edge.first))
      for(int s = 0; s < 2; ++s)
      {
        const std::size_t f = sides[s].first, g = sides[1 - s].first;
        const bool convex = internal::is_convex_side(data, f, sides[s].second, g);
        lines.push_back({convex ? 1u : 0u, f, static_cast<std::size_t>(sides[s].second)});
      }
  }
  std::sort(lines.begin(), lines.end(), [](const auto& a, const auto& b) {
    return std::make_pair(a[1], a[2]) < std::make_pair(b[1], b[2]);
  });
  os << lines.size() << "\n";
  for(const auto& l : lines) os << l[0] << "," << l[1] << "," << l[2] << "\n";
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the per-face field as a Directional raw field (`.rawfield`, read by `directional::read_raw_field()`):
the degree `n` and the number of faces, then per face its `n` unit directions `x y z`, counter-clockwise
about the face's normal.

\param os the output stream
\param data the field (`points`, `faces`, `degree`, `face_directions`)
*/
inline void write_rawfield(std::ostream& os, const Direction_field_data& data)
{
  using internal::Vec3;
  os << std::setprecision(17) << data.degree << " " << data.faces.size() << "\n";
  internal::Number_writer out(os);
  for(std::size_t f = 0; f < data.faces.size(); ++f)
  {
    const Vec3 normal = internal::triangle_unit_normal(data.points, data.faces[f]);
    for(int k = 0; k < data.degree; ++k)
    {
      const Vec3 d = internal::rotated(data.face_directions[f], normal,
                                                                       2. * CGAL_PI * k / data.degree);
      if(k > 0) out.space();
      out.number(d[0]).space().number(d[1]).space().number(d[2]);
    }
    out.end_line();
  }
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the singular vertices of a field on faces as a Directional singularity file (`.sing`, read by
`directional::read_singularities()`): the degree `n` and the number of singular vertices, then one
`vertex k` line each (the index is `k / n`).

\param os the output stream
\param data the field (`degree`, `vertex_singularities`)
*/
inline void write_vertex_singularities(std::ostream& os, const Direction_field_data& data)
{
  os << data.degree << " " << data.vertex_singularities.size() << "\n";
  for(const auto& vk : data.vertex_singularities) os << vk.first << " " << vk.second << "\n";
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsIO

writes the matching of a field on faces as a Directional matching file (`.matching`, read by
`directional::read_matching()`): `n`, the number of edges and of faces; per edge `f g a b m`: its face `f`
where it runs from vertex `a` to `b`, the face `g` on its other side (`-1` on the boundary) and the
matching `m`, from 0 to `n - 1`: direction `j` of `f`, transported to `g`, is direction `(j + m) mod n` of
`g` (the range and the sense of Directional's `principal_matching()`, which gives the same `m` wherever
the field turns by less than `pi / n` across the edge; vcglib's `MissMatchByCross(f, g)` is
`(n - m) mod n`, and the period jump of `Face_direction_field_result`'s `edge_matching_map` is `-m`
modulo `n`); then per face its three edges (edge `c` from `faces[f][c]` to `faces[f][(c+1)%3]`). The
edges are numbered in the order of their first side in the faces.

\param os the output stream
\param data the field (`faces`, `degree`, `face_matching`)
*/
inline void write_matching(std::ostream& os, const Direction_field_data& data)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> edge_of;
  std::vector<std::array<long long, 5> > edges;  // f g a b m
  std::vector<std::array<std::size_t, 3> > face_edges(data.faces.size());
  for(std::size_t f = 0; f < data.faces.size(); ++f)
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t a = data.faces[f][c], b = data.faces[f][(c + 1) % 3];
      const auto key = std::make_pair((std::min)(a, b), (std::max)(a, b));
      const auto found = edge_of.find(key);
      if(found == edge_of.end())
      {
        edge_of[key] = edges.size();
        face_edges[f][c] = edges.size();
        // the period jump p from f turns its first direction p times: direction j of f is direction j - p of g
        const long long n = data.degree;
        const long long p = data.face_matching.empty() ? 0 : static_cast<long long>(data.face_matching[f][c]);
        const long long m = ((-p % n) + n) % n;
        edges.push_back({static_cast<long long>(f), -1, static_cast<long long>(a), static_cast<long long>(b), m});
      }
      else
      {
        face_edges[f][c] = found->second;
        edges[found->second][1] = static_cast<long long>(f);
      }
    }
  os << data.degree << " " << edges.size() << " " << data.faces.size() << "\n";
  for(const auto& e : edges) os << e[0] << " " << e[1] << " " << e[2] << " " << e[3] << " " << e[4] << "\n";
  for(const auto& fe : face_edges) os << fe[0] << " " << fe[1] << " " << fe[2] << "\n";
}

/// @}

} // namespace IO
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_IO_FACE_FIELD_FILES_H
