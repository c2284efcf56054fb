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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_FACE_DIRECTION_FIELD_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_FACE_DIRECTION_FIELD_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Globally_optimal_direction_field.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/named_inputs.h>
// the method on the dual mesh behind one seam, as for vertex fields
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/Face_field_engine.h>
#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION
#  include <CGAL/Surface_mesh_direction_fields/internal/Engine/Face_field_engine_impl.h>
#endif

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/iterator.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

\brief computes globally optimal direction fields on the faces of one triangle mesh, repeatedly, without
redoing the work that does not change.

Construction does the mesh work once: the indexing, the intrinsic geometry, the components and the
connection across the edges. Each call of `compute()` then computes one field, with the named parameters
and results of `compute_globally_optimal_face_directions()` (which is this class used once). The first call
with `prescribed_singularities` also builds the spanning trees of the construction and factors the Laplacian
of the faces (user manual, section \ref SMDF_faces); both are kept, so that every later prescription (an edit
of the singularities, or another degree) costs a sweep, two triangular solves and the output. The mesh must
not change while the object is alive. `compute()` may be called from several threads; prescriptions run one
at a time.

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
\tparam GeomTraits a model of `DirectionFieldTraits_3`; by default the kernel of the mesh's point type
\tparam SparseSolver a model of `SparseLinearAlgebraWithFactorTraits_d` with `std::complex<double>` as `NT`

\sa `compute_globally_optimal_face_directions()`, `Globally_optimal_direction_field`
*/
template <typename TriangleMesh,
          typename GeomTraits = typename GetGeomTraits<TriangleMesh>::type,
          typename SparseSolver = Default_direction_field_solver>
class Globally_optimal_face_direction_field
{
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename Graph_traits::face_descriptor face_descriptor;
  typedef std::chrono::steady_clock Clock;

public:
  /// \name Creation
  /// @{

  /*!
  does the mesh work: indexing, intrinsic geometry, components, the connection across the edges.

  \param tmesh the triangle mesh; it is not modified, and must outlive the object unchanged
  \param np an optional sequence of named parameters among `vertex_point_map`, `vertex_index_map`,
         `face_index_map`, `geom_traits` and `intrinsic_mollification`, with the meaning and defaults given
         for `compute_globally_optimal_directions()`, and `vertex_point_index_map` (see
         `compute_globally_optimal_face_directions()`)
  \throws Invalid_input_error for the meshes `Globally_optimal_direction_field` refuses
  */
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Globally_optimal_face_direction_field(const TriangleMesh& tmesh,
                                                 const NamedParameters& np = parameters::default_values())
  {
    const auto start = Clock::now();
    internal::Indexed_mesh indexed = m_indexing.index(tmesh, np);
    m_engine = std::make_unique<Engine>(std::move(indexed), m_indexing.mollification, m_indexing.point_of_vertex(np));
    m_construction_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  }

  /// @}

  /// \name Operations
  /// @{

  /*!
  computes one field, exactly as `compute_globally_optimal_face_directions(tmesh, face_direction_map, np)`
  would, reusing what earlier calls computed. The named parameters are those of
  `compute_globally_optimal_face_directions()` except the ones of the constructor (ignored here). In the
  result, `timings` count the work of this call only, not the construction.

  \tparam FaceDirectionMap as for `compute_globally_optimal_face_directions()`
  \tparam NamedParameters a sequence of named parameters
  \param face_direction_map the property map receiving a unit direction per face
  \param np the named parameters of the field (see `compute_globally_optimal_face_directions()`)
  \returns the report of this field, as `compute_globally_optimal_face_directions()` returns it
  \throws Invalid_input_error, Solver_failure_error as `compute_globally_optimal_face_directions()`
  */
  template <typename FaceDirectionMap, typename NamedParameters = parameters::Default_named_parameters>
  Face_direction_field_result compute(FaceDirectionMap face_direction_map,
                                      const NamedParameters& np = parameters::default_values()) const
  {
    const internal::Point_to_array<GeomTraits> to_array{m_indexing.traits};  // n and s are checked as they are read
    const internal::Face_field_request request =
      internal::face_field_request(*m_indexing.tmesh, np, m_indexing.face_of_index, m_indexing.index_of_vertex,
                                   to_array);
    internal::Face_field_answer answer;
    const Face_direction_field_result result =
      internal::compute_with_solver<SparseSolver>(np, *m_engine, request, answer);
    write_answer(answer, face_direction_map, np);
    return result;
  }

  /// @}

  /// \cond SKIP_IN_MANUAL
  // The time spent in the constructor, in milliseconds.
  double construction_ms() const { return m_construction_ms; }
  /// \endcond

private:
  typedef internal::Face_field_engine<SparseSolver> Engine;

  // The directions, the singular vertices and the matching into the user's
  // maps and iterator, sequentially (a property map need not be thread-safe).
  template <typename FaceDirectionMap, typename NamedParameters>
  void write_answer(const internal::Face_field_answer& answer, FaceDirectionMap face_direction_map,
                    const NamedParameters& np) const
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    typedef typename GeomTraits::FT FT;
    const auto construct_vector = m_indexing.traits.construct_vector_3_object();
    for(std::size_t f = 0; f < m_indexing.face_of_index.size(); ++f)
    {
      const internal::Vec3& d = answer.directions[f];
      put(face_direction_map, m_indexing.face_of_index[f], construct_vector(FT(d[0]), FT(d[1]), FT(d[2])));
    }
    auto out = choose_parameter(get_parameter(np, internal_np::singularities_output_iterator), CGAL::Emptyset_iterator());
    for(std::size_t v = 0; v < answer.vertex_index.size(); ++v)
      if(answer.vertex_index[v] != 0) *out++ = std::make_pair(m_indexing.vertex_of_index[v], answer.vertex_index[v]);
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::edge_matching_map_t>::value)
    {
      auto matching_map = get_parameter(np, internal_np::edge_matching_map);
      const TriangleMesh& tm = *m_indexing.tmesh;
      for(auto e : edges(tm))
      {
        const auto h = halfedge(e, tm);
        const bool border = is_border(h, tm) || is_border(opposite(h, tm), tm);
        if(border)
        {
          put(matching_map, e, 0);
          continue;
        }
        const std::size_t corner =
          internal::corner_of_halfedge(tm, m_engine->mesh(), m_indexing.index_of_vertex, m_indexing.index_of_face, h);
        put(matching_map, e, answer.matching[corner]);
      }
    }
  }

  internal::Mesh_indexing<TriangleMesh, GeomTraits> m_indexing;  // the index maps of the construction
  std::unique_ptr<Engine> m_engine;
  double m_construction_ms = 0.;
};

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION
// compiled once, in the library CGAL::Surface_mesh_direction_fields_compiled
extern template class internal::Face_field_engine<Default_direction_field_solver>;
#endif

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_FACE_DIRECTION_FIELD_H
