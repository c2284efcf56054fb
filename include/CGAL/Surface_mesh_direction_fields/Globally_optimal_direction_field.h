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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_DIRECTION_FIELD_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_DIRECTION_FIELD_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Named_function_parameters.h>
#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_NAMED_PARAMETERS_DECLARED
#  error "The include directory of Surface_mesh_direction_fields must come before CGAL's include directory (see the README)."
#endif

#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/alignment.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
// the mesh plumbing: flat arrays, the named parameters read into index-based requests
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/named_inputs.h>
// the method and the linear algebra behind one seam (Field_engine.h)
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/Field_engine.h>
#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/Field_engine_impl.h>
#endif

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/iterator.h>

#if defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD)
#  ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION
#    include <CGAL/Surface_mesh_direction_fields/Cholmod_supernodal_solver.h>
#  endif
#else
#  include <CGAL/Eigen_solver_traits.h>
#  include <Eigen/SparseCholesky>
#endif

#include <Eigen/SparseCore>

#include <chrono>
#include <complex>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

The default model of `SparseLinearAlgebraWithFactorTraits_d` used by
`compute_globally_optimal_directions()` and `Globally_optimal_direction_field`:
Eigen's simplicial \f$ LDL^\top \f$ factorization of complex Hermitian
matrices; or, when the macro `CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD`
is defined (the CMake target does it when CHOLMOD is found; the program must
then link `libcholmod`, and the BLAS and LAPACK for the package's own
numerical factorization), `Cholmod_supernodal_solver`: a supernodal Cholesky
factorization on CHOLMOD's analysis, several times faster on large meshes with
an optimized BLAS (OpenBLAS).

With `CGAL::Eigen_solver_traits`, the package hands its Eigen matrices to the
Eigen solver directly (no copy) and reuses the symbolic analysis when a
matrix with the same sparsity pattern is factored again. Any other model of
`SparseLinearAlgebraWithFactorTraits_d` with `std::complex<double>` as `NT` works
too, through a copy of each matrix.
*/
/// \cond SKIP_IN_MANUAL
// What depends on the default solver (the free function) lives in an inline
// namespace named after it: two files of one program built with and without
// CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD then get two distinct
// functions, each with its own default, instead of one silently replacing
// the other at link time (test_default_solvers).
#if defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD)
#  define CGAL_SURFACE_MESH_DIRECTION_FIELDS_DEFAULT_SOLVER_NAMESPACE default_solver_cholmod
#else
#  define CGAL_SURFACE_MESH_DIRECTION_FIELDS_DEFAULT_SOLVER_NAMESPACE default_solver_eigen
#endif
/// \endcond
#if defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD) && !defined(DOXYGEN_RUNNING)
class Cholmod_supernodal_solver;
typedef Cholmod_supernodal_solver Default_direction_field_solver;
#else
typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<Eigen::SparseMatrix<std::complex<double> > > >
  Default_direction_field_solver;
#endif

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

\brief computes globally optimal direction fields on one triangle mesh,
repeatedly, without redoing the work that does not change.

Construction does the mesh work once: the indexing, the intrinsic geometry
(edge lengths, angles, the rescaled tangent spaces), the connected components
and the vertex normals. Each call of `compute()` then computes one field, with
the same named parameters and results as
`compute_globally_optimal_directions()` (which is this class used once). Between
calls the class keeps:
- the connection of the last degree `n` and the matrices of the last pair `(n, s)`,
  so that several guidance fields, \f$ \lambda_t \f$ or alignment weights for
  the same `n` and `s` cost no assembly and no eigen-solve of their own beyond
  the eigenvalue bound, which is also kept;
- with the default solver or `CGAL::Eigen_solver_traits`, one solver per component whose
  symbolic analysis (fill-reducing ordering) is reused for every later
  factorization of that component: the pattern of \f$ A - \sigma M \f$ does not
  depend on `n` or `s`. This memory (one Cholesky factor per component) is
  held until the object is destroyed.

The mesh must not change while the object is alive.

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
\tparam GeomTraits a model of `DirectionFieldTraits_3`; by default the kernel of the mesh's point type
\tparam SparseSolver a model of `SparseLinearAlgebraWithFactorTraits_d` with `std::complex<double>` as `NT`

\sa `compute_globally_optimal_directions()`
*/
template <typename TriangleMesh,
          typename GeomTraits = typename GetGeomTraits<TriangleMesh>::type,
          typename SparseSolver = Default_direction_field_solver>
class Globally_optimal_direction_field
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  typedef std::chrono::steady_clock Clock;
  typedef internal::Field_engine<SparseSolver> Engine;

public:
  /// \name Creation
  /// @{

  /*!
  does the mesh work: indexing, intrinsic geometry, components, vertex normals.

  \param tmesh the triangle mesh; it is not modified, and must outlive the object unchanged
  \param np an optional sequence of named parameters among `vertex_point_map`, `vertex_index_map`,
         `face_index_map`, `geom_traits`, `vertex_normal_map` and `intrinsic_mollification`, with the
         meaning and defaults given for `compute_globally_optimal_directions()`

  \tparam NamedParameters a sequence of named parameters
  \throws Invalid_input_error for an empty mesh, a non-triangle face, a non-manifold vertex, a non-finite
          coordinate, a zero-area face while `intrinsic_mollification` is `0`, a component all of whose
          faces have zero area (its points on a line), or a mesh too large for 32-bit indices (see
          `compute_globally_optimal_directions()`)
  */
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Globally_optimal_direction_field(const TriangleMesh& tmesh,
                                            const NamedParameters& np = parameters::default_values())
  {
    using parameters::get_parameter;
    using parameters::is_default_parameter;
    const auto start = Clock::now();
    internal::Indexed_mesh mesh = m_indexing.index(tmesh, np);
    const internal::Point_to_array<GeomTraits> to_array{m_indexing.traits};
    std::vector<internal::Vec3> normals;  // empty: the angle-weighted normals
    if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_normal_map_t>::value)
    {
      const auto vnm = get_parameter(np, internal_np::vertex_normal_map);
      normals.resize(m_indexing.vertex_of_index.size());
      for(std::size_t i = 0; i < m_indexing.vertex_of_index.size(); ++i)
        normals[i] = internal::normalized(to_array(get(vnm, m_indexing.vertex_of_index[i])));
    }
    m_engine = std::make_unique<Engine>(std::move(mesh), m_indexing.mollification, std::move(normals));
    m_construction_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  }

  /// @}

  /// \name Operations
  /// @{

  /*!
  computes one field, exactly as `compute_globally_optimal_directions(tmesh, vertex_direction_map, np)`
  would, reusing what earlier calls computed (see the class description).
  The named parameters are those of `compute_globally_optimal_directions()` except the ones of the
  constructor (which are ignored here). In the result, `timings.setup_ms` counts the work of this
  call only (connection and matrices, when `n` or `s` changed), not the construction.

  \tparam VertexDirectionMap as for `compute_globally_optimal_directions()`
  \tparam NamedParameters a sequence of named parameters
  \param vertex_direction_map the property map receiving a unit tangent direction per vertex
  \param np the named parameters of the field (see `compute_globally_optimal_directions()`)
  \returns the report of this field, as `compute_globally_optimal_directions()` returns it
  \throws Invalid_input_error, Solver_failure_error as `compute_globally_optimal_directions()`
  */
  template <typename VertexDirectionMap, typename NamedParameters = parameters::Default_named_parameters>
  Direction_field_result compute(VertexDirectionMap vertex_direction_map,
                                 const NamedParameters& np = parameters::default_values())
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    using parameters::is_default_parameter;
    const auto start = Clock::now();
    internal::Field_request request;
    internal::read_field_parameters(np, request);
    const internal::Point_to_array<GeomTraits> to_array{m_indexing.traits};
    internal::read_guidance_request(np, m_indexing.vertex_of_index, to_array, request);
    internal::read_constraint_request(*m_indexing.tmesh, np, m_indexing.vertex_of_index, m_indexing.index_of_vertex,
                                      to_array, request);
    if constexpr(!is_default_parameter<NamedParameters, internal_np::prescribed_singularities_t>::value)
    {
      request.prescribed = true;
      request.prescribed_index =
        internal::prescribed_indices(get_parameter(np, internal_np::prescribed_singularities),
                                     m_indexing.face_of_index.size(), m_indexing.index_of_face, "face");
      if constexpr(!is_default_parameter<NamedParameters, internal_np::prescribed_loop_turns_t>::value)
        for(const auto& entry : get_parameter(np, internal_np::prescribed_loop_turns))
          request.loop_turns.emplace_back(static_cast<std::size_t>(entry.first), static_cast<long>(entry.second));
    }
    else if constexpr(!is_default_parameter<NamedParameters, internal_np::prescribed_loop_turns_t>::value)
      throw Invalid_input_error("prescribed_loop_turns applies with prescribed_singularities only (the smoothest "
                                "and aligned fields choose their own turns)");
    // A backend over several processes (Petsc_distributed_solver) for this call.
    auto&& backend = parameters::get_parameter_reference(np, internal_np::distributed_solver);
    if constexpr(!is_default_parameter<NamedParameters, internal_np::distributed_solver_t>::value)
      request.distributed = &backend;

    // A solver given as a named parameter is used for this call only, without reuse.
    internal::Field_answer answer;
    Direction_field_result result = internal::compute_with_solver<SparseSolver>(np, *m_engine, request, answer);

    auto out = choose_parameter(get_parameter(np, internal_np::singularities_output_iterator),
                                CGAL::Emptyset_iterator());
    for(const auto& face_and_k : answer.singular_faces)
      *out++ = std::make_pair(m_indexing.face_of_index[face_and_k.first], face_and_k.second);
    write_directions(answer.directions, vertex_direction_map);
    if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_magnitude_map_t>::value)
    {
      const auto vmm = get_parameter(np, internal_np::vertex_magnitude_map);
      for(std::size_t i = 0; i < m_indexing.vertex_of_index.size(); ++i)
        put(vmm, m_indexing.vertex_of_index[i], answer.magnitudes[i]);
    }
    if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_coefficient_map_t>::value)
    {
      const auto vcm = get_parameter(np, internal_np::vertex_coefficient_map);
      for(std::size_t i = 0; i < m_indexing.vertex_of_index.size(); ++i)
        put(vcm, m_indexing.vertex_of_index[i], answer.coefficients[i]);
    }
    result.timings.total_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    result.timings.solve_ms = result.timings.total_ms - result.timings.setup_ms - result.timings.factorization_ms;
    return result;
  }

  /// @}

  /*!
  returns the loops around which the field's turning can be chosen when singularities are
  prescribed (named parameter `prescribed_loop_turns`; user manual, section "Placing
  Singularities"), each as the closed sequence of its halfedges: first the \f$ 2g \f$ loops through the
  handles of each component of genus `g`, then every boundary loop, each along the faces' orientation
  (the surface on its left). The longest boundary loop of each component turns as the others and the
  indices imply. The loops depend on the mesh only; the first call computes them (and factors the
  Laplacian that prescriptions use), later calls return them at once.
  \returns one vector of halfedges per loop, each halfedge's target the next one's source
  */
  std::vector<std::vector<halfedge_descriptor> > prescription_loops()
  {
    std::vector<std::vector<halfedge_descriptor> > loops;
    for(const internal::Corner_loop& corners : m_engine->prescription_loops())
    {
      loops.emplace_back();
      for(const auto& corner_and_sign : corners)
      {
        const halfedge_descriptor h = halfedge_of_corner(corner_and_sign.first);
        loops.back().push_back(corner_and_sign.second > 0 ? h : opposite(h, *m_indexing.tmesh));
      }
    }
    return loops;
  }

  /*!
  returns the energy matrix \f$ A \f$ and the mass matrix \f$ M \f$ of the fields of degree `n` and
  smoothness parameter `s` on this mesh (user manual, sections "Energies" and "The Smoothest Field"):
  both Hermitian, rows and columns numbered by the vertex index map of the construction, with no entry
  at isolated vertices, in the mesh's units (\f$ M \f$ scales with area, \f$ A \f$ not). The
  coefficients of a field (named parameter `vertex_coefficient_map`) are in the same reference frames:
  the smoothest field's satisfy \f$ A u = \lambda M u \f$ with \f$ \lambda \f$ the reported eigenvalue
  of each component. The matrices are those the computation uses, for users who build on them.

  \param degree the degree `n`, from 1 to `maximum_degree`
  \param s the smoothness parameter, in \f$ [-1, 1] \f$
  \returns the pair (\f$ A \f$, \f$ M \f$), square matrices with one row per vertex
  \throws Invalid_input_error for a degree or an `s` out of range
  */
  std::pair<Eigen::SparseMatrix<std::complex<double> >, Eigen::SparseMatrix<std::complex<double> > >
  energy_and_mass_matrices(int degree = default_degree, double s = 0.)
  {
    internal::check_field_parameters(degree, s);
    return m_engine->energy_and_mass(degree, s);
  }

  /// \cond SKIP_IN_MANUAL
  // The time spent in the constructor, in milliseconds.
  double construction_ms() const { return m_construction_ms; }
  // Whether factorizations are kept between calls (true by default;
  // compute_globally_optimal_directions() frees them after its single call).
  void keep_factorizations(bool keep) { m_engine->keep_factorizations(keep); }
  /// \endcond

private:
  // The halfedge along corner ci's side: corners are counted from the face's
  // halfedge whose source has the smallest index (make_indexed_mesh()).
  halfedge_descriptor halfedge_of_corner(std::size_t ci) const
  {
    const TriangleMesh& tm = *m_indexing.tmesh;
    const halfedge_descriptor start = halfedge(m_indexing.face_of_index[internal::Indexed_mesh::face_of_corner(ci)], tm);
    halfedge_descriptor h = start;
    for(halfedge_descriptor g = next(start, tm); g != start; g = next(g, tm))
      if(m_indexing.index_of_vertex(source(g, tm)) < m_indexing.index_of_vertex(source(h, tm))) h = g;
    for(std::size_t c = 0; c < ci % 3; ++c) h = next(h, tm);
    return h;
  }

  // The unit 3D direction of every vertex into the user's map, sequentially
  // (a property map need not be thread-safe).
  template <typename VertexDirectionMap>
  void write_directions(const std::vector<internal::Vec3>& directions, VertexDirectionMap vertex_direction_map) const
  {
    typedef typename GeomTraits::FT FT;
    auto construct_vector = m_indexing.traits.construct_vector_3_object();
    for(std::size_t i = 0; i < m_indexing.vertex_of_index.size(); ++i)
    {
      const internal::Vec3& d = directions[i];
      put(vertex_direction_map, m_indexing.vertex_of_index[i], construct_vector(FT(d[0]), FT(d[1]), FT(d[2])));
    }
  }

  internal::Mesh_indexing<TriangleMesh, GeomTraits> m_indexing;  // the index maps of the construction
  std::unique_ptr<Engine> m_engine;  // everything else: the method and its linear algebra
  double m_construction_ms = 0.;
};

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION
// compiled once, in the library CGAL::Surface_mesh_direction_fields_compiled
extern template class internal::Field_engine<Default_direction_field_solver>;
#endif

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_DIRECTION_FIELD_H
