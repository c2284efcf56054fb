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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FIELD_REQUEST_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FIELD_REQUEST_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/alignment.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <array>
#include <complex>
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

// What one field asks of the method, by vertex, face and loop index (read
// from the named parameters by Engine/named_inputs.h), and what comes back.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

class Distributed_backend;

// How strongly the field follows its guidance: lambda_t, or the alignment
// weight t from which lambda_t is found (user manual, "Aligned and Constrained Fields").
struct Alignment_request
{
  bool lambda_given = false, weight_given = false;
  double lambda = 0., weight = 0.5;
  bool eigenvalue_bound = false;  // lambda_1 asked for, also where the field does not need it
};

// One field as the named parameters ask for it, with vertices, faces and
// loops by index (the class's index maps).
struct Field_request
{
  int degree = 1;
  double s = 0.;
  unsigned int max_iterations = 1000;
  double residual_tolerance = 1e-10;
  unsigned int random_seed = 0;

  // guidance: from the principal curvatures and/or a 3D vector per vertex
  Principal_curvature_alignment curvature = Principal_curvature_alignment::NONE;
  Principal_curvature_estimate curvature_estimate = Principal_curvature_estimate::QUADRIC_FIT;
  bool has_guidance_map = false;
  std::vector<Vec3> guidance;  // per vertex, finite, when has_guidance_map
  Alignment_request alignment;

  // hard constraints
  Boundary_alignment boundary = Boundary_alignment::NONE;
  bool has_constraint_map = false;
  std::vector<unsigned char> constrained;  // per vertex, when has_constraint_map
  std::vector<Vec3> constrained_direction;  // per vertex (read where constrained)
  bool has_feature_map = false;
  std::vector<std::array<std::size_t, 2> > feature_edges;  // the two vertices of each feature edge

  // prescribed singularities (user manual, "Placing Singularities")
  bool prescribed = false;
  std::vector<int> prescribed_index;                        // k per face
  std::vector<std::pair<std::size_t, long> > loop_turns;  // (loop, turns) as given

  const Distributed_backend* distributed = nullptr;  // the backend of `distributed_solver`, if any

  // `progress_callback`: told the fraction done; false stops the computation
  std::function<bool(double)> progress;
};

// The field of one compute(), by vertex and face index.
struct Field_answer
{
  std::vector<Vec3> directions;   // unit tangent direction per vertex
  std::vector<double> magnitudes;  // |u| per vertex, times the square root of its component's area
  std::vector<std::complex<double> > coefficients;  // u per vertex, of length `magnitudes`
  std::vector<std::pair<std::size_t, int> > singular_faces;  // (face, k), in face order
};

// A field on faces as the named parameters ask for it, by vertex and face
// index (user manual, section "Fields on Faces").
struct Face_field_request
{
  int degree = 1;
  unsigned int max_iterations = 1000;
  double residual_tolerance = 1e-10;
  unsigned int random_seed = 0;
  Principal_curvature_alignment curvature = Principal_curvature_alignment::NONE;
  std::vector<Vec3> guidance;  // per face, finite; empty: none
  Alignment_request alignment;
  Boundary_alignment boundary = Boundary_alignment::NONE;
  std::vector<unsigned char> constrained;   // per face; empty: none
  std::vector<Vec3> constrained_direction;  // per face (read where constrained)
  std::vector<std::array<std::size_t, 2> > feature_edges;  // the two vertices of each feature edge
  bool prescribed = false;
  std::vector<int> prescribed_index;  // k per vertex, when prescribed
  double cancellation_radius = 0.;    // of opposite singular pairs, a fraction of the bounding box's diagonal
  std::function<bool(double)> progress;
};

// The field on faces of one call, by vertex and face index.
struct Face_field_answer
{
  std::vector<Vec3> directions;  // unit direction per face
  std::vector<int> vertex_index;  // k per vertex (0 on the boundary)
  std::vector<int> matching;      // per corner 3f+c (the period jump across its side), 0 on the border
};

// One loop of prescription_loops(): the corners along whose sides it runs,
// each with +1 if the loop follows the side's direction, -1 otherwise.
typedef std::vector<std::pair<std::size_t, int> > Corner_loop;

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_FIELD_REQUEST_H
