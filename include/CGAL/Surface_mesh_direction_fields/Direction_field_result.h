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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_DIRECTION_FIELD_RESULT_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_DIRECTION_FIELD_RESULT_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <array>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

the largest degree `n` the functions of this package, the command-line program
and the Python module accept (one thousand). The files and pictures hold `n`
directions per element, and beyond a few hundred directions most faces of a
common mesh are singular anyway; the integer indices `k` and their sums stay
far inside the integer types of the results.
*/
constexpr int maximum_degree = 1000;

/// \ingroup PkgSurfaceMeshDirectionFieldsRef
/// The degree `n` when the named parameter `degree` is not given: 4, a cross field, the field quad meshers
/// take. The same default holds in the command-line program (`--degree`) and in the Python module (`degree=`).
constexpr int default_degree = 4;

/// \ingroup PkgSurfaceMeshDirectionFieldsRef
/// The number of neighbours each point's local triangulation is built from when the named parameter
/// `number_of_neighbors` is not given (the program's `--neighbors`, Python's `neighbors=`).
constexpr unsigned int default_number_of_neighbors = 12;

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

What gave a component its field (`Component_solve_report::solve`).
*/
enum class Field_solve
{
  EIGEN_SOLVE,      ///< the smoothest field: the smallest eigenvector of \f$ A u = \lambda M u \f$
  LINEAR_SOLVE,     ///< an aligned or constrained field: \f$ (A - \lambda_t M) u = M q \f$ (the eigenvalue
                    ///< is computed beside it only where it is needed or asked for)
  PARALLEL_SECTION  ///< prescribed singularities: the parallel section of the changed connection (no eigenvalue)
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

What was solved on one connected component, and the component's shape: the
part of the report that fields on vertices (`Component_report`) and on faces
(`Face_field_component_report`) share. Components are numbered in the order
of their smallest vertex index.
*/
struct Component_solve_report
{
  /// what gave the component its field
  Field_solve solve = Field_solve::EIGEN_SOLVE;
  /// number of vertices of the component
  std::size_t number_of_vertices = 0;
  /// number of faces of the component
  std::size_t number_of_faces = 0;
  /// Euler characteristic \f$ \chi = V - E + F \f$ of the component
  int euler_characteristic = 0;
  /// `true` if the component has no boundary
  bool is_closed = false;
  /// smallest eigenvalue \f$ \lambda_1 \f$ of \f$ A u = \lambda M u \f$ (on faces: of the pencil on
  /// faces), the upper bound of \f$ \lambda_t \f$; empty where it was not computed: aligned and
  /// constrained fields compute it only when they need it or `compute_eigenvalue_bound` asks for it,
  /// prescribed singularities never. It scales like the inverse of an area (it is `n (1 - s) / R^2`
  /// for vertex fields on a round sphere of radius `R`)
  std::optional<double> eigenvalue;
  /// the \f$ \lambda_t \f$ of the aligned or constrained solve \f$ (A - \lambda_t M) u = M q \f$
  /// (0 for the smoothest field)
  double lambda = 0.;
  /// the alignment weight \f$ t = 1 / (1 + \|u\|_M) \f$ achieved, for \f$ \|q\|_M = 1 \f$
  /// (0 without guidance: the smoothest field)
  double alignment_weight = 0.;
  /// number of inverse iterations performed (plus, with `alignment_weight`, the linear solves of the root finding)
  std::size_t iterations = 0;
  /// final relative residual \f$ \|A u - \lambda M u\| / (s_A \|M u\|) \f$ of the eigen-solve, with
  /// \f$ s_A = \mathrm{tr}(A) / \mathrm{tr}(M) \f$ (a typical eigenvalue of the pencil); 0 for a direct solve
  double residual = 0.;
  /// `true` if the residual reached the requested tolerance (also `true` for an aligned or
  /// constrained field computed by a direct solve alone, without an eigen-solve)
  bool converged = false;
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

What the solve of a field on vertices found on one connected component of the mesh.
*/
struct Component_report : Component_solve_report
{
  /// sum of the integer indices `k` of the component's faces; equals `n * euler_characteristic`
  /// on a closed component (discrete Poincar&eacute;-Hopf)
  int index_sum = 0;
  /// number of faces of the component with a non-zero index
  std::size_t number_of_singular_faces = 0;
  /// fraction of the component's vertices where the field is too small for the solve's accuracy:
  /// its magnitude is below `100 * residual_tolerance` times the component's largest. The
  /// directions there, and the singular faces among them, are not determined by the tolerance
  /// and may differ between solvers, random seeds and numbers of processes (user manual,
  /// section "Where the Field Vanishes")
  double low_magnitude_fraction = 0.;
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

Wall-clock times of the phases of a computation, in milliseconds.
*/
struct Direction_field_timings
{
  /// indexing the mesh, tangent spaces, connection, and assembly of the matrices
  double setup_ms = 0.;
  /// sparse factorizations (one per component)
  double factorization_ms = 0.;
  /// inverse iterations, singularities and output directions
  double solve_ms = 0.;
  /// the whole call
  double total_ms = 0.;
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

The value returned by `compute_globally_optimal_directions()`: one report per
connected component, and totals over all of them.
*/
struct Direction_field_result
{
  /// the degree `n` of the field
  int degree = 1;
  /// the energy parameter `s`
  double smoothness_parameter = 0.;
  /// one entry per connected component
  std::vector<Component_report> components;
  /// number of vertices without incident face (they receive the zero vector)
  std::size_t number_of_isolated_vertices = 0;
  /// sum of the integer indices `k` over all faces (a 64-bit sum: `n` times the
  /// Euler characteristic of a closed mesh, which no degree up to `maximum_degree` overflows)
  long long index_sum = 0;
  /// number of faces with a non-zero index
  std::size_t number_of_singular_faces = 0;
  /// largest number of inverse iterations over the components
  std::size_t iterations = 0;
  /// largest final residual over the components
  double residual = 0.;
  /// `true` if every component converged
  bool converged = true;
  /// the length added to every edge by the intrinsic mollification (0 if the mesh needed none)
  double mollification = 0.;
  /// the number of vertices of folded triangles whose fans are laid out in the tangent plane of the
  /// fitted surface (user manual, section \ref SMDF_folds; 0 on a mesh without folds)
  std::size_t tangent_plane_vertices = 0;
  /// `true` if the singularities were prescribed (named parameter `prescribed_singularities`)
  bool prescribed = false;
  /// for prescribed singularities: the largest error, in radians, of the adjusted connection's holonomy
  /// around a face (against \f$ 2\pi k \f$) or around a loop of the cycle basis (against a multiple
  /// of \f$ 2\pi \f$), after the change of the connection; 0 otherwise
  double holonomy_error = 0.;
  /// the loops along which the field turns other than the nearest choice, as pairs `(l, t)`: `l` the
  /// position of the loop in `Globally_optimal_direction_field::prescription_loops()`, `t` how many more
  /// times the field turns along it, by \f$ 2\pi / n \f$ each (user manual, section \ref SMDF_prescribed).
  /// Given back as `prescribed_loop_turns`, with the singular faces as `prescribed_singularities`, they give
  /// this field's singularities back. The longest boundary loop of each component is left out: it turns as
  /// the indices and the other loops imply.
  std::vector<std::pair<std::size_t, int> > loop_turns;
  /// wall-clock times
  Direction_field_timings timings;
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

What the solve of a field on faces found on one connected component
(`compute_globally_optimal_face_directions()`; user manual, section \ref SMDF_faces).
*/
struct Face_field_component_report : Component_solve_report
{
  /// sum of the integer indices `k` of the component's interior vertices
  long long index_sum = 0;
  /// the boundary's contribution `B`: `index_sum + B` is `n * euler_characteristic` (0 on a closed
  /// component); `B` is the boundary's turning times `n` plus the field's rotation along the faces at the
  /// boundary, in turns (user manual, section \ref SMDF_faces)
  long long boundary_index = 0;
  /// number of interior vertices with a non-zero index
  std::size_t number_of_singular_vertices = 0;
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

The value returned by `compute_globally_optimal_face_directions()`.
*/
struct Face_direction_field_result
{
  /// the degree `n` of the field
  int degree = 1;
  /// one entry per connected component
  std::vector<Face_field_component_report> components;
  /// sum of the indices `k` over all interior vertices
  long long index_sum = 0;
  /// number of interior vertices with a non-zero index
  std::size_t number_of_singular_vertices = 0;
  /// largest number of iterations over the components
  std::size_t iterations = 0;
  /// largest final residual over the components
  double residual = 0.;
  /// `true` if every component converged
  bool converged = true;
  /// the length added to every edge by the intrinsic mollification (0 if the mesh needed none)
  double mollification = 0.;
  /// `true` if the singularities were prescribed (named parameter `prescribed_singularities`)
  bool prescribed = false;
  /// number of interior edges across which the matching is not the principal one: the field turns there by
  /// \f$ \pi / n \f$ or more between the two faces (only a prescription asks that, e.g. two opposite
  /// singularities at the ends of one edge). A consumer that recomputes the matching from the directions
  /// (QuadWild's `.rosy`) reads other singular vertices; `edge_matching_map` and Directional's `.matching`
  /// carry it. 0 for the smoothest and aligned fields
  std::size_t number_of_non_principal_jumps = 0;
  /// number of pairs of singular vertices with opposite indices removed by `singularity_cancellation_radius`
  /// (0 without it); the field is then the parallel one with the remaining singularities (`prescribed` is `true`)
  std::size_t number_of_cancelled_pairs = 0;
  /// number of non-manifold edges across which the faces share the field (named parameter
  /// `vertex_point_index_map`; 0 without it)
  std::size_t number_of_glued_edges = 0;
  /// wall-clock times
  Direction_field_timings timings;
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

What `compute_globally_optimal_point_set_directions()` found besides the
directions. Points are numbered in the order of the range; triangles list three
point numbers, counter-clockwise about the points' normals.
*/
struct Point_set_direction_field_result
{
  /// the normal used at each point (given, or estimated), of unit length
  std::vector<std::array<double, 3> > normals;
  /// whether the normals were estimated (no `normal_map` given)
  bool normals_estimated = false;
  /// the magnitude of the field at each point, relative to its largest in the point's component (1 there; the
  /// directions are less certain where it is small, as on a mesh)
  std::vector<double> magnitudes;
  /// the triangles of the local triangulations, each once
  std::vector<std::array<std::size_t, 3> > triangles;
  /// for each triangle, how many of its three points' local triangulations hold it (1 to 3)
  std::vector<unsigned char> holders;
  /// for each triangle, whether it belongs to the surface the singularities are read on: the triangles taken
  /// by decreasing holders, each unless one of its sides, in its direction, belongs to one taken before
  std::vector<unsigned char> on_surface;
  /// the surface triangles around which the field turns, with their integer index `k` (the index is `k / n`)
  std::vector<std::pair<std::size_t, int> > singular_triangles;
  /// per connected component (points joined by triangles), as on a mesh
  std::vector<Component_report> components;
  /// the points in no triangle: they receive the zero vector
  std::size_t number_of_points_without_triangles = 0;
  /// the Euler characteristic V - E + F of the surface triangles; where the surface closes, the indices of
  /// `singular_triangles` add up to `n` times it (the user manual says when they may not elsewhere)
  int surface_euler_characteristic = 0;
  /// whether every side of a surface triangle is a side of another one
  bool surface_is_closed = false;
  /// where the time went: `setup_ms` holds the neighbours, the local triangulations and the assembly
  Direction_field_timings timings;
  /// of `timings.setup_ms`, the estimation of the normals (0 when they are given)
  double normals_ms = 0.;
};

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_DIRECTION_FIELD_RESULT_H
