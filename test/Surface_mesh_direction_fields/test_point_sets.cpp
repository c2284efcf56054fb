// Fields on point sets (user manual, section "Point Sets"): discrete
// Poincare-Hopf on the agreed triangles of sampled spheres and tori, the
// mesh's field from the mesh's own vertices, invariance under rigid motions,
// scaling and the order of the points, estimated against given normals, and
// the refusals (too few points, points on a line, bad options).

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Point_set_3.h>
#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/globally_optimal_point_set_directions.h>

#include "test_types.h"
#include "generated_meshes.h"
#include "test_support.h"

#include <algorithm>
#include <array>
#include <complex>
#include <cmath>
#include <functional>
#include <iostream>
#include <random>
#include <string>
#include <vector>

typedef CGAL::Point_set_3<Point_3, Vector_3> Point_set;
namespace SMDF = CGAL::Surface_mesh_direction_fields;

namespace {

Test_report report("test_point_sets");

struct Cloud_field
{
  SMDF::Point_set_direction_field_result result;
  std::vector<Vector_3> directions;
};

// The field of `points` (whose normals are used when `with_normals`).
Cloud_field cloud_field(const Point_set& points, int n, bool with_normals = true,
                        unsigned k = SMDF::default_number_of_neighbors)
{
  Cloud_field field;
  Point_set copy = points;  // the function reads a const range; the copy gets the output map
  auto direction_map = copy.add_property_map<Vector_3>("direction", Vector_3(0, 0, 0)).first;
  auto np = params::point_map(copy.point_map()).degree(n).number_of_neighbors(k);
  if(with_normals)
    field.result = SMDF::compute_globally_optimal_point_set_directions(copy, direction_map, np.normal_map(copy.normal_map()));
  else
    field.result = SMDF::compute_globally_optimal_point_set_directions(copy, direction_map, np);
  for(auto i : copy) field.directions.push_back(direction_map[i]);
  return field;
}

long index_sum(const SMDF::Point_set_direction_field_result& r)
{
  long sum = 0;
  for(const auto& s : r.singular_triangles) sum += s.second;
  return sum;
}

// N points of the unit sphere (Fibonacci spiral), with their normals.
Point_set fibonacci_sphere(std::size_t N)
{
  Point_set points(true);
  const double golden = CGAL_PI * (3. - std::sqrt(5.));
  for(std::size_t i = 0; i < N; ++i)
  {
    const double z = 1. - (2. * i + 1.) / N, r = std::sqrt(1. - z * z), phi = golden * i;
    const Point_3 p(r * std::cos(phi), r * std::sin(phi), z);
    points.insert(p, p - CGAL::ORIGIN);
  }
  return points;
}

// Random points of a torus (uniform in its two angles, jittered), with normals.
Point_set random_torus(std::size_t N, double R, double r, unsigned seed)
{
  Point_set points(true);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> angle(0., 2. * CGAL_PI);
  for(std::size_t i = 0; i < N; ++i)
  {
    const double u = angle(rng), v = angle(rng);
    const Vector_3 n(std::cos(u) * std::cos(v), std::sin(u) * std::cos(v), std::sin(v));
    const Point_3 c(R * std::cos(u), R * std::sin(u), 0.);
    points.insert(c + r * n, n);
  }
  return points;
}

// The points of a nu x nv grid in the torus's two angles, each moved by up to
// `jitter` of a grid step, with normals.
Point_set grid_torus(int nu, int nv, double R, double r, double jitter, unsigned seed)
{
  Point_set points(true);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-jitter, jitter);
  for(int a = 0; a < nu; ++a)
    for(int b = 0; b < nv; ++b)
    {
      const double u = 2. * CGAL_PI * (a + shift(rng)) / nu, v = 2. * CGAL_PI * (b + shift(rng)) / nv;
      const Vector_3 n(std::cos(u) * std::cos(v), std::sin(u) * std::cos(v), std::sin(v));
      points.insert(Point_3(R * std::cos(u), R * std::sin(u), 0.) + r * n, n);
    }
  return points;
}

// The share of points where the fields a and b (degree n) differ by less than
// `degrees`, among the `counted` points, once b is turned by the one angle
// that best matches a: a smoothest field is defined up to such a turn.
double share_within(const std::vector<Vector_3>& a, const std::vector<Vector_3>& b,
                    const std::vector<std::array<double, 3> >& normals, int n, double degrees,
                    const std::vector<bool>& counted)
{
  std::vector<double> turn(a.size(), 0.);
  std::complex<double> mean(0., 0.);
  for(std::size_t i = 0; i < a.size(); ++i)
  {
    const Vector_3 normal(normals[i][0], normals[i][1], normals[i][2]);
    const Vector_3 pa = a[i] - (a[i] * normal) * normal, pb = b[i] - (b[i] * normal) * normal;
    turn[i] = n * std::atan2(CGAL::cross_product(pa, pb) * normal, pa * pb);  // the n-th power's turn
    if(counted[i]) mean += std::polar(1., turn[i]);
  }
  std::size_t within = 0, total = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
  {
    if(!counted[i]) continue;
    ++total;
    if(std::abs(std::arg(std::polar(1., turn[i]) / mean)) / n < degrees * CGAL_PI / 180.) ++within;
  }
  return total ? double(within) / total : 0.;
}

// On the surface triangles of a closed sampled surface the indices add up to n chi.
void test_poincare_hopf()
{
  for(int n : {1, 2, 4, 5})
  {
    for(std::size_t N : {500, 3000})
    {
      const Cloud_field sphere = cloud_field(fibonacci_sphere(N), n);
      report.check(sphere.result.surface_is_closed && sphere.result.surface_euler_characteristic == 2,
                   "the sphere's surface triangles close up, chi = 2 (N = " + std::to_string(N) + ")");
      report.check(index_sum(sphere.result) == 2 * n, "sphere: index sum " + std::to_string(index_sum(sphere.result)) +
                                                        " = 2n, n = " + std::to_string(n));
      report.check(sphere.result.components.size() == 1 && sphere.result.number_of_points_without_triangles == 0,
                   "sphere: one component, every point in a triangle");
      // the smallest eigenvalue of the round sphere's energy E_0 tends to n (user manual)
      report.check(std::abs(sphere.result.components[0].eigenvalue.value() - n) < (N < 1000 ? 0.12 : 0.03) * n,
                   "sphere: eigenvalue " + std::to_string(sphere.result.components[0].eigenvalue.value()) + " near n");
    }
    const Cloud_field torus = cloud_field(grid_torus(60, 25, 1., 0.4, 0.3, 7), n);
    report.check(torus.result.surface_is_closed && torus.result.surface_euler_characteristic == 0,
                 "the torus's surface triangles close up, chi = 0");
    report.check(index_sum(torus.result) == 0, "torus: index sum " + std::to_string(index_sum(torus.result)) + " = 0");
  }
}

// The points of a mesh give the mesh's field.
void test_mesh_vertices()
{
  Mesh mesh;
  make_lumpy_sphere(mesh, 4);
  for(int n : {1, 4})
  {
    auto mesh_dir = mesh.add_property_map<Mesh::Vertex_index, Vector_3>("v:dir").first;
    auto mesh_u = mesh.add_property_map<Mesh::Vertex_index, std::complex<double> >("v:u").first;
    std::vector<std::pair<Mesh::Face_index, int> > singular;
    const auto mesh_result = SMDF::compute_globally_optimal_directions(
      mesh, mesh_dir, params::degree(n).vertex_coefficient_map(mesh_u).singularities_output_iterator(std::back_inserter(singular)));
    Point_set points(false);
    for(auto v : mesh.vertices()) points.insert(mesh.point(v));
    const Cloud_field cloud = cloud_field(points, n, false);
    double largest = 0.;
    for(auto v : mesh.vertices()) largest = (std::max)(largest, std::abs(mesh_u[v]));
    std::vector<bool> counted;
    std::vector<Vector_3> mesh_directions;
    for(auto v : mesh.vertices())
    {
      counted.push_back(std::abs(mesh_u[v]) > 0.1 * largest);
      mesh_directions.push_back(mesh_dir[v]);
    }
    const double share = share_within(mesh_directions, cloud.directions, cloud.result.normals, n, 5., counted);
    const double lambda_mesh = mesh_result.components[0].eigenvalue.value(), lambda_cloud = cloud.result.components[0].eigenvalue.value();
    std::cout << "lumpy sphere, n = " << n << ": " << 100. * share << "% of directions within 5 degrees, eigenvalue "
              << lambda_cloud << " against the mesh's " << lambda_mesh << ", singular " << cloud.result.singular_triangles.size()
              << " against " << singular.size() << std::endl;
    report.check(share >= 0.95, "lumpy sphere: 95% of the directions within 5 degrees of the mesh's");
    report.check(std::abs(lambda_cloud - lambda_mesh) < 0.05 * lambda_mesh, "lumpy sphere: eigenvalue within 5%");
    report.check(index_sum(cloud.result) == 2 * n && cloud.result.surface_is_closed, "lumpy sphere: index sum 2n");
    mesh.remove_property_map(mesh_dir);
    mesh.remove_property_map(mesh_u);
  }
}

// A rigid motion and a scaling move the field with the points.
void test_invariance()
{
  const Point_set sphere = fibonacci_sphere(1500);
  const Cloud_field original = cloud_field(sphere, 4);
  const double c = std::cos(0.7), s = std::sin(0.7);
  for(double scale : {1., 1e-9, 1e12})
  {
    Point_set moved(true);
    auto rotate = [&](const Vector_3& v) { return Vector_3(c * v.x() - s * v.y(), s * v.x() + c * v.y(), v.z()); };
    for(auto i : sphere)
      moved.insert(Point_3(3, -2, 5) + scale * rotate(sphere.point(i) - CGAL::ORIGIN), rotate(sphere.normal(i)));
    const Cloud_field field = cloud_field(moved, 4);
    double worst = 0.;
    for(std::size_t i = 0; i < original.directions.size(); ++i)
      worst = (std::max)(worst, std::sqrt((rotate(original.directions[i]) - field.directions[i]).squared_length()));
    report.check(worst < 1e-4, "rotated, moved and scaled by " + std::to_string(scale) + ": the same field (" +
                                 std::to_string(worst) + ")");
    report.check(field.result.singular_triangles == original.result.singular_triangles,
                 "rotated, moved and scaled: the same singular triangles");
  }
  // beyond 2^100 the coordinates are scaled for the arithmetic: the eigenvalue is still the user's, 1 / R^2
  Point_set huge(true);
  for(auto i : sphere) huge.insert(CGAL::ORIGIN + 1e40 * (sphere.point(i) - CGAL::ORIGIN), sphere.normal(i));
  const double lambda = original.result.components[0].eigenvalue.value();
  const double huge_lambda = cloud_field(huge, 4).result.components[0].eigenvalue.value();
  report.check(std::abs(huge_lambda * 1e80 - lambda) < 1e-8 * lambda,
               "scaled by 1e40: the eigenvalue scaled by 1e-80 (" + std::to_string(huge_lambda * 1e80) + ")");
}

// The angle, modulo 2 pi / n, from direction d to the tangent part of w at a point of normal `normal`.
double angle_to(const Vector_3& d, const Vector_3& w, const Vector_3& normal, int n)
{
  const Vector_3 t = w - (w * normal) * normal;
  return std::abs(std::remainder(n * std::atan2(CGAL::cross_product(d, t) * normal, d * t), 2. * CGAL_PI)) / n;
}

// A guidance vector per point gives the aligned field, as on a mesh.
void test_guidance()
{
  // a flat patch: the smoothest field is parallel, so a constant guidance is followed exactly
  Point_set plane(true);
  for(int i = 0; i < 30; ++i)
    for(int j = 0; j < 30; ++j)
      plane.insert(Point_3(i + 0.3 * std::sin(7. * j), j + 0.2 * std::cos(3. * i), 0.), Vector_3(0, 0, 1));
  auto guidance = plane.add_property_map<Vector_3>("guidance", Vector_3(0, 0, 0)).first;
  auto directions = plane.add_property_map<Vector_3>("direction", Vector_3(0, 0, 0)).first;
  for(auto i : plane) guidance[i] = Vector_3(std::cos(0.3), std::sin(0.3), 0.4);  // its tangent part counts
  const auto flat = SMDF::compute_globally_optimal_point_set_directions(
    plane, directions, plane.parameters().degree(4).point_guidance_map(guidance));
  double worst = 0.;
  for(auto i : plane) worst = (std::max)(worst, angle_to(directions[i], guidance[i], Vector_3(0, 0, 1), 4));
  report.check(worst < 1e-8 && flat.components.size() == 1 &&
                 flat.components[0].solve == SMDF::Field_solve::LINEAR_SOLVE,
               "a plane with a constant guidance: a linear solve, the guidance's directions (" +
                 std::to_string(worst) + ")");

  // a sphere guided along its parallels with weight 0.9: the field follows them away from the poles
  Point_set sphere = fibonacci_sphere(2000);
  auto along = sphere.add_property_map<Vector_3>("guidance", Vector_3(0, 0, 0)).first;
  auto field = sphere.add_property_map<Vector_3>("direction", Vector_3(0, 0, 0)).first;
  for(auto i : sphere) along[i] = Vector_3(-sphere.point(i).y(), sphere.point(i).x(), 0.);
  const auto np = sphere.parameters().degree(4).point_guidance_map(along);
  const auto guided = SMDF::compute_globally_optimal_point_set_directions(sphere, field, np.alignment_weight(0.9));
  std::size_t near = 0, counted = 0;
  for(auto i : sphere)
    if(along[i].squared_length() > 0.25)
    {
      ++counted;
      near += angle_to(field[i], along[i], sphere.normal(i), 4) < 5. * CGAL_PI / 180.;
    }
  const SMDF::Component_report& c = guided.components[0];
  report.check(near >= 0.95 * counted, "a sphere guided along its parallels: 95% within 5 degrees (" +
                                         std::to_string(near) + " of " + std::to_string(counted) + ")");
  report.check(std::abs(c.alignment_weight - 0.9) < 1e-3 && c.eigenvalue && c.lambda < *c.eigenvalue,
               "alignment_weight 0.9 reached (" + std::to_string(c.alignment_weight) + "), lambda_t below lambda_1");

  auto refused = [&](auto call, const std::string& what) {
    try
    {
      call();
    }
    catch(const SMDF::Invalid_input_error& e)
    {
      return report.check(std::string(e.what()).find('\n') == std::string::npos, what + ": " + e.what());
    }
    return report.check(false, what + " is refused");
  };
  refused([&] { SMDF::compute_globally_optimal_point_set_directions(sphere, field, np.alignment_lambda(1e6)); },
          "alignment_lambda above lambda_1");
  refused([&] { SMDF::compute_globally_optimal_point_set_directions(
                  sphere, field, sphere.parameters().alignment_weight(0.5)); }, "alignment_weight without guidance");
  along[*sphere.begin()] = Vector_3(std::nan(""), 0, 0);
  refused([&] { SMDF::compute_globally_optimal_point_set_directions(sphere, field, np); }, "a NaN guidance vector");
}

// Points of an open cylinder (radius 1, |z| <= 2) on a jittered grid, with outward normals.
Point_set cylinder(int around, int along, unsigned seed)
{
  Point_set points(true);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-0.3, 0.3);
  for(int a = 0; a < around; ++a)
    for(int b = 0; b <= along; ++b)
    {
      const double u = 2. * CGAL_PI * (a + shift(rng)) / around, z = -2. + 4. * (b + (b % along ? shift(rng) : 0.)) / along;
      points.insert(Point_3(std::cos(u), std::sin(u), z), Vector_3(std::cos(u), std::sin(u), 0.));
    }
  return points;
}

// Curvature alignment on points: the principal directions of a cylinder
// (maximum around it, minimum along it) and of a torus.
void test_curvature_alignment()
{
  Point_set points = cylinder(60, 40, 3);
  auto field = points.add_property_map<Vector_3>("direction", Vector_3(0, 0, 0)).first;
  for(auto which : {SMDF::Principal_curvature_alignment::MAXIMUM, SMDF::Principal_curvature_alignment::MINIMUM})
  {
    const bool maximum = which == SMDF::Principal_curvature_alignment::MAXIMUM;
    const auto r = SMDF::compute_globally_optimal_point_set_directions(
      points, field, points.parameters().degree(2).principal_curvature_alignment(which).alignment_weight(0.9));
    std::size_t near = 0, counted = 0;
    for(auto i : points)
    {
      if(std::abs(points.point(i).z()) > 1.5) continue;  // away from the rims
      ++counted;
      const Vector_3 around(-points.point(i).y(), points.point(i).x(), 0.);
      near += angle_to(field[i], maximum ? around : Vector_3(0, 0, 1), points.normal(i), 2) < 2. * CGAL_PI / 180.;
    }
    report.check(near == counted && std::abs(r.components[0].alignment_weight - 0.9) < 1e-3,
                 std::string("a cylinder's ") + (maximum ? "maximum" : "minimum") + "-curvature line field: " +
                   std::to_string(near) + " of " + std::to_string(counted) + " points within 2 degrees");
  }
  try
  {
    SMDF::compute_globally_optimal_point_set_directions(
      points, field, points.parameters().degree(3).principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM));
    report.check(false, "curvature alignment of an odd degree is refused");
  }
  catch(const SMDF::Invalid_input_error& e)
  {
    report.check(true, std::string("curvature alignment of an odd degree: ") + e.what());
  }

  // a torus sampled at random: the maximum curvature runs along the meridians (1 / r against cos v / (R + r cos v)),
  // with the given normals and with normals estimated by jet fitting (oriented outward by the spanning tree)
  const Point_set torus = random_torus(3000, 2., 1., 5);
  for(bool with_normals : {true, false})
  {
    Point_set copy(with_normals);
    for(auto i : torus) with_normals ? copy.insert(torus.point(i), torus.normal(i)) : copy.insert(torus.point(i));
    auto along = copy.add_property_map<Vector_3>("direction", Vector_3(0, 0, 0)).first;
    SMDF::compute_globally_optimal_point_set_directions(
      copy, along, copy.parameters().degree(2).principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM).alignment_weight(0.99));
    std::size_t near = 0;
    auto t = torus.begin();
    for(auto i : copy)
    {
      const Vector_3 n = torus.normal(*t), parallel(-torus.point(*t).y(), torus.point(*t).x(), 0.);
      ++t;
      near += angle_to(along[i], CGAL::cross_product(n, parallel), n, 2) < 3. * CGAL_PI / 180.;
    }
    report.check(near >= 0.99 * copy.size(), std::string("a random torus (normals ") +
                                                (with_normals ? "given" : "estimated") + "): " + std::to_string(near) +
                                                " of 3000 maximum-curvature directions within 3 degrees of the meridians");
  }
}

// Hard constraints on points: the field takes the given directions exactly,
// and on a flat patch one constrained point fixes the parallel field.
void test_constraints()
{
  Point_set plane(true);
  for(int i = 0; i < 25; ++i)
    for(int j = 0; j < 25; ++j)
      plane.insert(Point_3(i + 0.3 * std::sin(5. * j), j + 0.2 * std::cos(3. * i), 0.), Vector_3(0, 0, 1));
  auto fixed = plane.add_property_map<bool>("fixed", false).first;
  auto wanted = plane.add_property_map<Vector_3>("wanted", Vector_3(0, 0, 0)).first;
  auto directions = plane.add_property_map<Vector_3>("direction", Vector_3(0, 0, 0)).first;
  const auto first = *plane.begin();
  fixed[first] = true;
  wanted[first] = Vector_3(1e250 * std::cos(0.4), 1e250 * std::sin(0.4), 3e249);  // its tangent part's direction counts
  const auto np = plane.parameters().degree(4).point_is_constrained_map(fixed).point_constrained_direction_map(wanted);
  const auto r = SMDF::compute_globally_optimal_point_set_directions(plane, directions, np);
  double worst = 0.;
  for(auto i : plane) worst = (std::max)(worst, angle_to(directions[i], wanted[first], Vector_3(0, 0, 1), 4));
  report.check(worst < 1e-8 && r.components[0].solve == SMDF::Field_solve::LINEAR_SOLVE,
               "a plane with one constrained point: the parallel field through it (" + std::to_string(worst) + ")");

  Point_set sphere = fibonacci_sphere(1500);
  auto on = sphere.add_property_map<bool>("fixed", false).first;
  auto to = sphere.add_property_map<Vector_3>("wanted", Vector_3(0, 0, 0)).first;
  auto field = sphere.add_property_map<Vector_3>("direction", Vector_3(0, 0, 0)).first;
  std::vector<Point_set::Index> chosen;
  for(auto i : sphere)
    if(std::size_t(i) % 300 == 7)
    {
      chosen.push_back(i);
      on[i] = true;
      to[i] = CGAL::cross_product(sphere.normal(i), Vector_3(0.3, -0.5, 0.8)) + Vector_3(0.1 * std::size_t(i) / 300., 0, 0);
    }
  const auto guided = sphere.parameters().degree(4).point_is_constrained_map(on).point_constrained_direction_map(to);
  SMDF::compute_globally_optimal_point_set_directions(
    sphere, field, guided.principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM));
  double off = 0.;
  for(auto i : chosen) off = (std::max)(off, angle_to(field[i], to[i], sphere.normal(i), 4));
  report.check(off < 1e-12, "a sphere with five constrained points: their directions exactly (" + std::to_string(off) + ")");

  for(const Vector_3& bad : {Vector_3(0, 0, 0), Vector_3(std::nan(""), 0, 0)})
  {
    to[chosen[0]] = bad;
    try
    {
      SMDF::compute_globally_optimal_point_set_directions(sphere, field, guided);
      report.check(false, "a zero or NaN constrained direction is refused");
    }
    catch(const SMDF::Invalid_input_error& e)
    {
      report.check(std::string(e.what()).find("constrained direction of point") != std::string::npos,
                   std::string("a bad constrained direction: ") + e.what());
    }
  }
}

// Normals estimated by jet fitting give nearly the field of the exact normals.
void test_estimated_normals()
{
  const Point_set sphere = fibonacci_sphere(3000);
  const Cloud_field exact = cloud_field(sphere, 4), estimated = cloud_field(sphere, 4, false);
  const double share =
    share_within(exact.directions, estimated.directions, exact.result.normals, 4, 5., std::vector<bool>(3000, true));
  report.check(share >= 0.95, "estimated normals: 95% of the directions within 5 degrees (" + std::to_string(share) + ")");
  report.check(index_sum(estimated.result) == 8, "estimated normals: index sum 2n");

  // Point_set_3::parameters() names a normal map also where the point set has none: estimated, as without it
  Point_set bare(false);
  for(auto i : sphere) bare.insert(sphere.point(i));
  auto direction_map = bare.add_property_map<Vector_3>("direction", Vector_3(0, 0, 0)).first;
  const auto r = SMDF::compute_globally_optimal_point_set_directions(bare, direction_map, bare.parameters().degree(4));
  report.check(r.normals_estimated && r.singular_triangles == estimated.result.singular_triangles,
               "Point_set_3::parameters() without normals: the normals estimated");
}

// Repeated points share the field of their position; bad input is refused in one line.
void test_hostile_points()
{
  Point_set sphere = fibonacci_sphere(1000);
  Point_set doubled = sphere;
  for(std::size_t i = 0; i < 1000; i += 10) doubled.insert(sphere.point(*(sphere.begin() + i)), sphere.normal(*(sphere.begin() + i)));
  const Cloud_field field = cloud_field(doubled, 4);
  std::vector<Vector_3> originals, copies;
  for(std::size_t i = 0; i < 100; ++i)
  {
    originals.push_back(field.directions[10 * i]);
    copies.push_back(field.directions[1000 + i]);
  }
  std::vector<std::array<double, 3> > normals(field.result.normals.begin() + 1000, field.result.normals.end());
  report.check(share_within(originals, copies, normals, 4, 5., std::vector<bool>(100, true)) >= 0.95,
               "a repeated point gets the direction of its twin");
  report.check(field.result.number_of_points_without_triangles == 0, "repeated points: each in a triangle");

  auto refused = [](const Point_set& points, int n, unsigned k, const std::string& what) {
    try
    {
      cloud_field(points, n, points.has_normal_map(), k);
    }
    catch(const SMDF::Invalid_input_error& e)
    {
      const std::string message = e.what();
      return report.check(message.find('\n') == std::string::npos, what + ": one line (" + message + ")");
    }
    return report.check(false, what + " is refused");
  };
  Point_set two(false), line(false), nan(false);
  two.insert(Point_3(0, 0, 0));
  two.insert(Point_3(1, 0, 0));
  for(int i = 0; i < 50; ++i) line.insert(Point_3(i, 2 * i, 0));
  for(int i = 0; i < 50; ++i) nan.insert(Point_3(i, i * i, i == 7 ? std::nan("") : 0.));
  refused(two, 4, 16, "two points");
  refused(line, 4, 16, "points on a line");
  refused(nan, 4, 16, "a NaN coordinate");
  refused(sphere, 0, 16, "degree 0");
  refused(sphere, 4, 2, "two neighbours");
}

} // namespace

int main()
{
  test_poincare_hopf();
  test_mesh_vertices();
  test_invariance();
  test_estimated_normals();
  test_guidance();
  test_curvature_alignment();
  test_constraints();
  test_hostile_points();
  return report.finish();
}
