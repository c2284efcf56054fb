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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FIELD_ENGINE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FIELD_ENGINE_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/alignment.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <array>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

// The seam between the mesh plumbing and the method. The class
// Globally_optimal_direction_field reads the mesh and the named parameters
// into the index-based requests below and writes the answers into the
// user's property maps; the engine does everything in between (user manual,
// sections "The Smoothest Field" to "Placing Singularities"). This header
// declares the engine without its definitions (Field_engine_impl.h): with
// CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION a program compiles
// only the plumbing and links the engine of the default solver from the
// compiled library (see the README).

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
};

// The field of one compute(), by vertex and face index.
struct Field_answer
{
  std::vector<Vec3> directions;   // unit tangent direction per vertex
  std::vector<double> magnitudes;  // |u| per vertex, times the square root of its component's area
  std::vector<std::pair<std::size_t, int> > singular_faces;  // (face, k), in face order
};

// One loop of prescription_loops(): the corners along whose sides it runs,
// each with +1 if the loop follows the side's direction, -1 otherwise.
typedef std::vector<std::pair<std::size_t, int> > Corner_loop;

template <typename SparseSolver>
class Field_engine
{
public:
  // The intrinsic geometry of the mesh (its coordinates normalized), its
  // components and normals: the given ones (one per vertex), or the
  // angle-weighted ones if `normals` is empty.
  Field_engine(Indexed_mesh mesh, double mollification, std::vector<Vec3> normals);
  ~Field_engine();
  Field_engine(const Field_engine&) = delete;
  Field_engine& operator=(const Field_engine&) = delete;

  // One field; `solver`, if not null, is the user's solver for this call
  // only (no factorization kept).
  Direction_field_result compute(const Field_request& request, const SparseSolver* solver, Field_answer& answer);

  std::vector<Corner_loop> prescription_loops();
  void keep_factorizations(bool keep);
  std::size_t number_of_vertices() const;
  std::size_t number_of_faces() const;

private:
  class Impl;
  std::unique_ptr<Impl> m_impl;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_FIELD_ENGINE_H
