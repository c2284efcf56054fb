// A measurement toward issue 50 (a factor-free eigen-solve): the smallest
// eigenpair of the smoothest field's pencil (A, M) by block LOBPCG,
// preconditioned by V-cycles on the package's aggregation hierarchy
// (coarse_hierarchy.h: aggregates transported by the phases of M) or, as the
// ideal to compare with, by an exact solve with B = A - shift M; against the
// package's direct path on the same mesh, in one run. Prints the levels, the
// V-cycle's own convergence factor, the iterations, the times, the
// eigenvalues and the angle between the two eigenvectors.
//   usage: multigrid_eigen_experiment MESH [--degree N] [--sweeps S] [--over-correction W]
//            [--prolongation plain|smoothed] [--block K] [--preconditioner multigrid|exact]
//            [--shift-fraction F] [--transport connection|none] [--strength THETA] [--augment K]
//            [--damping fixed|spectral]
// --shift-fraction F shifts B to A - F lambda_1 M (lambda_1 from the direct
// path: the ideal shift, for measurement only). --transport none replaces
// the pencil by the scalar cotangent Laplacian and mass (the transport
// removed), a control that tells the connection's part in the V-cycle's rate
// from the mesh's. --strength THETA aggregates along strong couplings only
// (strong_couplings()). --augment K keeps the coarsest level's next K
// eigenvectors, prolongated, in every LOBPCG basis. --damping spectral damps
// the Jacobi sweeps and the prolongation's smoothing by 4 / (3 rho) per
// level, rho the spectral radius of D^-1 B by power iteration (printed),
// instead of 2/3.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/coarse_hierarchy.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <chrono>
#include <complex>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;
namespace SI = SMDF::internal;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef std::complex<double> Complex;
typedef Eigen::SparseMatrix<Complex> Matrix;
typedef Eigen::VectorXcd Vector;
typedef Eigen::MatrixXcd Block;
typedef std::chrono::steady_clock Clock;

static double ms_since(Clock::time_point t)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

struct Options
{
  int degree = 4, sweeps = 2, block = 1, augment = 0;
  double over_correction = 1., shift_fraction = 0., strength = 0.;
  bool spectral = false;  // damping 4 / (3 rho(D^-1 B)) per level instead of 2/3
  bool smoothed = false, exact = false, scalar = false;
};

// The couplings the aggregation may follow: those of positive weight
// w_ij = Re(-B_ij conj(phase of M_ij)) above theta sqrt(B_ii B_jj) (the strength
// of connection of algebraic multigrid), with M's values for their phases.
// Without it every neighbour joins an aggregate, also across the negative
// cotangent weights of obtuse triangles and along the weak direction of
// stretched ones.
static Matrix strong_couplings(const Matrix& B, const Matrix& M, double theta)
{
  std::vector<Eigen::Triplet<Complex> > kept;
  for(Eigen::Index c = 0; c < B.outerSize(); ++c)
    for(Matrix::InnerIterator it(B, c); it; ++it)
    {
      const Complex m = M.coeff(it.row(), c);
      const double w = (-it.value() * std::conj(SI::unit(m))).real();
      if(it.row() == c || w > theta * std::sqrt(B.coeff(c, c).real() * B.coeff(it.row(), it.row()).real()))
        kept.emplace_back(it.row(), c, m);
    }
  Matrix strong(B.rows(), B.cols());
  strong.setFromTriplets(kept.begin(), kept.end());
  return strong;
}

// The hierarchy of B: B and its diagonal per level, the prolongations between
// levels (the aggregates' piecewise-constant one, with their phases, or that
// smoothed by one damped Jacobi step of B: smoothed aggregation), the
// Galerkin products P^* B P and P^* M P, and a factorization of the coarsest
// B (and of the finest, for the exact preconditioner).
struct Hierarchy
{
  std::vector<Matrix> B, M, P;
  std::vector<Eigen::VectorXd> diagonal;
  std::vector<double> damping;
  Eigen::SimplicialLDLT<Matrix> coarsest, finest;
  const Options& options;

  Hierarchy(const Matrix& B0, const Matrix& M0, Eigen::Index coarse_size, const Options& o) : options(o)
  {
    B.push_back(B0);
    M.push_back(M0);
    diagonal.push_back(B0.diagonal().real());
    damping.push_back(damping_of(B0, diagonal.back()));
    while(B.back().rows() > coarse_size)
    {
      const SI::Aggregates g =
        SI::aggregate_vertices(o.strength > 0. ? strong_couplings(B.back(), M.back(), o.strength) : M.back());
      if(g.count > B.back().rows() * 4 / 5) break;  // coarsening stalls (few strong couplings): factor this level
      std::vector<Eigen::Triplet<Complex> > entries;
      for(Eigen::Index i = 0; i < B.back().rows(); ++i)
        entries.emplace_back(i, g.of_vertex[std::size_t(i)], g.phase[i]);
      Matrix p(B.back().rows(), g.count);
      p.setFromTriplets(entries.begin(), entries.end());
      if(o.smoothed)
      {
        const Vector inverse = damping.back() * diagonal.back().cwiseInverse().cast<Complex>();
        p = Matrix(p - inverse.asDiagonal() * (B.back() * p));
        p.prune(Complex(0., 0.));
      }
      const Matrix pa = p.adjoint();
      P.push_back(p);
      B.push_back(pa * B.back() * p);
      M.push_back(pa * M.back() * p);
      diagonal.push_back(B.back().diagonal().real());
      damping.push_back(damping_of(B.back(), diagonal.back()));
    }
    coarsest.compute(B.back());
    if(o.exact) finest.compute(B[0]);
  }

  double damping_of(const Matrix& Bl, const Eigen::VectorXd& d) const
  {
    if(!options.spectral) return 2. / 3.;
    Vector x = Vector::Random(Bl.rows());
    double rho = 0.;
    for(int k = 0; k < 30; ++k)
    {
      Vector y = (Bl * x).array() / d.array().cast<Complex>();
      rho = y.norm() / x.norm();
      x = y / y.norm();
    }
    std::cerr << "level " << Bl.rows() << ": rho(D^-1 B) ~ " << rho << "\n";
    return 4. / (3. * 1.05 * rho);
  }

  void smooth(std::size_t l, const Vector& b, Vector& x) const
  {
    for(int s = 0; s < options.sweeps; ++s)
    {
      const Vector r = b - B[l] * x;
      x.array() += damping[l] * r.array() / diagonal[l].array().cast<Complex>();
    }
  }

  Vector cycle(std::size_t l, const Vector& b) const
  {
    if(l + 1 == B.size()) return coarsest.solve(b);
    Vector x = Vector::Zero(b.size());
    smooth(l, b, x);
    const Vector rc = P[l].adjoint() * (b - B[l] * x);
    x += options.over_correction * (P[l] * cycle(l + 1, rc));
    smooth(l, b, x);
    return x;
  }

  Vector precondition(const Vector& r) const { return options.exact ? Vector(finest.solve(r)) : cycle(0, r); }

  // The V-cycle as a stationary iteration on B x = 0 from a random x: the
  // factor by which the energy norm falls in the last of `cycles` cycles.
  double vcycle_factor(int cycles) const
  {
    Vector x = Vector::Random(B[0].rows());
    double previous = std::sqrt(x.dot(B[0] * x).real()), factor = 0.;
    for(int k = 0; k < cycles; ++k)
    {
      x -= cycle(0, B[0] * x);
      const double e = std::sqrt(x.dot(B[0] * x).real());
      factor = e / previous;
      previous = e;
    }
    return factor;
  }
};

struct Eigenpair
{
  Vector x;
  double lambda = 0., residual = 0.;
  int iterations = 0;
};

// Removes span(X) (X M-orthonormal) from Z; twice, as one pass leaves
// rounding of the size of Z's component along X.
static void project_out(const Matrix& M, const Block& X, Block& Z)
{
  for(int pass = 0; pass < 2; ++pass) Z -= X * (X.adjoint() * (M * Z));
}

// M-orthonormalizes Z by the eigen-decomposition of its Gram matrix after
// scaling each column to unit M-norm (SVQB), dropping dependent directions.
// The scaling is what lets a correction that is already tiny (a converged
// residual's) survive: unscaled, a threshold relative to the largest
// column drops it, and the iteration stalls.
static Block m_orthonormal(const Matrix& M, const Block& Z)
{
  const Block G = Z.adjoint() * (M * Z);
  Eigen::VectorXd d = G.diagonal().real();
  for(Eigen::Index i = 0; i < d.size(); ++i) d[i] = d[i] > 0. ? 1. / std::sqrt(d[i]) : 0.;
  const Block scaled = d.asDiagonal() * G * d.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Block> gram(0.5 * (scaled + scaled.adjoint()));
  const double largest = gram.eigenvalues().maxCoeff();
  std::vector<Eigen::Index> kept;
  for(Eigen::Index k = 0; k < scaled.rows(); ++k)
    if(gram.eigenvalues()[k] > 1e-13 * largest) kept.push_back(k);
  Block C(scaled.rows(), Eigen::Index(kept.size()));
  for(std::size_t k = 0; k < kept.size(); ++k)
    C.col(Eigen::Index(k)) = d.asDiagonal() * gram.eigenvectors().col(kept[k]) / std::sqrt(gram.eigenvalues()[kept[k]]);
  return Z * C;
}

// The Ritz vectors of span S (S M-orthonormal) for the `count` smallest Ritz values.
static Block ritz_vectors(const Matrix& A, const Block& S, Eigen::Index count, Block& coefficients,
                          Eigen::VectorXd& values)
{
  const Block H = S.adjoint() * (A * S);
  Eigen::SelfAdjointEigenSolver<Block> ritz(0.5 * (H + H.adjoint()));
  coefficients = ritz.eigenvectors().leftCols(count);
  values = ritz.eigenvalues().head(count);
  return S * coefficients;
}

// Block LOBPCG: Rayleigh-Ritz on [X, W, P] (X the current Ritz vectors, W
// their preconditioned residuals, P the last update outside span X);
// converged when the first vector's relative residual is below tol.
static Eigenpair lobpcg(const Matrix& A, const Matrix& M, const Hierarchy& h, const Vector& start, int block,
                        const Block& augmentation, double scale, double tol, int max_iterations)
{
  const Eigen::Index n = A.rows();
  Block X(n, block), P(n, 0), C;
  X.col(0) = start;
  for(Eigen::Index j = 1; j < block; ++j) X.col(j) = Vector::Random(n);
  Eigen::VectorXd theta;
  X = ritz_vectors(A, m_orthonormal(M, X), block, C, theta);
  Eigenpair e;
  for(e.iterations = 0;; ++e.iterations)
  {
    const Block MX = M * X;
    const Block R = A * X - MX * theta.asDiagonal();
    e.lambda = theta[0];
    e.residual = R.col(0).norm() / (scale * MX.col(0).norm());
    if(e.residual < tol || e.iterations == max_iterations) break;
    Block Z(n, R.cols() + P.cols() + augmentation.cols());
    for(Eigen::Index j = 0; j < R.cols(); ++j) Z.col(j) = h.precondition(R.col(j));
    Z.middleCols(R.cols(), P.cols()) = P;
    Z.rightCols(augmentation.cols()) = augmentation;
    for(int pass = 0; pass < 2; ++pass)
    {
      project_out(M, X, Z);
      Z = m_orthonormal(M, Z);
    }
    Block S(n, X.cols() + Z.cols());
    S << X, Z;
    X = ritz_vectors(A, S, block, C, theta);
    P = Z * C.bottomRows(Z.cols());
  }
  e.x = X.col(0);
  return e;
}

// The scalar control: the cotangent weights and the mass without the
// transport (each coupling rotated by the conjugate of M's phase), the
// diagonal made to sum each row of A to zero.
static void remove_transport(Matrix& A, Matrix& M)
{
  std::vector<Eigen::Triplet<Complex> > a, m;
  Eigen::VectorXd row_sum = Eigen::VectorXd::Zero(A.rows());
  for(Eigen::Index c = 0; c < A.outerSize(); ++c)
    for(Matrix::InnerIterator it(A, c); it; ++it)
    {
      const Complex mass = M.coeff(it.row(), c);
      if(it.row() == c)
      {
        m.emplace_back(c, c, mass);
        continue;
      }
      const double weight = (it.value() * std::conj(SI::unit(mass))).real();
      a.emplace_back(it.row(), c, weight);
      row_sum[it.row()] += weight;
      m.emplace_back(it.row(), c, std::abs(mass));
    }
  for(Eigen::Index i = 0; i < A.rows(); ++i) a.emplace_back(i, i, -row_sum[i]);
  A.setFromTriplets(a.begin(), a.end());
  M.setFromTriplets(m.begin(), m.end());
}

static bool parse(int argc, char** argv, Options& o)
{
  for(int i = 2; i + 1 < argc; i += 2)
  {
    const std::string a = argv[i], v = argv[i + 1];
    if(a == "--degree") o.degree = std::atoi(v.c_str());
    else if(a == "--sweeps") o.sweeps = std::atoi(v.c_str());
    else if(a == "--over-correction") o.over_correction = std::atof(v.c_str());
    else if(a == "--prolongation") o.smoothed = v == "smoothed";
    else if(a == "--block") o.block = std::max(1, std::atoi(v.c_str()));
    else if(a == "--preconditioner") o.exact = v == "exact";
    else if(a == "--shift-fraction") o.shift_fraction = std::atof(v.c_str());
    else if(a == "--augment") o.augment = std::max(0, std::atoi(v.c_str()));
    else if(a == "--strength") o.strength = std::atof(v.c_str());
    else if(a == "--transport") o.scalar = v == "none";
    else if(a == "--damping") o.spectral = v == "spectral";
    else return false;
  }
  return argc >= 2 && argc % 2 == 0;
}

// The coarsest level's `count` smallest eigenvectors by subspace inverse
// iteration, prolongated, with one smoothing step per level: column 0 is
// the start; the others, with --augment, stay in every LOBPCG basis so that
// Rayleigh-Ritz, not the iteration, separates the crowded lowest modes.
static Block coarse_eigenvectors(const Hierarchy& h, Eigen::Index count)
{
  const Matrix &Bc = h.B.back(), &Mc = h.M.back();
  Block Y = Block::Random(Bc.rows(), count);
  Y.col(0).setOnes();
  for(int k = 0; k < 30; ++k)
  {
    for(Eigen::Index j = 0; j < count; ++j) Y.col(j) = h.coarsest.solve(Mc * Y.col(j));
    Y = m_orthonormal(Mc, Y);
  }
  Block C;
  Eigen::VectorXd values;
  Y = ritz_vectors(Bc, Y, Y.cols(), C, values);
  for(std::size_t l = h.P.size(); l-- > 0;)
  {
    Y = h.P[l] * Y;
    for(Eigen::Index j = 0; j < Y.cols(); ++j)
    {
      Vector y = Y.col(j);
      const Vector b = h.M[l] * y;
      h.smooth(l, b, y);
      Y.col(j) = y;
    }
  }
  return Y;
}

int main(int argc, char** argv)
{
  Options o;
  if(!parse(argc, argv, o))
  {
    std::cerr << "usage: multigrid_eigen_experiment MESH [--degree N] [--sweeps S] [--over-correction W] "
                 "[--prolongation plain|smoothed] [--block K] [--preconditioner multigrid|exact] "
                 "[--shift-fraction F] [--transport connection|none] [--strength THETA] [--augment K] "
                 "[--damping fixed|spectral]\n";
    return 1;
  }
  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(argv[1], mesh) || mesh.is_empty())
  {
    std::cerr << "cannot read " << argv[1] << "\n";
    return 1;
  }
  auto dir = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:d").first;
  auto coefficient = mesh.add_property_map<Mesh::Vertex_index, Complex>("v:c").first;
  SMDF::Globally_optimal_direction_field<Mesh> field(mesh);
  auto t = Clock::now();
  const SMDF::Direction_field_result direct =
    field.compute(dir, CGAL::parameters::degree(o.degree).vertex_coefficient_map(coefficient));
  const double direct_ms = ms_since(t);
  if(direct.components.size() != 1)
  {
    std::cerr << "one component only\n";
    return 1;
  }
  auto matrices = field.energy_and_mass_matrices(o.degree, 0.);
  Matrix &A = matrices.first, &M = matrices.second;
  if(o.scalar) remove_transport(A, M);
  const double scale = A.diagonal().real().sum() / M.diagonal().real().sum();
  // B = A + epsilon M, positive definite: a tiny positive epsilon, or minus a fraction of lambda_1
  const double lambda_1 = direct.components[0].eigenvalue;
  const double epsilon = o.shift_fraction > 0. && !o.scalar ? -o.shift_fraction * lambda_1 : 1e-8 * scale;

  t = Clock::now();
  const Hierarchy h(Matrix(A + epsilon * M), M, 5000, o);
  const double setup_ms = ms_since(t);
  const double factor = h.vcycle_factor(12);
  t = Clock::now();
  const Block coarse = coarse_eigenvectors(h, 1 + o.augment);
  const Vector start = coarse.col(0);
  const Block augmentation = coarse.rightCols(o.augment);
  const double start_ms = ms_since(t);
  t = Clock::now();
  const Eigenpair e = lobpcg(A, M, h, start, o.block, augmentation, scale, 1e-10, 2000);
  const double lobpcg_ms = ms_since(t);

  Vector u(A.rows());
  for(auto v : mesh.vertices()) u[Eigen::Index(v.idx())] = coefficient[v];
  const double cosine = std::abs(u.dot(M * e.x)) / std::sqrt(u.dot(M * u).real() * e.x.dot(M * e.x).real());
  std::cout << argv[1] << ": " << A.rows() << " vertices, levels";
  for(const Matrix& B : h.B) std::cout << " " << B.rows();
  std::cout << "\n  direct: " << direct_ms << " ms, " << direct.iterations << " solves, eigenvalue " << lambda_1;
  std::cout << "\n  V-cycle (sweeps " << o.sweeps << ", over-correction " << o.over_correction
            << (o.smoothed ? ", smoothed" : ", plain") << " prolongation" << (o.scalar ? ", transport removed" : "");
  if(o.strength > 0.) std::cout << ", strength " << o.strength;
  std::cout << "): energy-norm factor " << factor << " per cycle";
  std::cout << "\n  LOBPCG (" << (o.exact ? "exact solve" : "V-cycle") << ", block " << o.block << ", shift "
            << epsilon / scale << " x scale, augmented by " << o.augment << "): hierarchy " << setup_ms
            << " ms, start " << start_ms << " ms, "
            << e.iterations << " iterations " << lobpcg_ms << " ms, residual " << e.residual << ", eigenvalue "
            << e.lambda;
  if(!o.scalar) std::cout << ", 1 - |cos| to the direct eigenvector " << 1. - cosine;
  std::cout << "\n";
  return 0;
}
