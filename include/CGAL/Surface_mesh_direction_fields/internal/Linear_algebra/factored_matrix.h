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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_FACTORED_MATRIX_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_FACTORED_MATRIX_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/shifted_matrix.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/use.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <complex>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

// The one place where the package talks to the sparse solver: factor a
// Hermitian positive definite matrix (given, or as A + shift M) once, then
// solve for blocks of right-hand sides.
//
// Any model of CGAL's `SparseLinearAlgebraWithFactorTraits_d` works through
// the generic version (the matrix is copied into the solver's matrix type and
// the columns are solved one by one). For `CGAL::Eigen_solver_traits` the
// specialization hands the Eigen matrix to the Eigen solver directly (no copy)
// and solves a whole block at once; when the sparsity pattern has not changed
// since the previous factorization, only the numerical factorization is
// redone (the ordering and symbolic analysis are reused). The package's
// default, `Cholmod_supernodal_solver`, has its own specialization, a thin
// adapter of its factorization interface, in its own header (this layer
// includes no public header).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// factor_shifted() and factor_shifted_if_positive_definite() of both
// versions of Factored_matrix below: they factor A + shift M, in the form
// Derived::matrix_to_factor() gives (the whole matrix, or the one triangle
// a Cholesky solver reads). A negative shift moves the matrix towards
// A - lambda_1 M, where inverse iteration converges fastest.
//
// They also hold the choice of precision: `allow_single_precision(true)`
// lets the following factorizations be computed and stored in single
// precision where the package's own factorization applies (only the
// specialization below has one). A solve then has the accuracy of a
// single-precision factor (relative errors of about 1e-3 to 1e-6 on the
// shared meshes), but reads half the bytes: for iterations that correct
// their own errors, like the eigen-solve (eigen_solve.h) and the refined
// solves of aligned fields (refined_solve() in linear_solves.h).
template <typename Derived>
class Shifted_factorization
{
  Derived& derived() { return static_cast<Derived&>(*this); }
  bool m_single_precision_allowed = false;

public:
  void allow_single_precision(bool allowed) { m_single_precision_allowed = allowed; }
  bool single_precision_allowed() const { return m_single_precision_allowed; }

  void factor_shifted(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M, double shift,
                      bool same_pattern = false)
  {
    derived().factor(Derived::matrix_to_factor(A, M, shift), same_pattern);
  }

  // Returns false, having factored nothing usable, when A + shift M is not
  // positive definite (as far as the solver can tell: see `detects_indefinite`).
  bool factor_shifted_if_positive_definite(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                           double shift, bool same_pattern = false)
  {
    return derived().factor_if_positive_definite(Derived::matrix_to_factor(A, M, shift), same_pattern);
  }
};

template <typename SparseSolver, typename Enable = void>
class Factored_matrix : public Shifted_factorization<Factored_matrix<SparseSolver, Enable> >
{
  typedef typename SparseSolver::Matrix Solver_matrix;
  typedef typename SparseSolver::Vector Solver_vector;
  typedef typename SparseSolver::NT Solver_NT;

  SparseSolver& m_solver;
  Solver_NT m_D = Solver_NT(1);
  Eigen::Index m_n = 0;

public:
  // A solver seen only through CGAL's concept cannot tell whether the matrix
  // it factored was positive definite.
  static constexpr bool detects_indefinite = false;
  // whether matrix_to_factor() is the lower triangle only
  static constexpr bool factors_lower_triangle = false;

  explicit Factored_matrix(SparseSolver& solver) : m_solver(solver) {}

  // The generic version analyzes nothing ahead (see the specialization).
  static constexpr bool analyzes_patterns = false;
  void analyze_pattern(const Complex_sparse_matrix&) {}

  // `same_pattern` is a hint that the generic version ignores.
  void factor(const Complex_sparse_matrix& S, bool /*same_pattern*/ = false)
  {
    m_n = S.rows();
    Solver_matrix matrix(static_cast<int>(m_n), static_cast<int>(m_n));
    for(Eigen::Index col = 0; col < S.outerSize(); ++col)
      for(Complex_sparse_matrix::InnerIterator it(S, col); it; ++it)
        matrix.add_coef(static_cast<std::size_t>(it.row()), static_cast<std::size_t>(it.col()), it.value());
    if(!m_solver.factor(matrix, m_D))
      throw Solver_failure_error("the sparse solver could not factor the matrix");
  }

  // Returns false where factor() throws: whether the matrix was positive
  // definite stays unknown (see `detects_indefinite`).
  bool factor_if_positive_definite(const Complex_sparse_matrix& S, bool same_pattern = false)
  {
    try
    {
      factor(S, same_pattern);
    }
    catch(const Solver_failure_error&)
    {
      return false;
    }
    return true;
  }

  static Complex_sparse_matrix matrix_to_factor(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                                double shift)
  {
    return shifted_matrix(A, M, shift);
  }

  // the generic version factors in the solver's precision
  bool holds_single_precision() const { return false; }

  Complex_dense_matrix solve(const Complex_dense_matrix& B) const
  {
    Complex_dense_matrix X(B.rows(), B.cols());
    Solver_vector rhs(static_cast<int>(m_n)), x(static_cast<int>(m_n));
    for(Eigen::Index j = 0; j < B.cols(); ++j)
    {
      for(Eigen::Index i = 0; i < m_n; ++i) rhs[i] = B(i, j);
      if(!m_solver.linear_solver(rhs, x))
        throw Solver_failure_error("the sparse solver failed to solve with its factorization");
      for(Eigen::Index i = 0; i < m_n; ++i) X(i, j) = x[i] / m_D;
    }
    return X;
  }
};

// Eigen's CHOLMOD wrappers (Eigen/CholmodSupport), declared here so that
// their properties below hold whether or not a user includes that header.
} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL
namespace Eigen {
template <typename MatrixType, int UpLo>
class CholmodSupernodalLLT;
template <typename MatrixType, int UpLo>
class CholmodSimplicialLLT;
} // namespace Eigen
namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The Eigen solvers whose factorization of a matrix that is not positive
// definite shows it: the Cholesky (LL^*) ones fail, and Eigen's LDL^* has a
// non-positive pivot in D. (CHOLMOD's LDL^* factors indefinite matrices
// without a word, like a general solver.)
template <typename EigenSolver>
struct Detects_indefinite : std::false_type
{};
template <typename Matrix, int UpLo, typename Ordering>
struct Detects_indefinite<Eigen::SimplicialLLT<Matrix, UpLo, Ordering> > : std::true_type
{};
template <typename Matrix, int UpLo, typename Ordering>
struct Detects_indefinite<Eigen::SimplicialLDLT<Matrix, UpLo, Ordering> > : std::true_type
{};
template <typename Matrix, int UpLo>
struct Detects_indefinite<Eigen::CholmodSupernodalLLT<Matrix, UpLo> > : std::true_type
{};
template <typename Matrix, int UpLo>
struct Detects_indefinite<Eigen::CholmodSimplicialLLT<Matrix, UpLo> > : std::true_type
{};

// The Eigen solvers that read only the lower triangle of the matrix they
// factor (those of self-adjoint matrices, whose `UpLo` is `Lower`, the
// default): they are given only that triangle of A + shift M.
template <typename EigenSolver, typename = void>
struct Reads_lower_triangle : std::false_type
{};
template <typename EigenSolver>
struct Reads_lower_triangle<EigenSolver, std::enable_if_t<int(EigenSolver::UpLo) == int(Eigen::Lower)> >
  : std::true_type
{};

// Whether the pivots of an LDL^* factorization are all positive (for the
// solvers without a vectorD(), the factorization's success says it).
template <typename EigenSolver>
auto has_positive_pivots(const EigenSolver& solver, int) -> decltype(solver.vectorD(), bool())
{
  return solver.vectorD().size() == 0 || solver.vectorD().real().minCoeff() > 0.;
}
template <typename EigenSolver>
bool has_positive_pivots(const EigenSolver&, long)
{
  return true;
}

// Eigen's CHOLMOD wrappers report a matrix that is not positive definite on
// stderr (as "CHOLMOD error" from print level 1 on, although its status is
// a warning); where that is an expected outcome (a trial shift), this turns
// the wrapper's printing off for the scope of the object. Nothing is lost: a
// real failure still shows in the status, the trial returns false, and the
// fallback factorization runs with the caller's print level.
template <typename EigenSolver, typename = void>
struct Cholmod_messages_off
{
  explicit Cholmod_messages_off(EigenSolver&) {}
};
template <typename EigenSolver>
struct Cholmod_messages_off<EigenSolver, std::void_t<decltype(std::declval<EigenSolver&>().cholmod().print)> >
{
  EigenSolver& solver;
  int saved;
  explicit Cholmod_messages_off(EigenSolver& s) : solver(s), saved(s.cholmod().print) { solver.cholmod().print = 0; }
  ~Cholmod_messages_off() { solver.cholmod().print = saved; }
};

template <typename EigenSolver>
class Factored_matrix<CGAL::Eigen_solver_traits<EigenSolver>,
                      std::enable_if_t<std::is_same<typename EigenSolver::MatrixType, Complex_sparse_matrix>::value> >
  : public Shifted_factorization<Factored_matrix<
      CGAL::Eigen_solver_traits<EigenSolver>,
      std::enable_if_t<std::is_same<typename EigenSolver::MatrixType, Complex_sparse_matrix>::value> > >
{
  typedef CGAL::Eigen_solver_traits<EigenSolver> Traits;
  Traits& m_traits;
  bool m_analyzed = false;

  bool m_new_structure = false;
  // the compressed pattern (column starts, rows) of the matrix to factor
  // that analyze_pattern() analyzed, until a factorization checks it
  Pending_pattern m_pending;

  void analyze(const Complex_sparse_matrix& S, bool same_pattern)
  {
    if(m_pending.pending())
    {
      // the first factorization after analyze_pattern(): its analysis is
      // used if S has exactly that pattern, and redone otherwise
      const bool matches = m_pending.take_and_compare(S);
      m_new_structure = true;
      if(matches) return;
      same_pattern = false;
    }
    m_new_structure = !(same_pattern && m_analyzed);
    if(m_new_structure)
      m_traits.solver().analyzePattern(S);
    m_analyzed = true;
  }

  // Returns whether S was factored; a `trial` also requires positive pivots
  // of an LDL^* factorization, and silences the message of Eigen's CHOLMOD
  // wrappers for a matrix that is not positive definite.
  bool factor_numerically(const Complex_sparse_matrix& S, bool same_pattern, bool trial)
  {
    EigenSolver& solver = m_traits.solver();
    analyze(S, same_pattern);
    if(trial)
    {
      Cholmod_messages_off<EigenSolver> messages_off(solver);
      solver.factorize(S);
    }
    else
      solver.factorize(S);
    return solver.info() == Eigen::Success && (!trial || has_positive_pivots(solver, 0));
  }

public:
  // A + shift M, or only its lower triangle if that is all the solver reads.
  static Complex_sparse_matrix matrix_to_factor(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                                double shift)
  {
    if constexpr(Reads_lower_triangle<EigenSolver>::value)
      return shifted_lower_triangle(A, M, shift);
    else
      return shifted_matrix(A, M, shift);
  }

  static constexpr bool detects_indefinite = Detects_indefinite<EigenSolver>::value;
  static constexpr bool factors_lower_triangle = Reads_lower_triangle<EigenSolver>::value;

  explicit Factored_matrix(Traits& traits) : m_traits(traits) {}

  // The symbolic analysis (ordering) of A + shift M from a matrix with the
  // pattern of both A and M (A itself when they share it), so that it can
  // run before the shift is known. The next factorization uses it if its
  // matrix has that pattern (it checks), and analyzes again otherwise.
  static constexpr bool analyzes_patterns = true;
  void analyze_pattern(const Complex_sparse_matrix& pattern)
  {
    const Complex_sparse_matrix S = matrix_to_factor(pattern, pattern, 0.);
    m_traits.solver().analyzePattern(S);
    m_pending.record(S);
    m_analyzed = true;
  }

  void factor(const Complex_sparse_matrix& S, bool same_pattern = false)
  {
    if(!factor_numerically(S, same_pattern, false))
      throw Solver_failure_error("the sparse solver could not factor the matrix (not positive definite?)");
  }

  // Factors S and returns true, or returns false, without a warning, if the
  // factorization shows that S is not positive definite (or fails otherwise);
  // the next factorization then redoes the analysis.
  bool factor_if_positive_definite(const Complex_sparse_matrix& S, bool same_pattern = false)
  {
    m_analyzed = factor_numerically(S, same_pattern, true);
    return m_analyzed;
  }

  // Eigen's solvers factor in double precision only.
  bool holds_single_precision() const { return false; }

  Complex_dense_matrix solve(const Complex_dense_matrix& B) const
  {
    Complex_dense_matrix X = m_traits.solver().solve(B);
    if(m_traits.solver().info() != Eigen::Success || !X.allFinite())
      throw Solver_failure_error("the sparse solver failed to solve with its factorization");
    return X;
  }
};


} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_FACTORED_MATRIX_H
