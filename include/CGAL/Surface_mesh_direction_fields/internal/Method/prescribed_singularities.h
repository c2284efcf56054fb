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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_PRESCRIBED_SINGULARITIES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_PRESCRIBED_SINGULARITIES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/real_factorization.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/cycles.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/singularities.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <cmath>
#include <complex>
#include <deque>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

// Fields with prescribed singularities (user manual, section "Placing
// Singularities"): the transport angles rho_e of the connection of degree n
// change by the least x_e (in the norm sum_e x_e^2 |e*| / |e|, the L2 norm of
// x as a 1-form) such that the holonomy around every face t becomes
// 2 pi k_t, and around every other loop of the cycle basis (the handle
// loops, and every boundary loop but the longest of its component) the
// multiple of 2 pi nearest to the connection's own. The adjusted connection is then flat with trivial holonomy, and its
// parallel section, propagated along a spanning tree, has index k_t in
// every face t, as long as no |x_e| reaches pi.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// How far below pi the change of the connection stays along every edge, so
// that the field's rotation there, recomputed from its angles, cannot round
// to the other side of the half turn (and the local checks ask the same).
constexpr double half_turn_margin = 1e-9;

// The distance from the centroid of a triangle to the midpoint of side a
// (a third of the median): the triangle's share of the dual edge.
inline double centroid_to_midpoint(double a2, double b2, double c2)
{
  return std::sqrt((std::max)(0., 2. * b2 + 2. * c2 - a2)) / 6.;
}

// w_e = |e| / |e*| per edge, |e*| through the centroids of its faces (always
// positive, unlike the circumcentric dual on obtuse triangles); dimensionless,
// so the change x does not depend on the mesh's scale.
inline Eigen::VectorXd dual_edge_weights(const Indexed_mesh& m, const Tangent_spaces& ts, const Edge_numbering& edges)
{
  Eigen::VectorXd primal = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(edges.number_of_edges()));
  Eigen::VectorXd dual = primal;
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
  {
    const Face_geometry g = face_geometry(m, f, ts.mollification);
    for(int c = 0; c < 3; ++c)
    {
      const Eigen::Index e = static_cast<Eigen::Index>(edges.edge_of_corner[3 * f + c]);
      const double a2 = g.squared_length[c];
      primal[e] = std::sqrt(a2);
      dual[e] += centroid_to_midpoint(a2, g.squared_length[(c + 1) % 3], g.squared_length[(c + 2) % 3]);
    }
  }
  Eigen::VectorXd weight(primal.size());
  for(Eigen::Index e = 0; e < primal.size(); ++e)
    weight[e] = primal[e] / (std::max)(dual[e], 1e-12 * primal[e]);
  return weight;
}

// The changes x of the connection for prescribed face indices, with what
// they need kept from one prescription to the next on the same mesh: the
// cycle basis and the factored vertex Laplacian d0^T W^-1 d0.
//
// Every x that meets the equations (a holonomy for every face and for every
// loop of the cycle basis) is one of them plus the gradient d0 phi of a
// function on the vertices, since the equations fix the holonomy of every
// cycle. A particular x comes from one sweep of the cotree, from its leaves
// to its roots (each face's equation sets the change on the edge to its
// parent; the tree's edges keep 0, the left-over edges close their handle
// loop); the least-norm x = x_p + d0 phi then solves
//     d0^T W^-1 d0 phi = -d0^T W^-1 x_p,
// phi fixed to 0 at each component's first vertex.
class Connection_adjustment
{
  Edge_numbering m_edges;
  Cycle_basis m_basis;
  Eigen::VectorXd m_weight;                 // w_e = |e| / |e*|: the norm is sum_e x_e^2 / w_e
  std::vector<Compact_index> m_unknown;     // the unknown of each vertex in phi (no_index: fixed or isolated)
  Eigen::Index m_unknowns = 0;
  Factored_real_matrix m_laplacian;
  bool m_factored = false;

  std::size_t tail(std::size_t e, const Indexed_mesh& m) const { return m.vertex_of_corner(m_edges.corner_of_edge[e]); }
  std::size_t head(std::size_t e, const Indexed_mesh& m) const
  {
    return m.vertex_of_corner(Indexed_mesh::next_corner(m_edges.corner_of_edge[e]));
  }

  void number_unknowns(const Indexed_mesh& m)
  {
    m_unknown.assign(m.number_of_vertices(), no_index);
    m_unknowns = 0;
    for(std::size_t v : m_basis.tree_order)
      if(m_basis.parent[v] != no_index) m_unknown[v] = static_cast<std::size_t>(m_unknowns++);
  }

  Real_sparse_matrix vertex_laplacian(const Indexed_mesh& m) const
  {
    std::vector<Eigen::Triplet<double> > entries;
    entries.reserve(4 * m_edges.number_of_edges());
    for(std::size_t e = 0; e < m_edges.number_of_edges(); ++e)
    {
      const std::size_t i = m_unknown[tail(e, m)], j = m_unknown[head(e, m)];
      const double a = 1. / m_weight[static_cast<Eigen::Index>(e)];
      const Eigen::Index ii = static_cast<Eigen::Index>(i), jj = static_cast<Eigen::Index>(j);
      if(i != no_index) entries.emplace_back(ii, ii, a);
      if(j != no_index) entries.emplace_back(jj, jj, a);
      if(i != no_index && j != no_index)
      {
        entries.emplace_back(ii, jj, -a);
        entries.emplace_back(jj, ii, -a);
      }
    }
    Real_sparse_matrix L(m_unknowns, m_unknowns);
    L.setFromTriplets(entries.begin(), entries.end());
    return L;
  }

  // x with every equation met: b_node the holonomy change each cotree node
  // asks for (faces, then boundary loops), b_handle that of each handle loop
  Eigen::VectorXd particular_change(const std::vector<double>& b_node, const std::vector<double>& b_handle) const
  {
    const std::size_t nf = b_node.size() - m_basis.boundary_loops.size();
    Eigen::VectorXd x = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m_edges.number_of_edges()));
    for(std::size_t l = 0; l < m_basis.handle_loops.size(); ++l)  // its other edges are the tree's: 0
      x[static_cast<Eigen::Index>(m_basis.handle_loops[l].edges.front())] = b_handle[l];
    for(auto it = m_basis.cotree_order.rbegin(); it != m_basis.cotree_order.rend(); ++it)
    {
      const std::size_t node = *it, to_parent = m_basis.cotree_parent_edge[node];
      if(to_parent == no_index) continue;  // a root: its equation follows from the others
      double sum = 0.;
      int parent_sign = 0;
      for_each_side_of_node(m_edges, m_basis, nf, node, [&](std::size_t e, int sign) {
        if(e == to_parent) parent_sign = sign;
        else sum += sign * x[static_cast<Eigen::Index>(e)];
      });
      x[static_cast<Eigen::Index>(to_parent)] = (b_node[node] - sum) / parent_sign;
    }
    return x;
  }

  // x + d0 phi with the least norm
  void remove_gradient(const Indexed_mesh& m, Eigen::VectorXd& x) const
  {
    // -d0^T W^-1 x at each unknown vertex: the weighted flow of x out of it
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m_unknowns);
    parallel_for_each_index(m.number_of_vertices(), [&](std::size_t v) {
      if(m_unknown[v] == no_index) return;
      double out = 0.;
      for_each_edge_at(m, m_edges, v, [&](std::size_t, std::size_t e, int sign) {
        out += sign * x[static_cast<Eigen::Index>(e)] / m_weight[static_cast<Eigen::Index>(e)];
      });
      rhs[static_cast<Eigen::Index>(m_unknown[v])] = out;
    });
    const Eigen::VectorXd phi_unknowns = m_laplacian.solve(rhs);
    Eigen::VectorXd phi = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m.number_of_vertices()));
    for(std::size_t v = 0; v < m_unknown.size(); ++v)
      if(m_unknown[v] != no_index) phi[static_cast<Eigen::Index>(v)] = phi_unknowns[static_cast<Eigen::Index>(m_unknown[v])];
    x += gradient(m, phi);
  }

public:
  // The cycle basis only: reading a field's loop turns needs no more. The
  // norm and the factored Laplacian come with factor(), before solve().
  Connection_adjustment(const Indexed_mesh& m, const Components& comps)
    : m_edges(number_edges(m)), m_basis(find_cycle_basis(m, m_edges, comps))
  {
  }

  bool is_factored() const { return m_factored; }
  void factor(const Indexed_mesh& m, const Tangent_spaces& ts)
  {
    m_weight = dual_edge_weights(m, ts, m_edges);
    number_unknowns(m);
    m_laplacian.factor(vertex_laplacian(m));
    m_factored = true;
  }

  const Edge_numbering& edges() const { return m_edges; }
  const Cycle_basis& cycle_basis() const { return m_basis; }

  // rho_e: the transport angle along each edge's orientation
  Eigen::VectorXd transport_angles(const Connection& con) const
  {
    Eigen::VectorXd rho(static_cast<Eigen::Index>(m_edges.number_of_edges()));
    for(std::size_t e = 0; e < m_edges.number_of_edges(); ++e)
      rho[static_cast<Eigen::Index>(e)] = std::arg(con.transport[m_edges.corner_of_edge[e]]);
    return rho;
  }

  // The sum of `angle` around a cycle
  static double sum_around(const Edge_cycle& loop, const Eigen::VectorXd& angle)
  {
    double sum = 0.;
    for(std::size_t i = 0; i < loop.edges.size(); ++i) sum += loop.signs[i] * angle[static_cast<Eigen::Index>(loop.edges[i])];
    return sum;
  }
  double sum_around_face(std::size_t f, const Eigen::VectorXd& angle) const
  {
    double sum = 0.;
    for(std::size_t ci = 3 * f; ci < 3 * f + 3; ++ci)
      sum += m_edges.sign_of_corner[ci] * angle[static_cast<Eigen::Index>(m_edges.edge_of_corner[ci])];
    return sum;
  }

  // The holonomy change a loop asks for: to the multiple of 2 pi nearest to
  // sum rho around it (plus `turns` more)
  static double loop_change(const Edge_cycle& loop, const Eigen::VectorXd& rho, int turns = 0)
  {
    return 2. * CGAL_PI * turns - reduce_angle(sum_around(loop, rho));
  }

  // The loops whose turning can be chosen: the handle loops, then the
  // boundary loops (loop(l) for l below number_of_loops()).
  std::size_t number_of_loops() const { return m_basis.handle_loops.size() + m_basis.boundary_loops.size(); }
  const Edge_cycle& loop(std::size_t l) const
  {
    const std::size_t handles = m_basis.handle_loops.size();
    return l < handles ? m_basis.handle_loops[l] : m_basis.boundary_loops[l - handles];
  }
  bool is_free_loop(std::size_t l) const
  {
    const std::size_t handles = m_basis.handle_loops.size();
    return l >= handles && m_basis.is_free[l - handles];
  }

  // The turns of loop l under the change x: how many times 2 pi its turning
  // exceeds the nearest multiple (what `turns` of solve() asks of it).
  int turns_of(std::size_t l, const Eigen::VectorXd& rho, const Eigen::VectorXd& x) const
  {
    return static_cast<int>(std::lround((sum_around(loop(l), x) - loop_change(loop(l), rho)) / (2. * CGAL_PI)));
  }

  // The turns of a field u (a coefficient per vertex) along every loop: its
  // change of the connection along each edge is its rotation against the
  // transport, in (-pi, pi] as face_indices() takes it, so that solve() with
  // u's face indices and these turns gives u's singularities back.
  // Only the loops whose turns can be chosen and differ from 0 are listed.
  std::vector<std::pair<std::size_t, int> > turns_of_field(const Indexed_mesh& m, const Eigen::VectorXd& rho,
                                                           const std::vector<std::complex<double> >& u) const
  {
    std::vector<double> theta(u.size());
    parallel_for_each_index(u.size(), [&](std::size_t v) { theta[v] = std::arg(u[v]); });  // arg(0) = 0
    Eigen::VectorXd x(rho.size());
    parallel_for_each_index(m_edges.number_of_edges(), [&](std::size_t e) {
      const Eigen::Index i = static_cast<Eigen::Index>(e);
      x[i] = reduce_angle(theta[head(e, m)] - theta[tail(e, m)] - rho[i]);
    });
    std::vector<std::pair<std::size_t, int> > turns;
    for(std::size_t l = 0; l < number_of_loops(); ++l)
    {
      const int t = is_free_loop(l) ? 0 : turns_of(l, rho, x);
      if(t != 0) turns.emplace_back(l, t);
    }
    return turns;
  }

  // x for the face indices k (the holonomy Omega_t + sum x = 2 pi k_t in every
  // face) and, around every other loop of the basis, the nearest multiple of
  // 2 pi plus `turns[l]` times 2 pi (missing entries: 0; a free loop's entry
  // is not used: it follows); the least such x, or (`below_half_turn`)
  // changed by a local rotation where it turns by pi or more along an edge.
  Eigen::VectorXd solve(const Indexed_mesh& m, const Connection& con, const Eigen::VectorXd& rho,
                        const std::vector<int>& k, const std::vector<int>& turns = {},
                        bool below_half_turn = true) const
  {
    auto turns_of_loop = [&turns](std::size_t l) { return l < turns.size() ? turns[l] : 0; };
    const std::size_t nf = k.size();
    std::vector<double> b_node(nf + m_basis.boundary_loops.size());
    for(std::size_t f = 0; f < nf; ++f) b_node[f] = 2. * CGAL_PI * k[f] - con.holonomy[f];
    for(std::size_t l = 0; l < m_basis.boundary_loops.size(); ++l)
      b_node[nf + l] = loop_change(m_basis.boundary_loops[l], rho, turns_of_loop(m_basis.handle_loops.size() + l));
    std::vector<double> b_handle(m_basis.handle_loops.size());
    for(std::size_t l = 0; l < b_handle.size(); ++l)
      b_handle[l] = loop_change(m_basis.handle_loops[l], rho, turns_of_loop(l));
    Eigen::VectorXd x = particular_change(b_node, b_handle);
    remove_gradient(m, x);
    if(below_half_turn && x.cwiseAbs().maxCoeff() >= largest_change) keep_within_half_turn(m, x);
    if(below_half_turn && x.cwiseAbs().maxCoeff() >= CGAL_PI - half_turn_margin) fit_below_half_turn(m, x);
    return x;
  }

private:
  // A change of more than pi along an edge is not seen by a field on the
  // vertices (its rotation along an edge is taken in (-pi, pi]): the
  // singularity would move to a neighbouring face. Any two changes that meet
  // all the equations differ by a gradient (the equations fix the holonomy
  // of every cycle), and adding the gradient of phi only rotates the
  // parallel field by phi at each vertex. So where the least-norm change
  // has such edges, a phi near them is found that brings every edge below
  // pi: the least squares of x + d0 phi over a few rings of vertices around
  // them, in the same norm with those edges' weights raised by the square of
  // their excess over `target_change`, again until none is left (or after
  // `rounds`; the caller checks the field's indices).
  static constexpr double largest_change = 0.97 * CGAL_PI;
  static constexpr double target_change = 0.75 * CGAL_PI;
  static constexpr int rounds = 12;
  static constexpr int rings = 3;

  void keep_within_half_turn(const Indexed_mesh& m, Eigen::VectorXd& x) const
  {
    const Eigen::VectorXd least_norm = x;
    Eigen::VectorXd penalty = Eigen::VectorXd::Ones(x.size());
    std::vector<std::size_t> seeds;
    for(int round = 0; round < rounds && x.cwiseAbs().maxCoeff() >= largest_change; ++round)
    {
      for(Eigen::Index e = 0; e < x.size(); ++e)
        if(std::abs(x[e]) > target_change)
        {
          penalty[e] *= std::pow(std::abs(x[e]) / target_change, 2);
          seeds.push_back(static_cast<std::size_t>(e));
        }
      const Vertex_region region = rings_around(m, seeds);
      set_rotated_change(m, least_norm, region, local_rotation(m, least_norm, penalty, region), x);
    }
  }

  // Where the smooth local rotations leave an edge at pi or more, the
  // rotations phi with |x_e + (d0 phi)_e| <= pi - margin on every edge are
  // the solutions of a system of difference constraints, phi_w - phi_v <=
  // c_vw, one per edge and direction: shortest paths from a virtual source
  // joined to every vertex at length 0 (Bellman-Ford, queued: only the
  // vertices that change are visited again). A solution exists whenever
  // some field on the vertices has these singularities (its own change is
  // one), and then phi is 0 away from the offending edges. When none exists
  // some cycle keeps lowering phi; the work is bounded and x is left as it
  // was (the caller then refuses the prescription).
  void fit_below_half_turn(const Indexed_mesh& m, Eigen::VectorXd& x) const
  {
    const double bound = CGAL_PI - half_turn_margin;
    std::vector<double> phi(m.number_of_vertices(), 0.);
    std::vector<unsigned char> queued(phi.size(), 0);
    std::deque<std::size_t> queue;
    for(std::size_t e = 0; e < m_edges.number_of_edges(); ++e)
      if(std::abs(x[static_cast<Eigen::Index>(e)]) > bound)
        for(std::size_t v : {tail(e, m), head(e, m)})
          if(!queued[v]) { queued[v] = 1; queue.push_back(v); }
    const std::size_t budget = 64 * m_edges.number_of_edges() + 1000000;
    std::size_t work = 0;
    while(!queue.empty())
    {
      const std::size_t v = queue.front();
      queue.pop_front();
      queued[v] = 0;
      for_each_edge_at(m, m_edges, v, [&](std::size_t w, std::size_t e, int sign) {
        ++work;
        const double limit = phi[v] + bound - sign * x[static_cast<Eigen::Index>(e)];
        if(phi[w] <= limit) return;
        phi[w] = limit;
        if(!queued[w]) { queued[w] = 1; queue.push_back(w); }
      });
      if(work > budget) return;
    }
    for(std::size_t e = 0; e < m_edges.number_of_edges(); ++e)
      x[static_cast<Eigen::Index>(e)] += phi[head(e, m)] - phi[tail(e, m)];
  }

  // The vertices within `rings` edges of the seed edges: local[v] is v's
  // position in `vertices` (no_index outside)
  struct Vertex_region
  {
    std::vector<Compact_index> local;
    std::vector<std::size_t> vertices;
  };

  // x = x0 + d0 phi on the edges at the region's vertices (phi = 0 outside;
  // the regions of successive rounds grow, so the other edges keep x0)
  void set_rotated_change(const Indexed_mesh& m, const Eigen::VectorXd& x0, const Vertex_region& region,
                          const Eigen::VectorXd& phi, Eigen::VectorXd& x) const
  {
    auto phi_at = [&](std::size_t v) {
      return region.local[v] == no_index ? 0. : phi[static_cast<Eigen::Index>(region.local[v])];
    };
    for(std::size_t v : region.vertices)
      for_each_edge_at(m, m_edges, v, [&](std::size_t, std::size_t e, int) {
        x[static_cast<Eigen::Index>(e)] = x0[static_cast<Eigen::Index>(e)] + phi_at(head(e, m)) - phi_at(tail(e, m));
      });
  }

  Vertex_region rings_around(const Indexed_mesh& m, const std::vector<std::size_t>& seeds) const
  {
    std::vector<Compact_index> local(m.number_of_vertices(), no_index);
    std::vector<std::size_t> region;
    auto add = [&](std::size_t v) {
      if(local[v] != no_index) return;
      local[v] = region.size();
      region.push_back(v);
    };
    for(std::size_t e : seeds)
    {
      add(m.vertex_of_corner(m_edges.corner_of_edge[e]));
      add(m.vertex_of_corner(Indexed_mesh::next_corner(m_edges.corner_of_edge[e])));
    }
    for(int ring = 0, first = 0; ring < rings; ++ring)
    {
      const std::size_t end = region.size();
      for(std::size_t i = static_cast<std::size_t>(first); i < end; ++i)
        for_each_edge_at(m, m_edges, region[i], [&](std::size_t w, std::size_t, int) { add(w); });
      first = static_cast<int>(end);
    }
    return Vertex_region{std::move(local), std::move(region)};
  }

  // phi on the region's vertices (0 elsewhere) minimizing
  // sum_e penalty_e / w_e (x_e + (d0 phi)_e)^2 over the edges at them.
  Eigen::VectorXd local_rotation(const Indexed_mesh& m, const Eigen::VectorXd& x, const Eigen::VectorXd& penalty,
                                 const Vertex_region& region) const
  {
    const std::vector<Compact_index>& local = region.local;
    const Eigen::Index size = static_cast<Eigen::Index>(region.vertices.size());
    std::vector<Eigen::Triplet<double> > entries;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
    for(std::size_t v : region.vertices)
      for_each_edge_at(m, m_edges, v, [&](std::size_t w, std::size_t e, int sign) {
        // the term of edge e = (v, w) from v's side; (d0 phi)_e = sign (phi_w - phi_v)
        const Eigen::Index a = static_cast<Eigen::Index>(local[v]);
        const double weight = penalty[static_cast<Eigen::Index>(e)] / m_weight[static_cast<Eigen::Index>(e)];
        entries.emplace_back(a, a, weight);
        if(local[w] != no_index) entries.emplace_back(a, static_cast<Eigen::Index>(local[w]), -weight);
        rhs[a] += sign * weight * x[static_cast<Eigen::Index>(e)];
      });
    Real_sparse_matrix H(size, size);
    H.setFromTriplets(entries.begin(), entries.end());
    // a region that covers a whole component has no fixed vertex: phi up to a constant
    const double regularization = 1e-12 * H.diagonal().maxCoeff();
    for(Eigen::Index i = 0; i < size; ++i) H.coeffRef(i, i) += regularization;
    Eigen::SimplicialLDLT<Real_sparse_matrix> solver(H);
    const Eigen::VectorXd phi = solver.solve(rhs);
    if(solver.info() != Eigen::Success || !phi.allFinite()) return Eigen::VectorXd::Zero(size);
    return phi;
  }

  // (d0 phi)_e = phi(head) - phi(tail) along each edge's orientation
  Eigen::VectorXd gradient(const Indexed_mesh& m, const Eigen::VectorXd& phi) const
  {
    Eigen::VectorXd d(static_cast<Eigen::Index>(m_edges.number_of_edges()));
    parallel_for_each_index(m_edges.number_of_edges(), [&](std::size_t e) {
      d[static_cast<Eigen::Index>(e)] = phi[static_cast<Eigen::Index>(head(e, m))] - phi[static_cast<Eigen::Index>(tail(e, m))];
    });
    return d;
  }

public:
  // The largest error of the holonomy the adjusted connection rho + x has
  // around a face (against 2 pi k_t) or a constrained loop (against a
  // multiple of 2 pi), in radians.
  double holonomy_error(const Connection& con, const Eigen::VectorXd& rho, const Eigen::VectorXd& x,
                        const std::vector<int>& k) const
  {
    double largest = 0.;
    for(std::size_t f = 0; f < k.size(); ++f)
      largest = (std::max)(largest, std::abs(con.holonomy[f] + sum_around_face(f, x) - 2. * CGAL_PI * k[f]));
    const Eigen::VectorXd adjusted = rho + x;
    for(const Edge_cycle& loop : m_basis.handle_loops)
      largest = (std::max)(largest, std::abs(reduce_angle(sum_around(loop, adjusted))));
    for(std::size_t l = 0; l < m_basis.boundary_loops.size(); ++l)
      if(!m_basis.is_free[l])
        largest = (std::max)(largest, std::abs(reduce_angle(sum_around(m_basis.boundary_loops[l], adjusted))));
    return largest;
  }
};

// The face indices of u with the transport angles per edge (rho, as
// Connection_adjustment::transport_angles() gives them): the same as
// face_indices(m, con, u) without an arctangent per corner.
inline std::vector<int> face_indices_with_edge_angles(const Indexed_mesh& m, const Connection& con,
                                                      const Edge_numbering& edges, const Eigen::VectorXd& rho,
                                                      const std::vector<std::complex<double> >& u)
{
  auto corner_angle = [&](std::size_t ci) {
    return edges.sign_of_corner[ci] * rho[static_cast<Eigen::Index>(edges.edge_of_corner[ci])];
  };
  return face_indices(m, con.holonomy, corner_angle, u);
}

// The parallel section of the adjusted connection rho + x: unit coefficients,
// angle 0 at each component's root, carried along the spanning tree.
inline std::vector<std::complex<double> > parallel_section(const Cycle_basis& basis, std::size_t number_of_vertices,
                                                           const Eigen::VectorXd& rho, const Eigen::VectorXd& x)
{
  std::vector<double> theta(number_of_vertices, 0.);
  for(std::size_t w : basis.tree_order)
  {
    if(basis.parent[w] == no_index) continue;
    const Eigen::Index e = static_cast<Eigen::Index>(basis.parent_edge[w]);
    theta[w] = reduce_angle(theta[basis.parent[w]] + basis.parent_sign[w] * (rho[e] + x[e]));
  }
  std::vector<std::complex<double> > u(number_of_vertices, std::complex<double>(0., 0.));
  parallel_for_each_index(basis.tree_order.size(), [&](std::size_t i) {
    const std::size_t w = basis.tree_order[i];
    u[w] = std::polar(1., theta[w]);
  });
  return u;
}

// What the refusals of a prescription add: the field on faces has no such
// limit (user manual, section "Fields on Faces").
inline std::string face_field_can_show()
{
  return "; a field on faces (compute_globally_optimal_face_directions(), the program's --on faces) places "
         "singularities at vertices and shows any indices there that satisfy Poincare-Hopf, side by side included";
}

// Why face f cannot hold index k/n: the field turns by less than pi along
// each side, so 2 pi k must be within 3 pi of the face's curvature times n.
inline std::string unholdable_index_message(std::size_t f, int k, const Connection& con)
{
  const std::string face = "face " + std::to_string(f);
  const std::string turns = compact_number(con.holonomy[f] / (2. * CGAL_PI));
  // the turns are those of the field's n-th power, u, which the index counts
  if(k == 0)
    return face + " is not listed, but a field of degree " + std::to_string(con.degree) + " must have a singularity "
           "there: its curvature turns the field's n-th power " + turns + " times around it, more than the one and a "
           "half a face without one can take (list it with an index near that, or lower the degree)";
  return face + " cannot hold index " + std::to_string(k) + "/" + std::to_string(con.degree) +
         ": with its curvature the field's n-th power would turn " +
         compact_number(std::abs(k - con.holonomy[f] / (2. * CGAL_PI))) +
         " times along its sides, and a field on the vertices turns at most one and a half times around a triangle "
         "(spread the index over neighbouring faces)" + face_field_can_show();
}

// Two neighbouring faces together: the field turns by less than pi along
// each of the four sides around them, so their indices with their curvature
// must ask less than two turns (two singularities of the same sign side by
// side on a flat part would need a half turn on all four sides). A local check that
// refuses the most common impossible prescriptions before any solve.
inline void check_neighbouring_faces(const Indexed_mesh& m, const Connection& con, const std::vector<int>& k)
{
  for(std::size_t ci = 0; ci < 3 * m.number_of_faces(); ++ci)
  {
    const std::size_t twin = m.twin_corner[ci];
    if(twin == no_index || twin < ci || m.twin_corner[twin] != ci) continue;
    const std::size_t f = Indexed_mesh::face_of_corner(ci), g = Indexed_mesh::face_of_corner(twin);
    if(k[f] == 0 && k[g] == 0) continue;
    const double asked = 2. * CGAL_PI * (k[f] + k[g]) - con.holonomy[f] - con.holonomy[g];
    if(!(std::abs(asked) <= 4. * (CGAL_PI - half_turn_margin)))
      throw Invalid_input_error("face " + std::to_string(f) + " (index " + std::to_string(k[f]) + "/" +
                                  std::to_string(con.degree) + ") and its neighbour, face " + std::to_string(g) +
                                  " (index " + std::to_string(k[g]) + "/" + std::to_string(con.degree) +
                                  "), ask the field to turn " + compact_number(std::abs(asked) / (2. * CGAL_PI)) +
                                  " times along their four outer sides, where it turns less than two (move them apart)" +
                                  face_field_can_show(),
                                f);
  }
}

// Poincare-Hopf on closed component c: its prescribed k add up to n chi.
inline void check_index_sum(std::size_t c, long long sum, int degree, int euler_characteristic)
{
  const long long expected = static_cast<long long>(degree) * euler_characteristic;
  if(sum != expected)
    throw Invalid_input_error("the prescribed indices of closed component " + std::to_string(c) + " add up to " +
                              std::to_string(sum) + ", but Poincare-Hopf requires n chi = " + std::to_string(degree) +
                              " * " + std::to_string(euler_characteristic) + " = " + std::to_string(expected));
}

// The checks of a prescription that need no solve: an index each face can
// show, alone and with each neighbour, and Poincare-Hopf on each closed
// component (sum k = n chi).
inline void check_prescription(const Indexed_mesh& m, const Components& comps, const Connection& con,
                               const std::vector<Component_report>& reports, const std::vector<int>& k)
{
  for(std::size_t f = 0; f < k.size(); ++f)
    // the field turns by less than pi along each of the three sides
    if(!(std::abs(2. * CGAL_PI * k[f] - con.holonomy[f]) <= 3. * (CGAL_PI - half_turn_margin)))
      throw Invalid_input_error(unholdable_index_message(f, k[f], con), f);
  check_neighbouring_faces(m, con, k);
  for(std::size_t c = 0; c < comps.list.size(); ++c)
  {
    if(!reports[c].is_closed) continue;
    long long sum = 0;
    for(std::size_t f : comps.list[c].faces) sum += k[f];
    check_index_sum(c, sum, con.degree, reports[c].euler_characteristic);
  }
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_PRESCRIBED_SINGULARITIES_H
