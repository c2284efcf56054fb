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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_FEATURE_EDGES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_FEATURE_EDGES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

namespace internal {

template <typename Point>
Vec3 as_vec3(const Point& p)
{
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
}

// The unit normal of face f (zero for a degenerate face), at any scale of
// the coordinates; a polygon's normal is that of its first three corners.
template <typename PolygonMesh, typename VertexPointMap>
Vec3 unit_face_normal(typename boost::graph_traits<PolygonMesh>::face_descriptor f, const PolygonMesh& mesh,
                      const VertexPointMap& vpm)
{
  const auto h = halfedge(f, mesh);
  return triangle_unit_normal(as_vec3(get(vpm, source(h, mesh))), as_vec3(get(vpm, target(h, mesh))),
                              as_vec3(get(vpm, target(next(h, mesh), mesh))));
}

// The feature edges as quad meshers keep them (QuadWild erodes and dilates
// its own the same way): `steps` times, every feature edge that ends at a
// free end (a vertex of one feature edge, not on the boundary) is dropped,
// all of them at once each time, unless it is long; then `steps` times every
// dropped edge that touches a free end of what is left comes back, unless
// that end was a junction (three or more feature edges, or a boundary vertex
// with one). An open chain of up to 2 steps edges, or a branch of up to
// `steps` edges, vanishes; longer chains and closed loops come back whole.
// `ends`: the two vertices of each edge; `marked`: the feature edges, in and out.
inline void erode_and_dilate_features(const std::vector<std::array<std::size_t, 2> >& ends,
                                      const std::vector<unsigned char>& border_vertex,
                                      const std::vector<unsigned char>& is_long, unsigned steps,
                                      std::vector<unsigned char>& marked)
{
  const std::size_t nv = border_vertex.size();
  auto valences = [&]() {
    std::vector<unsigned> count(nv, 0);
    for(std::size_t e = 0; e < ends.size(); ++e)
      if(marked[e]) { ++count[ends[e][0]]; ++count[ends[e][1]]; }
    return count;
  };
  const std::vector<unsigned> first = valences();
  auto free_end = [&](const std::vector<unsigned>& count, std::size_t v) { return count[v] == 1 && !border_vertex[v]; };
  auto junction = [&](std::size_t v) { return first[v] > 2 || (border_vertex[v] && first[v] > 0); };
  const std::vector<unsigned char> original = marked;
  for(unsigned s = 0; s < steps; ++s)
  {
    const std::vector<unsigned> count = valences();
    for(std::size_t e = 0; e < ends.size(); ++e)
      if(marked[e] && !is_long[e] && (free_end(count, ends[e][0]) || free_end(count, ends[e][1]))) marked[e] = 0;
  }
  for(unsigned s = 0; s < steps; ++s)
  {
    const std::vector<unsigned> count = valences();
    for(std::size_t e = 0; e < ends.size(); ++e)
      if(original[e] && !marked[e] &&
         ((free_end(count, ends[e][0]) && !junction(ends[e][0])) || (free_end(count, ends[e][1]) && !junction(ends[e][1]))))
        marked[e] = 1;
  }
}

// Whether the marked edges join a and b by a path of at most `length`
// edges that avoids the edge `skipped` (a breadth-first search).
inline bool joined_within(const std::vector<std::vector<std::size_t> >& edges_at,
                          const std::vector<std::array<std::size_t, 2> >& ends, const std::vector<unsigned char>& marked,
                          std::size_t skipped, std::size_t a, std::size_t b, unsigned length)
{
  std::vector<std::size_t> front{a}, next, visited{a};
  for(unsigned step = 0; step < length && !front.empty(); ++step)
  {
    next.clear();
    for(std::size_t v : front)
      for(std::size_t e : edges_at[v])
      {
        if(e == skipped || !marked[e]) continue;
        const std::size_t u = ends[e][0] == v ? ends[e][1] : ends[e][0];
        if(u == b) return true;
        if(std::find(visited.begin(), visited.end(), u) != visited.end()) continue;
        visited.push_back(u);
        next.push_back(u);
      }
    front.swap(next);
  }
  return false;
}

// Noise makes webs of sharp edges, small cycles side by side, where a
// person draws one line: the least sharp edge of each cycle of at most
// `length` edges is dropped (the least sharp first, each cycle checked again
// after every drop), unless it is long. `bend`: per edge, the cosine of its
// dihedral angle (the largest the least sharp); ties go by the vertex pair.
inline void thin_short_cycles(const std::vector<std::array<std::size_t, 2> >& ends, std::size_t vertex_count,
                              const std::vector<double>& bend, const std::vector<unsigned char>& is_long,
                              unsigned length, std::vector<unsigned char>& marked)
{
  if(length < 3) return;
  std::vector<std::vector<std::size_t> > edges_at(vertex_count);
  for(std::size_t e = 0; e < ends.size(); ++e)
    if(marked[e]) { edges_at[ends[e][0]].push_back(e); edges_at[ends[e][1]].push_back(e); }
  std::vector<std::size_t> order;
  for(std::size_t e = 0; e < ends.size(); ++e)
    if(marked[e] && !is_long[e]) order.push_back(e);
  auto key = [&](std::size_t e) {  // ties by the vertex pair: the same edges in any edge order
    return std::make_tuple(-bend[e], (std::min)(ends[e][0], ends[e][1]), (std::max)(ends[e][0], ends[e][1]));
  };
  std::sort(order.begin(), order.end(), [&](std::size_t e, std::size_t f) { return key(e) < key(f); });
  for(std::size_t e : order)
    if(joined_within(edges_at, ends, marked, e, ends[e][0], ends[e][1], length - 1)) marked[e] = 0;
}

// The length of the bounding box's diagonal of the mesh's points, at any scale.
template <typename PolygonMesh, typename VertexPointMap>
double bounding_box_diagonal(const PolygonMesh& mesh, const VertexPointMap& vpm)
{
  std::vector<Vec3> points;
  for(auto v : vertices(mesh)) points.push_back(as_vec3(get(vpm, v)));
  const std::array<Vec3, 2> box = bounding_box(points);
  return norm(0.5 * box[1] - 0.5 * box[0]) * 2.;
}

} // namespace internal

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

marks as feature edges the interior edges of `mesh` whose two faces' normals make an angle of more than
`angle_in_degrees` (the edges that `CGAL::Polygon_mesh_processing::detect_sharp_edges()` marks), cleaned
up as quad meshers need them, and returns how many it marked. On a scan, noise makes many short chains of
sharp edges and webs of small cycles; forced along each of them, a field gathers singularities there, and a
quad mesher makes irregular vertices at every junction. So each cycle of at most twice
`feature_cleanup_steps` edges loses its least sharp edge (the least sharp first, until no such cycle is
left), which thins a web to a line; then, as QuadWild does with its own features, the chains are eroded from
their free ends (a vertex of one feature edge, not on the boundary) `feature_cleanup_steps` times and then
grown back as many times along the sharp edges: an open
chain of at most twice that many edges, or a branch of at most that many from a junction, is dropped;
longer chains, closed loops of more edges, chains that end on the boundary and single edges longer than 5%
of the bounding box's diagonal (the long straight edges of a CAD model, never dropped) are kept whole (user manual, section
"Aligned and Constrained Fields").

Unlike `detect_sharp_edges()` it gives the same edges at every scale of the coordinates: the normals are
formed from sides scaled by a power of two, so coordinates near `1e300` or `1e-300` neither overflow nor
underflow. A degenerate face has no normal; its edges count as sharp for an angle below 90 degrees.
Boundary edges are not marked (the files for quad meshers add them). Edges that are not marked keep their
value in `edge_is_feature_map`.

\tparam PolygonMesh a model of `FaceListGraph`
\tparam EdgeIsFeatureMap a model of `WritablePropertyMap` with the edge descriptor as key and `bool` as value

\param mesh the mesh
\param angle_in_degrees the dihedral angle, in degrees, in `(0, 180)`
\param edge_is_feature_map where the feature edges are marked `true`
\param np an optional sequence of named parameters among:
  \cgalNamedParamsBegin
    \cgalParamNBegin{vertex_point_map}
      \cgalParamDescription{a property map associating points to the vertices of `mesh`}
      \cgalParamType{a model of `ReadablePropertyMap` with the vertex descriptor as key and a point as value}
      \cgalParamDefault{`boost::get(CGAL::vertex_point, mesh)`}
    \cgalParamNEnd
    \cgalParamNBegin{feature_cleanup_steps}
      \cgalParamDescription{the steps of erosion and growth of the chains of sharp edges, and half the length
                            of the cycles thinned (0: every sharp edge is kept)}
      \cgalParamType{`unsigned int`}
      \cgalParamDefault{4, as QuadWild}
    \cgalParamNEnd
  \cgalNamedParamsEnd

\return the number of edges marked

\pre `0 < angle_in_degrees < 180`
*/
template <typename PolygonMesh, typename EdgeIsFeatureMap,
          typename NamedParameters = parameters::Default_named_parameters>
std::size_t detect_feature_edges(const PolygonMesh& mesh, double angle_in_degrees,
                                 EdgeIsFeatureMap edge_is_feature_map,
                                 const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  const unsigned steps = choose_parameter(get_parameter(np, internal_np::feature_cleanup_steps), 4u);
  const double cos_angle = std::cos(angle_in_degrees * CGAL_PI / 180.);
  const auto vertex_index = get_initialized_vertex_index_map(mesh);
  std::vector<typename boost::graph_traits<PolygonMesh>::edge_descriptor> sharp;
  std::vector<std::array<std::size_t, 2> > ends;
  std::vector<double> bends;
  for(auto e : edges(mesh))
  {
    const auto h = halfedge(e, mesh);
    if(is_border_edge(h, mesh)) continue;
    const internal::Vec3 n1 = internal::unit_face_normal(face(h, mesh), mesh, vpm);
    const internal::Vec3 n2 = internal::unit_face_normal(face(opposite(h, mesh), mesh), mesh, vpm);
    const double bend = internal::dot(n1, n2);
    if(!(bend < cos_angle)) continue;
    sharp.push_back(e);
    bends.push_back(std::isfinite(bend) ? bend : -1.);
    ends.push_back({static_cast<std::size_t>(get(vertex_index, source(h, mesh))),
                    static_cast<std::size_t>(get(vertex_index, target(h, mesh)))});
  }
  std::size_t vertex_count = 0;
  for(auto v : vertices(mesh)) vertex_count = (std::max)(vertex_count, static_cast<std::size_t>(get(vertex_index, v)) + 1);
  std::vector<unsigned char> border_vertex(vertex_count, 0), is_long(sharp.size(), 0), kept(sharp.size(), 1);
  for(auto v : vertices(mesh))
    border_vertex[get(vertex_index, v)] = static_cast<bool>(is_border(v, mesh));
  const double longest_eroded = 0.05 * internal::bounding_box_diagonal(mesh, vpm);
  for(std::size_t i = 0; i < sharp.size(); ++i)
  {
    using internal::operator-;
    const auto h = halfedge(sharp[i], mesh);
    const internal::Vec3 side = internal::as_vec3(get(vpm, target(h, mesh))) - internal::as_vec3(get(vpm, source(h, mesh)));
    is_long[i] = internal::norm(side) > longest_eroded;
  }
  internal::thin_short_cycles(ends, vertex_count, bends, is_long, 2 * steps, kept);
  internal::erode_and_dilate_features(ends, border_vertex, is_long, steps, kept);
  std::size_t marked = 0;
  for(std::size_t i = 0; i < sharp.size(); ++i)
    if(kept[i])
    {
      put(edge_is_feature_map, sharp[i], true);
      ++marked;
    }
  return marked;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_FEATURE_EDGES_H
