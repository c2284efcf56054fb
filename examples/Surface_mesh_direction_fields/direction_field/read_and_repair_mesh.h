// Reading a mesh file as the command-line program does: as a polygon soup,
// repaired into a triangle mesh whose vertices and faces keep track of the
// file's, so that the outputs can be written in the file's order.
//
// Repairs, each counted in a Repair_report:
//  1. points with identical coordinates are merged (the first one is kept);
//  2. repeated consecutive vertices are removed from each polygon, and polygons
//     left with fewer than 3 vertices are dropped;
//  3. polygons with more than 3 vertices are triangulated by CGAL's
//     Polygon_mesh_processing (a fan if that fails);
//  4. repeated triangles (same three vertices) are dropped;
//  5. the triangles are oriented consistently, and non-manifold vertices are
//     duplicated, by CGAL::Polygon_mesh_processing::orient_polygon_soup();
//  6. a triangle that still cannot be added to the mesh is skipped.
// A vertex of the file is represented by the mesh vertex of its first copy.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_EXAMPLES_READ_AND_REPAIR_MESH_H
#define SURFACE_MESH_DIRECTION_FIELDS_EXAMPLES_READ_AND_REPAIR_MESH_H

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

struct Mesh_input_error : std::runtime_error { using std::runtime_error::runtime_error; };

struct Repair_report
{
  std::size_t merged_points = 0;
  std::size_t degenerate_polygons = 0;
  std::size_t triangulated_polygons = 0, triangles_from_polygons = 0;
  std::size_t repeated_triangles = 0;
  std::size_t reoriented_triangles = 0;
  std::size_t duplicated_vertices = 0;
  std::size_t skipped_triangles = 0;

  bool any() const
  {
    return merged_points + degenerate_polygons + triangulated_polygons + repeated_triangles + reoriented_triangles +
           duplicated_vertices + skipped_triangles > 0;
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
    return os.str();
  }
};

template <typename Mesh>
struct Repaired_mesh
{
  typedef typename Mesh::Vertex_index Vertex_index;
  Mesh mesh;
  std::size_t file_vertices = 0, file_faces = 0;
  std::vector<Vertex_index> vertex_of_file_vertex;  // file vertex -> mesh vertex (first copy)
  std::vector<std::size_t> file_face_of_face;       // mesh face -> polygon of the file
  std::vector<std::size_t> file_vertex_of_vertex;   // mesh vertex -> the file vertex it copies
  Repair_report report;
};

namespace read_and_repair_internal {

typedef std::array<double, 3> P3;

// The triangles of a polygon with more than three vertices, as index triples
// into it: CGAL's hole filling on the polygon as a closed polyline
// (Polygon_mesh_processing::triangulate_hole_polyline(), the same
// triangulation as PMP's triangulate_faces()), a fan where it finds none.
template <typename Point>
std::vector<std::array<std::size_t, 3> > triangulate_polygon(const std::vector<Point>& polygon)
{
  std::vector<CGAL::Triple<int, int, int> > triples;
  CGAL::Polygon_mesh_processing::triangulate_hole_polyline(polygon, std::back_inserter(triples));
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

// A pre-scan of ASCII OFF files: CGAL's reader trusts the vertex count of
// each face line, so a corrupted count (say 999999999) makes it allocate
// gigabytes before failing. Reject such a line first; everything else is left
// to CGAL's reader.
inline void check_off_face_sizes(const std::string& path)
{
  std::ifstream in(path);
  std::string line;
  auto next_data_line = [&](std::istringstream& fields) {
    while(std::getline(in, line))
    {
      const std::size_t hash = line.find('#');
      if(hash != std::string::npos) line.erase(hash);
      if(line.find_first_not_of(" \t\r") == std::string::npos) continue;
      fields.clear();
      fields.str(line);
      return true;
    }
    return false;
  };
  std::istringstream fields;
  if(!next_data_line(fields)) return;
  std::string keyword;
  fields >> keyword;
  if(keyword.find("OFF") == std::string::npos || line.find("BINARY") != std::string::npos) return;
  long long nv = -1, nf = -1;
  if(!(fields >> nv >> nf))  // counts on the next line
  {
    if(!next_data_line(fields) || !(fields >> nv >> nf)) return;
  }
  if(nv < 0 || nf < 0) return;
  for(long long i = 0; i < nv; ++i)
    if(!next_data_line(fields)) return;
  for(long long f = 0; f < nf; ++f)
  {
    if(!next_data_line(fields)) return;
    long long k = 0;
    if((fields >> k) && (k < 0 || k > (std::max)(nv, 3LL)))
      throw Mesh_input_error("face " + std::to_string(f) + " claims " + std::to_string(k) + " vertices, the file has " +
                             std::to_string(nv));
  }
}

} // namespace read_and_repair_internal

namespace read_and_repair_internal {

// The file as a polygon soup, checked: finite coordinates, valid indices, a face.
template <typename Point>
void read_soup(const std::string& path, std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons)
{
  {
    std::ifstream probe(path);
    if(!probe) throw Mesh_input_error("cannot open '" + path + "'");
  }
  std::string extension = path.substr(path.find_last_of('.') + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if(path.find('.') != std::string::npos && extension == "off")
    check_off_face_sizes(path);
  if(!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)))
    throw Mesh_input_error("cannot read '" + path + "' as a mesh (OFF, OBJ, PLY or STL)");
  if(polygons.empty()) throw Mesh_input_error("'" + path + "' holds no face");
  for(std::size_t i = 0; i < points.size(); ++i)
    if(!std::isfinite(CGAL::to_double(points[i].x())) || !std::isfinite(CGAL::to_double(points[i].y())) ||
       !std::isfinite(CGAL::to_double(points[i].z())))
      throw Mesh_input_error("vertex " + std::to_string(i) + " has a non-finite coordinate");
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t v : polygons[f])
      if(v >= points.size())
        throw Mesh_input_error("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                               ", which does not exist");
}

// Step 1: the first point with the same coordinates, for every point.
template <typename Point>
std::vector<std::size_t> first_copies(const std::vector<Point>& points, Repair_report& report)
{
  std::vector<std::size_t> first_copy(points.size());
  std::map<std::array<double, 3>, std::size_t> seen;
  for(std::size_t i = 0; i < points.size(); ++i)
  {
    const P3 key = {CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()), CGAL::to_double(points[i].z())};
    auto it = seen.emplace(key, i).first;
    first_copy[i] = it->second;
    if(it->second != i) ++report.merged_points;
  }
  return first_copy;
}

// Steps 2-4: each polygon without repeated vertices, triangulated, without
// repeated triangles; the polygon of each triangle.
template <typename Point>
void clean_and_triangulate(const std::vector<Point>& points, const std::vector<std::vector<std::size_t> >& polygons,
                           const std::vector<std::size_t>& first_copy, std::vector<std::vector<std::size_t> >& triangles,
                           std::vector<std::size_t>& polygon_of_triangle, Repair_report& report)
{
  std::set<std::array<std::size_t, 3> > triangle_set;
  for(std::size_t f = 0; f < polygons.size(); ++f)
  {
    std::vector<std::size_t> poly;
    for(std::size_t v : polygons[f])
    {
      const std::size_t w = first_copy[v];
      if(poly.empty() || poly.back() != w) poly.push_back(w);
    }
    while(poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
    if(poly.size() < 3) { ++report.degenerate_polygons; continue; }
    std::vector<std::array<std::size_t, 3> > local;
    if(poly.size() == 3) local.push_back({0, 1, 2});
    else
    {
      std::vector<Point> corners;
      for(std::size_t v : poly) corners.push_back(points[v]);
      local = triangulate_polygon(corners);
      ++report.triangulated_polygons;
      report.triangles_from_polygons += local.size();
    }
    for(const auto& t : local)
    {
      std::array<std::size_t, 3> tri = {poly[t[0]], poly[t[1]], poly[t[2]]};
      if(tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) { ++report.degenerate_polygons; continue; }
      std::array<std::size_t, 3> key = tri;
      std::sort(key.begin(), key.end());
      if(!triangle_set.insert(key).second) { ++report.repeated_triangles; continue; }
      triangles.push_back({tri[0], tri[1], tri[2]});
      polygon_of_triangle.push_back(f);
    }
  }
}

} // namespace read_and_repair_internal

// Throws Mesh_input_error with a one-line message when the file cannot be used.
template <typename Mesh>
Repaired_mesh<Mesh> read_and_repair_mesh(const std::string& path)
{
  typedef typename Mesh::Point Point;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Face_index Face_index;
  namespace repair = read_and_repair_internal;
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  repair::read_soup(path, points, polygons);
  Repaired_mesh<Mesh> out;
  out.file_vertices = points.size();
  out.file_faces = polygons.size();
  const std::vector<std::size_t> first_copy = repair::first_copies(points, out.report);
  std::vector<std::vector<std::size_t> > triangles;
  std::vector<std::size_t> polygon_of_triangle;
  repair::clean_and_triangulate(points, polygons, first_copy, triangles, polygon_of_triangle, out.report);
  if(triangles.empty()) throw Mesh_input_error("'" + path + "' holds no usable face");

  // 5. orientation and non-manifold vertices (new points are appended)
  repair::Counting_visitor visitor;
  visitor.reversed = &out.report.reoriented_triangles;
  visitor.duplicated = &out.report.duplicated_vertices;
  std::vector<std::pair<std::size_t, std::size_t> > copies;
  visitor.copies = &copies;
  CGAL::Polygon_mesh_processing::orient_polygon_soup(points, triangles, CGAL::parameters::visitor(visitor));

  // 6. the mesh, vertex i being point i
  for(const Point& p : points) out.mesh.add_vertex(p);
  for(std::size_t t = 0; t < triangles.size(); ++t)
  {
    const auto& tri = triangles[t];
    const Face_index f = out.mesh.add_face(Vertex_index(static_cast<typename Mesh::size_type>(tri[0])),
                                           Vertex_index(static_cast<typename Mesh::size_type>(tri[1])),
                                           Vertex_index(static_cast<typename Mesh::size_type>(tri[2])));
    if(f == Mesh::null_face()) { ++out.report.skipped_triangles; continue; }
    out.file_face_of_face.push_back(polygon_of_triangle[t]);
  }
  if(out.mesh.number_of_faces() == 0) throw Mesh_input_error("'" + path + "' holds no usable face");
  out.file_vertex_of_vertex.resize(points.size());
  for(std::size_t i = 0; i < points.size(); ++i) out.file_vertex_of_vertex[i] = i;  // copies are fixed below
  for(const auto& oc : copies)
    if(oc.second < points.size()) out.file_vertex_of_vertex[oc.second] = out.file_vertex_of_vertex[oc.first];
  out.vertex_of_file_vertex.resize(out.file_vertices);
  for(std::size_t i = 0; i < out.file_vertices; ++i)
    out.vertex_of_file_vertex[i] = Vertex_index(static_cast<typename Mesh::size_type>(first_copy[i]));
  return out;
}

#endif
