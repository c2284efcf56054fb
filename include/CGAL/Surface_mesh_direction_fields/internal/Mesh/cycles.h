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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_CYCLES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_CYCLES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>

#include <algorithm>
#include <cstddef>
#include <vector>

// The edges of the mesh and a basis of its cycles (user manual, section
// "Placing Singularities"): a spanning tree of the vertices (along which a
// parallel field is propagated), the boundary loops, and the 2g loops that
// go around the handles of a component of genus g, found by tree-cotree
// decomposition (Eppstein, "Dynamic generators of topologically embedded
// graphs", 2003) on the surface with each boundary loop capped by a virtual
// face. The cotree also gives, in one sweep, a change of the connection with
// any prescribed holonomies (prescribed_singularities.h).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// Whether corner ci's side is the representative halfedge of its edge: a
// border side, or the side of the smaller corner of an interior edge. The
// connection is computed on these sides (connection.h) and edge unknowns
// are oriented along them.
inline bool is_representative_side(const Indexed_mesh& m, std::size_t ci)
{
  const std::size_t twin = m.twin_corner[ci];
  return twin == no_index || ci < twin || m.twin_corner[twin] != ci;
}

struct Edge_numbering
{
  std::vector<Compact_index> edge_of_corner;  // the edge of corner 3f+c's side
  std::vector<Compact_index> corner_of_edge;  // its representative side
  std::vector<signed char> sign_of_corner;    // +1 if the side runs along its edge's orientation, -1 otherwise

  std::size_t number_of_edges() const { return corner_of_edge.size(); }
};

inline Edge_numbering number_edges(const Indexed_mesh& m)
{
  Edge_numbering edges;
  const std::size_t corners = 3 * m.number_of_faces();
  edges.edge_of_corner.assign(corners, no_index);
  edges.sign_of_corner.assign(corners, 1);
  for(std::size_t ci = 0; ci < corners; ++ci)
    if(is_representative_side(m, ci))
    {
      edges.edge_of_corner[ci] = edges.corner_of_edge.size();
      edges.corner_of_edge.push_back(ci);
    }
  for(std::size_t ci = 0; ci < corners; ++ci)
    if(!is_representative_side(m, ci))
    {
      edges.edge_of_corner[ci] = static_cast<std::size_t>(edges.edge_of_corner[m.twin_corner[ci]]);
      edges.sign_of_corner[ci] = -1;
    }
  return edges;
}

// A closed path of edges, each traversed along (+1) or against (-1) its orientation.
struct Edge_cycle
{
  std::vector<std::size_t> edges;
  std::vector<signed char> signs;
  std::size_t component = 0;
  bool is_boundary = false;

  void add(std::size_t edge, int sign)
  {
    edges.push_back(edge);
    signs.push_back(static_cast<signed char>(sign));
  }
};

// The spanning tree of the vertices, the boundary loops, the handle loops
// and the cotree: a spanning tree of the faces and of one virtual face per
// boundary loop (the loop's cap), across the edges outside the vertices'
// tree. Every edge lies in exactly one of: the tree, the cotree, or the 2g
// edges left over, each of which closes one handle loop with the tree.
struct Cycle_basis
{
  // the spanning tree of each component's vertices, rooted at its first vertex:
  std::vector<Compact_index> tree_order;   // every non-isolated vertex, each after its parent
  std::vector<Compact_index> parent;       // no_index at the roots (and isolated vertices)
  std::vector<Compact_index> parent_edge;  // the edge from the parent
  std::vector<signed char> parent_sign;    // +1 if parent -> vertex runs along that edge
  std::vector<Compact_index> depth;
  // every boundary loop along its faces' sides; per component with boundary
  // the longest is `free` (the cotree's root: its holonomy follows from the others)
  std::vector<Edge_cycle> boundary_loops;
  std::vector<unsigned char> is_free;
  // the handle loops: a left-over edge (first, along its orientation), then the tree path back
  std::vector<Edge_cycle> handle_loops;
  // the cotree over the nodes f (faces) and F + l (the cap of boundary loop l):
  std::vector<Compact_index> cotree_order;        // every node, each after its parent; the roots have none
  std::vector<Compact_index> cotree_parent_edge;  // the edge to the parent (no_index at a root)
};

// Every step v -> w across the edges at v: visit(w, edge, sign of v -> w).
template <typename Visit>
void for_each_edge_at(const Indexed_mesh& m, const Edge_numbering& edges, std::size_t v, const Visit& visit)
{
  for(std::size_t ci : m.fan(v))  // the side of ci runs v -> next vertex
    visit(m.vertex_of_corner(Indexed_mesh::next_corner(ci)), edges.edge_of_corner[ci], edges.sign_of_corner[ci]);
  if(m.is_border_vertex[v] && m.fan_size(v) > 0)
  {
    // the side of the last corner's previous corner runs (vertex before v) -> v
    const std::size_t pc = Indexed_mesh::previous_corner(m.fan_corners[m.fan_offsets[v + 1] - 1]);
    visit(m.vertex_of_corner(pc), edges.edge_of_corner[pc], -edges.sign_of_corner[pc]);
  }
}

// Every side of a cotree node: visit(edge, sign). A face's three sides; a
// loop's cap: the loop's edges (its equation is the sum along the loop).
template <typename Visit>
void for_each_side_of_node(const Edge_numbering& edges, const Cycle_basis& basis, std::size_t number_of_faces,
                           std::size_t node, const Visit& visit)
{
  if(node < number_of_faces)
    for(std::size_t ci = 3 * node; ci < 3 * node + 3; ++ci) visit(edges.edge_of_corner[ci], edges.sign_of_corner[ci]);
  else
  {
    const Edge_cycle& loop = basis.boundary_loops[node - number_of_faces];
    for(std::size_t i = 0; i < loop.edges.size(); ++i) visit(loop.edges[i], loop.signs[i]);
  }
}

namespace cycles_impl {

inline void build_spanning_trees(const Indexed_mesh& m, const Edge_numbering& edges, const Components& comps,
                                 Cycle_basis& basis, std::vector<unsigned char>& in_tree)
{
  const std::size_t nv = m.number_of_vertices();
  basis.parent.assign(nv, no_index);
  basis.parent_edge.assign(nv, no_index);
  basis.parent_sign.assign(nv, 1);
  basis.depth.assign(nv, 0);
  std::vector<unsigned char> reached(nv, 0);
  for(const Component& comp : comps.list)
  {
    std::size_t next = basis.tree_order.size();
    basis.tree_order.push_back(comp.vertices.front());
    reached[comp.vertices.front()] = 1;
    for(; next < basis.tree_order.size(); ++next)
    {
      const std::size_t v = basis.tree_order[next];
      for_each_edge_at(m, edges, v, [&](std::size_t w, std::size_t e, int sign) {
        if(reached[w]) return;
        reached[w] = 1;
        in_tree[e] = 1;
        basis.parent[w] = v;
        basis.parent_edge[w] = e;
        basis.parent_sign[w] = static_cast<signed char>(sign);
        basis.depth[w] = basis.depth[v] + 1;
        basis.tree_order.push_back(w);
      });
    }
  }
}

// The boundary loops, each along its faces' sides (the interior on its
// left); loop_of_edge[e] is the loop of a border edge.
inline std::vector<Edge_cycle> boundary_loops(const Indexed_mesh& m, const Edge_numbering& edges,
                                              const Components& comps, std::vector<std::size_t>& loop_of_edge)
{
  std::vector<Edge_cycle> loops;
  loop_of_edge.assign(edges.number_of_edges(), no_index);
  for(std::size_t e = 0; e < edges.number_of_edges(); ++e)
  {
    std::size_t ci = edges.corner_of_edge[e];
    if(m.twin_corner[ci] != no_index || loop_of_edge[e] != no_index) continue;
    Edge_cycle loop;
    loop.is_boundary = true;
    loop.component = comps.component_of_face[Indexed_mesh::face_of_corner(ci)];
    // the next border side starts where this one ends: the first corner of that vertex's fan
    while(loop_of_edge[edges.edge_of_corner[ci]] == no_index)
    {
      loop_of_edge[edges.edge_of_corner[ci]] = loops.size();
      loop.add(edges.edge_of_corner[ci], 1);
      const std::size_t end = m.vertex_of_corner(Indexed_mesh::next_corner(ci));
      ci = m.fan_corners[m.fan_offsets[end]];
      if(m.twin_corner[ci] != no_index) break;  // not a manifold border: the loop stops here
    }
    loops.push_back(std::move(loop));
  }
  return loops;
}

// The cycle closed by edge e (not in the tree): e, then the tree path back.
inline Edge_cycle handle_loop(const Indexed_mesh& m, const Edge_numbering& edges, const Cycle_basis& basis,
                              std::size_t e, std::size_t component)
{
  Edge_cycle loop;
  loop.component = component;
  const std::size_t ci = edges.corner_of_edge[e];
  std::size_t from = m.vertex_of_corner(ci), to = m.vertex_of_corner(Indexed_mesh::next_corner(ci));
  loop.add(e, 1);
  // to -> ... -> from: up from `to` against the tree, down to `from` along it
  std::vector<std::pair<std::size_t, int> > down;
  while(from != to)
  {
    if(basis.depth[to] >= basis.depth[from])
    {
      loop.add(basis.parent_edge[to], -basis.parent_sign[to]);
      to = basis.parent[to];
    }
    else
    {
      down.emplace_back(basis.parent_edge[from], basis.parent_sign[from]);
      from = basis.parent[from];
    }
  }
  for(auto it = down.rbegin(); it != down.rend(); ++it) loop.add(it->first, it->second);
  return loop;
}

// The root of each component's cotree: the cap of its longest boundary loop
// (marked free), or its first face on a closed component.
inline std::vector<std::size_t> cotree_roots(const Indexed_mesh& m, const Components& comps, Cycle_basis& basis)
{
  std::vector<std::size_t> longest(comps.list.size(), no_index);
  for(std::size_t l = 0; l < basis.boundary_loops.size(); ++l)
  {
    std::size_t& best = longest[basis.boundary_loops[l].component];
    if(best == no_index || basis.boundary_loops[l].edges.size() > basis.boundary_loops[best].edges.size()) best = l;
  }
  basis.is_free.assign(basis.boundary_loops.size(), 0);
  std::vector<std::size_t> roots;
  for(std::size_t c = 0; c < comps.list.size(); ++c)
  {
    if(longest[c] != no_index) basis.is_free[longest[c]] = 1;
    roots.push_back(longest[c] != no_index ? m.number_of_faces() + longest[c] : std::size_t(comps.list[c].faces.front()));
  }
  return roots;
}

// The cotree, breadth first from each root across the edges outside the
// vertices' tree; in_cotree marks its edges.
inline void build_cotree(const Indexed_mesh& m, const Edge_numbering& edges, const Components& comps,
                         const std::vector<std::size_t>& loop_of_edge, const std::vector<unsigned char>& in_tree,
                         Cycle_basis& basis, std::vector<unsigned char>& in_cotree)
{
  const std::size_t nf = m.number_of_faces();
  basis.cotree_parent_edge.assign(nf + basis.boundary_loops.size(), no_index);
  std::vector<unsigned char> reached(basis.cotree_parent_edge.size(), 0);
  for(std::size_t root : cotree_roots(m, comps, basis))
  {
    std::size_t next = basis.cotree_order.size();
    basis.cotree_order.push_back(root);
    reached[root] = 1;
    for(; next < basis.cotree_order.size(); ++next)
    {
      const std::size_t node = basis.cotree_order[next];
      for_each_side_of_node(edges, basis, nf, node, [&](std::size_t e, int) {
        if(in_tree[e]) return;
        const std::size_t ci = edges.corner_of_edge[e], twin = m.twin_corner[ci];
        const std::size_t face = Indexed_mesh::face_of_corner(ci);
        const std::size_t other = face != node ? face : twin != no_index ? Indexed_mesh::face_of_corner(twin)
                                                                        : nf + loop_of_edge[e];
        if(reached[other]) return;
        reached[other] = 1;
        in_cotree[e] = 1;
        basis.cotree_parent_edge[other] = e;
        basis.cotree_order.push_back(other);
      });
    }
  }
}

} // namespace cycles_impl

inline Cycle_basis find_cycle_basis(const Indexed_mesh& m, const Edge_numbering& edges, const Components& comps)
{
  using namespace cycles_impl;
  Cycle_basis basis;
  std::vector<unsigned char> in_tree(edges.number_of_edges(), 0), in_cotree(edges.number_of_edges(), 0);
  build_spanning_trees(m, edges, comps, basis, in_tree);
  std::vector<std::size_t> loop_of_edge;
  basis.boundary_loops = boundary_loops(m, edges, comps, loop_of_edge);
  build_cotree(m, edges, comps, loop_of_edge, in_tree, basis, in_cotree);
  for(std::size_t e = 0; e < edges.number_of_edges(); ++e)
    if(!in_tree[e] && !in_cotree[e])
      basis.handle_loops.push_back(handle_loop(
        m, edges, basis, e, comps.component_of_face[Indexed_mesh::face_of_corner(edges.corner_of_edge[e])]));
  return basis;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_CYCLES_H
