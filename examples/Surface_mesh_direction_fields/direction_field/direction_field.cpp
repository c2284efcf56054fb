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
//   --curvature-estimate  quadric-fit (default) or hopf (the paper's Hopf differential)
//   --feature-angle DEG   one direction follows the sharp edges (dihedral angle
//                         above DEG, CGAL's detect_sharp_edges); even n
//   --eigenvalue-bound    also compute lambda_1 for aligned fields (the JSON's
//                         eigenvalue_bound, null otherwise)
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

#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include "command_line_options.h"
#include "png_snapshot.h"
#include "read_and_repair_mesh.h"
#include "reports.h"

#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;

namespace {

// The field computed on the repaired mesh, per mesh vertex and face.
struct Computed_field
{
  explicit Computed_field(const Mesh& mesh)
    : directions(mesh.number_of_vertices(), CGAL::NULL_VECTOR), magnitudes(mesh.number_of_vertices(), 0.)
  {}
  std::vector<Vector_3> directions;
  std::vector<double> magnitudes;
  std::vector<std::pair<Face_index, int> > singular_faces;
  SMDF::Direction_field_result result;
};

void open_or_throw(std::ofstream& os, const std::string& path)
{
  os.open(path);
  if(!os) throw Usage_error("cannot write '" + path + "'");
}

// Writes `path` with writer(stream), if a path is given.
template <typename Writer>
void write_file(const std::string& path, const Writer& writer)
{
  if(path.empty()) return;
  std::ofstream os;
  open_or_throw(os, path);
  writer(os);
  if(!os) throw Usage_error("cannot write '" + path + "'");
}

// --guidance: one vector per vertex of the file, carried to the mesh's
// vertices (copies included).
std::vector<Vector_3> read_guidance(const Options& o, const Repaired_mesh<Mesh>& input)
{
  std::vector<Vector_3> guidance(input.mesh.number_of_vertices(), CGAL::NULL_VECTOR);
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
  for(Vertex_index v : input.mesh.vertices())
    guidance[std::size_t(v)] = file_guidance[input.file_vertex_of_vertex[std::size_t(v)]];
  return guidance;
}

// The library call, with the named parameters the options ask for.
void compute_field(const Options& o, const Repaired_mesh<Mesh>& input, Computed_field& field)
{
  const SMDF::Principal_curvature_alignment curvature =
    o.align == "none" ? SMDF::Principal_curvature_alignment::NONE
    : o.align == "min-curvature" ? SMDF::Principal_curvature_alignment::MINIMUM
                                 : SMDF::Principal_curvature_alignment::MAXIMUM;
  const SMDF::Boundary_alignment boundary =
    o.constrain_boundary == "tangent" ? SMDF::Boundary_alignment::TANGENT
    : o.constrain_boundary == "normal" ? SMDF::Boundary_alignment::NORMAL : SMDF::Boundary_alignment::NONE;
  const std::vector<Vector_3> guidance = o.guidance.empty() ? std::vector<Vector_3>() : read_guidance(o, input);
  auto directions = CGAL::make_property_map(field.directions);
  auto base = CGAL::parameters::degree(o.degree)
                .smoothness_parameter(o.s)
                .random_seed(o.seed)
                .number_of_iterations(o.max_iterations)
                .residual_tolerance(o.tolerance)
                .principal_curvature_alignment(curvature)
                .boundary_alignment(boundary)
                .compute_eigenvalue_bound(o.eigenvalue_bound)
                .principal_curvature_estimate(o.curvature_estimate == "hopf"
                                                ? SMDF::Principal_curvature_estimate::HOPF_DIFFERENTIAL
                                                : SMDF::Principal_curvature_estimate::QUADRIC_FIT)
                .vertex_magnitude_map(CGAL::make_property_map(field.magnitudes))
                .singularities_output_iterator(std::back_inserter(field.singular_faces));
  // --feature-angle: the edges whose faces meet at more than DEG from flat (CGAL's detection)
  std::vector<unsigned char> feature_storage(input.mesh.number_of_edges(), 0);
  auto is_feature = CGAL::make_property_map(feature_storage);
  if(o.feature_angle > 0.)
    CGAL::Polygon_mesh_processing::detect_sharp_edges(input.mesh, o.feature_angle, is_feature);
  auto with_features = [&](auto np) {
    if(o.feature_angle > 0.)
      return SMDF::compute_globally_optimal_directions(input.mesh, directions, np.edge_is_feature_map(is_feature));
    return SMDF::compute_globally_optimal_directions(input.mesh, directions, np);
  };
  auto with_guidance = [&](auto np) {
    if(o.guidance.empty()) return with_features(np);
    return with_features(np.vertex_guidance_map(CGAL::make_property_map(guidance)));
  };
  // lambda_t only when given: the library's default adapts to flat surfaces (lambda_1 = 0)
  field.result = o.weight_given ? with_guidance(base.alignment_weight(o.weight))
                 : o.lambda_given ? with_guidance(base.alignment_lambda(o.lambda)) : with_guidance(base);
}

// --directions and --singularities, in the order of the file's vertices and faces.
void write_file_order_outputs(const Options& o, const Repaired_mesh<Mesh>& input, const Computed_field& field)
{
  write_file(o.directions, [&](std::ostream& os) {
    os << std::setprecision(17);
    for(Vertex_index v : input.vertex_of_file_vertex)  // a merged or duplicated vertex: its first copy
    {
      const Vector_3& d = field.directions[std::size_t(v)];
      os << d.x() << " " << d.y() << " " << d.z() << "\n";
    }
  });
  write_file(o.singularities, [&](std::ostream& os) {
    // per face of the file (a triangulated polygon: the sum over its triangles)
    std::map<std::size_t, int> index_of_file_face;
    for(const auto& fk : field.singular_faces)
      index_of_file_face[input.file_face_of_face[static_cast<std::size_t>(fk.first)]] += fk.second;
    for(const auto& fk : index_of_file_face)
      if(fk.second != 0) os << fk.first << " " << fk.second << "\n";
  });
}

// The exchange files of the repaired mesh (IO/direction_field_files.h) and
// the field lines; returns the field lines (empty unless asked for).
std::vector<SMDF::Streamline> write_exchange_files(const Options& o, const Mesh& mesh, const Computed_field& field)
{
  std::vector<SMDF::Streamline> streamlines;
  if(o.vtk.empty() && o.ply.empty() && o.rosy.empty() && o.ffield.empty() && o.singularity_list.empty() &&
     o.streamlines.empty())
    return streamlines;
  const SMDF::Direction_field_data data = SMDF::make_direction_field_data(
    mesh, CGAL::make_property_map(field.directions), field.result, field.singular_faces,
    CGAL::parameters::vertex_magnitude_map(CGAL::make_property_map(field.magnitudes)));
  write_file(o.vtk, [&](std::ostream& os) { SMDF::IO::write_VTK(os, data); });
  write_file(o.ply, [&](std::ostream& os) { SMDF::IO::write_PLY(os, data); });
  write_file(o.rosy, [&](std::ostream& os) { SMDF::IO::write_rosy(os, data); });
  write_file(o.ffield, [&](std::ostream& os) { SMDF::IO::write_ffield(os, data); });
  write_file(o.singularity_list, [&](std::ostream& os) { SMDF::IO::write_singularities(os, data); });
  if(o.streamlines.empty()) return streamlines;
  streamlines = SMDF::trace_streamlines(data);
  write_file(o.streamlines, [&](std::ostream& os) {
    os << std::setprecision(17);
    for(const SMDF::Streamline& l : streamlines)
    {
      os << l.points.size();
      for(const auto& p : l.points) os << " " << p[0] << " " << p[1] << " " << p[2];
      os << "\n";
    }
  });
  return streamlines;
}

// --png: the shaded mesh with the field (or its lines) and the singular faces.
void write_picture(const Options& o, const Mesh& mesh, const Computed_field& field,
                   const std::vector<SMDF::Streamline>& streamlines)
{
  png_snapshot::Scene scene;
  scene.degree = o.degree;
  for(Vertex_index v : mesh.vertices())
  {
    const Point_3& p = mesh.point(v);
    const Vector_3& d = field.directions[std::size_t(v)];
    scene.points.push_back({p.x(), p.y(), p.z()});
    scene.directions.push_back({d.x(), d.y(), d.z()});
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
  for(const auto& fk : field.singular_faces) scene.face_index[static_cast<std::size_t>(fk.first)] = fk.second;
  if(!png_snapshot::render(scene, o.png))
    throw Usage_error("cannot write '" + o.png + "'");
}

} // namespace

int main(int argc, char** argv)
{
  try
  {
    const Options o = parse_options(argc, argv, CGAL::data_file_path("meshes/fandisk.off"));
    const Repaired_mesh<Mesh> input = read_and_repair_mesh<Mesh>(o.mesh);
    Computed_field field(input.mesh);
    compute_field(o, input, field);
    write_file_order_outputs(o, input, field);
    const std::vector<SMDF::Streamline> streamlines = write_exchange_files(o, input.mesh, field);
    if(!o.png.empty()) write_picture(o, input.mesh, field, streamlines);
    write_file(o.json_file, [&](std::ostream& os) { write_json(os, o, input, field.result); });
    if(o.json) write_json(std::cout, o, input, field.result);
    else write_summary(std::cout, o, input, field.result);
    return EXIT_SUCCESS;
  }
  catch(const std::exception& e)  // bad input, bad options, unwritable outputs: one line
  {
    std::cerr << "direction_field: error: " << e.what() << std::endl;
  }
  return EXIT_FAILURE;
}
