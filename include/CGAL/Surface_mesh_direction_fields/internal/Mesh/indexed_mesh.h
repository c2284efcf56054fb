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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_INDEXED_MESH_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_INDEXED_MESH_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/prefetch.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

// The mesh plumbing: the only place that talks to the BGL. Everything
// downstream (tangent spaces, assembly, solve, outputs) works on the flat
// arrays of `Indexed_mesh`, so the math never depends on the mesh class.
//
// Conventions, fixed here once:
//  * vertex `v` has index `get(vim, v)` in [0, |V|), face `f` has index in [0, |F|);
//  * `faces[f] = {a, b, c}` lists the face's vertices in the order of its
//    halfedge cycle, which is counter-clockwise for the mesh's orientation,
//    starting at the vertex of smallest index;
//  * a corner is the pair (face f, position c in 0..2), numbered `3 f + c`;
//    its vertex is `faces[f][c]`, and the halfedge leaving that vertex along the
//    face, `faces[f][c] -> faces[f][(c+1)%3]`, is the corner's first side
//    (sweeping counter-clockwise through the corner leads from it to the
//    halfedge `faces[f][c] -> faces[f][(c+2)%3]`);
//  * the fan of vertex v lists its corners counter-clockwise; the first side of
//    the first corner is v's reference direction X_v. For a boundary vertex the
//    fan starts at the boundary edge that has the interior on its left, so the
//    corners sweep the interior; a closed fan starts at the edge to the
//    neighbour of smallest index. Neither depends on halfedge(f) or
//    halfedge(v): the same vertex and face numbering gives the same field
//    whatever data structure holds the mesh.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

constexpr std::size_t no_index = static_cast<std::size_t>(-1);

// An index stored in 32 bits that reads and writes as a std::size_t,
// `no_index` included (stored as -1, read back by sign extension, which costs
// nothing). The mesh arrays hold these: half the memory and memory traffic of
// std::size_t, while the code computes with std::size_t throughout. Indices
// must stay below 2^31 - 1: make_indexed_mesh() rejects a mesh with more
// corners than that (715 million faces).
class Compact_index
{
  std::int32_t m_value;

public:
  static constexpr std::size_t largest = static_cast<std::size_t>(INT32_MAX) - 1;

  Compact_index() = default;
  Compact_index(std::size_t i) : m_value(i == no_index ? -1 : static_cast<std::int32_t>(i)) {}
  operator std::size_t() const { return static_cast<std::size_t>(static_cast<std::ptrdiff_t>(m_value)); }
};

struct Indexed_mesh
{
  std::vector<std::array<double, 3> > points;        // per vertex
  std::vector<std::array<Compact_index, 3> > faces;  // counter-clockwise
  std::vector<Compact_index> fan_offsets;            // |V| + 1 entries
  std::vector<Compact_index> fan_corners;            // corners 3 f + c, counter-clockwise
  std::vector<unsigned char> is_border_vertex;       // per vertex
  // For the side of corner 3f+c (the halfedge faces[f][c] -> faces[f][c+1]),
  // the corner of the other face whose first side is the reverse halfedge;
  // `no_index` on the border.
  std::vector<Compact_index> twin_corner;

  std::size_t number_of_vertices() const { return points.size(); }
  std::size_t number_of_faces() const { return faces.size(); }
  std::size_t fan_size(std::size_t v) const { return fan_offsets[v + 1] - fan_offsets[v]; }
  // the corners of v's fan, counter-clockwise, for a range-for over std::size_t
  struct Corner_range
  {
    const Compact_index *first, *last;
    const Compact_index* begin() const { return first; }
    const Compact_index* end() const { return last; }
  };
  Corner_range fan(std::size_t v) const
  {
    return {fan_corners.data() + static_cast<std::size_t>(fan_offsets[v]),
            fan_corners.data() + static_cast<std::size_t>(fan_offsets[v + 1])};
  }

  static std::size_t face_of_corner(std::size_t corner) { return corner / 3; }
  static std::size_t next_corner(std::size_t corner) { return 3 * (corner / 3) + (corner + 1) % 3; }
  static std::size_t previous_corner(std::size_t corner) { return 3 * (corner / 3) + (corner + 2) % 3; }
  std::size_t vertex_of_corner(std::size_t corner) const { return faces[corner / 3][corner % 3]; }

  // visit(u) for each neighbour u of v, once each on a fan without a
  // multiple edge: the vertex after v in each corner of its fan (the
  // counter-clockwise fan repeats the vertex before v as the next corner's
  // vertex after it), and at a border vertex also the last corner's vertex
  // before v.
  template <typename Visit>
  void for_each_neighbour(std::size_t v, const Visit& visit) const
  {
    for(std::size_t corner : fan(v)) visit(vertex_of_corner(next_corner(corner)));
    if(is_border_vertex[v] && fan_size(v) > 0)
      visit(vertex_of_corner(previous_corner(fan_corners[fan_offsets[v + 1] - 1])));
  }
};

// Starts loading data[v] for the three vertices v of face f (see prefetch.h).
template <typename PerVertex>
void prefetch_face_vertices(const Indexed_mesh& m, const std::vector<PerVertex>& data, std::size_t f)
{
  const auto& t = m.faces[f];
  for(int c = 0; c < 3; ++c) prefetch_address(data.data() + static_cast<std::size_t>(t[c]));
}

// body(f) for every face f, in parallel, each face's points being asked for
// a few faces ahead (the loops over faces that read the points).
template <typename FaceBody>
void parallel_for_each_face(const Indexed_mesh& m, const FaceBody& body)
{
  parallel_for_each_range(m.number_of_faces(), [&](std::size_t begin, std::size_t end) {
    for(std::size_t f = begin; f < end; ++f)
    {
      if(f + prefetch_distance < end) prefetch_face_vertices(m, m.points, f + prefetch_distance);
      body(f);
    }
  });
}

// Coordinates far from 1 are multiplied by a power of two (exactly: the
// mantissas do not change) to a largest magnitude in [1, 2), and the factor
// is returned (1 when the largest magnitude is already within 2^-100 to
// 2^100, which leaves common meshes as they are). The method is invariant
// under scaling, but its arithmetic is not: products of four lengths (Heron's
// formula) overflow from lengths of about 1e77 and underflow below 1e-77.
// What the computation reports in units of length is converted back by the
// caller (eigenvalues scale like 1 / length^2).
inline double normalize_coordinates(Indexed_mesh& m)
{
  double largest = 0.;
  for(const auto& p : m.points)
    for(double x : p) largest = (std::max)(largest, std::abs(x));
  if(!(largest > 0.) || (largest >= std::ldexp(1., -100) && largest <= std::ldexp(1., 100))) return 1.;
  const int exponent = std::ilogb(largest);
  for(auto& p : m.points)
    for(double& x : p) x = std::ldexp(x, -exponent);
  return std::ldexp(1., -exponent);
}

// The steps of make_indexed_mesh(), each a pass over the mesh.

// Checks, as the copy passes read them, that an index map numbers the
// elements 0, 1, ..., count - 1, each once (what the flat arrays need). A
// CGAL::Surface_mesh with removed elements that were not collected counts
// them in num_vertices() and num_faces() but does not list them, and its
// built-in numbering has gaps.
class Dense_numbering
{
  std::vector<unsigned char> m_seen;
  std::size_t m_listed = 0;
  bool m_vertices;

  [[noreturn]] void fail() const
  {
    throw Invalid_input_error(std::string(m_vertices ? "the vertex index map does not number the vertices 0 to |V| - 1"
                                                     : "the face index map does not number the faces 0 to |F| - 1") +
                              " (a CGAL::Surface_mesh with removed elements needs collect_garbage() first)");
  }

public:
  Dense_numbering(std::size_t count, bool vertices) : m_seen(count, 0), m_vertices(vertices) {}
  std::size_t operator()(std::size_t i)  // i, once checked
  {
    if(i >= m_seen.size() || m_seen[i]++) fail();
    ++m_listed;
    return i;
  }
  void check_complete() const
  {
    if(m_listed != m_seen.size()) fail();
  }
};

// The coordinates of every vertex, by index; throws on a non-finite one.
template <typename TriangleMesh, typename PointOf, typename VertexIndexMap>
void copy_points(const TriangleMesh& tm, const PointOf& point_of, VertexIndexMap vim, Indexed_mesh& m)
{
  m.points.resize(static_cast<std::size_t>(num_vertices(tm)));
  Dense_numbering numbering(m.points.size(), true);
  for(auto v : vertices(tm))
  {
    const std::size_t i = numbering(static_cast<std::size_t>(get(vim, v)));
    m.points[i] = point_of(v);
    for(double x : m.points[i])
      if(!std::isfinite(x))
        throw Invalid_input_error("vertex " + std::to_string(i) + " has a non-finite coordinate");
  }
  numbering.check_complete();
}

// The halfedge of face f whose source has the smallest vertex index: the
// face's first corner. Numbering corners from it (rather than from
// halfedge(f)) makes the corners, hence every reference direction and the
// field's digits, depend on the vertex numbering only, not on how the mesh's
// halfedges were built (user manual, "Reference Directions").
template <typename TriangleMesh, typename VertexIndexMap>
typename boost::graph_traits<TriangleMesh>::halfedge_descriptor
first_corner_halfedge(typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& tm,
                      VertexIndexMap vim)
{
  auto h = halfedge(f, tm), best = h;
  for(int c = 0; c < 3; ++c, h = next(h, tm))
    if(get(vim, source(h, tm)) < get(vim, source(best, tm))) best = h;
  return best;
}

// The vertices of every face in the order of its halfedge cycle, from its
// first corner; throws on a face that is not a triangle. Returns the number
// of faces of each vertex.
template <typename TriangleMesh, typename VertexIndexMap, typename FaceIndexMap>
std::vector<std::size_t> copy_triangles(const TriangleMesh& tm, VertexIndexMap vim, FaceIndexMap fim, Indexed_mesh& m)
{
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  m.faces.resize(nf);
  m.twin_corner.assign(3 * nf, no_index);
  std::vector<std::size_t> incident_faces(m.points.size(), 0);
  Dense_numbering numbering(nf, false);
  for(auto f : faces(tm))
  {
    const std::size_t fi = numbering(static_cast<std::size_t>(get(fim, f)));
    auto h = halfedge(f, tm);
    if(next(next(next(h, tm), tm), tm) != h)
      throw Invalid_input_error("face " + std::to_string(fi) + " is not a triangle");
    h = first_corner_halfedge(f, tm, vim);
    for(int c = 0; c < 3; ++c, h = next(h, tm))
    {
      m.faces[fi][c] = static_cast<std::size_t>(get(vim, source(h, tm)));
      ++incident_faces[m.faces[fi][c]];
    }
  }
  numbering.check_complete();
  return incident_faces;
}

// The corners of one vertex, counter-clockwise, found by walking its
// halfedges; for an open fan the walk starts on the border (see the
// conventions above).
template <typename TriangleMesh, typename VertexIndexMap, typename FaceIndexMap>
class Fan_walker
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::halfedge_descriptor halfedge_descriptor;
  const TriangleMesh& m_tm;
  VertexIndexMap m_vim;
  FaceIndexMap m_fim;
  std::vector<std::size_t> m_clockwise;  // the corners of an open fan before the start, clockwise

public:
  Fan_walker(const TriangleMesh& tm, VertexIndexMap vim, FaceIndexMap fim) : m_tm(tm), m_vim(vim), m_fim(fim) {}

  // The corner 3 f + c of halfedge h, c its position in its face's cycle
  // counted from the face's first corner.
  std::size_t corner_of(halfedge_descriptor h) const
  {
    const auto f = face(h, m_tm);
    halfedge_descriptor g = first_corner_halfedge(f, m_tm, m_vim);
    int c = 0;
    while(g != h) { g = next(g, m_tm); ++c; }
    return 3 * static_cast<std::size_t>(get(m_fim, f)) + static_cast<std::size_t>(c);
  }

  // The fan of the vertex whose halfedge is hv (at most `bound` corners are
  // visited, a guard on broken meshes); returns whether it is open.
  bool walk(halfedge_descriptor hv, std::size_t bound, std::vector<std::size_t>& fan)
  {
    // Walk counter-clockwise through the corners of v from one outgoing
    // halfedge (the next outgoing halfedge is opposite(prev(h))). Reaching a
    // border halfedge means the fan is open: its beginning is then found by
    // walking clockwise from the start (next(opposite(h))), so every halfedge
    // of the fan is visited once.
    const halfedge_descriptor start = opposite(hv, m_tm);
    halfedge_descriptor h = start;
    bool open = false;
    fan.clear();
    do
    {
      if(is_border(h, m_tm)) { open = true; break; }
      fan.push_back(corner_of(h));
      h = opposite(prev(h, m_tm), m_tm);
    }
    while(h != start && fan.size() <= bound);
    if(!open) return false;
    m_clockwise.clear();
    for(halfedge_descriptor g = start; !is_border(opposite(g, m_tm), m_tm) && m_clockwise.size() <= bound;)
    {
      g = next(opposite(g, m_tm), m_tm);
      if(g == start) break;
      m_clockwise.push_back(corner_of(g));
    }
    fan.insert(fan.begin(), m_clockwise.rbegin(), m_clockwise.rend());
    return true;
  }
};

// A closed fan has no border to start from: it starts at the corner whose
// first side leads to the neighbour of smallest index (the smallest corner
// among equals, on a multiple edge), so that the vertex's reference direction
// depends on the numbering only, not on halfedge(v).
inline void start_closed_fan_at_smallest_neighbour(const Indexed_mesh& m, std::vector<std::size_t>& fan)
{
  auto key = [&m](std::size_t corner) {
    return std::make_pair(m.vertex_of_corner(Indexed_mesh::next_corner(corner)), corner);
  };
  auto first = std::min_element(fan.begin(), fan.end(),
                                [&key](std::size_t a, std::size_t b) { return key(a) < key(b); });
  std::rotate(fan.begin(), first, fan.end());
}

// Twins from a fan: corner k at v has third vertex b, and the next corner k2
// counter-clockwise has first side v -> b, the reverse of the first side
// b -> v of previous_corner(k). Each vertex writes the twins of its own
// corners k2 (the other direction is written by b); the first corner of an
// open fan has a border side and no twin.
inline void set_twins_of_fan(const std::vector<std::size_t>& fan, bool open, Indexed_mesh& m)
{
  const std::size_t count = fan.size();
  for(std::size_t a = 0; a < count; ++a)
  {
    if(open && a + 1 == count) break;  // no corner after the last one of an open fan
    m.twin_corner[fan[(a + 1) % count]] = Indexed_mesh::previous_corner(fan[a]);
  }
}

// The fans, border flags and twins of all vertices. Each vertex's fan takes
// as many corners as the vertex has incident faces (more or fewer means a
// non-manifold vertex): the offsets are known before the walks, so the fans
// are walked in parallel, each vertex writing only its own range of
// fan_corners and the twins of its own corners. Throws on a non-manifold vertex.
template <typename TriangleMesh, typename VertexIndexMap, typename FaceIndexMap>
void build_fans(const TriangleMesh& tm, VertexIndexMap vim, FaceIndexMap fim,
                const std::vector<std::size_t>& incident_faces, Indexed_mesh& m)
{
  typedef boost::graph_traits<TriangleMesh> GT;
  const std::size_t nv = m.points.size();
  m.fan_offsets.assign(nv + 1, 0);
  for(std::size_t i = 0; i < nv; ++i) m.fan_offsets[i + 1] = m.fan_offsets[i] + incident_faces[i];
  m.fan_corners.assign(m.fan_offsets[nv], no_index);
  m.is_border_vertex.assign(nv, 0);
  // Vertices in index order, so that fans are laid out by index.
  std::vector<typename GT::vertex_descriptor> vertex_of_index(nv);
  for(auto v : vertices(tm))
    vertex_of_index[static_cast<std::size_t>(get(vim, v))] = v;

  std::vector<unsigned char> non_manifold(nv, 0);
  parallel_for_each_range(nv, [&](std::size_t begin, std::size_t end) {
    Fan_walker<TriangleMesh, VertexIndexMap, FaceIndexMap> walker(tm, vim, fim);
    std::vector<std::size_t> fan;
    for(std::size_t i = begin; i < end; ++i)
    {
      if(incident_faces[i] == 0)
        continue;  // isolated vertex: empty fan
      const auto hv = halfedge(vertex_of_index[i], tm);
      const bool open = hv != GT::null_halfedge() && walker.walk(hv, incident_faces[i] + 1, fan);
      if(hv == GT::null_halfedge() || fan.size() != incident_faces[i])
      {
        non_manifold[i] = 1;  // its incident faces do not form a single fan
        continue;
      }
      m.is_border_vertex[i] = open;
      if(!open) start_closed_fan_at_smallest_neighbour(m, fan);
      std::copy(fan.begin(), fan.end(), m.fan_corners.begin() + static_cast<std::ptrdiff_t>(m.fan_offsets[i]));
      set_twins_of_fan(fan, open, m);
    }
  });
  const auto bad = std::find(non_manifold.begin(), non_manifold.end(), 1);
  if(bad != non_manifold.end())
    throw Invalid_input_error("vertex " + std::to_string(bad - non_manifold.begin()) +
                              " is non-manifold (its incident faces do not form a single fan)");
}

// Builds the flat representation. `point_of(v)` returns the coordinates of a
// vertex as std::array<double,3>. Throws Invalid_input_error on an empty mesh,
// a non-triangle face, a non-finite coordinate or a non-manifold vertex.
template <typename TriangleMesh, typename PointOf, typename VertexIndexMap, typename FaceIndexMap>
Indexed_mesh make_indexed_mesh(const TriangleMesh& tm, const PointOf& point_of,
                               VertexIndexMap vim, FaceIndexMap fim)
{
  const std::size_t nv = static_cast<std::size_t>(num_vertices(tm));
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  if(nv == 0 || nf == 0)
    throw Invalid_input_error("empty mesh: the mesh has no " + std::string(nv == 0 ? "vertex" : "face"));
  if(nv > Compact_index::largest || nf > Compact_index::largest / 3)
    throw Invalid_input_error("the mesh is too large: at most " + std::to_string(Compact_index::largest / 3) +
                              " faces and " + std::to_string(Compact_index::largest) + " vertices");
  Indexed_mesh m;
  copy_points(tm, point_of, vim, m);
  const std::vector<std::size_t> incident_faces = copy_triangles(tm, vim, fim, m);
  build_fans(tm, vim, fim, incident_faces, m);
  return m;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_INDEXED_MESH_H
