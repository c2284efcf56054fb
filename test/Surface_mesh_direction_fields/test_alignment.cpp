// Aligned and constrained fields (user manual, section "Aligned and Constrained Fields"):
//  * lambda_t -> -infinity reproduces the normalized guidance; lambda_t -> lambda_1
//    reproduces the smoothest field; t(lambda) is strictly monotone; a requested
//    t is reached within 1e-6; guidance that is the smoothest field reproduces it;
//  * on an open cylinder, the maximum-curvature line field is circumferential
//    and the minimum one axial (1 degree, away from the rims);
//  * on triaxial ellipsoids, regular and irregularly triangulated (vertices
//    jittered along the surface), the strongly aligned curvature line field has
//    exactly 4 singular faces, of index +1/2, each within two edge lengths of
//    an umbilic point;
//  * a given lambda_t needs no lambda_1, and the class reuses its factorization;
//  * Poincare-Hopf for aligned and constrained fields; constrained vertices keep
//    their directions; boundary-aligned fields are tangent or normal to the boundary;
//  * sharp features (a capped cylinder, a box, fandisk): a direction within
//    1 degree of every feature polyline, Poincare-Hopf, no change without features;
//  * the documented errors.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include "test_types.h"
#include "field_checks.h"
#include "generated_meshes.h"
#include "umbilics.h"
#include "test_support.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;
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
  const double lambda_1 = smooth.components[0].eigenvalue.value();

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
  const double lambda_1_line = smooth.components[0].eigenvalue.value();
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

// Triaxial ellipsoids, regular and with vertices jittered along the surface by
// up to 0.3 of the edge length (several axes, seeds, 10k and 40k vertices):
// at t = 0.999 and 0.9999 exactly the 4 umbilics (index +1/2, within two edge
// lengths), at t = 0.99999 at most 20 singular faces.
static void check_ellipsoid_umbilics(Test_report& report)
{
  struct Case
  {
    int subdivisions;
    double a, b, c, jitter;
    unsigned int seed;
  };
  const Case cases[] = {{5, 1.5, 1.0, 0.6, 0., 0}, {5, 3., 2., 1., 0.15, 1}, {5, 3., 2., 1., 0.3, 2},
                        {5, 1.5, 1.0, 0.6, 0.3, 3}, {5, 2., 1.6, 1., 0.3, 4}, {6, 3., 2., 1., 0.3, 5}};
  for(const Case& k : cases)
  {
    Mesh mesh;
    make_jittered_ellipsoid(mesh, k.subdivisions, k.a, k.b, k.c, k.jitter, k.seed);
    const std::string name = "ellipsoid " + std::to_string(k.a) + ":" + std::to_string(k.b) + ":" + std::to_string(k.c) +
                             ", " + std::to_string(mesh.number_of_vertices()) + " vertices, jitter " +
                             std::to_string(k.jitter) + ", seed " + std::to_string(k.seed);
    for(double t : {0.999, 0.9999, 0.99999})
    {
      const Umbilic_count u = umbilic_singularities(mesh, k.a, k.b, k.c, t, SMDF::Principal_curvature_estimate::QUADRIC_FIT);
      std::cout << "  " << name << ", t = " << t << ": " << u.singular_faces << " singular faces, "
                << u.near_umbilics << " at umbilics\n";
      if(t < 0.99999)
        report.check(u.singular_faces == 4 && u.near_umbilics == 4 && u.index_sum == 4,
                     name + ", t = " + std::to_string(t) + ": exactly the 4 umbilics (" +
                     std::to_string(u.singular_faces) + " singular faces)");
      else
        report.check(u.singular_faces <= 20 && u.index_sum == 4,
                     name + ", t = 0.99999: at most 20 singular faces (" + std::to_string(u.singular_faces) + ")");
    }
  }
  // the paper's Hopf differential on the regular ellipsoid
  Mesh mesh;
  make_jittered_ellipsoid(mesh, 5, 1.5, 1.0, 0.6, 0., 0);
  const Umbilic_count u = umbilic_singularities(mesh, 1.5, 1.0, 0.6, 0.999, SMDF::Principal_curvature_estimate::HOPF_DIFFERENTIAL);
  report.check(u.singular_faces == 4 && u.near_umbilics == 4,
               "Hopf differential, regular ellipsoid: 4 singular faces of index +1/2 at the umbilics");
}

// A given lambda_t costs one factorization: no lambda_1 unless asked for; the
// field equals the one computed with lambda_1 first (the previous path); the
// class solves another guidance field with the same lambda_t on the kept
// factorization, with the result of a fresh computation.
static void check_one_factorization(Test_report& report)
{
  Mesh mesh;
  make_lumpy_sphere(mesh, 3);
  auto g1 = mesh.add_property_map<Vertex_index, Vector_3>("v:g1", Vector_3(1., 0., 0.)).first;
  auto g2 = mesh.add_property_map<Vertex_index, Vector_3>("v:g2", Vector_3(0., 0.3, 1.)).first;
  auto d1 = direction_map(mesh, "v:d1");
  auto d2 = direction_map(mesh, "v:d2");
  auto d3 = direction_map(mesh, "v:d3");
  const double lambda = -3.;
  const SMDF::Direction_field_result plain =
    SMDF::compute_globally_optimal_directions(mesh, d1, params::degree(4).vertex_guidance_map(g1).alignment_lambda(lambda));
  const SMDF::Direction_field_result bounded = SMDF::compute_globally_optimal_directions(
    mesh, d2, params::degree(4).vertex_guidance_map(g1).alignment_lambda(lambda).compute_eigenvalue_bound(true));
  double worst = 0.;
  for(Vertex_index v : mesh.vertices()) worst = (std::max)(worst, std::sqrt((d1[v] - d2[v]).squared_length()));
  report.check(!plain.components[0].eigenvalue && bounded.components[0].eigenvalue.value() > lambda,
               "lambda_t given: lambda_1 only when asked for (" + std::to_string(bounded.components[0].eigenvalue.value()) + ")");
  report.check(worst < 1e-9 && plain.index_sum == bounded.index_sum && plain.components[0].lambda == lambda,
               "lambda_t given: the same field with and without lambda_1 (" + std::to_string(worst) + ")");

  SMDF::Globally_optimal_direction_field<Mesh> field(mesh);
  field.compute(d3, params::degree(4).vertex_guidance_map(g1).alignment_lambda(lambda));
  const SMDF::Direction_field_result second = field.compute(d3, params::degree(4).vertex_guidance_map(g2).alignment_lambda(lambda));
  const SMDF::Direction_field_result fresh =
    SMDF::compute_globally_optimal_directions(mesh, d1, params::degree(4).vertex_guidance_map(g2).alignment_lambda(lambda));
  worst = 0.;
  for(Vertex_index v : mesh.vertices()) worst = (std::max)(worst, std::sqrt((d1[v] - d3[v]).squared_length()));
  report.check(worst < 1e-12 && second.index_sum == fresh.index_sum &&
               second.components[0].alignment_weight == fresh.components[0].alignment_weight,
               "class: a second guidance field with the same lambda_t equals a fresh computation (" + std::to_string(worst) + ")");
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

// The largest angle, in degrees, between a sharp feature and the nearest of
// the n directions, over the vertices inside a feature polyline (exactly two
// feature edges, turning by at most 45 degrees).
template <typename Directions, typename Is_feature>
static double feature_direction_error(const Mesh& mesh, const Directions& d, const Is_feature& is_feature, int n)
{
  std::vector<std::vector<Vertex_index> > along(mesh.number_of_vertices());
  for(auto e : mesh.edges())
    if(get(is_feature, e))
    {
      const Vertex_index a = mesh.source(mesh.halfedge(e)), b = mesh.target(mesh.halfedge(e));
      along[a].push_back(b);
      along[b].push_back(a);
    }
  const std::vector<Vector_3> normals = angle_weighted_normals(mesh);
  double worst = 0.;
  for(Vertex_index v : mesh.vertices())
  {
    if(along[v].size() != 2) continue;
    Vector_3 in = mesh.point(v) - mesh.point(along[v][0]), out = mesh.point(along[v][1]) - mesh.point(v);
    in = in / std::sqrt(in.squared_length());
    out = out / std::sqrt(out.squared_length());
    if(in * out < std::cos(CGAL_PI / 4.)) continue;  // a corner of the polyline: free
    // the feature's direction in the tangent plane (the directions are tangent vectors)
    const Vector_3& nv = normals[v];
    Vector_3 t = (in + out) - ((in + out) * nv) * nv;
    t = t / std::sqrt(t.squared_length());
    const Vector_3 dv = d[v];
    double best = 180.;
    for(int k = 0; k < n; ++k)
    {
      const double angle = 2. * CGAL_PI * k / n;
      const Vector_3 dk = std::cos(angle) * dv + std::sin(angle) * CGAL::cross_product(nv, dv);
      best = (std::min)(best, std::acos((std::min)(1., std::abs(dk * t) / std::sqrt(dk.squared_length()))) * 180. / CGAL_PI);
    }
    worst = (std::max)(worst, best);
  }
  return worst;
}

// The cleanup of detect_feature_edges() on graphs of known shape (steps
// 4): an open chain of 8 edges goes and one of 9 stays whole, a branch of 4
// from a loop goes and one of 5 stays, a closed loop stays, a chain that
// ends on the boundary goes when it has at most 4 edges, and a long edge stays;
// small cycles are thinned.
static void check_feature_cleanup(Test_report& report)
{
  using SMDF::internal::erode_and_dilate_features;
  struct Graph
  {
    std::vector<std::array<std::size_t, 2> > ends;
    std::size_t next = 0;
    std::size_t path(std::size_t from, std::size_t edges)  // a path of new vertices from `from`; its last vertex
    {
      std::size_t at = from;
      for(std::size_t i = 0; i < edges; ++i) { ends.push_back({at, next}); at = next++; }
      return at;
    }
  };
  auto kept_after = [](Graph& g, std::vector<unsigned char> border, std::vector<unsigned char> is_long) {
    border.resize(g.next, 0);
    is_long.resize(g.ends.size(), 0);
    std::vector<unsigned char> marked(g.ends.size(), 1);
    erode_and_dilate_features(g.ends, border, is_long, 4, marked);
    return static_cast<std::size_t>(std::count(marked.begin(), marked.end(), 1));
  };
  for(std::size_t length : {8, 9})
  {
    Graph g;
    g.path(g.next++, length);
    report.check(kept_after(g, {}, {}) == (length == 8 ? 0 : 9), "an open chain of " + std::to_string(length) + " edges " +
                                                                      (length == 8 ? "is dropped" : "stays whole"));
  }
  for(std::size_t branch : {4, 5})
  {
    Graph g;
    const std::size_t first = g.next++;
    g.ends.push_back({g.path(first, 9), first});  // a loop of 10 edges
    g.path(first, branch);
    report.check(kept_after(g, {}, {}) == (branch == 4 ? 10 : 15),
                 "a branch of " + std::to_string(branch) + " from a loop " + (branch == 4 ? "is dropped" : "stays"));
  }
  for(std::size_t length : {4, 5})
  {
    Graph g;
    const std::size_t on_boundary = g.next++;
    g.path(on_boundary, length);
    std::vector<unsigned char> border(g.next, 0);
    border[on_boundary] = 1;
    report.check(kept_after(g, border, {}) == (length == 4 ? 0 : 5),
                 "a chain of " + std::to_string(length) + " from the boundary " + (length == 4 ? "is dropped" : "stays"));
  }
  // thinning (cycles of at most 8 edges): a ladder of 5 squares whose rungs bend least keeps its rails
  // and one rung; a loop of 8 is opened and one of 9 stays; a long edge is never dropped
  auto thinned = [](Graph& g, const std::vector<double>& bend, std::vector<unsigned char> is_long) {
    is_long.resize(g.ends.size(), 0);
    std::vector<unsigned char> marked(g.ends.size(), 1);
    SMDF::internal::thin_short_cycles(g.ends, g.next, bend, is_long, 8, marked);
    return marked;
  };
  Graph ladder;
  const std::size_t rail_a = ladder.next++, rail_b = ladder.next++;
  ladder.path(rail_a, 5);
  ladder.path(rail_b, 5);
  std::vector<double> bend(ladder.ends.size(), 0.);
  for(std::size_t i = 0; i <= 5; ++i) { ladder.ends.push_back({i == 0 ? rail_a : 1 + i, i == 0 ? rail_b : 6 + i}); bend.push_back(0.5); }
  const std::vector<unsigned char> ladder_kept = thinned(ladder, bend, {});
  report.check(std::count(ladder_kept.begin(), ladder_kept.end(), 1) == 11 &&
                 std::count(ladder_kept.begin(), ladder_kept.begin() + 10, 1) == 10,
               "a ladder of 5 squares is thinned to its two rails and one rung");
  for(std::size_t length : {8, 9})
  {
    Graph loop;
    const std::size_t first = loop.next++;
    loop.ends.push_back({loop.path(first, length - 1), first});
    const std::vector<unsigned char> kept = thinned(loop, std::vector<double>(length, 0.), {});
    report.check(static_cast<std::size_t>(std::count(kept.begin(), kept.end(), 1)) == (length == 8 ? 7 : 9),
                 "a loop of " + std::to_string(length) + " edges " + (length == 8 ? "is opened" : "stays whole"));
  }
  Graph triangle;
  const std::size_t corner = triangle.next++;
  triangle.ends.push_back({triangle.path(corner, 2), corner});
  const std::vector<unsigned char> triangle_kept = thinned(triangle, {0., 0., 0.9}, {0, 0, 1});
  report.check(triangle_kept == std::vector<unsigned char>{0, 1, 1},
               "in a triangle the least sharp edge that is not long is dropped");
  Graph lone;
  lone.path(lone.next++, 1);
  report.check(kept_after(lone, {}, {1}) == 1, "a long edge alone stays");
  report.check(kept_after(lone, {}, {0}) == 0, "a short edge alone is dropped");
  // on a mesh: a box keeps its 12 edges (corners are junctions), at any scale
  std::size_t unscaled = 0;
  for(double scale : {1., 1e300, 1e-300})
  {
    Mesh box;
    make_box(box, 2. * scale, 1.5 * scale, scale, 12);
    auto is_feature = box.add_property_map<Mesh::Edge_index, bool>("e:feature", false).first;
    const std::size_t marked = SMDF::detect_feature_edges(box, 60., is_feature);
    std::size_t sharp = 0;
    auto pmp = box.add_property_map<Mesh::Edge_index, bool>("e:pmp", false).first;
    CGAL::Polygon_mesh_processing::detect_sharp_edges(box, 60., pmp);
    for(auto e : box.edges()) sharp += pmp[e] && is_feature[e];
    if(scale == 1.) unscaled = marked;
    report.check(marked > 0 && marked == unscaled && (scale != 1. || marked == sharp),
                 "a box scaled by " + std::to_string(scale) + ": " + std::to_string(marked) + " feature edges" +
                   (scale == 1. ? ", those of detect_sharp_edges()" : ", as unscaled"));
  }
}

// Sharp features: on a capped cylinder, a box and fandisk (CGAL's
// detect_sharp_edges at 60 degrees), every vertex inside a feature polyline
// has a direction within 1 degree of the feature, with the smoothest and
// with the curvature-aligned field; Poincare-Hopf holds; a map without any
// feature gives the field without a map bit for bit; odd n is an error.
static void check_features(Test_report& report)
{
  struct Case
  {
    std::string name;
    Mesh mesh;
  };
  std::vector<Case> cases(2);
  cases[0].name = "capped cylinder";
  make_capped_cylinder(cases[0].mesh, 1., 2., 48, 16);
  cases[1].name = "box";
  make_box(cases[1].mesh, 2., 1.5, 1., 12);
  const std::string fandisk = shared_mesh_path("fandisk.off");
  if(!fandisk.empty())
  {
    cases.emplace_back();
    cases.back().name = "fandisk";
    CGAL::IO::read_polygon_mesh(fandisk, cases.back().mesh);
  }
  for(Case& k : cases)
  {
    Mesh& mesh = k.mesh;
    auto is_feature = mesh.add_property_map<Mesh::Edge_index, bool>("e:feature", false).first;
    CGAL::Polygon_mesh_processing::detect_sharp_edges(mesh, 60., is_feature);
    std::size_t features = 0;
    for(auto e : mesh.edges()) features += is_feature[e];
    const int chi = static_cast<int>(mesh.number_of_vertices()) - static_cast<int>(mesh.number_of_edges()) +
                    static_cast<int>(mesh.number_of_faces());
    for(bool curvature : {false, true})
    {
      auto d = direction_map(mesh, "v:feature_field");
      auto np = params::degree(4).edge_is_feature_map(is_feature);
      const SMDF::Direction_field_result r =
        curvature ? SMDF::compute_globally_optimal_directions(
                      mesh, d, np.principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM))
                  : SMDF::compute_globally_optimal_directions(mesh, d, np);
      const double worst = feature_direction_error(mesh, d, is_feature, 4);
      const std::string name = k.name + (curvature ? ", curvature-aligned" : ", smoothest");
      report.check(features > 0 && worst <= 1.,
                   name + ": directions along the " + std::to_string(features) + " feature edges (" + std::to_string(worst) + " degrees)");
      report.check(r.index_sum == 4 * chi, name + ": Poincare-Hopf with features");
      mesh.remove_property_map(d);
    }
  }
  // no feature in the map: the field without a map, bit for bit
  Mesh& mesh = cases[0].mesh;
  auto none = mesh.add_property_map<Mesh::Edge_index, bool>("e:none", false).first;
  auto d0 = direction_map(mesh, "v:d0");
  auto d1 = direction_map(mesh, "v:d1");
  SMDF::compute_globally_optimal_directions(mesh, d0, params::degree(4));
  SMDF::compute_globally_optimal_directions(mesh, d1, params::degree(4).edge_is_feature_map(none));
  bool same = true;
  for(Vertex_index v : mesh.vertices()) same = same && d0[v] == d1[v];
  report.check(same, "an empty feature map leaves the field unchanged bit for bit");
  report.check(throws_invalid_input([&] {
    SMDF::compute_globally_optimal_directions(mesh, d0, params::degree(3).edge_is_feature_map(none)); }),
    "features with odd n rejected");
}

static void check_errors(Test_report& report)
{
  Mesh mesh;
  make_lumpy_sphere(mesh, 2);
  auto d = direction_map(mesh);
  auto guidance = mesh.add_property_map<Vertex_index, Vector_3>("v:g", Vector_3(1., 0., 0.)).first;
  const double lambda_1 = SMDF::compute_globally_optimal_directions(mesh, d, params::degree(2)).components[0].eigenvalue.value();
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

// A call that ends by an exception (here lambda_t above lambda_1, found after
// the matrices of another n and s were built and factored) leaves the class
// as a fresh one: the next fields are the same bit for bit.
static void check_class_after_a_refused_call(Test_report& report)
{
  Mesh mesh;
  make_lumpy_sphere(mesh, 3);
  auto guidance = mesh.add_property_map<Vertex_index, Vector_3>("v:g", Vector_3(0., 0., 1.)).first;
  auto d1 = direction_map(mesh, "v:refused_call_1");
  auto d2 = direction_map(mesh, "v:refused_call_2");
  auto d3 = direction_map(mesh, "v:refused_call_3");
  SMDF::Globally_optimal_direction_field<Mesh> field(mesh);
  const auto aligned = params::degree(4).vertex_guidance_map(guidance).alignment_lambda(-2.);
  const SMDF::Direction_field_result first = field.compute(d1, aligned);
  bool refused = false;
  try
  {
    field.compute(d2, params::degree(6).smoothness_parameter(0.5).vertex_guidance_map(guidance).alignment_lambda(1e6));
  }
  catch(const SMDF::Invalid_input_error&)
  {
    refused = true;
  }
  const SMDF::Direction_field_result again = field.compute(d2, aligned);
  const SMDF::Direction_field_result smoothest = field.compute(d3, params::degree(6).smoothness_parameter(0.5));
  SMDF::Globally_optimal_direction_field<Mesh> fresh(mesh);
  auto d4 = direction_map(mesh, "v:refused_call_4");
  const SMDF::Direction_field_result fresh_smoothest = fresh.compute(d4, params::degree(6).smoothness_parameter(0.5));
  bool same = true, same_smoothest = true;
  for(Vertex_index v : mesh.vertices())
  {
    same = same && d1[v] == d2[v];
    same_smoothest = same_smoothest && d3[v] == d4[v];
  }
  report.check(refused, "class: lambda_t above lambda_1 refused");
  report.check(same && again.index_sum == first.index_sum && again.components[0].lambda == first.components[0].lambda,
               "class: after a refused call, the aligned field of before, bit for bit");
  report.check(same_smoothest && smoothest.components[0].eigenvalue.value() == fresh_smoothest.components[0].eigenvalue.value(),
               "class: after a refused call, the smoothest field of a fresh class, bit for bit");
}

// progress_callback: fractions from 0 to 1, never decreasing, and a call per
// solve of the eigen-solve, whose fraction advances within it; `false` stops the call with Computation_interrupted,
// the output map untouched, and the class's next field is a fresh class's.
static void check_interrupted_call(Test_report& report)
{
  Mesh mesh;
  make_lumpy_sphere(mesh, 3);
  auto d1 = direction_map(mesh, "v:interrupted_1");
  auto d2 = direction_map(mesh, "v:interrupted_2");
  std::vector<double> fractions;
  SMDF::Globally_optimal_direction_field<Mesh> field(mesh);
  const SMDF::Direction_field_result full = field.compute(d1, params::degree(4).progress_callback([&](double f) {
    fractions.push_back(f);
    return true;
  }));
  report.check(!fractions.empty() && fractions.front() == 0. && fractions.back() == 1. &&
                 std::is_sorted(fractions.begin(), fractions.end()) &&
                 fractions.size() >= full.iterations + 4 &&
                 std::any_of(fractions.begin(), fractions.end(), [](double f) { return f > 0.3 && f < 1.; }),
               "progress_callback: " + std::to_string(fractions.size()) + " calls from 0 to 1, one per solve of the " +
                 std::to_string(full.iterations) + " and per step");
  for(Vertex_index v : mesh.vertices()) put(d2, v, Vector_3(7., 7., 7.));
  int calls = 0;
  bool interrupted = false;
  try
  {
    field.compute(d2, params::degree(6).smoothness_parameter(0.5).progress_callback([&](double) { return ++calls < 6; }));
  }
  catch(const SMDF::Computation_interrupted&)
  {
    interrupted = true;
  }
  bool untouched = true;
  for(Vertex_index v : mesh.vertices()) untouched = untouched && d2[v] == Vector_3(7., 7., 7.);
  field.compute(d2, params::degree(6).smoothness_parameter(0.5));
  SMDF::Globally_optimal_direction_field<Mesh> fresh(mesh);
  auto d3 = direction_map(mesh, "v:interrupted_3");
  fresh.compute(d3, params::degree(6).smoothness_parameter(0.5));
  bool same = true;
  for(Vertex_index v : mesh.vertices()) same = same && d2[v] == d3[v];
  report.check(interrupted && calls == 6 && untouched,
               "progress_callback returning false: Computation_interrupted at once, the output map untouched");
  report.check(same, "class: after an interrupted call, the field of a fresh class, bit for bit");
}

// A flat square (no curvature: the guidance vanishes, lambda_1 = 0): the
// curvature-aligned field of the free function is the smoothest one (its
// aligned system, factored before the guidance, is not used; the
// eigen-solve then assembles A and M, which that factorization had not).
static void check_flat_square(Test_report& report)
{
  Mesh mesh;
  const int n = 16;
  std::vector<Vertex_index> v;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) v.push_back(mesh.add_vertex(Point_3(i, 0.7 * j, 0.)));
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
    {
      const Vertex_index a = v[j * (n + 1) + i], b = v[j * (n + 1) + i + 1];
      const Vertex_index c = v[(j + 1) * (n + 1) + i + 1], d = v[(j + 1) * (n + 1) + i];
      mesh.add_face(a, b, c);
      mesh.add_face(a, c, d);
    }
  auto aligned = direction_map(mesh, "v:aligned");
  auto smoothest = direction_map(mesh, "v:smoothest");
  const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
    mesh, aligned, params::degree(2).principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM));
  SMDF::compute_globally_optimal_directions(mesh, smoothest, params::degree(2));
  double worst = 0.;
  for(Vertex_index u : mesh.vertices()) worst = (std::max)(worst, angle_mod(aligned[u], smoothest[u], 2));
  report.check(r.number_of_singular_faces == 0 && worst < 1e-6,
               "flat square: the curvature-aligned field of the free function is the smoothest one (" +
                 std::to_string(worst) + " rad)");
}

int main()
{
  Test_report report("alignment");
  check_limits_and_weight(report);
  check_cylinder(report);
  check_flat_square(report);
  check_ellipsoid_umbilics(report);
  check_one_factorization(report);
  check_features(report);
  check_feature_cleanup(report);
  check_constraints(report);
  check_errors(report);
  check_class_after_a_refused_call(report);
  check_interrupted_call(report);
  return report.finish();
}
