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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FIELD_TARGETS_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FIELD_TARGETS_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Engine/mesh_geometry.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/linear_solves.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_inputs.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/field_request.h>

#include <complex>
#include <cstddef>
#include <vector>

// What one field must follow, read from its request once per call: the
// guidance and the hard constraints as coefficients, and the alignment.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Field_targets
{
  std::vector<std::complex<double> > guidance;  // q per vertex, before normalization; empty: none
  bool has_guidance = false;                    // whether the named parameters ask for one
  Vertex_constraints constraints;
  Alignment_request alignment;
};

// The constraints and the alignment request (the guidance is computed later,
// while the factorizations that do not depend on it run).
inline Field_targets field_targets(const Mesh_geometry& g, const Field_request& request)
{
  Field_targets targets;
  targets.constraints = vertex_constraints(g.mesh, g.tangent_spaces, request, g.normals);
  add_feature_constraints(request, g.mesh, g.tangent_spaces, g.normals, targets.constraints);
  targets.has_guidance = request.has_guidance_map || request.curvature != Principal_curvature_alignment::NONE;
  targets.alignment = request.alignment;
  targets.alignment.lambda = g.eigenvalue_from_user(targets.alignment.lambda);
  return targets;
}

// A component's share of the guidance q (empty if there is none).
inline Complex_vector component_guidance(const Component& comp, const std::vector<std::complex<double> >& guidance)
{
  if(guidance.empty()) return Complex_vector();
  Complex_vector q(static_cast<Eigen::Index>(comp.vertices.size()));
  for(Eigen::Index i = 0; i < q.size(); ++i) q[i] = guidance[comp.vertices[static_cast<std::size_t>(i)]];
  return q;
}

// A component's share of the constraints (empty if it has none).
inline Constraints component_constraints(const Component& comp, const Vertex_constraints& constraints)
{
  Constraints local;
  if(constraints.is_constrained.empty()) return local;
  const Eigen::Index nc = static_cast<Eigen::Index>(comp.vertices.size());
  local.is_constrained.resize(comp.vertices.size());
  local.values.resize(nc);
  for(Eigen::Index i = 0; i < nc; ++i)
  {
    const std::size_t v = comp.vertices[static_cast<std::size_t>(i)];
    local.is_constrained[static_cast<std::size_t>(i)] = constraints.is_constrained[v];
    local.values[i] = constraints.values[v];
  }
  return local;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_ENGINE_FIELD_TARGETS_H
