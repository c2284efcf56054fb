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


#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_DISTRIBUTED_LOBPCG_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_DISTRIBUTED_LOBPCG_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/dense_kernels.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/eigen_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Distributed/petsc_calls.h>

#include <slepceps.h>

#include <algorithm>
#include <cmath>
#include <vector>

// The iteration of distributed_eigen_solve.h: its options and result, the
// multigrid preconditioner and LOBPCG for one vector.

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

struct Distributed_eigen_solve_options
{
  double relative_shift = 1e-8;  // epsilon = relative_shift * trace(A) / trace(M), as in eigen_solve.h
  double residual_tolerance = 1e-10;  // on ||A x - lambda M x|| / (trace(A) / trace(M) ||M x||), as eigen_solve.h
  PetscInt max_iterations = 10000;
  // The estimates of the processes agree poorly where their blocks meet
  // (each is the field of its own piece of surface, whose singularities may
  // lie elsewhere), and GAMG built in their gauge lets the residual fall by
  // only a few percent per step once it is small: the iteration stops at
  // this residual (or after this many steps) and starts again, with a new
  // GAMG, in the gauge of its iterate. The value gave the fewest steps over
  // the sizes measured in benchmark/ (the stall began below 1e-7).
  double regauge_tolerance = 1e-6;
  PetscInt regauge_iterations = 40;
  bool slepc_lobpcg = false;  // SLEPc's LOBPCG instead of the package's (for measurements)
  // LOBPCG's vector is accurate relative to its largest entries; where the
  // field is below low_magnitude_threshold() of them (user manual, "Where
  // the Field Vanishes"), or where LOBPCG converges slowly (the nearly equal
  // smallest eigenvalues of a sphere), a few steps of inverse iteration on a
  // distributed factorization (MUMPS, when PETSc has it) finish the solve.
  PetscInt refinement_steps = 4;
  PetscInt iterations_before_refining = 400;
};

struct Distributed_eigen_solve_result
{
  bool converged = false;
  double eigenvalue = 0.;
  PetscInt iterations = 0;
  double residual = 0.;
  Vec vector = nullptr;  // distributed like A's rows; the caller destroys it
};

// The multigrid preconditioner: one V-cycle of GAMG on P (options prefix
// "st_", as for SLEPc's spectral transformation).
inline KSP multigrid_preconditioner(Mat P)
{
  KSP ksp;
  PC pc;
  CGAL_SMDF_PETSC_CALL(KSPCreate(PetscObjectComm(reinterpret_cast<PetscObject>(P)), &ksp));
  CGAL_SMDF_PETSC_CALL(KSPSetOperators(ksp, P, P));
  CGAL_SMDF_PETSC_CALL(KSPSetType(ksp, KSPPREONLY));
  CGAL_SMDF_PETSC_CALL(KSPGetPC(ksp, &pc));
  CGAL_SMDF_PETSC_CALL(PCSetType(pc, PCGAMG));
  CGAL_SMDF_PETSC_CALL(KSPSetOptionsPrefix(ksp, "st_"));
  CGAL_SMDF_PETSC_CALL(KSPSetFromOptions(ksp));
  CGAL_SMDF_PETSC_CALL(KSPSetUp(ksp));
  return ksp;
}

// LOBPCG for one vector (Knyazev's locally optimal block preconditioned
// conjugate gradient with a block of one): each step is a Rayleigh-Ritz
// projection of (A, M) onto span{x, w, p}, with x the current vector, w the
// preconditioned residual and p the previous step. SLEPc's LOBPCG does the
// same with general blocks and pays for it on every step (its basis
// operations cost several times the multigrid cycle: see benchmark/), so the
// package keeps this one, whose step is one cycle, two products and six
// reductions.
class Single_vector_lobpcg
{
public:
  Single_vector_lobpcg(Mat A, Mat M, KSP preconditioner) : m_A(A), m_M(M), m_preconditioner(preconditioner)
  {
    for(Vec* v : {&m_S[0], &m_S[1], &m_S[2], &m_AS[0], &m_AS[1], &m_AS[2], &m_MS[0], &m_MS[1], &m_MS[2], &m_r})
      CGAL_SMDF_PETSC_CALL(MatCreateVecs(A, v, nullptr));
  }
  ~Single_vector_lobpcg()
  {
    for(Vec* v : {&m_S[0], &m_S[1], &m_S[2], &m_AS[0], &m_AS[1], &m_AS[2], &m_MS[0], &m_MS[1], &m_MS[2], &m_r})
      CGAL_SMDF_PETSC_CALL(VecDestroy(v));
  }
  Single_vector_lobpcg(const Single_vector_lobpcg&) = delete;
  Single_vector_lobpcg& operator=(const Single_vector_lobpcg&) = delete;

  Distributed_eigen_solve_result run(Vec start, double scale, const Distributed_eigen_solve_options& options)
  {
    Distributed_eigen_solve_result result;
    CGAL_SMDF_PETSC_CALL(VecCopy(start, m_S[0]));
    set_products(0);
    normalize(0);
    std::size_t size = 1;  // x, then w, then p once there is a previous step
    for(result.iterations = 0; result.iterations <= options.max_iterations; ++result.iterations)
    {
      result.eigenvalue = PetscRealPart(dot(m_AS[0], m_S[0]));
      CGAL_SMDF_PETSC_CALL(VecWAXPY(m_r, -result.eigenvalue, m_MS[0], m_AS[0]));  // r = A x - lambda M x
      PetscReal r_norm, mx_norm;
      CGAL_SMDF_PETSC_CALL(VecNorm(m_r, NORM_2, &r_norm));
      CGAL_SMDF_PETSC_CALL(VecNorm(m_MS[0], NORM_2, &mx_norm));
      result.residual = r_norm / (scale * mx_norm);
      if(!(result.residual > options.residual_tolerance))
      {
        result.converged = result.residual <= options.residual_tolerance;
        break;
      }
      CGAL_SMDF_PETSC_CALL(KSPSolve(m_preconditioner, m_r, m_S[1]));  // w
      set_products(1);
      normalize(1);
      size = (std::max)(size, std::size_t(2));
      if(!step(size) && (size < 3 || !step(size = 2))) break;  // without p when the basis is dependent
      size = 3;
    }
    CGAL_SMDF_PETSC_CALL(MatCreateVecs(m_A, &result.vector, nullptr));  // the last iterate, converged or not
    CGAL_SMDF_PETSC_CALL(VecCopy(m_S[0], result.vector));
    return result;
  }

private:
  PetscScalar dot(Vec a, Vec b) const
  {
    PetscScalar value;
    CGAL_SMDF_PETSC_CALL(VecDot(a, b, &value));  // b^* a
    return value;
  }
  void set_products(std::size_t k)
  {
    CGAL_SMDF_PETSC_CALL(MatMult(m_A, m_S[k], m_AS[k]));
    CGAL_SMDF_PETSC_CALL(MatMult(m_M, m_S[k], m_MS[k]));
  }
  void normalize(std::size_t k)
  {
    const double norm = std::sqrt((std::max)(0., PetscRealPart(dot(m_MS[k], m_S[k]))));
    if(norm > 0.)
      for(Vec v : {m_S[k], m_AS[k], m_MS[k]}) CGAL_SMDF_PETSC_CALL(VecScale(v, 1. / norm));
  }
  // The Rayleigh-Ritz step on the first `size` basis vectors: x and its
  // products become the best Ritz vector, p the part of it outside x.
  // Returns false if the basis' Gram matrix (of M) is not safely positive
  // definite.
  bool step(std::size_t size)
  {
    typedef Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic> Small;
    Small GA(size, size), GM(size, size);
    std::vector<PetscScalar> column(size);
    for(std::size_t j = 0; j < size; ++j)
    {
      CGAL_SMDF_PETSC_CALL(VecMDot(m_AS[j], static_cast<PetscInt>(size), m_S, column.data()));  // column[i] = s_i^* A s_j
      for(std::size_t i = 0; i < size; ++i) GA(i, j) = column[i];
      CGAL_SMDF_PETSC_CALL(VecMDot(m_MS[j], static_cast<PetscInt>(size), m_S, column.data()));
      for(std::size_t i = 0; i < size; ++i) GM(i, j) = column[i];
    }
    // p shrinks with the residual: measured in units of M-unit vectors, a
    // small p is not taken for a dependent one (which would drop it on every
    // other step and leave steepest descent, many times slower near the end)
    Eigen::VectorXd unit(size);
    for(std::size_t i = 0; i < size; ++i) unit[static_cast<Eigen::Index>(i)] = 1. / std::sqrt((std::max)(GM(i, i).real(), 1e-300));
    GA = unit.asDiagonal() * ((GA + GA.adjoint()) / 2.) * unit.asDiagonal();
    GM = unit.asDiagonal() * ((GM + GM.adjoint()) / 2.) * unit.asDiagonal();
    Eigen::SelfAdjointEigenSolver<Small> gram(GM);
    if(gram.eigenvalues().minCoeff() <= 1e-12 * gram.eigenvalues().maxCoeff()) return false;
    Eigen::GeneralizedSelfAdjointEigenSolver<Small> ritz(GA, GM);
    if(ritz.info() != Eigen::Success) return false;
    const Eigen::Matrix<Complex, Eigen::Dynamic, 1> c = unit.asDiagonal() * ritz.eigenvectors().col(0);
    // p = c_1 w + c_2 p (and its products), then x = c_0 x + p
    for(Vec* family : {m_S, m_AS, m_MS})
    {
      if(size == 3)
        CGAL_SMDF_PETSC_CALL(VecScale(family[2], c[2]));
      else
        CGAL_SMDF_PETSC_CALL(VecSet(family[2], 0.));
      CGAL_SMDF_PETSC_CALL(VecAXPY(family[2], c[1], family[1]));
      CGAL_SMDF_PETSC_CALL(VecAXPBY(family[0], 1., c[0], family[2]));
    }
    return true;
  }

  Mat m_A, m_M;
  KSP m_preconditioner;
  Vec m_S[3], m_AS[3], m_MS[3], m_r;
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_DISTRIBUTED_DISTRIBUTED_LOBPCG_H
