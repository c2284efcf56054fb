// direction_field: the command-line program of Surface_mesh_direction_fields.
//
//   direction_field [MESH] [--degree N] [--s S] [--directions FILE]
//                   [--singularities FILE] [--json] [--png FILE]
//                   [--json-file FILE] [--seed N] [--max-iterations N] [--tolerance T]
//                   [--align none|curvature|min-curvature|max-curvature] [--guidance FILE]
//                   [--lambda L | --alignment-weight T] [--constrain-boundary tangent|normal]
//                   [--vtk FILE] [--ply FILE] [--rosy FILE] [--ffield FILE] [--singularity-list FILE]
//                   [--streamlines FILE]
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
//   --align ...           guidance by the principal curvatures (even degrees):
//                         curvature = max-curvature (for n = 4 both at once)
//   --guidance FILE       guidance by a vector field, one "x y z" per vertex of the
//                         file (length = weight, zero = no preference)
//   --lambda L            the lambda_t of (A - lambda_t M) u = M q (default 0)
//   --alignment-weight T  or the alignment weight t in (0, 1) to reach
//   --constrain-boundary  fix one direction tangent (or normal) to the boundary
//   --png FILE            a picture of the field (shaded mesh, directions,
//                         singular faces in red (+) and blue (-))
//   The next files describe the repaired mesh (its vertices and triangles),
//   written by CGAL/Surface_mesh_direction_fields/IO/direction_field_files.h:
//   --vtk FILE            legacy VTK PolyData for ParaView: all n directions,
//                         the magnitude, the singularities as points with their index
//   --ply FILE            PLY with per-vertex direction (dx dy dz) and magnitude,
//                         per-face singularity integer k
//   --rosy FILE           the field moved to the faces, as read by vcglib/QuadWild
//   --ffield FILE         the same as a per-face frame file (vcglib's .ffield)
//   --singularity-list FILE  one line "face k n x y z" per singular face
//   --streamlines FILE    field lines of the per-face field (streamlines.h), one
//                         polyline per line: "N x1 y1 z1 ... xN yN zN" (CGAL's
//                         polylines text format); with --png they are drawn
//                         instead of the direction glyphs
// Exit status 0 on success; otherwise 1, with one line on stderr.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/IO/direction_field_files.h>
#include <CGAL/Surface_mesh_direction_fields/streamlines.h>

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
  std::string vtk, ply, rosy, ffield, singularity_list, streamlines;
  bool json = false;
  unsigned int seed = 0;
  unsigned int max_iterations = 1000;
  double tolerance = 1e-10;
  std::string align = "none", guidance, constrain_boundary = "none";
  bool lambda_given = false, weight_given = false;
  double lambda = 0., weight = 0.5;
};

// A problem with the input or the options: reported on one line, exit status 1.
struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };

const char* const usage =
  "usage: direction_field [MESH] [--degree N] [--s S] [--directions FILE] [--singularities FILE]\n"
  "                       [--json] [--json-file FILE] [--png FILE] [--seed N] [--max-iterations N]\n"
  "                       [--tolerance T] [--align none|curvature|min-curvature|max-curvature]\n"
  "                       [--guidance FILE] [--lambda L | --alignment-weight T]\n"
  "                       [--constrain-boundary tangent|normal]\n"
  "                       [--vtk FILE] [--ply FILE] [--rosy FILE] [--ffield FILE] [--singularity-list FILE]\n"
  "                       [--streamlines FILE]\n";

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
    else if(a == "--align") o.align = value();
    else if(a == "--guidance") o.guidance = value();
    else if(a == "--lambda") { o.lambda = parse_number<double>(a, value()); o.lambda_given = true; }
    else if(a == "--alignment-weight") { o.weight = parse_number<double>(a, value()); o.weight_given = true; }
    else if(a == "--constrain-boundary") o.constrain_boundary = value();
    else if(a == "--vtk") o.vtk = value();
    else if(a == "--ply") o.ply = value();
    else if(a == "--rosy") o.rosy = value();
    else if(a == "--ffield") o.ffield = value();
    else if(a == "--singularity-list") o.singularity_list = value();
    else if(a == "--streamlines") o.streamlines = value();
    else if(!a.empty() && a[0] == '-' && a != "-") throw Usage_error("unknown option " + a);
    else if(o.mesh.empty()) o.mesh = a;
    else throw Usage_error("more than one mesh given ('" + o.mesh + "' and '" + a + "')");
  }
  if(o.mesh.empty())
    o.mesh = CGAL::data_file_path("meshes/fandisk.off");
  if(o.align != "none" && o.align != "curvature" && o.align != "min-curvature" && o.align != "max-curvature")
    throw Usage_error("--align expects none, curvature, min-curvature or max-curvature, got '" + o.align + "'");
  if(o.constrain_boundary != "none" && o.constrain_boundary != "tangent" && o.constrain_boundary != "normal")
    throw Usage_error("--constrain-boundary expects tangent or normal, got '" + o.constrain_boundary + "'");
  if(o.lambda_given && o.weight_given)
    throw Usage_error("give either --lambda or --alignment-weight, not both");
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

// The largest component: the one whose lambda and t the JSON reports.
const SMDF::Component_report& main_component(const SMDF::Direction_field_result& r)
{
  std::size_t best = 0;
  for(std::size_t i = 1; i < r.components.size(); ++i)
    if(r.components[i].number_of_vertices > r.components[best].number_of_vertices) best = i;
  return r.components[best];
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
     << ",\"lambda\":" << number(main_component(r).lambda)
     << ",\"alignment_weight\":" << number(main_component(r).alignment_weight)
     << ",\"eigenvalue_bound\":" << number(main_component(r).eigenvalue)
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
  if(main_component(r).alignment_weight > 0. || main_component(r).lambda != 0.)
    os << "alignment       lambda_t = " << main_component(r).lambda << " (bound lambda_1 = " << main_component(r).eigenvalue
       << "), alignment weight t = " << main_component(r).alignment_weight << "\n";
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
    std::vector<double> magnitude_storage(mesh.number_of_vertices(), 0.);
    std::vector<std::pair<Face_index, int> > singular_faces;
    // guidance vectors of the file's vertices, carried to the mesh's (copies included)
    std::vector<Vector_3> guidance(mesh.number_of_vertices(), CGAL::NULL_VECTOR);
    if(!o.guidance.empty())
    {
      std::ifstream in(o.guidance);
      if(!in) throw Usage_error("cannot open '" + o.guidance + "'");
      std::vector<Vector_3> file_guidance;
      std::string line;
      while(std::getline(in, line))
      {
        if(line.find_first_not_of(" \t\r") == std::string::npos) continue;
        std::istringstream is(line);
        double x, y, z;
        if(!(is >> x >> y >> z) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
          throw Usage_error("line " + std::to_string(file_guidance.size() + 1) + " of '" + o.guidance +
                            "' is not three finite numbers");
        file_guidance.emplace_back(x, y, z);
      }
      if(file_guidance.size() != input.file_vertices)
        throw Usage_error("'" + o.guidance + "' has " + std::to_string(file_guidance.size()) + " vectors for " +
                          std::to_string(input.file_vertices) + " vertices");
      for(Vertex_index v : mesh.vertices())
        guidance[std::size_t(v)] = file_guidance[input.file_vertex_of_vertex[std::size_t(v)]];
    }
    const SMDF::Principal_curvature_alignment curvature =
      o.align == "none" ? SMDF::Principal_curvature_alignment::NONE
      : o.align == "min-curvature" ? SMDF::Principal_curvature_alignment::MINIMUM
                                   : SMDF::Principal_curvature_alignment::MAXIMUM;
    const SMDF::Boundary_alignment boundary =
      o.constrain_boundary == "tangent" ? SMDF::Boundary_alignment::TANGENT
      : o.constrain_boundary == "normal" ? SMDF::Boundary_alignment::NORMAL : SMDF::Boundary_alignment::NONE;
    auto base = CGAL::parameters::degree(o.degree)
                  .smoothness_parameter(o.s)
                  .random_seed(o.seed)
                  .number_of_iterations(o.max_iterations)
                  .residual_tolerance(o.tolerance)
                  .principal_curvature_alignment(curvature)
                  .boundary_alignment(boundary)
                  .vertex_magnitude_map(CGAL::make_property_map(magnitude_storage))
                  .singularities_output_iterator(std::back_inserter(singular_faces));
    auto with_guidance = [&](auto np) {
      if(o.guidance.empty())
        return SMDF::compute_globally_optimal_directions(mesh, directions, np);
      return SMDF::compute_globally_optimal_directions(mesh, directions,
                                                       np.vertex_guidance_map(CGAL::make_property_map(guidance)));
    };
    // lambda_t only when given: the library's default adapts to flat surfaces (lambda_1 = 0)
    const SMDF::Direction_field_result result =
      o.weight_given ? with_guidance(base.alignment_weight(o.weight))
      : o.lambda_given ? with_guidance(base.alignment_lambda(o.lambda)) : with_guidance(base);
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
    std::vector<SMDF::Streamline> streamlines;
    if(!o.vtk.empty() || !o.ply.empty() || !o.rosy.empty() || !o.ffield.empty() || !o.singularity_list.empty() ||
       !o.streamlines.empty())
    {
      namespace SIO = SMDF::IO;
      const SIO::Direction_field_data data = SIO::make_direction_field_data(
        mesh, directions, o.degree, singular_faces,
        CGAL::parameters::vertex_magnitude_map(CGAL::make_property_map(magnitude_storage)));
      auto write = [](const std::string& path, auto writer) {
        if(path.empty()) return;
        std::ofstream os;
        open_or_throw(os, path);
        writer(os);
        if(!os) throw Usage_error("cannot write '" + path + "'");
      };
      write(o.vtk, [&](std::ostream& os) { SIO::write_VTK(os, data); });
      write(o.ply, [&](std::ostream& os) { SIO::write_PLY(os, data); });
      write(o.rosy, [&](std::ostream& os) { SIO::write_rosy(os, data); });
      write(o.ffield, [&](std::ostream& os) { SIO::write_ffield(os, data); });
      write(o.singularity_list, [&](std::ostream& os) { SIO::write_singularities(os, data); });
      if(!o.streamlines.empty())
      {
        streamlines = SMDF::trace_streamlines(data);
        write(o.streamlines, [&](std::ostream& os) {
          os << std::setprecision(17);
          for(const SMDF::Streamline& l : streamlines)
          {
            os << l.points.size();
            for(const auto& p : l.points) os << " " << p[0] << " " << p[1] << " " << p[2];
            os << "\n";
          }
        });
      }
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
      for(const SMDF::Streamline& l : streamlines) scene.polylines.push_back(l.points);
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
