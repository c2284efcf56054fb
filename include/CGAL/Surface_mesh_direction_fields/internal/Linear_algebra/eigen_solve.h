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

#ifndef CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_EIGEN_SOLVE_H
#define CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_EIGEN_SOLVE_H

#include <CGAL/license/Surface_mesh_direction_fields.h>

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/coarse_hierarchy.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/factored_matrix.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/hermitian_products.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/interruption.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/ritz_basis.h>
#include <CGAL/Surface_mesh_direction_fields/internal/huge_pages.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <type_traits>
#include <utility>
#include <vector>

// The smallest generalized eigenpair of A u = lambda M u (user manual, section "The Smoothest Field"),
// by inverse iteration on one factorization of A - sigma M, accelerated by
// Rayleigh-Ritz on the space of its iterates, through any model of CGAL's
// `SparseLinearAlgebraWithFactorTraits_d` with complex scalars. The shift
// sigma comes from a coarse version of the problem, which also gives the
// start vector (eigenvalue_estimate.h).

namespace CGAL {
namespace Surface_mesh_direction_fields {
namespace internal {

// The fraction of the coarse bound R used as the shift, for the energy E_s.
// R overestimates lambda_1 by an error of about the same size for every s,
// but lambda_1 itself shrinks as |s| -> 1 (on a sphere it is n (1 - s)), so
// R / lambda_1 grows with |s|. A fraction above lambda_1 / R makes
// A - sigma M indefinite, which costs a second factorization; 0.6 (1 - |s|)
// stays below lambda_1 / R with a margin on every mesh measured, and the
// shift near lambda_1 halves the solves (the benchmark's README, "The coarse
// bound, the basis and the early moves").
inline double shift_fraction_for(double s)
{
  return 0.6 * (std::max)(0., 1. - std::abs(s));
}

struct Eigen_solve_options
{
  // The shift epsilon is this factor times trace(A) / trace(M), a typical
  // eigenvalue of the pencil: it scales like A / M, so the shifted problem and
  // hence the result do not change when the mesh is scaled, and it is small
  // enough to leave the smallest eigenvector dominant by far, yet large enough
  // for A + epsilon M to be safely positive definite when lambda_1 = 0.
  double relative_shift = 1e-8;
  double residual_tolerance = 1e-10;
  std::size_t max_iterations = 1000;
  unsigned int random_seed = 0;
  // asked before each solve with the share of the iteration done (estimated
  // from the residual's fall towards the tolerance); false stops the
  // iteration (Computation_interrupted)
  std::function<bool(double)> keep_going;
  // Vectors per block solve; the largest basis kept for Rayleigh-Ritz (its
  // memory is basis_size complex vectors); how many of its best Ritz vectors
  // a restart keeps. Keeping several matters where the lowest eigenvalues
  // cluster (a sphere): with too few, a restart loses the converging
  // direction and the solves multiply (the benchmark's README).
  Eigen::Index block_size = 1;
  Eigen::Index basis_size = 12;
  Eigen::Index restart_size = 4;
  bool same_pattern = false;  // A - sigma M has the pattern of the previous factorization
  // From `coarse_threshold` vertices on, the start vector and the shift come
  // from coarse versions of the problem (levels of aggregation down to fewer
  // than `coarse_threshold` vertices, solved to `coarse_tolerance`), each
  // prolongated and smoothed by `smoothing_sweeps` Jacobi sweeps. The
  // Rayleigh quotient R of the finest one bounds lambda_1 from above, and
  // A - shift_fraction R M is factored instead of A + epsilon M when the
  // solver can tell whether that matrix is positive definite (otherwise, or
  // if it is not, A + epsilon M is).
  // The fraction depends on the energy's s: see shift_fraction_for().
  Eigen::Index coarse_threshold = 5000;
  double coarse_tolerance = 1e-4;
  int smoothing_sweeps = 4;
  double shift_fraction = shift_fraction_for(0.);
  // M diagonal, stored with A's pattern (fields on faces): the coarse levels'
  // transport is read from -A (see aggregate_vertices())
  bool transport_in_energy = false;
  // whether A - sigma M may be factored in single precision (see
  // factor_below_smallest_eigenvalue()), and the solves after which a
  // single-precision factor is replaced if the best residual has not fallen
  // tenfold over them (see iterate_with_rayleigh_ritz()). No shared mesh
  // comes near: with single precision, each needs the solves it needs in
  // double precision (the benchmark's README).
  bool single_precision = true;
  std::size_t stall_window = 8;
  // On a stall, the shift moves to theta - reshift_fraction (theta - sigma), theta the best Ritz value, at most
  // max_reshifts times (see smallest_eigenpair()).
  double reshift_fraction = 0.15;
  int max_reshifts = 4;
  // The shift also moves before a stall, to the bound of early_reshift_target(), when that brings it
  // `early_reshift_gain` times closer to the best Ritz value and the iteration's rate over its last solves leaves
  // `early_reshift_min_solves` solves or more to the tolerance (a factorization costs several solves; with fewer
  // left a new one does not pay). A gain of 0 turns this off. These moves count among the `max_reshifts`.
  // Off by default: it helps an iteration started from the shift -epsilon on surfaces of high genus, but
  // started from the coarse bound, as the engine starts, the first targets lie above lambda_1 (the Ritz value's
  // nearest eigenvalue is not yet lambda_1), and each refusal costs a factorization and a move (the benchmark's
  // README).
  double early_reshift_gain = 0.;
  double early_reshift_min_solves = 12.;
};

// An eigenvector computed to the relative residual `tolerance` is
// determined to about that fraction of its largest entries: below this
// threshold (relative to the largest modulus) its entries, and so the
// directions and singularities there, may differ between solvers, seeds and
// numbers of processes (user manual, "Where the Field Vanishes").
inline double low_magnitude_threshold(double tolerance) { return 100. * tolerance; }

// The fraction of the entries of u whose modulus is below `relative` times the largest.
inline double fraction_below(const Complex_vector& u, double relative)
{
  if(u.size() == 0) return 0.;
  const double largest = u.cwiseAbs().maxCoeff();
  Eigen::Index below = 0;
  for(Eigen::Index i = 0; i < u.size(); ++i)
    if(std::abs(u[i]) < relative * largest) ++below;
  return double(below) / double(u.size());
}

struct Eigen_solve_result
{
  Complex_vector vector;  // M-normalized: u^* M u = 1
  double eigenvalue = 0.;
  double residual = 0.;   // ||A u - lambda M u|| / (s_A ||M u||), s_A = trace(A) / trace(M) (eigenvalue_scale())
  std::size_t iterations = 0;
  bool converged = false;
  double factorization_ms = 0., solve_ms = 0.;
  // the coarse estimate: its bound of lambda_1 (if it has one), the solves of
  // the coarsest level, the shift actually used (A + shift M was factored) and
  // whether the shift from the bound was tried and turned out too large
  std::optional<double> coarse_upper_bound;
  std::size_t coarse_iterations = 0;
  double shift = 0.;
  bool shift_rejected = false;
  // whether A + shift M was factored in single precision, and whether the
  // iteration then stalled and factored a single-precision factor's shift
  // again in double precision
  bool single_precision = false;
  bool refactored_in_double = false;
  int reshifts = 0;  // the moves of the shift tried, on stalls and early (see refactor_after_stall())
};


template <typename SparseSolver>
Eigen_solve_result smallest_eigenpair(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                      Factored_matrix<SparseSolver>& factored, const Eigen_solve_options& options);

// The eigenvector is defined up to a global phase, which the iteration leaves
// to rounding (the small dense eigenproblems of Rayleigh-Ritz choose a sign
// each): the phase that makes <x, M u> real and positive, for the seed's
// random vector x, is chosen instead. It moves continuously with u, so the
// same seed gives the same field after a rigid motion or another summation
// order (user manual, "Conventions").
inline void fix_global_phase(const Complex_vector& Mu, unsigned int seed, Complex_vector& u)
{
  const Complex c = random_start_vector(Mu.size(), seed).dot(Mu);
  if(!(std::abs(c) > 0.) || !std::isfinite(std::abs(c))) return;
  u *= std::conj(c) / std::abs(c);
}

struct Coarse_estimate
{
  Complex_vector vector;        // empty if there is no estimate
  std::optional<double> bound;  // an upper bound of lambda_1, with the vector
  std::size_t iterations = 0;
};

// A start vector and an upper bound of lambda_1 from the coarse problem of
// one level of aggregation: the coarse problem's own estimate (recursively)
// while it has `coarse_threshold` vertices or more, else its smallest
// eigenpair to `coarse_tolerance`, with a solver of the same type; then
// prolongated and smoothed. Only the coarsest level is solved: the smoothing
// at each level recovers as much as exact intermediate solves would (same
// solves on the fine level, at half the cost). No estimate if the solver type
// cannot be default-constructed, if aggregation does not halve the size, or
// if the coarsest solve fails.
template <typename SparseSolver>
Coarse_estimate coarse_estimate(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M, bool same_pattern,
                                const Eigen_solve_options& options)
{
  Coarse_estimate estimate;
  if constexpr(std::is_default_constructible<SparseSolver>::value)
  {
    if(!same_pattern) return estimate;
    const Aggregates aggregates =
      options.transport_in_energy ? aggregate_vertices(A, -1.) : aggregate_vertices(M);
    if(2 * aggregates.count > A.rows()) return estimate;
    Complex_sparse_matrix coarse_A, coarse_M;
    restrict_to_aggregates(A, M, aggregates, coarse_A, coarse_M);
    Complex_vector coarse_vector;
    if(coarse_A.rows() >= options.coarse_threshold)
    {
      Coarse_estimate coarse = coarse_estimate<SparseSolver>(coarse_A, coarse_M, true, options);
      coarse_vector.swap(coarse.vector);
      estimate.iterations = coarse.iterations;
    }
    else
    {
      SparseSolver coarse_solver;
      Factored_matrix<SparseSolver> coarse_factored(coarse_solver);
      Eigen_solve_options coarse_options = options;
      coarse_options.residual_tolerance = (std::max)(options.residual_tolerance, options.coarse_tolerance);
      coarse_options.same_pattern = false;
      if(options.keep_going)  // the coarse levels are a start: no share of the iteration done
        coarse_options.keep_going = [keep_going = options.keep_going](double) { return keep_going(0.); };
      try
      {
        Eigen_solve_result coarse = smallest_eigenpair(coarse_A, coarse_M, coarse_factored, coarse_options);
        coarse_vector.swap(coarse.vector);
        estimate.iterations = coarse.iterations;
      }
      catch(const Solver_failure_error&)
      {
      }
    }
    if(coarse_vector.size() != coarse_A.rows()) return estimate;
    Complex_vector x = prolongate(coarse_vector, aggregates);
    const std::optional<double> bound = smooth_and_bound(A, M, options.smoothing_sweeps, x);
    if(bound && std::isfinite(*bound) && x.allFinite())
    {
      estimate.vector.swap(x);
      estimate.bound = bound;
    }
  }
  return estimate;
}


// Factors A + shift M with the shift as close below lambda_1 as the coarse
// bound allows: shift = -shift_fraction R if that matrix is positive definite
// (R >= lambda_1, so it is unless R overestimates lambda_1 by 1 /
// shift_fraction or more), else shift = +epsilon (A + epsilon M). Not worth
// trying where lambda_1 is about 0. Records the shift in `result`.
//
// A + shift M may be factored in single precision (`single_allowed`, where
// the solver has such a factorization): the iteration applies the solve to
// residuals, so an inexact solve costs it no accuracy (see
// iterate_with_rayleigh_ritz()), and its convergence factor is about the
// solve's relative error, 1e-6 to 1e-3 for A - sigma M on the shared meshes.
// A + epsilon M is nearly singular when lambda_1 is about 0, and a
// single-precision solve with it has no correct digit: it is always factored
// in double precision.
template <typename SparseSolver>
void factor_below_smallest_eigenvalue(const Hermitian_pencil& pencil, std::optional<double> bound,
                                      const Eigen_solve_options& options, bool single_allowed,
                                      Factored_matrix<SparseSolver>& factored,
                                      Eigen_solve_result& result)
{
  typedef Factored_matrix<SparseSolver> Factored;
  result.shift = options.relative_shift * pencil.scale;
  bool factored_shifted = false;
  if(Factored::detects_indefinite && bound && options.shift_fraction * *bound > result.shift)
  {
    const double trial = -options.shift_fraction * *bound;
    factored.allow_single_precision(single_allowed);
    factored_shifted =
      factored.factor_if_positive_definite(pencil.matrix_to_factor<Factored>(trial), options.same_pattern);
    factored.allow_single_precision(false);
    if(factored_shifted)
      result.shift = trial;
    else
      result.shift_rejected = true;
  }
  if(!factored_shifted)
    factored.factor(pencil.matrix_to_factor<Factored>(result.shift), options.same_pattern);
}

// The Ritz vectors X of a step: their residuals R, r_j = A x_j - theta_j M x_j
// (theta_j: the Rayleigh quotient of x_j), and M X; the first one's
// eigenvalue and relative residual go to `result`. R holds A X first and is
// turned into the residuals in place (one vector of the mesh's size less).
inline void ritz_residuals(const Hermitian_pencil& pencil, const Complex_dense_matrix& X, Complex_dense_matrix& R,
                           Complex_dense_matrix& MX, Eigen_solve_result& result)
{
  pencil.multiply_pair(X, R, MX);
  for(Eigen::Index j = 0; j < X.cols(); ++j)
  {
    const double norm2 = (std::max)(0., X.col(j).dot(MX.col(j)).real());
    const double theta = norm2 > 0. ? X.col(j).dot(R.col(j)).real() / norm2 : 0.;
    R.col(j) -= theta * MX.col(j);
    if(j == 0)
    {
      result.eigenvalue = theta;
      result.residual = R.col(0).norm() / (pencil.scale * MX.col(0).norm());
    }
  }
}

// A shift below the eigenvalue nearest the Ritz value theta of x, from the residual r = A x - theta M x: some
// eigenvalue lies within ||r||_{M^-1} / ||x||_M of theta, and ||r||_{M^-1} <= sqrt(2) ||r||_{D^-1} for
// D = diag(M) wherever M >= D / 2, as for the mass matrix of a flat triangle (its eigenvalues relative to its
// diagonal are 2, 1/2, 1/2). The best Ritz value is an upper bound of lambda_1, so once its nearest eigenvalue is
// lambda_1 the bound is below lambda_1; before, or where the margin sqrt(2) does not hold, the factorization
// refuses the shift (refactor_after_stall()). None where the shift should not move yet (see
// Eigen_solve_options::early_reshift_gain); `best_residual` holds the best residual after each solve since
// the last factorization.
inline std::optional<double> early_reshift_target(const Hermitian_pencil& pencil, const Complex_vector& r,
                                                  const Complex_vector& x, const Complex_vector& Mx, double theta,
                                                  double sigma, const std::vector<double>& best_residual,
                                                  const Eigen_solve_options& options)
{
  const std::size_t k = best_residual.size() - 1;
  const double x_norm2 = x.dot(Mx).real();
  if(k < 2 || !(options.early_reshift_gain > 0.) || !(x_norm2 > 0.)) return std::nullopt;
  // ||r||_{D^-1} with r and D scaled first: at scales such as 1e-100 the plain sum of |r_i|^2 / D_i overflows
  const double largest = r.cwiseAbs().maxCoeff(), mean_mass = pencil.lumped_mass.mean();
  if(!(largest > 0.) || !(mean_mass > 0.)) return std::nullopt;
  const double scaled_sum = ((r / largest).cwiseAbs2().array() / (pencil.lumped_mass.array() / mean_mass)).sum();
  const double target = theta - std::sqrt(2. * scaled_sum / x_norm2) * largest / std::sqrt(mean_mass);
  if(!(target > sigma) || !(theta - sigma >= options.early_reshift_gain * (theta - target))) return std::nullopt;
  const std::size_t m = (std::min)(k, std::size_t(3));
  const double rate = std::pow(best_residual[k] / best_residual[k - m], 1. / double(m));
  const double remaining = rate < 1. ? std::log(options.residual_tolerance / best_residual[k]) / std::log(rate)
                                     : std::numeric_limits<double>::infinity();
  if(!(remaining >= options.early_reshift_min_solves)) return std::nullopt;
  return target;
}

// After a step of iterate_with_rayleigh_ritz() with the best Ritz pair (x, theta), residual r: records the
// step's residual and moves the shift, early (`refactor(theta, target)`, which returns whether it moved or
// factored), else on a stall (`refactor(theta, std::nullopt)`): when the best residual has not fallen tenfold over the
// last `options.stall_window` solves (a single step is no test: the residual of the best Ritz pair often grows
// for a step on the way). A new factorization starts a new history.
template <typename Refactor>
void reshift_if_due(const Hermitian_pencil& pencil, const Complex_vector& r, const Complex_vector& x,
                    const Complex_vector& Mx, const Eigen_solve_options& options, const Refactor& refactor,
                    const Eigen_solve_result& result, std::vector<double>& best_residual)
{
  best_residual.push_back((std::min)(best_residual.back(), result.residual));
  const std::optional<double> target =
    early_reshift_target(pencil, r, x, Mx, result.eigenvalue, -result.shift, best_residual, options);
  const std::size_t k = best_residual.size() - 1;
  const std::size_t window = (std::max)(std::size_t(1), options.stall_window);
  if(target && refactor(result.eigenvalue, target))
    best_residual.assign(1, best_residual.back());
  else if(k >= window && !(best_residual[k] <= 0.1 * best_residual[k - window]))
  {
    refactor(result.eigenvalue, std::nullopt);
    best_residual.assign(1, best_residual.back());
  }
}

// The iteration of smallest_eigenpair() on its factorization, from `start`:
// see there. Returns the best Ritz vector u and M u. `refactor` moves the
// shift (see reshift_if_due()); the iteration then goes on with the same
// basis.

template <typename SparseSolver, typename Refactor>
void iterate_with_rayleigh_ritz(const Hermitian_pencil& pencil, const Factored_matrix<SparseSolver>& factored,
                                const Eigen_solve_options& options, const Complex_dense_matrix& start,
                                const Refactor& refactor, Eigen_solve_result& result, Complex_vector& u,
                                Complex_vector& Mu)
{
  const Eigen::Index n = pencil.rows();
  const Eigen::Index block = start.cols();
  const Eigen::Index basis_size =
    (std::max)((std::max)(Eigen::Index(3), options.restart_size + 2) * block, (std::min)(options.basis_size, n));
  Ritz_basis basis(pencil, basis_size + 2 * block);
  // R and MX: the residuals and M X of the block `next`, while `current`;
  // in between, the basis's workspace for the products of what it adds
  Complex_dense_matrix R, MX;
  bool current = false;
  basis.add(start, R, MX);
  unsigned int next_seed = options.random_seed + static_cast<unsigned int>(block);
  Complex_dense_matrix next = basis.vectors();  // the block the next solve is applied to
  Complex_dense_matrix previous(n, 0);          // the best Ritz vectors of the previous step
  Complex_dense_matrix kept(n, 0);              // the best Ritz vectors a restart keeps
  ritz_residuals(pencil, next, R, MX, result);
  current = true;
  u = next.col(0);
  std::vector<double> best_residual(1, result.residual);  // after each solve
  while(result.iterations < options.max_iterations)
  {
    if(options.keep_going && !options.keep_going(share_done(best_residual, options.residual_tolerance)))
      throw Computation_interrupted("the computation was interrupted (progress_callback returned false)");
    Complex_dense_matrix W = factored.solve(R);
    ++result.iterations;
    current = false;
    if(basis.size() + W.cols() > basis_size)
    {
      // Restart with the best Ritz vectors and the previous best ones.
      basis.clear();
      basis.add(kept, R, MX);
      basis.add(previous, R, MX);
    }
    if(basis.add(std::move(W), R, MX) == 0)
    {
      // An invariant subspace: enrich with fresh random directions.
      if(basis.size() >= n || basis.add(random_block(n, block, next_seed), R, MX) == 0)
        break;
      next_seed += static_cast<unsigned int>(block);
    }

    // Rayleigh-Ritz: the best vectors of span(V), M-orthonormal.
    Eigen::GeneralizedSelfAdjointEigenSolver<Complex_dense_matrix> ritz(basis.projected_A(), basis.projected_M());
    if(ritz.info() != Eigen::Success)
      break;  // V^* M V not positive definite: cannot happen for a positive definite M
    const Eigen::Index k = basis.size();
    const Eigen::Index best = (std::min)(block, k);
    previous.swap(next);
    const Eigen::Index keep = (std::min)(k, (std::max)(best, options.restart_size));
    if(k + block > basis_size)  // the next step restarts: keep the best Ritz vectors
    {
      combine_columns(basis.vectors(), ritz.eigenvectors().leftCols(keep), kept);
      next = kept.leftCols(best);
    }
    else
      combine_columns(basis.vectors(), ritz.eigenvectors().leftCols(best), next);
    u = next.col(0);
    ritz_residuals(pencil, next, R, MX, result);
    current = true;
    if(result.residual <= options.residual_tolerance)
    {
      result.converged = true;
      break;
    }
    reshift_if_due(pencil, R.col(0), u, MX.col(0), options, refactor, result, best_residual);
  }
  // a step that ended early left the basis's products in MX: those of u
  // again (its eigenvalue and residual are those already in `result`)
  if(!current) ritz_residuals(pencil, next, R, MX, result);
  Mu = MX.col(0);  // MX = M u (u is next's first column)
}

// What smallest_eigenpair() does when its iteration stalls, or earlier when
// the residual shows lambda_1 close to the best Ritz value theta (an upper
// bound of lambda_1, far tighter than the coarse bound by then): the shift
// sigma moves to `target` if it is a number, else towards theta, at most
// `options.max_reshifts` times: where many eigenvalues crowd just above
// lambda_1 (surfaces of high genus) the rate (lambda_1 - sigma) /
// (lambda_2 - sigma) is close to 1 unless sigma is close to lambda_1. An
// early move (a target) once the moves are spent does nothing and returns
// false; otherwise the function returns true. The new shift is factored in single
// precision where the first one may be (a pivot that single precision
// refuses makes it double); the factorization tells whether it is still
// below lambda_1. If not, the old shift is factored again, in double
// precision. Once the re-shifts are spent, a stall with a single-precision
// factor factors its shift again in double precision (a single-precision
// factor too inexact for a shift close to lambda_1 thus costs stalls, not
// the convergence).
template <typename SparseSolver>
bool refactor_after_stall(const Hermitian_pencil& pencil, double theta, std::optional<double> target,
                          const Eigen_solve_options& options, Factored_matrix<SparseSolver>& factored,
                          Eigen_solve_result& result)
{
  typedef Factored_matrix<SparseSolver> Factored;
  const double sigma = -result.shift;
  const bool single = factored.holds_single_precision();
  const bool can_move =
    result.reshifts < options.max_reshifts && Factored::detects_indefinite && theta > sigma;
  if(target && !(can_move && *target > sigma)) return false;
  bool tried = false, moved = false;
  if(can_move)
  {
    ++result.reshifts;
    tried = true;
    const double closer = target ? *target : theta - options.reshift_fraction * (theta - sigma);
    factored.allow_single_precision(options.single_precision);
    moved = factored.factor_if_positive_definite(pencil.matrix_to_factor<Factored>(-closer), true);
    factored.allow_single_precision(false);
    if(moved) result.shift = -closer;
  }
  if(!moved && (tried || single))
  {
    factored.factor(pencil.matrix_to_factor<Factored>(-sigma), true);  // the shift it had, in double
    result.refactored_in_double = result.refactored_in_double || single;
  }
  return true;
}

// The coarse estimate of smallest_eigenpair(), with the symbolic analysis of
// A - sigma M beside it: the analysis does not depend on the shift sigma
// that the estimate gives, and reads A's pattern (which is M's), unless an
// earlier factorization's is reused (then `same_pattern` stays as it was).
template <typename SparseSolver>
Coarse_estimate estimate_and_analyze(const Hermitian_pencil& pencil, const Complex_sparse_matrix& A,
                                     const Complex_sparse_matrix& M, Factored_matrix<SparseSolver>& factored,
                                     const Eigen_solve_options& options, bool& same_pattern)
{
  const Eigen::Index n = A.rows();
  Coarse_estimate estimate;
  auto estimate_coarsely = [&] {
    if(n >= options.coarse_threshold)
      estimate = coarse_estimate<SparseSolver>(A, M, pencil.same_pattern, options);
  };
  if(Factored_matrix<SparseSolver>::analyzes_patterns && pencil.same_pattern && !options.same_pattern &&
     n >= options.coarse_threshold)
  {
    parallel_invoke(estimate_coarsely, [&] { factored.analyze_pattern(A); });
    same_pattern = true;
  }
  else
    estimate_coarsely();
  return estimate;
}

// The smallest eigenpair of the pencil (A, M) (user manual, section "The
// Smoothest Field").
//
// Inverse iteration, X <- (A - sigma M)^{-1} M X, on one factorization of
// A - sigma M (sigma from the coarse estimate, or -epsilon; the factored
// matrix is A + shift M with shift = -sigma), applied to a block of
// `block_size` vectors (1 by default: a block of b vectors saves fewer solves
// than the b times more work of a block solve), accelerated by Rayleigh-Ritz:
// the iterates are kept as a basis V (orthonormal for the lumped mass
// diag(M), which needs no sparse product and keeps V^* M V well conditioned)
// and the best vector of span(V) is the smallest eigenpair of the small
// pencil (V^* A V, V^* M V). Each step applies the solve to the current best
// Ritz vectors x_j, or rather to their residuals A x_j - theta_j M x_j: with
// x_j, (A - sigma M)^{-1} of the residual spans the same space as
// (A - sigma M)^{-1} M x_j, but its part that improves x_j is no longer the
// small difference of two large vectors, so a solve with a relative error
// (a single-precision factor) still improves x_j at the rate of an exact
// one, down to any tolerance. The basis holds the iterates of a Krylov-like
// sequence; on
// symmetric shapes, whose lowest eigenvalues cluster (a round sphere, a torus
// of revolution), this converges where plain inverse iteration would need
// thousands of steps. When V is full it is restarted with its `restart_size`
// best Ritz vectors (the next ones matter where eigenvalues cluster) and the
// previous best Ritz vectors, whose span holds the step direction (as in
// LOBPCG). Only V is stored (not A V, M V), so the memory is about
// `basis_size` + `restart_size` + 6 blocks of `block_size` vectors (with the
// kept, previous and next Ritz vectors, the residuals, their solve and M
// times the Ritz vectors). The iteration stops when the
// relative residual of the best Ritz pair reaches the tolerance;
// `iterations` counts the solves (of a block each).
//
// smallest_eigenpair_of() is smallest_eigenpair() with, in `owned`, A and M
// that nobody reads after it (or null): see smallest_eigenpair_freeing_matrices().
template <typename SparseSolver>
Eigen_solve_result smallest_eigenpair_of(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                         Factored_matrix<SparseSolver>& factored, const Eigen_solve_options& options,
                                         std::pair<Complex_sparse_matrix*, Complex_sparse_matrix*> owned)
{
  typedef std::chrono::steady_clock Clock;
  const Eigen::Index n = A.rows();
  Eigen_solve_result result;
  Hermitian_pencil pencil(A, M);
  Eigen_solve_options options_after_analysis = options;

  const auto t_start = Clock::now();
  Coarse_estimate estimate =
    estimate_and_analyze(pencil, A, M, factored, options, options_after_analysis.same_pattern);
  result.coarse_upper_bound = estimate.bound;
  result.coarse_iterations = estimate.iterations;
  std::optional<Compact_hermitian_pencil> compact;
  if(owned.first != nullptr && Factored_matrix<SparseSolver>::factors_lower_triangle && pencil.same_pattern)
  {
    compact.emplace(A, M);
    if(compact->valid())
    {
      pencil.use_compact_form(*compact);
      Complex_sparse_matrix().swap(*owned.first);  // (an assignment would keep the arrays)
      Complex_sparse_matrix().swap(*owned.second);
    }
    else
      compact.reset();
  }

  const auto t0 = Clock::now();
  factor_below_smallest_eigenvalue(pencil, estimate.bound, options_after_analysis, options.single_precision,
                                   factored, result);
  result.single_precision = factored.holds_single_precision();
  const auto t1 = Clock::now();
  double refactorization_ms = 0.;
  auto refactor = [&](double theta, std::optional<double> target) {
    const auto start = Clock::now();
    options_after_analysis.same_pattern = true;
    const bool acted = refactor_after_stall(pencil, theta, target, options, factored, result);
    refactorization_ms += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
    return acted;
  };

  const Eigen::Index block = (std::max)(Eigen::Index(1), (std::min)(options.block_size, n));
  Complex_dense_matrix start = random_block(n, block, options.random_seed);
  if(estimate.vector.size() == n) start.col(0) = estimate.vector;
  Complex_vector u, Mu;
  iterate_with_rayleigh_ritz(pencil, factored, options, start, refactor, result, u, Mu);
  const auto t2 = Clock::now();

  const double norm_u = std::sqrt((std::max)(0., u.dot(Mu).real()));
  result.vector = (norm_u > 0.) ? Complex_vector(u / norm_u) : u;
  fix_global_phase(Mu, options.random_seed, result.vector);
  result.factorization_ms = std::chrono::duration<double, std::milli>(t1 - t0).count() + refactorization_ms;
  result.solve_ms =
    std::chrono::duration<double, std::milli>((t2 - t1) + (t0 - t_start)).count() - refactorization_ms;
  return result;
}

template <typename SparseSolver>
Eigen_solve_result smallest_eigenpair(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                      Factored_matrix<SparseSolver>& factored, const Eigen_solve_options& options)
{
  return smallest_eigenpair_of(A, M, factored, options, {nullptr, nullptr});
}

// smallest_eigenpair() for A and M of a single use (the free function's):
// once the coarse estimate and the ordering have read them, they are freed
// (left empty) and the factorizations and products read their compact form
// instead (compact_pencil.h), the same values in less memory, where the
// solver factors only the lower triangle and A and M have one pattern. The
// result is the same.
template <typename SparseSolver>
Eigen_solve_result smallest_eigenpair_freeing_matrices(Complex_sparse_matrix& A, Complex_sparse_matrix& M,
                                                       Factored_matrix<SparseSolver>& factored,
                                                       const Eigen_solve_options& options)
{
  return smallest_eigenpair_of(A, M, factored, options, {&A, &M});
}

} // namespace internal
} // namespace Surface_mesh_direction_fields
} // namespace CGAL

#endif // CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_LINEAR_ALGEBRA_EIGEN_SOLVE_H
