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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_STREAMLINES_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_STREAMLINES_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/IO/direction_field_files.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

Options of `trace_streamlines()`. Lengths are relative to the diagonal of the
mesh's bounding box.
*/
struct Streamline_options
{
  /// the distance between seeds: one seed per cell of a grid of this size, at a face barycentre
  double seed_spacing = 0.04;
  /// the largest length of each half of a streamline (from its seed)
  double maximum_length = 0.08;
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

One field line: a polyline on the surface, straight inside each face.
*/
struct Streamline
{
  /// why a half of the line ended
  enum class End
  {
    BOUNDARY,     ///< it reached a boundary edge (or a non-manifold edge)
    SINGULARITY,  ///< the next face is singular: it stops on that face's edge
    LENGTH,       ///< `maximum_length` was reached
    TURNED_BACK,  ///< the field of the next face points back across the edge (a sink or source line): it stops on that edge
    DEGENERATE    ///< no exit could be found in a face (a degenerate face)
  };
  /// the points; consecutive points lie on the same face, `faces[i]` holds the segment from `points[i]` to `points[i+1]`
  std::vector<std::array<double, 3> > points;
  /// the face of each segment
  std::vector<std::size_t> faces;
  /// how the line ends at its first point (`LENGTH` for a line traced forwards only: its seed)
  End start_end = End::LENGTH;
  /// how the line ends at its last point
  End finish_end = End::LENGTH;
};

namespace internal {

typedef std::array<double, 3> S3;

// Across each edge (f, c) -- the side from faces[f][c] to faces[f][c+1] -- the
// neighbouring face and its side index; (no face, 0) on a boundary or
// non-manifold edge.
inline std::vector<std::pair<std::size_t, int> > edge_neighbours(const IO::Direction_field_data& d)
{
  const std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::pair<std::size_t, int> > result(3 * d.faces.size(), std::make_pair(none, 0));
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::pair<std::size_t, int> > > sides;
  for(std::size_t f = 0; f < d.faces.size(); ++f)
    for(int c = 0; c < 3; ++c)
    {
      const std::size_t a = d.faces[f][static_cast<std::size_t>(c)], b = d.faces[f][static_cast<std::size_t>((c + 1) % 3)];
      sides[std::make_pair((std::min)(a, b), (std::max)(a, b))].emplace_back(f, c);
    }
  for(const auto& s : sides)
    if(s.second.size() == 2)
    {
      result[3 * s.second[0].first + static_cast<std::size_t>(s.second[0].second)] = s.second[1];
      result[3 * s.second[1].first + static_cast<std::size_t>(s.second[1].second)] = s.second[0];
    }
  return result;
}

} // namespace internal

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

traces field lines of the per-face field of `data` (`data.face_directions`,
see `IO::face_directions()`): seeds at face barycentres spread by a grid of
spacing `options.seed_spacing`; from each seed, for a field of even degree `n`,
one line along each of the `n/2` direction families, traced both ways; for
`n = 1` one line, both ways; for odd `n > 1`, `n` lines, forwards.

Inside a face a line is straight along the face's field direction. When it
crosses an edge, the direction is carried into the next face by unfolding
(the rotation about the shared edge taking one face's plane to the other's),
and the line continues along the direction of that face closest to it (the
`n`-fold matching). A line stops at a boundary (or non-manifold) edge, on the
edge of a singular face (it never enters one), on an edge where the next
face's field points back (the per-face field is discontinuous there: a sink or
source line), when it reaches
`options.maximum_length`, or in a degenerate face. Seeds in singular faces are
skipped.

\param data the field with its mesh (`make_direction_field_data()` fills everything needed)
\param options seed spacing and maximum length
\returns the streamlines
*/
inline std::vector<Streamline> trace_streamlines(const IO::Direction_field_data& data,
                                                 const Streamline_options& options = Streamline_options())
{
  using namespace IO::internal;
  typedef std::array<double, 3> V;
  const std::size_t nf = data.faces.size(), none = static_cast<std::size_t>(-1);
  std::vector<Streamline> lines;
  if(nf == 0 || data.points.empty()) return lines;
  if(data.face_directions.size() != nf)
    throw Invalid_input_error("trace_streamlines: the data has no per-face directions");
  if(!(options.seed_spacing > 0.) || !(options.maximum_length > 0.))
    throw Invalid_input_error("trace_streamlines: the seed spacing and the maximum length must be positive");

  V lo = data.points[0], hi = data.points[0];
  for(const V& p : data.points)
    for(int k = 0; k < 3; ++k) { lo[k] = (std::min)(lo[k], p[k]); hi[k] = (std::max)(hi[k], p[k]); }
  const double diagonal = std::sqrt(dot3(sub(hi, lo), sub(hi, lo)));
  if(!(diagonal > 0.)) return lines;
  const double spacing = options.seed_spacing * diagonal, max_length = options.maximum_length * diagonal;

  std::vector<unsigned char> singular(nf, 0);
  for(const auto& s : data.singularities) if(s.first < nf && s.second != 0) singular[s.first] = 1;
  const std::vector<std::pair<std::size_t, int> > neighbour = internal::edge_neighbours(data);
  std::vector<V> normal(nf);
  for(std::size_t f = 0; f < nf; ++f)
  {
    normal[f] = face_unit_normal(data.points, data.faces[f]);
  }
  const int n = data.degree;
  // the field direction of face f closest to w (w in the plane of f)
  auto closest_direction = [&](std::size_t f, const V& w) {
    const V& d = data.face_directions[f];
    V best = d;
    double best_dot = -2.;
    for(int k = 0; k < n; ++k)
    {
      const V dk = rotated(d, normal[f], 2. * CGAL_PI * k / n);
      if(dot3(dk, w) > best_dot) { best_dot = dot3(dk, w); best = dk; }
    }
    return best;
  };

  // One half line from point p in face f along w; appends to points/faces.
  auto trace = [&](std::size_t f, V p, V w, std::vector<V>& points, std::vector<std::size_t>& faces) {
    double length = 0.;
    int entry = -1;  // the side through which the line entered f
    const std::size_t max_steps = 4 * nf + 16;
    for(std::size_t step = 0; step < max_steps; ++step)
    {
      // exit of the ray p + t w through a side of f other than the entry one
      const auto& t = data.faces[f];
      double best_t = HUGE_VAL;
      int best_side = -1;
      for(int c = 0; c < 3; ++c)
      {
        if(c == entry) continue;
        const V a = data.points[t[static_cast<std::size_t>(c)]], b = data.points[t[static_cast<std::size_t>((c + 1) % 3)]];
        // p + s w = a + r (b - a), in the face plane: 2x2 system by cross products with the normal
        const V e = sub(b, a), ap = sub(a, p);
        const double denominator = dot3(cross3(w, e), normal[f]);
        if(std::abs(denominator) < 1e-300) continue;
        const double s = dot3(cross3(ap, e), normal[f]) / denominator;
        const double r = dot3(cross3(ap, w), normal[f]) / denominator;
        if(s > 1e-12 * diagonal && r >= -1e-9 && r <= 1. + 1e-9 && s < best_t) { best_t = s; best_side = c; }
      }
      if(best_side < 0) return Streamline::End::DEGENERATE;
      const bool too_long = length + best_t > max_length;
      const double step_length = too_long ? max_length - length : best_t;
      const V q{p[0] + step_length * w[0], p[1] + step_length * w[1], p[2] + step_length * w[2]};
      points.push_back(q);
      faces.push_back(f);
      length += step_length;
      if(too_long) return Streamline::End::LENGTH;
      const auto next = neighbour[3 * f + static_cast<std::size_t>(best_side)];
      if(next.first == none) return Streamline::End::BOUNDARY;
      if(singular[next.first]) return Streamline::End::SINGULARITY;
      // unfold w into the next face, then follow its closest field direction
      const V unfolded = rotate_onto(w, normal[f], normal[next.first]);
      w = closest_direction(next.first, unfolded);
      {
        // the entry side of the next face, and the direction into that face
        const auto& g = data.faces[next.first];
        const V a = data.points[g[static_cast<std::size_t>(next.second)]];
        const V b = data.points[g[static_cast<std::size_t>((next.second + 1) % 3)]];
        const V inward = cross3(normal[next.first], sub(b, a));
        if(dot3(w, inward) <= 1e-12 * std::sqrt(dot3(inward, inward)))
          return Streamline::End::TURNED_BACK;
      }
      p = q;
      f = next.first;
      entry = next.second;
    }
    return Streamline::End::LENGTH;
  };

  // seeds: the first face barycentre in each grid cell
  std::unordered_map<long long, char> taken;
  auto cell_key = [&](const V& p) {
    const long long i = static_cast<long long>(std::floor((p[0] - lo[0]) / spacing));
    const long long j = static_cast<long long>(std::floor((p[1] - lo[1]) / spacing));
    const long long k = static_cast<long long>(std::floor((p[2] - lo[2]) / spacing));
    return (i * 2097152LL + j) * 2097152LL + k;
  };
  const bool both_ways = (n % 2 == 0) || n == 1;
  const int families = (n % 2 == 0) ? n / 2 : n;
  for(std::size_t f = 0; f < nf; ++f)
  {
    if(singular[f]) continue;
    const V seed = barycentre(data.points, data.faces[f]);
    if(!taken.emplace(cell_key(seed), 1).second) continue;
    for(int family = 0; family < families; ++family)
    {
      const V w = rotated(data.face_directions[f], normal[f], 2. * CGAL_PI * family / n);
      Streamline line;
      std::vector<V> back_points;
      std::vector<std::size_t> back_faces;
      Streamline::End back_end = Streamline::End::LENGTH;
      if(both_ways)
        back_end = trace(f, seed, scaled(w, -1.), back_points, back_faces);
      // the backward half, reversed, then the seed, then the forward half
      for(std::size_t i = back_points.size(); i-- > 0;)
      {
        line.points.push_back(back_points[i]);
        line.faces.push_back(back_faces[i]);
      }
      line.points.push_back(seed);
      std::vector<V> forward_points;
      std::vector<std::size_t> forward_faces;
      const Streamline::End forward_end = trace(f, seed, w, forward_points, forward_faces);
      line.points.insert(line.points.end(), forward_points.begin(), forward_points.end());
      line.faces.insert(line.faces.end(), forward_faces.begin(), forward_faces.end());
      line.start_end = both_ways ? back_end : Streamline::End::LENGTH;
      line.finish_end = forward_end;
      if(!both_ways) line.start_end = Streamline::End::LENGTH;  // the seed itself
      if(line.points.size() >= 2) lines.push_back(std::move(line));
    }
  }
  return lines;
}

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

traces the field lines of a field computed on `tmesh` and writes them as CGAL
polylines: one `std::vector<Point>` per line to `out`, where `Point` is the
point type of `tmesh` (the value type of its vertex point map). Same lines as
`trace_streamlines(make_direction_field_data(tmesh, direction_map, degree, singularities, np), options)`.

\tparam TriangleMesh a model of `FaceListGraph`
\tparam VertexDirectionMap a `ReadablePropertyMap` from vertices to a 3D vector type
\tparam SingularityRange a range of `std::pair<face_descriptor, int>`
\tparam PolylineOutputIterator an output iterator accepting `std::vector<Point>`

\param tmesh the mesh
\param direction_map the first direction of each vertex
\param degree the degree `n` of the field
\param singularities the singular faces and their integers `k`
\param out receives the polylines
\param options seed spacing and maximum length
\returns the output iterator past the last polyline
*/
template <typename TriangleMesh, typename VertexDirectionMap, typename SingularityRange,
          typename PolylineOutputIterator>
PolylineOutputIterator trace_streamlines(const TriangleMesh& tmesh, VertexDirectionMap direction_map, int degree,
                                         const SingularityRange& singularities, PolylineOutputIterator out,
                                         const Streamline_options& options = Streamline_options())
{
  typedef typename boost::property_traits<
    typename boost::property_map<TriangleMesh, CGAL::vertex_point_t>::const_type>::value_type Point;
  const IO::Direction_field_data data = IO::make_direction_field_data(tmesh, direction_map, degree, singularities);
  for(const Streamline& line : trace_streamlines(data, options))
  {
    std::vector<Point> polyline;
    polyline.reserve(line.points.size());
    for(const auto& p : line.points) polyline.push_back(Point(p[0], p[1], p[2]));
    *out++ = std::move(polyline);
  }
  return out;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_STREAMLINES_H
