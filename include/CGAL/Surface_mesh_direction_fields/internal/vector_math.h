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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_VECTOR_MATH_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_VECTOR_MATH_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/number_type_config.h>

#include <array>
#include <cmath>
#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

// Small double-precision 3-vectors, and the reduction of angles. All linear
// algebra of the package runs in double whatever the kernel: coordinates are
// converted once when the mesh is indexed, so exact kernels pay no price in
// the numerics.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

typedef std::array<double, 3> Vec3;

inline Vec3 operator-(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec3 operator+(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
inline Vec3 operator*(double s, const Vec3& a) { return {s * a[0], s * a[1], s * a[2]}; }
inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
// |a|, also where the sum of squares overflows or underflows (the squares
// of a cross product of coordinates near 1e80 or 1e-80 do): a is then scaled
// by a power of two, which keeps its bits, before squaring. Elsewhere the
// plain formula, so results do not change for vectors of ordinary size.
inline double norm(const Vec3& a)
{
  const double s = dot(a, a);
  if(s >= (std::numeric_limits<double>::min)() && s <= (std::numeric_limits<double>::max)()) return std::sqrt(s);
  double largest = 0.;
  for(double x : a) largest = (std::max)(largest, std::abs(x));
  if(!(largest > 0.) || !std::isfinite(largest)) return std::sqrt(s);
  int exponent = 0;
  std::frexp(largest, &exponent);
  const Vec3 b{std::ldexp(a[0], -exponent), std::ldexp(a[1], -exponent), std::ldexp(a[2], -exponent)};
  return std::ldexp(std::sqrt(dot(b, b)), exponent);
}
inline double squared_norm(const Vec3& a) { return dot(a, a); }
// The corners (low, high) of the axis-aligned bounding box of `points`
// (both zero if there are none).
inline std::array<Vec3, 2> bounding_box(const std::vector<Vec3>& points)
{
  std::array<Vec3, 2> box{};
  if(points.empty()) return box;
  box[0] = box[1] = points[0];
  for(const Vec3& p : points)
    for(int k = 0; k < 3; ++k)
    {
      box[0][k] = p[k] < box[0][k] ? p[k] : box[0][k];
      box[1][k] = p[k] > box[1][k] ? p[k] : box[1][k];
    }
  return box;
}

// a / |a|; a itself if |a| is not positive (the zero vector stays zero)
inline Vec3 normalized(const Vec3& a)
{
  const double l = norm(a);
  return l > 0. ? (1. / l) * a : a;
}

// a x b, scaled by a power of two where the sides' largest coordinate lies
// beyond 2^+-200: they are first brought to a largest coordinate in
// [0.5, 1), so that the product neither overflows (sides near 1e155) nor
// underflows (near 1e-160). A power of two keeps every bit, so its direction
// is that of the plain product wherever that one is finite; sides of
// ordinary size take the plain product (no scaling to pay for).
inline Vec3 scaled_cross(const Vec3& a, const Vec3& b)
{
  double largest = 0.;
  for(int i = 0; i < 3; ++i) largest = (std::max)(largest, (std::max)(std::abs(a[i]), std::abs(b[i])));
  if(!(largest > 0.) || !std::isfinite(largest) || (largest >= 0x1p-200 && largest <= 0x1p200)) return cross(a, b);
  int exponent = 0;
  std::frexp(largest, &exponent);
  const Vec3 sa{std::ldexp(a[0], -exponent), std::ldexp(a[1], -exponent), std::ldexp(a[2], -exponent)};
  const Vec3 sb{std::ldexp(b[0], -exponent), std::ldexp(b[1], -exponent), std::ldexp(b[2], -exponent)};
  return cross(sa, sb);
}

// The unit normal of the triangle t of `points`, counter-clockwise (zero for a
// degenerate triangle), at any scale of the coordinates.
inline Vec3 triangle_unit_normal(const Vec3& p0, const Vec3& p1, const Vec3& p2)
{
  return normalized(scaled_cross(p1 - p0, p2 - p0));
}
template <typename Triangle>
Vec3 triangle_unit_normal(const std::vector<Vec3>& points, const Triangle& t)
{
  return triangle_unit_normal(points[t[0]], points[t[1]], points[t[2]]);
}

template <typename Triangle>
Vec3 barycentre(const std::vector<Vec3>& points, const Triangle& t)
{
  Vec3 b{0., 0., 0.};
  for(int c = 0; c < 3; ++c)
    for(int i = 0; i < 3; ++i) b[i] += points[t[c]][i] / 3.;
  return b;
}

// d rotated by `angle` about the unit axis n (d orthogonal to n).
inline Vec3 rotated(const Vec3& d, const Vec3& n, double angle)
{
  const Vec3 nd = cross(n, d);
  return {std::cos(angle) * d[0] + std::sin(angle) * nd[0], std::cos(angle) * d[1] + std::sin(angle) * nd[1],
          std::cos(angle) * d[2] + std::sin(angle) * nd[2]};
}

// The smallest rotation taking the unit vector a to the unit vector b, applied
// to v (v itself when a = b, or a = -b, where no rotation is the smallest).
inline Vec3 rotate_onto(const Vec3& v, const Vec3& a, const Vec3& b)
{
  const Vec3 axis = cross(a, b);
  const double s = norm(axis), c = dot(a, b);
  if(s < 1e-15) return v;
  const Vec3 k = (1. / s) * axis;
  const Vec3 kv = cross(k, v);
  const double kd = dot(k, v) * (1. - c);
  return {v[0] * c + kv[0] * s + k[0] * kd, v[1] * c + kv[1] * s + k[1] * kd, v[2] * c + kv[2] * s + k[2] * kd};
}

inline double reduce_angle(double x)
{
  const double two_pi = 2. * CGAL_PI;
  const double turns = x / two_pi;
  if(!(std::abs(turns) < 1e15))
    return std::remainder(x, two_pi);  // huge (or non-finite) angles
  const double k = static_cast<double>(static_cast<long long>(turns + std::copysign(0.5, turns)));
  return x - two_pi * k;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_VECTOR_MATH_H
