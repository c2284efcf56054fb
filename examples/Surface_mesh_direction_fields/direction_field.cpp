// direction_field: the command-line program of Surface_mesh_direction_fields.
//
//   direction_field [MESH] [--degree N] [--s S] [--directions FILE]
//                   [--singularities FILE] [--json] [--png FILE]
//                   [--json-file FILE] [--seed N] [--max-iterations N] [--tolerance T]
//
// Computes the globally smoothest n-direction field of a mesh (OFF, OBJ, PLY
// or STL) and its singular faces. The file is read as a polygon soup and
// repaired if needed (read_and_repair_mesh.h: duplicate points merged,
// polygons triangulated, orientation made consistent, non-manifold vertices
// duplicated); the summary says what was changed. With no MESH, CGAL's fandisk
// (Debian package libcgal-demo) is used. The contract of the first six
// options is relied upon by other programs: it is only ever extended.
//
// Outputs
//   --directions FILE     one line "x y z" per vertex (17 significant digits),
//                         in the order of the input file's vertices
//   --singularities FILE  one line "f k" per singular face: the face's index in
//                         the input file and its integer index k (index k/n)
//   --json                one line of JSON on stdout (see README.md)
//   --json-file FILE      the same line of JSON written to FILE
//   --png FILE            a picture of the field (shaded mesh, directions,
//                         singular faces in red (+) and blue (-))
// Exit status 0 on success; otherwise 1, with one line on stderr.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <CGAL/Surface_mesh_direction_fields.h>

#include "png_snapshot.h"
#include "read_and_repair_mesh.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;

namespace SMDF = CGAL::Surface_mesh_direction_fields;

namespace {

struct Options
{
  std::string mesh;
  int degree = 4;
  double s = 0.;
  std::string directions, singularities, png, json_file;
  bool json = false;
  unsigned int seed = 0;
  unsigned int max_iterations = 1000;
  double tolerance = 1e-10;
};

// A problem with the input or the options: reported on one line, exit status 1.
struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };

const char* const usage =
  "usage: direction_field [MESH] [--degree N] [--s S] [--directions FILE] [--singularities FILE]\n"
  "                       [--json] [--json-file FILE] [--png FILE] [--seed N] [--max-iterations N]\n"
  "                       [--tolerance T]\n";

template <typename T>
T parse_number(const std::string& option, const std::string& text)
{
  std::istringstream is(text);
  T value;
  char rest;
  if(!(is >> value) || (is >> rest))
    throw Usage_error("option " + option + " expects a number, got '" + text + "'");
  return value;
}

Options parse_options(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw Usage_error("option " + a + " expects a value");
      return argv[++i];
    };
    if(a == "--help" || a == "-h") { std::cout << usage; std::exit(EXIT_SUCCESS); }
    else if(a == "--degree") o.degree = parse_number<int>(a, value());
    else if(a == "--s") o.s = parse_number<double>(a, value());
    else if(a == "--directions") o.directions = value();
    else if(a == "--singularities") o.singularities = value();
    else if(a == "--png") o.png = value();
    else if(a == "--json") o.json = true;
    else if(a == "--json-file") o.json_file = value();
    else if(a == "--seed") o.seed = parse_number<unsigned int>(a, value());
    else if(a == "--max-iterations") o.max_iterations = parse_number<unsigned int>(a, value());
    else if(a == "--tolerance") o.tolerance = parse_number<double>(a, value());
    else if(!a.empty() && a[0] == '-' && a != "-") throw Usage_error("unknown option " + a);
    else if(o.mesh.empty()) o.mesh = a;
    else throw Usage_error("more than one mesh given ('" + o.mesh + "' and '" + a + "')");
  }
  if(o.mesh.empty())
    o.mesh = CGAL::data_file_path("meshes/fandisk.off");
  return o;
}

std::string json_escape(const std::string& s)
{
  std::string out;
  for(char c : s)
  {
    if(c == '"' || c == '\\') { out += '\\'; out += c; }
    else if(static_cast<unsigned char>(c) < 0x20) { char buf[8]; std::snprintf(buf, sizeof buf, "\\u%04x", c); out += buf; }
    else out += c;
  }
  return out;
}

std::string number(double x)
{
  if(!std::isfinite(x)) return "null";
  std::ostringstream os;
  os << std::setprecision(17) << x;
  return os.str();
}

void write_json(std::ostream& os, const Options& o, const Repaired_mesh<Mesh>& input, const SMDF::Direction_field_result& r)
{
  const Mesh& mesh = input.mesh;
  const Repair_report& rep = input.report;
  int chi = 0;
  for(const auto& c : r.components) chi += c.euler_characteristic;
  os << "{\"mesh\":\"" << json_escape(o.mesh) << "\""
     << ",\"vertices\":" << input.file_vertices << ",\"faces\":" << input.file_faces
     << ",\"mesh_vertices\":" << mesh.number_of_vertices() << ",\"mesh_faces\":" << mesh.number_of_faces()
     << ",\"components\":" << r.components.size() << ",\"isolated_vertices\":" << r.number_of_isolated_vertices
     << ",\"euler_characteristic\":" << chi << ",\"degree\":" << r.degree << ",\"s\":" << number(r.smoothness_parameter);
  auto array = [&](const char* name, auto get) {
    os << ",\"" << name << "\":[";
    for(std::size_t i = 0; i < r.components.size(); ++i) os << (i ? "," : "") << get(r.components[i]);
    os << "]";
  };
  array("eigenvalues", [](const SMDF::Component_report& c) { return number(c.eigenvalue); });
  array("component_euler_characteristics", [](const SMDF::Component_report& c) { return std::to_string(c.euler_characteristic); });
  array("component_index_sums", [](const SMDF::Component_report& c) { return std::to_string(c.index_sum); });
  os << ",\"iterations\":" << r.iterations << ",\"residual\":" << number(r.residual)
     << ",\"converged\":" << (r.converged ? "true" : "false")
     << ",\"singular_faces\":" << r.number_of_singular_faces << ",\"index_sum\":" << r.index_sum
     << ",\"mollification\":" << number(r.mollification)
     << ",\"repairs\":{\"merged_points\":" << rep.merged_points << ",\"degenerate_faces_removed\":" << rep.degenerate_polygons
     << ",\"polygons_triangulated\":" << rep.triangulated_polygons << ",\"triangles_from_polygons\":" << rep.triangles_from_polygons
     << ",\"repeated_faces_removed\":" << rep.repeated_triangles << ",\"faces_reoriented\":" << rep.reoriented_triangles
     << ",\"vertices_duplicated\":" << rep.duplicated_vertices << ",\"faces_skipped\":" << rep.skipped_triangles << "}"
     << ",\"timings_ms\":{\"setup\":" << number(r.timings.setup_ms)
     << ",\"factorization\":" << number(r.timings.factorization_ms)
     << ",\"solve\":" << number(r.timings.solve_ms) << ",\"total\":" << number(r.timings.total_ms) << "}}\n";
}

void write_summary(std::ostream& os, const Options& o, const Repaired_mesh<Mesh>& input, const SMDF::Direction_field_result& r)
{
  const Mesh& mesh = input.mesh;
  int chi = 0;
  for(const auto& c : r.components) chi += c.euler_characteristic;
  os << "mesh            " << o.mesh << "\n"
     << "size            " << mesh.number_of_vertices() << " vertices, " << mesh.number_of_faces() << " faces, "
     << r.components.size() << " component(s), Euler characteristic " << chi << "\n"
     << "field           degree n = " << r.degree << ", s = " << r.smoothness_parameter << "\n";
  if(input.report.any())
    os << "repairs         " << input.report.summary() << "\n";
  if(r.mollification > 0.)
    os << "mollification   " << r.mollification << " added to every edge length (degenerate faces)\n";
  for(std::size_t i = 0; i < r.components.size() && i < 10; ++i)
  {
    const auto& c = r.components[i];
    os << "component " << std::setw(4) << i << "  eigenvalue " << c.eigenvalue << ", " << c.iterations
       << " iterations, residual " << c.residual << (c.converged ? "" : " (not converged)") << ", "
       << c.number_of_singular_faces << " singular faces, index sum " << c.index_sum << "/" << r.degree << "\n";
  }
  if(r.components.size() > 10) os << "...             (" << r.components.size() - 10 << " more components)\n";
  os << "singularities   " << r.number_of_singular_faces << " faces, index sum " << r.index_sum << "/" << r.degree
     << " (n * chi = " << r.degree * chi << " on a closed mesh)\n"
     << "time            " << std::fixed << std::setprecision(1) << r.timings.total_ms << " ms (setup "
     << r.timings.setup_ms << ", factorization " << r.timings.factorization_ms << ", solve " << r.timings.solve_ms
     << ")\n";
}

void open_or_throw(std::ofstream& os, const std::string& path)
{
  os.open(path);
  if(!os) throw Usage_error("cannot write '" + path + "'");
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Options o = parse_options(argc, argv);
    const Repaired_mesh<Mesh> input = read_and_repair_mesh<Mesh>(o.mesh);
    const Mesh& mesh = input.mesh;

    std::vector<Vector_3> direction_storage(mesh.number_of_vertices(), CGAL::NULL_VECTOR);
    auto directions = CGAL::make_property_map(direction_storage);
    std::vector<std::pair<Face_index, int> > singular_faces;
    const SMDF::Direction_field_result result = SMDF::compute_globally_optimal_directions(
      mesh, directions,
      CGAL::parameters::degree(o.degree)
        .smoothness_parameter(o.s)
        .random_seed(o.seed)
        .number_of_iterations(o.max_iterations)
        .residual_tolerance(o.tolerance)
        .singularities_output_iterator(std::back_inserter(singular_faces)));

    if(!o.directions.empty())
    {
      std::ofstream os;
      open_or_throw(os, o.directions);
      os << std::setprecision(17);
      for(Vertex_index v : input.vertex_of_file_vertex)  // the file's order; a merged or duplicated vertex: its first copy
        os << directions[v].x() << " " << directions[v].y() << " " << directions[v].z() << "\n";
    }
    if(!o.singularities.empty())
    {
      std::ofstream os;
      open_or_throw(os, o.singularities);
      // per face of the file (a triangulated polygon: the sum over its triangles)
      std::map<std::size_t, int> index_of_file_face;
      for(const auto& fk : singular_faces)
        index_of_file_face[input.file_face_of_face[static_cast<std::size_t>(fk.first)]] += fk.second;
      for(const auto& fk : index_of_file_face)
        if(fk.second != 0) os << fk.first << " " << fk.second << "\n";
    }
    if(!o.png.empty())
    {
      png_snapshot::Scene scene;
      scene.degree = o.degree;
      for(Vertex_index v : mesh.vertices())
      {
        const Point_3& p = mesh.point(v);
        scene.points.push_back({p.x(), p.y(), p.z()});
        scene.directions.push_back({directions[v].x(), directions[v].y(), directions[v].z()});
      }
      for(Face_index f : mesh.faces())
      {
        std::array<std::size_t, 3> t;
        int c = 0;
        for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[c++] = v;
        scene.triangles.push_back(t);
      }
      scene.face_index.assign(mesh.number_of_faces(), 0);
      for(const auto& fk : singular_faces) scene.face_index[static_cast<std::size_t>(fk.first)] = fk.second;
      if(!png_snapshot::render(scene, o.png))
        throw Usage_error("cannot write '" + o.png + "'");
    }

    if(!o.json_file.empty())
    {
      std::ofstream os;
      open_or_throw(os, o.json_file);
      write_json(os, o, input, result);
    }
    if(o.json) write_json(std::cout, o, input, result);
    else write_summary(std::cout, o, input, result);
    return EXIT_SUCCESS;
  }
  catch(const Mesh_input_error& e)
  {
    std::cerr << "direction_field: error: " << e.what() << std::endl;
  }
  catch(const Usage_error& e)
  {
    std::cerr << "direction_field: error: " << e.what() << std::endl;
  }
  catch(const SMDF::Direction_field_error& e)
  {
    std::cerr << "direction_field: error: " << e.what() << std::endl;
  }
  catch(const std::exception& e)
  {
    std::cerr << "direction_field: error: " << e.what() << std::endl;
  }
  return EXIT_FAILURE;
}
