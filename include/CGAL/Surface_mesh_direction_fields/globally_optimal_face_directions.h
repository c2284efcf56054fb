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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_FACE_DIRECTIONS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_FACE_DIRECTIONS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Globally_optimal_direction_field.h>
// the method on the dual mesh behind one seam, as for vertex fields
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/face_field_engine.h>
#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION
#  include <CGAL/Surface_mesh_direction_fields/internal/Engine/face_field_engine_impl.h>
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
namespace internal {

// face_is_constrained_map with face_constrained_direction_map.
template <typename NamedParameters, typename FaceDescriptor, typename ToArray>
void read_face_constraints(const NamedParameters& np, const std::vector<FaceDescriptor>& face_of_index,
                           const ToArray& to_array, Face_field_request& r)
{
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::face_is_constrained_t>::value)
  {
    if constexpr(is_default_parameter<NamedParameters, internal_np::face_constrained_direction_map_t>::value)
      throw Invalid_input_error("face_is_constrained_map needs face_constrained_direction_map");
    else
    {
      const auto is_constrained = get_parameter(np, internal_np::face_is_constrained);
      const auto directions = get_parameter(np, internal_np::face_constrained_direction_map);
      r.constrained.assign(face_of_index.size(), 0);
      r.constrained_direction.assign(face_of_index.size(), Vec3{0., 0., 0.});
      for(std::size_t i = 0; i < face_of_index.size(); ++i)
        if(get(is_constrained, face_of_index[i]))
        {
          const Vec3 d = to_array(get(directions, face_of_index[i]));
          if(!(std::isfinite(d[0]) && std::isfinite(d[1]) && std::isfinite(d[2])) || norm(d) == 0.)
            throw Invalid_input_error("the constrained direction of face " + std::to_string(i) +
                                      " is zero or not finite");
          r.constrained[i] = 1;
          r.constrained_direction[i] = d;
        }
    }
  }
}

// singularity_cancellation_radius: a length that the parallel field it leads
// to can honour (it turns as a whole, so it follows no feature or constraint).
inline void check_cancellation_request(const Face_field_request& r)
{
  if(r.cancellation_radius == 0.) return;
  if(!(r.cancellation_radius > 0.) || !std::isfinite(r.cancellation_radius))
    throw Invalid_input_error("singularity_cancellation_radius must be a non-negative number (a fraction of the "
                              "bounding box's diagonal)");
  if(r.prescribed)
    throw Invalid_input_error("singularity_cancellation_radius and prescribed_singularities exclude each other "
                              "(the prescription places every singularity)");
  const bool constrained = std::find(r.constrained.begin(), r.constrained.end(), 1) != r.constrained.end();
  if(!r.feature_edges.empty() || constrained || r.boundary != Boundary_alignment::NONE)
    throw Invalid_input_error("singularity_cancellation_radius does not apply with feature edges, constrained faces "
                              "or boundary alignment: the field it leads to turns only as a whole");
  if(r.alignment.lambda_given || r.alignment.weight_given)
    throw Invalid_input_error("singularity_cancellation_radius does not apply with alignment_lambda or "
                              "alignment_weight: the field it leads to turns only as a whole towards the guidance");
}

// The named parameters of a field on faces read into a Face_field_request.
template <typename TriangleMesh, typename NamedParameters, typename FaceDescriptor, typename IndexOfVertex,
          typename ToArray>
Face_field_request face_field_request(const TriangleMesh& tm, const NamedParameters& np,
                                      const std::vector<FaceDescriptor>& face_of_index, const IndexOfVertex& index_of,
                                      const ToArray& to_array)
{
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  Field_request common;
  read_field_parameters(np, common);
  if(common.s != 0.)
    throw Invalid_input_error("a field on faces has the Dirichlet energy only: the smoothness parameter s must be 0 "
                              "(user manual, section \"Fields on Faces\")");
  if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_guidance_map_t>::value ||
               !is_default_parameter<NamedParameters, internal_np::vertex_is_constrained_t>::value)
    throw Invalid_input_error("vertex_guidance_map and vertex_is_constrained_map apply to fields on vertices; a field "
                              "on faces takes face_guidance_map and face_is_constrained_map");
  if constexpr(!is_default_parameter<NamedParameters, internal_np::prescribed_loop_turns_t>::value)
    throw Invalid_input_error("prescribed_loop_turns applies to fields on vertices: a field on faces with "
                              "prescribed_singularities turns along each loop by the multiple of 2 pi / n nearest the "
                              "surface's own");
  read_constraint_request(tm, np, std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor>(),
                          index_of, to_array, common);
  Face_field_request r;
  r.degree = common.degree;
  r.max_iterations = common.max_iterations;
  r.residual_tolerance = common.residual_tolerance;
  r.random_seed = common.random_seed;
  r.progress = common.progress;
  r.boundary = common.boundary;
  r.feature_edges = common.feature_edges;
  r.curvature = parameters::choose_parameter(get_parameter(np, internal_np::principal_curvature_alignment),
                                             Principal_curvature_alignment::NONE);
  if(r.curvature != Principal_curvature_alignment::NONE && r.degree % 2 != 0)
    throw Invalid_input_error("curvature alignment needs an even degree n (got " + std::to_string(r.degree) + ")");
  if(!r.feature_edges.empty() && r.degree % 2 != 0)
    throw Invalid_input_error("alignment with sharp features needs an even degree n (got " +
                              std::to_string(r.degree) + ")");
  bool has_guidance = r.curvature != Principal_curvature_alignment::NONE;
  if constexpr(!is_default_parameter<NamedParameters, internal_np::face_guidance_map_t>::value)
  {
    has_guidance = true;
    const auto guidance_map = get_parameter(np, internal_np::face_guidance_map);
    r.guidance.resize(face_of_index.size());
    for(std::size_t i = 0; i < face_of_index.size(); ++i)
    {
      r.guidance[i] = to_array(get(guidance_map, face_of_index[i]));
      if(!std::isfinite(r.guidance[i][0]) || !std::isfinite(r.guidance[i][1]) || !std::isfinite(r.guidance[i][2]))
        throw Invalid_input_error("the guidance vector of face " + std::to_string(i) + " is not finite");
    }
  }
  r.alignment = alignment_request(np, has_guidance);
  read_face_constraints(np, face_of_index, to_array, r);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::prescribed_singularities_t>::value)
    r.prescribed_index = prescribed_indices(get_parameter(np, internal_np::prescribed_singularities),
                                            num_vertices(tm), index_of, "vertex");
  r.prescribed = !r.prescribed_index.empty();
  r.cancellation_radius = parameters::choose_parameter(get_parameter(np, internal_np::singularity_cancellation_radius), 0.);
  check_cancellation_request(r);
  return r;
}

// The corner 3f+c of the indexed mesh whose side is the halfedge h.
template <typename TriangleMesh, typename IndexOfVertex, typename IndexOfFace>
std::size_t corner_of_halfedge(const TriangleMesh& tm, const Indexed_mesh& m, const IndexOfVertex& index_of_vertex,
                               const IndexOfFace& index_of_face,
                               typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h)
{
  const std::size_t f = index_of_face(face(h, tm)), s = index_of_vertex(source(h, tm));
  for(std::size_t c = 0; c < 3; ++c)
    if(static_cast<std::size_t>(m.faces[f][c]) == s) return 3 * f + c;
  return no_index;
}

} // namespace internal

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
         for `compute_globally_optimal_directions()`
  \throws Invalid_input_error for the meshes `Globally_optimal_direction_field` refuses
  */
  template <typename NamedParameters = parameters::Default_named_parameters>
  explicit Globally_optimal_face_direction_field(const TriangleMesh& tmesh,
                                                 const NamedParameters& np = parameters::default_values())
    : m_tmesh(&tmesh)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    const auto start = Clock::now();
    m_traits = choose_parameter<GeomTraits>(get_parameter(np, internal_np::geom_traits));
    const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                      get_const_property_map(CGAL::vertex_point, tmesh));
    const auto vim = CGAL::get_initialized_vertex_index_map(tmesh, np);
    const auto fim = CGAL::get_initialized_face_index_map(tmesh, np);
    m_index_of_vertex = [vim](vertex_descriptor v) { return static_cast<std::size_t>(get(vim, v)); };
    m_index_of_face = [fim](face_descriptor f) { return static_cast<std::size_t>(get(fim, f)); };
    const double mollification = choose_parameter(get_parameter(np, internal_np::intrinsic_mollification), 1e-6);
    if(!(mollification >= 0.) || !std::isfinite(mollification))
      throw Invalid_input_error("the intrinsic mollification must be a non-negative number");
    m_face_of_index.resize(num_faces(tmesh));
    for(face_descriptor f : faces(tmesh)) m_face_of_index[m_index_of_face(f)] = f;
    m_vertex_of_index.resize(num_vertices(tmesh));
    for(vertex_descriptor v : vertices(tmesh)) m_vertex_of_index[m_index_of_vertex(v)] = v;
    const internal::Point_to_array<GeomTraits> to_array{m_traits};
    m_engine = std::make_unique<Engine>(
      internal::make_indexed_mesh(tmesh, [&](vertex_descriptor v) { return to_array(get(vpm, v)); }, vim, fim),
      mollification);
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
    using parameters::get_parameter;
    internal::check_field_parameters(parameters::choose_parameter(get_parameter(np, internal_np::degree), default_degree),
                                     parameters::choose_parameter(get_parameter(np, internal_np::smoothness_parameter), 0.));
    const internal::Point_to_array<GeomTraits> to_array{m_traits};
    const internal::Face_field_request request =
      internal::face_field_request(*m_tmesh, np, m_face_of_index, m_index_of_vertex, to_array);
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
    const auto construct_vector = m_traits.construct_vector_3_object();
    for(std::size_t f = 0; f < m_face_of_index.size(); ++f)
    {
      const internal::Vec3& d = answer.directions[f];
      put(face_direction_map, m_face_of_index[f], construct_vector(FT(d[0]), FT(d[1]), FT(d[2])));
    }
    auto out = choose_parameter(get_parameter(np, internal_np::singularities_output_iterator), CGAL::Emptyset_iterator());
    for(std::size_t v = 0; v < answer.vertex_index.size(); ++v)
      if(answer.vertex_index[v] != 0) *out++ = std::make_pair(m_vertex_of_index[v], answer.vertex_index[v]);
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::edge_matching_map_t>::value)
    {
      auto matching_map = get_parameter(np, internal_np::edge_matching_map);
      const TriangleMesh& tm = *m_tmesh;
      for(auto e : edges(tm))
      {
        const auto h = halfedge(e, tm);
        const bool border = is_border(h, tm) || is_border(opposite(h, tm), tm);
        put(matching_map, e, border ? 0 : answer.matching[internal::corner_of_halfedge(
                                            tm, m_engine->mesh(), m_index_of_vertex, m_index_of_face, h)]);
      }
    }
  }

  const TriangleMesh* m_tmesh = nullptr;
  GeomTraits m_traits;
  std::function<std::size_t(vertex_descriptor)> m_index_of_vertex;
  std::function<std::size_t(face_descriptor)> m_index_of_face;
  std::vector<vertex_descriptor> m_vertex_of_index;
  std::vector<face_descriptor> m_face_of_index;
  std::unique_ptr<Engine> m_engine;
  double m_construction_ms = 0.;
};

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

computes a globally optimal `n`-direction field on the faces of a triangle mesh:
one direction per face, by the method of `compute_globally_optimal_directions()`
on the dual mesh (user manual, section \ref SMDF_faces), with its singularities at
the vertices and the matching across every edge. This is the form quad meshers and
seamless parametrizations read.

The smoothest field minimizes \f$ u^* A u \f$ with \f$ \|u\|_M = 1 \f$, where
\f$ A \f$ sums over the interior edges the weighted squared difference between one face's
coefficient and its neighbour's transported across the edge, and \f$ M \f$ holds the face areas.
Guidance, hard constraints, features and boundary alignment work as for vertex fields.

An interior vertex has the integer index `k` (the field's index there is `k / n`); on every
closed component the indices sum to `n` times the Euler characteristic. The matching of an
interior edge is the principal one: a consumer that recomputes it from the directions (QuadWild,
vcglib, libigl) finds the same singular vertices. With `prescribed_singularities` any indices at the
interior vertices that satisfy Poincare-Hopf are shown exactly.

\tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
\tparam FaceDirectionMap a model of `WritablePropertyMap` with
        `boost::graph_traits<TriangleMesh>::%face_descriptor` as key type and `GT::Vector_3` as value type
\tparam NamedParameters a sequence of <a href="https://doc.cgal.org/5.5.1/BGL/group__bgl__namedparameters.html">Named Parameters</a>

\param tmesh the input triangle mesh; it is not modified
\param face_direction_map receives a unit direction per face, in the face's plane (the first of the
       `n` directions; the others are its rotations by \f$ 2\pi/n \f$)
\param np an optional sequence of named parameters among the ones listed below

\cgalNamedParamsBegin
  \cgalParamNBegin{degree}
    \cgalParamDescription{the degree `n` of the field, from 1 to `maximum_degree`}
    \cgalParamType{`int`}
    \cgalParamDefault{`default_degree`, 4: a cross field}
  \cgalParamNEnd
  \cgalParamNBegin{smoothness_parameter}
    \cgalParamDescription{must be `0` (the Dirichlet energy): the energies of other `s` do not carry over to faces}
    \cgalParamType{`double`}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{principal_curvature_alignment}
    \cgalParamDescription{aligns the field with the principal curvature directions of each face, estimated from the
                          dihedral angles of its three edges; requires an even `n`}
    \cgalParamType{`CGAL::Surface_mesh_direction_fields::Principal_curvature_alignment`}
    \cgalParamDefault{`Principal_curvature_alignment::NONE`}
  \cgalParamNEnd
  \cgalParamNBegin{face_guidance_map}
    \cgalParamDescription{a guidance vector per face, projected to the face's plane; its length is its weight}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
                   as key type and `GT::Vector_3` as value type}
    \cgalParamDefault{no user guidance}
  \cgalParamNEnd
  \cgalParamNBegin{alignment_lambda}
    \cgalParamDescription{as for `compute_globally_optimal_directions()`}
    \cgalParamType{`double`}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{alignment_weight}
    \cgalParamDescription{as for `compute_globally_optimal_directions()`}
    \cgalParamType{`double` in \f$ (0, 1) \f$}
    \cgalParamDefault{unused}
  \cgalParamNEnd
  \cgalParamNBegin{face_is_constrained_map}
    \cgalParamDescription{the faces whose direction is prescribed by `face_constrained_direction_map`}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
                   as key type and `bool` as value type}
    \cgalParamDefault{no constrained face}
  \cgalParamNEnd
  \cgalParamNBegin{face_constrained_direction_map}
    \cgalParamDescription{the prescribed direction of each constrained face (projected to its plane)}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%face_descriptor`
                   as key type and `GT::Vector_3` as value type}
    \cgalParamDefault{none; required with `face_is_constrained_map`}
  \cgalParamNEnd
  \cgalParamNBegin{boundary_alignment}
    \cgalParamDescription{constrains every face with a boundary edge to a direction along (or across) that edge}
    \cgalParamType{`CGAL::Surface_mesh_direction_fields::Boundary_alignment`}
    \cgalParamDefault{`Boundary_alignment::NONE`}
  \cgalParamNEnd
  \cgalParamNBegin{edge_is_feature_map}
    \cgalParamDescription{sharp features: one of the `n` directions of both faces of a feature edge follows the edge
                          (a face with two feature edges whose directions disagree follows the first); requires an
                          even `n`}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
                   as key type and `bool` as value type}
    \cgalParamDefault{no feature}
  \cgalParamNEnd
  \cgalParamNBegin{prescribed_singularities}
    \cgalParamDescription{places the singularities: the interior vertices listed get exactly the index `k / n`
                          given, every other interior vertex index 0, for any assignment whose indices add up to
                          `n` times the Euler characteristic on each closed component. The field is the parallel
                          section of the least changed connection on the dual mesh, each component turned as a
                          whole towards its guidance and constrained faces, and turns along each handle and
                          boundary loop by the multiple of \f$ 2\pi / n \f$ nearest the surface's own (user
                          manual, section \ref SMDF_faces). Where the field must turn by \f$ \pi / n \f$ or more
                          across an edge, the matching written to `edge_matching_map` is not the principal one
                          (`Face_direction_field_result::number_of_non_principal_jumps` counts those edges);
                          where each direction would have to turn by half a turn or more across some edge (an
                          index too large for the edges around its vertex), which no direction with a matching
                          can show, `Invalid_input_error` is thrown}
    \cgalParamType{a range of `std::pair<boost::graph_traits<TriangleMesh>::%vertex_descriptor, int>`, as
                   `singularities_output_iterator` writes them}
    \cgalParamDefault{none: the smoothest (or aligned) field, whose singularities the method places}
  \cgalParamNEnd
  \cgalParamNBegin{singularity_cancellation_radius}
    \cgalParamDescription{fewer singularities: once the smoothest (or aligned) field is computed, each pair of
                          singular vertices with opposite indices (`k` and `-k`) at most this far apart along the
                          edges is removed, the closest pairs first, and the field returned is the one of
                          `prescribed_singularities` with the singularities that remain (user manual, section
                          \ref SMDF_faces). Quad meshes built on it have fewer irregular vertices. The distance is
                          a fraction of the length of the diagonal of the mesh's bounding box; 0 removes nothing.
                          It excludes `prescribed_singularities`, `edge_is_feature_map`, `face_is_constrained_map`,
                          `boundary_alignment`, `alignment_lambda` and `alignment_weight`}
    \cgalParamType{`double`}
    \cgalParamDefault{`0`}
  \cgalParamNEnd
  \cgalParamNBegin{singularities_output_iterator}
    \cgalParamDescription{receives, for each interior vertex with a non-zero index, the pair of the vertex and its
                          integer index `k`, in the order of the vertex index map}
    \cgalParamType{a model of `OutputIterator` accepting
                   `std::pair<boost::graph_traits<TriangleMesh>::%vertex_descriptor, int>`}
    \cgalParamDefault{no output}
  \cgalParamNEnd
  \cgalParamNBegin{edge_matching_map}
    \cgalParamDescription{receives per edge the period jump `p` from the face of `halfedge(e)` to the face of its
                          opposite: that face's first direction is the first one's, transported across the edge
                          and turned `p` times by \f$ 2\pi/n \f$ (and by less than \f$ \pi/n \f$ more, except
                          across the edges `number_of_non_principal_jumps` counts); `0` on the boundary}
    \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%edge_descriptor`
                   as key type and `int` as value type}
    \cgalParamDefault{no output}
  \cgalParamNEnd
  \cgalParamNBegin{intrinsic_mollification, vertex_point_map, geom_traits, vertex_index_map, face_index_map,
                   number_of_iterations, residual_tolerance, random_seed, progress_callback, sparse_linear_solver}
    \cgalParamDescription{as for `compute_globally_optimal_directions()`}
  \cgalParamNEnd
\cgalNamedParamsEnd

\returns a `Face_direction_field_result`
\throws Invalid_input_error for the inputs `compute_globally_optimal_directions()` refuses, for `s` other than 0,
        for the named parameters of vertex fields (`vertex_guidance_map`, `vertex_is_constrained_map`,
        `prescribed_loop_turns`), and for a prescription that names a boundary or isolated vertex, lists a vertex
        twice, breaks Poincare-Hopf on a closed component, or comes with `alignment_lambda` or `alignment_weight`;
        nothing is written to the output maps then.
\throws Solver_failure_error if the sparse solver fails
*/
#ifndef DOXYGEN_RUNNING
inline namespace CGAL_SURFACE_MESH_DIRECTION_FIELDS_DEFAULT_SOLVER_NAMESPACE {
#endif
template <typename TriangleMesh, typename FaceDirectionMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
Face_direction_field_result
compute_globally_optimal_face_directions(const TriangleMesh& tmesh, FaceDirectionMap face_direction_map,
                                         const CGAL_NP_CLASS& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename GetGeomTraits<TriangleMesh, CGAL_NP_CLASS>::type Geom_traits;
  typedef typename GetSolver<CGAL_NP_CLASS, Default_direction_field_solver>::type Sparse_solver;
  internal::check_field_parameters(choose_parameter(get_parameter(np, internal_np::degree), default_degree),
                                   choose_parameter(get_parameter(np, internal_np::smoothness_parameter), 0.));
  const Globally_optimal_face_direction_field<TriangleMesh, Geom_traits, Sparse_solver> field(tmesh, np);
  Face_direction_field_result result = field.compute(face_direction_map, np);
  // the construction (indexing, geometry, dual connection) is part of the setup
  result.timings.setup_ms += field.construction_ms();
  result.timings.total_ms += field.construction_ms();
  return result;
}
#ifndef DOXYGEN_RUNNING
} // inline namespace CGAL_SURFACE_MESH_DIRECTION_FIELDS_DEFAULT_SOLVER_NAMESPACE
#endif

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_SEPARATE_COMPILATION
// compiled once, in the library CGAL::Surface_mesh_direction_fields_compiled
extern template class internal::Face_field_engine<Default_direction_field_solver>;
#endif

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_FACE_DIRECTIONS_H
