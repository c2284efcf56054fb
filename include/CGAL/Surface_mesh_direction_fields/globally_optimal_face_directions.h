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

#include <CGAL/Surface_mesh_direction_fields/Globally_optimal_face_direction_field.h>

namespace CGAL {
namespace Surface_mesh_direction_fields {

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
  \cgalParamNBegin{vertex_point_index_map}
    \cgalParamDescription{a non-manifold surface kept whole: vertices with the same value are copies of one point,
                          as `CGAL::Polygon_mesh_processing::orient_polygon_soup()` makes them where it cuts a
                          non-manifold edge or vertex (`polygon_soup_to_polygon_mesh()` keeps the order of the
                          points, so that the value of a vertex can be the index of the soup's point it copies).
                          The faces around an edge whose two ends are points shared by three or more faces are
                          then glued there: each pair is coupled as two faces across an ordinary edge, turned
                          about the edge until their normals agree, each pair with the weight of an ordinary
                          edge over the number of faces less one. Their components are solved as one. The
                          vertices on such an edge are boundary vertices of the copies (no index there, and the
                          glued sides count as boundary in the reports). It excludes `prescribed_singularities`
                          and `singularity_cancellation_radius` (user manual, section \ref SMDF_faces)}
    \cgalParamType{a model of `ReadablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
                   as key type and an integer type as value type}
    \cgalParamDefault{every vertex its own point: nothing is glued}
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
                          `prescribed_singularities` with the singularities that remain or, with
                          `edge_is_feature_map`, `face_is_constrained_map`, `boundary_alignment`,
                          `alignment_lambda` or `alignment_weight`, the same field turned off the constrained
                          faces, which keep their directions (user manual, section \ref SMDF_faces). A pair whose
                          removal would show other singularities is kept. Quad meshes built on it have fewer
                          irregular vertices. The distance is a fraction of the length of the diagonal of the
                          mesh's bounding box; 0 removes nothing. It excludes `prescribed_singularities`}
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

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_GLOBALLY_OPTIMAL_FACE_DIRECTIONS_H
