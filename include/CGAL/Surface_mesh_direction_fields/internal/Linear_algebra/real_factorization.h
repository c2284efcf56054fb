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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_REAL_FACTORIZATION_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_REAL_FACTORIZATION_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/dense_kernels.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/ordering_lock.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <memory>
#include <new>
#include <mutex>
#include <type_traits>

// Real symmetric positive definite sparse matrices, factored once and solved
// many times: the vertex Laplacian of the connection change for prescribed
// singularities (user manual, section "Placing Singularities").

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

typedef Eigen::SparseMatrix<double> Real_sparse_matrix;

// A real symmetric positive definite sparse matrix, factored once (CHOLMOD's
// supernodal Cholesky factorization when the package uses CHOLMOD, Eigen's
// simplicial one otherwise), then solved for any number of right-hand sides.
// CHOLMOD's factorization and solves call the BLAS, so they follow the
// discipline of the package's own factorization (dense_kernels.h): one at a
// time in the process (the same digits whatever else runs), and only where the BLAS's
// work buffers fit in the address space; otherwise Eigen's simplicial
// factorization runs, and a shortage of memory is std::bad_alloc, not a hang.
class Factored_real_matrix
{
  typedef Eigen::SimplicialLLT<Real_sparse_matrix> Simplicial_solver;
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
  typedef Eigen::CholmodSupernodalLLT<Real_sparse_matrix> Blas_solver;
#else
  typedef Simplicial_solver Blas_solver;
#endif
  std::unique_ptr<Blas_solver> m_blas_solver;
  std::unique_ptr<Simplicial_solver> m_simplicial_solver;
  Eigen::Index m_size = 0;

  static void check_factored(const Eigen::ComputationInfo info)
  {
    if(info != Eigen::Success)
      throw Solver_failure_error("the sparse solver could not factor the Laplacian of the connection change");
  }

  static std::unique_ptr<Simplicial_solver> factored_without_blas(const Real_sparse_matrix& S)
  {
    auto solver = std::make_unique<Simplicial_solver>(S);
    check_factored(solver->info());
    return solver;
  }

  // CHOLMOD allocates the factor before the BLAS takes its work buffers:
  // the analysis tells the factor's size (lnz entries, which the supernodes'
  // padding can take up to about one and a half times), and the BLAS is
  // called only where the address space leaves room for both (null
  // otherwise).
  static std::unique_ptr<Blas_solver> factored_with_blas(const Real_sparse_matrix& S)
  {
    auto solver = std::make_unique<Blas_solver>();
    solver->analyzePattern(S);
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
    if(solver->cholmod().status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
    const double factor_bytes = 2. * sizeof(double) * solver->cholmod().lnz;
    if(!(factor_bytes < 1e18) || !blas_work_space_available(static_cast<std::size_t>(factor_bytes))) return nullptr;
#endif
    solver->factorize(S);
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
    if(solver->cholmod().status == CHOLMOD_OUT_OF_MEMORY) throw std::bad_alloc();
#endif
    check_factored(solver->info());
    return solver;
  }

  template <typename Solver>
  static Eigen::VectorXd solved(const Solver& solver, const Eigen::VectorXd& B)
  {
    Eigen::VectorXd X = solver.solve(B);
    if(solver.info() != Eigen::Success || !X.allFinite())
      throw Solver_failure_error("the sparse solver failed to solve with the Laplacian of the connection change");
    return X;
  }

public:
  void factor(const Real_sparse_matrix& S)
  {
    m_size = S.rows();
    m_blas_solver.reset();
    m_simplicial_solver.reset();
    if(m_size == 0) return;
    if(!std::is_same<Blas_solver, Simplicial_solver>::value && blas_work_space_available())
    {
      // CHOLMOD's analysis may call METIS (ordering_lock.h)
      std::scoped_lock exclusive(blas_factorization_lock(), metis_ordering_lock());
      m_blas_solver = factored_with_blas(S);
    }
    if(!m_blas_solver) m_simplicial_solver = factored_without_blas(S);
  }

  // CHOLMOD's solve calls the BLAS too: under the same lock, so that its
  // digits do not depend on what other threads do meanwhile.
  Eigen::VectorXd solve(const Eigen::VectorXd& B) const
  {
    if(m_size == 0) return B;
    if(!m_blas_solver) return solved(*m_simplicial_solver, B);
    std::lock_guard<std::mutex> exclusive(blas_factorization_lock());
    return solved(*m_blas_solver, B);
  }
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_REAL_FACTORIZATION_H
