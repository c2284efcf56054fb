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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_DISTRIBUTED_BACKEND_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_DISTRIBUTED_BACKEND_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/eigen_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/linear_solves.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/components.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Mesh/indexed_mesh.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/connection.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/tangent_spaces.h>

#include <cstddef>
#include <vector>

// What Globally_optimal_direction_field asks of a backend that spreads a
// component over several processes (user manual, section "Several
// Processes"): the class runs on the first process, which holds the mesh,
// and hands the backend the data of one component; the backend builds A and
// M over its processes from that data and returns the result on the first
// process. No MPI or PETSc type appears here, so that the class compiles
// without them (the PETSc model is Petsc_distributed_solver.h).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The mesh data of one component, on the first process (empty on the others).
struct Assembly_source
{
  const Indexed_mesh* mesh = nullptr;
  const Tangent_spaces* tangent_spaces = nullptr;
  const Connection* connection = nullptr;
  const Component* component = nullptr;
  const std::vector<Compact_index>* local_index = nullptr;  // the row of each vertex in its component
};

// The result of a linear solve over the processes.
struct Distributed_solve_report
{
  bool converged = false;
  std::size_t iterations = 0;
  double residual = 0.;  // ||b - K u|| / ||b|| on the free vertices
};

class Distributed_backend
{
public:
  virtual ~Distributed_backend() = default;
  // Whether a component of this many vertices is spread over the processes
  // (a small one is solved on the first process alone).
  virtual bool distributes(std::size_t vertices) const = 0;
  // The smallest eigenpair of the component's pencil (A, M) for the energy E_s,
  // the eigenvector M-normalized, in the component's numbering.
  virtual Eigen_solve_result smallest_eigenpair(const Assembly_source& source, double s,
                                                const Eigen_solve_options& options) const = 0;
  // u with (A - lambda M) u = b on the free vertices and u = c on the
  // constrained ones (as Shifted_system), A - lambda M positive definite there.
  virtual Distributed_solve_report shifted_solve(const Assembly_source& source, double s, double lambda,
                                                 const Complex_vector& b, const Constraints& constraints,
                                                 const Eigen_solve_options& options, Complex_vector& u) const = 0;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_DISTRIBUTED_BACKEND_H
