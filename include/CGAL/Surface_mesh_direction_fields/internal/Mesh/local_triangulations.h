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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_LOCAL_TRIANGULATIONS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_LOCAL_TRIANGULATIONS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <boost/iterator/counting_iterator.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

// The triangles of a point set (user manual, "Point Sets"): each point's
// neighbours, found with a k-d tree, are projected onto the point's tangent
// plane, and the triangles of their Delaunay triangulation incident to the
// point are its local triangulation. Only that star is needed, so it is read
// off the point's Voronoi cell, cut out of a square by one bisector per
// neighbour, instead of triangulating all the neighbours. A triangle that the local triangulations of
// its three points agree on is listed once with the count 3; one that only one
// or two of them hold, with the count 1 or 2. Points at the same position as
// the centre are left out of its neighbours: they would be the same vertex of
// the plane's triangulation.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Local_triangles
{
  std::vector<std::array<std::size_t, 3> > triangles;  // counter-clockwise about the first holder's normal
  std::vector<unsigned char> holders;                  // how many of the three points' triangulations hold it
  std::vector<std::size_t> nearest;                    // each point's nearest other point (no_point if none)
};

constexpr std::size_t no_point = static_cast<std::size_t>(-1);

// A unit vector orthogonal to the unit vector n (any one; the caller turns it).
inline Vec3 some_orthogonal(const Vec3& n)
{
  const Vec3 axis = (std::abs(n[0]) < 0.6) ? Vec3{1., 0., 0.} : Vec3{0., 1., 0.};
  return normalized(axis - dot(axis, n) * n);
}

// The k nearest neighbours of every point (itself excluded), each list
// ordered from the nearest.
class Neighbour_search
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
  typedef Kernel::Point_3 Point;
  typedef CGAL::Pointer_property_map<Point>::type Point_map;
  typedef CGAL::Search_traits_adapter<std::size_t, Point_map, CGAL::Search_traits_3<Kernel> > Traits;
  typedef CGAL::Orthogonal_k_neighbor_search<Traits> Search;
  typedef Search::Tree Tree;

  std::vector<Point> m_points;
  Point_map m_map;
  Tree m_tree;

public:
  explicit Neighbour_search(const std::vector<Vec3>& points)
    : m_points(to_points(points)),
      m_map(CGAL::make_property_map(m_points)),
      m_tree(boost::counting_iterator<std::size_t>(0), boost::counting_iterator<std::size_t>(points.size()),
             Tree::Splitter(), Traits(m_map))
  {
    m_tree.build();  // before the parallel queries: the tree builds itself lazily otherwise
  }

  void neighbours(std::size_t i, std::size_t k, std::vector<std::size_t>& out) const
  {
    out.clear();
    Search search(m_tree, m_points[i], static_cast<unsigned int>(k + 1), 0., true,
                  Search::Distance(m_map));
    for(const auto& hit : search)
      if(hit.first != i) out.push_back(hit.first);
    if(out.size() > k) out.resize(k);
  }

private:
  static std::vector<Point> to_points(const std::vector<Vec3>& points)
  {
    std::vector<Point> result;
    result.reserve(points.size());
    for(const Vec3& p : points) result.emplace_back(p[0], p[1], p[2]);
    return result;
  }
};

// The Voronoi cell of the origin among points q of the plane, as a convex
// polygon whose edge e runs from corner e to corner e + 1 on the bisector of
// the origin and q = side[e] (no_point: an edge of the bounding square). Its
// edges, counter-clockwise, name the Delaunay neighbours of the origin in
// counter-clockwise order; two consecutive ones, a and b, make the Delaunay
// triangle (origin, a, b).
class Voronoi_cell
{
  struct Corner
  {
    double x, y;
    std::size_t side;  // the neighbour whose bisector the edge from this corner runs on
  };
  std::vector<Corner> m_corners, m_clipped;

public:
  // A square of half-side `reach` about the origin: Delaunay triangles whose
  // circumcentre lies beyond it (slivers) are not found.
  void reset(double reach)
  {
    m_corners = {{-reach, -reach, no_point}, {reach, -reach, no_point}, {reach, reach, no_point},
                 {-reach, reach, no_point}};
  }

  // Keeps the part nearer the origin than q (Sutherland-Hodgman on a convex polygon).
  void clip(double qx, double qy, std::size_t q)
  {
    const double limit = 0.5 * (qx * qx + qy * qy);
    m_clipped.clear();
    const std::size_t m = m_corners.size();
    for(std::size_t e = 0; e < m; ++e)
    {
      const Corner& a = m_corners[e];
      const Corner& b = m_corners[(e + 1) % m];
      const double da = a.x * qx + a.y * qy - limit, db = b.x * qx + b.y * qy - limit;
      const double t = (da - db != 0.) ? da / (da - db) : 0.;
      const Corner crossing = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), no_point};
      if(da <= 0.)
      {
        m_clipped.push_back(a);
        if(db > 0.) m_clipped.push_back({crossing.x, crossing.y, q});  // leaves: the new edge starts here
      }
      else if(db <= 0.)
        m_clipped.push_back({crossing.x, crossing.y, a.side});  // enters: the rest of edge e
    }
    m_corners.swap(m_clipped);
  }

  template <typename Triangle>
  void triangles(const Triangle& triangle) const
  {
    const std::size_t m = m_corners.size();
    for(std::size_t e = 0; e < m; ++e)
    {
      const std::size_t a = m_corners[e].side, b = m_corners[(e + 1) % m].side;
      if(a != no_point && b != no_point && a != b) triangle(a, b);
    }
  }
};

// The triangles of point i's local triangulation, (i, a, b) counter-clockwise
// about normal n, appended to `out`; `nearest` gets the nearest neighbour at
// a positive distance.
inline void local_triangulation(const std::vector<Vec3>& points, const Vec3& n, std::size_t i,
                                const std::vector<std::size_t>& neighbours, Voronoi_cell& cell,
                                std::vector<std::array<std::size_t, 3> >& out, std::size_t& nearest)
{
  nearest = no_point;
  const Vec3 e1 = some_orthogonal(n), e2 = cross(n, e1);
  double reach = 0.;
  for(std::size_t j : neighbours) reach = (std::max)(reach, norm(points[j] - points[i]));
  cell.reset(4. * reach);
  for(std::size_t j : neighbours)
  {
    const Vec3 d = points[j] - points[i];
    if(!(squared_norm(d) > 0.)) continue;
    if(nearest == no_point) nearest = j;
    const double x = dot(d, e1), y = dot(d, e2);
    if(x * x + y * y > 0.) cell.clip(x, y, j);
  }
  cell.triangles([&](std::size_t a, std::size_t b) { out.push_back({i, a, b}); });
}

// The local triangulations of all points (normals of unit length), merged:
// each triangle once, with the number of points whose triangulation holds it.
inline Local_triangles local_triangulations(const std::vector<Vec3>& points, const std::vector<Vec3>& normals,
                                            const Neighbour_search& search, std::size_t k)
{
  Local_triangles result;
  const std::size_t np = points.size();
  result.nearest.assign(np, no_point);
  std::vector<std::vector<std::array<std::size_t, 3> > > per_point(np);
  parallel_for_each_range(np, [&](std::size_t begin, std::size_t end) {
    std::vector<std::size_t> neighbours;
    Voronoi_cell cell;
    for(std::size_t i = begin; i < end; ++i)
    {
      search.neighbours(i, k, neighbours);
      local_triangulation(points, normals[i], i, neighbours, cell, per_point[i], result.nearest[i]);
    }
  });
  // merge: the same three points (in any order) make one triangle
  struct Instance
  {
    std::array<std::size_t, 3> sorted, oriented;
  };
  std::vector<Instance> instances;
  for(auto& list : per_point)
  {
    for(const auto& t : list)
    {
      Instance in{t, t};
      std::sort(in.sorted.begin(), in.sorted.end());
      instances.push_back(in);
    }
    list = {};
  }
  std::stable_sort(instances.begin(), instances.end(),
                   [](const Instance& a, const Instance& b) { return a.sorted < b.sorted; });
  for(std::size_t a = 0; a < instances.size();)
  {
    std::size_t b = a;
    while(b < instances.size() && instances[b].sorted == instances[a].sorted) ++b;
    result.triangles.push_back(instances[a].oriented);
    result.holders.push_back(static_cast<unsigned char>((std::min)(b - a, std::size_t(3))));
    a = b;
  }
  return result;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_LOCAL_TRIANGULATIONS_H
