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
//
// Appends the named parameters of the package Surface_mesh_direction_fields to
// CGAL's list of named parameters.
//
// Why a shadow file: CGAL 5.5 builds the member functions of
// `CGAL::Named_function_parameters` (the chaining `.degree(4).vertex_point_map(vpm)`)
// from this one list, and members cannot be added from outside. Placing this
// file before CGAL's include directory and forwarding with `#include_next`
// gives users exactly the CGAL syntax, in any order. When the package is merged
// into CGAL, the lines below move verbatim into CGAL's own file and this file
// is deleted. `#include_next` is a GCC/Clang extension (not MSVC).
//
// NOTE: no include guard, on purpose: CGAL includes this file three times with
// three different definitions of CGAL_add_named_parameter.

#include_next <CGAL/STL_Extension/internal/parameters_interface.h>

#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_NAMED_PARAMETERS_DECLARED 1

// Surface_mesh_direction_fields
CGAL_add_named_parameter(degree_t, degree, degree)
CGAL_add_named_parameter(smoothness_parameter_t, smoothness_parameter, smoothness_parameter)
CGAL_add_named_parameter(singularities_output_iterator_t, singularities_output_iterator, singularities_output_iterator)
CGAL_add_named_parameter(vertex_magnitude_map_t, vertex_magnitude_map, vertex_magnitude_map)
CGAL_add_named_parameter(vertex_coefficient_map_t, vertex_coefficient_map, vertex_coefficient_map)
CGAL_add_named_parameter(residual_tolerance_t, residual_tolerance, residual_tolerance)
CGAL_add_named_parameter(intrinsic_mollification_t, intrinsic_mollification, intrinsic_mollification)
CGAL_add_named_parameter(vertex_guidance_map_t, vertex_guidance_map, vertex_guidance_map)
CGAL_add_named_parameter(principal_curvature_alignment_t, principal_curvature_alignment, principal_curvature_alignment)
CGAL_add_named_parameter(principal_curvature_estimate_t, principal_curvature_estimate, principal_curvature_estimate)
CGAL_add_named_parameter(alignment_lambda_t, alignment_lambda, alignment_lambda)
CGAL_add_named_parameter(alignment_weight_t, alignment_weight, alignment_weight)
CGAL_add_named_parameter(compute_eigenvalue_bound_t, compute_eigenvalue_bound, compute_eigenvalue_bound)
CGAL_add_named_parameter(vertex_constrained_direction_map_t, vertex_constrained_direction_map, vertex_constrained_direction_map)
CGAL_add_named_parameter(boundary_alignment_t, boundary_alignment, boundary_alignment)
CGAL_add_named_parameter(edge_is_feature_t, edge_is_feature, edge_is_feature_map)
CGAL_add_named_parameter(feature_cleanup_steps_t, feature_cleanup_steps, feature_cleanup_steps)
CGAL_add_named_parameter(distributed_solver_t, distributed_solver, distributed_solver)
CGAL_add_named_parameter(prescribed_singularities_t, prescribed_singularities, prescribed_singularities)
CGAL_add_named_parameter(prescribed_loop_turns_t, prescribed_loop_turns, prescribed_loop_turns)
CGAL_add_named_parameter(singularity_cancellation_radius_t, singularity_cancellation_radius, singularity_cancellation_radius)
CGAL_add_named_parameter(progress_callback_t, progress_callback, progress_callback)
CGAL_add_named_parameter(face_guidance_map_t, face_guidance_map, face_guidance_map)
CGAL_add_named_parameter(face_is_constrained_t, face_is_constrained, face_is_constrained_map)
CGAL_add_named_parameter(face_constrained_direction_map_t, face_constrained_direction_map, face_constrained_direction_map)
CGAL_add_named_parameter(edge_matching_map_t, edge_matching_map, edge_matching_map)
CGAL_add_named_parameter(number_of_neighbors_t, number_of_neighbors, number_of_neighbors)
CGAL_add_named_parameter(point_guidance_map_t, point_guidance_map, point_guidance_map)
CGAL_add_named_parameter(point_constrained_direction_map_t, point_constrained_direction_map, point_constrained_direction_map)
CGAL_add_named_parameter(vertex_point_index_t, vertex_point_index, vertex_point_index_map)
