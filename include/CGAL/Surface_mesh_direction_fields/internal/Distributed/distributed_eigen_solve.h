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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_DISTRIBUTED_EIGEN_SOLVE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_DISTRIBUTED_EIGEN_SOLVE_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/dense_kernels.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Distributed/distributed_lobpcg.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/eigen_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Distributed/petsc_calls.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/shifted_matrix.h>

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <vector>

// The smallest eigenpair of a Hermitian pencil (A, M) whose rows are spread
// over MPI processes (PETSc matrices), without a factorization of the whole
// matrix: LOBPCG (SLEPc) preconditioned by smoothed-aggregation multigrid
// (PETSc's GAMG) on A + epsilon M (user manual, section "Several Processes").
//
// GAMG builds its coarse spaces from a near-null vector, by default the
// constant one. For a connection Laplacian the fields of nearly zero energy
// are the locally parallel ones, whose coefficients turn from vertex to
// vertex with the transport: the constant vector is far from them, and GAMG
// then barely helps. Giving GAMG a complex near-null vector does not work
// either: PETSc's multigrid restricts with the transpose of the prolongation,
// not its adjoint, so a complex prolongation makes the preconditioner
// non-Hermitian. Hence a change of gauge: with a rough estimate b of the
// eigenvector and the unit phases d_i = b_i / |b_i|, the pencil
// (D^* A D, D^* M D), D = diag(d), has the same eigenvalues, eigenvectors
// D^* x, and the real vector |b| as a near-null vector: GAMG's prolongation
// stays real. Each process estimates b on its own block of the pencil (the
// rows and columns of its vertices, the couplings to other processes left
// out) with the package's coarse estimate, so no process needs more than its
// part.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// This process's diagonal block of a PETSc matrix (rows and columns of its
// range) as a compressed-column Eigen matrix.
inline Complex_sparse_matrix local_diagonal_block(Mat S)
{
  Mat block;
  CGAL_SMDF_PETSC_CALL(MatGetDiagonalBlock(S, &block));
  PetscInt rows, columns;
  CGAL_SMDF_PETSC_CALL(MatGetSize(block, &rows, &columns));
  std::vector<Eigen::Triplet<Complex> > entries;
  for(PetscInt r = 0; r < rows; ++r)
  {
    PetscInt count;
    const PetscInt* cols;
    const PetscScalar* values;
    CGAL_SMDF_PETSC_CALL(MatGetRow(block, r, &count, &cols, &values));
    for(PetscInt k = 0; k < count; ++k) entries.emplace_back(r, cols[k], values[k]);
    CGAL_SMDF_PETSC_CALL(MatRestoreRow(block, r, &count, &cols, &values));
  }
  Complex_sparse_matrix result(rows, columns);
  result.setFromTriplets(entries.begin(), entries.end());
  return result;
}

// Blocks of at most this many rows are solved as dense matrices.
constexpr Eigen::Index dense_block_size = 200;

// A rough estimate of the smallest eigenvector of this process's block:
// the coarse estimate (aggregation levels, smoothed), or, when the block is
// too small for aggregation to pay, its smallest eigenvector to a loose
// tolerance (exactly for a tiny block).
template <typename SparseSolver>
Complex_vector local_eigenvector_estimate(Mat A, Mat M)
{
  const Complex_sparse_matrix A_local = local_diagonal_block(A), M_local = local_diagonal_block(M);
  if(A_local.rows() == 0) return Complex_vector();
  if(A_local.rows() <= dense_block_size)  // a few faces: exactly, and without a factorization that may fail
  {
    const Eigen::MatrixXcd A_dense(A_local), M_dense(M_local);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXcd> dense(A_dense, M_dense);
    if(dense.info() == Eigen::Success) return dense.eigenvectors().col(0);
    return Complex_vector::Ones(A_local.rows());
  }
  Eigen_solve_options options;
  options.residual_tolerance = options.coarse_tolerance;
  Coarse_estimate coarse =
    coarse_estimate<SparseSolver>(A_local, M_local, have_same_pattern(A_local, M_local), options);
  if(coarse.vector.size() == A_local.rows()) return coarse.vector;
  SparseSolver solver;
  Factored_matrix<SparseSolver> factored(solver);
  try
  {
    return smallest_eigenpair(A_local, M_local, factored, options).vector;
  }
  catch(const Solver_failure_error&)
  {
    return Complex_vector::Ones(A_local.rows());
  }
}

// A new vector laid out like the rows of S, with this process's entries.
inline Vec vector_like(Mat S, const Complex_vector& local)
{
  Vec v;
  CGAL_SMDF_PETSC_CALL(MatCreateVecs(S, &v, nullptr));
  PetscScalar* values;
  CGAL_SMDF_PETSC_CALL(VecGetArray(v, &values));
  for(Eigen::Index i = 0; i < local.size(); ++i) values[i] = local[i];
  CGAL_SMDF_PETSC_CALL(VecRestoreArray(v, &values));
  return v;
}

// The estimates of the processes are each right up to a factor of their
// own (a phase and a scale), which leaves jumps at the borders between
// processes. The factors c_r that make sum_r c_r b_r best are the smallest
// eigenvector of the pencil projected onto the pieces b_r (one per process,
// zero elsewhere): a Rayleigh-Ritz step on K vectors, K products with A
// and M. Returns this process's piece times its factor.
inline Complex_vector aligned_across_processes(Mat A, Mat M, const Complex_vector& local)
{
  MPI_Comm comm = PetscObjectComm(reinterpret_cast<PetscObject>(A));
  int processes, rank;
  CGAL_SMDF_MPI_CALL(MPI_Comm_size(comm, &processes));
  CGAL_SMDF_MPI_CALL(MPI_Comm_rank(comm, &rank));
  if(processes == 1) return local;
  Eigen::MatrixXcd projected_a(processes, processes), projected_m(processes, processes);
  Vec piece, product;
  CGAL_SMDF_PETSC_CALL(MatCreateVecs(A, &piece, &product));
  for(int s = 0; s < processes; ++s)
  {
    PetscScalar* values;
    CGAL_SMDF_PETSC_CALL(VecGetArray(piece, &values));
    for(Eigen::Index i = 0; i < local.size(); ++i) values[i] = rank == s ? local[i] : Complex(0., 0.);
    CGAL_SMDF_PETSC_CALL(VecRestoreArray(piece, &values));
    for(int which = 0; which < 2; ++which)
    {
      CGAL_SMDF_PETSC_CALL(MatMult(which == 0 ? A : M, piece, product));  // row r of column s: b_r^* (S b_s), summed on process r
      const PetscScalar* p;
      CGAL_SMDF_PETSC_CALL(VecGetArrayRead(product, &p));
      Complex mine(0., 0.);
      for(Eigen::Index i = 0; i < local.size(); ++i) mine += std::conj(local[i]) * p[i];
      CGAL_SMDF_PETSC_CALL(VecRestoreArrayRead(product, &p));
      Eigen::MatrixXcd& projected = which == 0 ? projected_a : projected_m;
      CGAL_SMDF_MPI_CALL(MPI_Allgather(&mine, 1, MPI_C_DOUBLE_COMPLEX, projected.col(s).data(), 1, MPI_C_DOUBLE_COMPLEX, comm));
    }
  }
  CGAL_SMDF_PETSC_CALL(VecDestroy(&piece));
  CGAL_SMDF_PETSC_CALL(VecDestroy(&product));
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXcd> ritz((projected_a + projected_a.adjoint()) / 2.,
                                                                  (projected_m + projected_m.adjoint()) / 2.);
  if(ritz.info() != Eigen::Success) return local;
  return local * ritz.eigenvectors().col(0)[rank];
}

// The vector GAMG builds its coarse spaces from.
inline void set_near_null_vector(Mat S, Vec near_null)
{
  MatNullSpace space;
  CGAL_SMDF_PETSC_CALL(MatNullSpaceCreate(PetscObjectComm(reinterpret_cast<PetscObject>(S)), PETSC_FALSE, 1, &near_null, &space));
  CGAL_SMDF_PETSC_CALL(MatSetNearNullSpace(S, space));
  CGAL_SMDF_PETSC_CALL(MatNullSpaceDestroy(&space));
}

// A + epsilon M, with the near-null vector `near_null` for GAMG.
inline Mat shifted_preconditioner_matrix(Mat A, Mat M, double epsilon, Vec near_null)
{
  Mat P;
  CGAL_SMDF_PETSC_CALL(MatDuplicate(A, MAT_COPY_VALUES, &P));
  CGAL_SMDF_PETSC_CALL(MatAXPY(P, epsilon, M, SAME_NONZERO_PATTERN));
  CGAL_SMDF_PETSC_CALL(MatSetOption(P, MAT_HERMITIAN, PETSC_TRUE));
  set_near_null_vector(P, near_null);
  return P;
}

// LOBPCG on (A, M) preconditioned by GAMG on P, started from `start`; PETSc's
// options (-eps_*, -st_*) given at run time override these choices.
inline Distributed_eigen_solve_result lobpcg_with_multigrid(Mat A, Mat M, Mat P, Vec start,
                                                            const Distributed_eigen_solve_options& options)
{
  Distributed_eigen_solve_result result;
  EPS eps;
  ST st;
  KSP ksp;
  PC pc;
  CGAL_SMDF_PETSC_CALL(EPSCreate(PetscObjectComm(reinterpret_cast<PetscObject>(A)), &eps));
  CGAL_SMDF_PETSC_CALL(EPSSetOperators(eps, A, M));
  CGAL_SMDF_PETSC_CALL(EPSSetProblemType(eps, EPS_GHEP));
  CGAL_SMDF_PETSC_CALL(EPSSetType(eps, EPSLOBPCG));
  CGAL_SMDF_PETSC_CALL(EPSSetWhichEigenpairs(eps, EPS_SMALLEST_REAL));
  CGAL_SMDF_PETSC_CALL(EPSSetDimensions(eps, 1, PETSC_DEFAULT, PETSC_DEFAULT));
  CGAL_SMDF_PETSC_CALL(EPSSetTolerances(eps, options.residual_tolerance, options.max_iterations));
  CGAL_SMDF_PETSC_CALL(EPSGetST(eps, &st));
  CGAL_SMDF_PETSC_CALL(STSetType(st, STPRECOND));
  CGAL_SMDF_PETSC_CALL(STSetPreconditionerMat(st, P));
  CGAL_SMDF_PETSC_CALL(STGetKSP(st, &ksp));
  CGAL_SMDF_PETSC_CALL(KSPSetType(ksp, KSPPREONLY));
  CGAL_SMDF_PETSC_CALL(KSPGetPC(ksp, &pc));
  CGAL_SMDF_PETSC_CALL(PCSetType(pc, PCGAMG));
  CGAL_SMDF_PETSC_CALL(EPSSetInitialSpace(eps, 1, &start));
  CGAL_SMDF_PETSC_CALL(EPSSetFromOptions(eps));
  PetscInt converged = 0;
  CGAL_SMDF_PETSC_CALL(EPSSolve(eps));
  CGAL_SMDF_PETSC_CALL(EPSGetConverged(eps, &converged));
  if(converged > 0)
  {
    PetscScalar lambda;
    CGAL_SMDF_PETSC_CALL(MatCreateVecs(A, &result.vector, nullptr));
    CGAL_SMDF_PETSC_CALL(EPSGetEigenpair(eps, 0, &lambda, nullptr, result.vector, nullptr));
    result.eigenvalue = PetscRealPart(lambda);
    result.converged = true;
  }
  CGAL_SMDF_PETSC_CALL(EPSGetIterationNumber(eps, &result.iterations));
  CGAL_SMDF_PETSC_CALL(EPSDestroy(&eps));
  return result;
}

// The change of gauge of an estimate b (see the note at the top): the unit
// phases d = b / |b|, their conjugates, and |b| normalized, the real
// near-null vector of the matrices in that gauge; each process holds its
// rows.
class Gauge
{
public:
  Gauge(Mat S, const Complex_vector& estimate)
  {
    d = vector_like(S, estimate.unaryExpr([](const Complex& z) { return unit(z); }));
    modulus = vector_like(S, estimate.cwiseAbs().cast<Complex>());
    CGAL_SMDF_PETSC_CALL(VecNormalize(modulus, nullptr));
    CGAL_SMDF_PETSC_CALL(VecDuplicate(d, &d_conjugate));
    CGAL_SMDF_PETSC_CALL(VecCopy(d, d_conjugate));
    CGAL_SMDF_PETSC_CALL(VecConjugate(d_conjugate));
  }
  ~Gauge()
  {
    for(Vec* v : {&d, &d_conjugate, &modulus}) CGAL_SMDF_PETSC_CALL(VecDestroy(v));
  }
  Gauge(const Gauge&) = delete;
  Gauge& operator=(const Gauge&) = delete;

  void enter(Mat S) const { CGAL_SMDF_PETSC_CALL(MatDiagonalScale(S, d_conjugate, d)); }  // S <- D^* S D
  void leave(Mat S) const { CGAL_SMDF_PETSC_CALL(MatDiagonalScale(S, d, d_conjugate)); }  // S <- D S D^*
  void enter(Vec v) const { CGAL_SMDF_PETSC_CALL(VecPointwiseMult(v, v, d_conjugate)); }  // v <- D^* v
  void leave(Vec v) const { CGAL_SMDF_PETSC_CALL(VecPointwiseMult(v, v, d)); }            // v <- D v

  Vec d = nullptr, d_conjugate = nullptr, modulus = nullptr;
};

// The trace ratio s_A = trace(A) / trace(M), the scale of eigen_solve.h.
inline double distributed_eigenvalue_scale(Mat A, Mat M)
{
  PetscScalar trace_a, trace_m;
  CGAL_SMDF_PETSC_CALL(MatGetTrace(A, &trace_a));
  CGAL_SMDF_PETSC_CALL(MatGetTrace(M, &trace_m));
  return PetscRealPart(trace_a) / PetscRealPart(trace_m);
}

// The smallest eigenpair of (A, M), both Hermitian with the same pattern and
// row distribution, in the gauge of `estimate` (this process's entries of a
// rough eigenvector; see the note at the top). A and M are rotated into that
// gauge and back; the eigenvector is returned in the original gauge.
inline Distributed_eigen_solve_result smallest_eigenpair_in_gauge(Mat A, Mat M, const Complex_vector& estimate,
                                                                  const Distributed_eigen_solve_options& options)
{
  const Gauge gauge(A, estimate);
  gauge.enter(A);
  gauge.enter(M);
  const double scale = distributed_eigenvalue_scale(A, M);
  Mat P = shifted_preconditioner_matrix(A, M, options.relative_shift * scale, gauge.modulus);
  Distributed_eigen_solve_result result;
  if(options.slepc_lobpcg)
    result = lobpcg_with_multigrid(A, M, P, gauge.modulus, options);
  else
  {
    KSP preconditioner = multigrid_preconditioner(P);
    Single_vector_lobpcg lobpcg(A, M, preconditioner);
    result = lobpcg.run(gauge.modulus, scale, options);
    CGAL_SMDF_PETSC_CALL(KSPDestroy(&preconditioner));
  }
  if(result.vector) gauge.leave(result.vector);
  gauge.leave(A);
  gauge.leave(M);
  CGAL_SMDF_PETSC_CALL(MatDestroy(&P));
  return result;
}

// The fraction of the entries of x (over all processes) whose modulus is
// below `relative` times the largest.
inline double fraction_below(Vec x, double relative)
{
  Vec modulus;
  CGAL_SMDF_PETSC_CALL(VecDuplicate(x, &modulus));
  CGAL_SMDF_PETSC_CALL(VecCopy(x, modulus));
  CGAL_SMDF_PETSC_CALL(VecAbs(modulus));
  PetscReal largest;
  CGAL_SMDF_PETSC_CALL(VecMax(modulus, nullptr, &largest));
  PetscInt size, global_size;
  CGAL_SMDF_PETSC_CALL(VecGetLocalSize(modulus, &size));
  CGAL_SMDF_PETSC_CALL(VecGetSize(modulus, &global_size));
  const PetscScalar* values;
  CGAL_SMDF_PETSC_CALL(VecGetArrayRead(modulus, &values));
  long long below = 0, total_below = 0;
  for(PetscInt i = 0; i < size; ++i)
    if(PetscRealPart(values[i]) < relative * largest) ++below;
  CGAL_SMDF_PETSC_CALL(VecRestoreArrayRead(modulus, &values));
  CGAL_SMDF_MPI_CALL(MPI_Allreduce(&below, &total_below, 1, MPI_LONG_LONG, MPI_SUM,
                                   PetscObjectComm(reinterpret_cast<PetscObject>(x))));
  CGAL_SMDF_PETSC_CALL(VecDestroy(&modulus));
  return global_size > 0 ? double(total_below) / double(global_size) : 0.;
}

// Whether PETSc can factor A over the processes (MUMPS's LU; PETSc's own
// factorizations are for one process).
inline bool distributed_factorization_available(Mat A)
{
  PetscBool available = PETSC_FALSE;
  CGAL_SMDF_PETSC_CALL(MatGetFactorAvailable(A, MATSOLVERMUMPS, MAT_FACTOR_LU, &available));
  return available == PETSC_TRUE;
}

// Whether every process has the address space for its share of the factor
// of A and for the BLAS's work buffers. Under an address-space limit,
// OpenBLAS's allocator retries forever when it cannot map its buffers
// (inside MUMPS's dense kernels here, as in dense_kernels.h), so the space is
// checked before. The share is taken as 30 times the process's entries of
// A, above the LU fill of the meshes measured (about 13 times at 400,000
// faces).
inline bool room_for_distributed_factorization(Mat A)
{
  MatInfo info;
  CGAL_SMDF_PETSC_CALL(MatGetInfo(A, MAT_LOCAL, &info));
  const std::size_t factor_bytes = static_cast<std::size_t>(30. * info.nz_used * sizeof(PetscScalar));
  int room = blas_work_space_available(factor_bytes) ? 1 : 0;
  int everywhere = 0;
  CGAL_SMDF_MPI_CALL(MPI_Allreduce(&room, &everywhere, 1, MPI_INT, MPI_MIN,
                                   PetscObjectComm(reinterpret_cast<PetscObject>(A))));
  return everywhere == 1;
}

// Whether any process's factorization or solve failed (MUMPS returns no
// error code when it runs out of memory, only a failed preconditioner), or
// gave a vector that is not finite.
inline bool solve_failed_anywhere(KSP ksp, Vec y)
{
  PC pc;
  PCFailedReason pc_reason = PC_NOERROR;
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  CGAL_SMDF_PETSC_CALL(KSPGetPC(ksp, &pc));
  CGAL_SMDF_PETSC_CALL(PCGetFailedReasonRank(pc, &pc_reason));
  if(y != nullptr) CGAL_SMDF_PETSC_CALL(KSPGetConvergedReason(ksp, &reason));
  int failed = pc_reason != PC_NOERROR || reason < 0;
  if(y != nullptr && !failed)
  {
    PetscReal norm;
    CGAL_SMDF_PETSC_CALL(VecNorm(y, NORM_2, &norm));
    failed = !std::isfinite(norm);
  }
  int anywhere = 0;
  CGAL_SMDF_MPI_CALL(MPI_Allreduce(&failed, &anywhere, 1, MPI_INT, MPI_MAX, PetscObjectComm(reinterpret_cast<PetscObject>(ksp))));
  return anywhere != 0;
}

// The Rayleigh quotient and residual (as LOBPCG's) of x, M-normalized in place.
inline void rayleigh_quotient_and_residual(Mat A, Mat M, double scale, Vec x, Distributed_eigen_solve_result& result)
{
  Vec Mx, Ax;
  CGAL_SMDF_PETSC_CALL(VecDuplicate(x, &Mx));
  CGAL_SMDF_PETSC_CALL(VecDuplicate(x, &Ax));
  CGAL_SMDF_PETSC_CALL(MatMult(M, x, Mx));
  PetscScalar squared;
  CGAL_SMDF_PETSC_CALL(VecDot(Mx, x, &squared));
  const double norm = std::sqrt((std::max)(0., PetscRealPart(squared)));
  if(norm > 0.)
  {
    CGAL_SMDF_PETSC_CALL(VecScale(x, 1. / norm));
    CGAL_SMDF_PETSC_CALL(VecScale(Mx, 1. / norm));
  }
  CGAL_SMDF_PETSC_CALL(MatMult(A, x, Ax));
  PetscScalar rayleigh;
  CGAL_SMDF_PETSC_CALL(VecDot(Ax, x, &rayleigh));
  result.eigenvalue = PetscRealPart(rayleigh);
  CGAL_SMDF_PETSC_CALL(VecAXPY(Ax, -result.eigenvalue, Mx));  // the residual A x - lambda M x
  PetscReal r_norm, mx_norm;
  CGAL_SMDF_PETSC_CALL(VecNorm(Ax, NORM_2, &r_norm));
  CGAL_SMDF_PETSC_CALL(VecNorm(Mx, NORM_2, &mx_norm));
  result.residual = r_norm / (scale * mx_norm);
  CGAL_SMDF_PETSC_CALL(VecDestroy(&Mx));
  CGAL_SMDF_PETSC_CALL(VecDestroy(&Ax));
}

// Inverse iteration on one distributed factorization of A + epsilon M (the
// shift of the single-process solve), started from `result`'s vector. An
// iterative eigen-solve is accurate relative to the largest entry of its
// vector: where the field is many orders smaller than that, its directions
// are noise. Each step of inverse iteration solves with the whole matrix,
// like the single process, and the directions there become the single
// process's. At least one step, at most `max_steps`, fewer once the
// tolerance is reached. If the factorization or a solve fails on any
// process (out of memory, say), `result` keeps the last good vector.
inline void refine_by_inverse_iteration(Mat A, Mat M, double scale, const Distributed_eigen_solve_options& options,
                                        PetscInt max_steps, Distributed_eigen_solve_result& result)
{
  Mat K;
  KSP ksp;
  PC pc;
  CGAL_SMDF_PETSC_CALL(MatDuplicate(A, MAT_COPY_VALUES, &K));
  CGAL_SMDF_PETSC_CALL(MatAXPY(K, options.relative_shift * scale, M, SAME_NONZERO_PATTERN));
  CGAL_SMDF_PETSC_CALL(KSPCreate(PetscObjectComm(reinterpret_cast<PetscObject>(A)), &ksp));
  CGAL_SMDF_PETSC_CALL(KSPSetOperators(ksp, K, K));
  CGAL_SMDF_PETSC_CALL(KSPSetType(ksp, KSPPREONLY));
  CGAL_SMDF_PETSC_CALL(KSPGetPC(ksp, &pc));
  CGAL_SMDF_PETSC_CALL(PCSetType(pc, PCLU));
  CGAL_SMDF_PETSC_CALL(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  CGAL_SMDF_PETSC_CALL(KSPSetOptionsPrefix(ksp, "refine_"));
  CGAL_SMDF_PETSC_CALL(KSPSetFromOptions(ksp));
  CGAL_SMDF_PETSC_CALL(KSPSetUp(ksp));
  if(!solve_failed_anywhere(ksp, nullptr))
  {
    Vec Mx, y;
    CGAL_SMDF_PETSC_CALL(VecDuplicate(result.vector, &Mx));
    CGAL_SMDF_PETSC_CALL(VecDuplicate(result.vector, &y));
    for(PetscInt step = 0; step < max_steps && (step == 0 || !result.converged); ++step)
    {
      CGAL_SMDF_PETSC_CALL(MatMult(M, result.vector, Mx));
      CGAL_SMDF_PETSC_CALL(KSPSolve(ksp, Mx, y));
      if(solve_failed_anywhere(ksp, y)) break;
      CGAL_SMDF_PETSC_CALL(VecCopy(y, result.vector));
      rayleigh_quotient_and_residual(A, M, scale, result.vector, result);
      result.converged = result.residual <= options.residual_tolerance;
      ++result.iterations;
    }
    CGAL_SMDF_PETSC_CALL(VecDestroy(&Mx));
    CGAL_SMDF_PETSC_CALL(VecDestroy(&y));
  }
  CGAL_SMDF_PETSC_CALL(KSPDestroy(&ksp));
  CGAL_SMDF_PETSC_CALL(MatDestroy(&K));
}

// The smallest eigenpair of (A, M) in the gauge of the processes' own
// estimates, aligned.
template <typename SparseSolver>
Distributed_eigen_solve_result distributed_smallest_eigenpair(Mat A, Mat M, const Distributed_eigen_solve_options& options)
{
  const Complex_vector estimate = aligned_across_processes(A, M, local_eigenvector_estimate<SparseSolver>(A, M));
  if(options.slepc_lobpcg) return smallest_eigenpair_in_gauge(A, M, estimate, options);  // (no restart)
  Distributed_eigen_solve_options first_options = options;
  first_options.residual_tolerance = (std::max)(options.residual_tolerance, options.regauge_tolerance);
  first_options.max_iterations = (std::min)(options.max_iterations, options.regauge_iterations);
  Distributed_eigen_solve_result first = smallest_eigenpair_in_gauge(A, M, estimate, first_options);
  if(first.residual <= options.residual_tolerance || !first.vector) return first;
  const PetscScalar* values;
  PetscInt size;
  CGAL_SMDF_PETSC_CALL(VecGetLocalSize(first.vector, &size));
  CGAL_SMDF_PETSC_CALL(VecGetArrayRead(first.vector, &values));
  const Complex_vector better = Eigen::Map<const Complex_vector>(values, size);
  CGAL_SMDF_PETSC_CALL(VecRestoreArrayRead(first.vector, &values));
  CGAL_SMDF_PETSC_CALL(VecDestroy(&first.vector));
  const bool can_refine = options.refinement_steps > 0 && distributed_factorization_available(A);
  Distributed_eigen_solve_options second_options = options;
  if(can_refine) second_options.max_iterations = (std::min)(options.max_iterations, options.iterations_before_refining);
  Distributed_eigen_solve_result result = smallest_eigenpair_in_gauge(A, M, better, second_options);
  result.iterations += first.iterations;
  if(can_refine && result.vector &&
     (!result.converged ||
      fraction_below(result.vector, low_magnitude_threshold(options.residual_tolerance)) > 0.) &&
     room_for_distributed_factorization(A))
    refine_by_inverse_iteration(A, M, distributed_eigenvalue_scale(A, M), options, options.refinement_steps, result);
  return result;
}

// The whole of a distributed vector on rank 0 (empty on the others).
inline Complex_vector gather_on_first_process(Vec x)
{
  VecScatter to_zero;
  Vec all;
  CGAL_SMDF_PETSC_CALL(VecScatterCreateToZero(x, &to_zero, &all));
  CGAL_SMDF_PETSC_CALL(VecScatterBegin(to_zero, x, all, INSERT_VALUES, SCATTER_FORWARD));
  CGAL_SMDF_PETSC_CALL(VecScatterEnd(to_zero, x, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscInt size;
  CGAL_SMDF_PETSC_CALL(VecGetLocalSize(all, &size));
  Complex_vector result(static_cast<Eigen::Index>(size));
  const PetscScalar* values;
  CGAL_SMDF_PETSC_CALL(VecGetArrayRead(all, &values));
  for(PetscInt i = 0; i < size; ++i) result[static_cast<Eigen::Index>(i)] = values[i];
  CGAL_SMDF_PETSC_CALL(VecRestoreArrayRead(all, &values));
  CGAL_SMDF_PETSC_CALL(VecScatterDestroy(&to_zero));
  CGAL_SMDF_PETSC_CALL(VecDestroy(&all));
  return result;
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_DISTRIBUTED_EIGEN_SOLVE_H
