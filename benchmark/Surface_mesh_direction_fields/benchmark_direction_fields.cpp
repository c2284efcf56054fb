// Runs compute_globally_optimal_directions() over a list of meshes and prints
// one row per mesh and backend: sizes, eigenvalue, singularities, iterations,
// the time of each phase, the peak memory of the computation; then the same
// as CSV. Also times a second field on the same mesh with the class
// Globally_optimal_direction_field (another s: no mesh work, no symbolic
// analysis).
//
//   usage: benchmark_direction_fields [--degree N] [--s S] [--repeat R] [--huge-pages | --no-huge-pages]
//                                     [--backend default|ldlt|both] [--subdivide K] [--csv FILE]
//                                     [--align curvature [--lambda L]] [--openblas-thread-control on|off]
//                                     [MESH...]
// --openblas-thread-control: set_openblas_thread_control() (on by default, as
// in the direction_field program).
// A mesh given as FILE@K is FILE after K steps of Loop subdivision (4^K times the faces).
// With no mesh: every mesh of ../shared/data/meshes, then nefertiti_sub4.off@1 (1.6 million faces).
//
// --align curvature: the curvature-aligned field ((A - lambda_t M) u = M q,
// lambda_t = L or the default 0) instead of the smoothest one; "again" is then
// the other principal direction with the same lambda_t on the class (the kept
// factorization: no factorization of its own).
//
// Peak memory: the kernel's high-water mark of the resident set (VmHWM), reset
// before each run (writing 5 to /proc/self/clear_refs), so it is the peak of
// that run, the mesh itself included; "KB/V" divides it by |V|, "+KB/V"
// divides the growth over the resident set before the run (the memory of the
// computation itself) by |V|.
//
// Reference ("ref"): one factorization (symbolic analysis included) and one
// solve of the matrix A + epsilon M of the same mesh, with the same backend,
// through the package's own factorization code, as a program that only
// needed one linear solve would do it; "x" is total / ref (the issue's target
// for the smoothest cross field at 400,000 faces is x <= 1.5).
//
// Huge pages: with --huge-pages (and GLIBC_TUNABLES not already set), the
// program runs itself again with GLIBC_TUNABLES=glibc.malloc.hugetlb=1
// (glibc >= 2.35; ignored by older ones), so that malloc asks the kernel for
// transparent huge pages. Whether that helps depends on the machine: see
// README.md beside this file (on the machines measured last it made a cold
// run slower, hence the default). --no-huge-pages, the default, is accepted
// for the scripts written when huge pages were the default.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/subdivision_method_3.h>

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "process_memory.h"

#include <unistd.h>  // execv: the rerun with malloc's huge pages

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace SMDF = CGAL::Surface_mesh_direction_fields;
typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<std::complex<double> > > > Ldlt_solver;

#ifndef SMDF_SHARED_MESH_DIR
#define SMDF_SHARED_MESH_DIR ""
#endif

// What is computed: the smoothest field, or the curvature-aligned one.
struct Field_request
{
  int degree = 4;
  double s = 0.;
  bool aligned = false, lambda_given = false;
  double lambda = 0.;
};

template <typename DirectionMap, typename NamedParameters>
SMDF::Direction_field_result compute_with(const Mesh& mesh, DirectionMap dir, const Field_request& f,
                                          SMDF::Principal_curvature_alignment which, const NamedParameters& np)
{
  if(!f.aligned) return SMDF::compute_globally_optimal_directions(mesh, dir, np);
  if(!f.lambda_given)
    return SMDF::compute_globally_optimal_directions(mesh, dir, np.principal_curvature_alignment(which));
  return SMDF::compute_globally_optimal_directions(mesh, dir, np.principal_curvature_alignment(which).alignment_lambda(f.lambda));
}

template <typename Solver>
SMDF::Direction_field_result compute(const Mesh& mesh, std::vector<Kernel::Vector_3>& directions,
                                     const Field_request& f,
                                     SMDF::Principal_curvature_alignment which = SMDF::Principal_curvature_alignment::MAXIMUM)
{
  auto dir = CGAL::make_property_map(directions);
  auto np = CGAL::parameters::degree(f.degree).smoothness_parameter(f.s);
  // the default backend as users get it (a solver given as a named parameter is used once, without reuse)
  if constexpr(std::is_same<Solver, SMDF::Default_direction_field_solver>::value)
    return compute_with(mesh, dir, f, which, np);
  else
    return compute_with(mesh, dir, f, which, np.sparse_linear_solver(Solver()));
}

struct Run
{
  std::string mesh, backend;
  std::size_t vertices = 0, faces = 0;
  SMDF::Direction_field_result result;
  double peak_mb = 0., before_mb = 0., again_ms = 0., reference_ms = 0.;
};

// One factorization and one solve of A + epsilon M (each component), with the
// backend Solver, the matrices being built first (not timed).
template <typename Solver>
double reference_ms(const Mesh& mesh, int degree, double s)
{
  namespace I = SMDF::internal;
  typedef std::chrono::steady_clock Clock;
  const I::Point_to_array<Kernel> to_array{Kernel()};
  const auto vpm = get(CGAL::vertex_point, mesh);
  const I::Indexed_mesh m = I::make_indexed_mesh(
    mesh, [&](Mesh::Vertex_index v) { return to_array(get(vpm, v)); }, get(CGAL::vertex_index, mesh),
    get(CGAL::face_index, mesh));
  const I::Tangent_spaces ts = I::compute_tangent_spaces(m, 1e-6);
  const I::Components comps = I::split_into_components(m);
  const I::Connection con = I::compute_connection(m, ts, degree);
  const std::vector<I::Energy_and_mass> matrices = I::assemble_energy_and_mass(m, ts, con, comps, s);
  double ms = 0.;
  for(const I::Energy_and_mass& em : matrices)
  {
    const double sigma = em.energy.diagonal().real().sum() / em.mass.diagonal().real().sum();
    const I::Complex_dense_matrix b = I::Complex_dense_matrix::Ones(em.energy.rows(), 1);
    Solver solver;
    I::Factored_matrix<Solver> factored(solver);
    const auto start = Clock::now();
    factored.factor_shifted(em.energy, em.mass, I::Eigen_solve_options().relative_shift * sigma);
    const I::Complex_dense_matrix x = factored.solve(b);
    ms += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  }
  return ms;
}

template <typename Solver>
Run run(const Mesh& mesh, const std::string& name, const std::string& backend, const Field_request& f, int repeat)
{
  const int degree = f.degree;
  const double s = f.s;
  Run r;
  r.mesh = name;
  r.backend = backend;
  r.vertices = mesh.number_of_vertices();
  r.faces = mesh.number_of_faces();
  std::vector<Kernel::Vector_3> directions(mesh.number_of_vertices());
  auto dir = CGAL::make_property_map(directions);
  for(int k = 0; k < repeat; ++k)  // keep the fastest run
  {
    reset_peak_memory();
    const double before = proc_status_mb("VmRSS:");
    SMDF::Direction_field_result res = compute<Solver>(mesh, directions, f);
    const double peak = proc_status_mb("VmHWM:");
    if(k == 0 || res.timings.total_ms < r.result.timings.total_ms) { r.result = res; r.peak_mb = peak; r.before_mb = before; }
  }
  for(int k = 0; k < repeat; ++k)  // the fastest one too
  {
    const double ms = reference_ms<Solver>(mesh, degree, s);
    if(k == 0 || ms < r.reference_ms) r.reference_ms = ms;
  }
  // The class for repeated work: a second field on the same mesh (another s;
  // or, aligned, the other principal direction with the same lambda_t).
  SMDF::Globally_optimal_direction_field<Mesh, Kernel, Solver> field(mesh);
  auto np = CGAL::parameters::degree(degree).smoothness_parameter(s);
  if(!f.aligned)
  {
    field.compute(dir, np);
    r.again_ms = field.compute(dir, CGAL::parameters::degree(degree).smoothness_parameter(s == 0. ? 0.5 : 0.))
                   .timings.total_ms;
    return r;
  }
  const double lambda = f.lambda_given ? f.lambda : 0.;
  field.compute(dir, np.principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM).alignment_lambda(lambda));
  r.again_ms = field.compute(dir, np.principal_curvature_alignment(SMDF::Principal_curvature_alignment::MINIMUM)
                                    .alignment_lambda(lambda)).timings.total_ms;
  return r;
}

int main(int argc, char** argv)
{
  int repeat = 1;
  Field_request request;
  int& degree = request.degree;
  double& s = request.s;
  std::string backend = "default", csv_file;
  bool huge_pages = false;
  bool openblas_threads = true;  // as the direction_field program
  std::vector<std::string> meshes;
  for(int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if(a == "--degree" && i + 1 < argc) degree = std::stoi(argv[++i]);
    else if(a == "--s" && i + 1 < argc) s = std::stod(argv[++i]);
    else if(a == "--repeat" && i + 1 < argc) repeat = std::stoi(argv[++i]);
    else if(a == "--backend" && i + 1 < argc) backend = argv[++i];
    else if(a == "--csv" && i + 1 < argc) csv_file = argv[++i];
    else if(a == "--no-huge-pages") huge_pages = false;
    else if(a == "--huge-pages") huge_pages = true;
    else if(a == "--openblas-thread-control" && i + 1 < argc) openblas_threads = std::string(argv[++i]) != "off";
    else if(a == "--align" && i + 1 < argc) request.aligned = std::string(argv[++i]) == "curvature";
    else if(a == "--lambda" && i + 1 < argc) { request.lambda = std::stod(argv[++i]); request.lambda_given = true; }
    else if(a == "--help") { std::cout << "see the comment at the top of benchmark_direction_fields.cpp\n"; return 0; }
    else meshes.push_back(a);
  }
  if(huge_pages && std::getenv("GLIBC_TUNABLES") == nullptr)
  {
    // run again with malloc's huge pages (see the comment at the top); go on without them if that fails
    setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1", 1);
    execv("/proc/self/exe", argv);
    unsetenv("GLIBC_TUNABLES");
  }
  CGAL::Surface_mesh_direction_fields::set_openblas_thread_control(openblas_threads);
  std::cout << "OpenBLAS thread control: "
            << (CGAL::Surface_mesh_direction_fields::openblas_thread_control() ? "on" : "off") << "\n";
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  std::cout << "malloc: " << (tunables != nullptr && std::strstr(tunables, "glibc.malloc.hugetlb=1") != nullptr
                                ? "transparent huge pages (GLIBC_TUNABLES=glibc.malloc.hugetlb=1)"
                                : "default pages")
            << "\n";
  if(meshes.empty())
  {
    const std::string dir = SMDF_SHARED_MESH_DIR;
    if(dir.empty()) { std::cerr << "no mesh given and ../shared/data/meshes not found\n"; return 1; }
    for(const char* name : {"eight.off", "sphere_oded.off", "bones.off", "torus_oded.off", "cow.off", "spot.off",
                            "fertility.off", "fandisk.off", "blade.off", "plane_holes.off", "camelhead.off",
                            "stanford_bunny_open.off", "nefertiti.off", "nefertiti_sub4.off", "nefertiti_sub4.off@1"})
      meshes.push_back(dir + "/" + name);
  }
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
  const std::string default_name = "cholmod";
#else
  const std::string default_name = "ldlt";
#endif

  std::vector<Run> runs;
  std::printf("%-22s %8s %8s %2s %-7s %11s %5s %4s %4s %8s %8s %8s %8s %8s %5s %8s %7s %5s %5s\n", "mesh", "|V|",
              "|F|", "n", "backend", "eigenvalue", "sing", "sum", "iter", "setup", "factor", "solve", "total", "ref",
              "x", "again", "peakMB", "KB/V", "+KB/V");
  for(const std::string& spec : meshes)
  {
    const std::size_t at = spec.find('@');
    const std::string path = spec.substr(0, at);
    const int steps = (at == std::string::npos) ? 0 : std::stoi(spec.substr(at + 1));
    Mesh mesh;
    if(!CGAL::IO::read_polygon_mesh(path, mesh)) { std::cerr << "cannot read " << path << "\n"; continue; }
    if(steps > 0) CGAL::Subdivision_method_3::Loop_subdivision(mesh, CGAL::parameters::number_of_iterations(steps));
    std::string name = path.substr(path.find_last_of('/') + 1);
    if(steps > 0) name += "@" + std::to_string(steps);

    std::vector<Run> rows;
    if(backend == "default" || backend == "both")
      rows.push_back(run<SMDF::Default_direction_field_solver>(mesh, name, default_name, request, repeat));
    if(backend == "ldlt" || (backend == "both" && default_name != "ldlt"))
      rows.push_back(run<Ldlt_solver>(mesh, name, "ldlt", request, repeat));
    for(const Run& r : rows)
    {
      const SMDF::Direction_field_result& b = r.result;
      std::printf("%-22s %8zu %8zu %2d %-7s %11.6g %5zu %4d %4zu %8.1f %8.1f %8.1f %8.1f %8.1f %5.2f %8.1f %7.1f "
                  "%5.2f %5.2f\n",
                  r.mesh.c_str(), r.vertices, r.faces, degree, r.backend.c_str(),
                  b.components.empty() ? 0. : b.components[0].eigenvalue.value_or(0.), b.number_of_singular_faces, b.index_sum,
                  b.iterations, b.timings.setup_ms, b.timings.factorization_ms, b.timings.solve_ms, b.timings.total_ms,
                  r.reference_ms, b.timings.total_ms / r.reference_ms, r.again_ms, r.peak_mb, 1024. * r.peak_mb / static_cast<double>(r.vertices),
                  1024. * (r.peak_mb - r.before_mb) / static_cast<double>(r.vertices));
      std::fflush(stdout);
      runs.push_back(r);
    }
  }

  std::ostringstream csv;
  csv << "mesh,vertices,faces,components,degree,s,backend,eigenvalue,singular_faces,index_sum,iterations,residual,"
         "setup_ms,factorization_ms,solve_ms,total_ms,reference_ms,total_over_reference,again_ms,peak_memory_mb,peak_kb_per_vertex,"
         "computation_kb_per_vertex,field\n";
  for(const Run& r : runs)
  {
    const SMDF::Direction_field_result& b = r.result;
    csv << r.mesh << "," << r.vertices << "," << r.faces << "," << b.components.size() << "," << degree << "," << s
        << "," << r.backend << "," << (b.components.empty() ? 0. : b.components[0].eigenvalue.value_or(0.)) << ","
        << b.number_of_singular_faces << "," << b.index_sum << "," << b.iterations << "," << b.residual << ","
        << b.timings.setup_ms << "," << b.timings.factorization_ms << "," << b.timings.solve_ms << ","
        << b.timings.total_ms << "," << r.reference_ms << "," << b.timings.total_ms / r.reference_ms << ","
        << r.again_ms << "," << r.peak_mb << ","
        << 1024. * r.peak_mb / static_cast<double>(r.vertices) << ","
        << 1024. * (r.peak_mb - r.before_mb) / static_cast<double>(r.vertices) << ","
        << (request.aligned ? "curvature_aligned" : "smoothest") << "\n";
  }
  std::cout << "\n" << csv.str();
  if(!csv_file.empty()) std::ofstream(csv_file) << csv.str();

  // Scaling exponent: least-squares slope of log(total) against log(|F|) over
  // the default backend's runs with at least 50,000 faces.
  double sx = 0., sy = 0., sxx = 0., sxy = 0.;
  int count = 0;
  for(const Run& r : runs)
    if(r.backend == runs.front().backend && r.faces >= 50000)
    {
      const double x = std::log(static_cast<double>(r.faces)), y = std::log(r.result.timings.total_ms);
      sx += x; sy += y; sxx += x * x; sxy += x * y; ++count;
    }
  if(count >= 2)
    std::cout << "\nscaling: total time ~ |F|^" << (count * sxy - sx * sy) / (count * sxx - sx * sx) << " ("
              << count << " meshes with >= 50000 faces, backend " << runs.front().backend << ")\n";
  return 0;
}
