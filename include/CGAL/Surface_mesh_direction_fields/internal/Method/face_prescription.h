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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FACE_PRESCRIPTION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FACE_PRESCRIPTION_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/real_factorization.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/cycles.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/face_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <cmath>
#include <cstddef>
#include <deque>
#include <vector>

// Placing singularities at the vertices of a field on faces (user manual,
// section "Fields on Faces", "Placing singularities at vertices"): the
// construction of "Placing Singularities" on the dual mesh. The unknowns are
// the changes delta of the dual connection n rho, one per interior edge
// (oriented from the face of its representative side to the other face). The
// equations ask, around every interior vertex, sum delta = 2 pi k_v - n K_v;
// around the faces along every boundary loop but one per component, and
// around every handle loop, the multiple of 2 pi nearest the connection's
// own. Every solution is one of them plus the dual gradient of a function
// on the faces (it sums to 0 around every closed path of faces); the least
// one in the norm sum_e w_e delta_e^2 (the L2 norm of a dual 1-form) removes
// that gradient with one solve of the weighted Laplacian of the faces.
// The field is the parallel section of n rho + delta. Its matching is read
// from delta, not rounded from the directions. The construction first tries
// to bring every delta below pi, so that readers who recompute the principal
// matching find the same vertices; where that cannot be (two opposite
// singularities side by side, an index of 2 or more), below n pi, so that
// each direction turns by less than half a turn across every edge and
// readers of the directions with the matching find the same vertices.
// Where that cannot be either, no file can carry the field (solve() says so).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The trees of the construction. Nodes: each interior vertex (node v) and
// each boundary loop (node V + l, its vertices taken together). The faces'
// tree crosses interior edges; the nodes' tree crosses the interior edges
// outside it; the edges left over close the handle loops.
struct Dual_trees
{
  Edge_numbering edges;
  std::vector<Compact_index> face_order;    // every face, each after its parent
  std::vector<Compact_index> entry_corner;  // per face: the parent's corner whose side leads to it (no_index: a root)
  std::vector<unsigned char> in_face_tree;  // per edge
  std::vector<std::size_t> node_of_vertex;  // per vertex (no_index: isolated)
  std::vector<std::vector<std::size_t> > loop_vertices;
  std::vector<std::size_t> node_order;        // every node, each after its parent
  std::vector<Compact_index> node_parent_edge;  // per node (no_index: a root)
  std::vector<std::size_t> handle_edges;
};

// Every interior side around a node, as the side s of a face that ends at
// one of the node's vertices: visit(s). Across s the dual path goes from
// s's face to its twin's; around an interior vertex these paths close.
template <typename Visit>
void for_each_side_around_node(const Indexed_mesh& m, const Dual_trees& t, std::size_t node, const Visit& visit)
{
  auto around = [&](std::size_t v) {
    for(std::size_t corner : m.fan(v))
    {
      const std::size_t side = Indexed_mesh::previous_corner(corner);
      if(m.twin_corner[side] != no_index) visit(side);
    }
  };
  if(node < m.number_of_vertices()) around(node);
  else
    for(std::size_t v : t.loop_vertices[node - m.number_of_vertices()]) around(v);
}

namespace face_prescription_impl {

inline void build_face_tree(const Indexed_mesh& m, const Components& comps, Dual_trees& t)
{
  t.entry_corner.assign(m.number_of_faces(), no_index);
  t.in_face_tree.assign(t.edges.number_of_edges(), 0);
  std::vector<unsigned char> reached(m.number_of_faces(), 0);
  for(const Component& comp : comps.list)
  {
    std::size_t next = t.face_order.size();
    t.face_order.push_back(comp.faces.front());
    reached[comp.faces.front()] = 1;
    for(; next < t.face_order.size(); ++next)
      for(std::size_t side = 3 * t.face_order[next]; side < 3 * t.face_order[next] + 3; ++side)
      {
        const std::size_t twin = m.twin_corner[side];
        if(twin == no_index || reached[twin / 3]) continue;
        reached[twin / 3] = 1;
        t.entry_corner[twin / 3] = side;
        t.in_face_tree[t.edges.edge_of_corner[side]] = 1;
        t.face_order.push_back(twin / 3);
      }
  }
}

// Each boundary vertex belongs to the node of its loop; the root of each
// component is its longest loop's node, or its first vertex when closed.
inline std::vector<std::size_t> number_nodes(const Indexed_mesh& m, const Components& comps, Dual_trees& t)
{
  std::vector<std::size_t> loop_of_edge;
  const std::vector<Edge_cycle> loops = cycles_impl::boundary_loops(m, t.edges, comps, loop_of_edge);
  const std::size_t nv = m.number_of_vertices();
  t.node_of_vertex.assign(nv, no_index);
  for(std::size_t v = 0; v < nv; ++v)
    if(m.fan_size(v) > 0) t.node_of_vertex[v] = v;
  std::vector<std::size_t> root(comps.list.size(), no_index);
  for(std::size_t l = 0; l < loops.size(); ++l)
  {
    t.loop_vertices.emplace_back();
    for(std::size_t e : loops[l].edges)
    {
      const std::size_t v = m.vertex_of_corner(t.edges.corner_of_edge[e]);
      t.node_of_vertex[v] = nv + l;
      t.loop_vertices.back().push_back(v);
    }
    std::size_t& best = root[loops[l].component];
    if(best == no_index || loops[l].edges.size() > t.loop_vertices[best - nv].size()) best = nv + l;
  }
  for(std::size_t c = 0; c < comps.list.size(); ++c)
    if(root[c] == no_index) root[c] = comps.list[c].vertices.front();
  return root;
}

inline void build_node_tree(const Indexed_mesh& m, const std::vector<std::size_t>& roots, Dual_trees& t)
{
  t.node_parent_edge.assign(m.number_of_vertices() + t.loop_vertices.size(), no_index);
  std::vector<unsigned char> reached(t.node_parent_edge.size(), 0);
  std::vector<unsigned char> in_node_tree(t.edges.number_of_edges(), 0);
  for(std::size_t root : roots)
  {
    std::size_t next = t.node_order.size();
    t.node_order.push_back(root);
    reached[root] = 1;
    for(; next < t.node_order.size(); ++next)
    {
      const std::size_t node = t.node_order[next];
      for_each_side_around_node(m, t, node, [&](std::size_t side) {
        const std::size_t e = t.edges.edge_of_corner[side], other = t.node_of_vertex[m.vertex_of_corner(side)];
        if(t.in_face_tree[e] || other == node || reached[other]) return;
        reached[other] = 1;
        in_node_tree[e] = 1;
        t.node_parent_edge[other] = e;
        t.node_order.push_back(other);
      });
    }
  }
  for(std::size_t e = 0; e < t.edges.number_of_edges(); ++e)
    if(m.twin_corner[t.edges.corner_of_edge[e]] != no_index && !t.in_face_tree[e] && !in_node_tree[e])
      t.handle_edges.push_back(e);
}

} // namespace face_prescription_impl

inline Dual_trees dual_trees(const Indexed_mesh& m, const Components& comps)
{
  using namespace face_prescription_impl;
  Dual_trees t;
  t.edges = number_edges(m);
  build_face_tree(m, comps, t);
  build_node_tree(m, number_nodes(m, comps, t), t);
  return t;
}

// The change of the connection across side s, from s's face to its twin's.
inline double change_across(const Dual_trees& t, const Eigen::VectorXd& delta, std::size_t side)
{
  return t.edges.sign_of_corner[side] * delta[static_cast<Eigen::Index>(t.edges.edge_of_corner[side])];
}

// The changes delta with the prescribed indices k (per vertex; interior
// vertices only) and the nearest loop turns. The trees and the factored
// Laplacian of the faces depend on the mesh only: made once, they serve
// every prescription and degree.
class Face_connection_change
{
  const Indexed_mesh& m_mesh;
  const Tangent_spaces& m_spaces;
  const Dual_connection& m_dual;
  Dual_trees m_trees;
  std::vector<Compact_index> m_unknown;  // per face: its unknown in phi (no_index: a root of the faces' tree)
  Eigen::Index m_unknowns = 0;
  Factored_real_matrix m_laplacian;
  int m_degree = 1;
  // What does not depend on the indices, for m_degree: the changes on the
  // handle loops, and each node's target without its 2 pi k (an edit then
  // walks no fan twice).
  int m_cached_degree = 0;
  Eigen::VectorXd m_handle_change;
  std::vector<double> m_node_base;

  double n_rho(std::size_t side) const { return static_cast<double>(m_degree) * m_dual.transport[side]; }

  // The Laplacian of the faces with the dual weights w, phi fixed to 0 at
  // the root face of each component.
  void factor_face_laplacian()
  {
    const Dual_trees& t = m_trees;
    m_unknown.assign(m_mesh.number_of_faces(), no_index);
    m_unknowns = 0;
    for(std::size_t f : t.face_order)
      if(t.entry_corner[f] != no_index) m_unknown[f] = static_cast<std::size_t>(m_unknowns++);
    std::vector<Eigen::Triplet<double> > entries;
    entries.reserve(4 * t.edges.number_of_edges());
    for(std::size_t side = 0; side < 3 * m_mesh.number_of_faces(); ++side)
    {
      const std::size_t twin = m_mesh.twin_corner[side];
      if(twin == no_index || m_unknown[side / 3] == no_index) continue;
      const Eigen::Index i = static_cast<Eigen::Index>(m_unknown[side / 3]);
      const double w = m_dual.weight[t.edges.corner_of_edge[t.edges.edge_of_corner[side]]];
      entries.emplace_back(i, i, w);
      if(m_unknown[twin / 3] != no_index) entries.emplace_back(i, static_cast<Eigen::Index>(m_unknown[twin / 3]), -w);
    }
    Real_sparse_matrix L(m_unknowns, m_unknowns);
    L.setFromTriplets(entries.begin(), entries.end());
    m_laplacian.factor(L);
  }

  // What each node's equation asks of sum delta around it, without the
  // 2 pi k of a vertex.
  double node_base(std::size_t node) const
  {
    if(node >= m_mesh.number_of_vertices())
    {
      double around = 0.;
      for_each_side_around_node(m_mesh, m_trees, node, [&](std::size_t side) { around += n_rho(side); });
      return -reduce_angle(around);
    }
    double defect = 2. * CGAL_PI;
    for(std::size_t corner : m_mesh.fan(node)) defect -= m_spaces.corner_angle[corner];
    return -(static_cast<double>(m_degree) * defect);
  }

  double node_target(std::size_t node, const std::vector<int>& k) const
  {
    const double base = m_node_base[node];
    return node < m_mesh.number_of_vertices() ? 2. * CGAL_PI * k[node] + base : base;
  }

  // The handle loops' changes (their other edges lie in the faces' tree,
  // with no change) and the nodes' bases, for m_degree.
  void cache_degree_terms()
  {
    if(m_cached_degree == m_degree) return;
    const Dual_trees& t = m_trees;
    m_handle_change = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(t.edges.number_of_edges()));
    std::vector<double> turn(m_mesh.number_of_faces(), 0.);  // n rho summed along the faces' tree
    for(std::size_t f : t.face_order)
      if(t.entry_corner[f] != no_index) turn[f] = turn[t.entry_corner[f] / 3] + n_rho(t.entry_corner[f]);
    for(std::size_t e : t.handle_edges)
    {
      const std::size_t side = t.edges.corner_of_edge[e], g = m_mesh.twin_corner[side] / 3;
      m_handle_change[static_cast<Eigen::Index>(e)] = -reduce_angle(turn[side / 3] + n_rho(side) - turn[g]);
    }
    m_node_base.assign(t.node_parent_edge.size(), 0.);
    parallel_for_each_index(t.node_order.size(), [&](std::size_t i) {
      const std::size_t node = t.node_order[i];
      if(t.node_parent_edge[node] != no_index) m_node_base[node] = node_base(node);
    });
    m_cached_degree = m_degree;
  }

  // The handle loops' changes, then each node's equation from the leaves to
  // the roots, solved for the edge to its parent.
  Eigen::VectorXd particular_change(const std::vector<int>& k) const
  {
    const Dual_trees& t = m_trees;
    Eigen::VectorXd delta = m_handle_change;
    for(auto it = t.node_order.rbegin(); it != t.node_order.rend(); ++it)
    {
      const std::size_t node = *it, to_parent = t.node_parent_edge[node];
      if(to_parent == no_index) continue;  // a root: its equation follows from the others
      double sum = 0.;
      int parent_sign = 0;
      for_each_side_around_node(m_mesh, t, node, [&](std::size_t side) {
        if(t.edges.edge_of_corner[side] == to_parent) parent_sign = t.edges.sign_of_corner[side];
        else sum += change_across(t, delta, side);
      });
      delta[static_cast<Eigen::Index>(to_parent)] = (node_target(node, k) - sum) / parent_sign;
    }
    return delta;
  }

  // delta + (phi_g - phi_f) with the least norm: the weighted flow of delta
  // out of each face is the right-hand side.
  void remove_dual_gradient(Eigen::VectorXd& delta) const
  {
    const Dual_trees& t = m_trees;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m_unknowns);
    // per face (its own entry, its sides in order: the same sums on any thread count)
    parallel_for_each_index(m_mesh.number_of_faces(), [&](std::size_t f) {
      if(m_unknown[f] == no_index) return;
      for(std::size_t side = 3 * f; side < 3 * f + 3; ++side)
      {
        if(m_mesh.twin_corner[side] == no_index) continue;
        const double w = m_dual.weight[t.edges.corner_of_edge[t.edges.edge_of_corner[side]]];
        rhs[static_cast<Eigen::Index>(m_unknown[f])] += w * change_across(t, delta, side);
      }
    });
    const Eigen::VectorXd phi = m_laplacian.solve(rhs);
    auto phi_of = [&](std::size_t f) {
      return m_unknown[f] == no_index ? 0. : phi[static_cast<Eigen::Index>(m_unknown[f])];
    };
    parallel_for_each_index(t.edges.number_of_edges(), [&](std::size_t e) {
      const std::size_t side = t.edges.corner_of_edge[e], twin = m_mesh.twin_corner[side];
      if(twin != no_index) delta[static_cast<Eigen::Index>(e)] += phi_of(twin / 3) - phi_of(side / 3);
    });
  }

  // Where some |delta_e| is more than `bound`, a phi on the faces with
  // |delta_e + phi_g - phi_f| <= bound on every edge solves a system of
  // difference constraints: shortest paths from a virtual source joined to
  // every face at length 0 (Bellman-Ford, queued). When none exists some
  // cycle keeps lowering phi; the work is bounded, delta is kept and the
  // answer is false.
  bool fit_below(double bound, Eigen::VectorXd& delta) const
  {
    std::vector<double> phi(m_mesh.number_of_faces(), 0.);
    std::vector<unsigned char> queued(phi.size(), 0);
    std::deque<std::size_t> queue;
    for(std::size_t e = 0; e < m_trees.edges.number_of_edges(); ++e)
      if(std::abs(delta[static_cast<Eigen::Index>(e)]) > bound)
      {
        const std::size_t side = m_trees.edges.corner_of_edge[e];
        for(std::size_t f : {side / 3, m_mesh.twin_corner[side] / 3})
          if(!queued[f]) { queued[f] = 1; queue.push_back(f); }
      }
    const std::size_t budget = 64 * 3 * m_mesh.number_of_faces() + 1000000;
    std::size_t work = 0;
    while(!queue.empty() && work <= budget)
    {
      const std::size_t f = queue.front();
      queue.pop_front();
      queued[f] = 0;
      for(std::size_t side = 3 * f; side < 3 * f + 3; ++side)
      {
        const std::size_t twin = m_mesh.twin_corner[side];
        if(twin == no_index) continue;
        ++work;
        const double limit = phi[f] + bound - change_across(m_trees, delta, side);
        if(phi[twin / 3] <= limit) continue;
        phi[twin / 3] = limit;
        if(!queued[twin / 3]) { queued[twin / 3] = 1; queue.push_back(twin / 3); }
      }
    }
    if(!queue.empty()) return false;
    for(std::size_t e = 0; e < m_trees.edges.number_of_edges(); ++e)
    {
      const std::size_t side = m_trees.edges.corner_of_edge[e], twin = m_mesh.twin_corner[side];
      if(twin != no_index) delta[static_cast<Eigen::Index>(e)] += phi[twin / 3] - phi[side / 3];
    }
    return true;
  }

public:
  Face_connection_change(const Indexed_mesh& m, const Tangent_spaces& ts, const Dual_connection& dc,
                         const Components& comps)
    : m_mesh(m), m_spaces(ts), m_dual(dc), m_trees(dual_trees(m, comps))
  {
    factor_face_laplacian();
  }

  const Dual_trees& trees() const { return m_trees; }

  // The change for degree n; parallel_angles() then uses the same degree.
  // False where some |delta_e| stays n pi or more: a direction then turns
  // by half a turn or more across that edge, which no direction and
  // matching can show.
  bool solve(const std::vector<int>& k, int n, Eigen::VectorXd& delta)
  {
    m_degree = n;
    cache_degree_terms();
    delta = particular_change(k);
    remove_dual_gradient(delta);
    const double principal = CGAL_PI - 1e-9, half_turn = n * (CGAL_PI - 1e-6);
    const double largest = delta.size() > 0 ? delta.cwiseAbs().maxCoeff() : 0.;
    if(largest <= principal || fit_below(principal, delta)) return true;
    return largest <= half_turn || fit_below(half_turn, delta);
  }

  // The angle of the n-th power per face: the parallel section of
  // n rho + delta along the faces' tree, 0 at each root.
  std::vector<double> parallel_angles(const Eigen::VectorXd& delta) const
  {
    std::vector<double> theta(m_mesh.number_of_faces(), 0.);
    for(std::size_t f : m_trees.face_order)
    {
      const std::size_t side = m_trees.entry_corner[f];
      if(side != no_index) theta[f] = reduce_angle(theta[side / 3] + n_rho(side) + change_across(m_trees, delta, side));
    }
    return theta;
  }
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FACE_PRESCRIPTION_H
