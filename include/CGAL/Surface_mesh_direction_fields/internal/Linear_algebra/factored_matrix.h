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
#include <CGAL/Surface_mesh_direction_fields/internal/huge_pages.h>

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/use.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/supernodal_factorization.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/supernodal_solve.h>
#endif

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
// and solves a whole block at once, which CHOLMOD's supernodal solve does with
// BLAS-3 kernels (4 right-hand sides cost about 1.6 single solves); when the
// sparsity pattern has not changed since the previous factorization, only the
// numerical factorization is redone (the ordering and symbolic analysis are
// reused). With CHOLMOD's supernodal LL^* factor, a single right-hand side
// is solved by the package's own parallel solve on CHOLMOD's factor
// (supernodal_solve.h): CHOLMOD's solve is sequential.

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
// their own errors, like the eigen-solve (eigen_solve.h), not for the
// direct solves of aligned fields.
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
#ifdef EIGEN_CHOLMODSUPPORT_MODULE_H
template <typename Matrix, int UpLo>
struct Detects_indefinite<Eigen::CholmodSupernodalLLT<Matrix, UpLo> > : std::true_type
{};
template <typename Matrix, int UpLo>
struct Detects_indefinite<Eigen::CholmodSimplicialLLT<Matrix, UpLo> > : std::true_type
{};
#endif

// The Eigen solvers that read only the lower triangle of the matrix they
// factor (the Cholesky ones, with their default `Lower`): they are given only
// that triangle of A + shift M.
template <typename EigenSolver>
struct Reads_lower_triangle : std::false_type
{};
template <typename Matrix, typename Ordering>
struct Reads_lower_triangle<Eigen::SimplicialLLT<Matrix, Eigen::Lower, Ordering> > : std::true_type
{};
template <typename Matrix, typename Ordering>
struct Reads_lower_triangle<Eigen::SimplicialLDLT<Matrix, Eigen::Lower, Ordering> > : std::true_type
{};
#ifdef EIGEN_CHOLMODSUPPORT_MODULE_H
template <typename Matrix>
struct Reads_lower_triangle<Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> > : std::true_type
{};
template <typename Matrix>
struct Reads_lower_triangle<Eigen::CholmodSimplicialLLT<Matrix, Eigen::Lower> > : std::true_type
{};
template <typename Matrix>
struct Reads_lower_triangle<Eigen::CholmodSimplicialLDLT<Matrix, Eigen::Lower> > : std::true_type
{};
template <typename Matrix>
struct Reads_lower_triangle<Eigen::CholmodDecomposition<Matrix, Eigen::Lower> > : std::true_type
{};
#endif

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

// CHOLMOD reports a matrix that is not positive definite on stderr (as
// "CHOLMOD error" from print level 1 on, although its status is a warning);
// where that is an expected outcome (a trial shift), this turns CHOLMOD's
// printing off for the scope of the object. Nothing is lost: a real failure
// still shows in the status, the trial returns false, and the fallback
// factorization runs with the caller's print level.
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

// CHOLMOD's default analysis orders with AMD and, when AMD's fill is high
// (flops >= 500 nnz(L)), again with METIS, keeping the better. On the
// matrices of surface meshes AMD's fill grows faster than METIS's, and it
// is high from a few hundred thousand vertices on: at 800,000 vertices AMD
// gives 50 million entries in L (30 Gflop), METIS 32 million (8 Gflop), and
// CHOLMOD keeps METIS. From `metis_only_size` rows on, METIS is therefore
// asked for directly, which saves the AMD ordering; at 200,000 vertices
// CHOLMOD keeps AMD (flops = 306 nnz(L), and METIS alone is slower than AMD
// there), and the ratio, growing like |V|^0.47, reaches 500 near 570,000
// vertices. The times are in the benchmark's README.
// If METIS is not available, the analysis is redone with the defaults.
constexpr Eigen::Index metis_only_size = 600000;

#ifdef EIGEN_CHOLMODSUPPORT_MODULE_H
template <typename EigenSolver>
auto analyze_with_ordering_for_size(EigenSolver& solver, const Complex_sparse_matrix& S, int)
  -> decltype(solver.cholmod().nmethods, void())
{
  if(S.rows() < metis_only_size)
  {
    solver.analyzePattern(S);
    return;
  }
  auto& common = solver.cholmod();
  const int nmethods = common.nmethods, ordering = common.method[0].ordering;
  common.nmethods = 1;
  common.method[0].ordering = CHOLMOD_METIS;
  solver.analyzePattern(S);
  const bool failed = common.status < 0;
  common.nmethods = nmethods;
  common.method[0].ordering = ordering;
  if(failed)
    solver.analyzePattern(S);
}
#endif
template <typename EigenSolver>
void analyze_with_ordering_for_size(EigenSolver& solver, const Complex_sparse_matrix& S, long)
{
  solver.analyzePattern(S);
}

#ifdef EIGEN_CHOLMODSUPPORT_MODULE_H
// CHOLMOD's factor inside Eigen's CHOLMOD solvers, which do not expose it:
// a pointer to the protected member, formed in a derived class, is applied
// to the solver (the standard way to read a protected member; nothing is
// modified).
template <typename EigenSolver>
struct Cholmod_factor_access : EigenSolver
{
  static const cholmod_factor* factor(const EigenSolver& solver)
  {
    return solver.*(&Cholmod_factor_access::m_cholmodFactor);
  }
  // for the package's own numerical factorization (which writes the values
  // of the factor CHOLMOD's analysis allocated)
  static cholmod_factor* factor(EigenSolver& solver) { return solver.*(&Cholmod_factor_access::m_cholmodFactor); }
  // the shift beta the wrapper would add (A + beta I); zero unless set
  static double shift(const EigenSolver& solver) { return (solver.*(&Cholmod_factor_access::m_shiftOffset))[0]; }
};

// The arrays of a supernodal factor with int indices: its structure, with
// the entries `values` (in CHOLMOD's layout, in the precision of Scalar).
template <typename Scalar>
Supernodal_factor_view<int, Scalar> supernodal_view(const cholmod_factor& L, const Scalar* values)
{
  Supernodal_factor_view<int, Scalar> view;
  view.n = L.n;
  view.supernodes = L.nsuper;
  view.super = static_cast<const int*>(L.super);
  view.row_start = static_cast<const int*>(L.pi);
  view.rows = static_cast<const int*>(L.s);
  view.value_start = static_cast<const int*>(L.px);
  view.values = values;
  view.permutation = static_cast<const int*>(L.Perm);
  return view;
}

// ... with CHOLMOD's own entries (complex: interleaved (re, im), the layout
// of std::complex<double>)
inline Supernodal_factor_view<int> supernodal_view(const cholmod_factor& L)
{
  return supernodal_view(L, static_cast<const std::complex<double>*>(L.x));
}

template <typename Matrix, int UpLo, typename Derived>
std::true_type is_cholmod_solver(const Eigen::CholmodBase<Matrix, UpLo, Derived>*);
#endif
std::false_type is_cholmod_solver(...);

// The package's parallel numerical factorization (supernodal_factorization.h)
// and solve (supernodal_solve.h) on CHOLMOD's supernodal analysis, when the
// solver is Eigen's CholmodSupernodalLLT of the lower triangle (without the
// wrapper's shift). The factorization needs the BLAS and LAPACK kernels
// (dense_kernels.h; without them CHOLMOD factors) and is used from factors
// of 16,384 entries on: on the shared meshes it was faster than CHOLMOD's
// from there (CHOLMOD's calls of a multithreaded BLAS on small supernodes
// cost more than they gain). The solve of one right-hand side is used from a
// million entries on: below, CHOLMOD's solve is as fast or faster. The
// times are in the benchmark's README.
//
// The values are written into the factor held by Eigen's wrapper, whose own
// state then still says "not factored": solves go through CHOLMOD's
// cholmod_solve directly (or the parallel solve), never through the wrapper.
constexpr std::size_t parallel_solve_minimum_entries = std::size_t(1) << 20;
constexpr std::size_t parallel_factorization_minimum_entries = std::size_t(1) << 14;

class Parallel_supernodal_cholmod
{
#ifdef EIGEN_CHOLMODSUPPORT_MODULE_H
  typedef std::complex<float> Single;
  Supernodal_factor_view<int> m_view;
  std::unique_ptr<Supernodal_solve_plan> m_plan;           // kept while the analysis is
  std::unique_ptr<Supernodal_updates<int> > m_updates;
  cholmod_factor* m_factored = nullptr;  // the factor this class factored, until the next factorization
  cholmod_common* m_common = nullptr;
  bool m_ready = false;                  // the factor is there, the plan fits it
  // a factor in single precision: its entries (CHOLMOD's factor then keeps
  // none), kept from one such factorization to the next
  Eigen::Matrix<Single, Eigen::Dynamic, 1> m_single_values;
  Supernodal_factor_view<int, Single> m_single_view;
  bool m_single = false;

  static bool has_usable_layout(const cholmod_factor* L, bool numeric)
  {
    return L != nullptr && L->is_super && L->itype == CHOLMOD_INT && L->dtype == CHOLMOD_DOUBLE &&
           L->super != nullptr && L->pi != nullptr && L->px != nullptr && L->s != nullptr &&
           (numeric ? L->is_ll && L->xtype == CHOLMOD_COMPLEX && L->x != nullptr
                    : L->xtype == CHOLMOD_COMPLEX || L->xtype == CHOLMOD_PATTERN);
  }

  // the view and the plan of L's structure (kept if it is the analysis of last time)
  void read_structure(const cholmod_factor& L, bool new_structure)
  {
    m_view = supernodal_view(L);
    if(new_structure || !m_plan)
    {
      m_plan = std::make_unique<Supernodal_solve_plan>(m_view);
      m_updates.reset();
    }
  }

  template <typename EigenSolver>
  static constexpr bool is_lower_supernodal_llt()
  {
    return std::is_same<EigenSolver, Eigen::CholmodSupernodalLLT<Complex_sparse_matrix, Eigen::Lower> >::value;
  }

  void release_single_precision_factor() { Eigen::Matrix<Single, Eigen::Dynamic, 1>().swap(m_single_values); }

  // Factors P S P^T (`lower`) in single precision, into the package's own
  // array. False if a pivot is not positive in single precision, which
  // says nothing sure about S: the caller then factors in double precision.
  bool factor_in_single_precision(const cholmod_factor& L, const Complex_sparse_matrix& lower)
  {
    if(static_cast<std::size_t>(m_single_values.size()) != L.xsize)
    {
      release_single_precision_factor();
      m_single_values.resize(static_cast<Eigen::Index>(L.xsize));  // not written: the advice comes first
      advise_huge_pages(m_single_values.data(), L.xsize * sizeof(Single));
    }
    m_single_view = supernodal_view(L, m_single_values.data());
    const Eigen::SparseMatrix<Single> lower_in_single = with_values_in_precision<Single>(lower);
    if(supernodal_factorize(m_single_view, m_single_values.data(), lower_in_single, *m_updates, *m_plan) >= 0)
    {
      release_single_precision_factor();
      return false;
    }
    m_single = true;
    m_ready = true;
    return true;
  }

public:
  enum Outcome { not_attempted, factored, not_positive_definite };

  // Factors S (the lower triangle) into the solver's analyzed factor, or in
  // single precision into the package's own (if `single_allowed`, and if
  // the kernels are there), or returns not_attempted (the caller has
  // CHOLMOD factor it).
  template <typename EigenSolver>
  Outcome factor(EigenSolver& solver, const Complex_sparse_matrix& S, bool new_structure, bool single_allowed)
  {
    reset();
    if constexpr(is_lower_supernodal_llt<EigenSolver>())
    {
      cholmod_factor* L = Cholmod_factor_access<EigenSolver>::factor(solver);
      if(!has_usable_layout(L, false) || L->xsize < parallel_factorization_minimum_entries ||
         Cholmod_factor_access<EigenSolver>::shift(solver) != 0. || !dense_kernels<double>().complete())
        return not_attempted;
      read_structure(*L, new_structure);
      if(!m_plan->valid()) return not_attempted;
      if(!m_updates) m_updates = std::make_unique<Supernodal_updates<int> >(m_view);
      const Complex_sparse_matrix lower = permuted_lower_triangle(S, m_view.permutation);
      if(single_allowed && dense_kernels<float>().complete() && factor_in_single_precision(*L, lower))
        return factored;
      release_single_precision_factor();
      cholmod_common& common = solver.cholmod();
      if(L->xtype == CHOLMOD_PATTERN && !cholmod_change_factor(CHOLMOD_COMPLEX, true, true, true, true, L, &common))
        return not_attempted;
      m_view = supernodal_view(*L);  // now with values
      const std::ptrdiff_t column =
        supernodal_factorize(m_view, static_cast<Complex*>(L->x), lower, *m_updates, *m_plan);
      L->is_ll = true;
      L->minor = column < 0 ? L->n : static_cast<std::size_t>(column);
      if(column >= 0) return not_positive_definite;
      m_factored = L;
      m_common = &common;
      m_ready = L->xsize >= parallel_solve_minimum_entries;
      return factored;
    }
    else
    {
      CGAL_USE(solver);
      CGAL_USE(S);
      CGAL_USE(new_structure);
      CGAL_USE(single_allowed);
      return not_attempted;
    }
  }

  // after a factorization by CHOLMOD; `new_structure`: the analysis was redone
  template <typename EigenSolver>
  void update(const EigenSolver& solver, bool new_structure)
  {
    reset();
    release_single_precision_factor();
    if constexpr(decltype(is_cholmod_solver(&solver))::value)
    {
      const cholmod_factor* L = Cholmod_factor_access<EigenSolver>::factor(solver);
      if(!has_usable_layout(L, true) || L->xsize < parallel_solve_minimum_entries)
      {
        m_plan.reset();
        m_updates.reset();
        return;
      }
      read_structure(*L, new_structure);
      m_ready = m_plan->valid();
    }
    else
    {
      CGAL_USE(solver);
      CGAL_USE(new_structure);
    }
  }
  void reset()  // before a factorization
  {
    m_ready = false;
    m_factored = nullptr;
    m_single = false;
  }
  bool available() const { return m_ready; }
  // whether the last factorization was this class's (solves of blocks then
  // go to cholmod_solve here, the wrapper believing itself unfactored)
  bool factored_here() const { return m_factored != nullptr || m_single; }
  bool holds_single_precision() const { return m_single; }
  Complex_dense_matrix solve(const Complex_dense_matrix& B) const
  {
    if(m_single) return supernodal_solve(m_single_view, *m_plan, B.col(0));
    return supernodal_solve(m_view, *m_plan, B.col(0));
  }
  Complex_dense_matrix solve_block(const Complex_dense_matrix& B) const
  {
    if(m_single)  // CHOLMOD has no single precision: column by column
    {
      Complex_dense_matrix X(B.rows(), B.cols());
      for(Eigen::Index j = 0; j < B.cols(); ++j) X.col(j) = supernodal_solve(m_single_view, *m_plan, B.col(j));
      return X;
    }
    Complex_dense_matrix rhs = B;
    cholmod_dense b = Eigen::viewAsCholmod(rhs);
    cholmod_dense* x = cholmod_solve(CHOLMOD_A, m_factored, &b, m_common);
    if(x == nullptr) throw Solver_failure_error("the sparse solver failed to solve with its factorization");
    Complex_dense_matrix X = Eigen::Map<const Complex_dense_matrix>(static_cast<const Complex*>(x->x), B.rows(), B.cols());
    cholmod_free_dense(&x, m_common);
    return X;
  }
#else
public:
  enum Outcome { not_attempted, factored, not_positive_definite };
  template <typename EigenSolver>
  Outcome factor(EigenSolver&, const Complex_sparse_matrix&, bool, bool) { return not_attempted; }
  template <typename EigenSolver>
  void update(const EigenSolver&, bool) {}
  void reset() {}
  bool available() const { return false; }
  bool factored_here() const { return false; }
  bool holds_single_precision() const { return false; }
  Complex_dense_matrix solve(const Complex_dense_matrix& B) const { return B; }
  Complex_dense_matrix solve_block(const Complex_dense_matrix& B) const { return B; }
#endif
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

  Parallel_supernodal_cholmod m_parallel;
  bool m_new_structure = false;
  // the compressed pattern (column starts, rows) of the matrix to factor
  // that analyze_pattern() analyzed, until a factorization checks it
  std::vector<Complex_sparse_matrix::StorageIndex> m_pending_starts, m_pending_rows;

  void analyze(const Complex_sparse_matrix& S, bool same_pattern)
  {
    if(!m_pending_starts.empty())
    {
      // the first factorization after analyze_pattern(): its analysis is
      // used if S has exactly that pattern, and redone otherwise
      const bool matches = has_pending_pattern(S);
      std::vector<Complex_sparse_matrix::StorageIndex>().swap(m_pending_starts);
      std::vector<Complex_sparse_matrix::StorageIndex>().swap(m_pending_rows);
      m_new_structure = true;
      if(matches) return;
      same_pattern = false;
    }
    m_new_structure = !(same_pattern && m_analyzed);
    if(m_new_structure)
      analyze_with_ordering_for_size(m_traits.solver(), S, 0);
    m_analyzed = true;
  }

  bool has_pending_pattern(const Complex_sparse_matrix& S) const
  {
    return S.isCompressed() && static_cast<std::size_t>(S.outerSize()) + 1 == m_pending_starts.size() &&
           static_cast<std::size_t>(S.nonZeros()) == m_pending_rows.size() &&
           std::equal(m_pending_starts.begin(), m_pending_starts.end(), S.outerIndexPtr()) &&
           std::equal(m_pending_rows.begin(), m_pending_rows.end(), S.innerIndexPtr());
  }

  // The package's parallel factorization where it applies, the solver's
  // otherwise. Returns whether S was factored; a `trial` also requires
  // positive pivots of an LDL^* factorization, and silences CHOLMOD's
  // message for a matrix that is not positive definite.
  bool factor_numerically(const Complex_sparse_matrix& S, bool same_pattern, bool trial)
  {
    EigenSolver& solver = m_traits.solver();
    analyze(S, same_pattern);
    const auto outcome = m_parallel.factor(solver, S, m_new_structure, this->single_precision_allowed());
    if(outcome != Parallel_supernodal_cholmod::not_attempted) return outcome == Parallel_supernodal_cholmod::factored;
    if(trial)
    {
      Cholmod_messages_off<EigenSolver> messages_off(solver);
      solver.factorize(S);
    }
    else
      solver.factorize(S);
    const bool factored = solver.info() == Eigen::Success && (!trial || has_positive_pivots(solver, 0));
    if(factored) m_parallel.update(solver, m_new_structure);
    return factored;
  }

  static Complex_dense_matrix finite_solution(Complex_dense_matrix X)
  {
    if(!X.allFinite()) throw Solver_failure_error("the sparse solver failed to solve with its factorization");
    return X;
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
    analyze_with_ordering_for_size(m_traits.solver(), S, 0);
    m_pending_starts.assign(S.outerIndexPtr(), S.outerIndexPtr() + S.outerSize() + 1);
    m_pending_rows.assign(S.innerIndexPtr(), S.innerIndexPtr() + S.nonZeros());
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

  // Whether a single right-hand side is solved by the parallel solve.
  bool solves_in_parallel() const { return m_parallel.available(); }
  // Whether the last factorization was the package's parallel one.
  bool factored_in_parallel() const { return m_parallel.factored_here(); }
  // Whether it was in single precision (see allow_single_precision()).
  bool holds_single_precision() const { return m_parallel.holds_single_precision(); }

  Complex_dense_matrix solve(const Complex_dense_matrix& B) const
  {
    if(B.cols() == 1 && m_parallel.available())
      return finite_solution(m_parallel.solve(B));
    if(m_parallel.factored_here())
      return finite_solution(m_parallel.solve_block(B));
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
