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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_DISTRIBUTED_LINEAR_SOLVE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_DISTRIBUTED_LINEAR_SOLVE_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/distributed_eigen_solve.h>

#include <petscksp.h>

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
  MatCreateVecs(S, &v, nullptr);
  VecScatterCreateToZero(v, &to_zero, &all);
  PetscInt size;
  VecGetLocalSize(all, &size);
  PetscScalar* values;
  VecGetArray(all, &values);
  for(PetscInt i = 0; i < size; ++i) values[i] = whole[static_cast<Eigen::Index>(i)];
  VecRestoreArray(all, &values);
  VecScatterBegin(to_zero, all, v, INSERT_VALUES, SCATTER_REVERSE);
  VecScatterEnd(to_zero, all, v, INSERT_VALUES, SCATTER_REVERSE);
  VecScatterDestroy(&to_zero);
  VecDestroy(&all);
  return v;
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
  VecGetOwnershipRange(flags, &first, &last);
  const PetscScalar* values;
  VecGetArrayRead(flags, &values);
  std::vector<PetscInt> rows;
  for(PetscInt i = first; i < last; ++i)
    if(values[i - first] != PetscScalar(0.)) rows.push_back(i);
  VecRestoreArrayRead(flags, &values);
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
  MatDuplicate(A, MAT_COPY_VALUES, &K);
  MatAXPY(K, -lambda, M, SAME_NONZERO_PATTERN);
  VecDuplicate(b, &rhs);
  VecCopy(b, rhs);
  MatZeroRowsColumns(K, static_cast<PetscInt>(constrained_rows.size()), constrained_rows.data(), 1., values, rhs);
  MatSetOption(K, MAT_HERMITIAN, PETSC_TRUE);
  const Gauge gauge(A, estimate);
  gauge.enter(K);
  gauge.enter(rhs);
  set_near_null_vector(K, gauge.modulus);

  KSP ksp;
  PC pc;
  KSPCreate(PetscObjectComm(reinterpret_cast<PetscObject>(A)), &ksp);
  KSPSetOperators(ksp, K, K);
  KSPSetType(ksp, KSPCG);
  KSPSetNormType(ksp, KSP_NORM_UNPRECONDITIONED);
  KSPSetTolerances(ksp, tolerance, PETSC_DEFAULT, PETSC_DEFAULT, max_iterations);
  KSPGetPC(ksp, &pc);
  PCSetType(pc, PCGAMG);
  // Unsmoothed aggregation: smoothing the prolongation with the complex
  // matrix makes it complex, and PETSc's coarse operator P^T K P is then not
  // Hermitian, nor is the preconditioner: conjugate gradients broke down on 4
  // processes (plane_holes.off, constrained boundary). The aggregates' own
  // prolongation, built from the real near-null vector, stays real.
  PCGAMGSetNSmooths(pc, 0);
  KSPSetFromOptions(ksp);
  Distributed_linear_solve_result result;
  VecDuplicate(b, &result.solution);
  KSPSolve(ksp, rhs, result.solution);
  KSPConvergedReason reason;
  KSPGetConvergedReason(ksp, &reason);
  KSPGetIterationNumber(ksp, &result.iterations);
  PetscReal residual_norm, rhs_norm;
  KSPGetResidualNorm(ksp, &residual_norm);
  VecNorm(rhs, NORM_2, &rhs_norm);
  result.residual = rhs_norm > 0. ? residual_norm / rhs_norm : 0.;
  result.converged = reason > 0;
  gauge.leave(result.solution);
  KSPDestroy(&ksp);
  VecDestroy(&rhs);
  MatDestroy(&K);
  return result;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_DISTRIBUTED_LINEAR_SOLVE_H
