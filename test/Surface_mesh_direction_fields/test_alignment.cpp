// Aligned and constrained fields (user manual, section "Aligned and Constrained Fields"):
//  * lambda_t -> -infinity reproduces the normalized guidance; lambda_t -> lambda_1
//    reproduces the smoothest field; t(lambda) is strictly monotone; a requested
//    t is reached within 1e-6; guidance that is the smoothest field reproduces it;
//  * on an open cylinder, the maximum-curvature line field is circumferential
//    and the minimum one axial (1 degree, away from the rims);
//  * on a triaxial ellipsoid, the curvature line field has 4 singular faces of
//    index +1/2, each within two edge lengths of an umbilic point;
//  * Poincare-Hopf for aligned and constrained fields; constrained vertices keep
//    their directions; boundary-aligned fields are tangent or normal to the boundary;
//  * the documented errors.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include "field_checks.h"
#include "generated_meshes.h"
#include "test_support.h"

#include <cmath>
#include <iostream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point_3;
typedef Kernel::Vector_3 Vector_3;
typedef CGAL::Surface_mesh<Point_3> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;
namespace SMDF = CGAL::Surface_mesh_direction_fields;
namespace params = CGAL::parameters;
typedef std::vector<std::pair<Face_index, int> > Singularities;

static void check_limits_and_weight(Test_report& report)
{
  Mesh mesh;
  make_lumpy_sphere(mesh, 3);
  const std::vector<Vector_3> normals = angle_weighted_normals(mesh);
  auto guidance = mesh.add_property_map<Vertex_index, Vector_3>("v:guidance", CGAL::NULL_VECTOR).first;
  for(Vertex_index v : mesh.vertices())  // a constant vector, projected: vanishes at two "poles"
    guidance[v] = Vector_3(1., 0.3, 0.2);
  int n = 1;  // (n = 1: the output is the guidance's own direction, see the user manual)
  auto dir = direction_map(mesh);
  SMDF::Direction_field_result smooth = SMDF::compute_globally_optimal_directions(mesh, dir, params::degree(n));
  const double lambda_1 = smooth.components[0].eigenvalue;

  // lambda_t -> -infinity: the guidance itself
  {
    auto d = direction_map(mesh, "v:aligned");
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
      mesh, d, params::degree(n).vertex_guidance_map(guidance).alignment_lambda(-1e9 * lambda_1));
    double worst = 0.;
    for(Vertex_index v : mesh.vertices())
    {
      const Vector_3 g = guidance[v] - (guidance[v] * normals[v]) * normals[v];
      if(g.squared_length() < 0.01) continue;  // where the guidance (nearly) vanishes
      worst = (std::max)(worst, angle_mod(d[v], g, n));
    }
    report.check(worst <= 1e-3, "lambda_t -> -infinity reproduces the guidance (" + std::to_string(worst) + " rad)");
    report.check(r.components[0].alignment_weight > 0.999999, "lambda_t -> -infinity: t -> 1");
  }
  n = 2;
  smooth = SMDF::compute_globally_optimal_directions(mesh, dir, params::degree(n));
  const double lambda_1_line = smooth.components[0].eigenvalue;
  // lambda_t -> lambda_1: the smoothest field (compared by what does not depend on the global phase)
  {
    auto d = direction_map(mesh, "v:smoothish");
    auto mag = mesh.add_property_map<Vertex_index, double>("v:m1", 0.).first;
    auto mag0 = mesh.add_property_map<Vertex_index, double>("v:m0", 0.).first;
    Singularities s0, s1;
    SMDF::compute_globally_optimal_directions(mesh, dir, params::degree(n).vertex_magnitude_map(mag0)
                                                             .singularities_output_iterator(std::back_inserter(s0)));
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
      mesh, d, params::degree(n).vertex_guidance_map(guidance).alignment_lambda(lambda_1_line * (1. - 1e-9))
                 .vertex_magnitude_map(mag).singularities_output_iterator(std::back_inserter(s1)));
    double worst = 0.;
    for(Vertex_index v : mesh.vertices()) worst = (std::max)(worst, std::abs(mag[v] - mag0[v]));
    report.check(worst < 1e-5 && s0.size() == s1.size(), "lambda_t -> lambda_1 reproduces the smoothest field (" +
                                                          std::to_string(worst) + ")");
    report.check(r.components[0].alignment_weight < 1e-3, "lambda_t -> lambda_1: t -> 0");
  }
  // t(lambda): strictly monotone (decreasing in lambda_t, from 1 to 0)
  {
    std::vector<double> lambdas;
    for(int k = 6; k >= -6; --k) lambdas.push_back(lambda_1_line - std::pow(10., k) * lambda_1_line);
    double previous = 2.;
    bool monotone = true;
    for(double lambda : lambdas)
    {
      auto d = direction_map(mesh, "v:sweep");
      const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
        mesh, d, params::degree(n).vertex_guidance_map(guidance).alignment_lambda(lambda));
      const double t = r.components[0].alignment_weight;
      monotone = monotone && t < previous && t > 0. && t < 1.;
      previous = t;
    }
    report.check(monotone, "t(lambda_t) strictly decreasing from 1 to 0 over lambda_1 - 1e6 lambda_1 .. lambda_1 - 1e-6 lambda_1");
  }
  // a requested t
  for(double t : {0.05, 0.3, 0.5, 0.9, 0.999})
  {
    auto d = direction_map(mesh, "v:weight");
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
      mesh, d, params::degree(n).vertex_guidance_map(guidance).alignment_weight(t));
    const double got = r.components[0].alignment_weight;
    report.check(std::abs(got - t) <= 1e-6 && r.components[0].lambda < lambda_1_line,
                 "alignment_weight(" + std::to_string(t) + ") reached (" + std::to_string(got) + ", lambda_t " +
                 std::to_string(r.components[0].lambda) + ")");
  }
  // guidance that is the smoothest field (its directions weighted by its magnitudes) reproduces it
  {
    auto mag = mesh.add_property_map<Vertex_index, double>("v:self_magnitude", 0.).first;
    SMDF::compute_globally_optimal_directions(mesh, dir, params::degree(n).vertex_magnitude_map(mag));
    auto weighted = mesh.add_property_map<Vertex_index, Vector_3>("v:weighted", CGAL::NULL_VECTOR).first;
    for(Vertex_index v : mesh.vertices()) weighted[v] = mag[v] * dir[v];
    auto d = direction_map(mesh, "v:self");
    SMDF::compute_globally_optimal_directions(mesh, d, params::degree(n).vertex_guidance_map(weighted).alignment_weight(0.5));
    double worst = 0.;
    for(Vertex_index v : mesh.vertices()) worst = (std::max)(worst, angle_mod(d[v], dir[v], n));
    report.check(worst < 1e-6, "the smoothest field as guidance is reproduced (" + std::to_string(worst) + " rad)");
  }
}

static void check_cylinder(Test_report& report)
{
  Mesh mesh;
  make_cylinder(mesh, 1., 3., 64, 48);
  for(auto which : {SMDF::Principal_curvature_alignment::MAXIMUM, SMDF::Principal_curvature_alignment::MINIMUM})
  {
    auto d = direction_map(mesh);
    SMDF::compute_globally_optimal_directions(mesh, d, params::degree(2).principal_curvature_alignment(which));
    double worst = 0.;
    for(Vertex_index v : mesh.vertices())
    {
      const Point_3& p = mesh.point(v);
      if(p.z() < 0.5 || p.z() > 2.5) continue;  // away from the rims
      const Vector_3 expected = which == SMDF::Principal_curvature_alignment::MAXIMUM ? Vector_3(-p.y(), p.x(), 0.)
                                                                                      : Vector_3(0., 0., 1.);
      worst = (std::max)(worst, angle_mod(d[v], expected, 2));
    }
    const bool max = which == SMDF::Principal_curvature_alignment::MAXIMUM;
    report.check(worst < CGAL_PI / 180., std::string("cylinder: ") + (max ? "maximum" : "minimum") +
                                         " curvature lines are " + (max ? "circumferential" : "axial") + " (" +
                                         std::to_string(worst * 180. / CGAL_PI) + " degrees)");
  }
}

static void check_ellipsoid_umbilics(Test_report& report)
{
  const double a = 1.5, b = 1.0, c = 0.6;
  Mesh mesh;
  make_icosphere(mesh, 5);
  for(Vertex_index v : mesh.vertices())
  {
    const Point_3& p = mesh.point(v);
    mesh.point(v) = Point_3(a * p.x(), b * p.y(), c * p.z());
  }
  // umbilics: (+-x0, 0, +-z0)
  const double x0 = a * std::sqrt((a * a - b * b) / (a * a - c * c));
  const double z0 = c * std::sqrt((b * b - c * c) / (a * a - c * c));
  double edge = 0.;
  for(auto e : mesh.edges()) edge += std::sqrt(CGAL::squared_distance(mesh.point(mesh.source(mesh.halfedge(e))), mesh.point(mesh.target(mesh.halfedge(e)))));
  edge /= mesh.number_of_edges();
  auto d = direction_map(mesh);
  Singularities sing;
  const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
    mesh, d, params::degree(2).principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM)
               .alignment_weight(0.999).singularities_output_iterator(std::back_inserter(sing)));
  bool near = sing.size() == 4;
  std::vector<Point_3> umbilics = {Point_3(x0, 0, z0), Point_3(-x0, 0, z0), Point_3(x0, 0, -z0), Point_3(-x0, 0, -z0)};
  std::vector<bool> found(4, false);
  for(const auto& fk : sing)
  {
    near = near && fk.second == 1;
    Vector_3 centre = CGAL::NULL_VECTOR;
    for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(fk.first), mesh)) centre = centre + (mesh.point(v) - CGAL::ORIGIN) / 3.;
    double best = 1e300;
    std::size_t which = 0;
    for(std::size_t k = 0; k < 4; ++k)
    {
      const double dist = std::sqrt(CGAL::squared_distance(CGAL::ORIGIN + centre, umbilics[k]));
      if(dist < best) { best = dist; which = k; }
    }
    std::cout << "  ellipsoid singular face " << fk.first << " index " << fk.second << "/2, " << best / edge
              << " edge lengths from umbilic " << which << "\n";
    near = near && best <= 2. * edge && !found[which];
    found[which] = true;
  }
  report.check(near && r.index_sum == 4, "triaxial ellipsoid: 4 singular faces of index +1/2, one near each umbilic (" +
                                         std::to_string(sing.size()) + " found)");
}

static void check_constraints(Test_report& report)
{
  // hard constraints on a closed mesh: exact directions, Poincare-Hopf
  Mesh mesh;
  make_lumpy_sphere(mesh, 3);
  const std::vector<Vector_3> normals = angle_weighted_normals(mesh);
  auto constrained = mesh.add_property_map<Vertex_index, bool>("v:constrained", false).first;
  auto prescribed = mesh.add_property_map<Vertex_index, Vector_3>("v:prescribed", CGAL::NULL_VECTOR).first;
  for(Vertex_index v : mesh.vertices())
    if(std::size_t(v) % 97 == 0)
    {
      constrained[v] = true;
      const Vector_3 w(std::cos(0.1 * std::size_t(v)), std::sin(0.1 * std::size_t(v)), 0.3);
      prescribed[v] = w - (w * normals[v]) * normals[v];
    }
  for(int n : {1, 2, 4})
  {
    auto d = direction_map(mesh);
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
      mesh, d, params::degree(n).vertex_is_constrained_map(constrained).vertex_constrained_direction_map(prescribed));
    double worst = 0.;
    for(Vertex_index v : mesh.vertices())
      if(constrained[v]) worst = (std::max)(worst, angle_mod(d[v], prescribed[v], n));
    report.check(worst < 1e-9, "constrained vertices keep their directions, n = " + std::to_string(n) + " (" +
                               std::to_string(worst) + " rad)");
    report.check(r.index_sum == 2 * n, "constrained field: Poincare-Hopf, n = " + std::to_string(n));
    // constrained and aligned at once
    auto guidance = mesh.add_property_map<Vertex_index, Vector_3>("v:g", Vector_3(0., 0., 1.)).first;
    const SMDF::Direction_field_result ra = SMDF::compute_globally_optimal_directions(
      mesh, d, params::degree(n).vertex_is_constrained_map(constrained).vertex_constrained_direction_map(prescribed)
                 .vertex_guidance_map(guidance));
    worst = 0.;
    for(Vertex_index v : mesh.vertices())
      if(constrained[v]) worst = (std::max)(worst, angle_mod(d[v], prescribed[v], n));
    report.check(worst < 1e-9 && ra.index_sum == 2 * n, "constrained and aligned: directions kept, Poincare-Hopf, n = " + std::to_string(n));
  }
  // aligned fields on closed meshes: Poincare-Hopf
  for(int n : {2, 4, 6})
  {
    auto d = direction_map(mesh);
    const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
      mesh, d, params::degree(n).principal_curvature_alignment(SMDF::Principal_curvature_alignment::MINIMUM));
    report.check(r.index_sum == 2 * n, "curvature-aligned field: Poincare-Hopf, n = " + std::to_string(n));
  }

  // boundary alignment on a flat disk and on an open cylinder
  Mesh disk;
  make_disk(disk, 10, 1.);
  for(auto mode : {SMDF::Boundary_alignment::TANGENT, SMDF::Boundary_alignment::NORMAL})
    for(int n : {1, 2, 4})
    {
      auto d = direction_map(disk);
      SMDF::compute_globally_optimal_directions(disk, d, params::degree(n).boundary_alignment(mode));
      double worst = 0.;
      for(auto h : disk.halfedges())
      {
        if(!disk.is_border(disk.opposite(h))) continue;  // h: interior side of a boundary edge, v -> next
        const Vertex_index v = disk.source(h);
        const Vector_3 to_next = disk.point(disk.target(h)) - disk.point(v);
        // the previous boundary vertex: across the border halfedge before
        const Vector_3 to_previous = disk.point(disk.target(disk.next(disk.opposite(h)))) - disk.point(v);
        const Vector_3 a = to_next / std::sqrt(to_next.squared_length()), b = to_previous / std::sqrt(to_previous.squared_length());
        const Vector_3 expected = mode == SMDF::Boundary_alignment::TANGENT ? a - b : a + b;
        worst = (std::max)(worst, angle_mod(d[v], expected, n));
      }
      report.check(worst < 1e-9, std::string("flat disk: boundary-aligned field ") +
                                 (mode == SMDF::Boundary_alignment::TANGENT ? "tangent" : "normal") +
                                 " to the boundary, n = " + std::to_string(n) + " (" + std::to_string(worst) + ")");
    }
  Mesh cylinder;
  make_cylinder(cylinder, 1., 2., 48, 20);
  auto d = direction_map(cylinder);
  SMDF::compute_globally_optimal_directions(cylinder, d, params::degree(2).boundary_alignment(SMDF::Boundary_alignment::TANGENT));
  double worst = 0.;
  for(Vertex_index v : cylinder.vertices())
    if(cylinder.is_border(v))
      worst = (std::max)(worst, angle_mod(d[v], Vector_3(-cylinder.point(v).y(), cylinder.point(v).x(), 0.), 2));
  report.check(worst < 1e-9, "cylinder: boundary-aligned field tangent to the rims (" + std::to_string(worst) + ")");
}

static void check_errors(Test_report& report)
{
  Mesh mesh;
  make_lumpy_sphere(mesh, 2);
  auto d = direction_map(mesh);
  auto guidance = mesh.add_property_map<Vertex_index, Vector_3>("v:g", Vector_3(1., 0., 0.)).first;
  const double lambda_1 = SMDF::compute_globally_optimal_directions(mesh, d, params::degree(2)).components[0].eigenvalue;
  report.check(throws_invalid_input([&] {
    SMDF::compute_globally_optimal_directions(mesh, d, params::degree(3).principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM)); }),
    "curvature alignment with odd n rejected");
  report.check(throws_invalid_input([&] {
    SMDF::compute_globally_optimal_directions(mesh, d, params::degree(2).vertex_guidance_map(guidance).alignment_lambda(lambda_1 * 1.01)); }),
    "lambda_t >= lambda_1 rejected");
  report.check(throws_invalid_input([&] {
    SMDF::compute_globally_optimal_directions(mesh, d, params::degree(2).vertex_guidance_map(guidance).alignment_weight(1.)); }),
    "t = 1 rejected");
  report.check(throws_invalid_input([&] {
    SMDF::compute_globally_optimal_directions(mesh, d, params::degree(2).alignment_weight(0.5)); }),
    "t without guidance rejected");
  report.check(throws_invalid_input([&] {
    SMDF::compute_globally_optimal_directions(mesh, d, params::degree(2).vertex_guidance_map(guidance).alignment_weight(0.5).alignment_lambda(0.)); }),
    "both lambda_t and t rejected");
}

int main()
{
  Test_report report("alignment");
  check_limits_and_weight(report);
  check_cylinder(report);
  check_ellipsoid_umbilics(report);
  check_constraints(report);
  check_errors(report);
  return report.finish();
}
