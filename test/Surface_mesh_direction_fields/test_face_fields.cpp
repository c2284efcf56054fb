// Fields on faces (user manual, section "Fields on Faces"): the closed form of
// the smallest eigenvalue on the sphere, discrete Poincare-Hopf at the vertices
// on every component (with the boundary's contribution), the matching closing
// up to the vertex indices, invariance under the numbering of the corners,
// constraints, features and the refusals.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include "test_types.h"
#include "generated_meshes.h"
#include "test_support.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <iterator>
#include <iostream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;

namespace {

Test_report report("test_face_fields");

struct Face_field
{
  SMDF::Face_direction_field_result result;
  std::vector<std::pair<Vertex_index, int> > singular;
  std::map<Edge_index, int> matching;
  std::vector<Vector_3> directions;  // by face index
};

template <typename NP>
Face_field face_field(const Mesh& mesh, const NP& np)
{
  Face_field field;
  // add_property_map() hands back the map if it exists
  auto direction_map = const_cast<Mesh&>(mesh).add_property_map<Face_index, Vector_3>("f:test_direction").first;
  auto matching = const_cast<Mesh&>(mesh).add_property_map<Edge_index, int>("e:test_matching", -99).first;
  field.result = SMDF::compute_globally_optimal_face_directions(
    mesh, direction_map, np.singularities_output_iterator(std::back_inserter(field.singular)).edge_matching_map(matching));
  for(Edge_index e : edges(mesh)) field.matching[e] = matching[e];
  for(Face_index f : faces(mesh)) field.directions.push_back(direction_map[f]);
  const_cast<Mesh&>(mesh).remove_property_map(matching);
  return field;
}

// The jumps around an interior vertex, clockwise (halfedges_around_target), add up to its index k modulo n.
void check_matching_closes(const Mesh& mesh, const Face_field& field, int n, const std::string& what)
{
  std::map<Vertex_index, int> index;
  for(const auto& vk : field.singular) index[vk.first] = vk.second;
  int failures = 0;
  for(Vertex_index v : vertices(mesh))
  {
    if(mesh.is_border(v) || mesh.is_isolated(v)) continue;
    long long sum = 0;
    for(auto h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh))
    {
      const auto crossed = mesh.next(h);  // from face(h) clockwise to the face across it
      // (the edge as edges() lists it: Surface_mesh's edge(h) remembers h as its halfedge)
      const Edge_index e(static_cast<Mesh::size_type>(crossed.idx() / 2));
      sum += (mesh.halfedge(e) == crossed) ? field.matching.at(e) : -field.matching.at(e);
    }
    const int k = index.count(v) ? index[v] : 0;
    if(((sum - k) % n + n) % n != 0)
    {
      if(failures < 3) std::cout << "  vertex " << v.idx() << ": k = " << k << ", clockwise jumps add up to " << sum << "\n";
      ++failures;
    }
  }
  report.check(failures == 0, what + ": the matching around " + std::to_string(failures) +
                                " vertices does not close to their index modulo n");
}

void check_poincare_hopf(const Face_field& field, int n, const std::string& what)
{
  long long sum = 0;
  for(const auto& vk : field.singular) sum += vk.second;
  report.check(sum == field.result.index_sum, what + ": the listed singularities add up to index_sum");
  for(std::size_t c = 0; c < field.result.components.size(); ++c)
  {
    const SMDF::Face_field_component_report& r = field.result.components[c];
    report.check(r.index_sum + r.boundary_index == static_cast<long long>(n) * r.euler_characteristic,
                 what + ": component " + std::to_string(c) + " index sum " + std::to_string(r.index_sum) +
                   " + boundary " + std::to_string(r.boundary_index) + " != n chi = " +
                   std::to_string(n * r.euler_characteristic));
    if(r.is_closed) report.check(r.boundary_index == 0, what + ": a closed component has no boundary contribution");
  }
}

// Unit, tangent to each face.
void check_directions(const Mesh& mesh, const Face_field& field, const std::string& what)
{
  int bad = 0;
  for(Face_index f : faces(mesh))
  {
    const auto h = mesh.halfedge(f);
    const Vector_3 normal = CGAL::cross_product(mesh.point(mesh.target(h)) - mesh.point(mesh.source(h)),
                                                mesh.point(mesh.target(mesh.next(h))) - mesh.point(mesh.source(h)));
    const Vector_3& d = field.directions[f.idx()];
    if(!(std::abs(d.squared_length() - 1.) < 1e-12) ||
       !(std::abs(d * normal) < 1e-9 * std::sqrt(normal.squared_length())))
      ++bad;
  }
  report.check(bad == 0, what + ": " + std::to_string(bad) + " face directions are not unit tangent vectors");
}

// The smallest eigenvalue of the Dirichlet energy of degree n on the unit sphere is n (the vertex
// field's closed form n (1 - s) at s = 0): it pins the sign and conjugation of the transport.
void check_sphere()
{
  Mesh sphere;
  make_icosphere(sphere, 4);
  for(int n : {1, 2, 4})
  {
    const Face_field field = face_field(sphere, params::degree(n));
    const double lambda = field.result.components[0].eigenvalue.value();
    report.check(std::abs(lambda - n) < 0.02 * n, "sphere, n = " + std::to_string(n) + ": lambda_1 = " +
                                                     std::to_string(lambda) + ", expected about " + std::to_string(n));
    report.check(field.result.index_sum == 2 * n, "sphere: the vertex indices add up to 2n");
    check_poincare_hopf(field, n, "sphere n = " + std::to_string(n));
    check_matching_closes(sphere, field, n, "sphere n = " + std::to_string(n));
    check_directions(sphere, field, "sphere");
  }
}

// Genus 1 and a surface with boundary; an aligned field with features.
void check_torus_and_disk()
{
  Mesh torus;
  make_torus(torus, 3., 1., 48, 20);
  const Face_field smooth = face_field(torus, params::degree(4));
  report.check(smooth.result.index_sum == 0 && smooth.result.components[0].euler_characteristic == 0,
               "torus: index sum 0");
  check_matching_closes(torus, smooth, 4, "torus");
  const Face_field curved = face_field(torus, params::degree(4).principal_curvature_alignment(
                                                SMDF::Principal_curvature_alignment::MAXIMUM));
  report.check(curved.result.number_of_singular_vertices == 0,
               "torus: the curvature-aligned cross field has no singularity (got " +
                 std::to_string(curved.result.number_of_singular_vertices) + ")");
  // on the torus of revolution the maximum curvature runs around the tube: along the meridians
  int off_meridian = 0;
  for(Face_index f : faces(torus))
  {
    Point_3 centre(0, 0, 0);
    Vector_3 sum(0, 0, 0);
    for(auto v : CGAL::vertices_around_face(torus.halfedge(f), torus)) sum = sum + (torus.point(v) - centre);
    const Vector_3 around_axis(-sum.y(), sum.x(), 0.);
    const Vector_3& d = curved.directions[f.idx()];
    const double c = std::abs(d * around_axis) / std::sqrt(around_axis.squared_length());
    if(!(c < 0.1 || c > 0.995)) ++off_meridian;  // a cross: along or across the parallels
  }
  report.check(off_meridian == 0, "torus: " + std::to_string(off_meridian) +
                                    " faces whose cross is not along the principal directions");

  Mesh disk;
  make_disk(disk, 12);
  const Face_field flat = face_field(disk, params::degree(4));
  report.check(flat.result.number_of_singular_vertices == 0, "flat disk: no singular vertex");
  report.check(flat.result.components[0].boundary_index == 4, "flat disk: the boundary contributes n chi = 4");
  report.check(std::abs(flat.result.components[0].eigenvalue.value()) < 1e-8, "flat disk: lambda_1 = 0");
  check_poincare_hopf(flat, 4, "flat disk");
  const Face_field along = face_field(disk, params::degree(4).boundary_alignment(SMDF::Boundary_alignment::TANGENT));
  check_poincare_hopf(along, 4, "disk along the boundary");
  report.check(along.result.index_sum == 4, "disk along the boundary: interior indices add up to n chi (got " +
                                              std::to_string(along.result.index_sum) + ")");
}

// The numbering of each face's corners (which side is its frame's axis) changes nothing.
void check_corner_numbering_invariance()
{
  Mesh a;
  make_lumpy_sphere(a, 3);
  Mesh b = a;
  for(Face_index f : faces(b)) b.set_halfedge(f, b.next(b.halfedge(f)));
  const auto np = params::degree(4).principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM);
  const Face_field fa = face_field(a, np), fb = face_field(b, np);
  report.check(fa.singular == fb.singular, "corner numbering: the same singular vertices and indices");
  double worst = 0.;
  for(std::size_t f = 0; f < fa.directions.size(); ++f)
  {
    // a cross: compare the fourth powers of the directions in a frame of the face (via dot and cross)
    const Vector_3& x = fa.directions[f];
    const Vector_3& y = fb.directions[f];
    const double cos4 = std::cos(4. * std::atan2(std::sqrt(CGAL::cross_product(x, y).squared_length()), x * y));
    worst = (std::max)(worst, 1. - cos4);
  }
  report.check(worst < 1e-8, "corner numbering: the same crosses (worst 1 - cos 4a = " + std::to_string(worst) + ")");
}

void check_constraints_and_refusals()
{
  Mesh sphere;
  make_icosphere(sphere, 3);
  auto constrained = sphere.add_property_map<Face_index, bool>("f:c", false).first;
  auto wanted = sphere.add_property_map<Face_index, Vector_3>("f:w", Vector_3(0, 0, 0)).first;
  const Face_index f0(0);
  constrained[f0] = true;
  const auto h = sphere.halfedge(f0);
  wanted[f0] = sphere.point(sphere.target(h)) - sphere.point(sphere.source(h));
  const Face_field field =
    face_field(sphere, params::degree(1).face_is_constrained_map(constrained).face_constrained_direction_map(wanted));
  const Vector_3 w = wanted[f0] / std::sqrt(wanted[f0].squared_length());
  report.check(std::abs(field.directions[0] * w - 1.) < 1e-12, "a constrained face keeps its direction");
  check_poincare_hopf(field, 1, "constrained sphere");

  auto refused = [&](auto call, const std::string& what) {
    bool thrown = false;
    try { call(); } catch(const SMDF::Invalid_input_error& e) { thrown = true; std::cout << "  refused: " << e.what() << "\n"; }
    report.check(thrown, what + " is refused");
  };
  auto dirs = sphere.add_property_map<Face_index, Vector_3>("f:d").first;
  refused([&] { SMDF::compute_globally_optimal_face_directions(sphere, dirs, params::smoothness_parameter(0.5)); },
          "s = 0.5");
  refused([&] { SMDF::compute_globally_optimal_face_directions(
                  sphere, dirs, params::degree(3).principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM)); },
          "curvature alignment with n = 3");
  auto vertex_guidance = sphere.add_property_map<Vertex_index, Vector_3>("v:g", Vector_3(1, 0, 0)).first;
  refused([&] { SMDF::compute_globally_optimal_face_directions(sphere, dirs, params::vertex_guidance_map(vertex_guidance)); },
          "a vertex guidance map");
  refused([&] { SMDF::compute_globally_optimal_face_directions(sphere, dirs, params::degree(0)); }, "n = 0");
}

// Sharp features on a box-like closed cylinder: the crosses of the faces at a rim follow the rim.
void check_features()
{
  Mesh cylinder;
  make_capped_cylinder(cylinder, 1., 2., 32, 8);
  auto is_feature = cylinder.add_property_map<Edge_index, bool>("e:f", false).first;
  CGAL::Polygon_mesh_processing::detect_sharp_edges(cylinder, 60., is_feature);
  std::size_t features = 0;
  for(Edge_index e : edges(cylinder)) features += is_feature[e];
  report.check(features == 64, "cylinder: 64 rim edges detected");
  const Face_field field = face_field(cylinder, params::degree(4).edge_is_feature_map(is_feature));
  check_poincare_hopf(field, 4, "cylinder with features");
  int off = 0;
  for(Edge_index e : edges(cylinder))
  {
    if(!is_feature[e]) continue;
    const auto h = cylinder.halfedge(e);
    Vector_3 along = cylinder.point(cylinder.target(h)) - cylinder.point(cylinder.source(h));
    along = along / std::sqrt(along.squared_length());
    for(auto g : {h, cylinder.opposite(h)})
    {
      const double c = std::abs(field.directions[cylinder.face(g).idx()] * along);
      if(!(c < 1e-9 || c > 1. - 1e-9)) ++off;
    }
  }
  report.check(off == 0, "cylinder: " + std::to_string(off) + " faces at a rim do not follow it");
}

// Prescribed singularities at vertices: the field shows exactly the indices asked for.
typedef std::vector<std::pair<Vertex_index, int> > Vertex_indices;

Face_field prescribed_field(const Mesh& mesh, int n, const Vertex_indices& k)
{
  return face_field(mesh, params::degree(n).prescribed_singularities(k));
}

void check_shows(const Mesh& mesh, int n, const Vertex_indices& k, const std::string& what,
                 bool principal = true)
{
  const Face_field field = prescribed_field(mesh, n, k);
  std::map<Vertex_index, int> asked(k.begin(), k.end()), got(field.singular.begin(), field.singular.end());
  for(auto it = asked.begin(); it != asked.end();) it = it->second == 0 ? asked.erase(it) : std::next(it);
  report.check(asked == got, what + ": the singular vertices are the prescribed ones (" +
                               std::to_string(got.size()) + " found, " + std::to_string(asked.size()) + " asked)");
  report.check(field.result.prescribed, what + ": the result says prescribed");
  if(principal)
    report.check(field.result.number_of_non_principal_jumps == 0,
                 what + ": principal matching (" + std::to_string(field.result.number_of_non_principal_jumps) +
                   " other jumps)");
  check_matching_closes(mesh, field, n, what);
  check_poincare_hopf(field, n, what);
  check_directions(mesh, field, what);
}

// Two vertices joined by an edge, neither singular in `field`.
std::pair<Vertex_index, Vertex_index> free_neighbours(const Mesh& mesh, const Face_field& field)
{
  std::map<Vertex_index, int> singular(field.singular.begin(), field.singular.end());
  for(Edge_index e : edges(mesh))
  {
    const Vertex_index a = mesh.vertex(e, 0), b = mesh.vertex(e, 1);
    if(!mesh.is_border(a) && !mesh.is_border(b) && !singular.count(a) && !singular.count(b)) return {a, b};
  }
  return {Vertex_index(), Vertex_index()};
}

void check_prescriptions_on_spheres()
{
  Mesh sphere;
  make_icosphere(sphere, 3);
  for(int n : {1, 2, 4, 6})
  {
    const Face_field smooth = face_field(sphere, params::degree(n));
    const std::string name = "sphere n = " + std::to_string(n);
    check_shows(sphere, n, smooth.singular, name + ", its own singularities");
    // each singularity moved to a neighbouring vertex that has none
    Vertex_indices moved = smooth.singular;
    std::map<Vertex_index, int> taken(moved.begin(), moved.end());
    for(auto& vk : moved)
      for(auto w : CGAL::vertices_around_target(sphere.halfedge(vk.first), sphere))
        if(!taken.count(w))
        {
          taken.erase(vk.first);
          vk.first = w;
          taken[w] = vk.second;
          break;
        }
    check_shows(sphere, n, moved, name + ", moved to neighbours");
    // an opposite pair at the two ends of one edge, on top of the smoothest singularities
    const auto ab = free_neighbours(sphere, smooth);
    Vertex_indices pair = smooth.singular;
    pair.emplace_back(ab.first, 1);
    pair.emplace_back(ab.second, -1);
    check_shows(sphere, n, pair, name + ", an opposite pair side by side");
    // all of the index on one vertex, and a pair the principal matching cannot read
    check_shows(sphere, n, {{Vertex_index(0), 2 * n}}, name + ", all of the index at one vertex", false);
    Vertex_indices strong = smooth.singular;
    strong.emplace_back(ab.first, 2 * n);
    strong.emplace_back(ab.second, -2 * n);
    // (for n = 1 a direction turning by half a turn or more is refused, so every jump is principal)
    const Face_field field = prescribed_field(sphere, n, strong);
    report.check((n == 1) == (field.result.number_of_non_principal_jumps == 0),
                 name + ": indices +-2n side by side need jumps the principal matching does not read (n > 1)");
    check_shows(sphere, n, strong, name + ", indices +-2n side by side", n == 1);
    // +-3n side by side: each direction would turn by half a turn or more across an edge of their fans
    Vertex_indices too_strong = smooth.singular;
    too_strong.emplace_back(ab.first, 3 * n);
    too_strong.emplace_back(ab.second, -3 * n);
    bool thrown = false;
    try { prescribed_field(sphere, n, too_strong); }
    catch(const SMDF::Invalid_input_error& e) { thrown = std::string(e.what()).find("half a turn") != std::string::npos; }
    report.check(thrown, name + ": indices +-3n side by side are refused (no direction with a matching shows them)");
  }
}

// The class keeps its trees and factorization between prescriptions: the same fields as the free function.
void check_prescription_class()
{
  Mesh sphere;
  make_icosphere(sphere, 3);
  {
    const SMDF::Globally_optimal_face_direction_field<Mesh> object(sphere);
    auto kept = sphere.add_property_map<Face_index, Vector_3>("f:kept").first;
    const Face_field smooth = face_field(sphere, params::degree(4));
    Vertex_indices edited = smooth.singular;
    double worst = 0.;
    for(int round = 0; round < 3; ++round)
    {
      std::map<Vertex_index, int> taken(edited.begin(), edited.end());
      Mesh::size_type next = edited.front().first.idx();
      while(taken.count(Vertex_index(++next))) {}
      edited.front().first = Vertex_index(next);
      for(int n : {4, 2})
      {
        Vertex_indices asked = edited;
        if(n == 2) asked = {{Vertex_index(0), 4}};
        const SMDF::Face_direction_field_result r =
          object.compute(kept, params::degree(n).prescribed_singularities(asked));
        const Face_field once = prescribed_field(sphere, n, asked);
        report.check(r.number_of_singular_vertices == once.result.number_of_singular_vertices,
                     "the class and the free function: the same singular vertices");
        for(Face_index f : faces(sphere))
          worst = (std::max)(worst, std::sqrt((kept[f] - once.directions[f.idx()]).squared_length()));
      }
    }
    report.check(worst == 0., "the class's kept factorization gives the free function's directions (worst " +
                                std::to_string(worst) + ")");
  }
}

// Genus 1 and a boundary.
void check_prescriptions_on_torus_and_disk()
{
  Mesh torus;
  make_torus(torus, 3., 1., 24, 12);
  check_shows(torus, 4, {}, "torus, no singularity");
  check_shows(torus, 4, {{Vertex_index(0), 1}, {Vertex_index(150), -1}}, "torus, a pair");
  Mesh disk;
  make_disk(disk, 8);
  check_shows(disk, 4, {{Vertex_index(0), 1}}, "disk, one singularity");
  check_shows(disk, 4, {{Vertex_index(0), -2}, {Vertex_index(1), 1}}, "disk, two singularities");

}

void check_prescription_refusals()
{
  Mesh sphere, disk;
  make_icosphere(sphere, 3);
  make_disk(disk, 8);
  auto dirs = sphere.add_property_map<Face_index, Vector_3>("f:prescribed").first;
  auto refused = [&](const Mesh& mesh, const Vertex_indices& k, const std::string& what) {
    bool thrown = false;
    try { SMDF::compute_globally_optimal_face_directions(mesh, dirs, params::degree(4).prescribed_singularities(k)); }
    catch(const SMDF::Invalid_input_error& e) { thrown = true; std::cout << "  refused: " << e.what() << "\n"; }
    report.check(thrown, what + " is refused");
  };
  refused(sphere, {{Vertex_index(0), 4}}, "a prescription against Poincare-Hopf");
  refused(sphere, {{Vertex_index(0), 4}, {Vertex_index(0), 4}}, "a vertex listed twice");
  refused(sphere, {{Vertex_index(static_cast<Mesh::size_type>(num_vertices(sphere))), 8}}, "a vertex out of range");
  Vertex_index border;
  for(Vertex_index v : vertices(disk)) if(disk.is_border(v)) border = v;
  auto disk_dirs = disk.add_property_map<Face_index, Vector_3>("f:prescribed").first;
  bool thrown = false;
  try { SMDF::compute_globally_optimal_face_directions(disk, disk_dirs, params::degree(4).prescribed_singularities(
          Vertex_indices{{border, 1}})); }
  catch(const SMDF::Invalid_input_error& e) { thrown = true; std::cout << "  refused: " << e.what() << "\n"; }
  report.check(thrown, "a singularity on the boundary is refused");
  thrown = false;
  try { SMDF::compute_globally_optimal_face_directions(sphere, dirs, params::degree(1).alignment_lambda(-1.)
          .prescribed_singularities(Vertex_indices{{Vertex_index(0), 2}})); }
  catch(const SMDF::Invalid_input_error& e) { thrown = true; std::cout << "  refused: " << e.what() << "\n"; }
  report.check(thrown, "alignment_lambda with a prescription is refused");
}

// singularity_cancellation_radius with feature edges (loops around the walls
// of the perforated slab): the field is turned
// off the constrained faces, which keep their directions; the pairs go, the
// index sum stays, the field shows exactly the singularities left.
void check_cancellation_along_features(const Mesh& mesh)
{
  // the features: the loops halfway up the walls (the slab is symmetric about z = 1/2)
  auto is_feature = const_cast<Mesh&>(mesh).add_property_map<Edge_index, bool>("e:feature", false).first;
  std::size_t features = 0;
  for(Edge_index e : edges(mesh))
  {
    const auto halfway = [&](Vertex_index v) { return std::abs(mesh.point(v).z() - 0.5) < 1e-9; };
    if(halfway(source(e, mesh)) && halfway(target(e, mesh))) is_feature[e] = true, ++features;
  }
  const auto with_features = params::degree(4).edge_is_feature_map(is_feature);
  const Face_field aligned = face_field(mesh, with_features);
  const Face_field fewer = face_field(mesh, with_features.singularity_cancellation_radius(10.));
  std::map<Vertex_index, int> own(aligned.singular.begin(), aligned.singular.end());
  bool subset = true;
  for(const auto& vk : fewer.singular) subset = subset && own.count(vk.first) && own[vk.first] == vk.second;
  report.check(features > 0 && fewer.result.number_of_cancelled_pairs > 0 && !fewer.result.prescribed && subset &&
                 fewer.singular.size() + 2 * fewer.result.number_of_cancelled_pairs == aligned.singular.size() &&
                 fewer.result.index_sum == aligned.result.index_sum,
               "perforated slab with " + std::to_string(features) + " feature edges: " +
                 std::to_string(fewer.result.number_of_cancelled_pairs) + " pairs of " +
                 std::to_string(aligned.singular.size()) + " singular vertices cancelled, the others kept");
  double moved = 0.;
  for(Edge_index e : edges(mesh))
    if(is_feature[e])
      for(Mesh::Halfedge_index h : {halfedge(e, mesh), opposite(halfedge(e, mesh), mesh)})
      {
        const std::size_t f = static_cast<std::size_t>(face(h, mesh));
        moved = (std::max)(moved, std::sqrt((fewer.directions[f] - aligned.directions[f]).squared_length()));
      }
  std::cout << "  perforated slab with " << features << " feature edges: " << aligned.singular.size() << " -> "
            << fewer.singular.size() << " singular vertices, constrained faces moved by " << moved << "\n";
  report.check(moved < 1e-12, "the faces along the features keep their directions (moved by " + std::to_string(moved) + ")");
  check_poincare_hopf(fewer, 4, "perforated slab with features after cancellation");
  check_matching_closes(mesh, fewer, 4, "perforated slab with features after cancellation");
  const_cast<Mesh&>(mesh).remove_property_map(is_feature);
}

// singularity_cancellation_radius: pairs of opposite singular vertices go,
// the index sum stays, the field shows exactly the singularities left; a
// radius below every edge's length cancels nothing and changes nothing.
void check_singularity_cancellation()
{
  Mesh lumpy, torus;
  make_perforated_slab(lumpy, 3, 12);  // holes and corners: singularities of both signs
  make_torus(torus, 3., 1., 48, 20);
  for(const Mesh* mesh : {&lumpy, &torus})
  {
    const std::string what = mesh == &lumpy ? "perforated slab" : "torus";
    const Face_field smooth = face_field(*mesh, params::degree(4));
    const Face_field fewer = face_field(*mesh, params::degree(4).singularity_cancellation_radius(10.));
    long long positive = 0, negative = 0;
    for(const auto& vk : smooth.singular) (vk.second > 0 ? positive : negative) += 1;
    report.check(fewer.result.number_of_cancelled_pairs > 0 && fewer.result.prescribed &&
                   fewer.singular.size() + 2 * fewer.result.number_of_cancelled_pairs == smooth.singular.size() &&
                   fewer.result.index_sum == smooth.result.index_sum,
                 what + ": " + std::to_string(fewer.result.number_of_cancelled_pairs) + " pairs of " +
                   std::to_string(smooth.singular.size()) + " singular vertices cancelled, the index sum kept");
    std::map<Vertex_index, int> kept(smooth.singular.begin(), smooth.singular.end());
    bool subset = true;
    for(const auto& vk : fewer.singular) subset = subset && kept.count(vk.first) && kept[vk.first] == vk.second;
    report.check(subset, what + ": the singularities left are the smoothest field's own");
    check_poincare_hopf(fewer, 4, what + " after cancellation");
    check_matching_closes(*mesh, fewer, 4, what + " after cancellation");
    const Face_field same = face_field(*mesh, params::degree(4).singularity_cancellation_radius(1e-9));
    report.check(same.result.number_of_cancelled_pairs == 0 && !same.result.prescribed &&
                   same.directions == smooth.directions && same.singular == smooth.singular,
                 what + ": a radius below every edge cancels nothing and gives the smoothest field");
  }
  check_cancellation_along_features(lumpy);
  auto dirs = lumpy.add_property_map<Face_index, Vector_3>("f:cancelled").first;
  for(const auto& [np_name, refuse] : std::vector<std::pair<std::string, std::function<void()> > >{
        {"a negative radius", [&] { SMDF::compute_globally_optimal_face_directions(
                                      lumpy, dirs, params::singularity_cancellation_radius(-1.)); }},
        {"a prescription", [&] { SMDF::compute_globally_optimal_face_directions(
                                   lumpy, dirs, params::singularity_cancellation_radius(0.1).prescribed_singularities(
                                     Vertex_indices{{Vertex_index(0), 8}})); }}})
  {
    bool thrown = false;
    try { refuse(); }
    catch(const SMDF::Invalid_input_error& e) { thrown = true; std::cout << "  refused: " << e.what() << "\n"; }
    report.check(thrown, "singularity_cancellation_radius with " + np_name + " is refused");
  }
}

} // namespace

// A given lambda_t is in the user's units, as on vertices: the same field on the mesh scaled by 1e-35 with
// lambda_t / 1e-70, and the report gives back the lambda_t asked for (the engine computes in coordinates
// normalized at such scales; before the face engine was the vertex one, it took lambda_t in those units).
void check_lambda_units()
{
  Mesh ellipsoid, scaled;
  make_jittered_ellipsoid(ellipsoid, 3, 1.3, 1., 0.7, 0.05, 3);
  scaled = ellipsoid;
  for(Vertex_index v : vertices(scaled)) scaled.point(v) = CGAL::ORIGIN + 1e-35 * (scaled.point(v) - CGAL::ORIGIN);
  const double lambda_1 = face_field(ellipsoid, params::degree(4)).result.components[0].eigenvalue.value();
  const double lambda = -0.5 * lambda_1;
  const auto aligned = [&](const Mesh& mesh, double l) {
    return face_field(mesh, params::degree(4)
                              .principal_curvature_alignment(SMDF::Principal_curvature_alignment::MAXIMUM)
                              .alignment_lambda(l));
  };
  const double scaled_lambda = lambda / (1e-35 * 1e-35);
  const Face_field unit = aligned(ellipsoid, lambda), small = aligned(scaled, scaled_lambda);
  report.check(std::abs(unit.result.components[0].lambda / lambda - 1.) < 1e-12 &&
                 std::abs(small.result.components[0].lambda / scaled_lambda - 1.) < 1e-12,
               "faces: the report's lambda_t is the one given (" + std::to_string(unit.result.components[0].lambda) +
                 " for " + std::to_string(lambda) + ")");
  double worst = 0.;
  for(std::size_t f = 0; f < unit.directions.size(); ++f)
    worst = (std::max)(worst, std::sqrt((unit.directions[f] - small.directions[f] / std::sqrt(small.directions[f].squared_length())).squared_length()));
  report.check(worst < 1e-6 && unit.singular == small.singular,
               "faces: lambda_t / 1e-70 on the mesh scaled by 1e-35 gives the same field (" + std::to_string(worst) + ")");
}

// Non-manifold meshes kept whole (vertex_point_index_map): a soup with
// non-manifold edges, cut into a mesh by orient_polygon_soup() (which copies
// the points it cuts at), and the point each vertex copies.
struct Soup
{
  std::vector<Point_3> points;
  std::vector<std::vector<std::size_t> > triangles;
  std::map<std::array<double, 3>, std::size_t> index;
  std::size_t point(double x, double y, double z)
  {
    const auto found = index.emplace(std::array<double, 3>{x, y, z}, points.size());
    if(found.second) points.emplace_back(x, y, z);
    return found.first->second;
  }
  // the surface of the cube [o, o + 1]^3, m x m squares per side, each in two triangles, outward
  void add_cube(double ox, double oy, double oz, int m)
  {
    for(int axis = 0; axis < 3; ++axis)
      for(int side = 0; side < 2; ++side)
        for(int i = 0; i < m; ++i)
          for(int j = 0; j < m; ++j)
          {
            auto at = [&](int a, int b) {
              double p[3];
              p[axis] = side;
              p[(axis + 1) % 3] = double(a) / m;
              p[(axis + 2) % 3] = double(b) / m;
              return point(ox + p[0], oy + p[1], oz + p[2]);
            };
            const std::size_t a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
            if(side == 1) { triangles.push_back({a, b, c}); triangles.push_back({a, c, d}); }
            else { triangles.push_back({a, c, b}); triangles.push_back({a, d, c}); }
          }
  }
};

struct Glued_mesh
{
  Mesh mesh;
  std::vector<std::size_t> point_of_vertex;  // by vertex index
};

Glued_mesh cut_into_mesh(Soup soup)
{
  Glued_mesh g;
  const std::size_t original = soup.points.size();
  CGAL::Polygon_mesh_processing::orient_polygon_soup(soup.points, soup.triangles);
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.triangles, g.mesh);
  for(std::size_t v = 0; v < soup.points.size(); ++v)
  {
    const Point_3& p = soup.points[v];
    g.point_of_vertex.push_back(v < original ? v : soup.index.at({p.x(), p.y(), p.z()}));
  }
  return g;
}

// The angle of d from the direction of a -> b, counter-clockwise about face f's normal.
double angle_from_side(const Mesh& mesh, Face_index f, const Point_3& a, const Point_3& b, const Vector_3& d)
{
  const auto h = mesh.halfedge(f);
  const Vector_3 normal = CGAL::cross_product(mesh.point(mesh.target(h)) - mesh.point(mesh.source(h)),
                                              mesh.point(mesh.target(mesh.next(h))) - mesh.point(mesh.source(h)));
  const Vector_3 e = b - a;
  return std::atan2(CGAL::cross_product(e, d) * normal / std::sqrt(normal.squared_length()), e * d);
}

// Per pair of faces on one non-manifold edge (three faces or more there), n times the difference of their
// directions' angles from the edge (each about its own normal), reduced to (-pi, pi]: 0 where the field is
// parallel across the pair.
std::vector<double> glued_differences(const Glued_mesh& g, const Face_field& field, int n)
{
  std::map<std::pair<std::size_t, std::size_t>, std::vector<Mesh::Halfedge_index> > sides;
  for(Face_index f : faces(g.mesh))
    for(auto h : CGAL::halfedges_around_face(g.mesh.halfedge(f), g.mesh))
    {
      const std::size_t a = g.point_of_vertex[g.mesh.source(h)], b = g.point_of_vertex[g.mesh.target(h)];
      sides[{(std::min)(a, b), (std::max)(a, b)}].push_back(h);
    }
  std::vector<double> differences;
  for(const auto& edge : sides)
  {
    if(edge.second.size() < 3) continue;
    const Point_3& a = g.mesh.point(g.mesh.source(edge.second[0]));
    const Point_3& b = g.mesh.point(g.mesh.target(edge.second[0]));
    std::vector<double> angle;
    for(auto h : edge.second)
      angle.push_back(angle_from_side(g.mesh, g.mesh.face(h), a, b, field.directions[g.mesh.face(h).idx()]));
    for(std::size_t i = 0; i < angle.size(); ++i)
      for(std::size_t j = i + 1; j < angle.size(); ++j)
        differences.push_back(std::remainder(n * (angle[j] - angle[i]), 2 * CGAL_PI));
  }
  return differences;
}

// A fin (a 2 x 2 square standing on the top of a cube) and two cubes sharing an edge: every face is flat
// and every edge along an axis, so the glued cross field is parallel (eigenvalue 0, no turn across any
// pair of faces on a non-manifold edge) and one component; cut, each piece is a field of its own.
void check_glued_cubes(const std::string& what, const Soup& soup, std::size_t pieces, std::size_t edges)
{
  const Glued_mesh g = cut_into_mesh(soup);
  const auto point_map = CGAL::make_property_map(g.point_of_vertex);
  const Face_field glued = face_field(g.mesh, params::degree(4).vertex_point_index_map(point_map));
  const Face_field cut = face_field(g.mesh, params::degree(4));
  report.check(glued.result.components.size() == 1 && cut.result.components.size() == pieces,
               what + ": one component glued (" + std::to_string(glued.result.components.size()) + "), " +
                 std::to_string(pieces) + " cut (" + std::to_string(cut.result.components.size()) + ")");
  report.check(glued.result.number_of_glued_edges == edges && cut.result.number_of_glued_edges == 0,
               what + ": " + std::to_string(edges) + " glued edges (" +
                 std::to_string(glued.result.number_of_glued_edges) + ")");
  report.check(std::abs(glued.result.components[0].eigenvalue.value_or(1.)) < 1e-10, what + ": eigenvalue 0");
  double worst = 0.;
  for(double d : glued_differences(g, glued, 4)) worst = (std::max)(worst, std::abs(d));
  report.check(worst < 1e-8, what + ": parallel across the glued pairs (" + std::to_string(worst) + ")");
  check_poincare_hopf(glued, 4, what + ", glued");
  check_directions(g.mesh, glued, what + ", glued");
}

void check_non_manifold_meshes()
{
  Soup fin;
  fin.add_cube(0, 0, 0, 4);
  for(int i = 0; i < 2; ++i)
    for(int j = 0; j < 2; ++j)
    {
      auto at = [&](int a, int b) { return fin.point(0.25 + 0.25 * a, 0.5, 1. + 0.25 * b); };
      fin.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      fin.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  check_glued_cubes("a fin on a cube", fin, 2, 2);
  Soup two;
  two.add_cube(0, 0, 0, 3);
  two.add_cube(1, 1, 0, 3);
  check_glued_cubes("two cubes sharing an edge", two, 2, 3);

  // Two cubes sharing a vertex: no non-manifold edge, nothing glued; the same field with or without the map.
  Soup bowtie;
  bowtie.add_cube(0, 0, 0, 3);
  bowtie.add_cube(1, 1, 1, 3);
  const Glued_mesh b = cut_into_mesh(bowtie);
  const Face_field with =
    face_field(b.mesh, params::degree(4).vertex_point_index_map(CGAL::make_property_map(b.point_of_vertex)));
  const Face_field without = face_field(b.mesh, params::degree(4));
  report.check(with.directions == without.directions && with.result.components.size() == 2 &&
                 with.result.number_of_glued_edges == 0,
               "two cubes sharing a vertex: two fields, the map changes nothing");

  // A curved surface with fins: an icosphere with a triangle standing on 6 of its edges. Each fin follows
  // its two neighbours: n times its angle lies on the shorter arc between theirs.
  Mesh sphere;
  make_icosphere(sphere, 2);
  Soup fins;
  for(Vertex_index v : vertices(sphere)) fins.point(sphere.point(v).x(), sphere.point(v).y(), sphere.point(v).z());
  for(Face_index f : faces(sphere))
  {
    fins.triangles.emplace_back();
    for(Vertex_index v : CGAL::vertices_around_face(sphere.halfedge(f), sphere)) fins.triangles.back().push_back(v);
  }
  for(std::size_t k = 0; k < 6; ++k)
  {
    const auto e = *std::next(edges(sphere).begin(), static_cast<std::ptrdiff_t>(37 * k));
    const Point_3 &p = sphere.point(source(e, sphere)), &q = sphere.point(target(e, sphere));
    const Point_3 apex = CGAL::midpoint(p, q) + 0.3 * (CGAL::midpoint(p, q) - CGAL::ORIGIN);
    fins.triangles.push_back({std::size_t(source(e, sphere)), std::size_t(target(e, sphere)),
                              fins.point(apex.x(), apex.y(), apex.z())});
  }
  const Glued_mesh g = cut_into_mesh(fins);
  const Face_field glued =
    face_field(g.mesh, params::degree(4).vertex_point_index_map(CGAL::make_property_map(g.point_of_vertex)));
  report.check(glued.result.components.size() == 1 && glued.result.number_of_glued_edges == 6,
               "a sphere with fins: one component, six edges glued");
  check_poincare_hopf(glued, 4, "a sphere with fins, glued");
  const std::vector<double> d = glued_differences(g, glued, 4);  // per fin: sphere-sphere, sphere-fin, sphere-fin
  bool between = d.size() == 18;
  for(std::size_t k = 0; between && k < 6; ++k)
  {
    const double ab = d[3 * k], ac = d[3 * k + 1], bc = d[3 * k + 2];  // the fin is the side listed last
    between = (ab >= 0. ? ac >= -1e-9 && ac <= ab + 1e-9 : ac <= 1e-9 && ac >= ab - 1e-9) &&
              std::abs(std::remainder(ac - ab - bc, 2 * CGAL_PI)) < 1e-9;
  }
  report.check(between, "a sphere with fins: each fin's direction between its two neighbours'");

  bool refused = false;
  try { face_field(g.mesh, params::degree(4).vertex_point_index_map(CGAL::make_property_map(g.point_of_vertex))
                             .singularity_cancellation_radius(0.1)); }
  catch(const SMDF::Invalid_input_error& e) { refused = true; std::cout << "  refused: " << e.what() << "\n"; }
  report.check(refused, "glued non-manifold edges with singularity_cancellation_radius are refused");
}

int main()
{
  check_lambda_units();
  check_sphere();
  check_torus_and_disk();
  check_corner_numbering_invariance();
  check_constraints_and_refusals();
  check_features();
  check_prescriptions_on_spheres();
  check_prescription_class();
  check_prescriptions_on_torus_and_disk();
  check_prescription_refusals();
  check_singularity_cancellation();
  check_non_manifold_meshes();
  return report.finish();
}
