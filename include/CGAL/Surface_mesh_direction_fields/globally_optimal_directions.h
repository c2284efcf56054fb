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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_DIRECTIONS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_DIRECTIONS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Globally_optimal_direction_field.h>

#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

\brief computes the globally smoothest unit `n`-direction field of a triangle
mesh (Kn&ouml;ppel, Crane, Pinkall and Schr&ouml;der, 2013), and its singularities.

The field is represented at each vertex by the `n`-th power `u` of a complex
number, so that the `n` directions of an `n`-direction field become one value.
The smoothest field minimizes the energy \f$ E_s(u) = u^* A u \f$ over all
`u` with \f$ u^* M u = 1 \f$, that is, it is the eigenvector of the smallest
eigenvalue of \f$ A u = \lambda M u \f$, where `A` is the finite-element
matrix of the energy \f$ E_s \f$ (\f$ s = 0 \f$: Dirichlet energy of the
covariant derivative; \f$ s = 1 \f$: holomorphic; \f$ s = -1 \f$:
anti-holomorphic) and `M` is the mass matrix, both built with the Levi-Civita
connection of the mesh. See the \ref Chapter_SurfaceMeshDirectionFields "user manual".

Each connected component is solved on its own (its own eigenproblem).
A vertex without incident face receives the zero vector.

At each vertex `v`, `vertex_direction_map` receives one unit vector `d`,
orthogonal to the vertex normal; the field's other `n - 1` directions at `v`
are the rotations of `d` by \f$ 2\pi k / n \f$, `k = 1, ..., n-1`, about the
vertex normal.

With a guidance field (`principal_curvature_alignment` or `vertex_guidance_map`)
the field trades smoothness for alignment, controlled by `alignment_lambda` or
`alignment_weight`; with `vertex_is_constrained_map` or `boundary_alignment`
some directions are fixed. Both are linear solves instead of the eigenproblem.

A face `f` is singular when the field turns by a non-zero multiple of
\f$ 2\pi / n \f$ around it: its index is `k / n` for a non-zero integer `k`.
On a closed component the integers `k` add up to `n` times its Euler
characteristic (discrete Poincar&eacute;-Hopf theorem), whatever the mesh.

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
\tparam VertexDirectionMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key type and
        `GT::Vector_3` as value type
\tparam NamedParameters a sequence of <a href="https://doc.cgal.org/5.5.1/BGL/group__bgl__namedparameters.html">Named Parameters</a>

\param tmesh the input triangle mesh; it is not modified
\param vertex_direction_map the property map receiving a unit tangent direction per vertex
\param np an optional sequence of <a href="https://doc.cgal.org/5.5.1/BGL/group__bgl__namedparameters.html">Named Parameters</a> among the ones
       listed below; `GT` stands for the type of the object given to `geom_traits()`

\cgalNamedParamsBegin
  \cgalParamNBegin{degree}
    \cgalParamDescription{the degree `n` of the field: 1 for a vector (direction) field,
                          2 for a line field, 4 for a cross field; any `n` from 1 to
                          `maximum_degree` (one thousand, as in the program and the Python module)}
    \cgalParamType{`int`}
    \cgalParamDefault{`default_degree`, 4: a cross field}
  \cgalParamNEnd
  \cgalParamNBegin{smoothness_parameter}
    \cgalParamDescription{the energy parameter `s` in \f$ [-1, 1] \f$: `-1` anti-holomorphic,
                          `0` Dirichlet, `1` holomorphic energy; larger `s` gives fewer singularities}
    \cgalParamType{`double`}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{principal_curvature_alignment}
    \cgalParamDescription{aligns the field with the principal curvature directions: the guidance `q` is a line field
                          along the maximum curvature direction whose magnitude is the difference of the principal
                          curvatures (so that umbilic regions are left to smoothness), raised to the power `n/2`;
                          `MINIMUM` takes the orthogonal line field. For `n = 4` both values give the same crosses.
                          Requires an even `n`.}
    \cgalParamType{`CGAL::Surface_mesh_direction_fields::Principal_curvature_alignment`}
    \cgalParamDefault{`Principal_curvature_alignment::NONE`}
  \cgalParamNEnd
  \cgalParamNBegin{principal_curvature_estimate}
    \cgalParamDescription{how the principal curvature line field is estimated: a least-squares quadric fitted at each
                          vertex to its two-ring (`QUADRIC_FIT`: stays close to the surface's own directions on
                          irregular triangulations), or the paper's discrete Hopf differential from the dihedral angles
                          of the edges (`HOPF_DIFFERENTIAL`: noisy vertex by vertex on irregular triangulations, which
                          strong alignment turns into spurious singularities).}
    \cgalParamType{`CGAL::Surface_mesh_direction_fields::Principal_curvature_estimate`}
    \cgalParamDefault{`Principal_curvature_estimate::QUADRIC_FIT`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_guidance_map}
    \cgalParamDescription{a guidance vector per vertex, projected to the tangent plane; its length is its weight and
                          the zero vector means no preference. It is added to the curvature guidance if both are given.
                          Sparse guidance (a few strokes) is spread smoothly by the solve.}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `GT::Vector_3` as value type}
    \cgalParamDefault{no user guidance}
  \cgalParamNEnd
  \cgalParamNBegin{alignment_lambda}
     \cgalParamDescription{with a guidance `q` (\f$ \|q\|_M = 1 \f$), the field solves \f$ (A - \lambda_t M) u = M q \f$:
                           \f$ \lambda_t \to -\infty \f$ gives the guidance, \f$ \lambda_t \to \lambda_1 \f$ the
                           smoothest field; it must be below the component's smallest eigenvalue \f$ \lambda_1 \f$}
     \cgalParamType{`double`}
     \cgalParamDefault{`0`, as in the paper (just below \f$ \lambda_1 \f$ where \f$ \lambda_1 \f$ is about 0): one
                       factorization and one solve (user manual, section "Aligned and Constrained Fields")}
   \cgalParamNEnd
  \cgalParamNBegin{alignment_weight}
    \cgalParamDescription{instead of \f$ \lambda_t \f$: the alignment weight \f$ t = 1/(1 + \|u\|_M) \in (0, 1) \f$ to
                          reach (close to 1: follow the guidance; close to 0: be smooth); \f$ \lambda_t \f$ is found by
                          root finding (each step is one factorization), per component.}
    \cgalParamType{`double` in \f$ (0, 1) \f$}
    \cgalParamDefault{unused}
  \cgalParamNEnd
  \cgalParamNBegin{compute_eigenvalue_bound}
    \cgalParamDescription{whether the smallest eigenvalue \f$ \lambda_1 \f$ (the upper bound of \f$ \lambda_t \f$) is
                          computed for aligned and constrained fields too, where the field itself needs it only with
                          `alignment_weight` (or with a solver that cannot tell whether a matrix is positive definite).
                          When it is not computed, `Component_solve_report::eigenvalue` is empty.}
    \cgalParamType{`bool`}
    \cgalParamDefault{`false` (the smoothest field always computes it)}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_is_constrained_map}
    \cgalParamDescription{the vertices whose direction is prescribed by `vertex_constrained_direction_map` (hard
                          constraints); the other values are the smoothest (or aligned) ones given these}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `bool` as value type}
    \cgalParamDefault{no constrained vertex}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_constrained_direction_map}
    \cgalParamDescription{the prescribed direction of each constrained vertex (projected to the tangent plane; its
                          length does not matter); the output at that vertex is one of its `n` rotations}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `GT::Vector_3` as value type}
    \cgalParamDefault{none; required with `vertex_is_constrained_map`}
  \cgalParamNEnd
  \cgalParamNBegin{boundary_alignment}
    \cgalParamDescription{constrains every boundary vertex to a direction tangent (or normal) to the boundary: the
                          bisector of the two boundary edges (or of the interior angle)}
    \cgalParamType{`CGAL::Surface_mesh_direction_fields::Boundary_alignment`}
    \cgalParamDefault{`Boundary_alignment::NONE`}
  \cgalParamNEnd
  \cgalParamNBegin{edge_is_feature_map}
     \cgalParamDescription{sharp features: inside a feature polyline one of the `n` directions follows it (a hard
                           constraint); corners and the ends of open polylines stay free. Requires an even `n`;
                           `detect_feature_edges()` fills such a map at any scale of the coordinates}
     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
                    as key type and `bool` as value type}
     \cgalParamDefault{no feature}
   \cgalParamNEnd
  \cgalParamNBegin{prescribed_singularities}
     \cgalParamDescription{places the singularities: the faces listed get exactly the index `k / n` given, every other
                           face index 0; the field is the parallel section of the least changed connection, rotated to
                           follow a constrained vertex or the guidance (user manual, section "Placing Singularities",
                           which says what is refused)}
     \cgalParamType{a range of `std::pair<boost::graph_traits<TriangleMesh>::%face_descriptor, int>`, as
                    `singularities_output_iterator` writes them}
     \cgalParamDefault{none: the smoothest (or aligned) field, whose singularities the method places}
   \cgalParamNEnd
  \cgalParamNBegin{prescribed_loop_turns}
     \cgalParamDescription{with `prescribed_singularities`: pairs `(l, t)`, the field turns `t` more times (by
                           \f$ 2\pi / n \f$) than the nearest choice along loop `l` of
                           `Globally_optimal_direction_field::prescription_loops()` (what
                           `Direction_field_result::loop_turns` reports gives a field back)}
     \cgalParamType{a range of `std::pair<std::size_t, int>`}
     \cgalParamDefault{0 for every loop: the turning nearest to the surface's own}
   \cgalParamNEnd
  \cgalParamNBegin{singularities_output_iterator}
    \cgalParamDescription{an output iterator receiving, for each singular face, the pair of the
                          face and its integer index `k` (the field's index there is `k / n`)}
    \cgalParamType{a model of `OutputIterator` accepting
                   `std::pair<boost::graph_traits<TriangleMesh>::%face_descriptor, int>`}
    \cgalParamDefault{no output}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_magnitude_map}
    \cgalParamDescription{a property map receiving at each vertex the magnitude \f$ |u_i| \f$ of the
                          smoothest section, normalized so that its area-weighted mean square is 1 on each
                          component; small values mark where the field is least defined (near singularities)}
    \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `double` (or `GT::FT`) as value type}
    \cgalParamDefault{no output}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_coefficient_map}
    \cgalParamDescription{a property map receiving at each vertex the field's complex coefficient
                          \f$ u_i \f$ in the vertex's reference frame (user manual, section "Conventions"):
                          its length is the magnitude of `vertex_magnitude_map`, its argument \f$ n \f$ times
                          the rescaled angle of the first direction; these are the vectors on which the matrices
                          of `Globally_optimal_direction_field::energy_and_mass_matrices()` act; `0` at isolated
                          vertices}
    \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `std::complex<double>` as value type}
    \cgalParamDefault{no output}
  \cgalParamNEnd
  \cgalParamNBegin{intrinsic_mollification}
     \cgalParamDescription{the relative margin \f$ \delta \f$ of the intrinsic mollification (Sharp and Crane, 2020):
                           where a face violates \f$ \ell_a + \ell_b - \ell_c \ge \delta \bar\ell \f$, the smallest
                           length that restores it is added to every edge length (reported in
                           `Direction_field_result::mollification`); `0` switches it off}
     \cgalParamType{`double`}
     \cgalParamDefault{`1e-6`}
   \cgalParamNEnd
  \cgalParamNBegin{vertex_point_map}
    \cgalParamDescription{a property map associating points to the vertices of `tmesh`}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `GT::Point_3` as value type}
    \cgalParamDefault{`boost::get(CGAL::vertex_point, tmesh)`}
    \cgalParamExtra{If this parameter is omitted, an internal property map for `CGAL::vertex_point_t`
                    must be available in `TriangleMesh`.}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_normal_map}
     \cgalParamDescription{the vertex normals that define the tangent planes of the output directions (they also
                           tell folded triangles: user manual, section \ref SMDF_folds)}
     \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                    as key type and `GT::Vector_3` as value type}
     \cgalParamDefault{the angle-weighted mean of the incident face normals (the fitted surface's at folds)}
   \cgalParamNEnd
  \cgalParamNBegin{geom_traits}
    \cgalParamDescription{an instance of a geometric traits class}
    \cgalParamType{a class model of `DirectionFieldTraits_3` (every \cgal kernel is one)}
    \cgalParamDefault{a \cgal Kernel deduced from the point type, using `CGAL::Kernel_traits`}
  \cgalParamNEnd
  \cgalParamNBegin{vertex_index_map}
    \cgalParamDescription{a property map associating to each vertex of `tmesh` a unique index between `0` and
                          `num_vertices(tmesh) - 1`}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `std::size_t` as value type}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
  \cgalParamNBegin{face_index_map}
    \cgalParamDescription{a property map associating to each face of `tmesh` a unique index between `0` and
                          `num_faces(tmesh) - 1`}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
                   as key type and `std::size_t` as value type}
    \cgalParamDefault{an automatically indexed internal map}
  \cgalParamNEnd
  \cgalParamNBegin{number_of_iterations}
    \cgalParamDescription{the maximum number of inverse power iterations per component}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{`1000`}
  \cgalParamNEnd
  \cgalParamNBegin{residual_tolerance}
    \cgalParamDescription{the iteration stops when \f$ \|A u - \lambda M u\| \le \tau\, \sigma \|M u\| \f$,
                          with \f$ \sigma = \mathrm{tr}(A) / \mathrm{tr}(M) \f$ (a scale-invariant test)}
    \cgalParamType{`double`}
    \cgalParamDefault{`1e-10`}
  \cgalParamNEnd
  \cgalParamNBegin{random_seed}
    \cgalParamDescription{the seed of the start vector of the iteration; a seed gives the same field on
                          every run and platform}
    \cgalParamType{`unsigned int`}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{progress_callback}
    \cgalParamDescription{called on the calling thread with the fraction done (0 to 1, never decreasing) at
                          each step, before each solve of the iteration (whose share is estimated from the
                          residual's rate of decrease) and repeatedly during the default solver's
                          factorizations; returning `false` stops the computation with
                          `Computation_interrupted`, the output maps unchanged (a way to honour Ctrl-C)}
    \cgalParamType{a callable `bool(double)`}
    \cgalParamDefault{none}
  \cgalParamNEnd
  \cgalParamNBegin{sparse_linear_solver}
    \cgalParamDescription{the solver that factors the shifted energy matrix \f$ A - \sigma M \f$ once per
                          component and solves with it at each iteration (\f$ \sigma \f$ just below
                          \f$ \lambda_1 \f$ if the solver is one of Eigen's or CHOLMOD's Cholesky or
                          \f$ LDL^* \f$ factorizations, which show whether the matrix is positive definite;
                          else \f$ \sigma = -\epsilon \f$, a tiny negative shift)}
    \cgalParamType{a model of `SparseLinearAlgebraWithFactorTraits_d` with `std::complex<double>` as `NT`,
                   able to factor Hermitian positive definite matrices (both triangles are given)}
    \cgalParamDefault{`CGAL::Surface_mesh_direction_fields::Default_direction_field_solver`}
  \cgalParamNEnd
  \cgalParamNBegin{distributed_solver}
    \cgalParamDescription{spreads the components of at least its `minimum_distributed_vertices()` vertices over
                          the processes of its MPI communicator (user manual, section "Several Processes"); the
                          call is made on the first process, while the others run its `serve()`. Such a component's
                          eigen-solve and aligned or constrained solve factor nothing: a given
                          `alignment_lambda` is then checked against \f$ \lambda_1 \f$, which is computed}
    \cgalParamType{`CGAL::Surface_mesh_direction_fields::Petsc_distributed_solver` (or another model of its
                   internal interface)}
    \cgalParamDefault{none: every component is solved by `sparse_linear_solver` in this process}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a `Direction_field_result`: per component, the smallest eigenvalue, the iterations used,
the final residual, the Euler characteristic and the index sum, and for aligned or constrained fields
the \f$ \lambda_t \f$ used and the alignment weight reached; and the timings.

\throws Invalid_input_error if `tmesh` is empty, has a non-triangle face, a non-manifold vertex or a
        non-finite coordinate, has more than 715,827,882 faces or 2,147,483,646 vertices (indices are stored in
        32 bits), a zero-area face while `intrinsic_mollification` is `0`, a component all of whose faces
        have zero area (its points on a line), if `n < 1`, if
        `s` is outside \f$ [-1, 1] \f$, for curvature alignment with an odd `n`, if
        \f$ \lambda_t \ge \lambda_1 \f$, if `t` is not in \f$ (0, 1) \f$ or given without guidance, if both
        \f$ \lambda_t \f$ and `t` are given, if a guidance vector is not finite, or if a constrained direction
        is zero or normal to the surface, and for the prescriptions `prescribed_singularities` refuses.
        Nothing is written to the output maps then.
\throws Solver_failure_error if the sparse solver fails to factor the shifted energy matrix.

\pre `CGAL::is_triangle_mesh(tmesh)` (checked, see above)

\warning All linear algebra is done in `double`, also with an exact kernel: coordinates are
         converted once, and the output vectors are built from doubles.
*/
#ifndef DOXYGEN_RUNNING
inline namespace CGAL_SURFACE_MESH_DIRECTION_FIELDS_DEFAULT_SOLVER_NAMESPACE {  // see Default_direction_field_solver
#endif
template <typename TriangleMesh, typename VertexDirectionMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Direction_field_result
compute_globally_optimal_directions(const TriangleMesh& tmesh,
                                    VertexDirectionMap vertex_direction_map,
                                    const CGAL_NP_CLASS& np = parameters::default_values())
{
  typedef typename GetGeomTraits<TriangleMesh, CGAL_NP_CLASS>::type Geom_traits;
  typedef typename GetSolver<CGAL_NP_CLASS, Default_direction_field_solver>::type Sparse_solver;
  // Check n and s before any work on the mesh.
  using parameters::choose_parameter;
  using parameters::get_parameter;
  internal::check_field_parameters(choose_parameter(get_parameter(np, internal_np::degree), default_degree),
                                   choose_parameter(get_parameter(np, internal_np::smoothness_parameter), 0.));
  Globally_optimal_direction_field<TriangleMesh, Geom_traits, Sparse_solver> field(tmesh, np);
  field.keep_factorizations(false);  // a single use: free each factorization once its component is done
  Direction_field_result result = field.compute(vertex_direction_map, np);
  result.timings.setup_ms += field.construction_ms();
  result.timings.total_ms += field.construction_ms();
  return result;
}
#ifndef DOXYGEN_RUNNING
} // inline namespace CGAL_SURFACE_MESH_DIRECTION_FIELDS_DEFAULT_SOLVER_NAMESPACE
#endif

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_DIRECTIONS_H
