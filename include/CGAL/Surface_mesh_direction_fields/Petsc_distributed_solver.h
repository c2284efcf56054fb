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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_PETSC_DISTRIBUTED_SOLVER_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_PETSC_DISTRIBUTED_SOLVER_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/Globally_optimal_direction_field.h>
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
// the default solver, which estimates each process's block
#include <CGAL/Surface_mesh_direction_fields/Cholmod_supernodal_solver.h>
#endif
#include <CGAL/Surface_mesh_direction_fields/internal/Distributed/distributed_eigen_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Distributed/distributed_linear_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Distributed/distributed_assembly.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Method/distributed_backend.h>

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

Spreads the large components of a mesh over the processes of an MPI
communicator (user manual, section "Several Processes"), through PETSc and
SLEPc with complex scalars (Debian packages `libpetsc-complex-dev`,
`libslepc-complex-dev`, `openmpi-bin`). Given as the named parameter
`distributed_solver` of `compute_globally_optimal_directions()` or of
`Globally_optimal_direction_field::compute()`.

The mesh and the class live on the first process (rank 0) only; every other
process calls `serve()`, which does its share of each request of the first
process and returns when the first process calls `finish()`. For a component
of at least `minimum_distributed_vertices()` vertices, the first process
sends every process the faces of its rows; each process computes their local
matrices and its rows of A and M; the smallest eigenpair is computed by the
locally optimal block preconditioned conjugate gradient method with PETSc's
algebraic multigrid (GAMG) as preconditioner, the aligned and constrained
fields by conjugate gradients with the same preconditioner. Smaller
components are solved on the first process with the class's own solver.

Neither method factors a matrix, so neither can tell that A - lambda_t M is
not positive definite: a given `alignment_lambda` is checked against the
smallest eigenvalue, which is then computed (as for any solver of the
concept that cannot tell).

LOBPCG's eigenvector is accurate relative to its largest entries. Where some
vertices' values are below `100 * residual_tolerance` of the largest (user
manual, section "Where the Field Vanishes"), or where LOBPCG has not
converged after 400 steps (the nearly equal smallest eigenvalues of a
sphere), the eigenvector is finished by up to 4 steps of inverse iteration
on MUMPS's LU factorization of \f$ A + \varepsilon M \f$ over the processes
(when PETSc has MUMPS), as on one process. The PETSc option
`-smdf_refinement_steps K` sets the number of steps (0: never). Components
with fewer than 32 vertices per process are always solved on the first
process.

Once a request has started, every process takes part in the same collective
calls, so an error on one process cannot be reported to the others: a failing
PETSc, SLEPc or MPI call, or an exception (out of memory, among others), on
any process prints one line on stderr (the process, what failed, in which
step) and ends every process with `MPI_Abort()`. An exception thrown on the
first process between requests (bad input, say) is the caller's to handle;
the other processes then still wait in `serve()` until `finish()`.

SLEPc (`SlepcInitialize()`) must be initialized before the first request and
finalized after the last. PETSc's run-time options (`-ksp_*`, `-pc_*` for
the linear solves, `-st_*` for the multigrid of the eigen-solve) are read.
*/
class Petsc_distributed_solver : public internal::Distributed_backend
{
  typedef internal::Complex_vector Complex_vector;

public:
  /// a solver over the processes of `communicator`, distributing the components
  /// of at least `minimum_distributed_vertices` vertices
  /// \param communicator the processes
  /// \param minimum_distributed_vertices the size from which a component is spread over them
  explicit Petsc_distributed_solver(MPI_Comm communicator = PETSC_COMM_WORLD,
                                    std::size_t minimum_distributed_vertices = 50000)
    : m_comm(communicator), m_minimum_vertices(minimum_distributed_vertices)
  {
    CGAL_SMDF_MPI_CALL(MPI_Comm_rank(m_comm, &m_rank));
    CGAL_SMDF_MPI_CALL(MPI_Comm_size(m_comm, &m_size));
  }

  /// PETSc's error handler that prints nothing and keeps PETSc's own message
  /// of where an error arose, for the one-line report of a failed call;
  /// given to `PetscPushErrorHandler()` after `SlepcInitialize()`, it
  /// replaces PETSc's trace from inside the failing routine
  /// \param communicator the communicator of the failing object (unused)
  /// \param line the line of PETSc's source where the error arose (unused)
  /// \param function the PETSc routine where the error arose
  /// \param file PETSc's source file (unused)
  /// \param code PETSc's error code
  /// \param type whether this is where the error arose (`PETSC_ERROR_INITIAL`) or a routine passing it on
  /// \param message PETSc's message
  /// \param context unused
  /// \returns `code`, so that the failing routine returns it
  static PetscErrorCode error_handler(MPI_Comm communicator, int line, const char* function, const char* file,
                                      PetscErrorCode code, PetscErrorType type, const char* message, void* context)
  {
    return internal::record_petsc_error(communicator, line, function, file, code, type, message, context);
  }

  /// the number of processes of the communicator
  /// \returns that number
  int number_of_processes() const { return m_size; }

  /// whether this process is the first one (rank 0), the one that calls the package
  /// \returns whether it is
  bool is_first_process() const { return m_rank == 0; }

  /// the size from which a component is spread over the processes
  /// \returns that number of vertices
  std::size_t minimum_distributed_vertices() const { return m_minimum_vertices; }

  /// on every process but the first: does this process's share of the first
  /// process's requests, until the first process calls `finish()`
  void serve() const
  {
    for(;;)
    {
      int request = finish_request;
      CGAL_SMDF_MPI_CALL(MPI_Bcast(&request, 1, MPI_INT, 0, m_comm));
      if(request == finish_request) return;
      const Parameters p = broadcast_parameters(Parameters());
      Complex_vector ignored;
      if(request == eigenpair_request)
        collective_eigenpair(internal::Assembly_source(), p);
      else
        collective_linear_solve(internal::Assembly_source(), p, ignored, internal::Constraints(), ignored);
    }
  }

  /// on the first process: lets the other processes return from `serve()`
  void finish() const
  {
    int request = finish_request;
    CGAL_SMDF_MPI_CALL(MPI_Bcast(&request, 1, MPI_INT, 0, m_comm));
  }

  /// \cond SKIP_IN_MANUAL
  bool distributes(std::size_t vertices) const override
  {
    return vertices >= m_minimum_vertices && vertices >= minimum_vertices_per_process * std::size_t(m_size);
  }

  internal::Eigen_solve_result smallest_eigenpair(const internal::Assembly_source& source, double s,
                                                  const internal::Eigen_solve_options& options) const override
  {
    send_request(eigenpair_request);
    return collective_eigenpair(source, broadcast_parameters(parameters(s, 0., options)));
  }

  internal::Distributed_solve_report shifted_solve(const internal::Assembly_source& source, double s, double lambda,
                                                   const Complex_vector& b, const internal::Constraints& constraints,
                                                   const internal::Eigen_solve_options& options,
                                                   Complex_vector& u) const override
  {
    send_request(linear_solve_request);
    return collective_linear_solve(source, broadcast_parameters(parameters(s, lambda, options)), b, constraints, u);
  }
  /// \endcond

private:
  enum { finish_request = 0, eigenpair_request = 1, linear_solve_request = 2 };
  // A component with fewer vertices than this per process is solved on the
  // first process whatever the threshold: its share of rows would cost each
  // process more in collective calls than it saves (a mesh of many tiny
  // components would wait on the network for each).
  static constexpr std::size_t minimum_vertices_per_process = 32;

  // What every process needs to know of a request.
  struct Parameters
  {
    double s = 0., lambda = 0., tolerance = 0., max_iterations = 0.;
  };

  static Parameters parameters(double s, double lambda, const internal::Eigen_solve_options& options)
  {
    Parameters p;
    p.s = s;
    p.lambda = lambda;
    p.tolerance = options.residual_tolerance;
    p.max_iterations = static_cast<double>(options.max_iterations);
    return p;
  }

  void send_request(int request) const
  {
    CGAL_SMDF_MPI_CALL(MPI_Bcast(&request, 1, MPI_INT, 0, m_comm));
  }

  Parameters broadcast_parameters(Parameters p) const
  {
    CGAL_SMDF_MPI_CALL(MPI_Bcast(&p, sizeof(Parameters) / sizeof(double), MPI_DOUBLE, 0, m_comm));
    return p;
  }

  static PetscInt iteration_limit(const Parameters& p)
  {
    const double limit = (std::min)(p.max_iterations, double((std::numeric_limits<PetscInt>::max)()));
    return static_cast<PetscInt>(limit);
  }

  // A failure inside a request, on any process, ends every process after one
  // line (internal::run_collective_step): the others wait inside it.
  internal::Eigen_solve_result collective_eigenpair(const internal::Assembly_source& source,
                                                    const Parameters& p) const
  {
    return internal::run_collective_step("the distributed eigen-solve", [&] { return eigenpair(source, p); });
  }

  internal::Distributed_solve_report collective_linear_solve(const internal::Assembly_source& source,
                                                             const Parameters& p, const Complex_vector& b,
                                                             const internal::Constraints& constraints,
                                                             Complex_vector& u) const
  {
    return internal::run_collective_step("the distributed linear solve",
                                         [&] { return linear_solve(source, p, b, constraints, u); });
  }

  // Collective: the eigenpair, M-normalized, whole on the first process.
  internal::Eigen_solve_result eigenpair(const internal::Assembly_source& source, const Parameters& p) const
  {
    internal::Distributed_matrices matrices = internal::assemble_distributed(m_comm, source, p.s);
    internal::Distributed_eigen_solve_options options;
    options.residual_tolerance = p.tolerance;
    options.max_iterations = iteration_limit(p);
    PetscInt steps = options.refinement_steps;
    PetscBool given = PETSC_FALSE;
    CGAL_SMDF_PETSC_CALL(PetscOptionsGetInt(nullptr, nullptr, "-smdf_refinement_steps", &steps, &given));
    if(given && steps < 0)
      throw std::invalid_argument("-smdf_refinement_steps must be at least 0 (got " + std::to_string(steps) + ")");
    options.refinement_steps = steps;
    internal::Distributed_eigen_solve_result r =
      internal::distributed_smallest_eigenpair<Default_direction_field_solver>(matrices.energy, matrices.mass,
                                                                               options);
    internal::Eigen_solve_result result;
    result.eigenvalue = r.eigenvalue;
    result.residual = r.residual;
    result.iterations = static_cast<std::size_t>(r.iterations);
    result.converged = r.converged;
    if(r.vector)
    {
      normalize(matrices.mass, r.vector);
      result.vector = internal::gather_on_first_process(r.vector);
      CGAL_SMDF_PETSC_CALL(VecDestroy(&r.vector));
    }
    matrices.destroy();
    return result;
  }

  // x / ||x||_M
  static void normalize(Mat M, Vec x)
  {
    Vec Mx;
    CGAL_SMDF_PETSC_CALL(VecDuplicate(x, &Mx));
    CGAL_SMDF_PETSC_CALL(MatMult(M, x, Mx));
    PetscScalar squared;
    CGAL_SMDF_PETSC_CALL(VecDot(Mx, x, &squared));
    if(PetscRealPart(squared) > 0.) CGAL_SMDF_PETSC_CALL(VecScale(x, 1. / std::sqrt(PetscRealPart(squared))));
    CGAL_SMDF_PETSC_CALL(VecDestroy(&Mx));
  }

  // Collective: the solution of the shifted system, whole on the first process.
  internal::Distributed_solve_report linear_solve(const internal::Assembly_source& source, const Parameters& p,
                                                  const Complex_vector& b, const internal::Constraints& constraints,
                                                  Complex_vector& u) const
  {
    internal::Distributed_matrices matrices = internal::assemble_distributed(m_comm, source, p.s);
    const Complex_vector estimate = internal::aligned_across_processes(
      matrices.energy, matrices.mass,
      internal::local_eigenvector_estimate<Default_direction_field_solver>(matrices.energy, matrices.mass));
    // the right-hand side, the constrained rows and their values, from the first process
    Vec rhs = internal::scattered_from_first_process(matrices.energy, b);
    Complex_vector flags, values;
    if(m_rank == 0 && !constraints.empty())
    {
      flags = Complex_vector::Zero(static_cast<Eigen::Index>(constraints.is_constrained.size()));
      for(std::size_t i = 0; i < constraints.is_constrained.size(); ++i)
        if(constraints.is_constrained[i]) flags[static_cast<Eigen::Index>(i)] = 1.;
      values = constraints.values;
    }
    else if(m_rank == 0)
      flags = values = Complex_vector::Zero(b.size());
    Vec flag_vector = internal::scattered_from_first_process(matrices.energy, flags);
    Vec value_vector = internal::scattered_from_first_process(matrices.energy, values);
    internal::Distributed_linear_solve_result r =
      internal::shifted_solve_in_gauge(matrices.energy, matrices.mass, p.lambda, rhs,
                                       internal::flagged_rows(flag_vector), value_vector, estimate, p.tolerance,
                                       iteration_limit(p));
    u = internal::gather_on_first_process(r.solution);
    for(Vec* v : {&rhs, &flag_vector, &value_vector, &r.solution}) CGAL_SMDF_PETSC_CALL(VecDestroy(v));
    matrices.destroy();
    internal::Distributed_solve_report report;
    report.converged = r.converged;
    report.iterations = static_cast<std::size_t>(r.iterations);
    report.residual = r.residual;
    return report;
  }

  MPI_Comm m_comm;
  int m_rank = 0, m_size = 1;
  std::size_t m_minimum_vertices;
};

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_PETSC_DISTRIBUTED_SOLVER_H
