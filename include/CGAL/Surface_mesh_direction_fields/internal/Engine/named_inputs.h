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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_NAMED_INPUTS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_NAMED_INPUTS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/Surface_mesh_direction_fields/Direction_field_result.h>
#include <CGAL/Surface_mesh_direction_fields/alignment.h>
#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_request.h>
#include <CGAL/Surface_mesh_direction_fields/internal/vector_math.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

// The named parameters of one field read into a Field_request, by vertex
// index: the plumbing between the user's property maps and the engine.

namespace CGAL {
namespace Surface_mesh_direction_fields {
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

// What the classes know of the user's mesh besides the engine: its traits,
// its index maps as functions, and the descriptor of each index.
template <typename TriangleMesh, typename GeomTraits>
struct Mesh_indexing
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;

  const TriangleMesh* tmesh = nullptr;
  GeomTraits traits;
  std::function<std::size_t(vertex_descriptor)> index_of_vertex;
  std::function<std::size_t(face_descriptor)> index_of_face;
  std::vector<vertex_descriptor> vertex_of_index;
  std::vector<face_descriptor> face_of_index;
  double mollification = 1e-6;

  // The mesh indexed as the named parameters `vertex_point_map`,
  // `vertex_index_map`, `face_index_map` and `geom_traits` say, and
  // `intrinsic_mollification` read.
  template <typename NamedParameters>
  Indexed_mesh index(const TriangleMesh& mesh, const NamedParameters& np)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    tmesh = &mesh;
    traits = choose_parameter<GeomTraits>(get_parameter(np, internal_np::geom_traits));
    const auto vpm = choose_parameter(get_parameter(np, internal_np::vertex_point),
                                      get_const_property_map(CGAL::vertex_point, mesh));
    const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
    const auto fim = CGAL::get_initialized_face_index_map(mesh, np);
    index_of_vertex = [vim](vertex_descriptor v) { return static_cast<std::size_t>(get(vim, v)); };
    index_of_face = [fim](face_descriptor f) { return static_cast<std::size_t>(get(fim, f)); };
    mollification = choose_parameter(get_parameter(np, internal_np::intrinsic_mollification), 1e-6);
    if(!(mollification >= 0.) || !std::isfinite(mollification))
      throw Invalid_input_error("the intrinsic mollification must be a non-negative number");
    const Point_to_array<GeomTraits> to_array{traits};
    Indexed_mesh indexed =
      make_indexed_mesh(mesh, [&](vertex_descriptor v) { return to_array(get(vpm, v)); }, vim, fim);
    vertex_of_index.resize(indexed.number_of_vertices());
    for(vertex_descriptor v : vertices(mesh)) vertex_of_index[index_of_vertex(v)] = v;
    face_of_index.resize(indexed.number_of_faces());
    for(face_descriptor f : faces(mesh)) face_of_index[index_of_face(f)] = f;
    return indexed;
  }

  // The named parameter `vertex_point_index_map` read into one number per
  // vertex index (empty without it).
  template <typename NamedParameters>
  std::vector<std::size_t> point_of_vertex(const NamedParameters& np) const
  {
    std::vector<std::size_t> points;
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::vertex_point_index_t>::value)
    {
      const auto map = parameters::get_parameter(np, internal_np::vertex_point_index);
      points.resize(vertex_of_index.size());
      for(std::size_t i = 0; i < points.size(); ++i) points[i] = static_cast<std::size_t>(get(map, vertex_of_index[i]));
    }
    return points;
  }
};

inline void check_field_parameters(int degree, double s)
{
  if(degree < 1 || degree > maximum_degree)
    throw Invalid_input_error("the degree n must be from 1 to " + std::to_string(maximum_degree) + " (got " +
                              std::to_string(degree) + ")");
  if(!(s >= -1. && s <= 1.))
    throw Invalid_input_error("the smoothness parameter s must lie in [-1, 1] (got " + compact_number(s) + ")");
}

// Whether the named parameters ask for a guidance field.
template <typename NamedParameters>
bool requests_guidance(const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  return choose_parameter(get_parameter(np, internal_np::principal_curvature_alignment),
                          Principal_curvature_alignment::NONE) != Principal_curvature_alignment::NONE ||
         !is_default_parameter<NamedParameters, internal_np::vertex_guidance_map_t>::value;
}

template <typename NamedParameters>
Alignment_request alignment_request(const NamedParameters& np, bool has_guidance)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  Alignment_request r;
  r.lambda_given = !is_default_parameter<NamedParameters, internal_np::alignment_lambda_t>::value;
  r.weight_given = !is_default_parameter<NamedParameters, internal_np::alignment_weight_t>::value;
  r.lambda = choose_parameter(get_parameter(np, internal_np::alignment_lambda), 0.);
  r.weight = choose_parameter(get_parameter(np, internal_np::alignment_weight), 0.5);
  r.eigenvalue_bound = choose_parameter(get_parameter(np, internal_np::compute_eigenvalue_bound), false);
  if(r.lambda_given && r.weight_given)
    throw Invalid_input_error("give either alignment_lambda or alignment_weight, not both");
  if(r.lambda_given && !std::isfinite(r.lambda))
    throw Invalid_input_error("alignment_lambda must be a finite number");
  if(r.weight_given && !(r.weight > 0. && r.weight < 1.))
    throw Invalid_input_error("alignment_weight must lie in (0, 1) (got " + compact_number(r.weight) + ")");
  if(r.weight_given && !has_guidance)
    throw Invalid_input_error("alignment_weight needs a guidance field (a guidance map or principal_curvature_alignment)");
  return r;
}

// A count given as any integer type, refused outside [0, 2^32 - 1] rather
// than wrapped (2^32 + 3 iterations would otherwise run 3).
template <typename Integer>
unsigned int checked_count(Integer value, const char* name)
{
  static_assert(std::is_integral<Integer>::value, "a count is an integer");
  bool in_range = true;
  if constexpr(std::is_signed<Integer>::value) in_range = value >= 0;
  if(in_range && static_cast<unsigned long long>(value) > std::numeric_limits<unsigned int>::max()) in_range = false;
  if(!in_range)
    throw Invalid_input_error(std::string(name) + " must be an integer from 0 to 4294967295");
  return static_cast<unsigned int>(value);
}

// n, s and the eigen-solve's options.
// k per element (face or vertex, by index) from the user's range of
// (element, k) pairs of prescribed_singularities; an element out of range or
// listed twice is an error.
template <typename Range, typename IndexOf>
std::vector<int> prescribed_indices(const Range& prescription, std::size_t count, const IndexOf& index_of,
                                    const std::string& element)
{
  std::vector<int> k(count, 0);
  std::vector<unsigned char> listed(count, 0);
  for(const auto& entry : prescription)
  {
    const std::size_t i = index_of(entry.first);
    if(i >= count)
      throw Invalid_input_error("prescribed_singularities names " + element + " " + std::to_string(i) +
                                ", but the mesh has " + std::to_string(count) + " " +
                                (element == "vertex" ? std::string("vertices") : element + "s"));
    if(listed[i]++)
      throw Invalid_input_error("prescribed_singularities lists " + element + " " + std::to_string(i) + " twice");
    k[i] = static_cast<int>(entry.second);
  }
  return k;
}

// One field from an engine (of vertex or face fields) with the user's
// sparse_linear_solver, for this call only, or else the engine's own.
template <typename SparseSolver, typename NamedParameters, typename Engine, typename Request, typename Answer>
auto compute_with_solver(const NamedParameters& np, Engine& engine, const Request& request, Answer& answer)
{
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::sparse_linear_solver_t>::value)
  {
    const SparseSolver solver = parameters::get_parameter(np, internal_np::sparse_linear_solver);
    return engine.compute(request, &solver, answer);
  }
  else
    return engine.compute(request, nullptr, answer);
}

template <typename NamedParameters>
void read_field_parameters(const NamedParameters& np, Field_request& r)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  r.degree = choose_parameter(get_parameter(np, internal_np::degree), default_degree);
  r.s = choose_parameter(get_parameter(np, internal_np::smoothness_parameter), 0.);
  check_field_parameters(r.degree, r.s);
  r.max_iterations =
    checked_count(choose_parameter(get_parameter(np, internal_np::number_of_iterations), 1000u), "number_of_iterations");
  r.residual_tolerance = choose_parameter(get_parameter(np, internal_np::residual_tolerance), 1e-10);
  r.random_seed = checked_count(choose_parameter(get_parameter(np, internal_np::random_seed), 0u), "random_seed");
  if(!(r.residual_tolerance >= 0.))
    throw Invalid_input_error("the residual tolerance must be non-negative");
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::progress_callback_t>::value)
    r.progress = get_parameter(np, internal_np::progress_callback);
}

// The guidance: principal curvatures and/or vertex_guidance_map.
template <typename NamedParameters, typename VertexDescriptor, typename ToArray>
void read_guidance_request(const NamedParameters& np, const std::vector<VertexDescriptor>& vertex_of_index,
                           const ToArray& to_array, Field_request& r)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  r.curvature =
    choose_parameter(get_parameter(np, internal_np::principal_curvature_alignment), Principal_curvature_alignment::NONE);
  r.curvature_estimate = choose_parameter(get_parameter(np, internal_np::principal_curvature_estimate),
                                          Principal_curvature_estimate::QUADRIC_FIT);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_guidance_map_t>::value)
  {
    const auto guidance_map = get_parameter(np, internal_np::vertex_guidance_map);
    r.has_guidance_map = true;
    r.guidance.resize(vertex_of_index.size());
    for(std::size_t i = 0; i < vertex_of_index.size(); ++i)
    {
      const Vec3 g = to_array(get(guidance_map, vertex_of_index[i]));
      if(!std::isfinite(g[0]) || !std::isfinite(g[1]) || !std::isfinite(g[2]))
        throw Invalid_input_error("the guidance vector of vertex " + std::to_string(i) + " is not finite");
      r.guidance[i] = g;
    }
  }
  r.alignment = alignment_request(np, requests_guidance(np));
}

// The hard constraints: boundary_alignment, vertex_is_constrained_map with
// vertex_constrained_direction_map, and edge_is_feature_map.
template <typename TriangleMesh, typename NamedParameters, typename VertexDescriptor, typename IndexOfVertex,
          typename ToArray>
void read_constraint_request(const TriangleMesh& tm, const NamedParameters& np,
                             const std::vector<VertexDescriptor>& vertex_of_index, const IndexOfVertex& index_of,
                             const ToArray& to_array, Field_request& r)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  r.boundary = choose_parameter(get_parameter(np, internal_np::boundary_alignment), Boundary_alignment::NONE);
  if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_is_constrained_t>::value)
  {
    if constexpr(is_default_parameter<NamedParameters, internal_np::vertex_constrained_direction_map_t>::value)
      throw Invalid_input_error("vertex_is_constrained_map needs vertex_constrained_direction_map");
    else
    {
      const auto is_constrained = get_parameter(np, internal_np::vertex_is_constrained);
      const auto directions = get_parameter(np, internal_np::vertex_constrained_direction_map);
      r.has_constraint_map = true;
      r.constrained.assign(vertex_of_index.size(), 0);
      r.constrained_direction.assign(vertex_of_index.size(), Vec3{0., 0., 0.});
      for(std::size_t i = 0; i < vertex_of_index.size(); ++i)
        if(get(is_constrained, vertex_of_index[i]))
        {
          r.constrained[i] = 1;
          r.constrained_direction[i] = to_array(get(directions, vertex_of_index[i]));
        }
    }
  }
  if constexpr(!is_default_parameter<NamedParameters, internal_np::edge_is_feature_t>::value)
  {
    const auto is_feature = get_parameter(np, internal_np::edge_is_feature);
    r.has_feature_map = true;
    for(auto e : edges(tm))
      if(get(is_feature, e))
        r.feature_edges.push_back({index_of(source(halfedge(e, tm), tm)), index_of(target(halfedge(e, tm), tm))});
  }
}

// The named parameters of a field on faces, by face index.

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

// singularity_cancellation_radius: a non-negative length, not with a
// prescription.
inline void check_cancellation_request(const Face_field_request& r)
{
  if(r.cancellation_radius == 0.) return;
  if(!(r.cancellation_radius > 0.) || !std::isfinite(r.cancellation_radius))
    throw Invalid_input_error("singularity_cancellation_radius must be a non-negative number (a fraction of the "
                              "bounding box's diagonal)");
  if(r.prescribed)
    throw Invalid_input_error("singularity_cancellation_radius and prescribed_singularities exclude each other "
                              "(the prescription places every singularity)");
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
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_NAMED_INPUTS_H
