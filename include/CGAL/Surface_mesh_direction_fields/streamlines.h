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

#include <CGAL/Surface_mesh_direction_fields/Direction_field_data.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

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
  double seed_spacing = 0.02;
  /// the largest length of each half of a streamline (from its seed)
  double maximum_length = 0.3;
  /// the least distance between lines of the same direction family: a line
  /// stops (and a seed is skipped) closer than this to a line traced before
  /// it whose direction is within 30 degrees of its own, so that lines are
  /// evenly spaced instead of bunching where the field converges; 0: no limit.
  /// The defaults are those of the command-line program's pictures and files.
  double minimum_separation = 0.012;
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
    DEGENERATE,   ///< no exit could be found in a face (a degenerate face)
    TOO_CLOSE     ///< it came closer than `minimum_separation` to an earlier line of the same family
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

// Across each edge (f, c) -- the side from faces[f][c] to faces[f][c+1] -- the
// neighbouring face and its side index; (no face, 0) on a boundary or
// non-manifold edge.
inline std::vector<std::pair<std::size_t, int> > edge_neighbours(const Direction_field_data& d)
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

// The points of the lines traced so far, with their unit tangents, in a hash
// grid of cells of the separation distance: is a new point too close to a
// line of the same family (a tangent within 30 degrees, either way)?
class Line_separation
{
  double m_distance;
  std::unordered_map<long long, std::vector<std::pair<Vec3, Vec3> > > m_cells;

  long long key(long long i, long long j, long long k) const { return (i * 2097152LL + j) * 2097152LL + k; }
  long long cell(double x) const { return static_cast<long long>(std::floor(x / m_distance)); }

public:
  explicit Line_separation(double distance) : m_distance(distance) {}
  bool active() const { return m_distance > 0.; }

  bool too_close(const Vec3& p, const Vec3& tangent) const
  {
    if(!active()) return false;
    const long long i = cell(p[0]), j = cell(p[1]), k = cell(p[2]);
    for(long long a = i - 1; a <= i + 1; ++a)
      for(long long b = j - 1; b <= j + 1; ++b)
        for(long long c = k - 1; c <= k + 1; ++c)
        {
          const auto it = m_cells.find(key(a, b, c));
          if(it == m_cells.end()) continue;
          for(const auto& sample : it->second)
          {
            const Vec3 d = sample.first - p;
            if(dot(d, d) < m_distance * m_distance && std::abs(dot(sample.second, tangent)) > 0.866) return true;
          }
        }
    return false;
  }

  // Samples every half distance along the polyline.
  void add(const std::vector<Vec3>& points)
  {
    if(!active()) return;
    for(std::size_t i = 0; i + 1 < points.size(); ++i)
    {
      const Vec3 e = points[i + 1] - points[i];
      const double length = norm(e);
      if(!(length > 0.)) continue;
      const Vec3 tangent = (1. / length) * e;
      const int steps = static_cast<int>(std::ceil(2. * length / m_distance));
      for(int s = 0; s < steps; ++s)
      {
        const Vec3 p = points[i] + (length * s / steps) * tangent;
        m_cells[key(cell(p[0]), cell(p[1]), cell(p[2]))].emplace_back(p, tangent);
      }
    }
  }
};

// Traces the field lines of one Direction_field_data (see trace_streamlines()).
class Streamline_tracer
{
  static constexpr std::size_t none = static_cast<std::size_t>(-1);
  const Direction_field_data& m_data;
  const int m_degree;
  Vec3 m_low, m_high;
  double m_diagonal = 0., m_spacing = 0., m_max_length = 0., m_separation = 0.;
  std::vector<unsigned char> m_singular;
  std::vector<std::pair<std::size_t, int> > m_neighbour;
  std::vector<Vec3> m_normal;

public:
  Streamline_tracer(const Direction_field_data& data, const Streamline_options& options)
    : m_data(data), m_degree(data.degree)
  {
    const std::array<Vec3, 2> box = bounding_box(data.points);
    m_low = box[0];
    m_high = box[1];
    m_diagonal = norm(m_high - m_low);
    m_spacing = options.seed_spacing * m_diagonal;
    m_max_length = options.maximum_length * m_diagonal;
    m_separation = options.minimum_separation * m_diagonal;
    const std::size_t nf = data.faces.size();
    m_singular.assign(nf, 0);
    for(const auto& s : data.singularities) if(s.first < nf && s.second != 0) m_singular[s.first] = 1;
    // a field on faces: its singularities are vertices, the faces around them are left alone
    std::vector<unsigned char> singular_vertex(data.points.size(), 0);
    for(const auto& s : data.vertex_singularities) if(s.first < data.points.size() && s.second != 0) singular_vertex[s.first] = 1;
    for(std::size_t f = 0; f < nf && !data.vertex_singularities.empty(); ++f)
      for(std::size_t v : data.faces[f]) if(singular_vertex[v]) m_singular[f] = 1;
    m_neighbour = edge_neighbours(data);
    m_normal.resize(nf);
    for(std::size_t f = 0; f < nf; ++f) m_normal[f] = triangle_unit_normal(data.points, data.faces[f]);
  }

  bool has_extent() const { return m_diagonal > 0.; }

  // Seeds: the first face barycentre in each grid cell; from each, one line
  // per direction family (both ways for even n and n = 1, forwards otherwise).
  std::vector<Streamline> trace_all() const
  {
    std::vector<Streamline> lines;
    std::unordered_map<long long, char> taken;
    Line_separation separation(m_separation);
    const int n = m_degree;
    const int families = (n % 2 == 0) ? n / 2 : n;
    for(std::size_t f = 0; f < m_data.faces.size(); ++f)
    {
      if(m_singular[f]) continue;
      const Vec3 seed = barycentre(m_data.points, m_data.faces[f]);
      if(!taken.emplace(cell_key(seed), 1).second) continue;
      for(int family = 0; family < families; ++family)
      {
        const Vec3 w = rotated(m_data.face_directions[f], m_normal[f], 2. * CGAL_PI * family / n);
        if(separation.too_close(seed, w)) continue;
        Streamline line = line_through(f, seed, w, separation);
        if(line.points.size() < 2) continue;
        separation.add(line.points);
        lines.push_back(std::move(line));
      }
    }
    return lines;
  }

private:
  long long cell_key(const Vec3& p) const
  {
    const long long i = static_cast<long long>(std::floor((p[0] - m_low[0]) / m_spacing));
    const long long j = static_cast<long long>(std::floor((p[1] - m_low[1]) / m_spacing));
    const long long k = static_cast<long long>(std::floor((p[2] - m_low[2]) / m_spacing));
    return (i * 2097152LL + j) * 2097152LL + k;
  }

  // The line through the seed in face f along w: the backward half reversed,
  // the seed, the forward half.
  Streamline line_through(std::size_t f, const Vec3& seed, const Vec3& w, const Line_separation& separation) const
  {
    const bool both_ways = (m_degree % 2 == 0) || m_degree == 1;
    Streamline line;
    std::vector<Vec3> back_points;
    std::vector<std::size_t> back_faces;
    Streamline::End back_end = Streamline::End::LENGTH;
    if(both_ways)  // backwards along the opposite of the field (for n = 1, its only direction points forwards)
      back_end = trace_half(f, seed, -1. * w, back_points, back_faces, separation, -1.);
    for(std::size_t i = back_points.size(); i-- > 0;)
    {
      line.points.push_back(back_points[i]);
      line.faces.push_back(back_faces[i]);
    }
    line.points.push_back(seed);
    std::vector<Vec3> forward_points;
    std::vector<std::size_t> forward_faces;
    const Streamline::End forward_end = trace_half(f, seed, w, forward_points, forward_faces, separation);
    line.points.insert(line.points.end(), forward_points.begin(), forward_points.end());
    line.faces.insert(line.faces.end(), forward_faces.begin(), forward_faces.end());
    line.start_end = both_ways ? back_end : Streamline::End::LENGTH;  // forwards only: the seed itself
    line.finish_end = forward_end;
    return line;
  }

  // The field direction of face f closest to w (w in the plane of f).
  Vec3 closest_direction(std::size_t f, const Vec3& w) const
  {
    const Vec3& d = m_data.face_directions[f];
    Vec3 best = d;
    double best_dot = -2.;
    for(int k = 0; k < m_degree; ++k)
    {
      const Vec3 dk = rotated(d, m_normal[f], 2. * CGAL_PI * k / m_degree);
      if(dot(dk, w) > best_dot) { best_dot = dot(dk, w); best = dk; }
    }
    return best;
  }

  // Where the ray p + t w leaves face f through a side other than `entry`:
  // that side (-1 if none) and t.
  int exit_side(std::size_t f, const Vec3& p, const Vec3& w, int entry, double& exit_t) const
  {
    const auto& t = m_data.faces[f];
    exit_t = HUGE_VAL;
    int best_side = -1;
    for(int c = 0; c < 3; ++c)
    {
      if(c == entry) continue;
      const Vec3 a = m_data.points[t[static_cast<std::size_t>(c)]], b = m_data.points[t[static_cast<std::size_t>((c + 1) % 3)]];
      // p + s w = a + r (b - a), in the face plane: 2x2 system by cross products with the normal
      const Vec3 e = b - a, ap = a - p;
      const double denominator = dot(cross(w, e), m_normal[f]);
      if(std::abs(denominator) < 1e-300) continue;
      const double s = dot(cross(ap, e), m_normal[f]) / denominator;
      const double r = dot(cross(ap, w), m_normal[f]) / denominator;
      if(s > 1e-12 * m_diagonal && r >= -1e-9 && r <= 1. + 1e-9 && s < exit_t) { exit_t = s; best_side = c; }
    }
    return best_side;
  }

  // Whether w points back out of face g across its side `side` (or along it).
  bool turns_back(std::size_t g, int side, const Vec3& w) const
  {
    const auto& t = m_data.faces[g];
    const Vec3 a = m_data.points[t[static_cast<std::size_t>(side)]];
    const Vec3 b = m_data.points[t[static_cast<std::size_t>((side + 1) % 3)]];
    const Vec3 inward = cross(m_normal[g], b - a);
    return dot(w, inward) <= 1e-12 * norm(inward);
  }

  // One half line from point p in face f along w; appends to points/faces.
  // `orientation` -1 follows the opposite of the field's directions (the
  // backward half of a vector field's line).
  Streamline::End trace_half(std::size_t f, Vec3 p, Vec3 w, std::vector<Vec3>& points,
                             std::vector<std::size_t>& faces, const Line_separation& separation,
                             double orientation = 1.) const
  {
    double length = 0.;
    int entry = -1;  // the side through which the line entered f
    const std::size_t max_steps = 4 * m_data.faces.size() + 16;
    for(std::size_t step = 0; step < max_steps; ++step)
    {
      double exit_t = 0.;
      const int side = exit_side(f, p, w, entry, exit_t);
      if(side < 0) return Streamline::End::DEGENERATE;
      const bool too_long = length + exit_t > m_max_length;
      const double step_length = too_long ? m_max_length - length : exit_t;
      const Vec3 q{p[0] + step_length * w[0], p[1] + step_length * w[1], p[2] + step_length * w[2]};
      if(separation.too_close(q, w))  // ends half way to a point too close
      {
        points.push_back(p + (0.5 * step_length) * w);
        faces.push_back(f);
        return Streamline::End::TOO_CLOSE;
      }
      points.push_back(q);
      faces.push_back(f);
      length += step_length;
      if(too_long) return Streamline::End::LENGTH;
      const auto next = m_neighbour[3 * f + static_cast<std::size_t>(side)];
      if(next.first == none) return Streamline::End::BOUNDARY;
      if(m_singular[next.first]) return Streamline::End::SINGULARITY;
      // unfold w into the next face, then follow its closest field direction
      w = orientation * closest_direction(next.first, orientation * rotate_onto(w, m_normal[f], m_normal[next.first]));
      if(turns_back(next.first, next.second, w)) return Streamline::End::TURNED_BACK;
      p = q;
      f = next.first;
      entry = next.second;
    }
    return Streamline::End::LENGTH;
  }
};

} // namespace internal

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

traces field lines of the per-face field of `data` (`data.face_directions`,
see `face_directions()`): seeds at face barycentres spread by a grid of
spacing `options.seed_spacing`; from each seed, for a field of even degree `n`,
one line along each of the `n/2` direction families, traced both ways; for
`n = 1` one line, both ways (backwards along the opposite of the field, so
that the whole line runs along the vectors, in the order of its points); for
odd `n > 1`, `n` lines, forwards.

Inside a face a line is straight along the face's field direction. When it
crosses an edge, the direction is carried into the next face by unfolding
(the rotation about the shared edge taking one face's plane to the other's),
and the line continues along the direction of that face closest to it (the
`n`-fold matching). A line stops at a boundary (or non-manifold) edge, on the
edge of a singular face (it never enters one; for a field on faces, a face
around a singular vertex of `data.vertex_singularities`), on an edge where the next
face's field points back (the per-face field is discontinuous there: a sink or
source line), when it reaches
`options.maximum_length`, in a degenerate face, or when it comes closer than
`options.minimum_separation` to a line of its family traced before it. Seeds in singular faces are
skipped.

\param data the field with its mesh (`make_direction_field_data()` fills everything needed)
\param options seed spacing and maximum length
\returns the streamlines
*/
inline std::vector<Streamline> trace_streamlines(const Direction_field_data& data,
                                                 const Streamline_options& options = Streamline_options())
{
  if(data.faces.empty() || data.points.empty()) return std::vector<Streamline>();
  if(data.face_directions.size() != data.faces.size())
    throw Invalid_input_error("trace_streamlines: the data has no per-face directions");
  if(!(options.seed_spacing > 0.) || !(options.maximum_length > 0.) || !(options.minimum_separation >= 0.))
    throw Invalid_input_error("trace_streamlines: the seed spacing and the maximum length must be positive, the separation not negative");
  // the tracer's lengths and tolerances hold for coordinates within about
  // 1e±18: beyond, the lines are traced on the points scaled by a power of
  // two and scaled back (exactly)
  if(const int e = internal::extreme_scale_exponent(data.points, 60))
  {
    Direction_field_data scaled = data;
    scaled.points = internal::scaled_by_power_of_two(data.points, -e);
    for(auto& p : scaled.singularity_points) p = internal::scaled_by_power_of_two({p}, -e)[0];
    std::vector<Streamline> lines = trace_streamlines(scaled, options);
    for(Streamline& l : lines) l.points = internal::scaled_by_power_of_two(l.points, e);
    return lines;
  }
  const internal::Streamline_tracer tracer(data, options);
  if(!tracer.has_extent()) return std::vector<Streamline>();
  return tracer.trace_all();
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
  const Direction_field_data data = make_direction_field_data(tmesh, direction_map, degree, singularities);
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
