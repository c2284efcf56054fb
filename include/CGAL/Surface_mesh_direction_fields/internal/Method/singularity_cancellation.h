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

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

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
// that lie close together are cancelled (user manual, "Fewer
// Singularities"): the prescription of the parallel field that replaces it.

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

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_SINGULARITY_CANCELLATION_H
