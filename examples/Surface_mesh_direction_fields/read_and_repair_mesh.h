// Reading a mesh file as the command-line program does: as a polygon soup,
// repaired into a triangle mesh whose vertices and faces keep track of the
// file's, so that the outputs can be written in the file's order.
//
// Repairs, each counted in a Repair_report:
//  1. points with identical coordinates are merged (the first one is kept);
//  2. repeated consecutive vertices are removed from each polygon, and polygons
//     left with fewer than 3 vertices are dropped;
//  3. polygons with more than 3 vertices are triangulated (ear clipping in the
//     plane of their Newell normal; a fan if that fails);
//  4. repeated triangles (same three vertices) are dropped;
//  5. the triangles are oriented consistently, and non-manifold vertices are
//     duplicated, by CGAL::Polygon_mesh_processing::orient_polygon_soup();
//  6. a triangle that still cannot be added to the mesh is skipped.
// A vertex of the file is represented by the mesh vertex of its first copy.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_EXAMPLES_READ_AND_REPAIR_MESH_H
#define SURFACE_MESH_DIRECTION_FIELDS_EXAMPLES_READ_AND_REPAIR_MESH_H

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
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

// Ear clipping of a simple polygon given by 3D points; returns index triples
// into `poly`, or an empty vector if the polygon is not simple enough.
inline std::vector<std::array<std::size_t, 3> > ear_clip(const std::vector<P3>& pts)
{
  const std::size_t k = pts.size();
  P3 n = {0, 0, 0};  // Newell normal
  for(std::size_t i = 0; i < k; ++i)
  {
    const P3& a = pts[i];
    const P3& b = pts[(i + 1) % k];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  int drop = 0;
  for(int c = 1; c < 3; ++c) if(std::abs(n[c]) > std::abs(n[drop])) drop = c;
  if(n[drop] == 0.) return {};
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const double sign = n[drop] > 0 ? 1. : -1.;  // keep the polygon counter-clockwise in (u, v)
  std::vector<std::array<double, 2> > q(k);
  for(std::size_t i = 0; i < k; ++i) q[i] = {pts[i][u], sign * pts[i][v]};
  auto cross = [&](std::size_t a, std::size_t b, std::size_t c) {
    return (q[b][0] - q[a][0]) * (q[c][1] - q[a][1]) - (q[b][1] - q[a][1]) * (q[c][0] - q[a][0]);
  };
  std::vector<std::size_t> idx(k);
  for(std::size_t i = 0; i < k; ++i) idx[i] = i;
  std::vector<std::array<std::size_t, 3> > tris;
  std::size_t guard = 0;
  while(idx.size() > 3 && guard++ < 4 * k * k)
  {
    bool clipped = false;
    for(std::size_t i = 0; i < idx.size() && !clipped; ++i)
    {
      const std::size_t a = idx[(i + idx.size() - 1) % idx.size()], b = idx[i], c = idx[(i + 1) % idx.size()];
      if(cross(a, b, c) <= 0.) continue;  // reflex or flat corner
      bool empty = true;
      for(std::size_t j : idx)
        if(j != a && j != b && j != c && cross(a, b, j) >= 0. && cross(b, c, j) >= 0. && cross(c, a, j) >= 0.)
        { empty = false; break; }
      if(!empty) continue;
      tris.push_back({a, b, c});
      idx.erase(idx.begin() + static_cast<long>(i));
      clipped = true;
    }
    if(!clipped) return {};
  }
  if(idx.size() == 3) tris.push_back({idx[0], idx[1], idx[2]});
  return tris;
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

// Throws Mesh_input_error with a one-line message when the file cannot be used.
template <typename Mesh>
Repaired_mesh<Mesh> read_and_repair_mesh(const std::string& path)
{
  typedef typename Mesh::Point Point;
  typedef typename Mesh::Vertex_index Vertex_index;
  typedef typename Mesh::Face_index Face_index;
  using read_and_repair_internal::P3;
  {
    std::ifstream probe(path);
    if(!probe) throw Mesh_input_error("cannot open '" + path + "'");
  }
  std::string extension = path.substr(path.find_last_of('.') + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if(path.find('.') != std::string::npos && extension == "off")
    read_and_repair_internal::check_off_face_sizes(path);
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  if(!CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false)))
    throw Mesh_input_error("cannot read '" + path + "' as a mesh (OFF, OBJ, PLY or STL)");
  Repaired_mesh<Mesh> out;
  out.file_vertices = points.size();
  out.file_faces = polygons.size();
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

  // 1. merge identical points
  std::vector<std::size_t> first_copy(points.size());
  {
    std::map<std::array<double, 3>, std::size_t> seen;
    for(std::size_t i = 0; i < points.size(); ++i)
    {
      const P3 key = {CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()), CGAL::to_double(points[i].z())};
      auto it = seen.emplace(key, i).first;
      first_copy[i] = it->second;
      if(it->second != i) ++out.report.merged_points;
    }
  }
  // 2-4. clean, triangulate, deduplicate
  std::vector<std::vector<std::size_t> > triangles;
  std::vector<std::size_t> polygon_of_triangle;
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
    if(poly.size() < 3) { ++out.report.degenerate_polygons; continue; }
    std::vector<std::array<std::size_t, 3> > local;
    if(poly.size() == 3) local.push_back({0, 1, 2});
    else
    {
      std::vector<P3> pts;
      for(std::size_t v : poly)
        pts.push_back({CGAL::to_double(points[v].x()), CGAL::to_double(points[v].y()), CGAL::to_double(points[v].z())});
      local = read_and_repair_internal::ear_clip(pts);
      if(local.empty())
        for(std::size_t i = 1; i + 1 < poly.size(); ++i) local.push_back({0, i, i + 1});
      ++out.report.triangulated_polygons;
      out.report.triangles_from_polygons += local.size();
    }
    for(const auto& t : local)
    {
      std::array<std::size_t, 3> tri = {poly[t[0]], poly[t[1]], poly[t[2]]};
      if(tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0]) { ++out.report.degenerate_polygons; continue; }
      std::array<std::size_t, 3> key = tri;
      std::sort(key.begin(), key.end());
      if(!triangle_set.insert(key).second) { ++out.report.repeated_triangles; continue; }
      triangles.push_back({tri[0], tri[1], tri[2]});
      polygon_of_triangle.push_back(f);
    }
  }
  if(triangles.empty()) throw Mesh_input_error("'" + path + "' holds no usable face");

  // 5. orientation and non-manifold vertices (new points are appended)
  read_and_repair_internal::Counting_visitor visitor;
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
