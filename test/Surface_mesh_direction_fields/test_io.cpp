// The exchange formats (IO/direction_field_files.h): every writer's output is
// read back and compared with what was written, a Surface_mesh reads the PLY
// file with CGAL's own reader, and the vertex-to-face transfer rule is checked
// against its defining properties.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/IO/direction_field_files.h>
#include <CGAL/Surface_mesh_direction_fields/streamlines.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cgal_compatibility.h>

#include "test_types.h"
#include "generated_meshes.h"
#include "test_support.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;
namespace SIO = CGAL::Surface_mesh_direction_fields::IO;
typedef std::array<double, 3> V3;

static double distance(const V3& a, const V3& b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

// The largest difference between two lists of 3-vectors (infinity if the sizes differ).
static double max_difference(const std::vector<V3>& a, const std::vector<V3>& b)
{
  if(a.size() != b.size()) return HUGE_VAL;
  double worst = 0.;
  for(std::size_t i = 0; i < a.size(); ++i) worst = (std::max)(worst, distance(a[i], b[i]));
  return worst;
}

static double max_direction_difference(const SIO::Direction_field_data& a, const SIO::Direction_field_data& b)
{
  if(a.directions.size() != b.directions.size()) return HUGE_VAL;
  double worst = 0.;
  for(std::size_t v = 0; v < a.directions.size(); ++v) worst = (std::max)(worst, max_difference(a.directions[v], b.directions[v]));
  return worst;
}

// The angle between two n-directions in the plane with normal `normal`, modulo 2 pi / n.
static double angle_mod(const V3& a, const V3& b, const V3& normal, int n)
{
  const V3 c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double angle = std::atan2(c[0] * normal[0] + c[1] * normal[1] + c[2] * normal[2],
                                  a[0] * b[0] + a[1] * b[1] + a[2] * b[2]);
  const double period = 2. * CGAL_PI / n;
  const double r = std::remainder(angle, period);
  return std::abs(r);
}

static V3 face_normal(const SIO::Direction_field_data& d, std::size_t f)
{
  const auto& t = d.faces[f];
  const V3 a{d.points[t[1]][0] - d.points[t[0]][0], d.points[t[1]][1] - d.points[t[0]][1], d.points[t[1]][2] - d.points[t[0]][2]};
  const V3 b{d.points[t[2]][0] - d.points[t[0]][0], d.points[t[2]][1] - d.points[t[0]][1], d.points[t[2]][2] - d.points[t[0]][2]};
  V3 c{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double l = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  for(double& x : c) x /= l;
  return c;
}

static void check_round_trips(Test_report& report, const std::string& name, const Mesh& mesh, int degree)
{
  std::vector<Vector_3> storage(mesh.number_of_vertices());
  auto dir = CGAL::make_property_map(storage);
  std::vector<double> magnitude(mesh.number_of_vertices());
  std::vector<std::pair<Face_index, int> > singular;
  const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
    mesh, dir, CGAL::parameters::degree(degree).vertex_magnitude_map(CGAL::make_property_map(magnitude))
                 .singularities_output_iterator(std::back_inserter(singular)));
  const SIO::Direction_field_data data = SIO::make_direction_field_data(
    mesh, dir, degree, singular, CGAL::parameters::vertex_magnitude_map(CGAL::make_property_map(magnitude)));
  const std::string what = name + " (n = " + std::to_string(degree) + ")";
  report.check(data.singularities.size() == r.number_of_singular_faces && (name != "icosphere" || !data.singularities.empty()),
               what + ": the data lists every singular face");

  // the n directions: unit, tangent to the solver's plane (orthogonal to d_0's normal), 2 pi / n apart
  bool directions_ok = true;
  for(const auto& ds : data.directions)
    for(std::size_t k = 0; k < ds.size(); ++k)
    {
      const V3& a = ds[k];
      const V3& b = ds[(k + 1) % ds.size()];
      const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
      directions_ok = directions_ok && std::abs(std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) - 1.) < 1e-12 &&
                      (ds.size() == 1 || std::abs(dot - std::cos(2. * CGAL_PI / degree)) < 1e-12);
    }
  report.check(directions_ok, what + ": the n directions are unit and 2 pi / n apart");

  // VTK
  {
    std::stringstream ss;
    SIO::write_VTK(ss, data);
    const SIO::Direction_field_data back = SIO::read_VTK(ss);
    report.check(back.degree == degree && max_difference(back.points, data.points) == 0. && back.faces == data.faces &&
                   max_direction_difference(back, data) == 0. && back.magnitudes == data.magnitudes &&
                   back.singularities == data.singularities &&
                   max_difference(back.singularity_points, data.singularity_points) == 0.,
                 what + ": VTK round trip is exact (points, triangles, all n directions, magnitudes, singularities)");
  }
  // PLY, read by the package and by CGAL's PLY reader
  {
    std::stringstream ss;
    SIO::write_PLY(ss, data);
    const std::string text = ss.str();
    const SIO::Direction_field_data back = SIO::read_PLY(ss);
    report.check(back.degree == degree && max_difference(back.points, data.points) == 0. && back.faces == data.faces &&
                   max_direction_difference(back, data) < 1e-12 && back.magnitudes == data.magnitudes &&
                   back.singularities == data.singularities,
                 what + ": PLY round trip (first direction exact, the others rebuilt to 1e-12)");
    Mesh read_mesh;
    std::istringstream is(text);
    const bool read = CGAL::IO::read_PLY(is, read_mesh);
    bool same = read && read_mesh.number_of_vertices() == mesh.number_of_vertices() &&
                read_mesh.number_of_faces() == mesh.number_of_faces();
    const auto dx = SMDF::internal::find_property_map<Vertex_index, double>(read_mesh, "v:dx");
    const auto dy = SMDF::internal::find_property_map<Vertex_index, double>(read_mesh, "v:dy");
    const auto dz = SMDF::internal::find_property_map<Vertex_index, double>(read_mesh, "v:dz");
    same = same && dx && dy && dz;
    if(same)
      for(Vertex_index v : read_mesh.vertices())
      {
        const auto& d = data.directions[std::size_t(v)][0];
        same = same && (*dx)[v] == d[0] && (*dy)[v] == d[1] && (*dz)[v] == d[2];
      }
    report.check(same, what + ": CGAL::IO::read_PLY reads the mesh and the direction properties v:dx, v:dy, v:dz");
  }
  // per-face formats
  {
    std::stringstream ss;
    SIO::write_rosy(ss, data);
    SIO::Direction_field_data back = data;
    back.face_directions.clear();
    SIO::read_rosy(ss, back);
    report.check(back.degree == degree && max_difference(back.face_directions, data.face_directions) == 0.,
                 what + ": rosy round trip is exact");
    std::stringstream sf;
    SIO::write_ffield(sf, data);
    SIO::Direction_field_data back2 = data;
    back2.face_directions.clear();
    SIO::read_ffield(sf, back2);
    report.check(max_difference(back2.face_directions, data.face_directions) < 1e-15,
                 what + ": ffield round trip (first frame vector)");
  }
  // singularities as text
  {
    std::stringstream ss;
    SIO::write_singularities(ss, data);
    SIO::Direction_field_data back;
    SIO::read_singularities(ss, back);
    int sum = 0;
    for(const auto& s : back.singularities) sum += s.second;
    report.check(back.singularities == data.singularities && back.degree == degree &&
                   max_difference(back.singularity_points, data.singularity_points) == 0. && sum == r.index_sum,
                 what + ": singularity list round trip, index sum " + std::to_string(sum) + "/" + std::to_string(degree));
  }

  // The face rule does not depend on which of its n directions a vertex lists
  // first, and face directions lie in the face plane.
  SIO::Direction_field_data turned = data;
  for(std::size_t v = 0; v < turned.directions.size(); ++v)
    std::rotate(turned.directions[v].begin(), turned.directions[v].begin() + static_cast<long>(v % degree),
                turned.directions[v].end());
  const std::vector<V3> faces_turned = SIO::face_directions(turned);
  double worst = 0., off_plane = 0.;
  for(std::size_t f = 0; f < data.faces.size(); ++f)
  {
    const V3 n = face_normal(data, f);
    worst = (std::max)(worst, angle_mod(faces_turned[f], data.face_directions[f], n, degree));
    const V3& d = data.face_directions[f];
    off_plane = (std::max)(off_plane, std::abs(d[0] * n[0] + d[1] * n[1] + d[2] * n[2]));
  }
  report.check(worst < 1e-9 && off_plane < 1e-12,
               what + ": face directions are in the face plane and independent of each vertex's first direction");
}

// The smoothest field of `mesh` as the arrays the field lines read (the
// separation check; check_streamlines() also needs the property maps).
static SIO::Direction_field_data smoothest_field_data(const Mesh& mesh, int degree)
{
  std::vector<Vector_3> storage(mesh.number_of_vertices());
  auto dir = CGAL::make_property_map(storage);
  std::vector<std::pair<Face_index, int> > singular;
  SMDF::compute_globally_optimal_directions(
    mesh, dir, CGAL::parameters::degree(degree).singularities_output_iterator(std::back_inserter(singular)));
  return SIO::make_direction_field_data(mesh, dir, degree, singular);
}

static double bounding_box_diagonal(const SIO::Direction_field_data& data)
{
  V3 lo = data.points[0], hi = data.points[0];
  for(const V3& p : data.points) for(int k = 0; k < 3; ++k) { lo[k] = (std::min)(lo[k], p[k]); hi[k] = (std::max)(hi[k], p[k]); }
  return distance(lo, hi);
}

// Streamlines: on the surface, along the per-face field, never inside a
// singular face, ending where they say they end.
static void check_streamlines(Test_report& report, const std::string& name, const Mesh& mesh, int degree,
                              bool expect_boundary, bool expect_singularity)
{
  std::vector<Vector_3> storage(mesh.number_of_vertices());
  auto dir = CGAL::make_property_map(storage);
  std::vector<std::pair<Face_index, int> > singular;
  SMDF::compute_globally_optimal_directions(
    mesh, dir, CGAL::parameters::degree(degree).singularities_output_iterator(std::back_inserter(singular)));
  const SIO::Direction_field_data data = SIO::make_direction_field_data(mesh, dir, degree, singular);
  SMDF::Streamline_options options;
  options.seed_spacing = 0.1;
  options.maximum_length = 0.7;
  options.minimum_separation = 0.;
  const std::vector<SMDF::Streamline> lines = SMDF::trace_streamlines(data, options);
  const std::string what = name + " (n = " + std::to_string(degree) + ")";

  const double diagonal = bounding_box_diagonal(data);
  std::vector<char> is_singular(data.faces.size(), 0);
  for(const auto& s : data.singularities) is_singular[s.first] = 1;
  // boundary edges and edges of singular faces, as vertex pairs
  std::map<std::pair<std::size_t, std::size_t>, int> edge_count;
  for(const auto& t : data.faces)
    for(int c = 0; c < 3; ++c) ++edge_count[std::minmax(t[c], t[(c + 1) % 3])];
  auto on_edge = [&](const V3& p, std::size_t a, std::size_t b) {
    const V3& A = data.points[a];
    const V3& B = data.points[b];
    const V3 e{B[0] - A[0], B[1] - A[1], B[2] - A[2]};
    const double t = ((p[0] - A[0]) * e[0] + (p[1] - A[1]) * e[1] + (p[2] - A[2]) * e[2]) / (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    const V3 q{A[0] + t * e[0], A[1] + t * e[1], A[2] + t * e[2]};
    return t > -1e-9 && t < 1. + 1e-9 && distance(p, q) < 1e-9 * diagonal;
  };
  // p in the triangle f: in its plane and with non-negative barycentric coordinates
  auto in_face = [&](const V3& p, std::size_t f) {
    const auto& t = data.faces[f];
    const V3 n = face_normal(data, f);
    const V3& A = data.points[t[0]];
    if(std::abs((p[0] - A[0]) * n[0] + (p[1] - A[1]) * n[1] + (p[2] - A[2]) * n[2]) > 1e-9 * diagonal) return false;
    for(int c = 0; c < 3; ++c)
    {
      const V3& a = data.points[t[c]];
      const V3& b = data.points[t[(c + 1) % 3]];
      const V3 e{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, ap{p[0] - a[0], p[1] - a[1], p[2] - a[2]};
      const V3 x{e[1] * ap[2] - e[2] * ap[1], e[2] * ap[0] - e[0] * ap[2], e[0] * ap[1] - e[1] * ap[0]};
      if((x[0] * n[0] + x[1] * n[1] + x[2] * n[2]) < -1e-9 * diagonal * diagonal) return false;
    }
    return true;
  };
  bool on_surface = true, follows = true, avoids = true, ends_ok = true, saw_boundary = false, saw_singularity = false;
  double worst_angle = 0.;
  for(const SMDF::Streamline& l : lines)
  {
    for(std::size_t i = 0; i + 1 < l.points.size(); ++i)
    {
      const std::size_t f = l.faces[i];
      on_surface = on_surface && in_face(l.points[i], f) && in_face(l.points[i + 1], f);
      avoids = avoids && !is_singular[f];
      const V3 s{l.points[i + 1][0] - l.points[i][0], l.points[i + 1][1] - l.points[i][1], l.points[i + 1][2] - l.points[i][2]};
      const double len = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
      if(len > 1e-12 * diagonal)
        worst_angle = (std::max)(worst_angle, angle_mod(V3{s[0] / len, s[1] / len, s[2] / len}, data.face_directions[f],
                                                        face_normal(data, f), degree));
    }
    // each end: on a boundary edge, on an edge of a singular face, or at the length limit
    for(int side = 0; side < 2; ++side)
    {
      const SMDF::Streamline::End end = side == 0 ? l.start_end : l.finish_end;
      const V3& p = side == 0 ? l.points.front() : l.points.back();
      const std::size_t f = side == 0 ? l.faces.front() : l.faces.back();
      const auto& t = data.faces[f];
      if(end == SMDF::Streamline::End::BOUNDARY)
      {
        saw_boundary = true;
        bool found = false;
        for(int c = 0; c < 3; ++c)
          found = found || (edge_count[std::minmax(t[c], t[(c + 1) % 3])] == 1 && on_edge(p, t[c], t[(c + 1) % 3]));
        ends_ok = ends_ok && found;
      }
      else if(end == SMDF::Streamline::End::SINGULARITY)
      {
        saw_singularity = true;
        bool found = false;  // p is on an edge of f shared with a singular face
        for(std::size_t g = 0; g < data.faces.size(); ++g)
          if(is_singular[g])
            for(int c = 0; c < 3; ++c)
              found = found || on_edge(p, data.faces[g][c], data.faces[g][(c + 1) % 3]);
        ends_ok = ends_ok && found;
      }
      else if(end == SMDF::Streamline::End::TURNED_BACK)
      {
        bool found = false;  // p is on an edge of its last face
        for(int c = 0; c < 3; ++c) found = found || on_edge(p, t[c], t[(c + 1) % 3]);
        ends_ok = ends_ok && found;
      }
      else
        ends_ok = ends_ok && end == SMDF::Streamline::End::LENGTH;
    }
  }
  follows = worst_angle < CGAL_PI / 180.;
  report.check(!lines.empty(), what + ": " + std::to_string(lines.size()) + " streamlines");
  // the same lines as CGAL polylines of the mesh's point type
  std::vector<std::vector<Kernel::Point_3> > polylines;
  SMDF::trace_streamlines(mesh, dir, degree, singular, std::back_inserter(polylines), options);
  bool same_polylines = polylines.size() == lines.size();
  for(std::size_t i = 0; same_polylines && i < lines.size(); ++i)
  {
    same_polylines = polylines[i].size() == lines[i].points.size();
    for(std::size_t j = 0; same_polylines && j < polylines[i].size(); ++j)
      same_polylines = polylines[i][j].x() == lines[i].points[j][0] && polylines[i][j].y() == lines[i].points[j][1] &&
                       polylines[i][j].z() == lines[i].points[j][2];
  }
  report.check(same_polylines, what + ": the polyline output gives the same lines as Point_3 vectors");
  report.check(on_surface, what + ": every streamline point lies in its face (within 1e-9 of the diagonal)");
  report.check(follows, what + ": every segment follows its face's field (worst " + std::to_string(worst_angle) + " rad)");
  report.check(avoids, what + ": no segment inside a singular face");
  report.check(ends_ok, what + ": each end is on a boundary edge, on a singular face's edge, on the edge where "
                                "the field turns back, or at the length limit");
  if(expect_boundary) report.check(saw_boundary, what + ": some streamlines end at the boundary");
  if(expect_singularity) report.check(saw_singularity, what + ": some streamlines end at a singularity");
}

// Evenly spaced lines (Streamline_options::minimum_separation): fewer lines
// than without, and no point of a line (but an end that says TOO_CLOSE)
// within half the separation of an earlier line running the same way (the
// tracer compares with samples of the earlier lines every half separation,
// the last point of a line included only through its segment's samples, so
// half is what it guarantees).
// `spaced`: the options with a separation (the library's defaults have one).
static void check_streamline_separation(Test_report& report, const std::string& name, const Mesh& mesh, int degree,
                                        const SMDF::Streamline_options& spaced)
{
  const SIO::Direction_field_data data = smoothest_field_data(mesh, degree);
  SMDF::Streamline_options options = spaced;
  options.minimum_separation = 0.;
  const std::size_t all_lines = SMDF::trace_streamlines(data, options).size();
  options = spaced;
  const std::vector<SMDF::Streamline> lines = SMDF::trace_streamlines(data, options);
  const double separation = options.minimum_separation * bounding_box_diagonal(data);
  auto unit = [](const V3& a, const V3& b) {
    const V3 e{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double l = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
    return l > 0. ? V3{e[0] / l, e[1] / l, e[2] / l} : V3{0., 0., 0.};
  };
  auto to_segment = [](const V3& p, const V3& a, const V3& b) {
    const V3 e{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double ee = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    double t = ee > 0. ? ((p[0] - a[0]) * e[0] + (p[1] - a[1]) * e[1] + (p[2] - a[2]) * e[2]) / ee : 0.;
    t = (std::max)(0., (std::min)(1., t));
    return distance(p, V3{a[0] + t * e[0], a[1] + t * e[1], a[2] + t * e[2]});
  };
  double closest = HUGE_VAL;
  bool stopped = false;
  for(std::size_t j = 0; j < lines.size(); ++j)
  {
    const SMDF::Streamline& l = lines[j];
    stopped = stopped || l.start_end == SMDF::Streamline::End::TOO_CLOSE || l.finish_end == SMDF::Streamline::End::TOO_CLOSE;
    for(std::size_t i = 1; i < l.points.size(); ++i)
    {
      if(i + 1 == l.points.size() && l.finish_end == SMDF::Streamline::End::TOO_CLOSE) continue;
      // the tracer tested the point with the direction it was moving in: the segment
      // before it (forwards) or after it (the backward half, reversed): count a
      // point as near a parallel line only when both its segments run parallel
      const V3 before = unit(l.points[i - 1], l.points[i]);
      const V3 after = i + 1 < l.points.size() ? unit(l.points[i], l.points[i + 1]) : before;
      for(std::size_t k = 0; k < j; ++k)
        for(std::size_t m = 0; m + 1 < lines[k].points.size(); ++m)
        {
          const V3 u = unit(lines[k].points[m], lines[k].points[m + 1]);
          if(std::abs(before[0] * u[0] + before[1] * u[1] + before[2] * u[2]) > 0.9 &&
             std::abs(after[0] * u[0] + after[1] * u[1] + after[2] * u[2]) > 0.9)
            closest = (std::min)(closest, to_segment(l.points[i], lines[k].points[m], lines[k].points[m + 1]));
        }
    }
  }
  report.check(lines.size() < all_lines && stopped && closest >= 0.5 * separation,
               name + " (n = " + std::to_string(degree) + "): evenly spaced lines, " + std::to_string(lines.size()) +
                 " of " + std::to_string(all_lines) + ", closest parallel points " + std::to_string(closest / separation) +
                 " separations apart");
}

// A PolyData file as the writer of earlier versions wrote it (the octahedron,
// n = 1, one singularity point at the barycentre of face 0): still read, the
// singular face found from the point.
static void check_old_polydata_file(Test_report& report)
{
  std::string text = "# vtk DataFile Version 3.0\ndirection field of degree 1 (CGAL Surface_mesh_direction_fields)\n"
                     "ASCII\nDATASET POLYDATA\nFIELD FieldData 1\ndegree 1 1 int\n1\nPOINTS 7 double\n"
                     "1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n0.33333333333333331 0.33333333333333331 "
                     "0.33333333333333331\nVERTICES 1 2\n1 6\nPOLYGONS 8 32\n3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n"
                     "3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\nPOINT_DATA 7\nSCALARS singularity_index double 1\n"
                     "LOOKUP_TABLE default\n0\n0\n0\n0\n0\n0\n1\nNORMALS normals double\n";
  for(int i = 0; i < 7; ++i) text += "1 0 0\n";
  text += "VECTORS direction_0 double\n0 1 0\n0 1 0\n1 0 0\n1 0 0\n1 0 0\n1 0 0\n0 0 0\n"
          "CELL_DATA 9\nSCALARS singularity_index double 1\nLOOKUP_TABLE default\n1\n0\n0\n0\n0\n0\n0\n0\n0\n";
  std::istringstream is(text);
  std::string error;
  SIO::Direction_field_data back;
  try { back = SIO::read_VTK(is); }
  catch(const std::exception& e) { error = e.what(); }
  const std::vector<std::pair<std::size_t, int> > expected{{0, 1}};
  report.check(error.empty() && back.degree == 1 && back.points.size() == 6 && back.faces.size() == 8 &&
                 back.singularities == expected && back.directions[2][0] == SIO::Direction_field_data::Vector{1., 0., 0.},
               "a PolyData file of earlier versions is read (" + error + ")");
}

// Normals at any scale: near coordinates of 1e±80 the squares of a cross
// product leave double's range (the field lines of a sphere scaled by 1e80
// differed from the sphere's), so norms scale by a power of two there.
void check_normals_at_extreme_scales(Test_report& report)
{
  namespace I = SMDF::internal;
  using I::operator-;
  using I::operator*;
  const std::vector<I::Vec3> unit{{0.3, -0.2, 1.1}, {1.7, 0.4, 0.9}, {0.6, 1.3, -0.4}};
  const std::array<std::size_t, 3> triangle{0, 1, 2};
  const I::Vec3 expected = I::triangle_unit_normal(unit, triangle);
  for(double scale : {1e-300, 1e-150, 1e-80, 1e80, 1e150})
  {
    std::vector<I::Vec3> scaled = unit;
    for(I::Vec3& p : scaled)
      for(double& x : p) x *= scale;
    std::ostringstream by;
    by << " scaled by " << scale;
    const I::Vec3 normal = I::triangle_unit_normal(scaled, triangle);
    // below about 1e-160 the cross product itself underflows: the library scales such coordinates first
    report.check(I::norm(normal - expected) < 1e-14 || scale < 1e-160, "the unit normal of a triangle" + by.str());
    report.check(std::abs(I::norm(scale * I::Vec3{3., 4., 12.}) / (13. * scale) - 1.) < 1e-15,
                 "the norm of a vector" + by.str());
  }
}

// A field on faces: make_face_direction_field_data() keeps the library's
// directions, singular vertices and matching; the VTK file holds them per
// cell and per point and reads back to the same data; the markers sit on the
// singular vertices; field lines stay out of the faces around them.
static void check_face_field_files(Test_report& report, const Mesh& mesh, int degree)
{
  const std::string what = "field on faces, n = " + std::to_string(degree);
  std::vector<Vector_3> directions(mesh.number_of_faces());
  std::vector<int> matching(mesh.number_of_edges(), 0);
  std::vector<std::pair<Vertex_index, int> > singular;
  const SMDF::Face_direction_field_result r = SMDF::compute_globally_optimal_face_directions(
    mesh, CGAL::make_property_map(directions),
    CGAL::parameters::degree(degree).singularities_output_iterator(std::back_inserter(singular))
      .edge_matching_map(CGAL::make_property_map(matching)));
  const SIO::Direction_field_data data = SMDF::make_face_direction_field_data(
    mesh, CGAL::make_property_map(directions), r, singular,
    CGAL::parameters::edge_matching_map(CGAL::make_property_map(matching)));
  long long sum = 0;
  for(const auto& vk : data.vertex_singularities) sum += vk.second;
  bool same_directions = data.face_directions.size() == mesh.number_of_faces() && data.directions.empty();
  for(Face_index f : mesh.faces())
    same_directions = same_directions && data.face_directions[f] == V3{directions[f].x(), directions[f].y(), directions[f].z()};
  report.check(same_directions && sum == 2 * degree && data.vertex_singularities.size() == singular.size(),
               what + ": the data holds the library's directions and singular vertices (index sum n chi)");
  // the matching per face side is the edge's jump, with the opposite sign from the other face
  bool matching_ok = data.face_matching.size() == mesh.number_of_faces();
  for(Mesh::Edge_index e : mesh.edges())
  {
    const Mesh::Halfedge_index h = mesh.halfedge(e);  // the jump is stored from this halfedge's face
    if(mesh.is_border(h) || mesh.is_border(mesh.opposite(h)) || !matching_ok) continue;
    auto side_of = [&](Mesh::Halfedge_index g) {
      const auto& t = data.faces[mesh.face(g)];
      const std::size_t source = mesh.source(g);
      return data.face_matching[mesh.face(g)][t[0] == source ? 0 : t[1] == source ? 1 : 2];
    };
    matching_ok = side_of(h) == matching[e] && side_of(mesh.opposite(h)) == -matching[e];
  }
  bool some_jump = false;
  for(int m : matching) some_jump = some_jump || m != 0;
  report.check(matching_ok && some_jump,
               what + ": the matching per face side is the edge's jump, opposite from the other face");

  std::ostringstream vtk;
  SIO::write_VTK(vtk, data);
  const std::string text = vtk.str();
  report.check(text.find("CELL_DATA " + std::to_string(mesh.number_of_faces()) + "\nVECTORS direction_0 double") !=
                   std::string::npos && text.find("POINT_DATA") != std::string::npos,
               what + ": the legacy VTK file has direction_0 as the active cell vectors");
  std::istringstream in(text);
  const SIO::Direction_field_data back = SIO::read_VTK(in);
  report.check(back.degree == degree && back.directions.empty() && back.faces == data.faces &&
                 max_difference(back.face_directions, data.face_directions) == 0. &&
                 back.vertex_singularities == data.vertex_singularities,
               what + ": read_VTK gives back the per-face directions and the singular vertices exactly");
  std::ostringstream vtu;
  SIO::write_VTU(vtu, data);
  report.check(vtu.str().find("<CellData Vectors=\"direction_0\">") != std::string::npos,
               what + ": the .vtu file has direction_0 as the active cell vectors");

  std::ostringstream markers;
  SIO::write_VTK_singularities(markers, data);
  std::istringstream marker_in(markers.str());
  std::string line;
  std::size_t marker_points = 0;
  while(std::getline(marker_in, line))
    if(line.rfind("POINTS ", 0) == 0) marker_points = std::stoul(line.substr(7));
  report.check(marker_points == 6 * data.vertex_singularities.size() && marker_points > 0,
               what + ": one marker (6 points) per singular vertex");

  const std::vector<SMDF::Streamline> lines = SMDF::trace_streamlines(data);
  std::vector<unsigned char> near_singular(data.faces.size(), 0);
  for(std::size_t f = 0; f < data.faces.size(); ++f)
    for(const auto& vk : data.vertex_singularities)
      if(std::count(data.faces[f].begin(), data.faces[f].end(), vk.first)) near_singular[f] = 1;
  bool avoids = !lines.empty();
  for(const SMDF::Streamline& l : lines)
    for(std::size_t f : l.faces) avoids = avoids && !near_singular[f];
  report.check(avoids, what + ": " + std::to_string(lines.size()) +
                         " field lines, none through a face around a singular vertex");
}

int main()
{
  Test_report report("io");
  Mesh sphere, torus;
  make_icosphere(sphere, 3);
  make_torus(torus, 2., 0.5, 40, 16);
  check_round_trips(report, "icosphere", sphere, 4);
  check_round_trips(report, "icosphere", sphere, 1);
  check_round_trips(report, "icosphere", sphere, 3);
  check_normals_at_extreme_scales(report);
  check_face_field_files(report, sphere, 4);
  check_face_field_files(report, sphere, 1);

  // A constant field on a planar disk: every face direction is that field.
  {
    Mesh disk;
    make_disk(disk, 6);
    std::vector<Vector_3> storage(disk.number_of_vertices(), Vector_3(std::cos(0.3), std::sin(0.3), 0.));
    const std::vector<std::pair<Face_index, int> > none;
    const SIO::Direction_field_data data =
      SIO::make_direction_field_data(disk, CGAL::make_property_map(storage), 4, none);
    double worst = 0.;
    for(std::size_t f = 0; f < data.faces.size(); ++f)
      worst = (std::max)(worst, angle_mod(data.face_directions[f], V3{std::cos(0.3), std::sin(0.3), 0.},
                                          face_normal(data, f), 4));
    report.check(worst < 1e-12, "a constant planar field is transferred to every face exactly");
  }

  // Bad input: clear errors, no crash.
  {
    std::istringstream not_vtk("hello\n");
    bool thrown = false;
    try { SIO::read_VTK(not_vtk); } catch(const SMDF::Invalid_input_error&) { thrown = true; }
    report.check(thrown, "read_VTK rejects a file that is not VTK");
    std::istringstream truncated("ply\nformat ascii 1.0\ncomment direction_field_degree 4\nelement vertex 3\n"
                                 "element face 1\nend_header\n0 0 0 1 0 0\n");
    thrown = false;
    try { SIO::read_PLY(truncated); } catch(const SMDF::Invalid_input_error&) { thrown = true; }
    report.check(thrown, "read_PLY rejects a truncated file");
    std::istringstream wrong_count("5\n4\n1 0 0\n");
    SIO::Direction_field_data three_faces;
    three_faces.faces.resize(3);
    thrown = false;
    try { SIO::read_rosy(wrong_count, three_faces); } catch(const SMDF::Invalid_input_error&) { thrown = true; }
    report.check(thrown, "read_rosy rejects a face count that does not match the mesh");
  }
  check_round_trips(report, "torus", torus, 4);

  // Mutated files: truncated, or with one character changed, every reader
  // either reads them or throws Invalid_input_error -- nothing else.
  {
    std::vector<Vector_3> storage(sphere.number_of_vertices());
    auto dir = CGAL::make_property_map(storage);
    std::vector<std::pair<Face_index, int> > singular;
    SMDF::compute_globally_optimal_directions(
      sphere, dir, CGAL::parameters::degree(4).singularities_output_iterator(std::back_inserter(singular)));
    const SIO::Direction_field_data data = SIO::make_direction_field_data(sphere, dir, 4, singular);
    std::stringstream vtk, ply, rosy, ffield, sing;
    SIO::write_VTK(vtk, data);
    SIO::write_PLY(ply, data);
    SIO::write_rosy(rosy, data);
    SIO::write_ffield(ffield, data);
    SIO::write_singularities(sing, data);
    const std::vector<std::string> texts{vtk.str(), ply.str(), rosy.str(), ffield.str(), sing.str()};
    std::size_t cases = 0, rejected = 0;
    bool only_documented_errors = true;
    unsigned long long state = 12345;
    auto random = [&state]() { state = state * 6364136223846793005ULL + 1442695040888963407ULL; return state >> 33; };
    for(std::size_t kind = 0; kind < texts.size(); ++kind)
      for(int trial = 0; trial < 40; ++trial)
      {
        std::string text = texts[kind];
        const std::size_t position = random() % text.size();
        if(trial % 2 == 0) text.resize(position);
        else text[position] = "x-9.e 0\n#"[random() % 10];
        std::istringstream is(text);
        ++cases;
        try
        {
          SIO::Direction_field_data back = data;
          if(kind == 0) SIO::read_VTK(is);
          else if(kind == 1) SIO::read_PLY(is);
          else if(kind == 2) SIO::read_rosy(is, back);
          else if(kind == 3) SIO::read_ffield(is, back);
          else SIO::read_singularities(is, back);
        }
        catch(const SMDF::Invalid_input_error&) { ++rejected; }
        catch(...) { only_documented_errors = false; }
      }
    report.check(only_documented_errors, std::to_string(cases) + " mutated files: read or rejected with Invalid_input_error (" +
                                           std::to_string(rejected) + " rejected)");
  }

  check_streamlines(report, "icosphere", sphere, 4, false, true);
  check_streamlines(report, "icosphere", sphere, 1, false, true);
  check_streamlines(report, "torus", torus, 2, false, false);
  SMDF::Streamline_options coarse;
  coarse.seed_spacing = 0.05;
  coarse.maximum_length = 0.5;
  coarse.minimum_separation = 0.08;
  check_streamline_separation(report, "icosphere", sphere, 4, coarse);
  check_streamline_separation(report, "torus", torus, 2, coarse);
  check_streamline_separation(report, "icosphere, the library's defaults", sphere, 4, SMDF::Streamline_options());
  {
    Mesh disk;
    make_disk(disk, 10);
    check_streamlines(report, "disk", disk, 4, true, false);
    check_streamlines(report, "disk", disk, 3, true, false);
  }
  check_old_polydata_file(report);
  return report.finish();
}
