// Prescribed singularities (named parameter prescribed_singularities):
//  * the field's own indices are exactly the prescription, face for face, on
//    spheres (n = 1, 2, 4, 6), a torus (none), a genus-2 surface (eight
//    -1/4), a disk, an open cylinder and a mesh of two components;
//  * the adjusted connection's holonomy error is at rounding level, and the
//    holonomy around the torus's loops is a multiple of 2 pi / n;
//  * Poincare-Hopf violations, faces listed twice or out of range, an index a
//    triangle cannot show, and the options that do not combine are clear errors;
//  * the class reuses its factorization: a moved singularity gives the same
//    bits as a fresh object, and the singular set follows the move;
//  * a constrained vertex fixes the rotation exactly, a guidance field rotates
//    the field towards itself;
//  * the cycle basis has 2g handle loops and every boundary loop (one free per
//    component); the change meets every equation and is the least one (its
//    weighted divergence vanishes at every vertex but the roots); scaling the
//    mesh changes nothing;
//  * prescription_loops() gives closed loops of halfedges; the turns asked of a
//    loop (prescribed_loop_turns) are what the field does there, and a free
//    boundary loop accepts only the turns the indices imply;
//  * a field's own singular faces and loop turns (result.loop_turns) give its
//    singularities back, face for face, on perforated slabs of genus 4 and 9
//    at n = 1 ... 8 and 100 (the turns are needed: without them some are
//    refused, with a message that says so); loop turns without a
//    prescription are refused.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/cgal_compatibility.h>
// the internals checked below (the engine itself may be compiled apart)
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/cycles.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/extrinsic_directions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/guidance.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/prescribed_singularities.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>

#include "test_types.h"
#include "generated_meshes.h"
#include "test_support.h"

#include <array>
#include <cmath>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;

typedef std::vector<std::pair<Face_index, int> > Prescription;

static Point_3 centroid(const Mesh& mesh, Face_index f)
{
  double x = 0., y = 0., z = 0.;
  for(Vertex_index v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
  {
    x += mesh.point(v).x() / 3.;
    y += mesh.point(v).y() / 3.;
    z += mesh.point(v).z() / 3.;
  }
  return Point_3(x, y, z);
}

// The face whose centroid is nearest to p.
static Face_index nearest_face(const Mesh& mesh, const Point_3& p)
{
  Face_index best;
  double best_distance = 1e300;
  for(Face_index f : mesh.faces())
  {
    const double d = CGAL::squared_distance(centroid(mesh, f), p);
    if(d < best_distance) { best_distance = d; best = f; }
  }
  return best;
}

static Prescription at_points(const Mesh& mesh, const std::vector<Point_3>& points, int k)
{
  Prescription p;
  for(const Point_3& q : points) p.emplace_back(nearest_face(mesh, q), k);
  return p;
}

struct Outcome
{
  SMDF::Direction_field_result result;
  std::map<Face_index, int> singular;
  std::string error;
};

static Outcome prescribe(const Mesh& mesh, int n, const Prescription& p)
{
  Outcome o;
  auto dir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(mesh, "v:direction").value();
  std::vector<std::pair<Face_index, int> > found;
  try
  {
    o.result = SMDF::compute_globally_optimal_directions(
      mesh, dir, params::degree(n).prescribed_singularities(p).singularities_output_iterator(std::back_inserter(found)));
  }
  catch(const SMDF::Invalid_input_error& e)
  {
    o.error = e.what();
  }
  for(const auto& s : found) o.singular[s.first] = s.second;
  return o;
}

static bool matches(const Outcome& o, const Prescription& p)
{
  std::map<Face_index, int> wanted;
  for(const auto& s : p)
    if(s.second != 0) wanted[s.first] = s.second;
  return o.error.empty() && o.singular == wanted;
}

static void check_exact(Test_report& report, const std::string& name, const Mesh& mesh, int n, const Prescription& p)
{
  const Outcome o = prescribe(mesh, n, p);
  report.check(o.error.empty(), name + ": computed (" + o.error + ")");
  report.check(matches(o, p), name + ": the singular faces are exactly the prescribed ones (" +
                                std::to_string(o.singular.size()) + " found, " + std::to_string(p.size()) + " asked)");
  report.check(o.result.prescribed, name + ": the result says prescribed");
  report.check(o.result.holonomy_error < 1e-9, name + ": holonomy error " + std::to_string(o.result.holonomy_error));
  std::cout << name << ": " << o.singular.size() << " singular faces, holonomy error " << o.result.holonomy_error
            << ", " << o.result.timings.total_ms << " ms" << std::endl;
}

static Mesh with_direction_map(Mesh mesh)
{
  mesh.add_property_map<Vertex_index, Vector_3>("v:direction", Vector_3(0, 0, 0));
  return mesh;
}

static Mesh sphere(int subdivisions)
{
  Mesh mesh;
  make_icosphere(mesh, subdivisions);
  return with_direction_map(mesh);
}

static std::vector<Point_3> cube_corners()
{
  std::vector<Point_3> p;
  for(int i = 0; i < 8; ++i) p.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  return p;
}

static void check_spheres(Test_report& report)
{
  const Mesh mesh = sphere(4);
  check_exact(report, "sphere n=4, cube corners", mesh, 4, at_points(mesh, cube_corners(), 1));
  check_exact(report, "sphere n=1, two poles", mesh, 1, at_points(mesh, {Point_3(0, 0, 1), Point_3(0, 0, -1)}, 1));
  check_exact(report, "sphere n=1, two +1 anywhere", mesh, 1,
              at_points(mesh, {Point_3(0.05, 0.02, 1), Point_3(0.3, 0.6, -0.5)}, 1));
  check_exact(report, "sphere n=2, tetrahedron", mesh, 2,
              at_points(mesh, {Point_3(1, 1, 1), Point_3(1, -1, -1), Point_3(-1, 1, -1), Point_3(-1, -1, 1)}, 1));
  // n = 1: an index +2 is more than a triangle can show (refused below), but
  // two faces with one face between them can hold +1 each (two neighbouring
  // faces cannot: the four outer sides of the pair would have to turn by 4 pi)
  const Face_index pole = nearest_face(mesh, Point_3(0, 0, 1));
  const Mesh::Halfedge_index across = mesh.opposite(mesh.halfedge(pole));
  check_exact(report, "sphere n=1, +2 as +1 in two faces one apart", mesh, 1,
              {{pole, 1}, {mesh.face(mesh.opposite(mesh.next(across))), 1}});
  // n = 6: twelve +1/6 at the icosahedron's vertex directions (Sigma = 6 chi = 12)
  Mesh ico;
  make_icosphere(ico, 0);
  std::vector<Point_3> twelve;
  for(Vertex_index v : ico.vertices()) twelve.push_back(ico.point(v));
  check_exact(report, "sphere n=6, icosahedron", mesh, 6, at_points(mesh, twelve, 1));
  // a mixed prescription: n = 4, ten +1 and two -1 (Sigma = 8)
  Prescription mixed = at_points(mesh, cube_corners(), 1);
  const Prescription extra = at_points(mesh, {Point_3(0, 0, 1), Point_3(0, 0, -1)}, 1);
  mixed.insert(mixed.end(), extra.begin(), extra.end());
  const Prescription minus = at_points(mesh, {Point_3(0, 1, 0), Point_3(0, -1, 0)}, -1);
  mixed.insert(mixed.end(), minus.begin(), minus.end());
  check_exact(report, "sphere n=4, ten +1/4 and two -1/4", mesh, 4, mixed);
  // the field is a unit tangent field at every vertex (tangent to the
  // package's vertex normal, within 1e-2 of the sphere's)
  auto dir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(mesh, "v:direction").value();
  double worst_length = 0., worst_normal = 0.;
  for(Vertex_index v : mesh.vertices())
  {
    const Vector_3 d = dir[v], normal = mesh.point(v) - CGAL::ORIGIN;
    worst_length = (std::max)(worst_length, std::abs(d.squared_length() - 1.));
    worst_normal = (std::max)(worst_normal, std::abs(d * normal));
  }
  report.check(worst_length < 1e-12 && worst_normal < 1e-2,
               "sphere: unit tangent directions (" + std::to_string(worst_length) + ", " + std::to_string(worst_normal) + ")");
}

// A genus-2 surface: the boundary of 5 x 1 x 3 unit cubes with the cubes
// (1, 0, 1) and (3, 0, 1) removed (two holes along y), each square face split
// into m x m squares of two triangles, optionally rounded by `smoothing`
// steps that move every vertex halfway to the mean of its neighbours. (The
// cubes' corners concentrate the curvature in single vertices: the least-norm
// change of the connection then turns by more than pi along some edges, and
// the reweighting has to spread it.)
static Mesh genus_two(int m, int smoothing)
{
  auto solid = [](int x, int y, int z) {
    if(x < 0 || x > 4 || y != 0 || z < 0 || z > 2) return false;
    return !(z == 1 && (x == 1 || x == 3));
  };
  Mesh mesh;
  std::map<std::array<int, 3>, Vertex_index> vertex;
  auto at = [&](const std::array<int, 3>& p) {
    auto it = vertex.find(p);
    if(it != vertex.end()) return it->second;
    const Vertex_index v = mesh.add_vertex(Point_3(double(p[0]) / m, double(p[1]) / m, double(p[2]) / m));
    vertex[p] = v;
    return v;
  };
  for(int x = -1; x <= 5; ++x)
    for(int y = -1; y <= 1; ++y)
      for(int z = -1; z <= 3; ++z)
        for(int axis = 0; axis < 3; ++axis)
        {
          std::array<int, 3> c{x, y, z}, d = c;
          d[axis] += 1;
          if(solid(c[0], c[1], c[2]) == solid(d[0], d[1], d[2])) continue;
          const bool outward = solid(c[0], c[1], c[2]);  // the normal points along +axis
          const int u = (axis + 1) % 3, w = (axis + 2) % 3;
          for(int i = 0; i < m; ++i)
            for(int j = 0; j < m; ++j)
            {
              std::array<int, 3> q[4];
              for(int k = 0; k < 4; ++k)
              {
                q[k] = {d[0] * m, d[1] * m, d[2] * m};
                q[k][u] = c[u] * m + i + (k == 1 || k == 2);
                q[k][w] = c[w] * m + j + (k >= 2);
              }
              if(outward)
              { mesh.add_face(at(q[0]), at(q[1]), at(q[2])); mesh.add_face(at(q[0]), at(q[2]), at(q[3])); }
              else
              { mesh.add_face(at(q[0]), at(q[2]), at(q[1])); mesh.add_face(at(q[0]), at(q[3]), at(q[2])); }
            }
        }
  for(int step = 0; step < smoothing; ++step)
  {
    std::vector<Point_3> moved;
    for(Vertex_index v : mesh.vertices())
    {
      Vector_3 sum(0, 0, 0);
      int count = 0;
      for(Vertex_index w : CGAL::vertices_around_target(mesh.halfedge(v), mesh)) { sum = sum + (mesh.point(w) - CGAL::ORIGIN); ++count; }
      moved.push_back(mesh.point(v) + 0.5 * (CGAL::ORIGIN + sum / count - mesh.point(v)));
    }
    std::size_t i = 0;
    for(Vertex_index v : mesh.vertices()) mesh.point(v) = moved[i++];
  }
  return with_direction_map(mesh);
}

static void check_other_topologies(Test_report& report)
{
  Mesh torus;
  make_torus(torus, 1., 0.4, 60, 24);
  torus = with_direction_map(torus);
  check_exact(report, "torus n=4, none", torus, 4, {});
  Prescription saddle = at_points(torus, {Point_3(1.4, 0, 0)}, 1);
  saddle.push_back({nearest_face(torus, Point_3(-0.6, 0, 0)), -1});
  check_exact(report, "torus n=1, +1 outside and -1 inside", torus, 1, saddle);

  const Mesh g2 = genus_two(6, 0);  // the cubes' corners as they are: the reweighted change is needed
  report.check(CGAL::is_closed(g2) && g2.number_of_vertices() - g2.number_of_edges() + g2.number_of_faces() == -2,
               "genus-2 generator: closed, chi = -2");
  check_exact(report, "genus 2 n=4, eight -1/4", g2, 4,
              at_points(g2, {Point_3(0.5, 0, 0.5), Point_3(1.5, 0, 0.5), Point_3(2.5, 0, 0.5), Point_3(3.5, 0, 0.5),
                             Point_3(0.5, 1, 2.5), Point_3(1.5, 1, 2.5), Point_3(2.5, 1, 2.5), Point_3(3.5, 1, 2.5)},
                        -1));

  Mesh disk;
  make_disk(disk, 20);
  disk = with_direction_map(disk);
  check_exact(report, "disk n=4, none", disk, 4, {});
  check_exact(report, "disk n=4, one +1/4", disk, 4, at_points(disk, {Point_3(0.1, 0.05, 0)}, 1));
  check_exact(report, "disk n=1, +1 and +1", disk, 1, at_points(disk, {Point_3(0.5, 0, 0), Point_3(-0.5, 0, 0)}, 1));

  Mesh cylinder;
  make_cylinder(cylinder, 1., 2., 48, 24);
  cylinder = with_direction_map(cylinder);
  Prescription annulus = at_points(cylinder, {Point_3(1, 0, 1)}, 1);
  const Prescription minus = at_points(cylinder, {Point_3(-1, 0, 1)}, -1);
  annulus.insert(annulus.end(), minus.begin(), minus.end());
  check_exact(report, "open cylinder n=4, +1/4 and -1/4", cylinder, 4, annulus);

  // two components: a sphere and a torus beside it
  Mesh two;
  make_icosphere(two, 3);
  Mesh ring;
  make_torus(ring, 1., 0.4, 48, 20);
  std::map<Vertex_index, Vertex_index> copy;
  for(Vertex_index v : ring.vertices()) copy[v] = two.add_vertex(ring.point(v) + Vector_3(4, 0, 0));
  for(Face_index f : ring.faces())
  {
    std::vector<Vertex_index> vs;
    for(Vertex_index v : CGAL::vertices_around_face(ring.halfedge(f), ring)) vs.push_back(copy[v]);
    two.add_face(vs);
  }
  two = with_direction_map(two);
  Prescription both = at_points(two, cube_corners(), 1);
  both.push_back({nearest_face(two, Point_3(5.4, 0, 0)), 1});                   // +1/4 and -1/4 on the torus
  both.push_back({nearest_face(two, Point_3(3.6, 0, 0)), -1});
  check_exact(report, "sphere + torus n=4, eight +1/4 and a pair", two, 4, both);
}

static bool error_contains(const Outcome& o, const std::string& a, const std::string& b = "")
{
  return !o.error.empty() && o.error.find(a) != std::string::npos && o.error.find(b) != std::string::npos &&
         o.error.find('\n') == std::string::npos;
}

static void check_errors(Test_report& report)
{
  const Mesh mesh = sphere(3);
  // Poincare-Hopf: n chi = 8 on a sphere, 7 given
  Prescription seven = at_points(mesh, cube_corners(), 1);
  seven.pop_back();
  Outcome o = prescribe(mesh, 4, seven);
  report.check(error_contains(o, "add up to 7", "= 8"), "Poincare-Hopf violated: both sums named (" + o.error + ")");
  o = prescribe(mesh, 4, {});
  report.check(error_contains(o, "add up to 0", "= 8"), "nothing prescribed on a sphere: refused (" + o.error + ")");
  Prescription twice = at_points(mesh, cube_corners(), 1);
  twice[1].first = twice[0].first;
  o = prescribe(mesh, 4, twice);
  report.check(error_contains(o, "twice"), "a face listed twice (" + o.error + ")");
  o = prescribe(mesh, 1, at_points(mesh, {Point_3(0, 0, 1)}, 2));
  report.check(error_contains(o, "cannot hold index 2/1"), "+2 in one triangle (" + o.error + ")");
  o = prescribe(mesh, 1, {{Face_index(static_cast<Mesh::size_type>(mesh.number_of_faces() + 5)), 2}});
  report.check(error_contains(o, "names face"), "a face out of range (" + o.error + ")");
  // singularities in adjacent faces that ask more than pi of their shared edge
  const Face_index f0 = nearest_face(mesh, Point_3(0, 0, 1));
  const Face_index f1 = mesh.face(mesh.opposite(mesh.halfedge(f0)));
  const Face_index f2 = mesh.face(mesh.opposite(mesh.next(mesh.halfedge(f0))));
  o = prescribe(mesh, 1, {{f0, 1}, {f1, 1}, {f2, 1}, {nearest_face(mesh, Point_3(0, 0, -1)), -1}});
  report.check(error_contains(o, "more than pi along an edge") || matches(o, {{f0, 1}, {f1, 1}, {f2, 1},
                                                                      {nearest_face(mesh, Point_3(0, 0, -1)), -1}}),
               "crowded singularities: exact or refused, never a wrong field (" + o.error + ")");
  // two +1/4 side by side on a flat disk ask two full turns of the four outer sides: refused before any
  // solve, naming both faces, and the exception carries the first
  Mesh disk;
  make_disk(disk, 8);
  disk = with_direction_map(disk);
  const Face_index d0 = nearest_face(disk, Point_3(0.3, 0.1, 0)), d1 = disk.face(disk.opposite(disk.halfedge(d0)));
  std::size_t named_face = std::size_t(-1);
  try
  {
    auto ddir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(disk, "v:direction").value();
    SMDF::compute_globally_optimal_directions(disk, ddir, params::degree(4).prescribed_singularities(
                                                            Prescription{{d0, 1}, {d1, 1}}));
  }
  catch(const SMDF::Invalid_input_error& e)
  {
    o.error = e.what();
    if(e.has_face()) named_face = e.face();
  }
  const std::size_t first = (std::min)(std::size_t(d0), std::size_t(d1));
  report.check(o.error.find("move them apart") != std::string::npos && named_face == first &&
                 o.error.find("face " + std::to_string(std::size_t(d0))) != std::string::npos &&
                 o.error.find("face " + std::to_string(std::size_t(d1))) != std::string::npos,
               "neighbouring +1/4 and +1/4 on a flat disk: refused by the local check, both faces named (" +
                 o.error + ")");

  auto dir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(mesh, "v:direction").value();
  const Prescription eight = at_points(mesh, cube_corners(), 1);
  auto refused = [&](auto np, const std::string& what) {
    try
    {
      SMDF::compute_globally_optimal_directions(mesh, dir, np.prescribed_singularities(eight));
    }
    catch(const SMDF::Invalid_input_error& e)
    {
      return report.check(std::string(e.what()).find(what) != std::string::npos, std::string("refused: ") + e.what());
    }
    return report.check(false, "not refused: " + what);
  };
  refused(params::degree(4).alignment_lambda(0.), "alignment_lambda");
  refused(params::degree(4).alignment_weight(0.5), "alignment_weight");
  refused(params::degree(4).compute_eigenvalue_bound(true), "compute_eigenvalue_bound");
}

// The class keeps its factorization: a moved singularity costs one solve and
// gives the same bits as a fresh object.
static void check_editing(Test_report& report)
{
  const Mesh mesh = sphere(4);
  Prescription p = at_points(mesh, cube_corners(), 1);
  auto dir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(mesh, "v:direction").value();
  SMDF::Globally_optimal_direction_field<Mesh> field(mesh);
  field.compute(dir, params::degree(4).prescribed_singularities(p));
  // move the first singularity to a neighbouring face
  p[0].first = mesh.face(mesh.opposite(mesh.halfedge(p[0].first)));
  std::vector<std::pair<Face_index, int> > found;
  const SMDF::Direction_field_result edited = field.compute(
    dir, params::degree(4).prescribed_singularities(p).singularities_output_iterator(std::back_inserter(found)));
  std::map<Face_index, int> got(found.begin(), found.end()), wanted(p.begin(), p.end());
  report.check(got == wanted, "edit: the singular set follows the moved singularity");
  report.check(edited.timings.factorization_ms == 0., "edit: no new factorization");
  std::vector<Vector_3> first;
  for(Vertex_index v : mesh.vertices()) first.push_back(dir[v]);
  SMDF::Globally_optimal_direction_field<Mesh> fresh(mesh);
  fresh.compute(dir, params::degree(4).prescribed_singularities(p));
  bool same = true;
  std::size_t i = 0;
  for(Vertex_index v : mesh.vertices()) same = same && dir[v] == first[i++];
  report.check(same, "edit: the same bits as a fresh object");
  // the class still computes the smoothest field afterwards, and again a prescribed one
  std::vector<std::pair<Face_index, int> > smoothest;
  const SMDF::Direction_field_result r =
    field.compute(dir, params::degree(4).singularities_output_iterator(std::back_inserter(smoothest)));
  report.check(!r.prescribed && r.index_sum == 8, "edit: the smoothest field after a prescription");
  found.clear();
  field.compute(dir, params::degree(4).prescribed_singularities(smoothest)
                       .singularities_output_iterator(std::back_inserter(found)));
  report.check(found == smoothest, "the smoothest field's singularities, prescribed, come back exactly");
}

// One constrained vertex fixes the rotation; a second one that disagrees is refused.
static void check_rotation(Test_report& report)
{
  const Mesh mesh = sphere(3);
  const Prescription eight = at_points(mesh, cube_corners(), 1);
  auto dir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(mesh, "v:direction").value();
  std::map<Vertex_index, bool> constrained;
  std::map<Vertex_index, Vector_3> wanted;
  // the message of the error the prescribed field with these constraints throws ("" if none)
  auto constrained_refusal = [&]() -> std::string {
    try
    {
      SMDF::compute_globally_optimal_directions(
        mesh, dir, params::degree(4).prescribed_singularities(eight)
                     .vertex_is_constrained_map(boost::make_assoc_property_map(constrained))
                     .vertex_constrained_direction_map(boost::make_assoc_property_map(wanted)));
    }
    catch(const SMDF::Invalid_input_error& e)
    {
      return e.what();
    }
    return "";
  };
  const Vertex_index v0(0);
  const Vector_3 normal = mesh.point(v0) - CGAL::ORIGIN;
  const Vector_3 tangent = CGAL::cross_product(normal, Vector_3(0.3, 0.2, 1.));
  const Vector_3 unit = tangent / std::sqrt(tangent.squared_length());
  constrained[v0] = true;
  wanted[v0] = unit;
  SMDF::compute_globally_optimal_directions(
    mesh, dir, params::degree(4).prescribed_singularities(eight)
                 .vertex_is_constrained_map(boost::make_assoc_property_map(constrained))
                 .vertex_constrained_direction_map(boost::make_assoc_property_map(wanted)));
  // its neighbours, in a smooth field, show nearly one of the four rotations of its direction
  auto rotation_gap = [&](const Vector_3& a, const Vector_3& b) {
    return std::abs(std::sin(2. * std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b)));
  };
  double worst = 0.;
  for(Vertex_index w : CGAL::vertices_around_target(mesh.halfedge(v0), mesh)) worst = (std::max)(worst, rotation_gap(unit, dir[w]));
  report.check(worst < 0.3, "a constrained vertex fixes the rotation near it (" + std::to_string(worst) + ")");
  // another vertex's output direction, constrained too, agrees with the field: accepted
  const Vertex_index far(100);
  const Vector_3 far_direction = dir[far];
  constrained[far] = true;
  wanted[far] = far_direction;
  report.check(constrained_refusal().empty(), "a second constrained vertex that agrees with the field is accepted");
  // turning the first constraint turns the field far from it
  constrained.erase(far);
  wanted[v0] = std::cos(0.4) * unit + std::sin(0.4) * CGAL::cross_product(normal / std::sqrt(normal.squared_length()), unit);
  SMDF::compute_globally_optimal_directions(
    mesh, dir, params::degree(4).prescribed_singularities(eight)
                 .vertex_is_constrained_map(boost::make_assoc_property_map(constrained))
                 .vertex_constrained_direction_map(boost::make_assoc_property_map(wanted)));
  report.check(rotation_gap(far_direction, dir[far]) > 0.1, "turning the constraint turns the whole field");
  wanted[v0] = unit;

  const Vertex_index v1(5);
  constrained[v1] = true;
  const Vector_3 n1 = mesh.point(v1) - CGAL::ORIGIN;
  const Vector_3 t1 = CGAL::cross_product(n1, Vector_3(1., -0.7, 0.1));
  wanted[v1] = t1 / std::sqrt(t1.squared_length());
report.check(constrained_refusal().find("constrained vertex") != std::string::npos,
               "two disagreeing constrained vertices are refused");
}

// The package's flat arrays of `mesh`.
static SMDF::internal::Indexed_mesh indexed(const Mesh& mesh)
{
  namespace I = SMDF::internal;
  return I::make_indexed_mesh(
    mesh, [&](Vertex_index v) { return I::Vec3{mesh.point(v).x(), mesh.point(v).y(), mesh.point(v).z()}; },
    get(CGAL::vertex_index, mesh), get(CGAL::face_index, mesh));
}

// The internals on a mesh: counts of the cycle basis, the equations, and the
// optimality of the change (d0^T W^-1 x = 0 at every vertex but the roots).
static void check_change(Test_report& report, const std::string& name, const Mesh& mesh, int n,
                         const Prescription& p, std::size_t handles, std::size_t boundaries)
{
  namespace I = SMDF::internal;
  const I::Indexed_mesh m = indexed(mesh);
  const I::Tangent_spaces ts = I::compute_tangent_spaces(m, 1e-6);
  const I::Components comps = I::split_into_components(m);
  const I::Connection con = I::compute_connection(m, ts, n);
  I::Connection_adjustment adjustment(m, comps);
  adjustment.factor(m, ts);
  const I::Cycle_basis& basis = adjustment.cycle_basis();
  std::size_t free_loops = 0;
  for(unsigned char f : basis.is_free) free_loops += f;
  report.check(basis.handle_loops.size() == handles && basis.boundary_loops.size() == boundaries &&
                 free_loops == (boundaries > 0 ? 1u : 0u),
               name + ": " + std::to_string(basis.handle_loops.size()) + " handle and " +
                 std::to_string(basis.boundary_loops.size()) + " boundary loops");
  std::vector<int> k(m.number_of_faces(), 0);
  for(const auto& fk : p) k[std::size_t(fk.first)] = fk.second;
  const Eigen::VectorXd rho = adjustment.transport_angles(con);
  const Eigen::VectorXd x = adjustment.solve(m, con, rho, k, {}, false), below = adjustment.solve(m, con, rho, k);
  report.check(adjustment.holonomy_error(con, rho, x, k) < 1e-10 && adjustment.holonomy_error(con, rho, below, k) < 1e-10,
               name + ": every equation met");
  const I::Edge_numbering& edges = adjustment.edges();
  const Eigen::VectorXd w = I::dual_edge_weights(m, ts, edges);
  std::vector<double> divergence(m.number_of_vertices(), 0.), scale(m.number_of_vertices(), 0.);
  for(std::size_t e = 0; e < edges.number_of_edges(); ++e)
  {
    const std::size_t ci = edges.corner_of_edge[e];
    const std::size_t tail = m.vertex_of_corner(ci), head = m.vertex_of_corner(I::Indexed_mesh::next_corner(ci));
    const double flow = x[Eigen::Index(e)] / w[Eigen::Index(e)];
    divergence[tail] += flow;
    divergence[head] -= flow;
    scale[tail] += std::abs(flow);
    scale[head] += std::abs(flow);
  }
  double worst = 0.;
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
    if(basis.parent[v] != I::no_index) worst = (std::max)(worst, std::abs(divergence[v]) / (scale[v] + 1e-300));
  report.check(worst < 1e-9, name + ": the least change (relative divergence " + std::to_string(worst) + ")");
  report.check(below.cwiseAbs().maxCoeff() < CGAL_PI, name + ": below a half turn on every edge");
  if(x.cwiseAbs().maxCoeff() < 0.97 * CGAL_PI) report.check(below == x, name + ": the least change kept where it is below");
}

static void check_internals(Test_report& report)
{
  const Mesh s = sphere(3);
  check_change(report, "sphere", s, 4, at_points(s, cube_corners(), 1), 0, 0);
  Mesh torus;
  make_torus(torus, 1., 0.4, 40, 16);
  check_change(report, "torus", torus, 4, {}, 2, 0);
  const Mesh g2 = genus_two(6, 0);
  check_change(report, "genus 2", g2, 4,
               at_points(g2, {Point_3(0.5, 0, 0.5), Point_3(1.5, 0, 0.5), Point_3(2.5, 0, 0.5), Point_3(3.5, 0, 0.5),
                              Point_3(0.5, 1, 2.5), Point_3(1.5, 1, 2.5), Point_3(2.5, 1, 2.5), Point_3(3.5, 1, 2.5)},
                         -1),
               4, 0);
  Mesh cylinder;
  make_cylinder(cylinder, 1., 2., 32, 12);
  check_change(report, "open cylinder", cylinder, 4, at_points(cylinder, {Point_3(1, 0, 1)}, 1), 0, 2);
  Mesh disk;
  make_disk(disk, 12);
  check_change(report, "disk", disk, 1, at_points(disk, {Point_3(0.3, 0.1, 0)}, 1), 0, 1);
}

// Scaling the mesh by powers of ten gives the same directions. The sphere is
// made lumpy: on the icosphere's symmetry some directions lie exactly on the
// edge of the output's first sector, where rounding picks either of two
// representatives.
static void check_scale_invariance(Test_report& report)
{
  Mesh mesh = sphere(3);
  for(Vertex_index v : mesh.vertices())
  {
    const Vector_3 p = mesh.point(v) - CGAL::ORIGIN;
    mesh.point(v) = CGAL::ORIGIN + (1. + 0.05 * std::sin(3. * p.x() + 2. * p.y() + p.z())) * p;
  }
  const Prescription p = at_points(mesh, cube_corners(), 1);
  auto dir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(mesh, "v:direction").value();
  SMDF::compute_globally_optimal_directions(mesh, dir, params::degree(4).prescribed_singularities(p));
  std::vector<Vector_3> unscaled(dir.begin(), dir.end());
  for(double factor : {1e-3, 1e-1, 1e2, 1e3})
  {
    Mesh scaled = mesh;
    for(Vertex_index v : scaled.vertices()) scaled.point(v) = CGAL::ORIGIN + factor * (mesh.point(v) - CGAL::ORIGIN);
    auto sdir = SMDF::internal::find_property_map<Vertex_index, Vector_3>(scaled, "v:direction").value();
    SMDF::compute_globally_optimal_directions(scaled, sdir, params::degree(4).prescribed_singularities(p));
    double worst = 0.;
    std::size_t i = 0;
    for(Vertex_index v : scaled.vertices()) worst = (std::max)(worst, std::sqrt((sdir[v] - unscaled[i++]).squared_length()));
    report.check(worst < 1e-6, "scaled by " + std::to_string(factor) + ": the same directions (" + std::to_string(worst) + ")");
  }
}

#include "test_prescribed_singularities_loops.h"

int main()
{
  Test_report report("test_prescribed_singularities");
  check_spheres(report);
  check_other_topologies(report);
  check_errors(report);
  check_editing(report);
  check_rotation(report);
  check_internals(report);
  check_scale_invariance(report);
  check_loop_turns(report);
  check_round_trips(report);
  return report.finish();
}
