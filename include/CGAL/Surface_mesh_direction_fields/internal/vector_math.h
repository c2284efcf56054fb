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

#include <array>
#include <cmath>

// Small double-precision 3-vectors. All linear algebra of the package runs in
// double whatever the kernel: coordinates are converted once when the mesh is
// indexed, so exact kernels pay no price in the numerics.

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

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_VECTOR_MATH_H
