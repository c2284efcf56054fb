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
#include <CGAL/Surface_mesh_direction_fields/internal/Engine/face_field_engine.h>
#if defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD)
#  include <CGAL/Surface_mesh_direction_fields/Cholmod_supernodal_solver.h>
#endif

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/iterator.h>

#include <chrono>
#include <cmath>
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
               !is_default_parameter<NamedParameters, internal_np::vertex_is_constrained_t>::value ||
               !is_default_parameter<NamedParameters, internal_np::prescribed_singularities_t>::value)
    throw Invalid_input_error("vertex_guidance_map, vertex_is_constrained_map and prescribed_singularities apply to "
                              "fields on vertices; a field on faces takes face_guidance_map and face_is_constrained_map");
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
  return r;
}

// The corner 3f+c of the indexed mesh whose side is the halfedge h.
template <typename TriangleMesh, typename VertexIndexMap, typename FaceIndexMap>
std::size_t corner_of_halfedge(const TriangleMesh& tm, const Indexed_mesh& m, VertexIndexMap vim, FaceIndexMap fim,
                               typename boost::graph_traits<TriangleMesh>::halfedge_descriptor h)
{
  const std::size_t f = static_cast<std::size_t>(get(fim, face(h, tm)));
  const std::size_t s = static_cast<std::size_t>(get(vim, source(h, tm)));
  for(std::size_t c = 0; c < 3; ++c)
    if(static_cast<std::size_t>(m.faces[f][c]) == s) return 3 * f + c;
  return no_index;
}

} // namespace internal

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
vcglib, libigl) finds the same singular vertices.

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
    \cgalParamDefault{`1`}
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
                          and turned `p` times by \f$ 2\pi/n \f$ (and by less than \f$ \pi/n \f$ more); `0` on the
                          boundary}
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
        and for the named parameters of vertex fields (`vertex_guidance_map`, `vertex_is_constrained_map`,
        `prescribed_singularities`); nothing is written to the output maps then.
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
  using parameters::is_default_parameter;
  typedef typename GetGeomTraits<TriangleMesh, CGAL_NP_CLASS>::type Geom_traits;
  typedef typename GetSolver<CGAL_NP_CLASS, Default_direction_field_solver>::type Sparse_solver;
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  internal::check_field_parameters(choose_parameter(get_parameter(np, internal_np::degree), 1),
                                   choose_parameter(get_parameter(np, internal_np::smoothness_parameter), 0.));
  const Geom_traits traits = choose_parameter<Geom_traits>(get_parameter(np, internal_np::geom_traits));
  const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tmesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(tmesh, np);
  const auto fim = CGAL::get_initialized_face_index_map(tmesh, np);
  const double mollification = choose_parameter(get_parameter(np, internal_np::intrinsic_mollification), 1e-6);
  if(!(mollification >= 0.) || !std::isfinite(mollification))
    throw Invalid_input_error("the intrinsic mollification must be a non-negative number");
  const internal::Point_to_array<Geom_traits> to_array{traits};
  std::vector<typename Graph_traits::face_descriptor> face_of_index(num_faces(tmesh));
  for(auto f : faces(tmesh)) face_of_index[static_cast<std::size_t>(get(fim, f))] = f;
  std::vector<typename Graph_traits::vertex_descriptor> vertex_of_index(num_vertices(tmesh));
  for(auto v : vertices(tmesh)) vertex_of_index[static_cast<std::size_t>(get(vim, v))] = v;
  auto index_of = [vim](typename Graph_traits::vertex_descriptor v) { return static_cast<std::size_t>(get(vim, v)); };
  const internal::Face_field_request request = internal::face_field_request(tmesh, np, face_of_index, index_of,
                                                                             to_array);

  const auto start = std::chrono::steady_clock::now();
  const internal::Face_field_engine<Sparse_solver> engine(
    internal::make_indexed_mesh(tmesh, [&](typename Graph_traits::vertex_descriptor v) { return to_array(get(vpm, v)); },
                                vim, fim),
    mollification);
  Sparse_solver solver = choose_parameter(get_parameter(np, internal_np::sparse_linear_solver), Sparse_solver());
  internal::Face_field_answer answer;
  Face_direction_field_result result = engine.compute(request, solver, answer);
  // the construction (indexing, geometry, dual connection) is part of the setup
  const double total_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  result.timings.setup_ms += total_ms - result.timings.total_ms;
  result.timings.total_ms = total_ms;

  typedef typename Geom_traits::FT FT;
  const auto construct_vector = traits.construct_vector_3_object();
  for(std::size_t f = 0; f < face_of_index.size(); ++f)
  {
    const internal::Vec3& d = answer.directions[f];
    put(face_direction_map, face_of_index[f], construct_vector(FT(d[0]), FT(d[1]), FT(d[2])));
  }
  auto out = choose_parameter(get_parameter(np, internal_np::singularities_output_iterator), CGAL::Emptyset_iterator());
  for(std::size_t v = 0; v < answer.vertex_index.size(); ++v)
    if(answer.vertex_index[v] != 0) *out++ = std::make_pair(vertex_of_index[v], answer.vertex_index[v]);
  if constexpr(!is_default_parameter<CGAL_NP_CLASS, internal_np::edge_matching_map_t>::value)
  {
    auto matching_map = get_parameter(np, internal_np::edge_matching_map);
    for(auto e : edges(tmesh))
    {
      const auto h = halfedge(e, tmesh);
      const bool border = is_border(h, tmesh) || is_border(opposite(h, tmesh), tmesh);
      put(matching_map, e, border ? 0 : answer.matching[internal::corner_of_halfedge(tmesh, engine.mesh(), vim, fim, h)]);
    }
  }
  return result;
}
#ifndef DOXYGEN_RUNNING
} // inline namespace CGAL_SURFACE_MESH_DIRECTION_FIELDS_DEFAULT_SOLVER_NAMESPACE
#endif

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_FACE_DIRECTIONS_H
