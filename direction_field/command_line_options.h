// The options of the command-line program direction_field: one table says
// what each one means (printed by --help, and in this folder's README.md),
// parse_options() reads and checks them.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_COMMAND_LINE_OPTIONS_H
#define SURFACE_MESH_DIRECTION_FIELDS_PROGRAM_COMMAND_LINE_OPTIONS_H

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/alignment.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>

#include "file_io/messages.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

#ifndef SMDF_VERSION
#define SMDF_VERSION "1.0"
#endif

struct Options
{
  std::string mesh;
  int degree = CGAL::Surface_mesh_direction_fields::default_degree;
  double s = 0.;
  std::string directions, singularities, png, json_file;
  std::string vtk, vtk_singularities, ply, rosy, ffield, singularity_list, streamlines, mesh_out;
  std::string on = "vertices";  // --on: where the field lives (vertices, or faces with singular vertices)
  std::string non_manifold = "glue";  // --non-manifold: a field on faces glued across non-manifold edges, or cut
  std::string sharp, rawfield, sing, matching;
  bool json = false, quiet = false;
  unsigned int seed = 0;
  unsigned int max_iterations = 1000;
  double tolerance = 1e-10;
  std::string align = "none", guidance, constrain_boundary = "none";
  std::string prescribe;  // --prescribe: 'f k' lines, the singular faces to place
  bool lambda_given = false, weight_given = false;
  double lambda = 0., weight = 0.5;
  bool eigenvalue_bound = false;
  std::string curvature_estimate = "quadric-fit";
  double feature_angle = -1.;  // negative: no feature alignment
  unsigned int feature_cleanup = 4;  // --feature-cleanup: steps of erosion and growth of the sharp chains
  unsigned int neighbors = CGAL::Surface_mesh_direction_fields::default_number_of_neighbors;  // --neighbors: point sets
  double cancel_singularities = 0.;   // --cancel-singularities: the radius, a fraction of the bounding box's diagonal
  std::string solver = "default";
  std::string petsc_options;  // --petsc-options: PETSc's own options, for experts
  bool distribute_from_given = false;
  unsigned int distribute_from = 50000;  // --distribute-from: the smallest component spread over the processes
  std::string huge_pages = "auto";  // --huge-pages: malloc's transparent huge pages (huge_pages_rerun.h)
};

// The largest degree the program accepts: the library's.
constexpr int program_maximum_degree = CGAL::Surface_mesh_direction_fields::maximum_degree;

// A problem with the input or the options: reported on one line, exit status 1.
struct Usage_error : std::runtime_error { using std::runtime_error::runtime_error; };

struct Option_help
{
  const char* group;
  const char* option;
  const char* text;
};

inline const Option_help option_help[] = {
  {"Field", "MESH", "the mesh: OFF, OBJ, PLY (ASCII or binary) or STL (ASCII or binary); default: CGAL's fandisk.off. "
                    "Read as a polygon soup and repaired when needed (the summary says what changed)"},
  {"Field", "POINTS", "or a point set: .xyz ('x y z' or 'x y z nx ny nz' per line), .pts ('x y z ...' per line) "
                      "or a PLY without faces (with or without normals nx ny nz): the field lives on the points, "
                      "its singularities in the triangles of the points' local triangulations (outputs --directions, "
                      "--ply, --vtk, --png, --json, --json-file)"},
  {"Field", "--neighbors K", "with a point set: each point's tangent plane is fitted and triangulated with its K "
                             "nearest points (3 to 1000; default 12; about 24 for noisy scans)"},
  {"Field", "--degree N", "the number n of directions: 1 vector, 2 line, 4 cross field ... (1 to 1000; default 4)"},
  {"Field", "--s S", "the smoothness parameter in [-1, 1]: -1 follows the intrinsic, +1 the extrinsic "
                     "(shape) connection (default 0)"},
  {"Field", "--on WHERE", "vertices (default): one direction per vertex, singularities in faces; or faces: one "
                         "direction per face, singularities at vertices, a matching per edge (what quad meshers "
                         "read; s must be 0; outputs --rosy, --ffield, --sharp, --rawfield, --sing, --matching, "
                         "--singularities, --vtk, --vtk-singularities, --streamlines, --png, --mesh-out, --json)"},
  {"Field", "--non-manifold HOW", "with --on faces: glue (default): the faces around a non-manifold edge share "
                                  "the field there, the mesh stays whole; cut: the repair's cut pieces are "
                                  "fields of their own (as always on vertices; needed by --prescribe and "
                                  "--cancel-singularities on such a mesh)"},
  {"Field", "--seed N", "the seed of the random start vector of the eigen-solve (default 0)"},
  {"Field", "--max-iterations N", "the largest number of eigen-solve iterations (default 1000)"},
  {"Field", "--tolerance T", "the relative residual at which the eigen-solve stops (default 1e-10)"},
  {"Field", "--prescribe FILE", "place the singularities: one 'f k' per singular face of MESH (index k/n; the "
                                  "format --singularities writes, with its '# loop l t' lines; faces not listed have "
                                  "index 0). The field is then "
                                  "the parallel one with exactly these singular faces (s has no effect; --align, "
                                  "--guidance or one constrained direction choose its rotation). On a closed mesh "
                                  "the k must add up to n times the Euler characteristic. With --on faces: one 'v k' per "
                                  "singular interior vertex, numbered as --mesh-out and --singularities number them; "
                                  "any k that satisfy Poincare-Hopf are shown, with --matching"},
  {"Field", "--cancel-singularities D", "with --on faces: fewer singularities, for quad meshes with fewer irregular "
                                        "vertices: pairs of singular vertices of opposite index at most D apart "
                                        "along the edges (D a fraction of the bounding box's diagonal, e.g. 0.1) "
                                        "are removed: the field is the parallel one with the others, or with "
                                        "--feature-angle, --constrain-boundary, --lambda or --alignment-weight "
                                        "the same field turned off the constrained faces (not with --prescribe; "
                                        "default 0: none removed)"},
  {"Alignment", "--align WHAT", "none (default), curvature (= max-curvature), min-curvature or max-curvature: "
                                "follow the principal curvature directions (even n; on a point set a quadric "
                                "fitted to each point's 2K nearest points, K of --neighbors)"},
  {"Alignment", "--guidance FILE", "follow a vector field: one 'x y z' per vertex of MESH, or per point of a "
                                   "point set (length = weight, zero = no preference)"},
  {"Alignment", "--lambda L", "the lambda_t of (A - lambda_t M) u = M q (default: chosen by the library)"},
  {"Alignment", "--alignment-weight T", "or the alignment weight t in (0, 1) (lambda_t from lambda_1)"},
  {"Alignment", "--constrain-boundary HOW", "tangent or normal: one direction fixed along the boundary"},
  {"Alignment", "--feature-angle DEG", "one direction follows the sharp edges, whose faces meet more than DEG "
                                       "degrees from flat (0 < DEG < 180; even n)"},
  {"Alignment", "--feature-cleanup N", "with --feature-angle: each cycle of at most 2N sharp edges loses its "
                                       "least sharp edge (a web becomes a line), then open chains of at most 2N "
                                       "edges and branches of at most N are dropped, as QuadWild does (default 4; "
                                       "0 keeps every sharp edge)"},
  {"Alignment", "--curvature-estimate HOW", "quadric-fit (default) or hopf (the paper's Hopf differential)"},
  {"Alignment", "--eigenvalue-bound", "also compute lambda_1 for aligned fields (the JSON's eigenvalue_bound)"},
  {"Outputs", "--directions FILE", "one 'x y z' per vertex of MESH, in its order (17 significant digits)"},
  {"Outputs", "--singularities FILE", "one 'f k' per singular face of MESH (index k/n), then one '# loop l t' per "
                                       "loop along which the field turns t times other than the nearest choice"},
  {"Outputs", "--json", "one line of JSON on stdout instead of the summary (keys: direction_field/README.md)"},
  {"Outputs", "--json-file FILE", "the same line of JSON in FILE"},
  {"Outputs", "--png FILE", "a picture: the shaded mesh from four sides, the field, the singularities, a legend"},
  {"Outputs", "--vtk FILE", "the field for ParaView: .vtk (legacy) or .vtu (XML; both read by VTK and meshio): "
                            "the mesh, its n directions per vertex, the singular triangles marked (with --on faces: per "
                            "face, the singular vertices marked)"},
  {"Outputs", "--vtk-singularities FILE", "the singularities as small markers coloured by index, to open beside "
                                          "--vtk's file (.vtk or .vtu)"},
  {"Outputs", "--ply FILE", "PLY with per-vertex direction and magnitude, per-face singularity"},
  {"Outputs", "--rosy FILE", "the per-face cross field for QuadWild/vcglib (n = 4 only); with --on vertices a "
                            "sampling of the vertex field, whose singular vertices can differ from the singular "
                            "faces on scans: --on faces writes the field whose singularities QuadWild finds"},
  {"Outputs", "--ffield FILE", "the per-face cross field as a vcglib frame file (n = 4 only)"},
  {"Outputs", "--sharp FILE", "QuadWild's feature file: the edges of --feature-angle and the boundary edges, "
                             "'type,face,edge' per side (1 convex, 0 concave), numbered as in --mesh-out's mesh"},
  {"Outputs", "--rawfield FILE", "with --on faces: Directional's raw field, the n directions of each face"},
  {"Outputs", "--sing FILE", "with --on faces: Directional's singularities, 'vertex k' per singular vertex"},
  {"Outputs", "--matching FILE", "with --on faces: Directional's matching file (the period jump of each edge)"},
  {"Outputs", "--singularity-list FILE", "one 'face k n x y z' per singular face"},
  {"Outputs", "--streamlines FILE", "field lines: .vtp (VTK polylines), .vtu or .vtk (VTK line segments, read by "
                                    "meshio too), .obj ('l' lines), or any other name: one 'N x1 y1 z1 ... xN yN "
                                    "zN' per line"},
  {"Outputs", "--mesh-out FILE", "the repaired triangle mesh the outputs refer to (.off, .obj or .ply)"},
  {"Outputs", "--quiet", "print nothing but errors, warnings and the --json line: no summary, no progress "
                        "(progress is shown only on a terminal anyway)"},
  {"Performance", "--solver WHICH", "default (CHOLMOD on this process) or petsc: the large components spread over "
                                    "the processes of mpirun, which assemble and solve their parts without a "
                                    "factorization (mpirun -np K direction_field MESH --solver petsc; a build with "
                                    "PETSc and SLEPc); the first process reads the mesh and writes the outputs"},
  {"Performance", "--distribute-from N", "with --solver petsc: the components of at least N vertices are spread over "
                                         "the processes, smaller ones solved by the first (default 50000)"},
  {"Performance", "--petsc-options TEXT", "PETSc's own options for --solver petsc, as one argument "
                                         "(say \"-mat_mumps_icntl_14 50 -log_view\")"},
  {"Performance", "--huge-pages auto|on|off", "on: the program runs itself again with glibc's malloc asking "
                                             "for transparent huge pages (GLIBC_TUNABLES=glibc.malloc.hugetlb=1), "
                                             "which saves most of the page faults of a large mesh; only for mesh "
                                             "files of 4 MB or more, not when GLIBC_TUNABLES is set, under mpirun or "
                                             "under a memory limit. auto (default): the same where a page fault "
                                             "costs more than 5 us (measured at start on 8 MB), where huge pages "
                                             "pay. The results are the same; the JSON's huge_pages says which ran"},
  {"Program", "--help, -h", "this text"},
  {"Program", "--version", "the program's version"},
};

inline const char* const usage =
  "usage: direction_field [MESH] [--degree N] [--s S] [--directions FILE] [--singularities FILE]\n"
  "                       [--json] [--json-file FILE] [--png FILE] [--seed N] [--max-iterations N]\n"
  "                       [--tolerance T] [--align none|curvature|min-curvature|max-curvature]\n"
  "                       [--guidance FILE] [--lambda L | --alignment-weight T]\n"
  "                       [--constrain-boundary tangent|normal] [--eigenvalue-bound]\n"
  "                       [--curvature-estimate quadric-fit|hopf] [--feature-angle DEG] [--feature-cleanup N]\n"
  "                       [--cancel-singularities D] [--neighbors K]\n"
  "                       [--vtk FILE] [--vtk-singularities FILE] [--ply FILE] [--rosy FILE] [--ffield FILE]\n"
  "                       [--singularity-list FILE]"
  " [--streamlines FILE] [--mesh-out FILE] [--quiet]\n"
  "                       [--on vertices|faces] [--non-manifold glue|cut] [--sharp FILE] [--rawfield FILE]\n"
  "                       [--sing FILE] [--matching FILE]\n"
  "                       [--solver default|petsc]"
  " [--petsc-options TEXT] [--distribute-from N] [--prescribe FILE]\n"
  "                       [--huge-pages auto|on|off]\n"
  "                       [--help] [--version]\n";

inline void print_help(std::ostream& os)
{
  os << usage << "\nComputes the globally smoothest (or aligned) n-direction field of a triangle mesh and its\n"
     << "singular faces (Knoeppel, Crane, Pinkall, Schroeder 2013), with CGAL Surface_mesh_direction_fields.\n";
  std::string group;
  for(const Option_help& h : option_help)
  {
    if(group != h.group) { group = h.group; os << "\n" << group << ":\n"; }
    os << "  " << h.option;
    const std::string option = h.option;
    if(option.size() < 26) os << std::string(26 - option.size(), ' ');
    else os << "\n" << std::string(28, ' ');
    // the description wrapped at 100 columns, continued under itself
    std::size_t column = 28;
    const std::string description = h.text;
    for(std::size_t start = 0; start < description.size();)
    {
      std::size_t end = description.find(' ', start);
      if(end == std::string::npos) end = description.size();
      if(column + (end - start) > 100 && column > 28) { os << "\n" << std::string(28, ' '); column = 28; }
      else if(column > 28) { os << ' '; ++column; }
      os << description.substr(start, end - start);
      column += end - start;
      start = end + 1;
    }
    os << "\n";
  }
  os << "\nOutput files are written only when the whole run succeeds. Exit status: 0 on success (also when\n"
     << "the eigen-solve stops before its tolerance: the JSON's converged is then false, and stderr says\n"
     << "so); 1 with one line on stderr for bad input, bad options or an output that cannot be written.\n";
}

// A number, compactly, for messages (as the library's messages print them).


template <typename T>
T parse_number(const std::string& option, const std::string& text)
{
  T value{};
  const char* first = text.c_str();
  const char* last = first + text.size();
  const std::from_chars_result r = std::from_chars(first + (text.size() > 1 && text[0] == '+'), last, value);
  if(text.empty() || r.ec != std::errc() || r.ptr != last)
    throw Usage_error("option " + option + " expects " + (std::is_integral<T>::value ? "an integer" : "a number") +
                      ", got '" + text + "'");
  if constexpr(std::is_floating_point<T>::value)
    if(!std::isfinite(value)) throw Usage_error("option " + option + " expects a finite number, got '" + text + "'");
  return value;
}

inline unsigned int parse_count(const std::string& option, const std::string& text)
{
  const long long value = parse_number<long long>(option, text);
  if(value < 0 || value > static_cast<long long>(std::numeric_limits<unsigned int>::max()))
    throw Usage_error("option " + option + " expects an integer from 0 to 4294967295, got '" + text + "'");
  return static_cast<unsigned int>(value);
}

// The options that name an output file, and where they go.
inline std::string* output_option(Options& o, const std::string& a)
{
  if(a == "--directions") return &o.directions;
  if(a == "--singularities") return &o.singularities;
  if(a == "--png") return &o.png;
  if(a == "--json-file") return &o.json_file;
  if(a == "--vtk") return &o.vtk;
  if(a == "--vtk-singularities") return &o.vtk_singularities;
  if(a == "--ply") return &o.ply;
  if(a == "--rosy") return &o.rosy;
  if(a == "--ffield") return &o.ffield;
  if(a == "--singularity-list") return &o.singularity_list;
  if(a == "--streamlines") return &o.streamlines;
  if(a == "--mesh-out") return &o.mesh_out;
  if(a == "--sharp") return &o.sharp;
  if(a == "--rawfield") return &o.rawfield;
  if(a == "--sing") return &o.sing;
  if(a == "--matching") return &o.matching;
  return nullptr;
}

// The options with a value; false if `a` is none of them.
inline bool parse_valued_option(Options& o, const std::string& a, const std::string& v)
{
  if(std::string* path = output_option(o, a))
  {
    if(v.empty()) throw Usage_error("option " + a + " expects a file name, got ''");
    *path = v;
  }
  else if(a == "--degree")
  {
    const long long n = parse_number<long long>(a, v);
    if(n < 1 || n > program_maximum_degree)
      throw Usage_error("--degree expects an integer from 1 to " + std::to_string(program_maximum_degree) + ", got " + v);
    o.degree = static_cast<int>(n);
  }
  else if(a == "--s") o.s = parse_number<double>(a, v);
  else if(a == "--seed") o.seed = parse_count(a, v);
  else if(a == "--max-iterations") o.max_iterations = parse_count(a, v);
  else if(a == "--tolerance") o.tolerance = parse_number<double>(a, v);
  else if(a == "--align") o.align = v;
  else if(a == "--guidance" || a == "--prescribe")
  {
    if(v.empty()) throw Usage_error("option " + a + " expects a file name, got ''");
    (a == "--guidance" ? o.guidance : o.prescribe) = v;
  }
  else if(a == "--lambda") { o.lambda = parse_number<double>(a, v); o.lambda_given = true; }
  else if(a == "--alignment-weight") { o.weight = parse_number<double>(a, v); o.weight_given = true; }
  else if(a == "--constrain-boundary") o.constrain_boundary = v;
  else if(a == "--curvature-estimate") o.curvature_estimate = v;
  else if(a == "--feature-angle") o.feature_angle = parse_number<double>(a, v);
  else if(a == "--feature-cleanup")
  {
    o.feature_cleanup = parse_count(a, v);
    if(o.feature_cleanup > 1000) throw Usage_error("--feature-cleanup expects an integer from 0 to 1000, got " + v);
  }
  else if(a == "--cancel-singularities")
  {
    o.cancel_singularities = parse_number<double>(a, v);
    if(!(o.cancel_singularities >= 0. && o.cancel_singularities <= 10.))
      throw Usage_error("--cancel-singularities expects a fraction of the bounding box's diagonal from 0 to 10, got " + v);
  }
  else if(a == "--neighbors")
  {
    o.neighbors = parse_count(a, v);
    if(o.neighbors < 3 || o.neighbors > 1000) throw Usage_error("--neighbors expects an integer from 3 to 1000, got " + v);
  }
  else if(a == "--solver") o.solver = v;
  else if(a == "--on") o.on = v;
  else if(a == "--non-manifold") o.non_manifold = v;
  else if(a == "--petsc-options") o.petsc_options = v;
  else if(a == "--distribute-from") { o.distribute_from = parse_count(a, v); o.distribute_from_given = true; }
  else if(a == "--huge-pages") o.huge_pages = v;
  else return false;
  return true;
}

// --align as the library's enumeration (meshes, faces and point sets).
inline CGAL::Surface_mesh_direction_fields::Principal_curvature_alignment curvature_alignment(const Options& o)
{
  typedef CGAL::Surface_mesh_direction_fields::Principal_curvature_alignment Alignment;
  return o.align == "none" ? Alignment::NONE : o.align == "min-curvature" ? Alignment::MINIMUM : Alignment::MAXIMUM;
}

// --prescribe and what does not combine with it: the field solves no
// eigenproblem and no aligned system, on one process.
inline void check_prescription_options(const Options& o)
{
  if(o.prescribe.empty()) return;
  if(o.lambda_given || o.weight_given)
    throw Usage_error(std::string(o.lambda_given ? "--lambda" : "--alignment-weight") +
                      " does not apply to --prescribe (the alignment only chooses the field's rotation)");
  if(o.eigenvalue_bound) throw Usage_error("--eigenvalue-bound does not apply to --prescribe");
  if(o.solver != "default") throw Usage_error("--prescribe runs on one process: no --solver " + o.solver);
}

// --on faces and the options of vertex fields; the files of face fields.
inline void check_field_location_options(const Options& o)
{
  if(o.on != "vertices" && o.on != "faces") throw Usage_error("--on expects vertices or faces, got '" + o.on + "'");
  if(o.non_manifold != "glue" && o.non_manifold != "cut")
    throw Usage_error("--non-manifold expects glue or cut, got '" + o.non_manifold + "'");
  if(o.on == "vertices")
  {
    const std::pair<const char*, const std::string*> face_files[] = {
      {"--rawfield", &o.rawfield}, {"--sing", &o.sing}, {"--matching", &o.matching}};
    for(const auto& f : face_files)
      if(!f.second->empty())
        throw Usage_error(std::string(f.first) + " writes a field on faces with its matching: add --on faces");
    if(o.cancel_singularities > 0.) throw Usage_error("--cancel-singularities applies to fields on faces: add --on faces");
    return;
  }
  const std::pair<const char*, const std::string*> vertex_outputs[] = {
    {"--directions", &o.directions}, {"--ply", &o.ply}, {"--singularity-list", &o.singularity_list},
    {"--guidance", &o.guidance}};
  for(const auto& f : vertex_outputs)
    if(!f.second->empty()) throw Usage_error(std::string(f.first) + " applies to fields on vertices, not to --on faces");
  if(o.s != 0.) throw Usage_error("--on faces has the Dirichlet energy only: --s must be 0");
  if(o.solver != "default") throw Usage_error("--on faces runs on one process: no --solver " + o.solver);
  if(o.eigenvalue_bound) throw Usage_error("--eigenvalue-bound applies to fields on vertices");
  if(o.cancel_singularities > 0. && !o.prescribe.empty())
    throw Usage_error("--cancel-singularities does not apply with --prescribe (which places every singularity)");
}

// The values that are words, and the combinations of options.
inline void check_options(const Options& o)
{
  if(!(o.s >= -1. && o.s <= 1.)) throw Usage_error("--s expects a number in [-1, 1], got " + compact(o.s));
  if(!(o.tolerance >= 0.)) throw Usage_error("--tolerance expects a number >= 0, got " + compact(o.tolerance));
  if(o.align != "none" && o.align != "curvature" && o.align != "min-curvature" && o.align != "max-curvature")
    throw Usage_error("--align expects none, curvature, min-curvature or max-curvature, got '" + o.align + "'");
  if(o.constrain_boundary != "none" && o.constrain_boundary != "tangent" && o.constrain_boundary != "normal")
    throw Usage_error("--constrain-boundary expects tangent or normal, got '" + o.constrain_boundary + "'");
  if(o.feature_angle != -1. && !(o.feature_angle > 0. && o.feature_angle < 180.))
    throw Usage_error("--feature-angle expects an angle in degrees in (0, 180), got " + compact(o.feature_angle));
  if(o.curvature_estimate != "quadric-fit" && o.curvature_estimate != "hopf")
    throw Usage_error("--curvature-estimate expects quadric-fit or hopf, got '" + o.curvature_estimate + "'");
  if(o.solver != "default" && o.solver != "petsc")
    throw Usage_error("--solver expects default or petsc, got '" + o.solver + "'");
  if(o.huge_pages != "auto" && o.huge_pages != "on" && o.huge_pages != "off")
    throw Usage_error("--huge-pages expects auto, on or off, got '" + o.huge_pages + "'");
  if(!o.petsc_options.empty() && o.solver != "petsc") throw Usage_error("--petsc-options needs --solver petsc");
  if(o.distribute_from_given && o.solver != "petsc") throw Usage_error("--distribute-from needs --solver petsc");
#ifndef SMDF_WITH_PETSC
  if(o.solver == "petsc")
    throw Usage_error("--solver petsc: this build has no distributed solver (PETSc with complex scalars was not found)");
#endif
  if(o.lambda_given && o.weight_given) throw Usage_error("give either --lambda or --alignment-weight, not both");
  if(o.weight_given && !(o.weight > 0. && o.weight < 1.))
    throw Usage_error("--alignment-weight expects a number in (0, 1), got " + compact(o.weight));
  if((o.lambda_given || o.weight_given) && o.align == "none" && o.guidance.empty())
    throw Usage_error(std::string(o.lambda_given ? "--lambda" : "--alignment-weight") +
                      " needs something to align to (--align or --guidance)");
  check_prescription_options(o);
  check_field_location_options(o);
  if((!o.rosy.empty() || !o.ffield.empty()) && o.degree != 4)
    throw Usage_error(std::string(o.rosy.empty() ? "--ffield" : "--rosy") +
                      " describes cross fields (n = 4) only, as vcglib and QuadWild read them; n is " +
                      std::to_string(o.degree));
}

// The number of single-character edits from a to b (Levenshtein).
inline std::size_t edit_distance(const std::string& a, const std::string& b)
{
  std::vector<std::size_t> row(b.size() + 1);
  for(std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for(std::size_t i = 1; i <= a.size(); ++i)
  {
    std::size_t diagonal = row[0];
    row[0] = i;
    for(std::size_t j = 1; j <= b.size(); ++j)
    {
      const std::size_t above = row[j];
      row[j] = (std::min)({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The name of the option an entry of the help describes ("--degree" of "--degree N").
inline std::string option_name(const Option_help& h)
{
  const std::string text = h.option;
  return text.substr(0, text.find_first_of(" ,"));
}

// "unknown option --degre (did you mean --degree? see --help)": the option of
// the help within two edits, if any.
inline std::string unknown_option(const std::string& given)
{
  std::string nearest;
  std::size_t best = 3;
  for(const Option_help& h : option_help)
  {
    const std::string name = option_name(h);
    const std::size_t d = name.compare(0, 2, "--") == 0 ? edit_distance(given, name) : best;
    if(d < best) { best = d; nearest = name; }
  }
  return "unknown option " + given + (nearest.empty() ? " (see --help)" : " (did you mean " + nearest + "? see --help)");
}

inline bool is_known_option(const std::string& given)
{
  return std::any_of(std::begin(option_help), std::end(option_help),
                     [&](const Option_help& h) { return option_name(h) == given; });
}

// `default_mesh()` is called when no MESH is given.
template <typename DefaultMesh>
Options parse_options(int argc, char** argv, const DefaultMesh& default_mesh)
{
  Options o;
  bool mesh_given = false;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--help" || a == "-h") { print_help(std::cout); std::exit(EXIT_SUCCESS); }
    if(a == "--version") { std::cout << "direction_field " << SMDF_VERSION << "\n"; std::exit(EXIT_SUCCESS); }
    if(a == "--json") o.json = true;
    else if(a == "--quiet") o.quiet = true;
    else if(a == "--eigenvalue-bound") o.eigenvalue_bound = true;
    else if(a.size() > 2 && a.compare(0, 2, "--") == 0)
    {
      if(i + 1 >= argc) throw Usage_error(is_known_option(a) ? "option " + a + " expects a value" : unknown_option(a));
      if(!parse_valued_option(o, a, argv[i + 1])) throw Usage_error(unknown_option(a));
      ++i;
    }
    else if(!a.empty() && a[0] == '-' && a != "-") throw Usage_error(unknown_option(a));
    else if(mesh_given) throw Usage_error("more than one mesh given ('" + o.mesh + "' and '" + a + "')");
    else if(a.empty()) throw Usage_error("the mesh file name is empty");
    else { o.mesh = a; mesh_given = true; }
  }
  if(!mesh_given) o.mesh = default_mesh();
  check_options(o);
  return o;
}

#endif
