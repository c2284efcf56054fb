// Part of test_matrices.cpp (one program, one compilation of the package):
// The eigen-solve: shifted factorizations, the fallback, and what CHOLMOD prints.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_TEST_MATRICES_EIGEN_SOLVE_H
#define SURFACE_MESH_DIRECTION_FIELDS_TEST_MATRICES_EIGEN_SOLVE_H

// Counts what CHOLMOD prints while an object of this class lives (all of
// CHOLMOD's printing goes through SuiteSparse_config.printf_func); without
// CHOLMOD there is nothing to count.
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
static int cholmod_messages = 0;
static int count_cholmod_message(const char*, ...)
{
  ++cholmod_messages;
  return 0;
}
struct Cholmod_message_counter
{
  int (*saved)(const char*, ...) = SuiteSparse_config.printf_func;
  Cholmod_message_counter()
  {
    cholmod_messages = 0;
    SuiteSparse_config.printf_func = count_cholmod_message;
  }
  ~Cholmod_message_counter() { SuiteSparse_config.printf_func = saved; }
  int count() const { return cholmod_messages; }
};
#else
struct Cholmod_message_counter
{
  int count() const { return 0; }
};
#endif

// The shifted solve again with a double-precision factor, and with a shift
// just below lambda_1, where a single-precision solve has no correct digit.
template <typename Solver, typename Same_eigenpair>
void check_single_precision_eigen_solve(Test_report& report, const std::string& name, const SI::Complex_sparse_matrix& A,
                                        const SI::Complex_sparse_matrix& M, SI::Eigen_solve_options options,
                                        const SI::Eigen_solve_result& shifted, const Same_eigenpair& same_eigenpair)
{
  options.single_precision = false;
  Solver solver;
  SI::Factored_matrix<Solver> factored(solver);
  const SI::Eigen_solve_result in_double = SI::smallest_eigenpair(A, M, factored, options);
  report.check(!in_double.single_precision && same_eigenpair(in_double) &&
                 in_double.iterations + 1 >= shifted.iterations && shifted.iterations + 1 >= in_double.iterations,
               name + ": a double-precision factor gives the same eigenpair in as many solves (+-1: " +
                 std::to_string(in_double.iterations) + " and " + std::to_string(shifted.iterations) + ", " +
                 (shifted.single_precision ? "single" : "double") + " precision)");
  if(!shifted.single_precision) return;
  options.single_precision = true;
  options.shift_fraction = in_double.eigenvalue * (1. - 1e-9) / shifted.coarse_upper_bound.value();
  Solver close_solver;
  SI::Factored_matrix<Solver> close_factored(close_solver);
  const SI::Eigen_solve_result close = SI::smallest_eigenpair(A, M, close_factored, options);
  std::cout << name << ": shift at (1 - 1e-9) lambda_1: single " << close.single_precision << ", refactored "
            << close.refactored_in_double << ", solves " << close.iterations << "\n";
  report.check(same_eigenpair(close), name + ": a shift at (1 - 1e-9) lambda_1 still gives the eigenpair");

  // a stall declared after every solve that does not gain a factor 10: the
  // factor is replaced by a double-precision one, and the iteration goes on
  options.shift_fraction = shifted.shift / -shifted.coarse_upper_bound.value();
  options.stall_window = 1;
  options.max_reshifts = 0;
  Solver stalled_solver;
  SI::Factored_matrix<Solver> stalled_factored(stalled_solver);
  const SI::Eigen_solve_result stalled = SI::smallest_eigenpair(A, M, stalled_factored, options);
  report.check(stalled.single_precision && stalled.refactored_in_double && !stalled_factored.holds_single_precision() &&
                 stalled.shift == shifted.shift && same_eigenpair(stalled),
               name + ": after a stall, the same shifted matrix is factored in double precision and the eigenpair found");
  // with re-shifts: each stall moves the shift towards the best Ritz value, factored in single precision as the
  // first one, and stays below lambda_1 (else the factorization refuses it and the old shift is factored again,
  // in double precision)
  options.max_reshifts = 4;
  Solver reshifted_solver;
  SI::Factored_matrix<Solver> reshifted_factored(reshifted_solver);
  const SI::Eigen_solve_result reshifted = SI::smallest_eigenpair(A, M, reshifted_factored, options);
  std::cout << name << ": re-shifted " << -shifted.shift << " -> " << -reshifted.shift << ", final factor in "
            << (reshifted_factored.holds_single_precision() ? "single" : "double") << " precision, solves "
            << reshifted.iterations << "\n";
  report.check((reshifted.shift < shifted.shift ||
                (reshifted.refactored_in_double && !reshifted_factored.holds_single_precision())) &&
                 reshifted.shift <= shifted.shift && -reshifted.shift < in_double.eigenvalue &&
                 same_eigenpair(reshifted),
               name + ": after stalls the shift moves towards lambda_1 (" + std::to_string(-shifted.shift) + " -> " +
                 std::to_string(-reshifted.shift) + ", lambda_1 " + std::to_string(in_double.eigenvalue) +
                 ") and the eigenpair is found");
}

// The early move of the shift: the bound early_reshift_target() gives from a Ritz pair near the eigenpair lies
// between the first shift and lambda_1, it is not given while few solves remain or with a gain of 0, and an
// iteration that moves its shift only early (no stall declared) moves it closer, stays below lambda_1 and finds
// the eigenpair.
template <typename Solver, typename Same_eigenpair>
void check_early_reshift(Test_report& report, const std::string& name, const SI::Complex_sparse_matrix& A,
                         const SI::Complex_sparse_matrix& M, SI::Eigen_solve_options options,
                         const SI::Eigen_solve_result& reference, const SI::Eigen_solve_result& shifted,
                         const Same_eigenpair& same_eigenpair)
{
  options.early_reshift_gain = 4.;
  const SI::Hermitian_pencil pencil(A, M);
  const SI::Complex_vector x = reference.vector + 1e-7 * SI::random_start_vector(A.rows(), 7);
  const SI::Complex_vector Ax = A * x, Mx = M * x;
  const double theta = x.dot(Ax).real() / x.dot(Mx).real();
  const SI::Complex_vector r = Ax - theta * Mx;
  const double sigma = -shifted.shift, lambda_1 = reference.eigenvalue;
  const double target =
    SI::early_reshift_target(pencil, r, x, Mx, theta, sigma, {1., 0.5, 0.25}, options).value_or(sigma);
  std::cout << name << ": early target " << target << " for theta " << theta << ", lambda_1 " << lambda_1
            << ", first shift " << sigma << "\n";
  report.check(target > sigma && target <= lambda_1 && lambda_1 < theta,
               name + ": the residual's bound lies between the first shift and lambda_1 (" + std::to_string(target) + ")");
  const std::optional<double> late = SI::early_reshift_target(pencil, r, x, Mx, theta, sigma, {1e-8, 1e-9, 1e-10}, options);
  options.early_reshift_gain = 0.;
  const std::optional<double> off = SI::early_reshift_target(pencil, r, x, Mx, theta, sigma, {1., 0.5, 0.25}, options);
  report.check(!late && !off,
               name + ": no early move where few solves remain, nor with a gain of 0");

  options.early_reshift_gain = 4.;
  options.early_reshift_min_solves = 0.;
  options.stall_window = 1000;
  Solver solver;
  SI::Factored_matrix<Solver> factored(solver);
  const SI::Eigen_solve_result early = SI::smallest_eigenpair(A, M, factored, options);
  std::cout << name << ": early moves " << early.reshifts << ", shift " << sigma << " -> " << -early.shift
            << ", solves " << early.iterations << "\n";
  report.check(early.reshifts >= 1 && -early.shift > sigma && -early.shift < lambda_1 && same_eigenpair(early),
               name + ": moved early, the shift comes closer to lambda_1 and stays below it (" +
                 std::to_string(-early.shift) + "), and the eigenpair is found");
}

// The coarse estimate and the shifted factorization of the eigen-solve, with
// the solver type `Solver`, on a mesh with a simple lambda_1.
template <typename Solver>
static void check_shifted_eigen_solve(Test_report& report, const std::string& solver_name, const Mesh& mesh, int n,
                                      double s)
{
  const std::string name = solver_name + ", n = " + std::to_string(n) + ", s = " + std::to_string(s);
  const SI::Indexed_mesh m = index_mesh(mesh);
  const SI::Tangent_spaces ts = SI::compute_tangent_spaces(m);
  const SI::Connection con = SI::compute_connection(m, ts, n);
  const SI::Components comps = SI::split_into_components(m);
  const SI::Energy_and_mass em = SI::assemble_energy_and_mass(m, ts, con, comps.list[0], comps.local_index, s);
  const SI::Complex_sparse_matrix& A = em.energy;
  const SI::Complex_sparse_matrix& M = em.mass;
  const Eigen::Index nv = A.rows();
  check_shifted_matrices(report, name, A, M);

  // aggregates: a partition with unit phases, at most half as many as vertices
  const SI::Aggregates g = SI::aggregate_vertices(M);
  bool partition = 2 * g.count <= nv && static_cast<Eigen::Index>(g.of_vertex.size()) == nv;
  for(Eigen::Index i = 0; i < nv; ++i)
    partition = partition && g.of_vertex[static_cast<std::size_t>(i)] >= 0 &&
                g.of_vertex[static_cast<std::size_t>(i)] < g.count && std::abs(std::abs(g.phase[i]) - 1.) < 1e-14;
  report.check(partition, name + ": the aggregates partition the vertices, with unit phases (" +
                            std::to_string(g.count) + " for " + std::to_string(nv) + " vertices)");

  // the coarse matrices are the Galerkin projections P^* A P and P^* M P
  std::vector<Eigen::Triplet<SI::Complex> > p_entries;
  for(Eigen::Index i = 0; i < nv; ++i) p_entries.emplace_back(i, g.of_vertex[static_cast<std::size_t>(i)], g.phase[i]);
  SI::Complex_sparse_matrix P(nv, g.count);
  P.setFromTriplets(p_entries.begin(), p_entries.end());
  SI::Complex_sparse_matrix Ac, Mc;
  SI::restrict_to_aggregates(A, M, g, Ac, Mc);
  const SI::Complex_sparse_matrix PAP = SI::Complex_sparse_matrix(P.adjoint()) * A * P;
  const SI::Complex_sparse_matrix PMP = SI::Complex_sparse_matrix(P.adjoint()) * M * P;
  report.check(max_abs(Ac - PAP) <= 1e-13 * max_abs(PAP) && max_abs(Mc - PMP) <= 1e-13 * max_abs(PMP),
               name + ": the coarse matrices are P^* A P and P^* M P");

  // reference: no coarse estimate, A + epsilon M factored
  SI::Eigen_solve_options plain;
  plain.coarse_threshold = nv + 1;
  plain.early_reshift_gain = 0.;  // the shifts below are the first ones (the early moves: check_early_reshift())
  Solver reference_solver;
  SI::Factored_matrix<Solver> reference_factored(reference_solver);
  const SI::Eigen_solve_result reference = SI::smallest_eigenpair(A, M, reference_factored, plain);
  report.check(reference.converged && !reference.coarse_upper_bound && reference.shift > 0.,
               name + ": without the coarse estimate, A + epsilon M is factored");

  auto same_eigenpair = [&](const SI::Eigen_solve_result& r) {
    const double overlap = std::abs(reference.vector.dot(M * r.vector));  // both M-normalized
    return r.converged && std::abs(r.eigenvalue - reference.eigenvalue) <= 1e-8 * reference.eigenvalue &&
           overlap >= 1. - 1e-8;
  };
  SI::Eigen_solve_options options;
  options.shift_fraction = SI::shift_fraction_for(s);
  options.early_reshift_gain = 0.;
  Solver solver;
  SI::Factored_matrix<Solver> factored(solver);
  const SI::Eigen_solve_result shifted = SI::smallest_eigenpair(A, M, factored, options);
  const double bound = shifted.coarse_upper_bound.value_or(0.);
  std::cout << name << ": lambda_1 = " << reference.eigenvalue << ", bound " << bound << " ("
            << bound / reference.eigenvalue << " lambda_1), solves " << reference.iterations
            << " -> " << shifted.iterations << " (+ " << shifted.coarse_iterations << " coarse)\n";
  report.check(shifted.coarse_upper_bound && *shifted.coarse_upper_bound >= reference.eigenvalue * (1. - 1e-12),
               name + ": the coarse estimate bounds lambda_1 from above");
  report.check(!shifted.shift_rejected && shifted.shift == -options.shift_fraction * *shifted.coarse_upper_bound,
               name + ": A - 0.6 (1 - |s|) R M is factored");
  report.check(same_eigenpair(shifted), name + ": the shifted solve gives the eigenpair of the plain one");
  report.check(shifted.iterations < reference.iterations, name + ": and needs fewer solves");
  check_single_precision_eigen_solve<Solver>(report, name, A, M, options, shifted, same_eigenpair);
  if(SI::Factored_matrix<Solver>::detects_indefinite)
    check_early_reshift<Solver>(report, name, A, M, options, reference, shifted, same_eigenpair);

  // a shift above lambda_1: detected, and A + epsilon M factored instead
  options.shift_fraction = 4.;
  Solver fallback_solver;
  SI::Factored_matrix<Solver> fallback_factored(fallback_solver);
  Cholmod_message_counter messages;
  const SI::Eigen_solve_result fallback = SI::smallest_eigenpair(A, M, fallback_factored, options);
  const int printed = messages.count();
  report.check(fallback.shift_rejected && fallback.shift == reference.shift,
               name + ": a shift above lambda_1 is detected and replaced by epsilon");
  report.check(printed == 0, name + ": the rejected trial shift prints nothing (" + std::to_string(printed) + " messages)");
  report.check(same_eigenpair(fallback), name + ": the fallback gives the same eigenpair");
}

#endif // SURFACE_MESH_DIRECTION_FIELDS_TEST_MATRICES_EIGEN_SOLVE_H
