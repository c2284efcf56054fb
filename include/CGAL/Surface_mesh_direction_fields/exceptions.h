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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_EXCEPTIONS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_EXCEPTIONS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <cstddef>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Surface_mesh_direction_fields {

namespace internal {

// A number in an error message, compactly ("1e+09", "0.5"), not std::to_string's six decimals.
inline std::string compact_number(double x)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", x);
  return text;
}

} // namespace internal

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

Base class of the exceptions thrown by the functions of this package.
`what()` names the problem and, where there is one, the offending element
(vertex or face index in the order of the mesh's index maps).
*/
class Direction_field_error : public std::runtime_error
{
public:
  /// constructs the exception.
  /// \param what the message, naming the problem
  explicit Direction_field_error(const std::string& what) : std::runtime_error(what) {}
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

Thrown when the input mesh or a parameter does not meet the documented
requirements: an empty mesh, a mesh too large for 32-bit indices, a
non-triangle face, a non-manifold vertex, a non-finite coordinate, a degenerate (zero-area) face when the intrinsic
mollification is switched off, a degree `n < 1`, or a smoothness parameter
`s` outside `[-1, 1]`. The input is left untouched.
*/
class Invalid_input_error : public Direction_field_error
{
public:
  /// constructs the exception.
  /// \param what the message, naming the problem
  explicit Invalid_input_error(const std::string& what) : Direction_field_error(what) {}

  /// constructs the exception for a problem at one face.
  /// \param what the message, naming the face as `"face " + std::to_string(face)` (once)
  /// \param face the face's index in the order of the mesh's face index map
  Invalid_input_error(const std::string& what, std::size_t face)
    : Direction_field_error(what), m_face(face), m_has_face(true)
  {
  }

  /// tells whether the problem is at a face, whose index `face()` gives. `what()` then names
  /// faces as "face " followed by their index, so that a program that numbers faces otherwise (a
  /// file's polygons, before a repair) can name them its own way.
  /// \return `true` for a problem at a face
  bool has_face() const { return m_has_face; }
  /// gives the face's index in the order of the mesh's face index map.
  /// \return the index (0 when `has_face()` is `false`)
  std::size_t face() const { return m_face; }

private:
  std::size_t m_face = 0;
  bool m_has_face = false;
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

Thrown when the sparse linear solver fails to factor the shifted energy
matrix, which only happens with a solver that does not support Hermitian
positive definite matrices, or on input that is numerically degenerate.
*/
class Solver_failure_error : public Direction_field_error
{
public:
  /// constructs the exception.
  /// \param what the message, naming the problem
  explicit Solver_failure_error(const std::string& what) : Direction_field_error(what) {}
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

Thrown when the `progress_callback` named parameter returned `false`: the
computation stopped there. The output maps are left unchanged, and the class
`Globally_optimal_direction_field` computes the next field as a new object
would.
*/
class Computation_interrupted : public Direction_field_error
{
public:
  /// constructs the exception.
  /// \param what the message
  explicit Computation_interrupted(const std::string& what) : Direction_field_error(what) {}
};

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_EXCEPTIONS_H
