// The program on a point set (.xyz, .pts, or a PLY without faces): the field
// of compute_globally_optimal_point_set_directions(), its files and report.
// A translation unit of its own, so that the program's two parts compile side
// by side.
#include "point_set_run.h"

#include "command_line_options.h"
#include "file_io/optional_named_parameters.h"
#include "file_io/output_files.h"
#include "file_io/read_polygon_soup.h"
#include "guidance_file.h"
#include "png_snapshot.h"
#include "progress.h"
#include "reports.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO.h>
#include <CGAL/Surface_mesh_direction_fields/globally_optimal_point_set_directions.h>

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace point_set_run {

namespace SMDF = CGAL::Surface_mesh_direction_fields;
namespace onp = optional_named_parameters;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef CGAL::Point_set_3<Kernel::Point_3, Kernel::Vector_3> Point_set;

std::string extension_of(const std::string& path)
{
  const std::size_t dot = path.rfind('.'), slash = path.rfind('/');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string e = path.substr(dot + 1);
  for(char& c : e) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

// Whether the file is a point set by its name: .xyz or .pts. A PLY is one
// when the program's own reader finds no face in it (read_point_set_ply()).
bool is_point_set_file(const std::string& path)
{
  const std::string e = extension_of(path);
  return e == "xyz" || e == "pts";
}

// .xyz and .pts: one point per line, 'x y z' and more numbers; in .xyz, the
// fourth to sixth numbers are the normal when every line has them. A first
// line with one number (the count of .pts files) and '#' lines are skipped.
// The bytes come from the mesh reader's read_whole_file() (devices, folders
// and silent pipes refused as for meshes).
inline Point_set read_text_points(const std::string& path)
{
  std::string bytes = soup_reading::read_whole_file(path, "a point file");
  soup_reading::prepare_text(bytes, true);
  std::istringstream in(bytes);
  std::vector<std::vector<double> > rows;
  std::string line;
  for(std::size_t number = 1; std::getline(in, line); ++number)
  {
    std::istringstream words(line);
    std::vector<double> row;
    std::string word;
    while(words >> word)
    {
      if(word[0] == '#') break;
      double x = 0.;
      const auto r = std::from_chars(word.data() + (word[0] == '+'), word.data() + word.size(), x);
      if(r.ec != std::errc() || r.ptr != word.data() + word.size() || !std::isfinite(x))
        throw Usage_error(path + " line " + std::to_string(number) + ": '" + word.substr(0, 40) +
                          "' is not a finite coordinate");
      row.push_back(x);
    }
    if(row.empty() || (number == 1 && row.size() == 1)) continue;
    if(row.size() < 3)
      throw Usage_error(path + " line " + std::to_string(number) + ": expected 'x y z', got '" + line.substr(0, 40) + "'");
    rows.push_back(row);
  }
  bool normals = extension_of(path) == "xyz" && !rows.empty();
  for(const auto& row : rows) normals = normals && row.size() >= 6;
  Point_set points(normals);
  for(const auto& r : rows)
  {
    if(normals) points.insert(Kernel::Point_3(r[0], r[1], r[2]), Kernel::Vector_3(r[3], r[4], r[5]));
    else points.insert(Kernel::Point_3(r[0], r[1], r[2]));
  }
  if(points.size() == 0) throw Usage_error("'" + path + "' holds no point");
  return points;
}

// A PLY without faces, already read by the program's reader (which checked
// it): its points, and its normals where the vertices have nx, ny, nz (read
// again by CGAL's PLY reader, on a file known to be sound).
inline Point_set read_point_set_ply(const std::string& path, const Polygon_soup& soup)
{
  Point_set with_normals;
  std::ifstream in(path, std::ios::binary);
  if(in && CGAL::IO::read_PLY(in, with_normals) && with_normals.has_normal_map() &&
     with_normals.size() == soup.points.size())
    return with_normals;
  Point_set points(false);
  for(const auto& p : soup.points) points.insert(Kernel::Point_3(p[0], p[1], p[2]));
  if(points.size() == 0) throw Usage_error("'" + path + "' holds no point");
  return points;
}

// The options that have no meaning on a point set, refused in one line.
inline void check_point_set_options(const Options& o)
{
  if(o.on != "vertices") throw Usage_error("--on faces applies to meshes: a point set has its field on its points");
  const std::pair<const char*, bool> refused[] = {
    {"--constrain-boundary", o.constrain_boundary != "none"},
    {"--feature-angle", o.feature_angle > 0.}, {"--prescribe", !o.prescribe.empty()},
    {"--solver", o.solver != "default"},
    {"--singularities", !o.singularities.empty()}, {"--vtk-singularities", !o.vtk_singularities.empty()},
    {"--rosy", !o.rosy.empty()}, {"--ffield", !o.ffield.empty()}, {"--sharp", !o.sharp.empty()},
    {"--singularity-list", !o.singularity_list.empty()}, {"--streamlines", !o.streamlines.empty()},
    {"--mesh-out", !o.mesh_out.empty()}};
  for(const auto& r : refused)
    if(r.second) throw Usage_error(std::string(r.first) + " applies to meshes, not to the point set '" + o.mesh + "'");
  if(!o.vtk.empty() && extension_of(o.vtk) != "vtk")
    throw Usage_error("--vtk with a point set writes legacy VTK: name the file .vtk");
}

// Writes the directions into a vector, by the points' indices.
struct Direction_map
{
  typedef Point_set::Index key_type;
  typedef Kernel::Vector_3 value_type;
  typedef Kernel::Vector_3& reference;
  typedef boost::writable_property_map_tag category;
  std::vector<Kernel::Vector_3>* directions;
  friend void put(const Direction_map& m, key_type i, const value_type& d) { (*m.directions)[std::size_t(i)] = d; }
};

struct Point_field
{
  SMDF::Point_set_direction_field_result result;
  std::vector<Kernel::Vector_3> directions;
  std::vector<Kernel::Point_3> points;
  double compute_ms = 0.;
};

inline Point_field compute(const Options& o, const Point_set& points)
{
  Point_field field;
  std::vector<Kernel::Vector_3> directions(points.size()), guidance;
  if(!o.guidance.empty())
    for(const auto& g : read_guidance_file(o.guidance, points.size(), "points")) guidance.emplace_back(g[0], g[1], g[2]);
  const Direction_map direction_map{&directions};
  const auto np = CGAL::parameters::point_map(points.point_map())
                    .degree(o.degree)
                    .smoothness_parameter(o.s)
                    .number_of_neighbors(o.neighbors)
                    .residual_tolerance(o.tolerance)
                    .principal_curvature_alignment(curvature_alignment(o))
                    .compute_eigenvalue_bound(o.eigenvalue_bound);
  onp::Given_options<onp::Not_offered, decltype(CGAL::make_property_map(guidance)), onp::Not_offered> given;
  if(!guidance.empty()) given.guidance = CGAL::make_property_map(guidance);
  if(o.weight_given) given.alignment_weight = o.weight;
  else if(o.lambda_given) given.alignment_lambda = o.lambda;
  auto compute = [&](const auto& with) {
    return SMDF::compute_globally_optimal_point_set_directions(points, direction_map, with);
  };
  field.result = points.has_normal_map()
                   ? onp::compute_with_point_guidance(given, np.normal_map(points.normal_map()), compute)
                   : onp::compute_with_point_guidance(given, np, compute);
  field.directions = directions;
  for(Point_set::Index i : points) field.points.push_back(points.point(i));
  return field;
}

inline long index_sum(const SMDF::Point_set_direction_field_result& r)
{
  long sum = 0;
  for(const auto& s : r.singular_triangles) sum += s.second;
  return sum;
}

// The direction k of point i (the first turned by 2 pi k / n about the normal).
inline Kernel::Vector_3 direction_k(const Point_field& f, std::size_t i, int k, int n)
{
  const auto& d = f.directions[i];
  const auto& nn = f.result.normals[i];
  const Kernel::Vector_3 normal(nn[0], nn[1], nn[2]);
  const double a = 2. * CGAL_PI * k / n;
  return std::cos(a) * d + std::sin(a) * CGAL::cross_product(normal, d);
}

inline void write_directions(std::ostream& os, const Point_field& f)
{
  os << std::setprecision(17);
  for(const auto& d : f.directions) os << d.x() << ' ' << d.y() << ' ' << d.z() << '\n';
}

// PLY: per point its position, normal and first direction.
inline void write_ply(std::ostream& os, const Point_field& f)
{
  os << "ply\nformat ascii 1.0\ncomment direction field of a point set (Surface_mesh_direction_fields)\n"
     << "element vertex " << f.points.size() << "\nproperty double x\nproperty double y\nproperty double z\n"
     << "property double nx\nproperty double ny\nproperty double nz\n"
     << "property double dx\nproperty double dy\nproperty double dz\nproperty double magnitude\nend_header\n"
     << std::setprecision(17);
  for(std::size_t i = 0; i < f.points.size(); ++i)
  {
    const auto& p = f.points[i];
    const auto& n = f.result.normals[i];
    const auto& d = f.directions[i];
    os << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << n[0] << ' ' << n[1] << ' ' << n[2] << ' ' << d.x() << ' '
       << d.y() << ' ' << d.z() << ' ' << f.result.magnitudes[i] << '\n';
  }
}

// Legacy VTK for ParaView: the points with their normals and n directions,
// the surface triangles (where the singularities are read) with their index.
inline void write_vtk(std::ostream& os, const Point_field& f, int n)
{
  std::vector<std::size_t> surface;
  for(std::size_t t = 0; t < f.result.triangles.size(); ++t)
    if(f.result.on_surface[t]) surface.push_back(t);
  std::vector<int> index(f.result.triangles.size(), 0);
  for(const auto& s : f.result.singular_triangles) index[s.first] = s.second;
  const std::size_t np = f.points.size();
  os << "# vtk DataFile Version 3.0\ndirection field of a point set (Surface_mesh_direction_fields)\nASCII\n"
     << "DATASET UNSTRUCTURED_GRID\nPOINTS " << np << " double\n" << std::setprecision(17);
  for(const auto& p : f.points) os << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  // a vertex cell per point (the points show without the triangles), then the surface triangles
  os << "CELLS " << np + surface.size() << ' ' << 2 * np + 4 * surface.size() << '\n';
  for(std::size_t i = 0; i < np; ++i) os << "1 " << i << '\n';
  for(std::size_t t : surface)
    os << "3 " << f.result.triangles[t][0] << ' ' << f.result.triangles[t][1] << ' ' << f.result.triangles[t][2] << '\n';
  os << "CELL_TYPES " << np + surface.size() << '\n';
  for(std::size_t i = 0; i < np; ++i) os << "1\n";
  for(std::size_t t = 0; t < surface.size(); ++t) os << "5\n";
  os << "CELL_DATA " << np + surface.size() << "\nSCALARS singularity_index int 1\nLOOKUP_TABLE default\n";
  for(std::size_t i = 0; i < np; ++i) os << "0\n";
  for(std::size_t t : surface) os << index[t] << '\n';
  os << "SCALARS holders int 1\nLOOKUP_TABLE default\n";  // how many local triangulations hold the triangle
  for(std::size_t i = 0; i < np; ++i) os << "0\n";
  for(std::size_t t : surface) os << int(f.result.holders[t]) << '\n';
  os << "POINT_DATA " << np << "\nSCALARS magnitude double 1\nLOOKUP_TABLE default\n";
  for(double m : f.result.magnitudes) os << m << '\n';
  for(int k = 0; k < n; ++k)
  {
    os << "VECTORS direction_" << k << " double\n";
    for(std::size_t i = 0; i < np; ++i)
    {
      const Kernel::Vector_3 d = direction_k(f, i, k, n);
      os << d.x() << ' ' << d.y() << ' ' << d.z() << '\n';
    }
  }
  os << "VECTORS normals double\n";  // after the directions: the first vectors are the active ones
  for(const auto& nn : f.result.normals) os << nn[0] << ' ' << nn[1] << ' ' << nn[2] << '\n';
}

// The picture: the surface triangles shaded, the field on the points.
inline void write_picture(std::ostream& os, const Point_field& f, int n)
{
  png_snapshot::Scene scene;
  scene.degree = n;
  for(std::size_t i = 0; i < f.points.size(); ++i)
  {
    scene.points.push_back({f.points[i].x(), f.points[i].y(), f.points[i].z()});
    scene.directions.push_back({f.directions[i].x(), f.directions[i].y(), f.directions[i].z()});
  }
  std::vector<int> index(f.result.triangles.size(), 0);
  for(const auto& s : f.result.singular_triangles) index[s.first] = s.second;
  for(std::size_t t = 0; t < f.result.triangles.size(); ++t)
    if(f.result.on_surface[t])
    {
      scene.triangles.push_back(f.result.triangles[t]);
      scene.face_index.push_back(index[t]);
    }
  png_snapshot::render(scene, os);
}

inline void write_json(std::ostream& os, const Options& o, const Point_field& f, const Left_out_outputs& left_out,
                       const Program_timings& timings)
{
  const SMDF::Point_set_direction_field_result& r = f.result;
  // the eigenvalue, lambda_t and t of the largest component (null: not computed, with --guidance); the
  // worst residual and convergence of all
  SMDF::Component_report main;
  double residual = 0.;
  std::size_t iterations = 0, largest = 0;
  bool converged = true;
  for(const auto& c : r.components)
  {
    if(c.number_of_vertices > largest) { largest = c.number_of_vertices; main = c; }
    residual = (std::max)(residual, c.residual);
    iterations = (std::max)(iterations, c.iterations);
    converged = converged && c.converged;
  }
  os << "{\"mesh\":\"" << json_escape(o.mesh) << "\",\"input\":\"point_set\",\"points\":" << f.points.size()
     << ",\"degree\":" << o.degree << ",\"s\":" << number(o.s) << ",\"neighbors\":" << o.neighbors
     << ",\"normals\":\"" << (r.normals_estimated ? "estimated" : "given") << "\",\"triangles\":" << r.triangles.size()
     << ",\"components\":" << r.components.size() << ",\"eigenvalue\":" << number(main.eigenvalue)
     << ",\"lambda_t\":" << number(main.lambda) << ",\"alignment_weight\":" << number(main.alignment_weight)
     << ",\"residual\":" << number(residual) << ",\"iterations\":" << iterations
     << ",\"converged\":" << (converged ? "true" : "false") << ",\"singular_triangles\":" << r.singular_triangles.size()
     << ",\"index_sum\":" << index_sum(r) << ",\"surface_euler_characteristic\":" << r.surface_euler_characteristic
     << ",\"surface_is_closed\":" << (r.surface_is_closed ? "true" : "false")
     << ",\"points_without_triangles\":" << r.number_of_points_without_triangles << ",\"outputs_left_out\":[";
  for(std::size_t i = 0; i < left_out.size(); ++i) os << (i ? "," : "") << "\"" << left_out[i].first << "\"";
  os << "],\"timings_ms\":{\"read\":" << number(timings.read) << ",\"normals\":" << number(r.normals_ms)
     << ",\"setup\":" << number(r.timings.setup_ms) << ",\"factorization\":" << number(r.timings.factorization_ms)
     << ",\"solve\":" << number(r.timings.solve_ms) << ",\"total\":" << number(f.compute_ms)
     << ",\"write\":" << number(timings.write) << "}}\n";
}

inline void write_summary(std::ostream& os, const Options& o, const Point_field& f)
{
  const SMDF::Point_set_direction_field_result& r = f.result;
  os << o.mesh << ": " << f.points.size() << " points (normals " << (r.normals_estimated ? "estimated" : "given")
     << "), " << r.triangles.size() << " triangles from the local triangulations of " << o.neighbors << " neighbours, "
     << r.components.size() << " component" << (r.components.size() == 1 ? "" : "s") << "\n";
  for(std::size_t c = 0; c < r.components.size() && c < 5; ++c)
    os << "  component " << c << ": " << r.components[c].number_of_vertices << " points, "
       << describe_solve(r.components[c]) << "\n";
  os << "degree " << o.degree << ": " << r.singular_triangles.size() << " singular triangles, index sum "
     << index_sum(r) << "/" << o.degree;
  if(r.surface_is_closed)
    os << " (the surface triangles close up with Euler characteristic " << r.surface_euler_characteristic
       << ": n times it is " << o.degree * r.surface_euler_characteristic << ")\n";
  else
    os << " (the surface triangles do not close up: the sum need not be n times an Euler characteristic)\n";
  if(r.number_of_points_without_triangles > 0)
    os << r.number_of_points_without_triangles << " points in no triangle got no direction (zero vectors)\n";
  os << "compute " << compact(f.compute_ms) << " ms\n";
}

// The whole run on a point set: read, compute, write, report.
// `soup`: the PLY read by the program's reader, without faces (null for .xyz and .pts).
int run(const Options& o, Progress& progress, Program_timings& timings, Output_files& outputs,
        const Polygon_soup* soup)
{
  check_point_set_options(o);
  progress.begin("reading the points of " + o.mesh, timings.read);
  const Point_set points = soup ? read_point_set_ply(o.mesh, *soup) : read_text_points(o.mesh);
  progress.end();
  double compute_ms = 0.;
  progress.begin("computing the field on the points", compute_ms);
  Point_field field = compute(o, points);
  progress.end();
  field.compute_ms = compute_ms;
  progress.begin("writing", timings.write);
  if(!o.directions.empty()) write_directions(outputs.stream(o.directions), field);
  if(!o.ply.empty()) write_ply(outputs.stream(o.ply), field);
  if(!o.vtk.empty()) write_vtk(outputs.stream(o.vtk), field, o.degree);
  if(!o.png.empty()) write_picture(outputs.stream(o.png), field, o.degree);
  outputs.close_all_except(o.json_file);
  progress.end();
  if(!o.json_file.empty())
  {
    write_json(outputs.stream(o.json_file), o, field, outputs.left_out(), timings);
    outputs.close(o.json_file);
  }
  if(o.json) write_json(std::cout, o, field, outputs.left_out(), timings);
  else if(!o.quiet) write_summary(std::cout, o, field);
  std::cout.flush();
  if(!std::cout) throw Usage_error("cannot write to standard output");
  outputs.commit();
  return EXIT_SUCCESS;
}

} // namespace point_set_run

