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

#include <CGAL/Named_function_parameters.h>
#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_NAMED_PARAMETERS_DECLARED
#  error "The include directory of Surface_mesh_direction_fields must come before CGAL's include directory (see the README)."
#endif

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/alignment.h>
#include <CGAL/Surface_mesh_direction_fields/internal/aligned_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/assembly.h>
#include <CGAL/Surface_mesh_direction_fields/internal/guidance.h>
#include <CGAL/Surface_mesh_direction_fields/internal/extrinsic_directions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/inverse_iteration.h>
#include <CGAL/Surface_mesh_direction_fields/internal/singularities.h>
#include <CGAL/Surface_mesh_direction_fields/internal/tangent_spaces.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/iterator.h>

#include <Eigen/SparseCholesky>
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <chrono>
#include <cmath>
#include <complex>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

The default model of `SparseLinearAlgebraWithFactorTraits_d` used by
`compute_globally_optimal_directions()`: Eigen's simplicial \f$ LDL^\top \f$
factorization of complex Hermitian matrices; or, when the macro
`CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD` is defined (the CMake target
does it when CHOLMOD is found; the program must then link `libcholmod`), CHOLMOD's
supernodal Cholesky factorization through Eigen's `CholmodSupernodalLLT`, about
four times faster on large meshes with an optimized BLAS (OpenBLAS).
*/
#if defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD) && !defined(DOXYGEN_RUNNING)
typedef CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<std::complex<double> > > >
  Default_direction_field_solver;
#else
typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<std::complex<double> > > >
  Default_direction_field_solver;
#endif

namespace internal {

template <typename GeomTraits>
struct Point_to_array
{
  GeomTraits gt;
  template <typename Point>
  Vec3 operator()(const Point& p) const
  {
    return Vec3{CGAL::to_double(gt.compute_x_3_object()(p)),
                CGAL::to_double(gt.compute_y_3_object()(p)),
                CGAL::to_double(gt.compute_z_3_object()(p))};
  }
};

inline void check_field_parameters(int degree, double s)
{
  if(degree < 1)
    throw Invalid_input_error("the degree n must be at least 1 (got " + std::to_string(degree) + ")");
  if(!(s >= -1. && s <= 1.))
    throw Invalid_input_error("the smoothness parameter s must lie in [-1, 1] (got " + std::to_string(s) + ")");
}

// Euler characteristic of a component: V - E + F with E = (3F + B) / 2, where B
// counts the boundary edges, equal to the number of boundary vertices on a
// manifold mesh (each boundary loop has as many vertices as edges).
inline void describe_component(const Indexed_mesh& m, const Component& comp, Component_report& report)
{
  std::size_t border_vertices = 0;
  for(std::size_t v : comp.vertices)
    border_vertices += m.is_border_vertex[v];
  const long V = static_cast<long>(comp.vertices.size());
  const long F = static_cast<long>(comp.faces.size());
  const long E = (3 * F + static_cast<long>(border_vertices)) / 2;
  report.number_of_vertices = comp.vertices.size();
  report.number_of_faces = comp.faces.size();
  report.euler_characteristic = static_cast<int>(V - E + F);
  report.is_closed = (border_vertices == 0);
}


// The guidance field q (n-th power coefficients per vertex), from the
// principal curvatures and/or a user vector field; empty if there is none.
template <typename TriangleMesh, typename NamedParameters, typename VertexIndexMap, typename SparseSolver,
          typename ToArray>
std::vector<std::complex<double> >
guidance_coefficients(const Indexed_mesh& mesh, const Tangent_spaces& ts, const Components& components,
                      const NamedParameters& np, VertexIndexMap vim, const std::vector<Vec3>& normals, int degree,
                      SparseSolver& solver, const ToArray& to_array, const TriangleMesh& tmesh)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  typedef std::complex<double> Complex;
  std::vector<Complex> q;
  const Principal_curvature_alignment curvature =
    choose_parameter(get_parameter(np, internal_np::principal_curvature_alignment), Principal_curvature_alignment::NONE);
  if(curvature != Principal_curvature_alignment::NONE)
  {
    if(degree % 2 != 0)
      throw Invalid_input_error("curvature alignment needs an even degree n (got " + std::to_string(degree) + ")");
    // The Hopf differential is a line field (n = 2): its coefficients solve
    // M_2 q = q~ with the mass matrix of the degree-2 connection.
    const std::vector<Complex> pairing = hopf_differential_pairing(mesh, ts);
    const Connection line_connection = compute_connection(mesh, ts, 2);
    q.assign(mesh.number_of_vertices(), Complex(0., 0.));
    for(const Component& comp : components.list)
    {
      const Energy_and_mass em = assemble_energy_and_mass(mesh, ts, line_connection, comp, components.local_index, 0.);
      Complex_vector rhs(static_cast<Eigen::Index>(comp.vertices.size()));
      for(std::size_t i = 0; i < comp.vertices.size(); ++i) rhs[static_cast<Eigen::Index>(i)] = pairing[comp.vertices[i]];
      const Complex_vector line = solve_aligned_system(em.mass, em.mass, 0., rhs, Constraints(), solver);
      for(std::size_t i = 0; i < comp.vertices.size(); ++i)
      {
        Complex w = line[static_cast<Eigen::Index>(i)];
        if(curvature == Principal_curvature_alignment::MINIMUM) w = -w;  // the orthogonal line field
        q[comp.vertices[i]] = std::pow(w, degree / 2);
      }
    }
  }
  if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_guidance_map_t>::value)
  {
    const auto guidance_map = get_parameter(np, internal_np::vertex_guidance_map);
    if(q.empty()) q.assign(mesh.number_of_vertices(), Complex(0., 0.));
    for(auto v : vertices(tmesh))
    {
      const std::size_t i = static_cast<std::size_t>(get(vim, v));
      const Vec3 g = to_array(get(guidance_map, v));
      if(!std::isfinite(g[0]) || !std::isfinite(g[1]) || !std::isfinite(g[2]))
        throw Invalid_input_error("the guidance vector of vertex " + std::to_string(i) + " is not finite");
      q[i] += tangent_coefficient(mesh, ts, i, g, degree, normals[i]);
    }
  }
  return q;
}

struct Vertex_constraints
{
  std::vector<unsigned char> is_constrained;        // per vertex; empty: no constraint
  std::vector<std::complex<double> > values;        // unit coefficients where constrained
};

// Hard constraints: boundary alignment and/or vertex_is_constrained_map with
// vertex_constrained_direction_map (the latter win where both apply).
template <typename TriangleMesh, typename NamedParameters, typename VertexIndexMap, typename ToArray>
Vertex_constraints vertex_constraints(const Indexed_mesh& mesh, const Tangent_spaces& ts, const NamedParameters& np,
                                      VertexIndexMap vim, const std::vector<Vec3>& normals, int degree,
                                      const ToArray& to_array, const TriangleMesh& tmesh)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  Vertex_constraints vc;
  const Boundary_alignment boundary =
    choose_parameter(get_parameter(np, internal_np::boundary_alignment), Boundary_alignment::NONE);
  constexpr bool has_map = !is_default_parameter<NamedParameters, internal_np::vertex_is_constrained_t>::value;
  if(boundary == Boundary_alignment::NONE && !has_map)
    return vc;
  vc.is_constrained.assign(mesh.number_of_vertices(), 0);
  vc.values.assign(mesh.number_of_vertices(), std::complex<double>(0., 0.));
  if(boundary != Boundary_alignment::NONE)
    for(std::size_t v = 0; v < mesh.number_of_vertices(); ++v)
      if(mesh.is_border_vertex[v])
      {
        vc.is_constrained[v] = 1;
        vc.values[v] = boundary_coefficient(mesh, ts, v, degree, boundary == Boundary_alignment::NORMAL);
      }
  if constexpr(has_map)
  {
    if constexpr(is_default_parameter<NamedParameters, internal_np::vertex_constrained_direction_map_t>::value)
      throw Invalid_input_error("vertex_is_constrained_map needs vertex_constrained_direction_map");
    else
    {
      const auto is_constrained = get_parameter(np, internal_np::vertex_is_constrained);
      const auto directions = get_parameter(np, internal_np::vertex_constrained_direction_map);
      for(auto v : vertices(tmesh))
      {
        const std::size_t i = static_cast<std::size_t>(get(vim, v));
        if(!get(is_constrained, v) || mesh.fan_size(i) == 0) continue;
        const std::complex<double> c = tangent_coefficient(mesh, ts, i, to_array(get(directions, v)), degree, normals[i]);
        if(!(std::abs(c) > 0.) || !std::isfinite(std::abs(c)))
          throw Invalid_input_error("the prescribed direction of constrained vertex " + std::to_string(i) +
                                    " is zero, normal to the surface or not finite");
        vc.is_constrained[i] = 1;
        vc.values[i] = c / std::abs(c);
      }
    }
  }
  return vc;
}

} // namespace internal

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
                          2 for a line field, 4 for a cross field; any `n >= 1`}
    \cgalParamType{`int`}
    \cgalParamDefault{`1`}
  \cgalParamNEnd
  \cgalParamNBegin{smoothness_parameter}
    \cgalParamDescription{the energy parameter `s` in \f$ [-1, 1] \f$: `-1` anti-holomorphic,
                          `0` Dirichlet, `1` holomorphic energy; larger `s` gives fewer singularities}
    \cgalParamType{`double`}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{principal_curvature_alignment}
    \cgalParamDescription{aligns the field with the principal curvature directions: the guidance `q` is the discrete
                          Hopf differential (a line field along the maximum curvature direction, whose magnitude is
                          the difference of the principal curvatures, so that umbilic regions are left to smoothness),
                          raised to the power `n/2`; `MINIMUM` takes the orthogonal line field. For `n = 4` both
                          values give the same crosses. Requires an even `n`.}
    \cgalParamType{`CGAL::Surface_mesh_direction_fields::Principal_curvature_alignment`}
    \cgalParamDefault{`Principal_curvature_alignment::NONE`}
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
    \cgalParamDescription{with a guidance `q` (normalized to \f$ \|q\|_M = 1 \f$), the field is the solution of
                          \f$ (A - \lambda_t M) u = M q \f$, normalized. \f$ \lambda_t \to -\infty \f$ gives the
                          guidance itself, \f$ \lambda_t \to \lambda_1 \f$ the smoothest field; it must be below
                          the smallest eigenvalue \f$ \lambda_1 \f$ of the component. With constraints and no guidance,
                          the value used for \f$ (A - \lambda_t M)_{FF} \f$.}
    \cgalParamType{`double`}
    \cgalParamDefault{`0`, as in the paper (or just below \f$ \lambda_1 \f$ if \f$ \lambda_1 \f$ is about 0, as on
                      flat and developable surfaces)}
  \cgalParamNEnd
  \cgalParamNBegin{alignment_weight}
    \cgalParamDescription{instead of \f$ \lambda_t \f$: the alignment weight \f$ t = 1/(1 + \|u\|_M) \in (0, 1) \f$ to
                          reach (close to 1: follow the guidance; close to 0: be smooth); \f$ \lambda_t \f$ is found by
                          root finding (each step is one factorization), per component.}
    \cgalParamType{`double` in \f$ (0, 1) \f$}
    \cgalParamDefault{unused}
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
  \cgalParamNBegin{intrinsic_mollification}
    \cgalParamDescription{the relative margin \f$ \delta \f$ of the intrinsic mollification of degenerate
                          triangles: if some face violates \f$ \ell_a + \ell_b - \ell_c \ge \delta \bar\ell \f$
                          (\f$ \bar\ell \f$ the mean edge length), the smallest length that restores it everywhere
                          is added to every edge length, and the computation uses these lengths (Sharp and Crane,
                          2020). Faces with zero area, coincident vertices or collinear vertices then get finite
                          matrices. A mesh with no such face is not changed at all. `0` switches it off; zero-area
                          faces are then rejected.}
    \cgalParamType{`double`}
    \cgalParamDefault{`1e-6`}
    \cgalParamExtra{The length added is reported in `Direction_field_result::mollification`.}
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
    \cgalParamDescription{a property map giving the vertex normals that define the tangent planes of the
                          output directions}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and `GT::Vector_3` as value type}
    \cgalParamDefault{the angle-weighted mean of the incident face normals}
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
  \cgalParamNBegin{sparse_linear_solver}
    \cgalParamDescription{the solver that factors the shifted energy matrix \f$ A + \epsilon M \f$ once per
                          component and solves with it at each iteration}
    \cgalParamType{a model of `SparseLinearAlgebraWithFactorTraits_d` with `std::complex<double>` as `NT`,
                   able to factor Hermitian positive definite matrices (both triangles are given)}
    \cgalParamDefault{`CGAL::Surface_mesh_direction_fields::Default_direction_field_solver`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a `Direction_field_result`: per component, the smallest eigenvalue, the iterations used,
the final residual, the Euler characteristic and the index sum, and for aligned or constrained fields
the \f$ \lambda_t \f$ used and the alignment weight reached; and the timings.

\throws Invalid_input_error if `tmesh` is empty, has a non-triangle face, a non-manifold vertex or a
        non-finite coordinate, a zero-area face while `intrinsic_mollification` is `0`, if `n < 1`, if
        `s` is outside \f$ [-1, 1] \f$, for curvature alignment with an odd `n`, if
        \f$ \lambda_t \ge \lambda_1 \f$, if `t` is not in \f$ (0, 1) \f$ or given without guidance, if both
        \f$ \lambda_t \f$ and `t` are given, if a guidance vector is not finite, or if a constrained direction
        is zero or normal to the surface.
        Nothing is written to the output maps then.
\throws Solver_failure_error if the sparse solver fails to factor the shifted energy matrix.

\pre `CGAL::is_triangle_mesh(tmesh)` (checked, see above)

\warning All linear algebra is done in `double`, also with an exact kernel: coordinates are
         converted once, and the output vectors are built from doubles.
*/
template <typename TriangleMesh, typename VertexDirectionMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Direction_field_result
compute_globally_optimal_directions(const TriangleMesh& tmesh,
                                    VertexDirectionMap vertex_direction_map,
                                    const CGAL_NP_CLASS& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  typedef std::chrono::steady_clock Clock;
  typedef std::complex<double> Complex;

  typedef typename GetGeomTraits<TriangleMesh, CGAL_NP_CLASS>::type Geom_traits;
  typedef typename GetVertexPointMap<TriangleMesh, CGAL_NP_CLASS>::const_type Vertex_point_map;
  typedef typename GetSolver<CGAL_NP_CLASS, Default_direction_field_solver>::type Sparse_solver;
  typedef typename Geom_traits::FT FT;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  const auto start = Clock::now();
  Direction_field_result result;
  result.degree = choose_parameter(get_parameter(np, internal_np::degree), 1);
  result.smoothness_parameter = choose_parameter(get_parameter(np, internal_np::smoothness_parameter), 0.);
  internal::check_field_parameters(result.degree, result.smoothness_parameter);

  const Geom_traits gt = choose_parameter<Geom_traits>(get_parameter(np, internal_np::geom_traits));
  const Vertex_point_map vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                                get_const_property_map(CGAL::vertex_point, tmesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(tmesh, np);
  const auto fim = CGAL::get_initialized_face_index_map(tmesh, np);
  Sparse_solver solver = choose_parameter<Sparse_solver>(get_parameter(np, internal_np::sparse_linear_solver));

  internal::Eigen_solve_options options;
  options.max_iterations = choose_parameter(get_parameter(np, internal_np::number_of_iterations), 1000u);
  options.residual_tolerance = choose_parameter(get_parameter(np, internal_np::residual_tolerance), 1e-10);
  options.random_seed = choose_parameter(get_parameter(np, internal_np::random_seed), 0u);
  if(!(options.residual_tolerance >= 0.))
    throw Invalid_input_error("the residual tolerance must be non-negative");
  const double mollification = choose_parameter(get_parameter(np, internal_np::intrinsic_mollification), 1e-6);
  if(!(mollification >= 0.) || !std::isfinite(mollification))
    throw Invalid_input_error("the intrinsic mollification must be a non-negative number");

  // --- setup: mesh plumbing, tangent spaces, connection, matrices
  const internal::Point_to_array<Geom_traits> to_array{gt};
  const internal::Indexed_mesh mesh = internal::make_indexed_mesh(
    tmesh, [&](vertex_descriptor v) { return to_array(get(vpm, v)); }, vim, fim);
  const internal::Tangent_spaces ts = internal::compute_tangent_spaces(mesh, mollification);
  result.mollification = ts.mollification;
  const internal::Connection connection = internal::compute_connection(mesh, ts, result.degree);
  const internal::Components components = internal::split_into_components(mesh);

  std::vector<internal::Energy_and_mass> matrices;
  matrices.reserve(components.list.size());
  for(const internal::Component& comp : components.list)
    matrices.push_back(internal::assemble_energy_and_mass(mesh, ts, connection, comp, components.local_index,
                                                          result.smoothness_parameter));
  const auto setup_end = Clock::now();
  result.timings.setup_ms = std::chrono::duration<double, std::milli>(setup_end - start).count();

  // --- vertex normals: the tangent planes of the outputs and of the guidance vectors
  std::vector<internal::Vec3> normals;
  if constexpr(is_default_parameter<CGAL_NP_CLASS, internal_np::vertex_normal_map_t>::value)
    normals = internal::angle_weighted_vertex_normals(mesh, ts);
  else
  {
    const auto vnm = get_parameter(np, internal_np::vertex_normal_map);
    normals.resize(mesh.number_of_vertices());
    for(vertex_descriptor v : vertices(tmesh))
      normals[static_cast<std::size_t>(get(vim, v))] = internal::normalized(to_array(get(vnm, v)));
  }

  // --- guidance field q and hard constraints (method.md, section 6)
  const std::vector<Complex> guidance =
    internal::guidance_coefficients(mesh, ts, components, np, vim, normals, result.degree, solver, to_array, tmesh);
  const bool has_guidance = !guidance.empty();
  const internal::Vertex_constraints constraints =
    internal::vertex_constraints(mesh, ts, np, vim, normals, result.degree, to_array, tmesh);
  const bool lambda_given = !is_default_parameter<CGAL_NP_CLASS, internal_np::alignment_lambda_t>::value;
  const bool weight_given = !is_default_parameter<CGAL_NP_CLASS, internal_np::alignment_weight_t>::value;
  const double lambda_requested = choose_parameter(get_parameter(np, internal_np::alignment_lambda), 0.);
  const double weight_requested = choose_parameter(get_parameter(np, internal_np::alignment_weight), 0.5);
  if(lambda_given && weight_given)
    throw Invalid_input_error("give either alignment_lambda or alignment_weight, not both");
  if(lambda_given && !std::isfinite(lambda_requested))
    throw Invalid_input_error("alignment_lambda must be a finite number");
  if(weight_given && !(weight_requested > 0. && weight_requested < 1.))
    throw Invalid_input_error("alignment_weight must lie in (0, 1) (got " + std::to_string(weight_requested) + ")");
  if(weight_given && !has_guidance)
    throw Invalid_input_error("alignment_weight needs a guidance field (vertex_guidance_map or principal_curvature_alignment)");

  // --- one problem per component: the smallest eigenvector, or the aligned /
  //     constrained linear solve
  std::vector<Complex> u(mesh.number_of_vertices(), Complex(0., 0.));
  std::vector<double> magnitude(mesh.number_of_vertices(), 0.);
  result.components.resize(components.list.size());
  for(std::size_t c = 0; c < components.list.size(); ++c)
  {
    const internal::Component& comp = components.list[c];
    const Eigen::Index nc = static_cast<Eigen::Index>(comp.vertices.size());
    Component_report& report = result.components[c];
    internal::describe_component(mesh, comp, report);
    const internal::Complex_sparse_matrix& A = matrices[c].energy;
    const internal::Complex_sparse_matrix& M = matrices[c].mass;

    // this component's guidance, normalized to ||q||_M = 1 (none if it vanishes here)
    internal::Complex_vector q = internal::Complex_vector::Zero(nc);
    for(Eigen::Index i = 0; i < nc; ++i)
      if(has_guidance) q[i] = guidance[comp.vertices[static_cast<std::size_t>(i)]];
    const double q_norm = internal::m_norm(M, q);
    const bool aligned = has_guidance && q_norm > 0.;
    if(aligned) q /= q_norm;
    internal::Constraints local_constraints;
    bool constrained = false;
    if(!constraints.is_constrained.empty())
    {
      local_constraints.is_constrained.resize(comp.vertices.size());
      local_constraints.values.resize(nc);
      for(Eigen::Index i = 0; i < nc; ++i)
      {
        const std::size_t v = comp.vertices[static_cast<std::size_t>(i)];
        local_constraints.is_constrained[static_cast<std::size_t>(i)] = constraints.is_constrained[v];
        local_constraints.values[i] = constraints.values[v];
        constrained = constrained || constraints.is_constrained[v];
      }
    }

    internal::Complex_vector field;
    const bool needs_eigenvalue = !constrained || aligned;  // lambda_1: the smoothest field, or the bound of lambda_t
    if(needs_eigenvalue)
    {
      const internal::Eigen_solve_result eig = internal::smallest_eigenpair(A, M, solver, options);
      report.eigenvalue = eig.eigenvalue;
      report.iterations = eig.iterations;
      report.residual = eig.residual;
      report.converged = eig.converged;
      result.timings.factorization_ms += eig.factorization_ms;
      field = eig.vector;
    }
    if(aligned || constrained)
    {
      const internal::Complex_vector Mq = M * q;
      const double sigma = A.diagonal().real().sum() / M.diagonal().real().sum();
      // The default lambda_t is 0, as in the paper, unless lambda_1 is (nearly) 0
      // (a flat or developable component), where 0 is not admissible.
      double lambda = lambda_requested;
      if(aligned && !lambda_given)
        lambda = (std::min)(0., report.eigenvalue - 1e-6 * sigma);
      if(aligned && weight_given)
      {
        std::size_t evaluations = 0;
        lambda = internal::find_lambda_for_weight(A, M, Mq, local_constraints, report.eigenvalue, weight_requested,
                                                  sigma, solver, field, evaluations);
        report.iterations += evaluations;
      }
      else
      {
        if(aligned && !(lambda < report.eigenvalue))
          throw Invalid_input_error("alignment_lambda must be below the smallest eigenvalue lambda_1 = " +
                                    std::to_string(report.eigenvalue) + " of component " + std::to_string(c) +
                                    " (got " + std::to_string(lambda) + ")");
        field = internal::solve_aligned_system(A, M, lambda, Mq, local_constraints, solver);
      }
      report.lambda = lambda;
      report.alignment_weight = aligned ? internal::alignment_weight_of(M, field) : 0.;
      const double field_norm = internal::m_norm(M, field);
      if(field_norm > 0.) field /= field_norm;
    }

    double area = 0.;
    for(std::size_t f : comp.faces) area += ts.face_area[f];
    for(std::size_t i = 0; i < comp.vertices.size(); ++i)
    {
      u[comp.vertices[i]] = field[static_cast<Eigen::Index>(i)];
      magnitude[comp.vertices[i]] = std::abs(field[static_cast<Eigen::Index>(i)]) * std::sqrt(area);
    }
    result.iterations = (std::max)(result.iterations, report.iterations);
    result.residual = (std::max)(result.residual, report.residual);
    result.converged = result.converged && report.converged;
  }

  // --- singularities
  const std::vector<int> index = internal::face_indices(mesh, connection, u);
  std::vector<face_descriptor> face_of_index(mesh.number_of_faces());
  for(face_descriptor f : faces(tmesh))
    face_of_index[static_cast<std::size_t>(get(fim, f))] = f;
  auto singularities_out = choose_parameter(get_parameter(np, internal_np::singularities_output_iterator),
                                            CGAL::Emptyset_iterator());
  for(std::size_t f = 0; f < mesh.number_of_faces(); ++f)
  {
    Component_report& report = result.components[mesh.component_of_face[f]];
    report.index_sum += index[f];
    result.index_sum += index[f];
    if(index[f] != 0)
    {
      ++report.number_of_singular_faces;
      ++result.number_of_singular_faces;
      *singularities_out++ = std::make_pair(face_of_index[f], index[f]);
    }
  }

  // --- directions in 3D
  auto construct_vector = gt.construct_vector_3_object();
  for(vertex_descriptor v : vertices(tmesh))
  {
    const std::size_t i = static_cast<std::size_t>(get(vim, v));
    const internal::Vec3 d = internal::tangent_direction(mesh, ts, i, u[i], result.degree, normals[i]);
    put(vertex_direction_map, v, construct_vector(FT(d[0]), FT(d[1]), FT(d[2])));
    if(mesh.fan_size(i) == 0)
      ++result.number_of_isolated_vertices;
  }
  if constexpr(!is_default_parameter<CGAL_NP_CLASS, internal_np::vertex_magnitude_map_t>::value)
  {
    auto vmm = get_parameter(np, internal_np::vertex_magnitude_map);
    for(vertex_descriptor v : vertices(tmesh))
      put(vmm, v, magnitude[static_cast<std::size_t>(get(vim, v))]);
  }

  const auto end = Clock::now();
  result.timings.total_ms = std::chrono::duration<double, std::milli>(end - start).count();
  result.timings.solve_ms = result.timings.total_ms - result.timings.setup_ms - result.timings.factorization_ms;
  return result;
}

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_DIRECTIONS_H
