// Any CGAL mesh, any input:
//  * mesh models: Surface_mesh with Epick and with Epeck, Polyhedron_3 with and
//    without item ids, points in a separate property map, outputs into
//    std::vector-backed and associative property maps; a minimal traits class
//    (the DirectionFieldTraits_3 concept, nothing more) compiles and agrees;
//  * hard meshes: zero-area, collinear and needle faces, coincident vertices,
//    angles down to 1e-3 degrees, boundary vertices with tiny and huge angle
//    sums, many boundary loops: no NaN, unit tangent outputs, Poincare-Hopf on
//    every closed component;
//  * the input mesh and its property maps are never modified.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cgal_compatibility.h>

#include "test_types.h"
#include "field_checks.h"
#include "generated_meshes.h"
#include "test_support.h"

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <iterator>
#include <map>
#include <new>
#include <string>
#include <utility>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;

// Exactly the requirements of the concept DirectionFieldTraits_3.
struct Minimal_traits
{
  typedef double FT;
  typedef Kernel::Point_3 Point_3;
  typedef Kernel::Vector_3 Vector_3;
  struct Compute_x_3
  {
    FT operator()(const Point_3& p) const { return p.x(); }
    FT operator()(const Vector_3& v) const { return v.x(); }
  };
  struct Compute_y_3
  {
    FT operator()(const Point_3& p) const { return p.y(); }
    FT operator()(const Vector_3& v) const { return v.y(); }
  };
  struct Compute_z_3
  {
    FT operator()(const Point_3& p) const { return p.z(); }
    FT operator()(const Vector_3& v) const { return v.z(); }
  };
  struct Construct_vector_3
  {
    Vector_3 operator()(FT x, FT y, FT z) const { return Vector_3(x, y, z); }
  };
  Compute_x_3 compute_x_3_object() const { return Compute_x_3(); }
  Compute_y_3 compute_y_3_object() const { return Compute_y_3(); }
  Compute_z_3 compute_z_3_object() const { return Compute_z_3(); }
  Construct_vector_3 construct_vector_3_object() const { return Construct_vector_3(); }
};

static void check_models(Test_report& report)
{
  Mesh mesh;
  make_lumpy_sphere(mesh, 3);
  auto dir = mesh.add_property_map<Vertex_index, Vector_3>("v:direction", CGAL::NULL_VECTOR).first;
  auto magnitude = mesh.add_property_map<Vertex_index, double>("v:magnitude", 0.).first;
  std::vector<std::pair<Face_index, int> > singularities;
  const SMDF::Direction_field_result ref = SMDF::compute_globally_optimal_directions(
    mesh, dir, params::degree(3).vertex_magnitude_map(magnitude).singularities_output_iterator(std::back_inserter(singularities)));
  const double lambda = ref.components[0].eigenvalue.value();
  auto same_field = [&](auto get_direction) {
    double worst = 0.;
    for(Vertex_index v : mesh.vertices())
    {
      const auto d = get_direction(v);
      worst = (std::max)(worst, angle_mod(dir[v], Vector_3(CGAL::to_double(d.x()), CGAL::to_double(d.y()),
                                                            CGAL::to_double(d.z())), 3));
    }
    return worst < 1e-9;
  };

  { // Epeck. The vertex order is kept but the halfedges differ, so the
    // reference directions and hence the global phase of the eigenvector may
    // differ: compare what does not depend on it (magnitudes, singularities).
    typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
    typedef CGAL::Surface_mesh<Epeck::Point_3> Exact_mesh;
    Exact_mesh exact;
    std::map<Vertex_index, Exact_mesh::Vertex_index> v2v;
    CGAL::copy_face_graph(mesh, exact, params::vertex_to_vertex_output_iterator(std::inserter(v2v, v2v.end())));
    auto edir = exact.add_property_map<Exact_mesh::Vertex_index, Epeck::Vector_3>("v:d").first;
    std::vector<double> emag(num_vertices(exact));
    std::vector<std::pair<Exact_mesh::Face_index, int> > esing;
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
      exact, edir, params::degree(3).singularities_output_iterator(std::back_inserter(esing))
                     .vertex_magnitude_map(boost::make_iterator_property_map(emag.begin(), get(CGAL::vertex_index, exact))));
    report.check(std::abs(r.components[0].eigenvalue.value() - lambda) <= 1e-12 * lambda, "Epeck: same eigenvalue");
    double worst = 0.;
    for(Vertex_index v : mesh.vertices()) worst = (std::max)(worst, std::abs(emag[std::size_t(v2v[v])] - magnitude[v]));
    report.check(worst < 1e-8 && esing.size() == singularities.size() && r.index_sum == ref.index_sum,
                 "Epeck: same magnitudes and singularities (" + std::to_string(worst) + ")");
    bool unit = true;
    for(auto v : exact.vertices())
      unit = unit && std::abs(CGAL::to_double(edir[v].squared_length()) - 1.) < 1e-12;
    report.check(unit, "Epeck: unit outputs");
  }
  { // Polyhedron_3 with item ids, given as index maps
    typedef CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3> Polyhedron;
    Polyhedron poly;
    std::map<Vertex_index, Polyhedron::Vertex_handle> v2v;
    CGAL::copy_face_graph(mesh, poly, params::vertex_to_vertex_output_iterator(std::inserter(v2v, v2v.end())));
    std::size_t i = 0;
    for(auto v : vertices(poly)) v->id() = i++;
    i = 0;
    for(auto f : faces(poly)) f->id() = i++;
    std::vector<Vector_3> pdir(num_vertices(poly));
    auto pdir_map = boost::make_iterator_property_map(pdir.begin(), get(CGAL::vertex_index, poly));
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
      poly, pdir_map, params::degree(3).vertex_index_map(get(CGAL::vertex_index, poly))
                                      .face_index_map(get(CGAL::face_index, poly)));
    report.check(std::abs(r.components[0].eigenvalue.value() - lambda) <= 1e-12 * lambda &&
                 r.index_sum == ref.index_sum, "Polyhedron_3 with ids, std::vector output: same eigenvalue");
    std::vector<double> pmag(num_vertices(poly));
    SMDF::compute_globally_optimal_directions(
      poly, pdir_map, params::degree(3).vertex_index_map(get(CGAL::vertex_index, poly))
                                      .face_index_map(get(CGAL::face_index, poly))
                                      .vertex_magnitude_map(boost::make_iterator_property_map(pmag.begin(), get(CGAL::vertex_index, poly))));
    double worst = 0.;
    for(Vertex_index v : mesh.vertices()) worst = (std::max)(worst, std::abs(pmag[v2v[v]->id()] - magnitude[v]));
    report.check(worst < 1e-8, "Polyhedron_3 with ids: same magnitudes (" + std::to_string(worst) + ")");
  }
  { // Polyhedron_3 without ids, associative output
    typedef CGAL::Polyhedron_3<Kernel> Polyhedron;
    Polyhedron poly;
    CGAL::copy_face_graph(mesh, poly);
    std::map<Polyhedron::Vertex_handle, Vector_3> storage;
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
      poly, boost::make_assoc_property_map(storage), params::degree(3));
    report.check(std::abs(r.components[0].eigenvalue.value() - lambda) <= 1e-12 * lambda && storage.size() == num_vertices(mesh),
                 "Polyhedron_3 without ids, associative output: same eigenvalue");
  }
  { // points in a separate property map; the mesh's own points are garbage
    Mesh garbage = mesh;
    std::vector<Point_3> points(num_vertices(mesh));
    for(Vertex_index v : mesh.vertices()) { points[v] = mesh.point(v); garbage.point(v) = Point_3(0, 0, 0); }
    auto gdir = garbage.add_property_map<Vertex_index, Vector_3>("v:d").first;
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
      garbage, gdir, params::degree(3).vertex_point_map(
        boost::make_iterator_property_map(points.begin(), get(CGAL::vertex_index, garbage))));
    report.check(std::abs(r.components[0].eigenvalue.value() - lambda) <= 1e-12 * lambda, "vertex_point_map: same eigenvalue");
    report.check(same_field([&](Vertex_index v) { return gdir[v]; }), "vertex_point_map: same field");
  }
  { // the minimal traits class
    auto mdir = mesh.add_property_map<Vertex_index, Vector_3>("v:minimal", CGAL::NULL_VECTOR).first;
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
      mesh, mdir, params::degree(3).geom_traits(Minimal_traits()));
    report.check(r.components[0].eigenvalue.value() == lambda && same_field([&](Vertex_index v) { return mdir[v]; }),
                 "a minimal model of DirectionFieldTraits_3 gives the same field");
  }
}

// No NaN, unit tangent outputs, Poincare-Hopf per closed component, and the
// input left as it was.
static void check_hard_mesh(Test_report& report, const std::string& name, Mesh& mesh, bool expect_mollification)
{
  const Mesh before = mesh;
  for(int n : {1, 2, 4})
  {
    auto dir = mesh.add_property_map<Vertex_index, Vector_3>("v:direction", CGAL::NULL_VECTOR).first;
    auto magnitude = mesh.add_property_map<Vertex_index, double>("v:magnitude", -1.).first;
    SMDF::Direction_field_result r;
    try
    {
      r = SMDF::compute_globally_optimal_directions(mesh, dir, params::degree(n).vertex_magnitude_map(magnitude));
    }
    catch(const std::exception& e)
    {
      report.check(false, name + ": unexpected exception: " + e.what());
      continue;
    }
    bool ok = true;
    for(Vertex_index v : mesh.vertices())
    {
      const Vector_3 d = dir[v];
      if(mesh.is_isolated(v)) { ok = ok && d == CGAL::NULL_VECTOR; continue; }
      ok = ok && std::isfinite(d.x()) && std::isfinite(d.y()) && std::isfinite(d.z()) &&
           std::abs(d.squared_length() - 1.) < 1e-12 && std::isfinite(magnitude[v]);
    }
    report.check(ok, name + ": finite unit outputs, n = " + std::to_string(n));
    bool poincare_hopf = true, finite = true;
    for(const auto& c : r.components)
    {
      finite = finite && (!c.eigenvalue || std::isfinite(*c.eigenvalue)) && std::isfinite(c.residual);
      if(c.is_closed) poincare_hopf = poincare_hopf && c.index_sum == n * c.euler_characteristic;
    }
    report.check(finite, name + ": finite eigenvalues and residuals, n = " + std::to_string(n));
    report.check(poincare_hopf, name + ": Poincare-Hopf on every closed component, n = " + std::to_string(n));
    report.check((r.mollification > 0.) == expect_mollification,
                 name + (expect_mollification ? ": mollified" : ": not mollified") + " (" + std::to_string(r.mollification) + ")");
    mesh.remove_property_map(dir);
    mesh.remove_property_map(magnitude);
  }
  bool same = mesh.number_of_vertices() == before.number_of_vertices() && mesh.number_of_faces() == before.number_of_faces();
  for(Vertex_index v : mesh.vertices()) same = same && mesh.point(v) == before.point(v);
  for(Face_index f : mesh.faces()) same = same && mesh.halfedge(f) == before.halfedge(f);
  report.check(same, name + ": the mesh is not modified");
}

// The message of the Invalid_input_error a cross field of `m` throws ("" if none).
static std::string refusal_of(Mesh& m)
{
  auto dir = m.add_property_map<Vertex_index, Vector_3>("v:direction").first;
  try
  {
    SMDF::compute_globally_optimal_directions(m, dir, CGAL::parameters::degree(4));
  }
  catch(const SMDF::Invalid_input_error& e)
  {
    return e.what();
  }
  return "";
}

static void check_hard_meshes(Test_report& report)
{
  { // every point on one line: no face has an area, a clear error (not a field of needles)
    Mesh m;
    make_icosphere(m, 2);
    Mesh ball;
    make_icosphere(ball, 1);
    for(Vertex_index v : m.vertices()) m.point(v) = Point_3(m.point(v).x(), 0., 0.);
    std::size_t offset = m.number_of_vertices();  // and a sound second component: the error names the first
    for(Vertex_index v : ball.vertices()) m.add_vertex(ball.point(v) + Vector_3(5., 0., 0.));
    for(Face_index f : ball.faces())
    {
      std::vector<Vertex_index> vs;
      for(Vertex_index v : CGAL::vertices_around_face(ball.halfedge(f), ball)) vs.push_back(Vertex_index(Mesh::size_type(offset + std::size_t(v))));
      m.add_face(vs);
    }
    const std::string message = refusal_of(m);
    report.check(message.find("component 0 has no area") != std::string::npos, "all points on a line: " + message);
  }
  { // a vertex moved exactly onto an edge's midpoint: a zero-area face in a closed mesh
    Mesh m;
    make_icosphere(m, 2);
    auto h = m.halfedge(Face_index(10));
    m.point(m.target(m.next(h))) = CGAL::midpoint(m.point(m.source(h)), m.point(m.target(h)));
    check_hard_mesh(report, "collinear face", m, true);
  }
  { // two vertices at the same position: a zero-length edge, two zero-area faces
    Mesh m;
    make_icosphere(m, 2);
    auto h = m.halfedge(Face_index(3));
    m.point(m.target(h)) = m.point(m.source(h));
    check_hard_mesh(report, "coincident vertices", m, true);
  }
  { // slivers with angles down to 1e-3 degrees (no mollification needed)
    Mesh m;
    make_disk(m, 6);
    const double tiny = 1e-3 * CGAL_PI / 180.;
    // a fan of thin triangles around an extra vertex on the rim
    std::vector<Vertex_index> rim;
    for(int k = 0; k <= 8; ++k)
      rim.push_back(m.add_vertex(Point_3(3. + std::cos(k * tiny), std::sin(k * tiny), 0.)));
    const Vertex_index apex = m.add_vertex(Point_3(3., 0., 0.));
    for(int k = 0; k < 8; ++k) m.add_face(apex, rim[k], rim[k + 1]);
    check_hard_mesh(report, "1e-3 degree slivers", m, false);
  }
  { // boundary vertices with tiny and huge angle sums: a thin spike and a pleated fan
    Mesh m;
    const Vertex_index c = m.add_vertex(Point_3(0, 0, 0));
    std::vector<Vertex_index> ring;
    const int k = 24;  // 24 corners of ~25 degrees zig-zagging: angle sum ~ 600 degrees
    for(int i = 0; i <= k; ++i)
    {
      const double a = 1.9 * CGAL_PI * i / k;
      ring.push_back(m.add_vertex(Point_3(std::cos(a), std::sin(a), (i % 2) ? 0.8 : -0.8)));
    }
    for(int i = 0; i < k; ++i) m.add_face(c, ring[i], ring[i + 1]);
    const Vertex_index spike = m.add_vertex(Point_3(40., 0.2, 0.));  // ~0.3 degree boundary corner
    m.add_face(ring[0], spike, ring[1]);
    check_hard_mesh(report, "tiny and huge boundary angle sums", m, false);
  }
  { // removed elements not collected: a clear error, never an access past the arrays
    Mesh m;
    make_icosphere(m, 2);
    CGAL::Euler::remove_face(m.halfedge(Face_index(3)), m);
    CGAL::Euler::remove_face(m.halfedge(Face_index(100)), m);
    const std::string message = refusal_of(m);
    report.check(message.find("collect_garbage()") != std::string::npos, "removed faces not collected: " + message);
    m.collect_garbage();
    auto collected = SMDF::internal::find_property_map<Vertex_index, Vector_3>(m, "v:direction").value();
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(m, collected, CGAL::parameters::degree(4));
    report.check(r.components.size() == 1 && !r.components[0].is_closed, "after collect_garbage(): computed");
  }
  { // many boundary loops, several components, an isolated vertex
    Mesh m;
    make_torus(m, 2., 0.7, 40, 16);
    std::vector<Face_index> holes;
    for(Face_index f : m.faces())
      if(std::size_t(f) % 37 == 0) holes.push_back(f);
    for(Face_index f : holes) CGAL::Euler::remove_face(m.halfedge(f), m);
    m.collect_garbage();
    Mesh sphere;
    make_icosphere(sphere, 2);
    for(Vertex_index v : sphere.vertices()) sphere.point(v) = sphere.point(v) + Vector_3(6, 0, 0);
    CGAL::copy_face_graph(sphere, m);
    m.add_vertex(Point_3(-9, -9, -9));
    check_hard_mesh(report, "many holes, two components, isolated vertex", m, false);
  }
  for(const char* name : {"blade.off", "plane_holes.off", "bones.off"})
  {
    const std::string path = shared_mesh_path(name);
    Mesh m;
    if(!path.empty() && report.check(CGAL::IO::read_polygon_mesh(path, m), std::string("read ") + name))
      check_hard_mesh(report, name, m, false);
  }
}

// The degree's documented range: 1 to maximum_degree; beyond, a clear error.
static void check_degree_range(Test_report& report)
{
  Mesh mesh;
  make_icosphere(mesh, 1);
  auto dir = mesh.add_property_map<Vertex_index, Vector_3>("v:direction", CGAL::NULL_VECTOR).first;
  for(int n : {0, SMDF::maximum_degree + 1})
  {
    bool refused = false;
    try { SMDF::compute_globally_optimal_directions(mesh, dir, params::degree(n)); }
    catch(const SMDF::Invalid_input_error&) { refused = true; }
    report.check(refused, "degree " + std::to_string(n) + " is refused with Invalid_input_error");
  }
  const SMDF::Direction_field_result r =
    SMDF::compute_globally_optimal_directions(mesh, dir, params::degree(SMDF::maximum_degree));
  report.check(r.index_sum == 2LL * SMDF::maximum_degree,
               "degree maximum_degree: the index sum n chi = " + std::to_string(2LL * SMDF::maximum_degree) + " exactly");
}

// Coordinates at any scale: the same singular faces and directions as the
// unscaled mesh, the eigenvalue scaled by 1 / factor^2 (where a double holds
// it), the mollification by factor.
static void check_any_scale(Test_report& report)
{
  typedef std::vector<std::pair<Face_index, int> > Singular;
  auto solve = [](Mesh& m, Singular& singular) {
    auto dir = m.add_property_map<Vertex_index, Vector_3>("v:direction").first;
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
      m, dir, CGAL::parameters::degree(4).singularities_output_iterator(std::back_inserter(singular)));
    return r;
  };
  Mesh base;
  make_lumpy_sphere(base, 3);
  Singular base_singular;
  const SMDF::Direction_field_result unscaled = solve(base, base_singular);
  const auto base_dir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(base, "v:direction").value();
  for(double factor : {1e-310, 1e-300, 1e-150, 1e-80, 1e80, 1e150, 1e300})
  {
    Mesh m = base;
    auto old_dir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(m, "v:direction").value();
    m.remove_property_map(old_dir);
    for(Vertex_index v : m.vertices()) m.point(v) = CGAL::ORIGIN + factor * (base.point(v) - CGAL::ORIGIN);
    Singular singular;
    std::string error;
    SMDF::Direction_field_result r;
    try { r = solve(m, singular); }
    catch(const std::exception& e) { error = e.what(); }
    const std::string name = "scaled by " + std::to_string(factor);
    if(!report.check(error.empty(), name + ": computed (" + error + ")")) continue;
    report.check(singular == base_singular, name + ": the same singular faces");
    const auto dir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(m, "v:direction").value();
    double worst = 0.;
    for(Vertex_index v : m.vertices()) worst = (std::max)(worst, std::sqrt((dir[v] - base_dir[v]).squared_length()));
    report.check(worst < 1e-6, name + ": the same directions (" + std::to_string(worst) + ")");
    const double expected = unscaled.components[0].eigenvalue.value() / factor / factor;
    if(std::isfinite(expected) && expected > 1e-290)
      report.check(std::abs(r.components[0].eigenvalue.value() / expected - 1.) < 1e-6, name + ": the eigenvalue scales");
  }
}

// Out of memory in one half of the package's parallel_invoke() leaves the
// other half's parallel loops complete (an exception reaching TBB would cancel
// them, and they would return with iterations not run), and is rethrown.
static void check_parallel_invoke_exceptions(Test_report& report)
{
  namespace I = CGAL::Surface_mesh_direction_fields::internal;
  const int rounds = 20;
  std::vector<int> done(std::size_t(1) << 20, 0);
  bool thrown = false;
  try
  {
    I::parallel_invoke([] { throw std::bad_alloc(); },
                       [&] {
                         for(int round = 0; round < rounds; ++round)
                           I::parallel_for_each_index(done.size(), [&](std::size_t i) { ++done[i]; });
                       });
  }
  catch(const std::bad_alloc&)
  {
    thrown = true;
  }
  const bool complete = std::all_of(done.begin(), done.end(), [&](int d) { return d == rounds; });
  report.check(thrown && complete, "parallel_invoke: an exception in one half is rethrown, the other half's loops complete");
}

int main()
{
  Test_report report("robustness");
  check_parallel_invoke_exceptions(report);
  check_any_scale(report);
  check_degree_range(report);
  check_models(report);
  check_hard_meshes(report);
  return report.finish();
}
