// The linear-algebra layer on its own (internal/Linear_algebra/): it includes
// no mesh header, and its eigen-solve and linear solves are checked here on a
// pencil with closed-form eigenpairs, without any mesh.
//
// The pencil: the piecewise-linear finite elements of a "magnetic" cycle of N
// nodes, where the transport along each edge is e^{i alpha} (total holonomy
// Phi = N alpha): A has 2 on the diagonal and -e^{i alpha} from node j to
// node j + 1, M has 4/6 and e^{i alpha} / 6. Both are circulant, so their
// eigenvectors are the Fourier modes u_j = e^{2 pi i m j / N}; on mode m an
// edge compares e^{2 pi i m / N} with the transport e^{i alpha}, so
//     lambda_m = (2 - 2 cos theta_m) / (4/6 + 2/6 cos theta_m),
//     theta_m = (2 pi m - Phi) / N,
// and for |Phi| < pi the smallest is m = 0: the constant vector.

#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/eigen_solve.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/linear_solves.h>

// The layer must not have pulled in the mesh plumbing, the method or the BGL.
#if defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_MESH_INDEXED_MESH_H) ||                                        \
  defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_ASSEMBLY_H) ||                                           \
  defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_INTERNAL_METHOD_TANGENT_SPACES_H) ||                                     \
  defined(CGAL_BOOST_GRAPH_HELPERS_H) || defined(CGAL_BOOST_GRAPH_ITERATOR_H)
#error "a Linear_algebra header includes a mesh header"
#endif

#include <CGAL/Eigen_solver_traits.h>

#include "test_support.h"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

namespace SI = CGAL::Surface_mesh_direction_fields::internal;
typedef std::complex<double> Complex;
typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<SI::Complex_sparse_matrix> > Solver;

struct Cycle_pencil
{
  SI::Complex_sparse_matrix A, M;
};

// Both matrices share one pattern (as the package's assembly makes them).
static Cycle_pencil magnetic_cycle(Eigen::Index n, double holonomy)
{
  const Complex r = std::polar(1., holonomy / static_cast<double>(n));
  std::vector<Eigen::Triplet<Complex> > a, m;
  for(Eigen::Index j = 0; j < n; ++j)
  {
    const Eigen::Index k = (j + 1) % n;
    a.emplace_back(j, j, 2.);
    m.emplace_back(j, j, 4. / 6.);
    // the energy |u_k - r u_j|^2 couples (row k, column j) by -r, its Hermitian pair by -conj(r)
    a.emplace_back(k, j, -r);
    a.emplace_back(j, k, -std::conj(r));
    m.emplace_back(k, j, r / 6.);
    m.emplace_back(j, k, std::conj(r) / 6.);
  }
  Cycle_pencil p;
  p.A.resize(n, n);
  p.M.resize(n, n);
  p.A.setFromTriplets(a.begin(), a.end());
  p.M.setFromTriplets(m.begin(), m.end());
  p.A.makeCompressed();
  p.M.makeCompressed();
  return p;
}

static double closed_form_eigenvalue(Eigen::Index n, double holonomy, long m)
{
  const double theta = (2. * CGAL_PI * static_cast<double>(m) - holonomy) / static_cast<double>(n);
  return (2. - 2. * std::cos(theta)) / (4. / 6. + 2. / 6. * std::cos(theta));
}

// The smallest eigenpair, with and without the coarse start (N below and above
// the coarse threshold): the closed-form eigenvalue, the Fourier mode.
static void check_smallest_eigenpair(Test_report& report, Eigen::Index n, double holonomy)
{
  const Cycle_pencil p = magnetic_cycle(n, holonomy);
  Solver solver;
  SI::Factored_matrix<Solver> factored(solver);
  SI::Eigen_solve_options options;
  options.same_pattern = false;
  const SI::Eigen_solve_result r = SI::smallest_eigenpair(p.A, p.M, factored, options);
  const double expected = closed_form_eigenvalue(n, holonomy, 0);  // |Phi| < pi: m = 0 is the smallest
  const std::string what = "cycle of " + std::to_string(n) + " nodes, holonomy " + std::to_string(holonomy);
  report.check(r.converged, what + ": converged");
  // lambda_1 ~ (Phi / N)^2 is small against the entries of A (about 2): the
  // Rayleigh quotient carries a rounding error of about 1e-16 * 4 / lambda_1
  report.check(std::abs(r.eigenvalue - expected) <= 1e-7 * expected,
               what + ": lambda_1 = " + std::to_string(r.eigenvalue) + ", closed form " + std::to_string(expected));
  // the mode m = 0: all coefficients equal (up to the residual's accuracy)
  double spread = 0.;
  for(Eigen::Index j = 0; j < n; ++j) spread = (std::max)(spread, std::abs(r.vector[j] - r.vector[0]));
  report.check(spread <= 1e-4 * std::abs(r.vector[0]), what + ": the eigenvector is the constant mode (spread " + std::to_string(spread / std::abs(r.vector[0])) + ")");
  report.check(std::abs(SI::m_norm(p.M, r.vector) - 1.) <= 1e-12, what + ": M-normalized");
}

// The shifted solve with constraints against a dense solve of the same system.
static void check_shifted_solve(Test_report& report)
{
  const Eigen::Index n = 40;
  const Cycle_pencil p = magnetic_cycle(n, 0.7);
  const double lambda = 0.5 * closed_form_eigenvalue(n, 0.7, 0);
  SI::Complex_vector b(n);
  for(Eigen::Index j = 0; j < n; ++j) b[j] = Complex(std::cos(0.3 * j), std::sin(0.11 * j * j));
  SI::Constraints constraints;
  constraints.is_constrained.assign(static_cast<std::size_t>(n), 0);
  constraints.values = SI::Complex_vector::Zero(n);
  constraints.is_constrained[3] = constraints.is_constrained[17] = 1;
  constraints.values[3] = Complex(0.6, 0.8);
  constraints.values[17] = Complex(-1., 0.);
  Solver solver;
  SI::Factored_matrix<Solver> factored(solver);
  const SI::Complex_vector u = SI::solve_shifted_system(p.A, p.M, lambda, b, constraints, factored);

  // dense reference: rows of the constrained nodes replaced by u_c = value
  SI::Complex_dense_matrix K = SI::Complex_dense_matrix(p.A) - lambda * SI::Complex_dense_matrix(p.M);
  SI::Complex_vector rhs = b;
  for(Eigen::Index c : {Eigen::Index(3), Eigen::Index(17)})
  {
    K.row(c).setZero();
    K(c, c) = 1.;
    rhs[c] = constraints.values[c];
  }
  const SI::Complex_vector reference = K.fullPivLu().solve(rhs);
  report.check((u - reference).norm() <= 1e-10 * reference.norm(),
               "constrained shifted solve equals the dense solve");
  report.check(u[3] == constraints.values[3] && u[17] == constraints.values[17],
               "constrained values are kept exactly");
}

// An analysis from the pattern alone (Factored_matrix::analyze_pattern(),
// which runs beside the coarse estimate) is used by the next factorization
// when its matrix has that pattern (the same solution, bit for bit, as with
// an analysis of that matrix), and redone when it has not.
static void check_analysis_from_pattern(Test_report& report)
{
  const Eigen::Index n = 300;
  const Cycle_pencil p = magnetic_cycle(n, 0.4);
  const double shift = 0.05;
  SI::Complex_dense_matrix b(n, 1);
  for(Eigen::Index j = 0; j < n; ++j) b(j, 0) = Complex(std::sin(0.7 * j), std::cos(0.05 * j * j));
  Solver reference_solver;
  SI::Factored_matrix<Solver> reference(reference_solver);
  reference.factor_shifted(p.A, p.M, shift);
  const SI::Complex_dense_matrix expected = reference.solve(b);

  Solver solver;
  SI::Factored_matrix<Solver> ahead(solver);
  ahead.analyze_pattern(p.A);
  ahead.factor_shifted(p.A, p.M, shift, true);
  report.check(ahead.solve(b) == expected, "a factorization on the analysis of its pattern solves bit for bit the same");

  // a pattern that is not the matrix's (the diagonal only): analyzed again
  SI::Complex_sparse_matrix diagonal(n, n);
  diagonal.setIdentity();
  Solver other_solver;
  SI::Factored_matrix<Solver> wrong(other_solver);
  wrong.analyze_pattern(diagonal);
  wrong.factor_shifted(p.A, p.M, shift, true);
  report.check((wrong.solve(b) - expected).norm() <= 1e-12 * expected.norm(),
               "a factorization whose matrix does not have the analyzed pattern analyzes it again");
}

// The compact form of a pencil (compact_pencil.h): the same products and the
// same matrix to factor as the assembled A and M, bit for bit; refused where
// the pattern is not symmetric or misses a diagonal entry.
static void check_compact_pencil(Test_report& report)
{
  const Eigen::Index n = 500;
  const Cycle_pencil p = magnetic_cycle(n, 0.9);
  const SI::Compact_hermitian_pencil compact(p.A, p.M);
  report.check(compact.valid() && compact.rows() == n, "the compact form applies to an assembled pencil");
  const SI::Complex_dense_matrix X = SI::random_block(n, 3, 11);
  SI::Complex_dense_matrix AX, MX, compact_AX, compact_MX;
  SI::hermitian_multiply_pair(p.A, p.M, true, X, AX, MX);
  compact.multiply_pair(X, compact_AX, compact_MX);
  report.check(AX == compact_AX && MX == compact_MX, "compact form: A X and M X bit for bit");
  const SI::Complex_sparse_matrix lower = SI::shifted_lower_triangle(p.A, p.M, -0.25);
  const SI::Complex_sparse_matrix compact_lower = compact.shifted_lower_triangle(-0.25);
  const Eigen::Index entries = lower.nonZeros();
  report.check(entries == compact_lower.nonZeros() &&
                 std::equal(lower.outerIndexPtr(), lower.outerIndexPtr() + n + 1, compact_lower.outerIndexPtr()) &&
                 std::equal(lower.innerIndexPtr(), lower.innerIndexPtr() + entries, compact_lower.innerIndexPtr()) &&
                 std::equal(lower.valuePtr(), lower.valuePtr() + entries, compact_lower.valuePtr()),
               "compact form: the lower triangle of A + shift M bit for bit");
  report.check(compact.diagonal_of_mass() == p.M.diagonal().real() &&
                 compact.diagonal_of_energy() == p.A.diagonal().real(),
               "compact form: the diagonals");

  SI::Complex_sparse_matrix one_sided(3, 3), no_diagonal(2, 2);
  one_sided.insert(0, 0) = 1.;
  one_sided.insert(1, 1) = 1.;
  one_sided.insert(2, 2) = 1.;
  one_sided.insert(2, 0) = 0.5;  // (0, 2) missing
  one_sided.makeCompressed();
  no_diagonal.insert(1, 0) = 1.;
  no_diagonal.insert(0, 1) = 1.;
  no_diagonal.makeCompressed();
  report.check(!SI::Compact_hermitian_pencil(one_sided, one_sided).valid(),
               "compact form refused: a pattern that is not symmetric");
  report.check(!SI::Compact_hermitian_pencil(no_diagonal, no_diagonal).valid(),
               "compact form refused: a missing diagonal entry");
}

// The eigen-solve of a single use frees A and M after the coarse estimate
// and the ordering and goes on with their compact form: the same result,
// bit for bit.
static void check_eigen_solve_freeing_matrices(Test_report& report)
{
  const Eigen::Index n = 12000;  // above the coarse threshold: the analysis runs beside the coarse estimate
  const Cycle_pencil p = magnetic_cycle(n, 1.1);
  SI::Eigen_solve_options options;
  options.same_pattern = false;
  Solver kept_solver, freeing_solver;
  SI::Factored_matrix<Solver> kept(kept_solver), freeing(freeing_solver);
  const SI::Eigen_solve_result expected = SI::smallest_eigenpair(p.A, p.M, kept, options);
  SI::Complex_sparse_matrix A = p.A, M = p.M;
  const SI::Eigen_solve_result r = SI::smallest_eigenpair_freeing_matrices(A, M, freeing, options);
  report.check(r.vector == expected.vector && r.eigenvalue == expected.eigenvalue &&
                 r.iterations == expected.iterations && r.residual == expected.residual,
               "the eigen-solve on the compact form gives the same eigenpair, bit for bit");
  report.check(A.nonZeros() == 0 && M.nonZeros() == 0 && A.rows() == 0,
               "the eigen-solve of a single use frees A and M");
}

int main()
{
  Test_report report("test_linear_algebra");
  check_smallest_eigenpair(report, 200, 0.3);
  check_smallest_eigenpair(report, 200, -2.5);
  check_smallest_eigenpair(report, 12000, 1.1);  // above the coarse threshold: the coarse start is used
  check_shifted_solve(report);
  check_analysis_from_pattern(report);
  check_compact_pencil(report);
  check_eigen_solve_freeing_matrices(report);
  return report.finish();
}
