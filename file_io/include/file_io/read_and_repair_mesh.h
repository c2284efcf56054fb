// Reading a mesh file as the command-line program does: as a polygon soup
// (read_polygon_soup.h), repaired into a triangle mesh whose vertices and
// faces keep track of the file's, so that the outputs can be written in the
// file's order.
//
// Repairs, each counted in a Repair_report:
//  1. points with identical coordinates are merged (the first one is kept);
//  2. repeated consecutive vertices are removed from each polygon, and polygons
//     left with fewer than 3 vertices are dropped;
//  3. polygons with more than 3 vertices are triangulated by CGAL's
//     Polygon_mesh_processing (a fan if that fails, beyond 256 vertices, or
//     once a time budget is spent: see triangulate_polygon());
//  4. repeated triangles (same three vertices) are dropped;
//  5. the triangles are oriented consistently, and non-manifold vertices are
//     duplicated, by CGAL::Polygon_mesh_processing::orient_polygon_soup();
//  6. a triangle that still cannot be added to the mesh is skipped.
// A vertex of the file is represented by the mesh vertex of its first copy.
// Steps 1, 2 and 4 are sorts; step 5 runs only when the triangles are not
// already an oriented manifold mesh (no directed edge twice, every vertex one
// fan), so that a clean file goes straight to the mesh.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_READ_AND_REPAIR_MESH_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_READ_AND_REPAIR_MESH_H

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#endif

#include "read_polygon_soup.h"

#include <algorithm>
#include <numeric>
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

struct Repair_report
{
  std::size_t merged_points = 0;
  std::size_t degenerate_polygons = 0;
  std::size_t triangulated_polygons = 0, triangles_from_polygons = 0;
  std::size_t repeated_triangles = 0;
  std::size_t reoriented_triangles = 0;
  std::size_t duplicated_vertices = 0;
  std::size_t skipped_triangles = 0;
  std::size_t unused_vertices = 0;

  bool any() const
  {
    return merged_points + degenerate_polygons + triangulated_polygons + repeated_triangles + reoriented_triangles +
           duplicated_vertices + skipped_triangles + unused_vertices > 0;
  }
  std::string summary() const
  {
    std::ostringstream os;
    const char* sep = "";
    auto item = [&](std::size_t n, const std::string& what) { if(n) { os << sep << n << " " << what; sep = ", "; } };
    item(merged_points, "duplicate points merged");
    item(degenerate_polygons, "degenerate faces removed");
    if(triangulated_polygons)
    { os << sep << triangulated_polygons << " polygons triangulated into " << triangles_from_polygons << " triangles"; sep = ", "; }
    item(repeated_triangles, "repeated faces removed");
    item(reoriented_triangles, "faces reoriented");
    item(duplicated_vertices, "non-manifold vertices duplicated");
    item(skipped_triangles, "faces skipped");
    item(unused_vertices, "vertices without a face left out");
    return os.str();
  }
};

template <typename Mesh>
struct Repaired_mesh
{
  typedef typename Mesh::Vertex_index Vertex_index;
  Mesh mesh;
  std::size_t file_vertices = 0, file_faces = 0;
  std::vector<Vertex_index> vertex_of_file_vertex;  // file vertex -> mesh vertex (first copy; null if unused)
  std::vector<std::size_t> file_face_of_face;       // mesh face -> polygon of the file
  std::vector<std::size_t> file_vertex_of_vertex;   // mesh vertex -> the file vertex it copies
  Repair_report report;
};

namespace read_and_repair_internal {

// The repair's independent loops and steps: on TBB's threads when CGAL is
// linked with it (each index writes only its own outputs), one after the
// other otherwise.
template <typename Body>
void for_each_index(std::size_t n, const Body& body)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 4096), [&body](const tbb::blocked_range<std::size_t>& r) {
    for(std::size_t i = r.begin(); i < r.end(); ++i) body(i);
  });
#else
  for(std::size_t i = 0; i < n; ++i) body(i);
#endif
}

template <typename First, typename Second>
void invoke_both(const First& first, const Second& second)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_invoke(first, second);
#else
  first();
  second();
#endif
}


typedef std::array<double, 3> P3;

// The triangles of a polygon with more than three vertices, as index triples
// into it: CGAL's hole filling on the polygon as a closed polyline
// (Polygon_mesh_processing::triangulate_hole_polyline(), the same
// triangulation as PMP's triangulate_faces()), a fan where it finds none.
// CGAL's search falls back on an exhaustive one, cubic in time and quadratic
// in memory, where its Delaunay search fails (a non-planar polygon). So that
// no file can make the program run for hours, a polygon is searched only if
// it has at most `largest_searched_polygon` vertices (a tenth of a second at
// worst) and the cubes of the sizes searched so far stay within
// `search_budget` (some seconds in all); other polygons are fans.
constexpr std::size_t largest_searched_polygon = 256;

template <typename Point>
std::vector<std::array<std::size_t, 3> > triangulate_polygon(const std::vector<Point>& polygon,
                                                            double& search_budget)
{
  std::vector<CGAL::Triple<int, int, int> > triples;
  const double cost = std::pow(static_cast<double>(polygon.size()), 3.);
  if(polygon.size() <= largest_searched_polygon && cost <= search_budget)
  {
    search_budget -= cost;
    CGAL::Polygon_mesh_processing::triangulate_hole_polyline(polygon, std::back_inserter(triples));
  }
  std::vector<std::array<std::size_t, 3> > triangles;
  for(const auto& t : triples)
    triangles.push_back({std::size_t(t.first), std::size_t(t.second), std::size_t(t.third)});
  if(triangles.size() + 2 != polygon.size())  // not a triangulation of the whole polygon
  {
    triangles.clear();
    for(std::size_t i = 1; i + 1 < polygon.size(); ++i) triangles.push_back({0, i, i + 1});
  }
  return triangles;
}

struct Counting_visitor : public CGAL::Polygon_mesh_processing::Default_orientation_visitor
{
  std::size_t* reversed;
  std::size_t* duplicated;
  std::vector<std::pair<std::size_t, std::size_t> >* copies;  // (original point, new point)
  void polygon_orientation_reversed(std::size_t) { ++*reversed; }
  void duplicated_vertex(std::size_t original, std::size_t copy) { ++*duplicated; copies->emplace_back(original, copy); }
};

// Step 6: the vertices that no face uses (points of the file no face
// refers to, points merged into their first copy, originals whose faces all
// went to copies) are left out of the mesh, so that every file written on it
// refers to all its vertices (vcglib's loaders, as QuadWild uses them,
// assume that). The faces keep their order; a file vertex left out maps to
// a copy of it if one is used, else to no vertex.
template <typename Mesh>
void remove_unused_vertices(Repaired_mesh<Mesh>& out)
{
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::size_type size_type;
  const Mesh& mesh = out.mesh;
  std::size_t used = 0;
  for(Vertex_index v : mesh.vertices())
    if(!mesh.is_isolated(v)) ++used;
  if(used == mesh.number_of_vertices()) return;
  Mesh compact;
  compact.reserve(static_cast<size_type>(used), mesh.number_of_edges(), mesh.number_of_faces());
  std::vector<Vertex_index> new_vertex(mesh.number_of_vertices(), Mesh::null_vertex());
  std::vector<std::size_t> file_vertex_of_vertex;
  file_vertex_of_vertex.reserve(used);
  for(Vertex_index v : mesh.vertices())
    if(!mesh.is_isolated(v))
    {
      new_vertex[std::size_t(v)] = compact.add_vertex(mesh.point(v));
      file_vertex_of_vertex.push_back(out.file_vertex_of_vertex[std::size_t(v)]);
    }
  for(auto f : mesh.faces())
  {
    std::array<Vertex_index, 3> corners;
    std::size_t k = 0;
    for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) corners[k++] = new_vertex[std::size_t(v)];
    compact.add_face(corners[0], corners[1], corners[2]);  // a face of a valid mesh: always added
  }
  for(Vertex_index& v : out.vertex_of_file_vertex) v = new_vertex[std::size_t(v)];
  for(std::size_t k = 0; k < file_vertex_of_vertex.size(); ++k)  // a vertex left out: a used copy of it
    if(out.vertex_of_file_vertex[file_vertex_of_vertex[k]] == Mesh::null_vertex())
      out.vertex_of_file_vertex[file_vertex_of_vertex[k]] = Vertex_index(static_cast<size_type>(k));
  out.report.unused_vertices = mesh.number_of_vertices() - used;
  out.file_vertex_of_vertex = std::move(file_vertex_of_vertex);
  out.mesh = std::move(compact);
}

} // namespace read_and_repair_internal


namespace read_and_repair_internal {

// Step 1: the first point with the same coordinates, for every point (a sort,
// ties broken by index, so that the first copy leads each run).
inline std::vector<std::size_t> first_copies(const std::vector<P3>& points, Repair_report& report)
{
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return points[a] < points[b] || (!(points[b] < points[a]) && a < b);
  });
  std::vector<std::size_t> first_copy(points.size());
  for(std::size_t i = 0; i < order.size(); ++i)
  {
    const bool repeated = i > 0 && !(points[order[i - 1]] < points[order[i]]);
    first_copy[order[i]] = repeated ? first_copy[order[i - 1]] : order[i];
    if(repeated) ++report.merged_points;
  }
  return first_copy;
}

// The polygon of the soup on merged points, without repeated consecutive vertices.
inline std::vector<std::size_t> merged_polygon(const Polygon_soup& soup, std::size_t f,
                                               const std::vector<std::size_t>& first_copy)
{
  std::vector<std::size_t> poly;
  for(const std::size_t* v = soup.begin(f); v != soup.end(f); ++v)
  {
    const std::size_t w = first_copy[*v];
    if(poly.empty() || poly.back() != w) poly.push_back(w);
  }
  while(poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
  return poly;
}

typedef std::array<std::size_t, 3> Triangle;

// Steps 2-3: every polygon as triangles (with its polygon), degenerate ones dropped.
inline void triangulate_soup(const Polygon_soup& soup, const std::vector<std::size_t>& first_copy,
                             std::vector<Triangle>& triangles, std::vector<std::size_t>& polygon_of_triangle,
                             Repair_report& report)
{
  triangles.reserve(soup.number_of_polygons());
  polygon_of_triangle.reserve(soup.number_of_polygons());
  double search_budget = 5e8;  // about 30 non-planar polygons of 256 vertices, 4 s
  for(std::size_t f = 0; f < soup.number_of_polygons(); ++f)
  {
    if(soup.size(f) == 3)  // the common case, without a polygon of its own
    {
      const std::size_t* c = soup.begin(f);
      const Triangle tri = {first_copy[c[0]], first_copy[c[1]], first_copy[c[2]]};
      if(tri[0] != tri[1] && tri[1] != tri[2] && tri[2] != tri[0])
      {
        triangles.push_back(tri);
        polygon_of_triangle.push_back(f);
        continue;
      }
    }
    const std::vector<std::size_t> poly = merged_polygon(soup, f, first_copy);
    if(poly.size() < 3) { ++report.degenerate_polygons; continue; }
    std::vector<Triangle> local(1, Triangle{0, 1, 2});
    if(poly.size() > 3)
    {
      std::vector<CGAL::Simple_cartesian<double>::Point_3> corners;
      for(std::size_t v : poly) corners.emplace_back(soup.points[v][0], soup.points[v][1], soup.points[v][2]);
      local = triangulate_polygon(corners, search_budget);
      ++report.triangulated_polygons;
      report.triangles_from_polygons += local.size();
    }
    for(const Triangle& t : local)
    {
      const Triangle tri = {poly[t[0]], poly[t[1]], poly[t[2]]};
      if(tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) { ++report.degenerate_polygons; continue; }
      triangles.push_back(tri);
      polygon_of_triangle.push_back(f);
    }
  }
}

// Items grouped by a vertex (a counting sort, linear in their number): the
// items of vertex v are item[first[v]] ... item[first[v + 1] - 1], in the
// order they were given.
template <typename Item>
struct Vertex_buckets
{
  std::vector<std::size_t> first;
  std::vector<Item> item;

  template <typename ForEach>  // for_each(add) calls add(vertex, item) for every item, twice in the same order
  Vertex_buckets(std::size_t vertices, const ForEach& for_each)
    : first(vertices + 2, 0)
  {
    for_each([&](std::size_t v, const Item&) { ++first[v + 2]; });
    for(std::size_t v = 2; v < first.size(); ++v) first[v] += first[v - 1];
    item.resize(first.back());
    for_each([&](std::size_t v, const Item& i) { item[first[v + 1]++] = i; });
    first.pop_back();
  }
  // Calls f(begin, end) on the items of each vertex, sorted.
  template <typename F>
  void for_each_sorted(const F& f)
  {
    for(std::size_t v = 0; v + 1 < first.size(); ++v)
    {
      const auto begin = item.begin() + static_cast<std::ptrdiff_t>(first[v]);
      const auto end = item.begin() + static_cast<std::ptrdiff_t>(first[v + 1]);
      std::sort(begin, end);
      f(begin, end);
    }
  }
};

// Step 4: the triangles with the same three vertices as an earlier one,
// dropped (grouped by their smallest vertex).
inline void remove_repeated_triangles(std::size_t points, std::vector<Triangle>& triangles,
                                      std::vector<std::size_t>& polygon_of_triangle, Repair_report& report)
{
  typedef std::pair<std::pair<std::size_t, std::size_t>, std::size_t> Key;  // the other two vertices, the triangle
  Vertex_buckets<Key> buckets(points, [&](const auto& add) {
    for(std::size_t t = 0; t < triangles.size(); ++t)
    {
      Triangle k = triangles[t];
      std::sort(k.begin(), k.end());
      add(k[0], Key({k[1], k[2]}, t));
    }
  });
  std::vector<char> repeated(triangles.size(), 0);
  buckets.for_each_sorted([&](auto begin, auto end) {
    for(auto it = begin; it != end && it + 1 != end; ++it)
      if((it + 1)->first == it->first) repeated[(it + 1)->second] = 1;
  });
  std::size_t kept = 0;
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    if(repeated[t]) { ++report.repeated_triangles; continue; }
    triangles[kept] = triangles[t];
    polygon_of_triangle[kept++] = polygon_of_triangle[t];
  }
  triangles.resize(kept);
  polygon_of_triangle.resize(kept);
}

// The mesh with vertex i = point i; the triangles it could not add are counted.
template <typename Mesh>
std::vector<std::size_t> add_triangles(const std::vector<P3>& points, const std::vector<Triangle>& triangles,
                                       Mesh& mesh, std::size_t& skipped)
{
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::size_type size_type;
  std::vector<std::size_t> added;  // the triangles that are faces, in order
  mesh.reserve(static_cast<size_type>(points.size()), static_cast<size_type>(3 * triangles.size() / 2 + 3),
               static_cast<size_type>(triangles.size()));
  for(const P3& p : points) mesh.add_vertex(typename Mesh::Point(p[0], p[1], p[2]));
  added.reserve(triangles.size());
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const Triangle& tri = triangles[t];
    if(mesh.add_face(Vertex_index(static_cast<size_type>(tri[0])), Vertex_index(static_cast<size_type>(tri[1])),
                     Vertex_index(static_cast<size_type>(tri[2]))) == Mesh::null_face())
      ++skipped;
    else
      added.push_back(t);
  }
  return added;
}

// 32-bit indices of directed edges, as Surface_mesh's: half the memory
// traffic of std::size_t; `no_edge`: none.
typedef std::uint32_t Edge_number;
constexpr Edge_number no_edge = std::numeric_limits<Edge_number>::max();

// The directed edges of the triangles (edge 3t+k goes from corner k of
// triangle t to corner k+1) listed by their source vertex, each vertex's
// sorted by target; the opposite of each (the same two vertices the other
// way; no_edge on the border) and the border edge leaving each vertex.
// `Triangles` is a range of triangles whose t[k] are vertex numbers (a
// std::vector<Triangle>, or the rows of a numpy array).
template <typename Triangles>
struct Directed_edges
{
  typedef std::pair<Edge_number, Edge_number> Target_and_edge;
  const Triangles& triangles;
  std::vector<Edge_number> first_leaving;  // the edges leaving v: leaving[first_leaving[v] .. first_leaving[v+1])
  std::vector<Target_and_edge> leaving;
  std::vector<Edge_number> opposite;
  std::vector<Edge_number> border_leaving;  // per vertex

  std::size_t source(std::size_t e) const { return triangles[e / 3][e % 3]; }
  std::size_t target(std::size_t e) const { return triangles[e / 3][(e + 1) % 3]; }
  static Edge_number previous(Edge_number e) { return e - e % 3 + (e + 2) % 3; }
  std::size_t number_of_vertices() const { return border_leaving.size(); }
  auto begin(std::size_t v) const { return leaving.begin() + static_cast<std::ptrdiff_t>(first_leaving[v]); }
  auto end(std::size_t v) const { return leaving.begin() + static_cast<std::ptrdiff_t>(first_leaving[v + 1]); }

  Directed_edges(std::size_t points, const Triangles& t)
    : triangles(t), first_leaving(points + 2, 0), leaving(3 * t.size()), opposite(3 * t.size(), no_edge),
      border_leaving(points, no_edge)
  {
    for(std::size_t e = 0; e < leaving.size(); ++e) ++first_leaving[source(e) + 2];
    for(std::size_t v = 2; v < first_leaving.size(); ++v) first_leaving[v] += first_leaving[v - 1];
    for(std::size_t e = 0; e < leaving.size(); ++e)
      leaving[first_leaving[source(e) + 1]++] = {static_cast<Edge_number>(target(e)), static_cast<Edge_number>(e)};
    first_leaving.pop_back();
    for_each_index(
      points, [&](std::size_t v) { std::sort(leaving.begin() + static_cast<std::ptrdiff_t>(first_leaving[v]),
                                             leaving.begin() + static_cast<std::ptrdiff_t>(first_leaving[v + 1])); });
  }

  // Finds every edge's opposite and each vertex's border edge; false if a
  // directed edge is repeated (an edge of two triangles with the same
  // direction, or of more than two) or two border edges leave one vertex.
  bool pair_up()
  {
    std::atomic<bool> refused{false};
    for_each_index(number_of_vertices(), [&](std::size_t u) {
      for(auto it = begin(u); it != end(u); ++it)
      {
        if(it + 1 != end(u) && (it + 1)->first == it->first) refused = true;
        const auto found = std::lower_bound(begin(it->first), end(it->first),
                                            Target_and_edge(static_cast<Edge_number>(u), 0));
        if(found != end(it->first) && found->first == u)
          opposite[it->second] = found->second;
        else if(border_leaving[u] == no_edge)
          border_leaving[u] = it->second;
        else
          refused = true;
      }
    });
    return !refused;
  }

  // Whether the triangles around each vertex form one fan: turning from the
  // border edge (or any edge) leaving it, e to opposite(previous(e)), meets
  // every edge leaving it.
  bool one_fan_per_vertex() const
  {
    std::atomic<bool> one_fan{true};
    for_each_index(number_of_vertices(), [&](std::size_t v) {
      if(begin(v) == end(v)) return;
      const std::size_t corners = static_cast<std::size_t>(end(v) - begin(v));
      const Edge_number start = border_leaving[v] != no_edge ? border_leaving[v] : begin(v)->second;
      std::size_t met = 0;
      for(Edge_number e = start; e != no_edge && met <= corners; e = opposite[previous(e)])
      {
        ++met;
        if(opposite[previous(e)] == start) break;
      }
      if(met != corners) one_fan = false;
    });
    return one_fan;
  }

  // The first halfedge into v in the order of the faces (no_edge: v is isolated).
  Edge_number first_into(std::size_t v) const
  {
    Edge_number first = no_edge;
    for(auto it = begin(v); it != end(v); ++it) first = (std::min)(first, it->second);
    return first == no_edge ? no_edge : previous(first);
  }
};

// The mesh of triangles that form an oriented manifold, built halfedge by
// halfedge in time linear in the number of triangles, with the independent
// steps in parallel: CGAL's add_face() searches the halfedges around a vertex
// for each face added to it, quadratic in its valence (a fan of valence
// 100,000 took 10 s). Vertex i = point i, face t = triangle t, edges in the
// order of their first directed edge; each face's halfedge points into its
// first corner and each vertex's is its border halfedge, or else the first
// halfedge into it in face order (as CGAL's add_face() would leave them).
// Returns false, leaving the mesh empty, if a vertex is not manifold (its
// triangles form more than one fan: then CGAL's orientation duplicates it),
// if an edge has more than two triangles or two with the same direction, or
// if a triangle repeats a vertex. `Points` and `Triangles` are ranges whose
// elements p[0..2] are coordinates and t[0..2] vertex numbers (std::vectors of
// P3 and Triangle, or views of numpy arrays).
template <typename Mesh, typename Points, typename Triangles>
bool build_oriented_manifold(const Points& points, const Triangles& triangles, Mesh& mesh)
{
  typedef typename Mesh::Halfedge_index Halfedge_index;
  typedef typename Mesh::size_type size_type;
  if(points.size() >= no_edge || triangles.size() >= no_edge / 3)
    throw Mesh_input_error("the mesh is too large for 32-bit indices");
  for(std::size_t t = 0; t < triangles.size(); ++t)
    if(triangles[t][0] == triangles[t][1] || triangles[t][1] == triangles[t][2] || triangles[t][2] == triangles[t][0])
      return false;
  // the vertices and faces are allocated while the edges are paired and checked
  std::unique_ptr<Directed_edges<Triangles> > edges;
  bool manifold = false;
  invoke_both(
    [&] {
      edges = std::make_unique<Directed_edges<Triangles> >(points.size(), triangles);
      manifold = edges->pair_up() && edges->one_fan_per_vertex();
    },
    [&] {
      mesh.reserve(static_cast<size_type>(points.size()), static_cast<size_type>(3 * triangles.size() / 2 + 3),
                   static_cast<size_type>(triangles.size()));
      for(std::size_t i = 0; i < points.size(); ++i)
        mesh.add_vertex(typename Mesh::Point(points[i][0], points[i][1], points[i][2]));
      for(std::size_t t = 0; t < triangles.size(); ++t) mesh.add_face();
    });
  if(!manifold)
  {
    mesh.clear();
    return false;
  }
  // the halfedge of each directed edge: the first of a pair opens an edge
  std::vector<Halfedge_index> halfedge_of(edges->leaving.size());
  size_type next_edge = 0;
  for(std::size_t e = 0; e < halfedge_of.size(); ++e)
  {
    const std::size_t o = edges->opposite[e];
    if(o == no_edge || e < o) halfedge_of[e] = Halfedge_index(2 * next_edge++);
    else halfedge_of[e] = Halfedge_index(static_cast<size_type>(halfedge_of[o]) + 1);
  }
  for(size_type i = 0; i < next_edge; ++i) mesh.add_edge();
  link_halfedges(*edges, halfedge_of, mesh);
  return true;
}

// Targets, next and faces of the triangles' halfedges and of the border's;
// the halfedges of faces and vertices.
template <typename Mesh, typename Triangles>
void link_halfedges(const Directed_edges<Triangles>& edges, const std::vector<typename Mesh::Halfedge_index>& halfedge_of,
                    Mesh& mesh)
{
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Face_index Face_index;
  typedef typename Mesh::size_type size_type;
  auto vertex = [](std::size_t v) { return Vertex_index(static_cast<size_type>(v)); };
  auto border_of = [&](std::size_t e) { return mesh.opposite(halfedge_of[e]); };  // e without opposite
  for_each_index(edges.triangles.size(), [&](std::size_t t) {
    const Face_index f(static_cast<size_type>(t));
    for(std::size_t k = 0; k < 3; ++k)
    {
      const std::size_t e = 3 * t + k;
      mesh.set_target(halfedge_of[e], vertex(edges.target(e)));
      mesh.set_next(halfedge_of[e], halfedge_of[3 * t + (k + 1) % 3]);
      mesh.set_face(halfedge_of[e], f);
      if(edges.opposite[e] == no_edge) mesh.set_target(border_of(e), vertex(edges.source(e)));
    }
    mesh.set_halfedge(f, halfedge_of[3 * t + 2]);
  });
  // the border halfedge of the edge e leaving u goes into u; the one before
  // it is that of the border edge leaving target(e). Each vertex has one.
  for_each_index(edges.number_of_vertices(), [&](std::size_t u) {
    const Edge_number e = edges.border_leaving[u];
    if(e != no_edge)
    {
      mesh.set_next(border_of(edges.border_leaving[edges.target(e)]), border_of(e));
      mesh.set_halfedge(vertex(u), border_of(e));
    }
    else if(edges.first_into(u) != no_edge)
      mesh.set_halfedge(vertex(u), halfedge_of[edges.first_into(u)]);
  });
}

// Step 5 when needed: orientation and non-manifold vertices by CGAL (new
// points are appended); the copies made, as (original point, new point).
inline std::vector<std::pair<std::size_t, std::size_t> > orient(std::vector<P3>& points, std::vector<Triangle>& triangles,
                                                                 Repair_report& report)
{
  typedef CGAL::Simple_cartesian<double>::Point_3 Point_3;
  std::vector<Point_3> cgal_points;
  cgal_points.reserve(points.size());
  for(const P3& p : points) cgal_points.emplace_back(p[0], p[1], p[2]);
  std::vector<std::vector<std::size_t> > polygons;
  polygons.reserve(triangles.size());
  for(const Triangle& t : triangles) polygons.push_back({t[0], t[1], t[2]});
  Counting_visitor visitor;
  visitor.reversed = &report.reoriented_triangles;
  visitor.duplicated = &report.duplicated_vertices;
  std::vector<std::pair<std::size_t, std::size_t> > copies;
  visitor.copies = &copies;
  CGAL::Polygon_mesh_processing::orient_polygon_soup(cgal_points, polygons, CGAL::parameters::visitor(visitor));
  for(std::size_t i = points.size(); i < cgal_points.size(); ++i)
    points.push_back({cgal_points[i].x(), cgal_points[i].y(), cgal_points[i].z()});
  for(std::size_t t = 0; t < triangles.size(); ++t) triangles[t] = {polygons[t][0], polygons[t][1], polygons[t][2]};
  return copies;
}

} // namespace read_and_repair_internal

// The soup as a mesh, repaired as the steps above say. Throws Mesh_input_error
// when no usable face is left, naming the soup as `source` does (a quoted file
// name, or the arrays it came from).
template <typename Mesh>
Repaired_mesh<Mesh> repair_into_mesh(Polygon_soup& soup, const std::string& source)
{
  typedef typename Mesh::Vertex_index Vertex_index;
  namespace repair = read_and_repair_internal;
  Repaired_mesh<Mesh> out;
  out.file_vertices = soup.points.size();
  out.file_faces = soup.number_of_polygons();
  const std::vector<std::size_t> first_copy = repair::first_copies(soup.points, out.report);
  std::vector<repair::Triangle> triangles;
  std::vector<std::size_t> polygon_of_triangle;
  repair::triangulate_soup(soup, first_copy, triangles, polygon_of_triangle, out.report);
  repair::remove_repeated_triangles(soup.points.size(), triangles, polygon_of_triangle, out.report);
  if(triangles.empty()) throw Mesh_input_error(source + " holds no usable face");

  std::vector<std::pair<std::size_t, std::size_t> > copies;
  std::size_t skipped = 0;
  std::vector<std::size_t> added;
  if(repair::build_oriented_manifold(soup.points, triangles, out.mesh))
  {
    added.resize(triangles.size());
    std::iota(added.begin(), added.end(), std::size_t(0));
  }
  if(out.mesh.number_of_faces() == 0)
  {
    copies = repair::orient(soup.points, triangles, out.report);
    added = repair::add_triangles(soup.points, triangles, out.mesh, skipped);
  }
  out.report.skipped_triangles = skipped;
  if(out.mesh.number_of_faces() == 0) throw Mesh_input_error(source + " holds no usable face");
  for(std::size_t t : added) out.file_face_of_face.push_back(polygon_of_triangle[t]);
  out.file_vertex_of_vertex.resize(soup.points.size());
  std::iota(out.file_vertex_of_vertex.begin(), out.file_vertex_of_vertex.end(), std::size_t(0));
  for(const auto& oc : copies)  // a copy represents what its original represents
    if(oc.second < soup.points.size()) out.file_vertex_of_vertex[oc.second] = out.file_vertex_of_vertex[oc.first];
  out.vertex_of_file_vertex.resize(out.file_vertices);
  for(std::size_t i = 0; i < out.file_vertices; ++i)
    out.vertex_of_file_vertex[i] = Vertex_index(static_cast<typename Mesh::size_type>(first_copy[i]));
  repair::remove_unused_vertices(out);
  return out;
}

// Throws Mesh_input_error with a one-line message when the file cannot be used.
template <typename Mesh>
Repaired_mesh<Mesh> read_and_repair_mesh(const std::string& path)
{
  Polygon_soup soup = read_polygon_soup(path);
  if(soup.number_of_polygons() == 0) throw Mesh_input_error("'" + path + "' holds no face");
  return repair_into_mesh<Mesh>(soup, "'" + path + "'");
}

#endif
