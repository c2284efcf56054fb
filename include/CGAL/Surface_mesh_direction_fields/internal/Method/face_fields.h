// Copyright (c) 2026  The Surface_mesh_direction_fields authors.
// All rights reserved.
//
// This file is part of CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s)     : The Surface_mesh_direction_fields authors

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FACE_FIELDS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FACE_FIELDS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/assembly.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/guidance.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <utility>
#include <vector>

// The method on the dual mesh (user manual, section "Fields on Faces"): one
// coefficient u_f per face, written in the face's frame (its first side,
// faces[f][0] -> faces[f][1], at angle 0), the energy on the dual edges with
// the transport across each edge, the face areas as the mass. Everything is
// computed from the (mollified) edge lengths, as for vertex fields.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The angle of side c (faces[f][c] -> faces[f][c+1]) in face f's frame:
// walking counter-clockwise around the triangle turns by pi minus the corner
// angle at each vertex.
inline double side_angle(const Tangent_spaces& ts, std::size_t f, int c)
{
  const double* alpha = &ts.corner_angle[3 * f];
  if(c == 0) return 0.;
  return c == 1 ? CGAL_PI - alpha[1] : CGAL_PI + alpha[0];
}

// Per corner 3f+c whose side is interior: the transport rho (an angle of
// directions, not of n-th powers) across that side from f to the twin's face
// g, and the weight of the dual edge. A vector at angle beta from the side in
// f is the vector at angle beta from the same side in g, so
// rho = (angle of the side in g, reversed) - (its angle in f).
struct Dual_connection
{
  std::vector<double> transport;  // 0 on the border
  std::vector<double> weight;     // 0 on the border
  // Sides of faces that share a non-manifold edge (user manual, "Fields on
  // Faces"): each pair once (corner < other), and a flag per corner.
  struct Glued_pair
  {
    std::size_t corner, other;
    double transport, weight;
  };
  std::vector<Glued_pair> glued;
  std::vector<unsigned char> is_glued;
  std::size_t number_of_glued_edges = 0;  // the non-manifold edges (groups of sides)
};

// The weight |e| / |e*| of the dual edge: the side's length over the distance
// between the barycentres of its two faces laid out flat across it (the
// diagonal Hodge star of the barycentric dual). It is positive for every pair
// of faces with area, unlike the circumcentric dual's cotangent weights.
// `other_at_a`: the corner of g at the side's first vertex a (for a twin,
// (d + 1) % 3; for a glued side that runs the same way as the corner's, d).
inline double dual_edge_weight(const Tangent_spaces& ts, const std::vector<Face_geometry>& geometry,
                               std::size_t corner, std::size_t twin, int other_at_a)
{
  const std::size_t f = corner / 3, g = twin / 3;
  const int c = static_cast<int>(corner % 3);
  const Face_geometry& gf = geometry[f];
  const Face_geometry& gg = geometry[g];
  const double length = std::sqrt(gf.squared_length[c]);
  // with the side a -> b of f along the x axis and its midpoint at 0, f's third vertex is at (x_f, h_f)
  // and g's at (x_g, -h_g); x_g from g's corner at a, whose sides are a -> c_g and a -> b
  const double x_f = gf.corner_dot[c] / length - 0.5 * length;
  const double x_g = gg.corner_dot[other_at_a] / length - 0.5 * length;
  const double h_f = 2. * ts.face_area[f] / length, h_g = 2. * ts.face_area[g] / length;
  const double dual_length = std::sqrt((x_f - x_g) * (x_f - x_g) + (h_f + h_g) * (h_f + h_g)) / 3.;
  return length / dual_length;
}

// The sides around each non-manifold edge: all sides grouped by the points
// of their two ends (`point_of_vertex`: vertices that are copies of one
// point share it), the groups of three sides or more.
inline std::vector<std::vector<std::size_t> > non_manifold_side_groups(const Indexed_mesh& m,
                                                                       const std::vector<std::size_t>& point_of_vertex)
{
  // three sides or more between two points: one of the points has several vertices (a halfedge mesh has
  // two faces at most on an edge), so the sides with no end at such a point are not sorted
  std::vector<std::pair<std::size_t, std::size_t> > by_point(point_of_vertex.size());
  for(std::size_t v = 0; v < by_point.size(); ++v) by_point[v] = {point_of_vertex[v], v};
  std::sort(by_point.begin(), by_point.end());
  std::vector<unsigned char> shared(point_of_vertex.size(), 0);
  for(std::size_t i = 1; i < by_point.size(); ++i)
    if(by_point[i].first == by_point[i - 1].first) shared[by_point[i].second] = shared[by_point[i - 1].second] = 1;
  std::vector<std::pair<std::pair<std::size_t, std::size_t>, std::size_t> > keyed;
  for(std::size_t corner = 0; corner < 3 * m.number_of_faces(); ++corner)
  {
    const std::size_t u = m.vertex_of_corner(corner), w = m.vertex_of_corner(Indexed_mesh::next_corner(corner));
    if(!shared[u] && !shared[w]) continue;
    const std::size_t a = point_of_vertex[u], b = point_of_vertex[w];
    keyed.push_back({{(std::min)(a, b), (std::max)(a, b)}, corner});
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::vector<std::size_t> > groups;
  for(std::size_t i = 0, j = 0; i < keyed.size(); i = j)
  {
    for(j = i + 1; j < keyed.size() && keyed[j].first == keyed[i].first; ++j) {}
    if(j - i < 3) continue;
    groups.emplace_back();
    for(std::size_t k = i; k < j; ++k) groups.back().push_back(keyed[k].second);
  }
  return groups;
}

// The faces around a non-manifold edge are coupled pairwise, each pair as
// twins are: a direction at angle beta from the edge's direction (from its
// first point to its second) in one face is at angle beta from it in the
// other, each angle measured in its own face's frame (the face turned about
// the edge until the normals agree). So that each face is held across the
// edge as across a manifold one, every pair of the k faces there, twins
// included, has the dual edge weight over k - 1.
inline void glue_non_manifold_sides(const Indexed_mesh& m, const Tangent_spaces& ts,
                                    const std::vector<Face_geometry>& geometry,
                                    const std::vector<std::size_t>& point_of_vertex, Dual_connection& dc)
{
  dc.is_glued.assign(3 * m.number_of_faces(), 0);
  for(const std::vector<std::size_t>& group : non_manifold_side_groups(m, point_of_vertex))
  {
    ++dc.number_of_glued_edges;
    const double share = 1. / static_cast<double>(group.size() - 1);
    for(std::size_t i = 0; i < group.size(); ++i)
      for(std::size_t j = i + 1; j < group.size(); ++j)
      {
        const std::size_t corner = (std::min)(group[i], group[j]), other = (std::max)(group[i], group[j]);
        if(corner / 3 == other / 3) continue;  // a face folded onto itself has no transport to itself
        if(m.twin_corner[corner] == other)
        {
          dc.weight[corner] *= share;
          dc.weight[other] *= share;
          continue;
        }
        const std::size_t a = point_of_vertex[m.vertex_of_corner(corner)];
        const bool same_way = point_of_vertex[m.vertex_of_corner(other)] == a;
        const double in_f = side_angle(ts, corner / 3, static_cast<int>(corner % 3));
        const double in_g = side_angle(ts, other / 3, static_cast<int>(other % 3)) + (same_way ? 0. : CGAL_PI);
        const int other_at_a = static_cast<int>(same_way ? other % 3 : (other + 1) % 3);
        dc.glued.push_back({corner, other, reduce_angle(in_g - in_f),
                            share * dual_edge_weight(ts, geometry, corner, other, other_at_a)});
        dc.is_glued[corner] = dc.is_glued[other] = 1;
      }
  }
}

// Whether some vertex copies another's point: `point_of_vertex` neither
// empty nor the identity (what a front end passes for a manifold mesh).
inline bool copies_points(const Indexed_mesh& m, const std::vector<std::size_t>& point_of_vertex)
{
  if(point_of_vertex.empty()) return false;
  if(point_of_vertex.size() != m.number_of_vertices())
    throw Invalid_input_error("vertex_point_index_map must give a value for every vertex");
  for(std::size_t v = 0; v < point_of_vertex.size(); ++v)
    if(point_of_vertex[v] != v) return true;
  return false;
}

// `point_of_vertex`: see copies_points().
inline Dual_connection dual_connection(const Indexed_mesh& m, const Tangent_spaces& ts,
                                       const std::vector<std::size_t>& point_of_vertex = {})
{
  Dual_connection dc;
  dc.transport.assign(3 * m.number_of_faces(), 0.);
  dc.weight.assign(3 * m.number_of_faces(), 0.);
  // each face's geometry once (each is read by its three sides)
  std::vector<Face_geometry> geometry(m.number_of_faces());
  parallel_for_each_index(m.number_of_faces(),
                          [&](std::size_t f) { geometry[f] = face_geometry(m, f, ts.mollification); });
  parallel_for_each_index(3 * m.number_of_faces(), [&](std::size_t corner) {
    const std::size_t twin = m.twin_corner[corner];
    if(twin == no_index) return;
    const double in_f = side_angle(ts, corner / 3, static_cast<int>(corner % 3));
    const double in_g = side_angle(ts, twin / 3, static_cast<int>(twin % 3)) + CGAL_PI;
    dc.transport[corner] = reduce_angle(in_g - in_f);
    dc.weight[corner] = dual_edge_weight(ts, geometry, corner, twin, static_cast<int>((twin + 1) % 3));
  });
  if(copies_points(m, point_of_vertex)) glue_non_manifold_sides(m, ts, geometry, point_of_vertex, dc);
  else dc.is_glued.assign(3 * m.number_of_faces(), 0);
  return dc;
}

// The faces of a component numbered 0..|F_c|-1 (their order in comp.faces).
inline std::vector<std::size_t> local_face_numbers(const Component& comp, std::size_t number_of_faces)
{
  std::vector<std::size_t> local(number_of_faces, no_index);
  for(std::size_t i = 0; i < comp.faces.size(); ++i) local[comp.faces[i]] = i;
  return local;
}

// A and M of one component for degree n: E(u) = sum over dual edges of
// w |u_g - r_fg u_f|^2 with r_fg = exp(i n rho_fg), M = diag(|f|). Each
// interior side is visited from both faces; the visit from f adds w to A_ff
// and -w r_fg to A_gf, so both triangles of the Hermitian A are written. M
// stores explicit zeros where A has entries: with one pattern the eigen-solve
// estimates its shift and start vector on coarse levels (coarse_hierarchy.h)
// and forms A - sigma M entry by entry.
inline Energy_and_mass face_energy_and_mass(const Indexed_mesh& m, const Tangent_spaces& ts, const Dual_connection& dc,
                                            const Component& comp, int n, const std::vector<std::size_t>& local)
{
  const Eigen::Index nf = static_cast<Eigen::Index>(comp.faces.size());
  std::vector<Eigen::Triplet<Complex> > energy, mass;
  energy.reserve(7 * comp.faces.size());
  mass.reserve(4 * comp.faces.size());
  for(std::size_t i = 0; i < comp.faces.size(); ++i)
  {
    const std::size_t f = comp.faces[i];
    const Eigen::Index row = static_cast<Eigen::Index>(i);
    mass.emplace_back(row, row, Complex(ts.face_area[f], 0.));
    energy.emplace_back(row, row, Complex(0., 0.));  // a diagonal entry even on an isolated face
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t corner = 3 * f + static_cast<std::size_t>(c), twin = m.twin_corner[corner];
      if(twin == no_index) continue;
      const double w = dc.weight[corner];
      const Eigen::Index j = static_cast<Eigen::Index>(local[twin / 3]);
      energy.emplace_back(row, row, Complex(w, 0.));
      energy.emplace_back(j, row, -w * std::polar(1., static_cast<double>(n) * dc.transport[corner]));
      mass.emplace_back(j, row, Complex(0., 0.));
    }
  }
  for(const Dual_connection::Glued_pair& glued : dc.glued)
  {
    if(local[glued.corner / 3] == no_index) continue;  // another component's
    const Eigen::Index i = static_cast<Eigen::Index>(local[glued.corner / 3]);
    const Eigen::Index j = static_cast<Eigen::Index>(local[glued.other / 3]);
    const Complex r = std::polar(1., static_cast<double>(n) * glued.transport);
    energy.emplace_back(i, i, Complex(glued.weight, 0.));
    energy.emplace_back(j, j, Complex(glued.weight, 0.));
    energy.emplace_back(j, i, -glued.weight * r);
    energy.emplace_back(i, j, -glued.weight * std::conj(r));
    mass.emplace_back(j, i, Complex(0., 0.));
    mass.emplace_back(i, j, Complex(0., 0.));
  }
  Energy_and_mass em;
  em.energy.resize(nf, nf);
  em.mass.resize(nf, nf);
  em.energy.setFromTriplets(energy.begin(), energy.end());
  em.mass.setFromTriplets(mass.begin(), mass.end());
  return em;
}

// The principal-curvature line field per face (n = 2 coefficient): the
// traceless part of the face's shape operator from the dihedral angles of its
// three sides, each side's bending shared by its two faces:
// q_f = -1/(8 |f|) sum over the sides e of f of exp(2 i angle_f(e)) beta_e |e|,
// pointing along the maximum curvature direction (a convex edge bends across it).
inline std::vector<Complex> face_curvature_line_field(const Indexed_mesh& m, const Tangent_spaces& ts)
{
  std::vector<Complex> q(m.number_of_faces(), Complex(0., 0.));
  parallel_for_each_index(m.number_of_faces(), [&](std::size_t f) {
    const Face_geometry g = face_geometry(m, f, ts.mollification);
    Complex sum(0., 0.);
    for(int c = 0; c < 3; ++c)
    {
      const double beta = dihedral_angle(m, 3 * f + static_cast<std::size_t>(c));
      sum += -0.125 * beta * std::sqrt(g.squared_length[c]) * std::polar(1., 2. * side_angle(ts, f, c));
    }
    q[f] = sum / ts.face_area[f];
  });
  return q;
}

// The 3D frame of face f: its first side's unit direction and the unit
// normal (zero for a face without embedded area).
inline std::array<Vec3, 2> face_frame(const Indexed_mesh& m, std::size_t f)
{
  const auto& t = m.faces[f];
  return {normalized(m.points[t[1]] - m.points[t[0]]), triangle_unit_normal(m.points, t)};
}

// The angle in face f's frame of a 3D vector w (projected onto the face).
inline double angle_in_face(const Indexed_mesh& m, std::size_t f, const Vec3& w)
{
  const std::array<Vec3, 2> frame = face_frame(m, f);
  return std::atan2(dot(w, cross(frame[1], frame[0])), dot(w, frame[0]));
}

// The unit 3D direction at angle `angle` in face f's frame.
inline Vec3 direction_in_face(const Indexed_mesh& m, std::size_t f, double angle)
{
  const std::array<Vec3, 2> frame = face_frame(m, f);
  return normalized(rotated(frame[0], frame[1], angle));
}

// Where the field turns at the vertices (user manual, section "Fields on
// Faces"): omega across each dual edge, the index k_v of every interior
// vertex, the principal matching of every interior side, and per component
// the boundary's contribution B (sum over interior vertices of k_v plus B is
// n chi).
struct Face_field_turning
{
  std::vector<int> vertex_index;       // k_v; 0 on boundary and isolated vertices
  std::vector<int> matching;           // per corner 3f+c: the period jump from f to the twin's face; 0 on the border
  std::vector<long long> boundary_index;  // per component
};

// omega_fg in (-pi, pi]: the rotation from r_fg u_f to u_g (zero coefficients
// taken at angle 0), from the angle theta of each coefficient.
inline double face_rotation(const std::vector<double>& theta, const Dual_connection& dc, int n, std::size_t corner,
                            std::size_t twin)
{
  return reduce_angle(theta[twin / 3] - theta[corner / 3] - static_cast<double>(n) * dc.transport[corner]);
}

// The turn of the fan of v: the field's rotations across the interior sides
// between consecutive corners (rotation(side), across the side from its face
// to its twin's) plus n times the angle defect (2 pi - sum of the corner
// angles inside, pi - that sum on the boundary).
template <typename Rotation>
double fan_turn(const Indexed_mesh& m, const Tangent_spaces& ts, int n, std::size_t v, const Rotation& rotation)
{
  double turn = (m.is_border_vertex[v] ? CGAL_PI : 2. * CGAL_PI);
  double rotated = 0.;
  for(std::size_t corner : m.fan(v))
  {
    turn -= ts.corner_angle[corner];
    // the corner's second side, reversed, is the side of the previous corner of f
    const std::size_t side = Indexed_mesh::previous_corner(corner);
    if(m.twin_corner[side] != no_index) rotated += rotation(side);
  }
  return rotated + static_cast<double>(n) * turn;
}

// The indices and the matching of the field with n-th power angles theta
// whose rotation across each interior side is rotation(side): the period
// jump across a side is the whole turns of 2 pi that theta_g - theta_f -
// n rho holds beyond that rotation.
template <typename Rotation>
Face_field_turning turning_of_field(const Indexed_mesh& m, const Tangent_spaces& ts, const Dual_connection& dc,
                                    const Components& comps, const std::vector<double>& theta, int n,
                                    const Rotation& rotation)
{
  Face_field_turning turning;
  turning.vertex_index.assign(m.number_of_vertices(), 0);
  turning.boundary_index.assign(comps.list.size(), 0);
  // the fans' turns in parallel; the boundary's sums after, in vertex order (the same digits on any thread count)
  std::vector<double> turn(m.number_of_vertices(), 0.);
  parallel_for_each_index(turn.size(), [&](std::size_t v) {
    if(m.fan_size(v) == 0) return;
    turn[v] = fan_turn(m, ts, n, v, rotation) / (2. * CGAL_PI);
    if(!m.is_border_vertex[v]) turning.vertex_index[v] = static_cast<int>(std::lround(turn[v]));
  });
  std::vector<double> boundary_turn(comps.list.size(), 0.);
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v)
    if(m.fan_size(v) != 0 && m.is_border_vertex[v])
      boundary_turn[comps.component_of_face[m.fan_corners[m.fan_offsets[v]] / 3]] += turn[v];
  for(std::size_t c = 0; c < comps.list.size(); ++c) turning.boundary_index[c] = std::llround(boundary_turn[c]);
  turning.matching.assign(3 * m.number_of_faces(), 0);
  parallel_for_each_index(3 * m.number_of_faces(), [&](std::size_t corner) {
    const std::size_t twin = m.twin_corner[corner];
    if(twin == no_index) return;
    const double jump = theta[twin / 3] - theta[corner / 3] - static_cast<double>(n) * dc.transport[corner] -
                        rotation(corner);
    turning.matching[corner] = static_cast<int>(std::lround(jump / (2. * CGAL_PI)));
  });
  return turning;
}

// The turning of a field u read with the principal matching: the rotation
// across each side is taken in (-pi, pi].
inline Face_field_turning face_field_turning(const Indexed_mesh& m, const Tangent_spaces& ts,
                                             const Dual_connection& dc, const Components& comps,
                                             const std::vector<Complex>& u, int n)
{
  std::vector<double> theta(u.size());
  for(std::size_t f = 0; f < u.size(); ++f) theta[f] = std::arg(u[f]);
  return turning_of_field(m, ts, dc, comps, theta, n, [&](std::size_t side) {
    return face_rotation(theta, dc, n, side, m.twin_corner[side]);
  });
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FACE_FIELDS_H
