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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FOLDED_FANS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FOLDED_FANS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/quadric_fit.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <cstddef>
#include <map>
#include <queue>
#include <utility>
#include <vector>

// Tangent spaces at folded triangles (user manual, section "Folded
// Triangles"). A triangle folded over (its normal points against the
// surface's normal at one of its vertices) turns the wrong way around that
// vertex: the intrinsic layout counts its corner angle positively, so the
// fan's angle sum exceeds 2 pi by twice that angle, the rescaling squeezes
// every other corner, and the transport across the fold turns a direction
// that is smooth on the surface by up to twice the corner angle. Fields then
// need singularities at folds that the surface does not have. At the vertices
// of such triangles the fan is laid out in the tangent plane of the fitted
// surface instead: the angle of a side is the angle of its projection, a
// folded corner's width is negative, and directions are rotations about the
// normal. Everywhere else the layout stays the rescaled intrinsic one.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The orthonormal frame of v's tangent plane in the projected layout: x the
// projection of the first side of v's fan (rescaled angle 0), y = normal x x.
struct Projected_frame
{
  Vec3 x, y;
};

// The side of a corner: its first (i -> j) or second (i -> k) side.
inline Vec3 corner_side(const Indexed_mesh& m, std::size_t corner, int which)
{
  const auto& t = m.faces[corner / 3];
  const int c = static_cast<int>(corner % 3);
  return m.points[t[(c + which) % 3]] - m.points[t[c]];
}

// false where a side of v's fan is (nearly) parallel to the normal: its
// projection has no angle.
inline bool projected_frame(const Indexed_mesh& m, std::size_t v, const Vec3& normal, Projected_frame& frame)
{
  if(m.fan_size(v) == 0 || !(std::abs(norm(normal) - 1.) < 1e-6)) return false;
  const Vec3 side = corner_side(m, m.fan_corners[m.fan_offsets[v]], 1);
  const Vec3 x = side - dot(side, normal) * normal;
  if(!(norm(x) > 1e-8 * norm(side))) return false;
  frame.x = normalized(x);
  frame.y = cross(normal, frame.x);
  return true;
}

// The angle of the projection of `side` in the frame, in (-pi, pi]; none
// where the side is (nearly) parallel to the normal.
inline std::optional<double> projected_angle(const Projected_frame& frame, const Vec3& side)
{
  const double x = dot(side, frame.x), y = dot(side, frame.y);
  if(!(std::sqrt(x * x + y * y) > 1e-8 * norm(side))) return std::nullopt;
  return std::atan2(y, x);
}

inline Vec3 face_area_normal(const Indexed_mesh& m, std::size_t f)
{
  const auto& t = m.faces[f];
  return cross(m.points[t[1]] - m.points[t[0]], m.points[t[2]] - m.points[t[0]]);
}

// Whether a face of v's fan turns more than 60 degrees away from the unit
// `normal`: where it does, `normal` may be the wrong plane to tell folds by
// (an angle-weighted normal is pulled over by a folded triangle with a wide
// corner), and the fitted surface's normal decides.
inline bool fan_disagrees_with(const Indexed_mesh& m, std::size_t v, const Vec3& normal)
{
  for(std::size_t corner : m.fan(v))
  {
    const Vec3 n = face_area_normal(m, corner / 3);
    const double d = dot(n, normal);
    if(d < 0. || 4. * d * d < squared_norm(n)) return true;  // cos < 1/2
  }
  return false;
}

// An interior fan whose corners add up to more than 3 pi. Angle sums on a
// smooth surface are near 2 pi: this fan wraps around its vertex twice, as a
// vertex between folds can without a folded triangle of its own.
inline bool over_wound(const Indexed_mesh& m, const Tangent_spaces& ts, std::size_t v)
{
  if(m.is_border_vertex[v]) return false;
  double sum = 0.;
  for(std::size_t corner : m.fan(v)) sum += ts.corner_angle[corner];
  return sum > 3. * CGAL_PI;
}

// The largest relative residual (quadric_fit.h) at which the fitted surface
// is trusted to tell a fold from a feature.
constexpr double trusted_fit_residual = 0.05;

// Sets surface[v] to the normal of the fitted surface (quadric_fit.h) at every
// vertex v of `which` where the fit is trusted.
inline void set_trusted_fitted_normals(const Indexed_mesh& m, const std::vector<std::size_t>& which,
                                       std::vector<Vec3>& surface)
{
  parallel_for_each_range(which.size(), [&](std::size_t begin, std::size_t end) {
    Fit_workspace work;
    Vertex_fit fit;
    for(std::size_t k = begin; k < end; ++k)
      if(fit_quadric_at(m, which[k], work, fit) && relative_fit_residual(fit, work.points) <= trusted_fit_residual)
        surface[which[k]] = fitted_normal(fit);
  });
}

// The vertices flagged by `flag(v)`, in increasing order.
template <typename Flag>
std::vector<std::size_t> vertices_where(std::size_t count, const Flag& flag)
{
  std::vector<unsigned char> flagged(count, 0);
  parallel_for_each_index(count, [&](std::size_t v) { flagged[v] = flag(v); });
  std::vector<std::size_t> list;
  for(std::size_t v = 0; v < count; ++v)
    if(flagged[v]) list.push_back(v);
  return list;
}

// The faces of the fans of `vertices` whose normal points against the known
// (nonzero) surface normal at one of their vertices, each once, in
// increasing order; with `all_known`, only those whose three surface normals
// are known.
inline std::vector<std::size_t> faces_against(const Indexed_mesh& m, const std::vector<std::size_t>& vertices,
                                              const std::vector<Vec3>& surface, bool all_known)
{
  std::vector<std::size_t> faces;
  for(std::size_t v : vertices)
    for(std::size_t corner : m.fan(v))
    {
      const std::size_t f = corner / 3;
      const Vec3 n = face_area_normal(m, f);
      bool known = true, against = false;
      for(int c = 0; c < 3; ++c)
      {
        const Vec3& normal = surface[m.faces[f][c]];
        known = known && norm(normal) > 0.;
        against = against || dot(n, normal) < 0.;
      }
      if(against && (known || !all_known)) faces.push_back(f);
    }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

// The surface normals that tell folds (zero where unknown), and the vertices
// where they are known. With the package's own (angle-weighted) normals: the
// fitted surface's normal where it is trusted, at the vertices whose fan has a
// face turned far from their normal or winds twice, and then at the other
// vertices of the faces folded against it. A user's normals where they point
// to the side of the faces around the vertex and its neighbours (normals
// given for the other orientation tell no fold).
inline std::vector<Vec3> surface_normals_for_folds(const Indexed_mesh& m, const Tangent_spaces& ts,
                                                   const std::vector<Vec3>& normals, bool own_normals,
                                                   std::vector<std::size_t>& known)
{
  const std::size_t nv = m.number_of_vertices();
  std::vector<Vec3> surface(nv, Vec3{0., 0., 0.});
  if(!own_normals)
  {
    known = vertices_where(nv, [&](std::size_t v) {
      return m.fan_size(v) > 0 && dot(normals[v], neighbourhood_normal(m, v)) > 0.;
    });
    for(std::size_t v : known) surface[v] = normals[v];
    return surface;
  }
  known = vertices_where(nv, [&](std::size_t v) { return fan_disagrees_with(m, v, normals[v]) || over_wound(m, ts, v); });
  set_trusted_fitted_normals(m, known, surface);
  std::vector<std::size_t> more;
  for(std::size_t f : faces_against(m, known, surface, false))
    for(int c = 0; c < 3; ++c)
      if(norm(surface[m.faces[f][c]]) == 0.) more.push_back(m.faces[f][c]);
  std::sort(more.begin(), more.end());
  more.erase(std::unique(more.begin(), more.end()), more.end());
  set_trusted_fitted_normals(m, more, surface);
  known.insert(known.end(), more.begin(), more.end());
  return surface;
}

// The projected layout of v's fan; false (and ts unchanged) where a side has
// no projected angle.
inline bool lay_out_projected_fan(const Indexed_mesh& m, std::size_t v, const Vec3& normal, Tangent_spaces& ts)
{
  Projected_frame frame;
  if(!projected_frame(m, v, normal, frame)) return false;
  for(std::size_t corner : m.fan(v))
    if(!projected_angle(frame, corner_side(m, corner, 1)) || !projected_angle(frame, corner_side(m, corner, 2)))
      return false;
  for(std::size_t corner : m.fan(v))
  {
    const double first = *projected_angle(frame, corner_side(m, corner, 1));
    ts.corner_theta[corner] = first;
    ts.corner_width[corner] = reduce_angle(*projected_angle(frame, corner_side(m, corner, 2)) - first);
  }
  ts.angle_scale[v] = 1.;
  ts.projected_fan[v] = 1;
  return true;
}

// The projected vertices joined through the faces they share: a cluster
// label per vertex (no_index where not projected), by union-find.
inline std::vector<std::size_t> projected_clusters(const Indexed_mesh& m, const Tangent_spaces& ts)
{
  std::vector<std::size_t> parent(m.number_of_vertices(), no_index);
  for(std::size_t v = 0; v < parent.size(); ++v)
    if(ts.projected_fan[v]) parent[v] = v;
  auto root = [&parent](std::size_t v) {
    while(parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
    for(int c = 0; c < 2; ++c)
    {
      const std::size_t a = m.faces[f][c], b = m.faces[f][c + 1], d = m.faces[f][(c + 2) % 3];
      for(std::size_t other : {b, d})
        if(ts.projected_fan[a] && ts.projected_fan[other]) parent[root(a)] = root(other);
    }
  for(std::size_t v = 0; v < parent.size(); ++v)
    if(parent[v] != no_index) parent[v] = root(v);
  return parent;
}

// The whole turns by which v's projected fan falls short of the intrinsic
// one: 2 pi for an interior fan, its angle sum for a boundary fan.
inline double missing_turns(const Indexed_mesh& m, const Tangent_spaces& ts, std::size_t v)
{
  double turn = 0., intrinsic = 0.;
  for(std::size_t corner : m.fan(v))
  {
    turn += ts.corner_width[corner];
    intrinsic += ts.corner_angle[corner];
  }
  const double expected = m.is_border_vertex[v] ? intrinsic : 2. * CGAL_PI;
  return std::round((expected - turn) / (2. * CGAL_PI));
}

// Adds |missing| turns of 2 pi (with the sign of `missing`) to the defects of
// the faces in [first, last), one at a time, each to the face whose defect it
// changes least (the smallest |defect + turn|, the smallest face on a tie). A
// heap keeps the choice O(log faces): a cluster can hold thousands of faces
// and miss thousands of turns (closed surfaces of high genus with sharp edges).
template <typename Iterator>
void give_turns(double missing, Iterator first, Iterator last, std::vector<double>& defect)
{
  const double turn = missing > 0. ? 2. * CGAL_PI : -2. * CGAL_PI;
  typedef std::pair<double, std::size_t> Keyed_face;
  std::priority_queue<Keyed_face, std::vector<Keyed_face>, std::greater<Keyed_face> > nearest;
  for(Iterator it = first; it != last; ++it) nearest.emplace(std::abs(defect[it->second] + turn), it->second);
  for(double left = std::abs(missing); left > 0.; left -= 1.)
  {
    const std::size_t f = nearest.top().second;
    nearest.pop();
    defect[f] += turn;
    nearest.emplace(std::abs(defect[f] + turn), f);
  }
}

// Gauss-Bonnet with projected fans. A projected interior fan turns by 2 pi w
// (w = 0 at a vertex pushed over the opposite side of its folded face), the
// intrinsic one by exactly 2 pi. The defect of a face with a projected vertex
// is taken in (-pi, pi], which adds whole turns to the sum of its corners
// (one to a folded face, whose corners add up to about -pi). Over each
// cluster of projected vertices the turns added to its faces must be the
// turns its fans miss, so that the defects still add up to 2 pi chi and index
// sums stay n chi. Where a cluster is short (a face nearly orthogonal to the
// tangent planes, whose projected corners are ambiguous), the missing turns
// go to the faces they change least, those whose defect is nearest -pi (or pi).
inline void balance_projected_turns(const Indexed_mesh& m, Tangent_spaces& ts)
{
  const double two_pi = 2. * CGAL_PI;
  const std::vector<std::size_t> cluster = projected_clusters(m, ts);
  std::map<std::size_t, double> balance;                       // per cluster root
  std::vector<std::pair<std::size_t, std::size_t> > faces_of;  // (cluster root, face)
  for(std::size_t v = 0; v < cluster.size(); ++v)
    if(cluster[v] != no_index) balance[cluster[v]] += missing_turns(m, ts, v);
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
  {
    const auto& t = m.faces[f];
    const std::size_t c = cluster[t[0]] != no_index ? cluster[t[0]] : cluster[t[1]] != no_index ? cluster[t[1]] : cluster[t[2]];
    if(c == no_index) continue;
    const double raw = face_angle_defect(ts, f);
    ts.face_angle_defect[f] = reduce_angle(raw);
    balance[c] -= std::round((ts.face_angle_defect[f] - raw) / two_pi);
    faces_of.emplace_back(c, f);
  }
  std::sort(faces_of.begin(), faces_of.end());
  for(auto [c, missing] : balance)
  {
    const auto first = std::lower_bound(faces_of.begin(), faces_of.end(), std::make_pair(c, std::size_t(0)));
    const auto last = std::lower_bound(faces_of.begin(), faces_of.end(), std::make_pair(c + 1, std::size_t(0)));
    if(missing != 0. && first != last) give_turns(missing, first, last, ts.face_angle_defect);
  }
}

// Lays out the fans of the vertices of folded faces in their tangent planes
// and updates the angle defects of their faces; returns how many fans were
// laid out so. `normals` are the unit vertex normals: where they are the
// package's own (`own_normals`, angle-weighted: vertex_normals.h), the fitted
// surface tells folds, and the vertices of folded faces get its normal as
// theirs (the plane their directions lie in); a user's normals are kept.
inline std::size_t lay_out_folded_fans(const Indexed_mesh& m, std::vector<Vec3>& normals, bool own_normals,
                                       Tangent_spaces& ts)
{
  std::vector<std::size_t> known;
  const std::vector<Vec3> surface = surface_normals_for_folds(m, ts, normals, own_normals, known);
  std::vector<std::size_t> candidates = known;  // the vertices of folded faces, and those winding twice
  std::vector<unsigned char> folded(m.number_of_vertices(), 0);
  for(std::size_t f : faces_against(m, known, surface, true))
    for(int c = 0; c < 3; ++c)
    {
      folded[m.faces[f][c]] = 1;
      candidates.push_back(m.faces[f][c]);
    }
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  std::size_t count = 0;
  for(std::size_t v : candidates)
  {
    const bool wound = !folded[v] && norm(surface[v]) > 0. && over_wound(m, ts, v);
    if(!(folded[v] || wound) || !lay_out_projected_fan(m, v, surface[v], ts)) continue;
    if(wound && missing_turns(m, ts, v) == 0.)
      lay_out_intrinsic_fan(m, v, ts);  // it does wind once around the normal
    else
    {
      normals[v] = surface[v];
      ++count;
    }
  }
  if(count > 0) balance_projected_turns(m, ts);
  return count;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FOLDED_FANS_H
