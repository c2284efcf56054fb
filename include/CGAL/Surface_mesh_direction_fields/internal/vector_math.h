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
inline double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }
inline double squared_norm(const Vec3& a) { return dot(a, a); }
// a / |a|, or a itself when it is the zero vector
inline Vec3 normalized(const Vec3& a)
{
  const double l = norm(a);
  return l > 0. ? (1. / l) * a : a;
}

// x reduced to (-pi, pi] by subtracting the nearest multiple of 2 pi, found
// by truncation (which does not depend on the rounding mode), instead of
// std::remainder, which took a quarter of the time of the face indices and a
// tenth of the connection's. Every operation in it is odd (x / c, adding
// sign(y) / 2, truncation, k c and x - k c, fused or not, change sign exactly
// with x), so reduce_angle(-x) = -reduce_angle(x) bit for bit. (Where x / 2 pi
// is within an ulp of a half, the result may fall just outside (-pi, pi]; it
// is still congruent to x and odd in x.)
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
