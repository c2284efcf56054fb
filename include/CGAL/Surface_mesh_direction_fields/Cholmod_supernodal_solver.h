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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_CHOLMOD_SUPERNODAL_SOLVER_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_CHOLMOD_SUPERNODAL_SOLVER_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/internal/Supernodal/cholmod_supernodal_factorization.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/factored_matrix.h>

#include <CGAL/Eigen_sparse_matrix.h>
#include <CGAL/Eigen_vector.h>

#include <complex>
#include <memory>

namespace CGAL {
namespace Surface_mesh_direction_fields {

/*!
\ingroup PkgSurfaceMeshDirectionFieldsRef

\brief The supernodal Cholesky factorization of Hermitian positive definite
matrices with CHOLMOD's analysis (SuiteSparse), the default solver of the
package when CHOLMOD is found.

The object talks to CHOLMOD through its C interface only and owns its CHOLMOD
workspace (`cholmod_common`) and factor: it changes no setting that other
users of CHOLMOD or of the BLAS in the same process can observe. The
numerical factorization is the package's own on CHOLMOD's symbolic analysis,
with the independent subtrees of the elimination tree on the package's
threads, when the BLAS and LAPACK are linked
(`CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_BLAS`, defined by the package's
CMake target together with the libraries); CHOLMOD's own factorization
otherwise. One right-hand side is solved with the package's parallel
supernodal solve on large factors. The user manual's section on the
implementation explains the design.

It is a model of `SparseLinearAlgebraWithFactorTraits_d` with
`std::complex<double>` as `NT`: the package itself uses a richer interface
(factorization of a lower triangle, reuse of the analysis for matrices of the
same pattern, solves of blocks, single-precision factors for the eigen-solve).
Like `CGAL::Eigen_solver_traits`, copies share one factorization.

A program that uses it defines `CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD`
and links CHOLMOD (and, for the package's factorization, the BLAS and LAPACK):
the CMake target `CGAL::Surface_mesh_direction_fields` does both.
*/
class Cholmod_supernodal_solver
{
public:
  /// the number type of the matrices
  typedef std::complex<double> NT;
  /// the matrix type of `factor()`
  typedef CGAL::Eigen_sparse_matrix<NT> Matrix;
  /// the vector type of `linear_solver()`
  typedef CGAL::Eigen_vector<NT> Vector;

  /// creates a solver with its own CHOLMOD workspace.
  Cholmod_supernodal_solver() : m_factorization(std::make_shared<internal::Cholmod_supernodal_factorization>()) {}

  /// factors the Hermitian positive definite matrix `A` (its lower triangle is read)
  /// \param A the matrix
  /// \param D set to 1
  /// \returns `false` if `A` is not positive definite
  bool factor(const Matrix& A, NT& D)
  {
    D = NT(1);
    const internal::Complex_sparse_matrix lower = A.eigen_object().template triangularView<Eigen::Lower>();
    return m_factorization->factor(lower, false, false);
  }

  /// solves `A X = B` with the matrix `A` of the last `factor()`
  /// \param B the right-hand side
  /// \param X the solution
  /// \returns whether the solve succeeded
  bool linear_solver(const Vector& B, Vector& X)
  {
    try
    {
      const internal::Complex_dense_matrix x = m_factorization->solve(B.eigen_object());
      X.eigen_object() = x.col(0);
    }
    catch(const Solver_failure_error&)
    {
      return false;
    }
    return true;
  }

  /// factors `A` and solves `A X = B`
  /// \param A the matrix
  /// \param B the right-hand side
  /// \param X the solution
  /// \param D set to 1
  /// \returns whether both succeeded
  bool linear_solver(const Matrix& A, const Vector& B, Vector& X, NT& D)
  {
    return factor(A, D) && linear_solver(B, X);
  }

  /// \cond SKIP_IN_MANUAL
  // the package's interface (internal::Factored_matrix)
  internal::Cholmod_supernodal_factorization& factorization() { return *m_factorization; }
  const internal::Cholmod_supernodal_factorization& factorization() const { return *m_factorization; }
  /// \endcond

private:
  std::shared_ptr<internal::Cholmod_supernodal_factorization> m_factorization;
};

/// \cond SKIP_IN_MANUAL
namespace internal {

// The solver as the package's engine uses it (internal::Factored_matrix):
// its factorization interface, as it is.
template <>
class Factored_matrix<Surface_mesh_direction_fields::Cholmod_supernodal_solver>
  : public Shifted_factorization<Factored_matrix<Surface_mesh_direction_fields::Cholmod_supernodal_solver> >
{
  // the solver, not its factorization: an assignment to the solver (a copy
  // shares its factorization) must be seen here
  Surface_mesh_direction_fields::Cholmod_supernodal_solver& m_solver;

  Cholmod_supernodal_factorization& factorization() { return m_solver.factorization(); }
  const Cholmod_supernodal_factorization& factorization() const { return m_solver.factorization(); }

  bool factor_numerically(const Complex_sparse_matrix& S, bool same_pattern)
  {
    return factorization().factor(S, same_pattern, this->single_precision_allowed());
  }

public:
  static constexpr bool detects_indefinite = true;
  static constexpr bool factors_lower_triangle = true;
  static constexpr bool analyzes_patterns = true;

  explicit Factored_matrix(Surface_mesh_direction_fields::Cholmod_supernodal_solver& solver) : m_solver(solver) {}

  static Complex_sparse_matrix matrix_to_factor(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                                double shift)
  {
    return shifted_lower_triangle(A, M, shift);
  }

  void analyze_pattern(const Complex_sparse_matrix& pattern)
  {
    factorization().analyze_pattern(matrix_to_factor(pattern, pattern, 0.));
  }

  void factor(const Complex_sparse_matrix& S, bool same_pattern = false)
  {
    if(!factor_numerically(S, same_pattern))
      throw Solver_failure_error("the sparse solver could not factor the matrix (not positive definite?)");
  }

  bool factor_if_positive_definite(const Complex_sparse_matrix& S, bool same_pattern = false)
  {
    return factor_numerically(S, same_pattern);
  }

  // Whether a single right-hand side is solved by the parallel solve.
  bool solves_in_parallel() const { return factorization().solves_in_parallel(); }
  // Whether the last factorization was the package's (not CHOLMOD's).
  bool factored_in_parallel() const { return factorization().factored_by_package(); }
  // Whether it was in single precision (see allow_single_precision()).
  bool holds_single_precision() const { return factorization().holds_single_precision(); }

  Complex_dense_matrix solve(const Complex_dense_matrix& B) const { return factorization().solve(B); }
};

} // namespace internal
/// \endcond

} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_CHOLMOD_SUPERNODAL_SOLVER_H
