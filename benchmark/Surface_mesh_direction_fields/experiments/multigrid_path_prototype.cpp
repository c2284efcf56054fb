// Issue 50's multigrid path as the library would run it (multigrid_path_prototype.h)
// against the direct path, on one mesh, in one run: the times and iterations of
// both, the eigenvalues, and the cost of one two-level cycle, one product
// with A, one with A and M together and one coarse solve (means of 10).
//   usage: multigrid_path_prototype MESH [--degree N] [--strength THETA] [--no-direct] [--spectrum K]
// --no-direct skips the direct path (for the process's peak memory, /usr/bin/time).
// --spectrum K prints the lowest K eigenvalues of the fine and the coarse
// pencils instead (compare_spectra()).
// Built with -DSMDF_BUILD_EXPERIMENTS=ON.
#include "multigrid_path_prototype.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>

namespace SMDF = CGAL::Surface_mesh_direction_fields;
namespace MP = multigrid_prototype;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef std::chrono::steady_clock Clock;
typedef SMDF::internal::Factored_matrix<SMDF::Cholmod_supernodal_solver> Coarse_factor;

static double ms_since(Clock::time_point t)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

template <typename F>
static double mean_ms(const F& f)
{
  const Clock::time_point t = Clock::now();
  for(int k = 0; k < 10; ++k) f();
  return ms_since(t) / 10.;
}

// The pieces of one LOBPCG iteration, timed apart.
static void time_pieces(const MP::Complex_sparse_matrix& A, const MP::Complex_sparse_matrix& M,
                        const MP::Multigrid_options& options)
{
  SMDF::Cholmod_supernodal_solver solver;
  Coarse_factor coarse(solver);
  const MP::Two_level_cycle<Coarse_factor> cycle(A, M, 1e-8 * MP::eigenvalue_scale(A, M), options, coarse);
  MP::Complex_dense_matrix r = MP::random_start_vector(A.rows(), 1);
  MP::Complex_dense_matrix X = r, AX, MX, R = MP::random_start_vector(cycle.coarse_rows(), 2);
  std::cout << "  per call: two-level cycle " << mean_ms([&] {
    cycle.apply_in_place(r);
    r /= r.norm();
  }) << " ms, A x "
            << mean_ms([&] { MP::hermitian_multiply(A, X, AX); }) << " ms, (A x, M x) "
            << mean_ms([&] { MP::hermitian_multiply_pair(A, M, true, X, AX, MX); }) << " ms, coarse solve ("
            << cycle.coarse_rows() << " rows) " << mean_ms([&] { R = coarse.solve(R); }) << " ms\n";
}

// The lowest `count` eigenvalues of the fine pencil (A, M) and of the
// two-level cycle's Galerkin pencil (P^* A P, P^* M P), side by side: the
// coarse ones are upper bounds of the fine ones, and a coarse level can
// separate (deflate, or shift between) the lowest modes only where its
// errors are below their gaps.
static void compare_spectra(const MP::Complex_sparse_matrix& A, const MP::Complex_sparse_matrix& M,
                            const MP::Multigrid_options& options, int count)
{
  const double epsilon = 1e-8 * MP::eigenvalue_scale(A, M);
  SMDF::Cholmod_supernodal_solver fine_solver, coarse_solver;
  Coarse_factor fine(fine_solver), coarse(coarse_solver);
  const MP::Two_level_cycle<Coarse_factor> cycle(A, M, epsilon, options, coarse);
  const auto pencil = cycle.coarse_pencil(M);
  fine.factor(Coarse_factor::matrix_to_factor(A, M, epsilon));
  double fine_residual = 0., coarse_residual = 0.;
  const Eigen::VectorXd lambda = MP::lowest_eigenvalues(A, M, fine, count, 1e-7, 300, fine_residual);
  const Eigen::VectorXd mu =
    MP::lowest_eigenvalues(pencil.first, pencil.second, coarse, count, 1e-7, 300, coarse_residual);
  std::cout << "  spectra (relative residuals " << fine_residual << " fine, " << coarse_residual
            << " coarse, " << cycle.coarse_rows() << " coarse rows):\n";
  for(int i = 0; i < count; ++i)
    std::cout << "    lambda_" << i + 1 << " " << lambda[i] << "  coarse " << mu[i] << "  coarse error "
              << (mu[i] - lambda[i]) / lambda[i] << "  gap to the next "
              << (i + 1 < count ? (lambda[i + 1] - lambda[i]) / lambda[i] : 0.) << "\n";
}

int main(int argc, char** argv)
{
  int degree = 4, spectrum = 0;
  bool direct = true;
  MP::Multigrid_options options;
  for(int i = 2; i < argc; ++i)
  {
    if(!std::strcmp(argv[i], "--degree") && i + 1 < argc) degree = std::atoi(argv[++i]);
    else if(!std::strcmp(argv[i], "--strength") && i + 1 < argc) options.strength = std::atof(argv[++i]);
    else if(!std::strcmp(argv[i], "--no-direct")) direct = false;
    else if(!std::strcmp(argv[i], "--spectrum") && i + 1 < argc) spectrum = std::atoi(argv[++i]);
    else argc = 0;
  }
  Mesh mesh;
  if(argc < 2 || !CGAL::IO::read_polygon_mesh(argv[1], mesh) || mesh.is_empty())
  {
    std::cerr << "usage: multigrid_path_prototype MESH [--degree N] [--strength THETA] [--no-direct] [--spectrum K]\n";
    return 1;
  }
  SMDF::Globally_optimal_direction_field<Mesh> field(mesh);
  std::cout << argv[1] << ": " << num_vertices(mesh) << " vertices\n";
  if(direct)
  {
    auto dir = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:d").first;
    const Clock::time_point t = Clock::now();
    const SMDF::Direction_field_result result = field.compute(dir, CGAL::parameters::degree(degree));
    std::cout << "  direct: " << ms_since(t) << " ms, " << result.iterations << " solves, eigenvalue "
              << *result.components[0].eigenvalue << "\n";
  }
  const auto matrices = field.energy_and_mass_matrices(degree, 0.);
  if(spectrum > 0)
  {
    compare_spectra(matrices.first, matrices.second, options, spectrum);
    return 0;
  }
  SMDF::Cholmod_supernodal_solver solver;
  Coarse_factor coarse(solver);
  const Clock::time_point t = Clock::now();
  const MP::Eigen_solve_result e =
    MP::multigrid_smallest_eigenpair(matrices.first, matrices.second, coarse, MP::Eigen_solve_options(), options);
  std::cout << "  multigrid: " << ms_since(t) << " ms (hierarchy, coarse factor and start " << e.factorization_ms
            << " ms), " << e.iterations << " iterations, residual " << e.residual << ", eigenvalue " << e.eigenvalue
            << (e.converged ? "" : " (not converged)") << "\n";
  if(direct) time_pieces(matrices.first, matrices.second, options);
  return 0;
}
