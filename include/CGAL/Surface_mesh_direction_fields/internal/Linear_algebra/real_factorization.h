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

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <memory>

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
class Factored_real_matrix
{
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
  typedef Eigen::CholmodSupernodalLLT<Real_sparse_matrix> Solver;
#else
  typedef Eigen::SimplicialLLT<Real_sparse_matrix> Solver;
#endif
  std::unique_ptr<Solver> m_solver = std::make_unique<Solver>();
  Eigen::Index m_size = 0;

public:
  void factor(const Real_sparse_matrix& S)
  {
    m_size = S.rows();
    if(m_size == 0) return;
    m_solver->compute(S);
    if(m_solver->info() != Eigen::Success)
      throw Solver_failure_error("the sparse solver could not factor the Laplacian of the connection change");
  }

  Eigen::VectorXd solve(const Eigen::VectorXd& B) const
  {
    if(m_size == 0) return B;
    Eigen::VectorXd X = m_solver->solve(B);
    if(m_solver->info() != Eigen::Success || !X.allFinite())
      throw Solver_failure_error("the sparse solver failed to solve with the Laplacian of the connection change");
    return X;
  }
};

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_REAL_FACTORIZATION_H
