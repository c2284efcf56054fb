// Issue 50's multigrid path in the form the library would hold it (a
// prototype, measured in README.md, "The multigrid path as the library would
// run it"): the smallest eigenpair of the smoothest field's pencil (A, M) by
// LOBPCG with one vector, preconditioned by a two-level cycle of
// B = A + epsilon M, with the package's parallel products and its own
// factorization of the coarse level. Not in include/: at 1.6M faces it is
// slower than the direct path, which the package keeps.
#ifndef SMDF_BENCHMARK_MULTIGRID_PATH_PROTOTYPE_H
#define SMDF_BENCHMARK_MULTIGRID_PATH_PROTOTYPE_H

#include <CGAL/Surface_mesh_direction_fields/exceptions.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/coarse_hierarchy.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/eigen_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/hermitian_products.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/matrix_types.h>
#include <CGAL/Surface_mesh_direction_fields/internal/parallel.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>
#include <vector>

// Nothing of the size of the mesh's own factor is stored: the fine level is
// only smoothed (damped Jacobi), and the one factorization is of the coarse
// level, an aggregate of about seven vertices per row.

namespace multigrid_prototype {

using namespace CGAL::Surface_mesh_direction_fields::internal;
using CGAL::Surface_mesh_direction_fields::Computation_interrupted;
using CGAL::Surface_mesh_direction_fields::Solver_failure_error;

struct Multigrid_options
{
  // Aggregates follow the strong couplings only: positive weights above
  // `strength` sqrt(A_ii A_jj) (algebraic multigrid's strength of
  // connection). Across the negative cotangent weights of obtuse triangles
  // and along the weak direction of stretched ones, aggregates hold no
  // smooth mode, and the cycle's rate degrades (README.md, "Toward a factor-free eigen-solve").
  double strength = 0.1;
  double damping = 2. / 3.;
  int sweeps = 2;               // Jacobi sweeps before and after the coarse correction
  int start_iterations = 20;    // inverse iterations on the coarse level for the start vector
};

// y = S^* x for any S stored in compressed columns: entry j is a dot product
// over column j, so columns run in parallel without write conflicts.
inline void adjoint_times(const Complex_sparse_matrix& S, const Eigen::Ref<const Complex_vector>& x, Complex_vector& y)
{
  y.resize(S.cols());
  const auto* outer = S.outerIndexPtr();
  const auto* inner = S.innerIndexPtr();
  const Complex* value = S.valuePtr();
  parallel_for_each_index(static_cast<std::size_t>(S.outerSize()), [&](std::size_t j) {
    Complex sum(0., 0.);
    for(auto p = outer[j]; p < outer[j + 1]; ++p) sum += std::conj(value[p]) * x[inner[p]];
    y[static_cast<Eigen::Index>(j)] = sum;
  });
}

// The couplings aggregation may follow: M's entries (their phases carry the
// transport) where the weight -A_ij, turned by the conjugate of M_ij's
// phase, is positive and strong. A and M share one pattern.
inline Complex_sparse_matrix strong_couplings(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                              double strength)
{
  Complex_sparse_matrix strong = M;
  const auto* outer = A.outerIndexPtr();
  const auto* inner = A.innerIndexPtr();
  const Complex* a = A.valuePtr();
  Complex* m = strong.valuePtr();
  const Eigen::VectorXd d = A.diagonal().real();
  parallel_for_each_index(static_cast<std::size_t>(A.outerSize()), [&](std::size_t c) {
    for(auto p = outer[c]; p < outer[c + 1]; ++p)
    {
      const auto r = inner[p];
      if(static_cast<std::size_t>(r) == c) continue;
      const double weight = (-a[p] * std::conj(unit(m[p]))).real();
      if(!(weight > strength * std::sqrt(d[r] * d[static_cast<Eigen::Index>(c)]))) m[p] = Complex(0., 0.);
    }
  });
  strong.prune(Complex(0., 0.));
  return strong;
}

// The smoothed-aggregation prolongation P = (I - w D^-1 A) P0, P0 the
// aggregates' one (P0_{i, agg(i)} = phase_i), D the diagonal of B. Column c
// of A P0 gathers the columns of A of the aggregate's members, so columns are
// built independently (fixed chunks, in parallel) and then copied in place.
inline Complex_sparse_matrix smoothed_prolongation(const Complex_sparse_matrix& A, const Eigen::VectorXd& diagonal,
                                                   const Aggregates& g, double damping)
{
  typedef Complex_sparse_matrix::StorageIndex Storage_index;
  const Eigen::Index n = A.rows(), nc = g.count;
  std::vector<Eigen::Index> first, members;
  aggregate_members(g, first, members);

  typedef std::pair<Storage_index, Complex> Entry;
  const std::size_t chunks = (static_cast<std::size_t>(nc) + parallel_grain_size - 1) / parallel_grain_size;
  std::vector<std::vector<Entry> > chunk_entries(chunks);
  std::vector<Storage_index> column_size(static_cast<std::size_t>(nc), 0);
  parallel_for_each_chunk(static_cast<std::size_t>(nc), [&](std::size_t begin, std::size_t end) {
    std::vector<Entry>& entries = chunk_entries[begin / parallel_grain_size];
    for(std::size_t c = begin; c < end; ++c)
    {
      const std::size_t column_begin = entries.size();
      for(Eigen::Index k = first[c]; k < first[c + 1]; ++k)
      {
        const Eigen::Index j = members[static_cast<std::size_t>(k)];
        entries.emplace_back(static_cast<Storage_index>(j), g.phase[j]);
        for(Complex_sparse_matrix::InnerIterator it(A, j); it; ++it)
          entries.emplace_back(static_cast<Storage_index>(it.row()),
                               -damping * it.value() * g.phase[j] / diagonal[it.row()]);
      }
      auto column = entries.begin() + static_cast<std::ptrdiff_t>(column_begin);
      std::sort(column, entries.end(), [](const Entry& x, const Entry& y) { return x.first < y.first; });
      std::size_t kept = column_begin;  // sum the entries of one row
      for(std::size_t e = column_begin; e < entries.size(); ++e)
        if(kept > column_begin && entries[kept - 1].first == entries[e].first)
          entries[kept - 1].second += entries[e].second;
        else
          entries[kept++] = entries[e];
      entries.resize(kept);
      column_size[c] = static_cast<Storage_index>(kept - column_begin);
    }
  });
  std::vector<std::size_t> offset(chunks + 1, 0);
  for(std::size_t c = 0; c < chunks; ++c) offset[c + 1] = offset[c] + chunk_entries[c].size();
  Complex_sparse_matrix P(n, nc);
  P.resizeNonZeros(static_cast<Eigen::Index>(offset[chunks]));
  P.outerIndexPtr()[0] = 0;
  for(std::size_t c = 0; c < static_cast<std::size_t>(nc); ++c)
    P.outerIndexPtr()[c + 1] = P.outerIndexPtr()[c] + column_size[c];
  parallel_for_each_task(chunks, [&](std::size_t c) {
    for(std::size_t e = 0, p = offset[c]; e < chunk_entries[c].size(); ++e, ++p)
    {
      P.innerIndexPtr()[p] = chunk_entries[c][e].first;
      P.valuePtr()[p] = chunk_entries[c][e].second;
    }
  });
  return P;
}

// The two-level cycle of B = A + epsilon M: damped Jacobi sweeps on the mesh
// (with B's diagonal, and A for the off-diagonal part: epsilon M changes
// B by 1e-8 of its scale), a coarse correction with the Galerkin matrix
// P^* B P, factored, and the same sweeps after: a symmetric cycle, hence a
// Hermitian positive definite preconditioner, as LOBPCG requires.
template <typename Factorization>
class Two_level_cycle
{
public:
  Two_level_cycle(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M, double epsilon,
                  const Multigrid_options& options, Factorization& coarse)
    : m_A(A), m_options(options), m_coarse(coarse)
  {
    const Eigen::VectorXd diagonal = A.diagonal().real() + epsilon * M.diagonal().real();
    m_inverse_diagonal = options.damping * diagonal.cwiseInverse();
    const Aggregates g = aggregate_vertices(strong_couplings(A, M, options.strength));
    m_P = smoothed_prolongation(A, diagonal, g, options.damping);
    m_P_adjoint = m_P.adjoint();
    const Complex_sparse_matrix AP = A * m_P;
    const Complex_sparse_matrix Ac = m_P_adjoint * AP;
    const Complex_sparse_matrix MP = M * m_P;
    m_coarse_mass = m_P_adjoint * MP;
    m_coarse.factor(Factorization::matrix_to_factor(Ac, m_coarse_mass, epsilon));
  }

  Eigen::Index coarse_rows() const { return m_P.cols(); }

  // r <- the cycle applied to r (n x 1), in buffers kept between calls.
  void apply_in_place(Complex_dense_matrix& r) const
  {
    m_b = r;
    Complex_dense_matrix& x = r;
    x.col(0) = m_inverse_diagonal.cwiseProduct(m_b.col(0));  // the first sweep from x = 0
    for(int s = 1; s < m_options.sweeps; ++s) sweep(x);
    hermitian_multiply(m_A, x, m_Ax);
    m_Ax = m_b - m_Ax;
    adjoint_times(m_P, m_Ax.col(0), m_coarse_rhs);
    const Complex_dense_matrix xc = m_coarse.solve(m_coarse_rhs);
    adjoint_times(m_P_adjoint, xc.col(0), m_correction);
    x.col(0) += m_correction;
    for(int s = 0; s < m_options.sweeps; ++s) sweep(x);
  }

  // A start vector: inverse iteration on the coarse pencil, prolongated.
  Complex_vector coarse_start(unsigned int seed, int iterations) const
  {
    // y is kept at unit M-norm: M y serves the norm and the next solve.
    Complex_vector y = random_start_vector(coarse_rows(), seed);
    Complex_dense_matrix My = hermitian_multiply(m_coarse_mass, y);
    for(int k = 0; k < iterations; ++k)
    {
      y = m_coarse.solve(My).col(0);
      hermitian_multiply(m_coarse_mass, y, My);
      const double norm = std::sqrt((std::max)(std::numeric_limits<double>::min(), y.dot(My.col(0)).real()));
      y /= norm;
      My /= norm;
    }
    Complex_vector x;
    adjoint_times(m_P_adjoint, y, x);
    return x;
  }

  // The coarse mass is needed for the start only.
  void forget_coarse_mass() { m_coarse_mass = Complex_sparse_matrix(); }

  // The Galerkin pencil's matrices (P^* A P, P^* M P), for measurements.
  std::pair<Complex_sparse_matrix, Complex_sparse_matrix> coarse_pencil(const Complex_sparse_matrix& M) const
  {
    const Complex_sparse_matrix AP = m_A * m_P, MP = M * m_P;
    return std::make_pair(Complex_sparse_matrix(m_P_adjoint * AP), Complex_sparse_matrix(m_P_adjoint * MP));
  }

private:
  // x += w D^-1 (b - A x)
  void sweep(Complex_dense_matrix& x) const
  {
    hermitian_multiply(m_A, x, m_Ax);
    x.col(0) += m_inverse_diagonal.cwiseProduct(m_b.col(0) - m_Ax.col(0));
  }

  const Complex_sparse_matrix& m_A;
  const Multigrid_options& m_options;
  Factorization& m_coarse;
  Eigen::VectorXcd m_inverse_diagonal;
  Complex_sparse_matrix m_P, m_P_adjoint, m_coarse_mass;
  mutable Complex_dense_matrix m_b, m_Ax;
  mutable Complex_vector m_coarse_rhs, m_correction;
};

// The lowest `count` eigenvalues of the pencil (K, N), with `factor` holding
// K + epsilon N: subspace iteration on count + 3 vectors with Rayleigh-Ritz,
// until the relative residuals of the lowest `count` fall below `tolerance`
// (the eigenvalues are then accurate to about its square) or `iterations`
// steps. For measurements: the fine and coarse levels' spectra compared.
template <typename Factorization>
Eigen::VectorXd lowest_eigenvalues(const Complex_sparse_matrix& K, const Complex_sparse_matrix& N,
                                   const Factorization& factor, int count, double tolerance, int iterations,
                                   double& residual)
{
  const Eigen::Index n = K.rows(), block = count + 3;
  Complex_dense_matrix X(n, block), KX, NX, GK, GN, Y;
  for(Eigen::Index j = 0; j < block; ++j) X.col(j) = random_start_vector(n, static_cast<unsigned int>(j + 1));
  hermitian_multiply(N, X, NX);
  const double scale = eigenvalue_scale(K, N);
  Eigen::VectorXd values;
  for(int step = 0; step < iterations; ++step)
  {
    X = factor.solve(NX);
    hermitian_multiply_pair(K, N, true, X, KX, NX);
    adjoint_products(X, KX, NX, GK, GN);
    Eigen::GeneralizedSelfAdjointEigenSolver<Complex_dense_matrix> ritz(0.5 * (GK + GK.adjoint()),
                                                                         0.5 * (GN + GN.adjoint()));
    values = ritz.eigenvalues().head(count);
    const Complex_dense_matrix& C = ritz.eigenvectors();  // N-orthonormal Ritz vectors, and their images
    combine_columns(X, C, Y);
    X.swap(Y);
    combine_columns(KX, C, Y);
    KX.swap(Y);
    combine_columns(NX, C, Y);
    NX.swap(Y);
    residual = 0.;
    for(Eigen::Index j = 0; j < count; ++j)
      residual = (std::max)(residual, (KX.col(j) - values[j] * NX.col(j)).norm() / (scale * NX.col(j).norm()));
    if(residual <= tolerance) break;
  }
  return values;
}

// One LOBPCG step's space: columns x, w, p of S (the first `columns` of
// them: p is absent on the first step) with their images under A and M,
// allocated once (fresh pages are slow on large meshes).
struct Lobpcg_space
{
  Complex_dense_matrix S, AS, MS, next, A_next, M_next, w, Aw, Mw;
  Eigen::Index columns = 1;

  explicit Lobpcg_space(Eigen::Index n)
    : S(n, 3), AS(n, 3), MS(n, 3), next(n, 2), A_next(n, 2), M_next(n, 2), w(n, 1), Aw(n, 1), Mw(n, 1)
  {}

  // The smallest Ritz pair: coefficients c over the columns (c^* S^* M S c =
  // 1). Columns are first scaled to unit M-norm, then the Gram matrix's
  // nearly dependent directions dropped (SVQB): a correction that is already
  // tiny survives the scaling, where a threshold relative to the largest
  // column would drop it and stall the iteration.
  Eigen::VectorXcd smallest_ritz_vector() const
  {
    Complex_dense_matrix GA, GM;
    adjoint_products(S.leftCols(columns), AS.leftCols(columns), MS.leftCols(columns), GA, GM);
    Eigen::VectorXd d = GM.diagonal().real();
    for(Eigen::Index i = 0; i < d.size(); ++i) d[i] = d[i] > 0. ? 1. / std::sqrt(d[i]) : 0.;
    const Complex_dense_matrix scaled = d.asDiagonal() * GM * d.asDiagonal();
    Eigen::SelfAdjointEigenSolver<Complex_dense_matrix> gram(0.5 * (scaled + scaled.adjoint()));
    const double largest = gram.eigenvalues().maxCoeff();
    std::vector<Eigen::Index> kept;
    for(Eigen::Index k = 0; k < scaled.rows(); ++k)
      if(gram.eigenvalues()[k] > 1e-12 * largest) kept.push_back(k);
    Complex_dense_matrix C(scaled.rows(), static_cast<Eigen::Index>(kept.size()));
    for(std::size_t k = 0; k < kept.size(); ++k)
      C.col(static_cast<Eigen::Index>(k)) =
        d.asDiagonal() * gram.eigenvectors().col(kept[k]) / std::sqrt(gram.eigenvalues()[kept[k]]);
    const Complex_dense_matrix H = C.adjoint() * GA * C;
    Eigen::SelfAdjointEigenSolver<Complex_dense_matrix> ritz(0.5 * (H + H.adjoint()));
    return C * ritz.eigenvectors().col(0);
  }

  // The Ritz vector of coefficients c as the new x, c's part along w and p
  // as the new p (scaled to unit M-norm); images by linear combination
  // (checked by explicit products before convergence is declared).
  void step(const Eigen::VectorXcd& c)
  {
    Complex_dense_matrix C = Complex_dense_matrix::Zero(columns, 2);
    C.col(0) = c;
    C.col(1).tail(columns - 1) = c.tail(columns - 1);
    combine_columns(S.leftCols(columns), C, next);
    combine_columns(AS.leftCols(columns), C, A_next);
    combine_columns(MS.leftCols(columns), C, M_next);
    const double p_norm = std::sqrt((std::max)(0., next.col(1).dot(M_next.col(1)).real()));
    S.col(0) = next.col(0);
    AS.col(0) = A_next.col(0);
    MS.col(0) = M_next.col(0);
    columns = p_norm > 0. ? 3 : 1;
    if(columns == 1) return;
    S.col(2) = next.col(1) / p_norm;
    AS.col(2) = A_next.col(1) / p_norm;
    MS.col(2) = M_next.col(1) / p_norm;
  }

  // The preconditioned residual in `w`, made M-orthogonal to x (projected
  // twice: once leaves rounding of the size of w's part along x) and of unit
  // M-norm, as the second column, with its images.
  bool add_correction(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M)
  {
    for(int pass = 0; pass < 2; ++pass) w.col(0) -= MS.col(0).dot(w.col(0)) * S.col(0);
    hermitian_multiply_pair(A, M, true, w, Aw, Mw);
    const double norm = std::sqrt((std::max)(0., w.col(0).dot(Mw.col(0)).real()));
    if(!(norm > 0.)) return false;
    S.col(1) = w.col(0) / norm;
    AS.col(1) = Aw.col(0) / norm;
    MS.col(1) = Mw.col(0) / norm;
    if(columns == 1) columns = 2;
    return true;
  }

  // x's Rayleigh quotient theta and relative residual, as the direct path
  // measures it (eigen_solve.h): ||A x - theta M x|| / (s_A ||M x||); the
  // residual itself into `w`.
  double residual(double scale, double& theta)
  {
    theta = S.col(0).dot(AS.col(0)).real() / S.col(0).dot(MS.col(0)).real();
    w.col(0) = AS.col(0) - theta * MS.col(0);
    return w.col(0).norm() / (scale * MS.col(0).norm());
  }

  void recompute_images(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M)
  {
    next.col(0) = S.col(0);
    hermitian_multiply_pair(A, M, true, next.leftCols(1), A_next, M_next);
    AS.col(0) = A_next.col(0);
    MS.col(0) = M_next.col(0);
  }
};

// LOBPCG with one vector, preconditioned by `precondition` (which maps the
// residual in its argument to the correction, in place), from x0, to the
// relative residual of `options`.
template <typename Preconditioner>
void lobpcg_iterate(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M, const Preconditioner& precondition,
                    const Complex_vector& x0, const Eigen_solve_options& options, Eigen_solve_result& result)
{
  const double scale = eigenvalue_scale(A, M);
  Lobpcg_space space(A.rows());
  space.S.col(0) = x0;
  space.recompute_images(A, M);
  const double x_norm = std::sqrt(space.S.col(0).dot(space.MS.col(0)).real());
  if(!(x_norm > 0.)) throw Solver_failure_error("the multigrid path's start vector vanished");
  space.S.col(0) /= x_norm;
  space.AS.col(0) /= x_norm;
  space.MS.col(0) /= x_norm;
  bool images_exact = true;
  for(;;)
  {
    double theta = 0.;
    result.residual = space.residual(scale, theta);
    result.eigenvalue = theta;
    if(result.residual <= options.residual_tolerance && !images_exact)
    {
      space.recompute_images(A, M);  // the combined images drift by rounding
      images_exact = true;
      continue;
    }
    result.converged = result.residual <= options.residual_tolerance;
    if(result.converged || result.iterations >= options.max_iterations) break;
    if(options.keep_going && !options.keep_going(0.))
      throw Computation_interrupted("the computation was interrupted (progress_callback returned false)");
    ++result.iterations;
    precondition(space.w);
    if(!space.add_correction(A, M)) break;
    space.step(space.smallest_ritz_vector());
    images_exact = false;
  }
  result.vector = space.S.col(0);
  fix_global_phase(space.MS.col(0), options.random_seed, result.vector);
}

// The smallest eigenpair of (A, M) on the multigrid path; `coarse` factors
// the coarse level (the package's own factorization or the user's solver).
// A and M must share one pattern (vertex fields).
template <typename Factorization>
Eigen_solve_result multigrid_smallest_eigenpair(const Complex_sparse_matrix& A, const Complex_sparse_matrix& M,
                                                Factorization& coarse, const Eigen_solve_options& options,
                                                const Multigrid_options& multigrid = Multigrid_options())
{
  typedef std::chrono::steady_clock Clock;
  const Clock::time_point start = Clock::now();
  Eigen_solve_result result;
  const double epsilon = options.relative_shift * eigenvalue_scale(A, M);
  Two_level_cycle<Factorization> cycle(A, M, epsilon, multigrid, coarse);
  const Complex_vector x0 = cycle.coarse_start(options.random_seed, multigrid.start_iterations);
  cycle.forget_coarse_mass();
  result.factorization_ms = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
  lobpcg_iterate(A, M, [&cycle](Complex_dense_matrix& r) { cycle.apply_in_place(r); }, x0, options, result);
  return result;
}

} // namespace multigrid_prototype

#endif // SMDF_BENCHMARK_MULTIGRID_PATH_PROTOTYPE_H
