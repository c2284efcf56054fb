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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_SINGULARITY_CANCELLATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_SINGULARITY_CANCELLATION_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/real_factorization.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/cycles.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <Eigen/Sparse>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <queue>
#include <tuple>
#include <utility>
#include <vector>

// The singularities a field on faces keeps when pairs of opposite indices
// that lie close together are cancelled (user manual, section "Fields on
// Faces", "Fewer singularities"): the prescription of the parallel field
// that replaces a smoothest field, or the turn of a field that follows
// constraints.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The length of the diagonal of the points' bounding box.
inline double bounding_box_diagonal(const Indexed_mesh& m)
{
  if(m.points.empty()) return 0.;
  const std::array<Vec3, 2> box = bounding_box(m.points);
  return norm(box[1] - box[0]);
}

// For the singular vertex `source`, each singular vertex of the opposite
// integer within `radius` along the edges (Dijkstra's search, stopped at
// `radius`), with its distance.
inline void opposite_singularities_within(const Indexed_mesh& m, const std::vector<int>& k, std::size_t source,
                                          double radius, std::vector<double>& distance,
                                          std::vector<std::tuple<double, std::size_t, std::size_t> >& pairs)
{
  typedef std::pair<double, std::size_t> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  std::vector<std::size_t> reached;
  distance[source] = 0.;
  reached.push_back(source);
  queue.emplace(0., source);
  while(!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if(d > distance[v]) continue;
    if(v != source && k[v] == -k[source]) pairs.emplace_back(d, source, v);
    m.for_each_neighbour(v, [&](std::size_t u) {
      const double du = d + norm(m.points[u] - m.points[v]);
      if(du > radius || du >= distance[u]) return;
      if(distance[u] == std::numeric_limits<double>::infinity()) reached.push_back(u);
      distance[u] = du;
      queue.emplace(du, u);
    });
  }
  for(std::size_t u : reached) distance[u] = std::numeric_limits<double>::infinity();  // ready for the next search
}

// The indices k (per vertex) without the cancelled pairs: every pair of
// singular vertices with opposite k (k and -k) at most `radius` apart along
// the edges, taken greedily from the closest pair, each vertex in at most one
// pair. Returns the pairs cancelled (positive vertex, negative vertex).
inline std::vector<std::pair<std::size_t, std::size_t> > cancel_singularity_pairs(const Indexed_mesh& m, double radius,
                                                                                  std::vector<int>& k)
{
  std::vector<double> distance(m.number_of_vertices(), std::numeric_limits<double>::infinity());
  std::vector<std::tuple<double, std::size_t, std::size_t> > pairs;  // (distance, positive vertex, negative vertex)
  for(std::size_t v = 0; v < k.size(); ++v)
    if(k[v] > 0) opposite_singularities_within(m, k, v, radius, distance, pairs);
  std::sort(pairs.begin(), pairs.end());
  std::vector<unsigned char> taken(k.size(), 0);
  std::vector<std::pair<std::size_t, std::size_t> > cancelled;
  for(const auto& [d, positive, negative] : pairs)
  {
    if(taken[positive] || taken[negative]) continue;
    taken[positive] = taken[negative] = 1;
    k[positive] = k[negative] = 0;
    cancelled.emplace_back(positive, negative);
  }
  return cancelled;
}

// The cancelled pair closest to the vertex v (by the nearer of its two
// vertices), as an index into `pairs`.
inline std::size_t closest_pair(const Indexed_mesh& m, const std::vector<std::pair<std::size_t, std::size_t> >& pairs,
                                std::size_t v)
{
  auto distance = [&](std::size_t u) { return norm(m.points[u] - m.points[v]); };
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for(std::size_t i = 0; i < pairs.size(); ++i)
  {
    const double d = (std::min)(distance(pairs[i].first), distance(pairs[i].second));
    if(d < best_distance) { best_distance = d; best = i; }
  }
  return best;
}

// Cancelling pairs in a field that follows constraints (features, the
// boundary, constrained faces, or a guidance it is drawn to): the field is
// kept and only turned, by an angle psi per face, so that each cancelled
// pair's turns vanish. A cut of 2 pi (on the n-th power) runs along the
// edges between the two vertices; psi is the turn, in the dual edges'
// weighted norm, whose rotation across each side differs least from that
// cut, with psi = 0 on the fixed faces. Across each side the field then turns
// by its old rotation minus the part of the cut that psi does not take
// (user manual, section "Fields on Faces", "Fewer singularities"). The cuts
// cross only sides with a free face, as a fixed face cannot turn.

// A pair to cancel and the path of its cut: the sides from the positive
// vertex to the negative one.
struct Cut_pair
{
  double length;
  std::size_t positive, negative;
  std::vector<std::size_t> sides;
};

// For the singular vertex `source`, each singular vertex of the opposite
// integer within `radius` along the edges that a cut may cross (Dijkstra's
// search), with its path. `distance` and `reached_by` (per vertex) come in
// and leave unset (infinity, no_index).
inline void pairs_from(const Indexed_mesh& m, const std::vector<unsigned char>& fixed, const std::vector<int>& k,
                       std::size_t source, double radius, std::vector<double>& distance,
                       std::vector<std::size_t>& reached_by, std::vector<Cut_pair>& found)
{
  typedef std::pair<double, std::size_t> Entry;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry> > queue;
  std::vector<std::size_t> reached{source};
  distance[source] = 0.;
  queue.emplace(0., source);
  while(!queue.empty())
  {
    const auto [d, v] = queue.top();
    queue.pop();
    if(d > distance[v]) continue;
    if(v != source && k[v] == -k[source])  // settled: its path is final
    {
      Cut_pair pair{d, source, v, {}};
      for(std::size_t u = v; u != source; u = m.vertex_of_corner(reached_by[u])) pair.sides.push_back(reached_by[u]);
      found.push_back(std::move(pair));
    }
    for(std::size_t side : m.fan(v))  // the side of corner c runs from v to the next corner's vertex
    {
      const std::size_t twin = m.twin_corner[side];
      if(twin == no_index || m.twin_corner[twin] != side || (fixed[side / 3] && fixed[twin / 3])) continue;
      const std::size_t u = m.vertex_of_corner(Indexed_mesh::next_corner(side));
      const double du = d + norm(m.points[u] - m.points[v]);
      if(du > radius || du >= distance[u]) continue;
      if(reached_by[u] == no_index) reached.push_back(u);
      distance[u] = du;
      reached_by[u] = side;
      queue.emplace(du, u);
    }
  }
  for(std::size_t u : reached) distance[u] = std::numeric_limits<double>::infinity(), reached_by[u] = no_index;
}

// The pairs cancelled greedily from the closest (each vertex in at most one
// pair) with their cuts.
inline std::vector<Cut_pair> pairs_to_cut(const Indexed_mesh& m, const std::vector<unsigned char>& fixed,
                                          double radius, const std::vector<int>& k)
{
  std::vector<double> distance(m.number_of_vertices(), std::numeric_limits<double>::infinity());
  std::vector<std::size_t> reached_by(m.number_of_vertices(), no_index);
  std::vector<Cut_pair> found;
  for(std::size_t v = 0; v < k.size(); ++v)
    if(k[v] > 0) pairs_from(m, fixed, k, v, radius, distance, reached_by, found);
  std::sort(found.begin(), found.end(), [](const Cut_pair& a, const Cut_pair& b) {
    return std::tie(a.length, a.positive, a.negative) < std::tie(b.length, b.positive, b.negative);
  });
  std::vector<unsigned char> taken(k.size(), 0);
  std::vector<Cut_pair> pairs;
  for(Cut_pair& pair : found)
  {
    if(taken[pair.positive] || taken[pair.negative]) continue;
    taken[pair.positive] = taken[pair.negative] = 1;
    pairs.push_back(std::move(pair));
  }
  return pairs;
}

// The cut per side: 2 pi across each side of the paths taken from the
// negative vertex to the positive one (-2 pi the other way).
inline std::vector<double> cut_of(const Indexed_mesh& m, const std::vector<Cut_pair>& pairs)
{
  std::vector<double> cut(3 * m.number_of_faces(), 0.);
  for(const Cut_pair& pair : pairs)
    for(std::size_t side : pair.sides)
    {
      cut[m.twin_corner[side]] += 2. * CGAL_PI;
      cut[side] -= 2. * CGAL_PI;
    }
  return cut;
}

// The fixed faces and, in each region of free faces joined across sides
// that touches none, its first face (psi is then determined).
inline std::vector<unsigned char> with_a_fixed_face_per_region(const Indexed_mesh& m, std::vector<unsigned char> fixed)
{
  std::vector<unsigned char> seen(fixed);
  std::vector<std::size_t> stack;
  for(std::size_t start = 0; start < fixed.size(); ++start)
  {
    if(seen[start]) continue;
    bool touches_fixed = false;
    seen[start] = 1;
    stack.assign(1, start);
    while(!stack.empty())
    {
      const std::size_t f = stack.back();
      stack.pop_back();
      for(std::size_t side = 3 * f; side < 3 * f + 3; ++side)
      {
        const std::size_t twin = m.twin_corner[side];
        if(twin == no_index || m.twin_corner[twin] != side) continue;
        if(fixed[twin / 3]) touches_fixed = true;
        else if(!seen[twin / 3]) { seen[twin / 3] = 1; stack.push_back(twin / 3); }
      }
    }
    if(!touches_fixed) fixed[start] = 1;
  }
  return fixed;
}

// The turn psi per face for a cut: the least squares solution of
// psi_g - psi_f = cut across every side from face f to face g (weights:
// the dual edges'), psi = 0 on the fixed faces. The Laplacian of the free
// faces is factored once for every cut.
class Turning_along_cuts
{
  const Indexed_mesh& m_mesh;
  const std::vector<double>& m_weight;
  std::vector<Eigen::Index> m_unknown;  // per face, -1 where fixed
  Eigen::Index m_unknowns = 0;
  Factored_real_matrix m_laplacian;

  template <typename Visit>
  void for_each_free_side(const Visit& visit) const
  {
    for(std::size_t side = 0; side < 3 * m_mesh.number_of_faces(); ++side)
    {
      const std::size_t twin = m_mesh.twin_corner[side];
      if(twin == no_index || m_mesh.twin_corner[twin] != side || m_unknown[side / 3] < 0) continue;
      visit(side, twin, m_weight[is_representative_side(m_mesh, side) ? side : twin]);
    }
  }

public:
  Turning_along_cuts(const Indexed_mesh& m, const std::vector<double>& weight, const std::vector<unsigned char>& fixed)
    : m_mesh(m), m_weight(weight), m_unknown(m.number_of_faces(), -1)
  {
    const std::vector<unsigned char> pinned = with_a_fixed_face_per_region(m, fixed);
    for(std::size_t f = 0; f < m_unknown.size(); ++f)
      if(!pinned[f]) m_unknown[f] = m_unknowns++;
    std::vector<Eigen::Triplet<double> > entries;
    for_each_free_side([&](std::size_t side, std::size_t twin, double w) {
      entries.emplace_back(m_unknown[side / 3], m_unknown[side / 3], w);
      if(m_unknown[twin / 3] >= 0) entries.emplace_back(m_unknown[side / 3], m_unknown[twin / 3], -w);
    });
    Real_sparse_matrix L(m_unknowns, m_unknowns);
    L.setFromTriplets(entries.begin(), entries.end());
    if(m_unknowns > 0) m_laplacian.factor(L);
  }

  // theta (n-th power angles per face) turned by psi
  std::vector<double> turned(std::vector<double> theta, const std::vector<double>& cut) const
  {
    if(m_unknowns == 0) return theta;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(m_unknowns);
    for_each_free_side([&](std::size_t side, std::size_t, double w) { rhs[m_unknown[side / 3]] -= w * cut[side]; });
    const Eigen::VectorXd psi = m_laplacian.solve(rhs);
    for(std::size_t f = 0; f < theta.size(); ++f)
      if(m_unknown[f] >= 0) theta[f] += psi[m_unknown[f]];
    return theta;
  }
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_SINGULARITY_CANCELLATION_H
