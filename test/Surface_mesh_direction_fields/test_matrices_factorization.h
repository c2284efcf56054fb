// Part of test_matrices.cpp (one program, one compilation of the package):
// The factorizations and solves: the parallel supernodal solve and factorization, single precision, BLAS threads, huge pages, and the components.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_TEST_MATRICES_FACTORIZATION_H
#define SURFACE_MESH_DIRECTION_FIELDS_TEST_MATRICES_FACTORIZATION_H

#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
// A Hermitian positive definite matrix with the pattern of a g x g grid: a
// connection Laplacian (unit phases on the edges) plus 0.1 I.
static SI::Complex_sparse_matrix grid_matrix(int g)
{
  std::vector<Eigen::Triplet<Complex> > entries;
  auto id = [g](int i, int j) { return i * g + j; };
  for(int i = 0; i < g; ++i)
    for(int j = 0; j < g; ++j)
    {
      double degree = 0.;
      for(const auto& [di, dj] : {std::pair<int, int>(1, 0), std::pair<int, int>(0, 1), std::pair<int, int>(-1, 0), std::pair<int, int>(0, -1)})
      {
        const int ni = i + di, nj = j + dj;
        if(ni < 0 || nj < 0 || ni >= g || nj >= g) continue;
        degree += 1.;
        const int a = (std::min)(id(i, j), id(ni, nj)), b = (std::max)(id(i, j), id(ni, nj));
        const Complex phase = std::polar(1., 0.37 * a + 1.1 * b);
        entries.emplace_back(id(i, j), id(ni, nj), id(i, j) < id(ni, nj) ? -std::conj(phase) : -phase);
      }
      entries.emplace_back(id(i, j), id(i, j), Complex(degree + 0.1, 0.));
    }
  SI::Complex_sparse_matrix S(g * g, g * g);
  S.setFromTriplets(entries.begin(), entries.end());
  return S;
}

// The package's parallel solve with CHOLMOD's supernodal factor: the same
// solution as CHOLMOD's own solve, the same bits for any number of threads,
// and a plan that cuts the tree into whole subtrees and a top.
static void check_parallel_supernodal_solve(Test_report& report, int g)
{
  typedef Eigen::CholmodSupernodalLLT<SI::Complex_sparse_matrix> Llt;  // the reference: CHOLMOD through Eigen
  typedef SMDF::Cholmod_supernodal_solver Cholmod;
  const std::string name = "parallel supernodal solve, grid " + std::to_string(g) + " x " + std::to_string(g);
  const SI::Complex_sparse_matrix S = grid_matrix(g);
  Cholmod solver;
  SI::Factored_matrix<Cholmod> factored(solver);
  factored.factor(S);
  const cholmod_factor* L = solver.factorization().factor();
  report.check(L != nullptr && L->is_super && L->is_ll, name + ": CHOLMOD's factor is supernodal LL^*");
  if(L == nullptr || !L->is_super) return;

  const SI::Supernodal_factor_view<int> view = SI::supernodal_view(*L, static_cast<const Complex*>(L->x));
  const SI::Supernodal_solve_plan plan(view);
  // what the solve's kernels divide by: the diagonal of an LL^* factor, real and positive
  bool real_diagonal = true;
  for(std::size_t s = 0; s < view.supernodes; ++s)
  {
    const int columns = view.super[s + 1] - view.super[s], rows = view.row_start[s + 1] - view.row_start[s];
    for(int j = 0; j < columns; ++j)
    {
      const Complex d = view.values[view.value_start[s] + j * rows + j];
      real_diagonal = real_diagonal && d.imag() == 0. && d.real() > 0.;
    }
  }
  report.check(real_diagonal, name + ": the diagonal of CHOLMOD's factor is real and positive");
  // every supernode in the top or in exactly one task; a supernode's parent
  // is in its task or in the top; the top's parents are in the top
  const std::size_t ns = view.supernodes;
  std::vector<int> owner(ns, -2);  // -1: top, t: task t
  bool partition = plan.valid();
  for(std::size_t s : plan.top()) owner[s] = -1;
  for(std::size_t t = 0; t < plan.tasks().size(); ++t)
    for(std::size_t s = plan.tasks()[t].first; s <= plan.tasks()[t].last; ++s)
    {
      partition = partition && owner[s] == -2;
      owner[s] = static_cast<int>(t);
    }
  std::vector<std::size_t> supernode_of_column(view.n);
  for(std::size_t s = 0; s < ns; ++s)
    for(int j = view.super[s]; j < view.super[s + 1]; ++j) supernode_of_column[static_cast<std::size_t>(j)] = s;
  bool subtrees = true, large_top = false;
  long largest_top = 0;
  for(std::size_t s = 0; s < ns; ++s)
  {
    partition = partition && owner[s] != -2;
    const int columns = view.super[s + 1] - view.super[s], rows = view.row_start[s + 1] - view.row_start[s];
    if(owner[s] == -1)
    {
      large_top = large_top || SI::is_large_supernode(rows, columns);
      largest_top = (std::max)(largest_top, long(rows) * long(columns));
    }
    if(rows == columns) continue;
    const std::size_t parent = supernode_of_column[static_cast<std::size_t>(view.rows[view.row_start[s] + columns])];
    subtrees = subtrees && (owner[parent] == -1 || owner[parent] == owner[s]);
  }
  report.check(partition && subtrees, name + ": " + std::to_string(plan.tasks().size()) + " subtrees and a top of " +
                                        std::to_string(plan.top().size()) + " supernodes partition the tree");
  if(g >= 100)
    report.check(plan.tasks().size() > 1 && large_top, name + ": several tasks (" + std::to_string(plan.tasks().size()) +
                                                         "), and a top supernode solved in parallel (largest: " +
                                                         std::to_string(largest_top) + " entries)");

  const bool large = L->xsize >= SI::parallel_solve_minimum_entries;
  report.check(factored.solves_in_parallel() == large,
               name + ": the parallel solve is used exactly for factors of a million entries or more (" +
                 std::to_string(L->xsize) + ")");
  if(g >= 100) report.check(large, name + ": the factor is large enough for the parallel solve");

  SI::Complex_dense_matrix B = SI::Complex_dense_matrix::Random(S.rows(), 2);
  auto parallel_solve = [&] { return SI::Complex_dense_matrix(SI::supernodal_solve(view, plan, SI::Complex_vector(B.col(0)))); };
  const SI::Complex_dense_matrix X = parallel_solve();
  if(large)
    report.check(factored.solve(B.leftCols(1)) == X, name + ": the factored matrix solves with the same plan");
  // CHOLMOD alone (its own analysis, factorization and solve)
  Llt reference;
  reference.compute(S);
  const SI::Complex_dense_matrix X_cholmod = reference.solve(B.leftCols(1));
  const SI::Complex_sparse_matrix S_full = S;  // both triangles were given
  report.check((X - X_cholmod).norm() <= 1e-13 * X_cholmod.norm() &&
                 (S_full * X - B.leftCols(1)).norm() <= 1e-13 * B.leftCols(1).norm(),
               name + ": the solution of CHOLMOD's solve, residual below 1e-13");
  const SI::Complex_dense_matrix X2 = factored.solve(B);  // two columns: CHOLMOD's solve on the factor
  const SI::Complex_dense_matrix X2_cholmod = reference.solve(B);
  report.check(factored.factored_in_parallel() ? (X2 - X2_cholmod).norm() <= 1e-13 * X2_cholmod.norm() : X2 == X2_cholmod,
               name + ": two right-hand sides go to CHOLMOD's solve");
#ifdef CGAL_LINKED_WITH_TBB
  SI::Complex_dense_matrix X_one_thread;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    X_one_thread = parallel_solve();
  }
  report.check(X_one_thread == X, name + ": the same bits on one thread as on all");
#endif
  {
    // a second factorization of the same pattern (the analysis and the plan are
    // kept): the solve uses the new values
    SI::Complex_sparse_matrix S2 = S;
    S2.diagonal().array() += Complex(0.5, 0.);
    factored.factor(S2, true);
    const SI::Complex_dense_matrix X_again = factored.solve(B.leftCols(1));
    reference.compute(S2);
    report.check((S2 * X_again - B.leftCols(1)).norm() <= 1e-13 * B.leftCols(1).norm() &&
                   (X_again - reference.solve(B.leftCols(1))).norm() <= 1e-13 * X_again.norm(),
                 name + ": after a refactorization of the same pattern, the solution of the new matrix");
  }
}

// Scotch's separators depend on the number of threads that find them, and by
// default it starts one per core, or as many as SCOTCH_PTHREAD_NUMBER says:
// the package fixes the number, so the environment (here standing in for a
// machine with another number of cores) changes nothing.
static void check_scotch_threads_fixed(Test_report& report, const SI::Complex_sparse_matrix& lower,
                                       const cholmod_factor& L, const std::string& name)
{
  const char* variable = "SCOTCH_PTHREAD_NUMBER";
  const char* before = std::getenv(variable);
  const std::string saved = before ? before : "";
  bool same = true;
  for(const char* threads : {"1", "3"})
  {
    setenv(variable, threads, 1);
    SI::Cholmod_supernodal_factorization other;
    other.analyze_pattern(lower);
    const cholmod_factor* L_other = other.factor();
    same = same && L_other != nullptr && L_other->n == L.n &&
           std::equal(static_cast<const int*>(L.Perm), static_cast<const int*>(L.Perm) + L.n,
                      static_cast<const int*>(L_other->Perm));
  }
  if(before) setenv(variable, saved.c_str(), 1);
  else unsetenv(variable);
  report.check(same, name + ": the same ordering whatever number of threads Scotch would start by itself");
}

// From `nested_dissection_size` rows the analysis orders by nested dissection
// directly: Scotch's with CAMD where the package has Scotch, METIS's
// otherwise (and when asked). Either gives the same ordering on every
// analysis, also on two threads at once (METIS draws from the C library's one
// random generator, hence its lock; Scotch from a context of its own), and a
// solve to the factorization's accuracy. Returns the factor's entries.
static std::size_t check_nested_dissection_ordering(Test_report& report, bool scotch)
{
  int g = 1;
  while(Eigen::Index(g) * g < SI::nested_dissection_size) ++g;
  const std::string name = std::string(scotch ? "Scotch and CAMD" : "METIS") + ", grid " + std::to_string(g) +
                           " x " + std::to_string(g);
  const SI::Complex_sparse_matrix S = grid_matrix(g);
  const SI::Complex_sparse_matrix lower = S.triangularView<Eigen::Lower>();
  SI::Cholmod_supernodal_factorization first, second, left, right;
  for(SI::Cholmod_supernodal_factorization* f : {&first, &second, &left, &right}) f->use_scotch_ordering(scotch);
  first.analyze_pattern(lower);
  second.analyze_pattern(lower);
  const cholmod_factor* L = first.factor();
  const cholmod_factor* L_again = second.factor();
  report.check(L != nullptr && L->ordering == (scotch ? CHOLMOD_GIVEN : CHOLMOD_METIS),
               name + ": ordered by " + (scotch ? "the package (Scotch, CAMD)" : "METIS"));
  if(L == nullptr || L_again == nullptr) return 0;
  const int* perm = static_cast<const int*>(L->Perm);
  std::vector<bool> seen(L->n, false);
  for(std::size_t k = 0; k < L->n; ++k) seen[static_cast<std::size_t>(perm[k])] = true;
  report.check(std::find(seen.begin(), seen.end(), false) == seen.end(), name + ": a permutation of the rows");
  report.check(L_again->xsize == L->xsize && std::equal(perm, perm + L->n, static_cast<const int*>(L_again->Perm)),
               name + ": the same ordering on a second analysis");
  // two analyses at once: without the lock METIS's draws interleave and
  // both orderings differ from the one of an analysis alone
  std::thread beside([&] { left.analyze_pattern(lower); });
  right.analyze_pattern(lower);
  beside.join();
  bool same = true;
  for(const SI::Cholmod_supernodal_factorization* f : {&left, &right})
    same = same && f->factor() != nullptr && f->factor()->n == L->n &&
           std::equal(perm, perm + L->n, static_cast<const int*>(f->factor()->Perm));
  report.check(same, name + ": two analyses on two threads at once give the ordering of one alone");
  if(scotch) check_scotch_threads_fixed(report, lower, *L, name);
  const bool factored = first.factor(lower, true, false);
  const SI::Complex_dense_matrix B = SI::Complex_dense_matrix::Random(S.rows(), 1);
  const SI::Complex_sparse_matrix S_full = S;
  report.check(factored && (S_full * first.solve(B) - B).norm() <= 1e-12 * B.norm(),
               name + ": factored and solved (residual below 1e-12)");
  return first.factor()->xsize;
}

// Both nested dissections; Scotch's with CAMD no more than 20% larger a
// factor than METIS's (16% on this grid, where METIS's separators are
// straight lines; 2 to 8% on the surface meshes of the benchmark).
static void check_nested_dissection_orderings(Test_report& report)
{
  const std::size_t metis_entries = check_nested_dissection_ordering(report, false);
  if(!SI::scotch_ordering_available) return;
  const std::size_t scotch_entries = check_nested_dissection_ordering(report, true);
  std::cout << "  factor entries on the grid: METIS " << metis_entries << ", Scotch and CAMD " << scotch_entries
            << std::endl;
  report.check(scotch_entries > 0 && double(scotch_entries) <= 1.2 * double(metis_entries),
               "Scotch and CAMD: a factor at most 20% larger than METIS's on the grid");
}

// The default solver seen through CGAL's SparseLinearAlgebraWithFactorTraits_d:
// factor, solve, copies sharing the factorization, an indefinite matrix refused.
static void check_cholmod_solver_concept(Test_report& report)
{
  typedef SMDF::Cholmod_supernodal_solver Solver;
  const SI::Complex_sparse_matrix S = grid_matrix(30);
  Solver solver;
  const Solver::Matrix A(S);
  Solver::Vector B(static_cast<std::size_t>(S.rows())), X, X_copy, X_once;
  for(Eigen::Index i = 0; i < S.rows(); ++i) B.set(static_cast<std::size_t>(i), Complex(double(i % 7), 1.));
  Complex D(0.);
  const bool solved = solver.factor(A, D) && solver.linear_solver(B, X);
  const Solver copy = solver;
  const bool copy_solved = Solver(copy).linear_solver(B, X_copy);
  Complex D_once(0.);
  const bool solved_once = Solver().linear_solver(A, B, X_once, D_once);
  report.check(solved && D == Complex(1.) && (S * X.eigen_object() - B.eigen_object()).norm() <= 1e-12 * B.norm() &&
                 copy_solved && X_copy.eigen_object() == X.eigen_object() && solved_once && X_once.eigen_object() == X.eigen_object(),
               "Cholmod_supernodal_solver as SparseLinearAlgebraWithFactorTraits_d: solves (residual below 1e-12), copies share the factor");
  SI::Complex_sparse_matrix indefinite = S;
  indefinite.diagonal().array() -= Complex(5., 0.);
  report.check(!Solver().factor(Solver::Matrix(indefinite), D), "Cholmod_supernodal_solver: factor() refuses an indefinite matrix");
}

// The one process-wide setting the factorization may make (dense_kernels.h):
// OpenBLAS on one thread while the subtrees are factored. Off by default: a
// thread watching OpenBLAS's number of threads during factorizations never
// sees it change. Switched on (openblas_thread_control.h): outside the
// factorization the user's number of threads is in force again, also after
// factorizations running concurrently on two threads of the program.
static void check_blas_threads_restored(Test_report& report)
{
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_OPENBLAS_THREADS
  typedef SMDF::Cholmod_supernodal_solver Cholmod;
  const SI::Complex_sparse_matrix S = grid_matrix(120);
  const int original = openblas_get_num_threads();
  openblas_set_num_threads(3);
  auto factor_once = [&S] {
    Cholmod solver;
    SI::Factored_matrix<Cholmod> factored(solver);
    factored.factor(S);
    return factored.factored_in_parallel();
  };
  report.check(!SMDF::openblas_thread_control(), "OpenBLAS's thread control is off until a program opts in");
  {
    std::atomic<bool> done(false), changed(false);
    std::thread watcher([&] {
      while(!done.load())
        if(openblas_get_num_threads() != 3) changed.store(true);
    });
    bool factored = true;
    for(int i = 0; i < 5; ++i) factored = factor_once() && factored;
    done.store(true);
    watcher.join();
    report.check(factored && !changed.load(),
                 "left off, five factorizations never change OpenBLAS's number of threads (3)");
  }
  SMDF::set_openblas_thread_control(true);
  const bool by_package = factor_once();
  const int after_one = openblas_get_num_threads();
  bool both = true;
  {
    bool first = false, second = false;
    std::thread other([&] { first = factor_once(); });
    second = factor_once();
    other.join();
    both = first && second;
  }
  const int after_two = openblas_get_num_threads();
  SMDF::set_openblas_thread_control(false);
  openblas_set_num_threads(original);
  report.check(by_package && both && after_one == 3 && after_two == 3,
               "switched on, OpenBLAS's number of threads (3) is given back after one factorization (" +
                 std::to_string(after_one) + ") and after two concurrent ones (" + std::to_string(after_two) + ")");
#else
  (void)report;
#endif
}

// The package's numerical factorization on CHOLMOD's analysis
// (supernodal_factorization.h): used exactly for large factors, equal to the
// factor CHOLMOD computes on its own (CHOLMOD's ordering is deterministic, so
// both have the same layout) up to rounding, the same bits on one thread as
// on all, and a matrix that is not positive definite refused.
static void check_parallel_factorization(Test_report& report, int g)
{
  typedef SMDF::Cholmod_supernodal_solver Cholmod;
  const std::string name = "parallel supernodal factorization, grid " + std::to_string(g) + " x " + std::to_string(g);
#ifdef __linux__
  report.check(SI::has_dense_kernels, name + ": the BLAS and LAPACK kernels are linked");
#endif
  const SI::Complex_sparse_matrix S = grid_matrix(g);
  Cholmod solver;
  SI::Factored_matrix<Cholmod> factored(solver);
  factored.factor(S);
  const cholmod_factor* L = solver.factorization().factor();
  const bool large = L->xsize >= SI::parallel_factorization_minimum_entries;
  report.check(factored.factored_in_parallel() == (large && SI::has_dense_kernels),
               name + ": the package factors exactly the factors of 16,384 entries or more (" +
                 std::to_string(L->xsize) + ")");
  if(!factored.factored_in_parallel()) return;
  report.check(factored.solves_in_parallel() == (L->xsize >= SI::parallel_solve_minimum_entries),
               name + ": one right-hand side is solved in parallel exactly from a million entries on");

  Cholmod reference;  // CHOLMOD's own numerical factorization on the same analysis
  reference.factorization().use_package_factorization(false);
  SI::Factored_matrix<Cholmod>(reference).factor(S);
  const cholmod_factor* R = reference.factorization().factor();
  const Complex* Lx = static_cast<const Complex*>(L->x);
  const Complex* Rx = static_cast<const Complex*>(R->x);
  const bool same_layout = R->xsize == L->xsize && R->nsuper == L->nsuper &&
                           std::equal(static_cast<const int*>(L->Perm), static_cast<const int*>(L->Perm) + L->n,
                                      static_cast<const int*>(R->Perm));
  double difference = 0., largest = 0.;
  for(std::size_t k = 0; same_layout && k < L->xsize; ++k)
  {
    difference = (std::max)(difference, std::abs(Lx[k] - Rx[k]));
    largest = (std::max)(largest, std::abs(Rx[k]));
  }
  report.check(same_layout && difference <= 1e-12 * largest,
               name + ": CHOLMOD's factor, to 1e-12 relative");
#ifdef CGAL_LINKED_WITH_TBB
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    Cholmod solver_one;
    SI::Factored_matrix<Cholmod> factored_one(solver_one);
    factored_one.factor(S);
    const cholmod_factor* L1 = solver_one.factorization().factor();
    report.check(factored_one.factored_in_parallel() && L1->xsize == L->xsize &&
                   std::equal(Lx, Lx + L->xsize, static_cast<const Complex*>(L1->x)),
                 name + ": the same bits on one thread as on all");
  }
#endif
  // the grid's connection Laplacian has eigenvalues in [0, 8]: S - 5 I is indefinite
  SI::Complex_sparse_matrix indefinite = S;
  indefinite.diagonal().array() -= Complex(5., 0.);
  bool threw = false;
  try
  {
    factored.factor(indefinite, true);
  }
  catch(const CGAL::Surface_mesh_direction_fields::Solver_failure_error&)
  {
    threw = true;
  }
  report.check(threw && !factored.factor_if_positive_definite(indefinite, true),
               name + ": a matrix that is not positive definite is refused (factor() throws, the trial says so)");
  factored.factor(S);
  const SI::Complex_dense_matrix B = SI::Complex_dense_matrix::Random(S.rows(), 3);
  const SI::Complex_dense_matrix X = factored.solve(B), x = factored.solve(B.leftCols(1));
  const SI::Complex_sparse_matrix S_full = S;
  report.check(factored.factored_in_parallel() && (S_full * X - B).norm() <= 1e-13 * B.norm() &&
                 (S_full * x - B.leftCols(1)).norm() <= 1e-13 * B.leftCols(1).norm(),
               name + ": factored again after the refusal, blocks and single right-hand sides solved (residual below 1e-13)");
}

// The factorization in single precision (allow_single_precision(true)), on
// a grid large enough for the package's own factorization.
static void check_single_precision_factorization(Test_report& report, int g)
{
  typedef SMDF::Cholmod_supernodal_solver Cholmod;
  const std::string name = "single-precision factorization, grid " + std::to_string(g) + " x " + std::to_string(g);
  if(!SI::has_dense_kernels) return;
  const SI::Complex_sparse_matrix S = grid_matrix(g), S_full = S;
  auto factor_single = [&S](SI::Factored_matrix<Cholmod>& f) {
    f.allow_single_precision(true);
    f.factor(S);
  };
  Cholmod solver;
  SI::Factored_matrix<Cholmod> factored(solver);
  factor_single(factored);
  report.check(factored.holds_single_precision() && factored.solves_in_parallel(),
               name + ": allowed, the factor is in single precision, solved by the package");
  const SI::Complex_dense_matrix B = SI::Complex_dense_matrix::Random(S.rows(), 3);
  const SI::Complex_dense_matrix x = factored.solve(B.leftCols(1)), X = factored.solve(B);
  const double residual = (S_full * x - B.leftCols(1)).norm() / B.leftCols(1).norm();
  report.check(residual <= 1e-5 && residual >= 1e-10,
               name + ": a solve has single precision's accuracy (relative residual " + std::to_string(residual) + ")");
  report.check(X.col(0) == x, name + ": a block is solved column by column");
  const double tiny = std::ldexp(1., -1000);
  const SI::Complex_dense_matrix x_tiny = factored.solve(SI::Complex_dense_matrix(B.leftCols(1) * tiny));
  report.check(x_tiny == SI::Complex_dense_matrix(x * tiny),
               name + ": a right-hand side far below float's range is scaled exactly (2^-1000 b)");
#ifdef CGAL_LINKED_WITH_TBB
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    Cholmod solver_one;
    SI::Factored_matrix<Cholmod> factored_one(solver_one);
    factor_single(factored_one);
    report.check(factored_one.solve(B.leftCols(1)) == x, name + ": the same bits on one thread as on all");
  }
#endif
  // the solve of aligned fields: conjugate gradients preconditioned by the
  // single-precision factor, with products by the lower triangle alone
  const SI::Complex_sparse_matrix lower = S.triangularView<Eigen::Lower>();
  const SI::Complex_vector b = B.col(0), Sb = S_full * b;
  report.check((SI::lower_hermitian_times(lower, b) - Sb).norm() <= 1e-14 * Sb.norm(),
               name + ": products with the lower triangle equal those with the whole matrix");
  SI::Complex_vector x_refined;
  const bool refined = SI::refined_solve(factored, lower, b, x_refined, 4);
  const double refined_residual = (S_full * x_refined - b).norm() / b.norm();
  report.check(refined && refined_residual <= 1e-13,
               name + ": refined to a double-precision residual in at most 4 steps (" +
                 std::to_string(refined_residual) + ")");
  SI::Complex_vector x_unrefined;
  report.check(!SI::refined_solve(factored, lower, b, x_unrefined, 0),
               name + ": no step allowed, the refinement reports that it did not converge");
  SI::Complex_sparse_matrix indefinite = S;
  indefinite.diagonal().array() -= Complex(5., 0.);
  report.check(!factored.factor_if_positive_definite(indefinite, true) && !factored.holds_single_precision(),
               name + ": a matrix that is not positive definite is refused");
  factored.allow_single_precision(false);
  factored.factor(S);
  report.check(!factored.holds_single_precision() && (S_full * factored.solve(B) - B).norm() <= 1e-13 * B.norm(),
               name + ": not allowed, the factor is in double precision again (residual below 1e-13)");
}
#endif


// Subnormal numbers flushed to zero in single precision (subnormals.h): the
// guard's mode on the calling thread and its restoration, and a
// single-precision factor without subnormal entries where the fill decays
// below float's range (a grid's matrix with a large diagonal: without the
// flush, thousands of its entries are subnormal).
static void check_subnormals_flushed(Test_report& report)
{
  typedef SI::Subnormals_flushed_in_scope<std::complex<float> > Flushed_single;
  typedef SI::Subnormals_flushed_in_scope<std::complex<double> > Flushed_double;
  const std::string name = "subnormal numbers in single precision";
  volatile float tiny_float = 1e-20f;  // volatile: computed at run time, in the thread's mode
  volatile double tiny_double = 1e-160;
  const float subnormal = tiny_float * tiny_float;
  bool flushed_inside = false, double_kept = false;
  {
    const Flushed_double unchanged;
    double_kept = tiny_double * tiny_double != 0.;
    const Flushed_single flushed;
    flushed_inside = tiny_float * tiny_float == 0.f;
  }
  const float after = tiny_float * tiny_float;
  report.check(subnormal != 0.f && after == subnormal && double_kept,
               name + ": the thread's mode is restored after the guard, and a double-precision guard changes nothing");
  report.check(flushed_inside == Flushed_single::flushes(),
               name + ": inside the single-precision guard, a product below float's range is zero (where the "
                      "processor has the SSE control register)");
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
  if(!SI::has_dense_kernels || !Flushed_single::flushes()) return;
  typedef SMDF::Cholmod_supernodal_solver Cholmod;
  SI::Complex_sparse_matrix S = grid_matrix(120);
  S.diagonal().array() += Complex(6., 0.);
  const SI::Complex_sparse_matrix lower = S.triangularView<Eigen::Lower>();
  Cholmod solver;
  SI::Factored_matrix<Cholmod>(solver).factor(lower);
  const cholmod_factor* L = solver.factorization().factor();
  std::vector<std::complex<float> > values(L->xsize);
  const SI::Supernodal_factor_view<int, std::complex<float> > view = SI::supernodal_view(*L, values.data());
  const SI::Supernodal_solve_plan plan(view);
  const SI::Supernodal_updates<int> updates(view);
  const Eigen::SparseMatrix<std::complex<float> > permuted =
    SI::with_values_in_precision<std::complex<float> >(SI::permuted_lower_triangle(lower, view.permutation));
  // as the program and the module run it: the package controls OpenBLAS's threads, here two (OpenBLAS's own
  // threads do not flush: the top of the factor must run on the calling thread)
  SMDF::set_openblas_thread_control(true);
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_OPENBLAS_THREADS
  const int blas_threads = openblas_get_num_threads();
  openblas_set_num_threads(2);
#endif
  const std::ptrdiff_t failed = SI::supernodal_factorize(view, values.data(), permuted, updates, plan);
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_OPENBLAS_THREADS
  openblas_set_num_threads(blas_threads);
#endif
  SMDF::set_openblas_thread_control(false);
  std::size_t subnormals = 0, zeros = 0;
  for(const std::complex<float>& x : values)
  {
    for(const float part : {x.real(), x.imag()})
      if(part != 0.f && std::abs(part) < std::numeric_limits<float>::min()) ++subnormals;
    if(x == std::complex<float>(0.f, 0.f)) ++zeros;
  }
  report.check(failed < 0 && subnormals == 0 && zeros > 0,
               name + ": a factor whose fill decays below float's range holds no subnormal entry (" +
                 std::to_string(subnormals) + " subnormal, " + std::to_string(zeros) + " zero of " +
                 std::to_string(values.size()) + ")");
#endif
}

// The VmFlags of the mapping of /proc/self/smaps that holds address a ("" if
// not found or /proc is not there).
static std::string vm_flags_of(const void* a)
{
  std::ifstream smaps("/proc/self/smaps");
  const auto address = reinterpret_cast<std::uintptr_t>(a);
  std::string line;
  bool inside = false;
  while(std::getline(smaps, line))
  {
    unsigned long long begin = 0, end = 0;
    char dash = 0;
    std::istringstream header(line);
    if(header >> std::hex >> begin >> dash >> end && dash == '-')
      inside = begin <= address && address < end;
    else if(inside && line.compare(0, 8, "VmFlags:") == 0)
      return line + " ";
  }
  return "";
}

// advise_huge_pages(): the advice reaches the kernel for the whole pages of
// the range (the mapping is marked "hg"), a buffer written after it reads back
// unchanged, and sizes below the minimum, null or unaligned pointers are fine.
static void check_huge_page_advice(Test_report& report)
{
  const std::size_t bytes = std::size_t(16) << 20;
  std::unique_ptr<unsigned char[]> buffer(new unsigned char[bytes]);  // not written yet
  SI::advise_huge_pages(buffer.get() + 1, bytes - 1);
  SI::advise_huge_pages(nullptr, bytes);
  SI::advise_huge_pages(buffer.get(), SI::huge_page_advice_minimum_bytes - 1);
  for(std::size_t i = 0; i < bytes; ++i) buffer[i] = static_cast<unsigned char>(i * 7);
  bool same = true;
  for(std::size_t i = 0; i < bytes; ++i) same = same && buffer[i] == static_cast<unsigned char>(i * 7);
  report.check(same, "huge page advice: the buffer reads back what was written");
#if defined(__linux__) && defined(MADV_HUGEPAGE) && !defined(CGAL_SURFACE_MESH_DIRECTION_FIELDS_NO_HUGE_PAGES)
  const std::string flags = vm_flags_of(buffer.get() + bytes / 2);
  if(flags.empty())
    std::cout << "SKIP huge page advice: /proc/self/smaps not readable\n";
  else
    report.check(flags.find(" hg ") != std::string::npos, "huge page advice: the kernel marked the range (" + flags + ")");
#endif
}

// The components: an isolated vertex, then a sphere, then a torus: two components,
// numbered in the order of their smallest vertex, each listing its vertices
// once (the smallest first, local_index its inverse) and exactly its faces,
// increasing; the isolated vertex belongs to none.
static void check_components(Test_report& report)
{
  Mesh sphere, torus, mesh;
  make_icosphere(sphere, 1);
  make_torus(torus, 2., 0.5, 8, 6);
  const Mesh::Vertex_index isolated = mesh.add_vertex(Kernel::Point_3(9., 9., 9.));
  CGAL::copy_face_graph(sphere, mesh);
  CGAL::copy_face_graph(torus, mesh);
  const SI::Indexed_mesh m = index_mesh(mesh);
  const SI::Components comps = SI::split_into_components(m);
  report.check(comps.list.size() == 2, "components: a sphere and a torus");
  report.check(comps.local_index[isolated] == SI::no_index, "components: an isolated vertex belongs to none");
  if(comps.list.size() != 2) return;
  const std::size_t first_torus_vertex = 1 + sphere.number_of_vertices();
  const std::size_t first_torus_face = sphere.number_of_faces();
  bool vertices_ok = true, faces_ok = true;
  std::vector<int> seen(m.number_of_vertices(), 0);
  for(std::size_t c = 0; c < 2; ++c)
  {
    const SI::Component& comp = comps.list[c];
    const std::size_t expected_size = c == 0 ? sphere.number_of_vertices() : torus.number_of_vertices();
    vertices_ok = vertices_ok && comp.vertices.size() == expected_size &&
                  static_cast<std::size_t>(comp.vertices[0]) == (c == 0 ? 1 : first_torus_vertex);
    for(std::size_t i = 0; i < comp.vertices.size(); ++i)
    {
      const std::size_t v = comp.vertices[i];
      vertices_ok = vertices_ok && comps.local_index[v] == i && ++seen[v] == 1 && ((v >= first_torus_vertex) == (c == 1));
    }
    const std::size_t expected_faces = c == 0 ? sphere.number_of_faces() : torus.number_of_faces();
    faces_ok = faces_ok && comp.faces.size() == expected_faces;
    for(std::size_t k = 0; k < comp.faces.size(); ++k)
    {
      const std::size_t f = comp.faces[k];
      faces_ok = faces_ok && comps.component_of_face[f] == c && ((f >= first_torus_face) == (c == 1)) &&
                 (k == 0 || comp.faces[k - 1] < f);
      for(int corner = 0; corner < 3; ++corner)
        faces_ok = faces_ok && comps.local_index[m.faces[f][corner]] < comp.vertices.size() &&
                   comp.vertices[comps.local_index[m.faces[f][corner]]] == m.faces[f][corner];
    }
  }
  report.check(vertices_ok, "components: each vertex once, smallest first, local_index the inverse");
  report.check(faces_ok, "components: each face in the component of its vertices, in increasing order");
}

#endif // SURFACE_MESH_DIRECTION_FIELDS_TEST_MATRICES_FACTORIZATION_H
