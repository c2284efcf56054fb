// direction_field: the command-line program of Surface_mesh_direction_fields.
//
// Computes the globally smoothest (or aligned) n-direction field of a mesh
// (OFF, OBJ, PLY or STL) and its singular faces, and writes what the options
// ask for. The options, their defaults and the files written are described
// once, in command_line_options.h (printed by --help) and in README.md. The
// contract of the options, the output files and the JSON keys is relied upon
// by other programs: it is only ever extended.
//
// main() is a sequence of steps: options, outputs tried (output_files.h),
// mesh read (read_polygon_soup.h) and repaired (read_and_repair_mesh.h), the
// library call, outputs written, then all renamed into place at once.
// Exit status 0 on success; otherwise 1, with one line on stderr.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Surface_mesh_direction_fields/feature_edges.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include "command_line_options.h"
#include "exchange_files.h"
#include "face_field_run.h"
#include "guidance_file.h"
#include "file_io/optional_named_parameters.h"
#include "huge_pages_rerun.h"
#include "process_start.h"
#include "file_io/output_files.h"
#include "progress.h"
#include "png_snapshot.h"
#include "point_set_run.h"
#include "file_io/read_and_repair_mesh.h"
#include "reports.h"

#ifdef SMDF_WITH_PETSC
#include <CGAL/Surface_mesh_direction_fields/Petsc_distributed_solver.h>
#endif
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
#include <SuiteSparse_config.h>
#endif

#include <csignal>
#include <cstdio>
#include <cstdlib>
#if defined(__unix__) || defined(__APPLE__)
#include <sys/resource.h>
#endif
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <array>
#include <algorithm>
#include <map>
#include <memory>
#include <regex>
#include <sstream>
#include <string>
#include <functional>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;
namespace onp = optional_named_parameters;

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
  std::vector<std::array<std::size_t, 2> > features;  // of --feature-angle, for the picture
  SMDF::Direction_field_result result;
};

// --guidance: one vector per vertex of the file, carried to the mesh's
// vertices (copies included).
std::vector<Vector_3> read_guidance(const Options& o, const Repaired_mesh<Mesh>& input)
{
  const std::vector<std::array<double, 3> > file_guidance =
    read_guidance_file(o.guidance, input.file_vertices, "vertices");
  std::vector<Vector_3> guidance(input.mesh.number_of_vertices(), CGAL::NULL_VECTOR);
  for(Vertex_index v : input.mesh.vertices())
  {
    const std::array<double, 3>& g = file_guidance[input.file_vertex_of_vertex[std::size_t(v)]];
    guidance[std::size_t(v)] = Vector_3(g[0], g[1], g[2]);
  }
  return guidance;
}

// --prescribe, as --singularities writes it: 'f k' per singular face of the
// file, '# loop l t' per loop along which the field turns t times other than
// the nearest choice (a comment to readers of 'f k' lines, numpy.loadtxt's
// included), each face and loop once; blank lines and other lines starting
// with '#' are skipped.
struct Prescription
{
  std::vector<std::pair<Face_index, int> > faces;   // of the repaired mesh: a polygon's k on its first triangle
  std::vector<std::pair<std::size_t, int> > loop_turns;
};

// A whole token as an integer: digits, with a sign if `signed_number`.
bool read_integer(const std::string& token, bool signed_number, long long& value)
{
  const std::size_t first = signed_number && !token.empty() && (token[0] == '-' || token[0] == '+') ? 1 : 0;
  if(token.size() == first || token.size() > first + 18 ||
     token.find_first_not_of("0123456789", first) != std::string::npos)
    return false;
  value = std::stoll(token.substr(first)) * (token[0] == '-' ? -1 : 1);
  return true;
}

// One line 'f k' or '# loop l t' into k_of_file_face or loop_turns (other
// comments skipped); with `on_vertices`, 'v k' lines of --on faces (no loop).
void read_prescription_line(const std::string& line, const std::string& where, std::size_t file_faces,
                            std::map<std::size_t, int>& k_of_file_face, std::map<std::size_t, int>& loop_turns,
                            bool on_vertices = false)
{
  const std::string element = on_vertices ? "vertex" : "face";
  std::istringstream is(line);
  std::string first, second, rest;
  if(!(is >> first)) return;  // white space only
  const bool comment = first[0] == '#';
  if(comment && first.size() > 1) first.erase(0, 1);  // "#loop"
  else if(comment && !(is >> first)) return;
  const bool loop = comment && first == "loop";
  if(comment && !loop) return;
  if(loop) is >> first;
  is >> second;
  long long number, k;
  if(!read_integer(first, false, number) || !read_integer(second, true, k) || (is >> rest))
    throw Usage_error(where + (on_vertices ? " is not 'v k' (a vertex and its index, two integers)"
                                           : " is not 'f k' (a face and its index, two integers) or '# loop l t'"));
  if(loop && on_vertices)
    throw Usage_error(where + ": loop turns apply to fields on vertices (a field on faces takes the nearest turns)");
  if(k < -1000000 || k > 1000000) throw Usage_error(where + ": " + std::to_string(k) + " is out of range");
  if(loop && !loop_turns.emplace(std::size_t(number), int(k)).second)
    throw Usage_error(where + ": loop " + std::to_string(number) + " is listed twice");
  if(loop) return;
  if(static_cast<unsigned long long>(number) >= file_faces)
    throw Usage_error(where + ": " + element + " " + std::to_string(number) + " is not a " + element +
                      " of the mesh (it has " + std::to_string(file_faces) + ")");
  if(!k_of_file_face.emplace(std::size_t(number), int(k)).second)
    throw Usage_error(where + ": " + element + " " + std::to_string(number) + " is listed twice");
}

// Only interior vertices of a field on faces have an index: any other named
// with a k is refused at its line of the file.
void check_prescribed_vertex(const Mesh& mesh, const std::pair<std::size_t, int>& vk, const std::string& where)
{
  const Vertex_index v(static_cast<Mesh::size_type>(vk.first));
  if(vk.second == 0) return;
  if(mesh.is_isolated(v))
    throw Usage_error(where + ": vertex " + std::to_string(vk.first) + " belongs to no face");
  if(mesh.is_border(v))
    throw Usage_error(where + ": vertex " + std::to_string(vk.first) + " is on the boundary, where a field on "
                      "faces has no index (the boundary's turning is its component's boundary index)");
}

// --prescribe with --on faces: 'v k' per singular vertex, numbered as
// --mesh-out and --singularities number them (the repaired mesh's vertices).
std::vector<std::pair<Vertex_index, int> > read_vertex_prescription(const Options& o, const Mesh& mesh)
{
  std::istringstream in(text_file(o.prescribe, "a prescription file"));
  std::map<std::size_t, int> k_of_vertex, no_loops;
  std::string line;
  for(std::size_t number = 1; std::getline(in, line); ++number)
  {
    if(line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = "line " + std::to_string(number) + " of '" + o.prescribe + "'";
    std::map<std::size_t, int> of_line;
    read_prescription_line(line, where, mesh.number_of_vertices(), of_line, no_loops, true);
    for(const auto& vk : of_line)
    {
      if(!k_of_vertex.emplace(vk).second)
        throw Usage_error(where + ": vertex " + std::to_string(vk.first) + " is listed twice");
      check_prescribed_vertex(mesh, vk, where);
    }
  }
  std::vector<std::pair<Vertex_index, int> > prescription;
  for(const auto& vk : k_of_vertex)
    if(vk.second != 0) prescription.emplace_back(Vertex_index(static_cast<Mesh::size_type>(vk.first)), vk.second);
  return prescription;
}

Prescription read_prescription(const Options& o, const Repaired_mesh<Mesh>& input)
{
  std::istringstream in(text_file(o.prescribe, "a prescription file"));
  std::vector<Face_index> first_triangle(input.file_faces, Face_index());
  for(Face_index f : input.mesh.faces())
  {
    Face_index& first = first_triangle[input.file_face_of_face[std::size_t(f)]];
    if(first == Face_index()) first = f;
  }
  std::map<std::size_t, int> k_of_file_face, loop_turns;
  std::string line;
  for(std::size_t number = 1; std::getline(in, line); ++number)
  {
    if(line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string where = "line " + std::to_string(number) + " of '" + o.prescribe + "'";
    read_prescription_line(line, where, input.file_faces, k_of_file_face, loop_turns);
  }
  Prescription prescription;
  for(const auto& fk : k_of_file_face)
  {
    if(fk.second == 0) continue;
    if(first_triangle[fk.first] == Face_index())
      throw Usage_error("face " + std::to_string(fk.first) + " of '" + o.prescribe +
                        "' was removed by the repair (degenerate or repeated)");
    prescription.faces.emplace_back(first_triangle[fk.first], fk.second);
  }
  prescription.loop_turns.assign(loop_turns.begin(), loop_turns.end());
  return prescription;
}

// An error of the library about faces of the repaired mesh ("face 12"),
// naming the file's faces instead (the numbering of --prescribe and
// --singularities).
std::string in_file_numbering(const SMDF::Invalid_input_error& e, const Repaired_mesh<Mesh>& input)
{
  const std::string what = e.what();
  if(!e.has_face()) return what;
  static const std::regex mesh_face("face ([0-9]{1,18})");
  std::string named;
  std::size_t done = 0;
  for(auto it = std::sregex_iterator(what.begin(), what.end(), mesh_face); it != std::sregex_iterator(); ++it)
  {
    const std::size_t f = std::stoull((*it)[1].str());
    if(f >= input.file_face_of_face.size()) continue;
    named += what.substr(done, static_cast<std::size_t>(it->position()) - done) + "face " +
             std::to_string(input.file_face_of_face[f]) + " of the file";
    done = static_cast<std::size_t>(it->position() + it->length());
  }
  return named + what.substr(done);
}

// --solver petsc: MPI, PETSc and SLEPc for the whole run. The first process
// runs the program; the others serve its requests (assembly and solves of the
// large components) until it has computed the field, then return.
class Processes
{
public:
  explicit Processes(const Options& o)
  {
#ifdef SMDF_WITH_PETSC
    if(o.solver != "petsc") return;
    if(SlepcInitializeNoArguments() != 0) throw Usage_error("--solver petsc: PETSc (MPI) could not start");
    m_petsc = true;
    // PETSc's errors are reported in one line by the failing process, which
    // then ends every process (petsc_calls.h): no trace from inside PETSc
    if(PetscPushErrorHandler(SMDF::Petsc_distributed_solver::error_handler, nullptr) != 0)
      throw Usage_error("--solver petsc: PETSc's error handler could not be set");
    if(PetscOptionsInsertString(nullptr, o.petsc_options.c_str()) != 0)
      throw Usage_error("--petsc-options: PETSc does not accept '" + o.petsc_options + "'");
    m_solver.reset(new SMDF::Petsc_distributed_solver(PETSC_COMM_WORLD, o.distribute_from));
    m_rank = m_solver->is_first_process() ? 0 : 1;
    m_size = m_solver->number_of_processes();
#else
    (void)o;
#endif
  }
  ~Processes()
  {
#ifdef SMDF_WITH_PETSC
    if(m_solver && m_rank == 0) m_solver->finish();  // the others return from serve()
    m_solver.reset();
    if(m_petsc) SlepcFinalize();  // after an error: its own failure adds nothing
#endif
  }
  // Ends PETSc once the field is computed, before any output is committed:
  // what PETSc does at its end (writing -log_view's file, for one) can fail,
  // and then the run fails.
  void finish()
  {
#ifdef SMDF_WITH_PETSC
    if(!m_petsc) return;
    if(m_solver && m_rank == 0) m_solver->finish();
    m_solver.reset();
    m_petsc = false;
    if(SlepcFinalize() != 0)
      throw std::runtime_error("PETSc failed at its end (an option such as -log_view could not write its file?)");
#endif
  }
  Processes(const Processes&) = delete;
  Processes& operator=(const Processes&) = delete;

  bool writes() const { return m_rank == 0; }
  int size() const { return m_size; }
  // Every process but the first: its share of the first one's requests.
  void serve() const
  {
#ifdef SMDF_WITH_PETSC
    if(m_solver && m_rank != 0) m_solver->serve();
#endif
  }
#ifdef SMDF_WITH_PETSC
  const SMDF::Petsc_distributed_solver& distributed_solver() const { return *m_solver; }
#endif

private:
  bool m_petsc = false;
  int m_rank = 0, m_size = 1;
#ifdef SMDF_WITH_PETSC
  std::unique_ptr<SMDF::Petsc_distributed_solver> m_solver;
#endif
};

// The library call, with the named parameters the options ask for.
void compute_field(const Options& o, const Repaired_mesh<Mesh>& input, const Processes& processes,
                   Progress& progress, Computed_field& field)
{
  const std::vector<Vector_3> guidance = o.guidance.empty() ? std::vector<Vector_3>() : read_guidance(o, input);
  auto directions = CGAL::make_property_map(field.directions);
  auto base = CGAL::parameters::degree(o.degree)
                .smoothness_parameter(o.s)
                .random_seed(o.seed)
                .number_of_iterations(o.max_iterations)
                .residual_tolerance(o.tolerance)
                .principal_curvature_alignment(curvature_alignment(o))
                .boundary_alignment(face_field_run::boundary_alignment(o))
                .compute_eigenvalue_bound(o.eigenvalue_bound)
                .principal_curvature_estimate(o.curvature_estimate == "hopf"
                                                ? SMDF::Principal_curvature_estimate::HOPF_DIFFERENTIAL
                                                : SMDF::Principal_curvature_estimate::QUADRIC_FIT)
                .vertex_magnitude_map(CGAL::make_property_map(field.magnitudes))
                .singularities_output_iterator(std::back_inserter(field.singular_faces))
                .progress_callback(std::function<bool(double)>([&progress](double f) { return progress.fraction(f); }));
  // --feature-angle: the edges whose faces meet at more than DEG from flat
  std::vector<unsigned char> feature_storage(input.mesh.number_of_edges(), 0);
  auto is_feature = CGAL::make_property_map(feature_storage);
  if(o.feature_angle > 0.)
    SMDF::detect_feature_edges(input.mesh, o.feature_angle, is_feature,
                               CGAL::parameters::feature_cleanup_steps(o.feature_cleanup));
  const Prescription prescription = o.prescribe.empty() ? Prescription() : read_prescription(o, input);
  onp::Given_options<Face_index, decltype(CGAL::make_property_map(guidance)), decltype(is_feature)> given;
  // lambda_t only when given: the library's default adapts to flat surfaces (lambda_1 = 0)
  if(o.weight_given) given.alignment_weight = o.weight;
  else if(o.lambda_given) given.alignment_lambda = o.lambda;
  if(!o.guidance.empty()) given.guidance = CGAL::make_property_map(guidance);
  if(o.feature_angle > 0.) given.features = is_feature;
  for(auto e : input.mesh.edges())
    if(feature_storage[e]) field.features.push_back({input.mesh.source(input.mesh.halfedge(e)), input.mesh.target(input.mesh.halfedge(e))});
  if(!o.prescribe.empty())
  {
    given.prescribed = &prescription.faces;
    given.loop_turns = &prescription.loop_turns;
  }
  auto compute = [&](auto np) {
#ifdef SMDF_WITH_PETSC
    if(o.solver == "petsc" && o.prescribe.empty())  // a prescription: one process (checked)
      return SMDF::compute_globally_optimal_directions(input.mesh, directions,
                                                       np.distributed_solver(processes.distributed_solver()));
#endif
    (void)processes;
    return SMDF::compute_globally_optimal_directions(input.mesh, directions, np);
  };
  try
  {
    field.result = onp::compute_with(given, base, compute);
  }
  catch(const SMDF::Invalid_input_error& e)
  {
    throw Usage_error(in_file_numbering(e, input));
  }
}

// --directions and --singularities, in the order of the file's vertices and faces.
void write_file_order_outputs(const Options& o, const Repaired_mesh<Mesh>& input, const Computed_field& field,
                              Output_files& outputs)
{
  if(!o.directions.empty())
  {
    std::vector<std::array<double, 3> > in_file_order;
    in_file_order.reserve(input.vertex_of_file_vertex.size());
    for(Vertex_index v : input.vertex_of_file_vertex)  // a merged or duplicated vertex: its first copy
    {
      if(v == Mesh::null_vertex())  // a point no face uses: the zero vector
      {
        in_file_order.push_back({0., 0., 0.});
        continue;
      }
      const Vector_3& d = field.directions[std::size_t(v)];
      in_file_order.push_back({d.x(), d.y(), d.z()});
    }
    SMDF::IO::write_vectors(outputs.stream(o.directions), in_file_order);
  }
  if(!o.singularities.empty())
  {
    // per face of the file (a triangulated polygon: the sum over its triangles)
    std::map<std::size_t, long long> index_of_file_face;
    for(const auto& fk : field.singular_faces)
      index_of_file_face[input.file_face_of_face[static_cast<std::size_t>(fk.first)]] += fk.second;
    std::ostream& os = outputs.stream(o.singularities);
    for(const auto& fk : index_of_file_face)
      if(fk.second != 0) os << fk.first << " " << fk.second << "\n";
    for(const auto& lt : field.result.loop_turns) os << "# loop " << lt.first << " " << lt.second << "\n";
  }
}

// --png: the shaded mesh with the field (or its lines) and the singular faces.
void write_picture(const Options& o, const Mesh& mesh, const Computed_field& field,
                   const std::vector<SMDF::Streamline>& streamlines, Output_files& outputs)
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
  scene.feature_edges = field.features;
  png_snapshot::render(scene, outputs.stream(o.png));
}

// Every output path of the options, tried before the mesh is read.
void register_outputs(const Options& o, Output_files& outputs)
{
  const std::pair<const char*, const std::string*> paths[] = {
    {"--directions", &o.directions}, {"--singularities", &o.singularities}, {"--json-file", &o.json_file},
    {"--png", &o.png}, {"--vtk", &o.vtk}, {"--vtk-singularities", &o.vtk_singularities}, {"--ply", &o.ply}, {"--rosy", &o.rosy}, {"--ffield", &o.ffield},
    {"--singularity-list", &o.singularity_list}, {"--streamlines", &o.streamlines}, {"--mesh-out", &o.mesh_out},
    {"--sharp", &o.sharp}, {"--rawfield", &o.rawfield}, {"--sing", &o.sing}, {"--matching", &o.matching}};
  const Input_files inputs = {{"input mesh", o.mesh}, {"--guidance", o.guidance}, {"--prescribe", o.prescribe}};
  for(const auto& input : inputs)  // the same spelling, before the file exists
    for(const auto& p : paths)
      if(!input.second.empty() && *p.second == input.second)
        throw Usage_error(std::string(p.first) + " would overwrite the " + input.first + " file");
  for(const auto& p : paths) outputs.add(p.first, *p.second, inputs);
}

// What the computation did, on stderr while running; a solve that stopped
// before its tolerance is said there even with --quiet.
void report_computation(const Progress& progress, const SMDF::Direction_field_result& r)
{
  std::ostringstream line;
  line << "setup " << compact(r.timings.setup_ms) << " ms, factorization " << compact(r.timings.factorization_ms)
       << " ms, solve " << compact(r.timings.solve_ms) << " ms: ";
  if(r.prescribed) line << "prescribed singularities, holonomy error " << compact(r.holonomy_error);
  else line << r.iterations << " iterations, residual " << compact(r.residual);
  progress.say(line.str());
  if(!r.converged)
    std::cerr << "direction_field: warning: the eigen-solve stopped after " << r.iterations
              << " iterations with residual " << compact(r.residual) << ", above the tolerance" << std::endl;
}

// The summary or the JSON on stdout, checked.
void write_report(const Options& o, const Repaired_mesh<Mesh>& input, const SMDF::Direction_field_result& r,
                  const Left_out_outputs& left_out, const Program_timings& timings, int ranks)
{
  if(o.json) write_json(std::cout, o, input, r, left_out, timings, ranks);
  else if(!o.quiet) write_summary(std::cout, o, input, r, left_out, timings, ranks);
  std::cout.flush();
  if(!std::cout) throw Usage_error("cannot write to standard output");
}

// The rank a launcher (Open MPI's, MPICH's or Slurm's) gave this process in
// its environment, or nullptr outside a launcher.
const char* launcher_rank()
{
  for(const char* variable : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "SLURM_PROCID"})
    if(const char* rank = std::getenv(variable)) return rank;
  return nullptr;
}

// Under mpirun every process parses the options before MPI starts, so a bad
// option fails on all of them: only the first says it.
bool is_first_launched_process()
{
  const char* rank = launcher_rank();
  return rank == nullptr || std::string(rank) == "0";
}

void report_out_of_memory(Progress& progress)
{
  const std::string step = progress.step();
  progress.interrupt();
  std::cerr << "direction_field: error: out of memory" << (step.empty() ? "" : " while " + step) << std::endl;
}

// The point each vertex copies, for the field on faces: with --non-manifold
// glue, the file's vertex where the repair cut the mesh (a non-manifold edge
// or vertex), else the vertex itself (nothing glued).
std::vector<std::size_t> points_of_vertices(const Options& o, const Repaired_mesh<Mesh>& input)
{
  const bool glue = input.report.duplicated_vertices > 0 && o.non_manifold == "glue";
  std::vector<std::size_t> points(input.mesh.number_of_vertices());
  for(std::size_t v = 0; v < points.size(); ++v) points[v] = glue ? input.file_vertex_of_vertex[v] : v;
  return points;
}

// --on faces: the field on the faces, its files and its report.
int run_on_faces(const Options& o, const Repaired_mesh<Mesh>& input, Progress& progress, Program_timings& timings,
                 Output_files& outputs)
{
  face_field_run::Face_field field;
  double compute_ms = 0.;
  progress.begin("computing the field on faces", compute_ms);
  try
  {
    const std::vector<std::pair<Vertex_index, int> > prescription =
      o.prescribe.empty() ? std::vector<std::pair<Vertex_index, int> >() : read_vertex_prescription(o, input.mesh);
    field = face_field_run::compute(o, input.mesh, points_of_vertices(o, input),
                                    o.prescribe.empty() ? nullptr : &prescription,
                                    [&progress](double done) { return progress.fraction(done); });
  }
  catch(const SMDF::Invalid_input_error& e)
  {
    if(std::string(e.what()).find("non-manifold edges are glued") != std::string::npos)  // the library's refusal
      throw Usage_error(std::string(o.prescribe.empty() ? "--cancel-singularities" : "--prescribe") +
                        " on a mesh with non-manifold edges needs --non-manifold cut");
    throw Usage_error(in_file_numbering(e, input));
  }
  progress.end();
  if(field.result.number_of_non_principal_jumps > 0 && (!o.rosy.empty() || !o.ffield.empty()))
    std::cerr << "direction_field: warning: the field turns by pi/n or more across "
              << field.result.number_of_non_principal_jumps << " edges, where readers that recompute the matching "
              << "from the directions (--rosy, --ffield) find other singular vertices; --matching carries it"
              << std::endl;
  if(!field.result.converged)
    std::cerr << "direction_field: warning: the eigen-solve stopped after " << field.result.iterations
              << " iterations with residual " << compact(field.result.residual) << ", above the tolerance" << std::endl;
  progress.begin("writing", timings.write);
  if(!o.mesh_out.empty()) exchange_files::write_mesh(o.mesh_out, outputs.stream(o.mesh_out), input.mesh);
  face_field_run::write_files(o, field, outputs);
  const std::vector<SMDF::Streamline> lines = face_field_run::write_streamlines(o, field, outputs);
  if(!o.png.empty()) face_field_run::write_picture(o, field, lines, outputs);
  outputs.close_all_except(o.json_file);
  progress.end();
  if(!o.json_file.empty())
  {
    face_field_run::write_json(outputs.stream(o.json_file), o, input, field, outputs, timings);
    outputs.close(o.json_file);
  }
  if(o.json) face_field_run::write_json(std::cout, o, input, field, outputs, timings);
  else if(!o.quiet) face_field_run::write_summary(std::cout, o, input, field);
  std::cout.flush();
  if(!std::cout) throw Usage_error("cannot write to standard output");
  outputs.commit();
  return EXIT_SUCCESS;
}

} // namespace

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
// CHOLMOD prints its messages with printf; standard output holds the report
// (the JSON of --json) alone.
int print_to_stderr(const char* format, ...)
{
  va_list arguments;
  va_start(arguments, format);
  const int written = std::vfprintf(stderr, format, arguments);
  va_end(arguments);
  return written;
}
#endif

static int run(int argc, char** argv)
{
  std::signal(SIGPIPE, SIG_IGN);  // a closed standard output is a write error (output_files.h)
  Progress progress(true);
  try
  {
    const Options o = parse_options(argc, argv, [] { return CGAL::data_file_path("meshes/fandisk.off"); });
    if(o.huge_pages != "off" && launcher_rank() == nullptr) rerun_with_huge_pages(argv, o.mesh, o.huge_pages);
    Processes processes(o);
    if(!processes.writes())
    {
      processes.serve();
      processes.finish();
      return EXIT_SUCCESS;
    }
    Output_files outputs;
    register_outputs(o, outputs);
    exchange_files::check_mesh_out_name(o.mesh_out);
    exchange_files::warn_about_vtk_names(o.vtk, o.vtk_singularities);
    progress = Progress(o.quiet);
    Program_timings timings;
    if(point_set_run::is_point_set_file(o.mesh)) return point_set_run::run(o, progress, timings, outputs);
    progress.begin("reading " + o.mesh, timings.read);
    Polygon_soup soup = read_polygon_soup(o.mesh);
    progress.end();
    if(soup.number_of_polygons() == 0 && !soup.points.empty() && point_set_run::extension_of(o.mesh) == "ply")
      return point_set_run::run(o, progress, timings, outputs, &soup);
    progress.begin("repairing", timings.repair);
    const Repaired_mesh<Mesh> input = repair_into_mesh<Mesh>(soup, "'" + o.mesh + "'");
    soup = Polygon_soup();
    progress.end();
    if(o.on == "faces") return run_on_faces(o, input, progress, timings, outputs);
    Computed_field field(input.mesh);
    double compute_ms = 0.;
    progress.begin("computing the field", compute_ms);
    compute_field(o, input, processes, progress, field);
    processes.finish();
    progress.end();
    report_computation(progress, field.result);
    progress.begin("writing", timings.write);
    write_file_order_outputs(o, input, field, outputs);
    const std::vector<SMDF::Streamline> streamlines = write_exchange_files(o, input.mesh, field.directions,
                                                                           field.magnitudes, field.singular_faces,
                                                                           field.result, outputs);
    if(!o.png.empty()) write_picture(o, input.mesh, field, streamlines, outputs);
    if(!o.sharp.empty())
    {
      std::vector<unsigned char> is_feature;
      SMDF::IO::write_sharp(outputs.stream(o.sharp), face_field_run::field_data(input.mesh, o.degree),
                            face_field_run::feature_edges(o, input.mesh, is_feature));
    }
    outputs.close_all_except(o.json_file);
    progress.end();
    if(!o.json_file.empty())
    {
      write_json(outputs.stream(o.json_file), o, input, field.result, outputs.left_out(), timings, processes.size());
      outputs.close(o.json_file);
    }
    write_report(o, input, field.result, outputs.left_out(), timings, processes.size());
    outputs.commit();
    return EXIT_SUCCESS;
  }
  catch(const std::length_error&)  // a size beyond what a container can hold: memory too
  {
    report_out_of_memory(progress);
  }
  catch(const std::bad_alloc&)
  {
    report_out_of_memory(progress);
  }
  catch(const std::exception& e)  // bad input, bad options, unwritable outputs: one line
  {
    progress.interrupt();
    if(is_first_launched_process()) std::cerr << "direction_field: error: " << e.what() << std::endl;
  }
  return EXIT_FAILURE;
}

// Under an address-space limit too small for OpenBLAS's work buffers, a
// thread of OpenBLAS's pool retries its allocation forever, and OpenBLAS's
// exit handler waits for that thread: the program would never end although
// its work is done (the package itself then avoids the BLAS, see
// dense_kernels.h). With a limit set, the program therefore ends without
// the libraries' exit handlers, once its outputs are committed and flushed.
static bool address_space_is_limited()
{
#if defined(__unix__) || defined(__APPLE__)
  rlimit limit{};
  return getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY;
#else
  return false;
#endif
}

int main(int argc, char** argv)
{
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
  SuiteSparse_config.printf_func = print_to_stderr;
#endif
  // The program is the only user of OpenBLAS in its process: it lets the
  // factorization keep OpenBLAS to one thread where that is faster
  // (openblas_thread_control.h).
  CGAL::Surface_mesh_direction_fields::set_openblas_thread_control(true);
  open_closed_standard_streams();
  const std::string no_threads = threads_cannot_start();
  if(!no_threads.empty())
  {
    std::cerr << "direction_field: error: " << no_threads << std::endl;
    return EXIT_FAILURE;
  }
  const int status = run(argc, argv);
  if(address_space_is_limited())
  {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    std::_Exit(status);
  }
  return status;
}
