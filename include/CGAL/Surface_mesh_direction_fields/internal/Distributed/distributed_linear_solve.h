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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_DISTRIBUTED_LINEAR_SOLVE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_DISTRIBUTED_LINEAR_SOLVE_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Distributed/distributed_eigen_solve.h>

#include <petscksp.h>

#include <stdexcept>
#include <string>
#include <vector>

// The aligned and constrained fields over MPI processes (user manual,
// section "Several Processes"): (A - lambda M) u = b with u = c on the
// constrained vertices, by conjugate gradients preconditioned with GAMG,
// in the gauge of a rough eigenvector, for the reason given at the top of
// distributed_eigen_solve.h: the matrix's nearly null fields are the locally
// parallel ones, which the gauge makes real.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// A vector laid out like the rows of S, filled from `whole` given on rank 0
// (ignored on the others).
inline Vec scattered_from_first_process(Mat S, const Complex_vector& whole)
{
  Vec v, all;
  VecScatter to_zero;
  CGAL_SMDF_PETSC_CALL(MatCreateVecs(S, &v, nullptr));
  CGAL_SMDF_PETSC_CALL(VecScatterCreateToZero(v, &to_zero, &all));
  PetscInt size;
  CGAL_SMDF_PETSC_CALL(VecGetLocalSize(all, &size));
  PetscScalar* values;
  CGAL_SMDF_PETSC_CALL(VecGetArray(all, &values));
  for(PetscInt i = 0; i < size; ++i) values[i] = whole[static_cast<Eigen::Index>(i)];
  CGAL_SMDF_PETSC_CALL(VecRestoreArray(all, &values));
  CGAL_SMDF_PETSC_CALL(VecScatterBegin(to_zero, all, v, INSERT_VALUES, SCATTER_REVERSE));
  CGAL_SMDF_PETSC_CALL(VecScatterEnd(to_zero, all, v, INSERT_VALUES, SCATTER_REVERSE));
  CGAL_SMDF_PETSC_CALL(VecScatterDestroy(&to_zero));
  CGAL_SMDF_PETSC_CALL(VecDestroy(&all));
  return v;
}

// PETSc takes a negative -ksp_max_it and then stops at once, unconverged,
// which would read as a matrix that is not positive definite: such an option
// is refused (on every process alike, as every process reads it).
inline void check_iteration_limit(KSP ksp, const char* option)
{
  PetscReal relative, absolute, divergence;
  PetscInt limit;
  CGAL_SMDF_PETSC_CALL(KSPGetTolerances(ksp, &relative, &absolute, &divergence, &limit));
  if(limit < 1)
    throw std::invalid_argument(std::string(option) + " must be at least 1 (got " + std::to_string(limit) + ")");
}

struct Distributed_linear_solve_result
{
  bool converged = false;
  PetscInt iterations = 0;
  double residual = 0.;  // ||b - K u|| / ||b||
  Vec solution = nullptr;  // the caller destroys it
};

// The rows of this process flagged by a nonzero entry of `flags`.
inline std::vector<PetscInt> flagged_rows(Vec flags)
{
  PetscInt first, last;
  CGAL_SMDF_PETSC_CALL(VecGetOwnershipRange(flags, &first, &last));
  const PetscScalar* values;
  CGAL_SMDF_PETSC_CALL(VecGetArrayRead(flags, &values));
  std::vector<PetscInt> rows;
  for(PetscInt i = first; i < last; ++i)
    if(values[i - first] != PetscScalar(0.)) rows.push_back(i);
  CGAL_SMDF_PETSC_CALL(VecRestoreArrayRead(flags, &values));
  return rows;
}

// u with (A - lambda M) u = b on the rows not in `constrained_rows` (this
// process's share of them) and u = `values` on those rows, in the gauge of
// `estimate` (this process's entries of a rough smallest eigenvector). The
// constrained rows and columns become rows of the identity, their
// contribution moved to the right-hand side (PETSc's MatZeroRowsColumns), so
// that the matrix stays Hermitian for conjugate gradients. PETSc's -ksp_* and
// -pc_* options given at run time override these choices.
inline Distributed_linear_solve_result shifted_solve_in_gauge(Mat A, Mat M, double lambda, Vec b,
                                                              const std::vector<PetscInt>& constrained_rows,
                                                              Vec values, const Complex_vector& estimate,
                                                              double tolerance, PetscInt max_iterations)
{
  Mat K;
  Vec rhs;
  CGAL_SMDF_PETSC_CALL(MatDuplicate(A, MAT_COPY_VALUES, &K));
  CGAL_SMDF_PETSC_CALL(MatAXPY(K, -lambda, M, SAME_NONZERO_PATTERN));
  CGAL_SMDF_PETSC_CALL(VecDuplicate(b, &rhs));
  CGAL_SMDF_PETSC_CALL(VecCopy(b, rhs));
  CGAL_SMDF_PETSC_CALL(MatZeroRowsColumns(K, static_cast<PetscInt>(constrained_rows.size()), constrained_rows.data(), 1., values, rhs));
  CGAL_SMDF_PETSC_CALL(MatSetOption(K, MAT_HERMITIAN, PETSC_TRUE));
  const Gauge gauge(A, estimate);
  gauge.enter(K);
  gauge.enter(rhs);
  set_near_null_vector(K, gauge.modulus);

  KSP ksp;
  PC pc;
  CGAL_SMDF_PETSC_CALL(KSPCreate(PetscObjectComm(reinterpret_cast<PetscObject>(A)), &ksp));
  CGAL_SMDF_PETSC_CALL(KSPSetOperators(ksp, K, K));
  CGAL_SMDF_PETSC_CALL(KSPSetType(ksp, KSPCG));
  CGAL_SMDF_PETSC_CALL(KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED));
  CGAL_SMDF_PETSC_CALL(KSPSetTolerances(ksp, tolerance, PETSC_DEFAULT, PETSC_DEFAULT, max_iterations));
  CGAL_SMDF_PETSC_CALL(KSPGetPC(ksp, &pc));
  CGAL_SMDF_PETSC_CALL(PCSetType(pc, PCGAMG));
  // Unsmoothed aggregation: smoothing the prolongation with the complex
  // matrix makes it complex, and PETSc's coarse operator P^T K P is then not
  // Hermitian, nor is the preconditioner: conjugate gradients broke down on 4
  // processes (plane_holes.off, constrained boundary). The aggregates' own
  // prolongation, built from the real near-null vector, stays real.
  CGAL_SMDF_PETSC_CALL(PCGAMGSetNSmooths(pc, 0));
  CGAL_SMDF_PETSC_CALL(KSPSetFromOptions(ksp));
  check_iteration_limit(ksp, "-ksp_max_it");
  Distributed_linear_solve_result result;
  CGAL_SMDF_PETSC_CALL(VecDuplicate(b, &result.solution));
  CGAL_SMDF_PETSC_CALL(KSPSolve(ksp, rhs, result.solution));
  KSPConvergedReason reason;
  CGAL_SMDF_PETSC_CALL(KSPGetConvergedReason(ksp, &reason));
  CGAL_SMDF_PETSC_CALL(KSPGetIterationNumber(ksp, &result.iterations));
  PetscReal residual_norm, rhs_norm;
  CGAL_SMDF_PETSC_CALL(KSPGetResidualNorm(ksp, &residual_norm));
  CGAL_SMDF_PETSC_CALL(VecNorm(rhs, NORM_2, &rhs_norm));
  result.residual = rhs_norm > 0. ? residual_norm / rhs_norm : 0.;
  result.converged = reason > 0;
  gauge.leave(result.solution);
  CGAL_SMDF_PETSC_CALL(KSPDestroy(&ksp));
  CGAL_SMDF_PETSC_CALL(VecDestroy(&rhs));
  CGAL_SMDF_PETSC_CALL(MatDestroy(&K));
  return result;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_DISTRIBUTED_LINEAR_SOLVE_H
