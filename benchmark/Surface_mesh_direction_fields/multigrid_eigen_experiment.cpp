// A measurement toward issue 50 (a factor-free eigen-solve): the smallest
// eigenpair of the smoothest field's pencil (A, M) by LOBPCG (one vector),
// preconditioned by V-cycles on the package's aggregation hierarchy
// (coarse_hierarchy.h: aggregates transported by the phases of M), against
// the package's direct path on the same mesh, in one run. Prints the levels,
// the iterations, the times, the eigenvalues and the angle between the two
// eigenvectors.
//   usage: multigrid_eigen_experiment MESH [--degree N] [--sweeps S] [--over-correction W]
//                                     [--prolongation plain|smoothed]
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
#include <string>
#include <vector>

namespace SMDF = CGAL::Surface_mesh_direction_fields;
namespace SI = SMDF::internal;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef std::complex<double> Complex;
typedef Eigen::SparseMatrix<Complex> Matrix;
typedef Eigen::VectorXcd Vector;
typedef std::chrono::steady_clock Clock;

static double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// The hierarchy of B = A + epsilon M: B and its diagonal per level, the
// prolongations between levels (the aggregates' piecewise-constant one, with
// their phases, or that smoothed by one damped Jacobi step of B: smoothed
// aggregation), the Galerkin products P^* B P and P^* M P, and a factorization
// of the coarsest B.
struct Hierarchy
{
  std::vector<Matrix> B, M, P;
  std::vector<Eigen::VectorXd> diagonal;
  Eigen::SimplicialLDLT<Matrix> coarsest;
  int sweeps = 2;
  double over_correction = 1.;

  Hierarchy(const Matrix& A0, const Matrix& M0, double epsilon, Eigen::Index coarse_size, bool smoothed)
  {
    B.push_back(A0 + epsilon * M0);
    M.push_back(M0);
    diagonal.push_back(B.back().diagonal().real());
    while(B.back().rows() > coarse_size)
    {
      const SI::Aggregates g = SI::aggregate_vertices(M.back());
      std::vector<Eigen::Triplet<Complex> > entries;
      for(Eigen::Index i = 0; i < B.back().rows(); ++i) entries.emplace_back(i, g.of_vertex[std::size_t(i)], g.phase[i]);
      Matrix p(B.back().rows(), g.count);
      p.setFromTriplets(entries.begin(), entries.end());
      if(smoothed)
      {
        Eigen::VectorXcd inverse = (2. / 3.) * diagonal.back().cwiseInverse().cast<Complex>();
        p = Matrix(p - inverse.asDiagonal() * (B.back() * p));
        p.prune(Complex(0., 0.));
      }
      const Matrix pa = p.adjoint();
      const Matrix bc = pa * B.back() * p, mc = pa * M.back() * p;
      P.push_back(p);
      B.push_back(bc);
      M.push_back(mc);
      diagonal.push_back(bc.diagonal().real());
    }
    coarsest.compute(B.back());
  }

  void smooth(std::size_t l, const Vector& b, Vector& x) const
  {
    for(int s = 0; s < sweeps; ++s)
    {
      const Vector r = b - B[l] * x;
      x.array() += (2. / 3.) * r.array() / diagonal[l].array().cast<Complex>();
    }
  }

  Vector cycle(std::size_t l, const Vector& b) const
  {
    if(l + 1 == B.size()) return coarsest.solve(b);
    Vector x = Vector::Zero(b.size());
    smooth(l, b, x);
    const Vector rc = P[l].adjoint() * (b - B[l] * x);
    x += over_correction * (P[l] * cycle(l + 1, rc));
    smooth(l, b, x);
    return x;
  }
};

struct Eigenpair
{
  Vector x;
  double lambda = 0., residual = 0.;
  int iterations = 0;
};

// LOBPCG for one vector: Rayleigh-Ritz on span{x, T r, p}, orthonormalized for M.
static Eigenpair lobpcg(const Matrix& A, const Matrix& M, const Hierarchy& h, Vector x, double scale, double tol,
                        int max_iterations)
{
  Eigenpair e;
  Vector p;
  for(e.iterations = 0; e.iterations < max_iterations; ++e.iterations)
  {
    x /= std::sqrt(x.dot(M * x).real());
    const Vector Ax = A * x, Mx = M * x;
    e.lambda = x.dot(Ax).real();
    const Vector r = Ax - e.lambda * Mx;
    e.residual = r.norm() / (scale * Mx.norm());
    if(e.residual < tol) break;
    if(std::getenv("TRACE") && e.iterations % 10 == 0) std::cout << "    " << e.iterations << " " << e.residual << "\n";
    Eigen::MatrixXcd S(x.size(), p.size() > 0 ? 3 : 2);
    S.col(0) = x;
    S.col(1) = h.cycle(0, r);
    if(p.size() > 0) S.col(2) = p;
    // M-orthonormal basis (Cholesky of the Gram matrix, columns dropped if dependent)
    const Eigen::MatrixXcd MS = M * S;
    Eigen::MatrixXcd G = S.adjoint() * MS;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> gram(G);
    const double largest = gram.eigenvalues().maxCoeff();
    std::vector<Eigen::Index> kept;
    for(Eigen::Index k = 0; k < G.rows(); ++k)
      if(gram.eigenvalues()[k] > 1e-14 * largest) kept.push_back(k);
    Eigen::MatrixXcd W(G.rows(), Eigen::Index(kept.size()));
    for(std::size_t k = 0; k < kept.size(); ++k)
      W.col(Eigen::Index(k)) = gram.eigenvectors().col(kept[k]) / std::sqrt(gram.eigenvalues()[kept[k]]);
    const Eigen::MatrixXcd Q = S * W;
    const Eigen::MatrixXcd H = Q.adjoint() * (A * Q);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> ritz(0.5 * (H + H.adjoint()));
    const Eigen::VectorXcd c = ritz.eigenvectors().col(0);
    const Vector next = Q * c;
    // the search direction: next without its component along x
    p = next - x * (x.dot(M * next));
    x = next;
  }
  e.x = x;
  return e;
}

int main(int argc, char** argv)
{
  if(argc < 2)
  {
    std::cerr << "usage: multigrid_eigen_experiment MESH [--degree N] [--sweeps S] [--over-correction W] [--prolongation plain|smoothed]\n";
    return 1;
  }
  int degree = 4, sweeps = 2;
  double over = 1.;
  bool smoothed = false;
  for(int i = 2; i + 1 < argc; i += 2)
  {
    const std::string a = argv[i];
    if(a == "--degree") degree = std::atoi(argv[i + 1]);
    else if(a == "--sweeps") sweeps = std::atoi(argv[i + 1]);
    else if(a == "--over-correction") over = std::atof(argv[i + 1]);
    else if(a == "--prolongation") smoothed = std::string(argv[i + 1]) == "smoothed";
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
    field.compute(dir, CGAL::parameters::degree(degree).vertex_coefficient_map(coefficient));
  const double direct_ms = ms_since(t);
  if(direct.components.size() != 1)
  {
    std::cerr << "one component only\n";
    return 1;
  }
  const auto am = field.energy_and_mass_matrices(degree, 0.);
  const Matrix &A = am.first, &M = am.second;
  const double scale = A.diagonal().real().sum() / M.diagonal().real().sum();

  t = Clock::now();
  Hierarchy h(A, M, 1e-8 * scale, 5000, smoothed);
  h.sweeps = sweeps;
  h.over_correction = over;
  const double setup_ms = ms_since(t);
  // start: the coarsest level's smallest eigenvector by inverse iteration, prolongated and smoothed
  t = Clock::now();
  Vector xc = Vector::Ones(h.B.back().rows());
  for(int k = 0; k < 30; ++k)
  {
    xc = h.coarsest.solve(h.M.back() * xc);
    xc /= xc.norm();
  }
  for(std::size_t l = h.P.size(); l-- > 0;)
  {
    xc = h.P[l] * xc;
    const Vector b = h.M[l] * xc;  // one smoothing step of inverse iteration on the level
    h.smooth(l, b, xc);
  }
  const double start_ms = ms_since(t);
  t = Clock::now();
  const Eigenpair e = lobpcg(A, M, h, xc, scale, 1e-10, 2000);
  const double lobpcg_ms = ms_since(t);

  Vector u(A.rows());
  for(auto v : mesh.vertices()) u[Eigen::Index(v.idx())] = coefficient[v];
  const double cosine = std::abs(u.dot(M * e.x)) / std::sqrt(u.dot(M * u).real() * e.x.dot(M * e.x).real());
  std::cout << argv[1] << ": " << A.rows() << " vertices, levels";
  for(const Matrix& B : h.B) std::cout << " " << B.rows();
  std::cout << "\n  direct: " << direct_ms << " ms, " << direct.iterations << " solves, eigenvalue "
            << direct.components[0].eigenvalue << "\n  multigrid LOBPCG (sweeps " << sweeps << ", over-correction "
            << over << (smoothed ? ", smoothed" : ", plain") << " prolongation): hierarchy " << setup_ms << " ms, start " << start_ms << " ms, " << e.iterations
            << " iterations " << lobpcg_ms << " ms, residual " << e.residual << ", eigenvalue " << e.lambda
            << ", 1 - |cos| to the direct eigenvector " << 1. - cosine << "\n";
  return 0;
}
