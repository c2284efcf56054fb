// End-to-end checks of compute_globally_optimal_directions():
//  * discrete Poincare-Hopf: the indices of a closed component add up to
//    n chi, for n = 1..6 and s in {-1, 0, 1}, on every closed shared mesh, on
//    generated spheres and tori, and per component on bones.off;
//  * closed forms: a flat disk has eigenvalue 0, a parallel field and no
//    singularity; a torus of revolution carries a cross field without
//    singularity; a sphere's vector field has index sum 2;
//  * invariance under rotation, translation and uniform scaling (x1e-3, x1e3);
//  * every output vector has unit length, is orthogonal to the vertex normal
//    (ours or the one given by vertex_normal_map), and is finite;
//  * the documented errors on bad input, with the input left untouched;
//  * determinism for a seed, and the optional outputs;
//  * other sparse solvers give the same field, also an aligned one refined
//    from a single-precision factor.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <boost/property_map/property_map.hpp>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include "test_types.h"
#include "field_checks.h"
#include "generated_meshes.h"
#include "test_support.h"

#include <array>
#include <cmath>
#include <complex>
#include <iostream>
#include <iterator>
#include <map>
#include <memory>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;

typedef std::vector<std::pair<Face_index, int> > Singularities;

// Unit length, finite, orthogonal to the given normals (1e-9).
template <typename Directions>
static void check_outputs(Test_report& report, const std::string& name, const Mesh& mesh, const Directions& dir,
                          const std::vector<Vector_3>& normals)
{
  double worst_length = 0., worst_normal = 0.;
  bool finite = true;
  for(Vertex_index v : mesh.vertices())
  {
    const Vector_3 d = dir[v];
    if(mesh.is_isolated(v))  // documented: the zero vector
    {
      finite = finite && d == CGAL::NULL_VECTOR;
      continue;
    }
    finite = finite && std::isfinite(d.x()) && std::isfinite(d.y()) && std::isfinite(d.z());
    worst_length = (std::max)(worst_length, std::abs(std::sqrt(d.squared_length()) - 1.));
    worst_normal = (std::max)(worst_normal, std::abs(d * normals[v]));
  }
  report.check(finite, name + ": finite outputs (zero at isolated vertices)");
  report.check(worst_length < 1e-12, name + ": unit length (" + std::to_string(worst_length) + ")");
  report.check(worst_normal < 1e-9, name + ": orthogonal to the vertex normal (" + std::to_string(worst_normal) + ")");
}

static int euler_characteristic(const Mesh& mesh)
{
  return int(mesh.number_of_vertices()) - int(mesh.number_of_edges()) + int(mesh.number_of_faces());
}

// Poincare-Hopf for n = 1..6 and s in {-1, 0, 1}. The identity holds for any
// field, converged or not, so large meshes run with few iterations.
static void check_poincare_hopf(Test_report& report, const std::string& name, Mesh& mesh, bool per_component = false)
{
  auto dir = direction_map(mesh);
  const unsigned int iterations = mesh.number_of_vertices() > 20000 ? 20u : 300u;
  bool all = true;
  for(int n = 1; n <= 6; ++n)
    for(double s : {-1., 0., 1.})
    {
      Singularities sing;
      const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
        mesh, dir, params::degree(n).smoothness_parameter(s).number_of_iterations(iterations)
                     .singularities_output_iterator(std::back_inserter(sing)));
      int chi = 0, sum = 0;
      bool components_ok = true;
      for(const auto& c : r.components)
      {
        chi += c.euler_characteristic;
        components_ok = components_ok && c.is_closed && c.index_sum == n * c.euler_characteristic;
      }
      for(const auto& fk : sing) sum += fk.second;
      const bool ok = chi == euler_characteristic(mesh) && r.index_sum == n * chi && sum == r.index_sum &&
                      sing.size() == r.number_of_singular_faces && (!per_component || components_ok);
      if(!ok)
        std::cerr << name << " n = " << n << " s = " << s << ": index sum " << r.index_sum << ", n chi = " << n * chi
                  << std::endl;
      all = all && ok;
    }
  report.check(all, name + ": Poincare-Hopf (index sum = n chi" + (per_component ? " per component" : "") +
                    ") for n = 1..6, s = -1, 0, 1");
}

static void check_flat_disk(Test_report& report)
{
  Mesh disk;
  make_disk(disk, 12, 2.);
  auto dir = direction_map(disk);
  for(int n : {1, 2, 4})
  {
    Singularities sing;
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
      disk, dir, params::degree(n).singularities_output_iterator(std::back_inserter(sing)));
    // radius 2: the next eigenvalues are O(1)
    report.check(std::abs(r.components[0].eigenvalue.value()) < 1e-8,
                 "flat disk: eigenvalue 0 (n = " + std::to_string(n) + ", got " + std::to_string(r.components[0].eigenvalue.value()) + ")");
    report.check(sing.empty(), "flat disk: no singular face, n = " + std::to_string(n));
    // All directions parallel modulo 2 pi / n.
    const double a0 = std::atan2(dir[Vertex_index(0)].y(), dir[Vertex_index(0)].x());
    double worst = 0.;
    for(Vertex_index v : disk.vertices())
    {
      double d = n * (std::atan2(dir[v].y(), dir[v].x()) - a0);
      d = std::remainder(d, 2. * CGAL_PI) / n;
      worst = (std::max)(worst, std::abs(d));
    }
    report.check(worst < 1e-6, "flat disk: parallel directions within 1e-6 rad, n = " + std::to_string(n) +
                               " (" + std::to_string(worst) + ")");
  }
}

static void check_torus_and_sphere(Test_report& report)
{
  // A thin torus (R/r = 10). On fat tori (R/r <= 4 here) the smoothest cross
  // field has pairs of singularities of opposite index, for any resolution.
  Mesh torus;
  make_torus(torus, 10., 1., 200, 24);
  auto dir = direction_map(torus);
  Singularities sing;
  SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
    torus, dir, params::degree(4).singularities_output_iterator(std::back_inserter(sing)));
  report.check(sing.empty(), "torus of revolution, n = 4: no singular face (" + std::to_string(sing.size()) + ")");
  check_outputs(report, "torus", torus, dir, angle_weighted_normals(torus));

  Mesh sphere;
  make_icosphere(sphere, 3);
  auto sdir = direction_map(sphere);
  sing.clear();
  r = SMDF::compute_globally_optimal_directions(sphere, sdir,
                                              params::degree(1).singularities_output_iterator(std::back_inserter(sing)));
  int sum = 0;
  for(const auto& fk : sing) sum += fk.second;
  report.check(r.index_sum == 2 && sum == 2, "sphere, n = 1: index sum 2");
}

// The same field (rotated with the mesh) after a rigid motion or a uniform
// scaling: the computation is intrinsic and the seed fixes the start vector.
static void check_invariance(Test_report& report, const Mesh& base, const std::string& name)
{
  Mesh reference = base;
  auto dref = direction_map(reference);
  const SMDF::Direction_field_result r0 = SMDF::compute_globally_optimal_directions(reference, dref, params::degree(4));
  // a rotation about an oblique axis
  const double c = std::cos(0.83), s = std::sin(0.83);
  const Vector_3 axis = Vector_3(1., 2., -0.5) / std::sqrt(5.25);
  auto rotate = [&](const Vector_3& v) {
    return c * v + s * CGAL::cross_product(axis, v) + (1. - c) * (axis * v) * axis;
  };
  struct Motion { std::string label; double scale; bool rotate; Vector_3 shift; };
  const std::vector<Motion> motions = {{"rotation", 1., true, CGAL::NULL_VECTOR},
                                       {"translation", 1., false, Vector_3(12., -7., 30.)},
                                       {"scale 1e-3", 1e-3, false, CGAL::NULL_VECTOR},
                                       {"scale 1e3", 1e3, false, CGAL::NULL_VECTOR},
                                       {"all", 1e3, true, Vector_3(-3e3, 1e3, 5e2)}};
  for(const Motion& m : motions)
  {
    Mesh moved = base;
    for(Vertex_index v : moved.vertices())
    {
      Vector_3 p = moved.point(v) - CGAL::ORIGIN;
      if(m.rotate) p = rotate(p);
      moved.point(v) = CGAL::ORIGIN + m.scale * p + m.shift;
    }
    auto dmoved = direction_map(moved);
    const SMDF::Direction_field_result r1 = SMDF::compute_globally_optimal_directions(moved, dmoved, params::degree(4));
    double worst = 0.;
    for(Vertex_index v : moved.vertices())
    {
      const Vector_3 expected = m.rotate ? rotate(dref[v]) : dref[v];
      const double sin_angle = std::sqrt(CGAL::cross_product(expected, dmoved[v]).squared_length());
      const double cos_angle = expected * dmoved[v];
      worst = (std::max)(worst, std::abs(std::atan2(sin_angle, cos_angle)));
    }
    const double eig_ratio = r1.components[0].eigenvalue.value() * m.scale * m.scale / r0.components[0].eigenvalue.value();
    report.check(worst < 1e-6, name + ", " + m.label + ": same field within 1e-6 rad (" + std::to_string(worst) + ")");
    report.check(std::abs(eig_ratio - 1.) < 1e-9, name + ", " + m.label + ": eigenvalue scales as 1 / scale^2");
    report.check(r1.index_sum == r0.index_sum && r1.number_of_singular_faces == r0.number_of_singular_faces,
                 name + ", " + m.label + ": same singularities");
  }
}

static void check_bad_input(Test_report& report)
{
  Mesh sphere;
  make_icosphere(sphere, 1);
  auto dir = direction_map(sphere);
  const Mesh copy = sphere;
  report.check(throws_invalid_input([&] { SMDF::compute_globally_optimal_directions(sphere, dir, params::degree(0)); }), "n = 0 rejected");
  report.check(throws_invalid_input([&] { SMDF::compute_globally_optimal_directions(sphere, dir, params::degree(-3)); }), "n < 0 rejected");
  report.check(throws_invalid_input([&] { SMDF::compute_globally_optimal_directions(sphere, dir, params::smoothness_parameter(1.5)); }), "s > 1 rejected");
  report.check(throws_invalid_input([&] { SMDF::compute_globally_optimal_directions(sphere, dir, params::smoothness_parameter(-1.01)); }), "s < -1 rejected");
  report.check(throws_invalid_input([&] {
    SMDF::compute_globally_optimal_directions(sphere, dir, params::smoothness_parameter(std::numeric_limits<double>::quiet_NaN())); }), "s = NaN rejected");
  bool untouched = true;
  for(Vertex_index v : sphere.vertices()) untouched = untouched && dir[v] == CGAL::NULL_VECTOR && sphere.point(v) == copy.point(v);
  report.check(untouched, "rejected calls write nothing and leave the mesh as it was");

  Mesh empty;
  auto edir = direction_map(empty);
  report.check(throws_invalid_input([&] { SMDF::compute_globally_optimal_directions(empty, edir); }), "empty mesh rejected");

  Mesh quad;
  {
    auto a = quad.add_vertex(Point_3(0, 0, 0)), b = quad.add_vertex(Point_3(1, 0, 0)),
         c = quad.add_vertex(Point_3(1, 1, 0)), d = quad.add_vertex(Point_3(0, 1, 0));
    quad.add_face(a, b, c, d);
  }
  auto qdir = direction_map(quad);
  report.check(throws_invalid_input([&] { SMDF::compute_globally_optimal_directions(quad, qdir); }), "quad face rejected");

  Mesh nan_mesh = sphere;
  nan_mesh.point(Vertex_index(5)) = Point_3(std::numeric_limits<double>::quiet_NaN(), 0, 0);
  auto ndir = direction_map(nan_mesh);
  report.check(throws_invalid_input([&] { SMDF::compute_globally_optimal_directions(nan_mesh, ndir); }), "NaN coordinate rejected");

  Mesh flat_face = sphere;  // move a vertex onto the line of two others: a zero-area face
  {
    auto h = flat_face.halfedge(Face_index(0));
    const Point_3 a = flat_face.point(flat_face.source(h)), b = flat_face.point(flat_face.target(h));
    flat_face.point(flat_face.target(flat_face.next(h))) = CGAL::midpoint(a, b);
  }
  auto fdir = direction_map(flat_face);
  report.check(throws_invalid_input([&] {
    SMDF::compute_globally_optimal_directions(flat_face, fdir, params::intrinsic_mollification(0.)); }),
    "zero-area face rejected without mollification");
}

// Several components, an isolated vertex, determinism, optional outputs.
static void check_components_and_outputs(Test_report& report)
{
  Mesh mesh;
  make_icosphere(mesh, 2);
  Mesh torus;
  make_torus(torus, 2., 0.6, 30, 12);
  for(Vertex_index v : torus.vertices()) torus.point(v) = torus.point(v) + Vector_3(5., 0., 0.);
  CGAL::copy_face_graph(torus, mesh);
  const Vertex_index isolated = mesh.add_vertex(Point_3(9., 9., 9.));
  auto dir = direction_map(mesh);
  auto magnitude = mesh.add_property_map<Vertex_index, double>("v:magnitude", -1.).first;
  Singularities sing;
  const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
    mesh, dir, params::degree(2).vertex_magnitude_map(magnitude).singularities_output_iterator(std::back_inserter(sing)));
  report.check(r.components.size() == 2, "two components found");
  report.check(r.components.size() == 2 && r.components[0].index_sum == 4 && r.components[1].index_sum == 0,
               "Poincare-Hopf per component (sphere 2 n, torus 0)");
  report.check(r.number_of_isolated_vertices == 1 && dir[isolated] == CGAL::NULL_VECTOR && magnitude[isolated] == 0.,
               "an isolated vertex gets the zero vector and magnitude 0");
  bool magnitudes_ok = true;
  for(Vertex_index v : mesh.vertices()) magnitudes_ok = magnitudes_ok && std::isfinite(magnitude[v]) && magnitude[v] >= 0.;
  report.check(magnitudes_ok, "magnitudes finite and non-negative");
  {
    // On a single sphere: area-weighted mean square of the magnitude is 1
    // (lumped quadrature, hence the tolerance).
    Mesh ball;
    make_icosphere(ball, 3, 2.5);
    auto bdir = direction_map(ball);
    auto bmag = ball.add_property_map<Vertex_index, double>("v:magnitude", -1.).first;
    SMDF::compute_globally_optimal_directions(ball, bdir, params::degree(3).vertex_magnitude_map(bmag));
    double mean_square = 0., area = 0.;
    for(Face_index f : ball.faces())
    {
      const double a = CGAL::Polygon_mesh_processing::face_area(f, ball);
      area += a;
      for(Vertex_index v : CGAL::vertices_around_face(ball.halfedge(f), ball)) mean_square += a / 3. * bmag[v] * bmag[v];
    }
    report.check(std::abs(mean_square / area - 1.) < 0.02, "magnitude: area-weighted mean square 1 (" +
                                                           std::to_string(mean_square / area) + ")");
  }

  auto dir2 = mesh.add_property_map<Vertex_index, Vector_3>("v:direction2", CGAL::NULL_VECTOR).first;
  SMDF::compute_globally_optimal_directions(mesh, dir2, params::degree(2));
  bool same = true;
  for(Vertex_index v : mesh.vertices()) same = same && dir[v] == dir2[v];
  report.check(same, "same seed, same field (bitwise)");
  SMDF::compute_globally_optimal_directions(mesh, dir2, params::degree(2).random_seed(7));
  int differ = 0;
  for(Vertex_index v : mesh.vertices()) differ += (dir[v] != dir2[v]);
  std::cout << "  another seed changes " << differ << " of " << mesh.number_of_vertices() << " directions (global phase)\n";

  // Given normals: the outputs are orthogonal to them.
  auto normals = mesh.add_property_map<Vertex_index, Vector_3>("v:normal", CGAL::NULL_VECTOR).first;
  CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
  normals[isolated] = Vector_3(0, 0, 1);
  SMDF::compute_globally_optimal_directions(mesh, dir2, params::degree(2).vertex_normal_map(normals));
  double worst = 0.;
  for(Vertex_index v : mesh.vertices())
    if(v != isolated) worst = (std::max)(worst, std::abs(dir2[v] * normals[v]));
  report.check(worst < 1e-9, "orthogonal to the normals given by vertex_normal_map");
}

// Another mesh model and another factorization give the same field.
// A minimal model of SparseLinearAlgebraWithFactorTraits_d that is not
// CGAL::Eigen_solver_traits (so the package takes its generic path).
struct Generic_ldlt_solver
{
  typedef std::complex<double> NT;
  typedef CGAL::Eigen_sparse_matrix<NT> Matrix;
  typedef CGAL::Eigen_vector<NT> Vector;
  std::shared_ptr<Eigen::SimplicialLDLT<Matrix::EigenType> > ldlt = std::make_shared<Eigen::SimplicialLDLT<Matrix::EigenType> >();
  bool factor(const Matrix& A, NT& D)
  {
    D = NT(1.);
    ldlt->compute(A.eigen_object());
    return ldlt->info() == Eigen::Success;
  }
  bool linear_solver(const Vector& B, Vector& X)
  {
    X = ldlt->solve(B.eigen_object());
    return ldlt->info() == Eigen::Success;
  }
};

// An aligned field whose factor the package computes itself (from 2^14
// entries) is factored in single precision and each solve refined to double
// precision (user manual, "Performance and Repeated Work"): the field of a
// double-precision factorization (Eigen's LDL^*), to 1e-9 radians, with the
// same singular faces; the class's second guidance field on the kept factor
// also equals a fresh call's.
static void check_refined_aligned_field(Test_report& report)
{
  Mesh mesh;
  make_lumpy_sphere(mesh, 5);
  typedef Eigen::SparseMatrix<std::complex<double> > Complex_matrix;
  typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Complex_matrix> > Ldlt;
  auto d1 = direction_map(mesh, "v:d1");
  auto d2 = direction_map(mesh, "v:d2");
  const auto curvature = SMDF::Principal_curvature_alignment::MAXIMUM;
  Singularities s1, s2;
  const SMDF::Direction_field_result refined = SMDF::compute_globally_optimal_directions(
    mesh, d1, params::degree(4).principal_curvature_alignment(curvature).singularities_output_iterator(std::back_inserter(s1)));
  const SMDF::Direction_field_result ldlt = SMDF::compute_globally_optimal_directions(
    mesh, d2,
    params::degree(4).principal_curvature_alignment(curvature).sparse_linear_solver(Ldlt()).singularities_output_iterator(
      std::back_inserter(s2)));
  double worst = 0.;
  for(Vertex_index v : mesh.vertices()) worst = (std::max)(worst, angle_mod(d1[v], d2[v], 4));
  std::sort(s1.begin(), s1.end());
  std::sort(s2.begin(), s2.end());
  report.check(worst < 1e-9 && s1 == s2 && !s1.empty() && refined.index_sum == 8,
               "aligned field refined from a single-precision factor: the field of a double-precision one (" +
                 std::to_string(worst) + " rad, " + std::to_string(s1.size()) + " singular faces)");
}

static void check_models_and_solvers(Test_report& report)
{
  Mesh mesh;
  make_icosphere(mesh, 3);
  for(Vertex_index v : mesh.vertices())
  {
    const Vector_3 p = mesh.point(v) - CGAL::ORIGIN;
    mesh.point(v) = CGAL::ORIGIN + (1. + 0.2 * std::sin(3. * p.x()) * std::cos(2. * p.y() + p.z())) * p;
  }
  auto dir = direction_map(mesh);
  const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(mesh, dir, params::degree(4));

  // Polyhedron_3 (no vertex ids: the index maps are made internally)
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
  typedef CGAL::Polyhedron_3<Epick> Polyhedron;
  Polyhedron poly;
  CGAL::copy_face_graph(mesh, poly);
  std::map<Polyhedron::Vertex_handle, Epick::Vector_3> poly_dir_storage;
  auto poly_dir = boost::make_assoc_property_map(poly_dir_storage);
  Singularities sing;
  std::vector<std::pair<Polyhedron::Facet_handle, int> > poly_sing;
  const SMDF::Direction_field_result rp = SMDF::compute_globally_optimal_directions(
    poly, poly_dir, params::degree(4).singularities_output_iterator(std::back_inserter(poly_sing)));
  report.check(std::abs(rp.components[0].eigenvalue.value() - r.components[0].eigenvalue.value()) <= 1e-9 * r.components[0].eigenvalue.value() &&
               rp.index_sum == r.index_sum && rp.number_of_singular_faces == r.number_of_singular_faces &&
               poly_sing.size() == rp.number_of_singular_faces && poly_dir_storage.size() == poly.size_of_vertices(),
               "Polyhedron_3 gives the same eigenvalue and singularities as Surface_mesh");

  // Other sparse solvers (the default is CHOLMOD when the build found it):
  // the same field up to the solver tolerance.
  auto compare_with = [&](auto solver, const std::string& name) {
    auto dir2 = mesh.add_property_map<Vertex_index, Vector_3>("v:direction_" + name, CGAL::NULL_VECTOR).first;
    const SMDF::Direction_field_result rl = SMDF::compute_globally_optimal_directions(
      mesh, dir2, params::degree(4).sparse_linear_solver(solver));
    double worst = 0.;
    for(Vertex_index v : mesh.vertices()) worst = (std::max)(worst, angle_mod(dir[v], dir2[v], 4));
    report.check(std::abs(rl.components[0].eigenvalue.value() - r.components[0].eigenvalue.value()) <= 1e-10 * r.components[0].eigenvalue.value() &&
                 worst < 1e-6, "sparse_linear_solver(" + name + ") gives the same field (" + std::to_string(worst) + " rad)");
  };
  typedef Eigen::SparseMatrix<std::complex<double> > Complex_matrix;
  compare_with(CGAL::Eigen_solver_traits<Eigen::SimplicialLLT<Complex_matrix> >(), "SimplicialLLT");
  compare_with(CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Complex_matrix> >(), "SimplicialLDLT");
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
  std::cout << "  default solver: CHOLMOD supernodal\n";
  compare_with(CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<Complex_matrix> >(), "CholmodSupernodalLLT");
  compare_with(SMDF::Cholmod_supernodal_solver(), "Cholmod_supernodal_solver");
#endif
  // A model of the concept that is not CGAL::Eigen_solver_traits: the generic
  // path (matrix copied, one right-hand side at a time).
  compare_with(Generic_ldlt_solver(), "generic SparseLinearAlgebraWithFactorTraits_d model");

  // The class for repeated work: every call, in any order of (n, s), gives the
  // field of a fresh free-function call (kept connection, matrices and
  // symbolic analyses must not leak from one call into the next).
  SMDF::Globally_optimal_direction_field<Mesh> field(mesh);
  bool same = true;
  std::string worst_case;
  for(const auto& ns : std::vector<std::pair<int, double> >{{4, 0.}, {4, 0.5}, {2, 0.5}, {4, 0.}, {1, -1.}, {4, 0.}})
  {
    auto d1 = mesh.add_property_map<Vertex_index, Vector_3>("v:class_a", CGAL::NULL_VECTOR).first;
    auto d2 = mesh.add_property_map<Vertex_index, Vector_3>("v:class_b", CGAL::NULL_VECTOR).first;
    const auto np = params::degree(ns.first).smoothness_parameter(ns.second);
    const SMDF::Direction_field_result a = field.compute(d1, np);
    const SMDF::Direction_field_result b = SMDF::compute_globally_optimal_directions(mesh, d2, np);
    double worst = 0.;
    for(Vertex_index v : mesh.vertices()) worst = (std::max)(worst, angle_mod(d1[v], d2[v], ns.first));
    const bool ok = std::abs(a.components[0].eigenvalue.value() - b.components[0].eigenvalue.value()) <=
                      1e-10 * std::abs(b.components[0].eigenvalue.value()) && worst < 1e-6 && a.index_sum == b.index_sum &&
                    a.number_of_singular_faces == b.number_of_singular_faces;
    if(!ok) worst_case += " (n=" + std::to_string(ns.first) + ", s=" + std::to_string(ns.second) + ")";
    same = same && ok;
  }
  report.check(same, "Globally_optimal_direction_field: six calls with changing (n, s) match the free function" +
                       worst_case);
}

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
// A solver given for one call (sparse_linear_solver) serves every component
// in turn. On a mesh of three components (10,242, 10,242 and 2,562
// vertices), it gives the default solver's smoothest field, bit for bit, and
// its curvature-aligned field (factored before the guidance by default, after
// it with a given solver: equal to rounding), each component with its own
// index sum. The aligned field of the second component was once solved with
// the first one's factorization (same size, same lambda_t: 4,204 singular
// faces instead of 16).
static void check_given_solver_per_component(Test_report& report)
{
  Mesh mesh;
  for(const auto& part_size : std::vector<std::pair<int, double> >{{5, 1.}, {5, 2.}, {4, 3.}})
  {
    Mesh part;
    make_icosphere(part, part_size.first, part_size.second);
    for(Vertex_index v : part.vertices())
    {
      const Vector_3 p = (part.point(v) - CGAL::ORIGIN) / part_size.second;
      part.point(v) = CGAL::ORIGIN + Vector_3(3. * part_size.second, 0., 0.) +
                      part_size.second * (1. + 0.2 * std::sin(3. * p.x()) * std::cos(2. * p.y() + p.z())) * p;
    }
    CGAL::copy_face_graph(part, mesh);
  }
  typedef Mesh::Property_map<Vertex_index, std::complex<double> > Coefficients;
  for(const bool aligned : {false, true})
  {
    Coefficients own = mesh.add_property_map<Vertex_index, std::complex<double> >("v:own").first;
    Coefficients given = mesh.add_property_map<Vertex_index, std::complex<double> >("v:given").first;
    auto dir = direction_map(mesh);
    const auto np = params::degree(4).principal_curvature_alignment(
      aligned ? SMDF::Principal_curvature_alignment::MAXIMUM : SMDF::Principal_curvature_alignment::NONE);
    const SMDF::Direction_field_result a =
      SMDF::compute_globally_optimal_directions(mesh, dir, np.vertex_coefficient_map(own));
    const SMDF::Direction_field_result b = SMDF::compute_globally_optimal_directions(
      mesh, dir, np.vertex_coefficient_map(given).sparse_linear_solver(SMDF::Cholmod_supernodal_solver()));
    double difference = 0.;
    for(Vertex_index v : mesh.vertices()) difference = (std::max)(difference, std::abs(own[v] - given[v]));
    bool same = a.components.size() == 3 && b.components.size() == 3 && a.index_sum == b.index_sum &&
                a.number_of_singular_faces == b.number_of_singular_faces && difference <= (aligned ? 1e-12 : 0.);
    for(std::size_t c = 0; c < a.components.size() && c < b.components.size(); ++c)
      same = same && a.components[c].index_sum == 8 && b.components[c].index_sum == 8;
    report.check(same, std::string(aligned ? "aligned" : "smoothest") +
                         " field, three components: a given solver gives the default solver's field (" +
                         std::to_string(difference) + ")");
    mesh.remove_property_map(own);
    mesh.remove_property_map(given);
  }
}
#endif

// Without the named parameter degree, both functions compute cross fields
// (default_degree, the program's and the Python module's default too).
static void check_default_degree(Test_report& report)
{
  Mesh sphere;
  make_icosphere(sphere, 2);
  auto dir = direction_map(sphere);
  const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(sphere, dir);
  auto fdir = sphere.add_property_map<Mesh::Face_index, Vector_3>("f:direction").first;
  const SMDF::Face_direction_field_result rf = SMDF::compute_globally_optimal_face_directions(sphere, fdir);
  report.check(SMDF::default_degree == 4 && r.degree == 4 && r.index_sum == 8 && rf.degree == 4 && rf.index_sum == 8,
               "the default degree is 4 (a cross field: index sum 8 on a sphere)");
}

// The field depends on the vertex and face numbering only (user manual,
// "Conventions"): moving every face's halfedge(f) and every interior vertex's
// halfedge(v) gives the same digits, for the vertex field, the face field and
// its matching, on a closed and an open mesh.
static void check_halfedge_independence(Test_report& report, const Mesh& base, const std::string& name)
{
  Mesh moved = base;
  for(auto f : moved.faces()) moved.set_halfedge(f, moved.next(moved.halfedge(f)));
  for(Vertex_index v : moved.vertices())
    if(!moved.is_border(v)) moved.set_halfedge(v, moved.opposite(moved.next(moved.halfedge(v))));
  std::array<const Mesh*, 2> meshes = {&base, &moved};
  std::array<std::vector<Vector_3>, 2> vertex_dirs, face_dirs;
  std::array<std::vector<int>, 2> jumps;
  for(std::size_t i = 0; i < 2; ++i)
  {
    Mesh m = *meshes[i];
    auto dir = direction_map(m);
    SMDF::compute_globally_optimal_directions(m, dir, params::degree(4));
    for(Vertex_index v : m.vertices()) vertex_dirs[i].push_back(dir[v]);
    auto fdir = m.add_property_map<Mesh::Face_index, Vector_3>("f:direction").first;
    auto matching = m.add_property_map<Mesh::Edge_index, int>("e:matching", 0).first;
    SMDF::compute_globally_optimal_face_directions(m, fdir, params::degree(4).edge_matching_map(matching));
    for(auto f : m.faces()) face_dirs[i].push_back(fdir[f]);
    for(auto e : m.edges())  // the jump read along the edge's halfedge of the base mesh
      jumps[i].push_back(m.halfedge(e) == base.halfedge(e) ? matching[e] : -matching[e]);
  }
  const bool same_vertex_field = vertex_dirs[0] == vertex_dirs[1];
  const bool same_face_field = face_dirs[0] == face_dirs[1] && jumps[0] == jumps[1];
  report.check(same_vertex_field, name + ": halfedge(f), halfedge(v) moved: the same vertex field, bit for bit");
  report.check(same_face_field, name + ": halfedge(f), halfedge(v) moved: the same face field and matching");
}

// The matrices of energy_and_mass_matrices() act on the coefficients of
// vertex_coefficient_map (user manual, "Conventions"): the smoothest field's
// solve A u = lambda M u with the reported eigenvalue; A and M are Hermitian,
// |u| is the magnitude, and scaling the mesh by 10 scales M by 100, A not.
static void check_energy_and_mass_matrices(Test_report& report, const Mesh& base)
{
  typedef Eigen::SparseMatrix<std::complex<double> > Matrix;
  Mesh mesh = base;
  auto dir = direction_map(mesh);
  auto magnitude = mesh.add_property_map<Vertex_index, double>("v:magnitude", 0.).first;
  auto coefficient = mesh.add_property_map<Vertex_index, std::complex<double> >("v:coefficient").first;
  SMDF::Globally_optimal_direction_field<Mesh> field(mesh);
  const SMDF::Direction_field_result r =
    field.compute(dir, params::degree(5).smoothness_parameter(0.3).vertex_magnitude_map(magnitude)
                         .vertex_coefficient_map(coefficient));
  const std::pair<Matrix, Matrix> am = field.energy_and_mass_matrices(5, 0.3);
  Eigen::VectorXcd u(static_cast<Eigen::Index>(mesh.number_of_vertices()));
  bool lengths = true;
  for(Vertex_index v : mesh.vertices())
  {
    u[static_cast<Eigen::Index>(v.idx())] = coefficient[v];
    lengths = lengths && std::abs(std::abs(coefficient[v]) - magnitude[v]) <= 1e-14 * magnitude[v];
  }
  const double lambda = r.components[0].eigenvalue.value();
  const Eigen::VectorXcd mu = lambda * (am.second * u);
  const double residual = (am.first * u - mu).norm() / mu.norm();
  const Matrix a_adjoint = am.first.adjoint(), m_adjoint = am.second.adjoint();
  const bool hermitian = (am.first - a_adjoint).norm() == 0. && (am.second - m_adjoint).norm() == 0.;
  report.check(lengths && hermitian && residual < 1e-7,
               "energy_and_mass_matrices(): Hermitian, |u| the magnitude, A u = lambda M u (relative residual " +
                 std::to_string(residual) + ")");
  Mesh larger = base;
  for(Vertex_index v : larger.vertices()) larger.point(v) = CGAL::ORIGIN + 10. * (larger.point(v) - CGAL::ORIGIN);
  const std::pair<Matrix, Matrix> scaled =
    SMDF::Globally_optimal_direction_field<Mesh>(larger).energy_and_mass_matrices(5, 0.3);
  const double energy_change = (scaled.first - am.first).norm() / am.first.norm();
  const double mass_change = (scaled.second - 100. * am.second).norm() / (100. * am.second.norm());
  report.check(energy_change < 1e-12 && mass_change < 1e-12, "energy_and_mass_matrices(): M scales with area, A not");
  bool refused = false;
  try { field.energy_and_mass_matrices(0, 0.); }
  catch(const SMDF::Invalid_input_error&) { refused = true; }
  report.check(refused, "energy_and_mass_matrices(): degree 0 refused");
}

int main()
{
  Test_report report("fields");
  check_models_and_solvers(report);
  check_refined_aligned_field(report);
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
  check_given_solver_per_component(report);
#endif

  Mesh sphere, torus;
  make_icosphere(sphere, 4);
  make_torus(torus, 2., 0.7, 48, 20);
  check_poincare_hopf(report, "icosphere", sphere);
  check_poincare_hopf(report, "generated torus", torus);
  for(const char* const* name = closed_shared_meshes(); *name; ++name)
  {
    const std::string path = shared_mesh_path(*name);
    if(path.empty()) continue;
    Mesh mesh;
    if(!report.check(CGAL::IO::read_polygon_mesh(path, mesh), std::string("read ") + *name)) continue;
    check_poincare_hopf(report, *name, mesh, std::string(*name) == "bones.off");
  }

  // Unit, tangent, finite outputs on the shared meshes with one component.
  for(const char* const* list : {closed_shared_meshes(), open_shared_meshes()})
    for(const char* const* name = list; *name; ++name)
    {
      const std::string path = shared_mesh_path(*name);
      if(path.empty() || std::string(*name) == "nefertiti_sub4.off") continue;
      Mesh mesh;
      if(!report.check(CGAL::IO::read_polygon_mesh(path, mesh), std::string("read ") + *name)) continue;
      auto dir = direction_map(mesh);
      const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(mesh, dir, params::degree(4));
      std::cout << *name << ": |V| = " << mesh.number_of_vertices() << ", eigenvalue " << r.components[0].eigenvalue.value()
                << ", " << r.iterations << " iterations, residual " << r.residual << ", "
                << r.number_of_singular_faces << " singular faces\n";
      check_outputs(report, *name, mesh, dir, package_normals(mesh));
      bool eigenvalues_finite = true;
      for(const auto& c : r.components) eigenvalues_finite = eigenvalues_finite && c.eigenvalue && std::isfinite(*c.eigenvalue) && *c.eigenvalue > -1e-9;
      report.check(eigenvalues_finite, std::string(*name) + ": finite, non-negative eigenvalues");
    }

  check_flat_disk(report);
  check_torus_and_sphere(report);
  {
    const std::string path = shared_mesh_path("spot.off");
    Mesh spot;
    if(!path.empty() && CGAL::IO::read_polygon_mesh(path, spot)) check_invariance(report, spot, "spot");
    Mesh lumpy;
    make_icosphere(lumpy, 3);
    for(Vertex_index v : lumpy.vertices())  // a sphere with bumps: no symmetry
    {
      const Vector_3 p = lumpy.point(v) - CGAL::ORIGIN;
      lumpy.point(v) = CGAL::ORIGIN + (1. + 0.2 * std::sin(3. * p.x() + 1.) * std::cos(2. * p.y()) + 0.1 * p.z()) * p;
    }
    check_invariance(report, lumpy, "lumpy sphere");
    check_halfedge_independence(report, lumpy, "lumpy sphere");
    check_energy_and_mass_matrices(report, lumpy);
    Mesh disk;
    make_disk(disk, 12);
    for(Vertex_index v : disk.vertices())  // a curved cap
    {
      const Point_3 p = disk.point(v);
      disk.point(v) = Point_3(p.x(), p.y(), 0.3 * std::sin(2. * p.x()) * std::cos(p.y()));
    }
    check_halfedge_independence(report, disk, "disk");
  }
  check_bad_input(report);
  check_components_and_outputs(report);
  check_default_degree(report);
  return report.finish();
}
