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
//            [--damping fixed|spectral] [--patches off|on] [--coarse-size N]
//            [--operator mesh|cotan|delaunay|delaunay-guide]
// --shift-fraction F shifts B to A - F lambda_1 M (lambda_1 from the direct
// path: the ideal shift, for measurement only). --transport none replaces
// the pencil by the scalar cotangent Laplacian and mass (the transport
// removed), a control that tells the connection's part in the V-cycle's rate
// from the mesh's. --strength THETA aggregates along strong couplings only
// (strong_couplings()). --augment K keeps the coarsest level's next K
// eigenvectors, prolongated, in every LOBPCG basis. --damping spectral damps
// the Jacobi sweeps and the prolongation's smoothing by 4 / (3 rho) per
// level, rho the spectral radius of D^-1 B by power iteration (printed),
// instead of 2/3. --patches on adds, after the finest level's sweeps, exact
// solves on the closed one-ring of each vertex with a negative cotangent
// weight. --coarse-size N: the largest level that is factored (5,000).
// --operator replaces the preconditioner's B by a connection Laplacian with
// weights (cot alpha + cot beta) / 2 and M's transport: on the mesh's edges
// (cotan), on its intrinsic Delaunay triangulation (delaunay), or the latter
// guiding only the aggregation and the prolongation of A's hierarchy
// (delaunay-guide).
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_direction_fields.h>
#include <CGAL/Surface_mesh_direction_fields/internal/Linear_algebra/coarse_hierarchy.h>

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>

#include <array>
#include <chrono>
#include <complex>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <unordered_map>
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
  int degree = 4, sweeps = 2, block = 1, augment = 0, coarse_size = 5000;
  double over_correction = 1., shift_fraction = 0., strength = 0.;
  bool spectral = false;  // damping 4 / (3 rho(D^-1 B)) per level instead of 2/3
  bool delaunay = false;  // the preconditioner's operator on the intrinsic Delaunay triangulation
  bool flip = true;       // (with delaunay) false: the same operator on the mesh's own edges
  bool guide = false;     // (with delaunay) that operator only guides the aggregation and the prolongation
  bool patches = false;   // exact solves on the closed one-rings of vertices with a negative weight (finest level)
  bool smoothed = false, exact = false, scalar = false;
};

// The couplings the aggregation may follow: those of positive weight
// w_ij = Re(-B_ij conj(phase of M_ij)) above theta sqrt(B_ii B_jj) (the strength
// of connection of algebraic multigrid), with M's values for their phases.
// Without it every neighbour joins an aggregate, also across the negative
// cotangent weights of obtuse triangles and along the weak direction of
// stretched ones.
static Matrix strong_couplings(const Matrix& B, const Matrix& M, double theta, bool phases_of_B)
{
  std::vector<Eigen::Triplet<Complex> > kept;
  for(Eigen::Index c = 0; c < B.outerSize(); ++c)
    for(Matrix::InnerIterator it(B, c); it; ++it)
    {
      const Complex m = !phases_of_B ? M.coeff(it.row(), c) : it.row() == c ? it.value() : -it.value();
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
  std::vector<Matrix> B, M, P, G;  // G: the guide's levels (--operator delaunay-guide), else B's
  std::vector<Eigen::VectorXd> diagonal;
  std::vector<double> damping;
  Eigen::SimplicialLDLT<Matrix> coarsest, finest;
  const Options& options;
  // the patches of the finest level's smoother (--patches on): a vertex with
  // a negative cotangent weight and its neighbours, with the Cholesky
  // factor of B restricted to them
  std::vector<std::vector<Eigen::Index> > patch;
  std::vector<Eigen::LLT<Block> > patch_factor;

  void make_patches(const Matrix& Bf, const Matrix& Mf)
  {
    for(Eigen::Index c = 0; c < Bf.outerSize(); ++c)
    {
      bool negative = false;
      std::vector<Eigen::Index> members{c};
      for(Matrix::InnerIterator it(Bf, c); it; ++it)
        if(it.row() != c)
        {
          members.push_back(it.row());
          negative = negative || (-it.value() * std::conj(SI::unit(Mf.coeff(it.row(), c)))).real() < 0.;
        }
      if(!negative) continue;
      Block Bp(Eigen::Index(members.size()), Eigen::Index(members.size()));
      for(std::size_t a = 0; a < members.size(); ++a)
        for(std::size_t b = 0; b < members.size(); ++b) Bp(Eigen::Index(a), Eigen::Index(b)) = Bf.coeff(members[a], members[b]);
      patch.push_back(members);
      patch_factor.emplace_back(Bp);
    }
    std::cout << "  patches: " << patch.size() << " of " << Bf.rows() << " vertices\n";
  }

  // one multiplicative pass of the patch solves on B x = b (residual rows from B's columns: B is Hermitian)
  void smooth_patches(const Vector& b, Vector& x) const
  {
    const Matrix& Bf = B[0];
    for(std::size_t k = 0; k < patch.size(); ++k)
    {
      const std::vector<Eigen::Index>& members = patch[k];
      Vector r(Eigen::Index(members.size()));
      for(std::size_t a = 0; a < members.size(); ++a)
      {
        Complex bx(0., 0.);
        for(Matrix::InnerIterator it(Bf, members[a]); it; ++it) bx += std::conj(it.value()) * x[it.row()];
        r[Eigen::Index(a)] = b[members[a]] - bx;
      }
      const Vector d = patch_factor[k].solve(r);
      for(std::size_t a = 0; a < members.size(); ++a) x[members[a]] += d[Eigen::Index(a)];
    }
  }

  Hierarchy(const Matrix& B0, const Matrix& M0, Eigen::Index coarse_size, const Options& o, const Matrix& G0 = Matrix())
    : options(o)
  {
    B.push_back(B0);
    G.push_back(G0.rows() ? G0 : B0);
    M.push_back(M0);
    diagonal.push_back(B0.diagonal().real());
    damping.push_back(damping_of(B0, diagonal.back()));
    while(B.back().rows() > coarse_size)
    {
      const SI::Aggregates g =
        SI::aggregate_vertices(o.strength > 0. ? strong_couplings(G.back(), M.back(), o.strength, o.delaunay) : M.back());
      if(g.count > B.back().rows() * 4 / 5) break;  // coarsening stalls (few strong couplings): factor this level
      std::vector<Eigen::Triplet<Complex> > entries;
      for(Eigen::Index i = 0; i < B.back().rows(); ++i)
        entries.emplace_back(i, g.of_vertex[std::size_t(i)], g.phase[i]);
      Matrix p(B.back().rows(), g.count);
      p.setFromTriplets(entries.begin(), entries.end());
      if(o.smoothed)
      {
        const double w = G0.rows() ? 2. / 3. : damping.back();
        const Vector inverse = w * G.back().diagonal().real().cwiseInverse().cast<Complex>();
        p = Matrix(p - inverse.asDiagonal() * (G.back() * p));
        p.prune(Complex(0., 0.));
      }
      const Matrix pa = p.adjoint();
      P.push_back(p);
      B.push_back(pa * B.back() * p);
      G.push_back(G0.rows() ? Matrix(pa * G.back() * p) : B.back());
      M.push_back(pa * M.back() * p);
      diagonal.push_back(B.back().diagonal().real());
      damping.push_back(damping_of(B.back(), diagonal.back()));
    }
    coarsest.compute(B.back());
    if(o.exact) finest.compute(B[0]);
    if(o.patches) make_patches(B[0], M[0]);
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
    if(l == 0 && !patch.empty()) smooth_patches(b, x);
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

// The preconditioner's operator on the intrinsic Delaunay triangulation of
// the mesh (edge flips that keep the metric, Fisher et al. 2007): its
// cotangent weights are non-negative. Each edge keeps its length and the
// transport of the coefficients along it (x_q ~ t x_p from p to q), read
// from M's phases on the mesh's edges (x_i = unit(M_ij) x_j, as the
// aggregation reads them) and, for a flipped edge, composed through the two
// vertices of the old edge and averaged. Returns the connection Laplacian
// with weights (cot alpha + cot beta) / 2 in A's scale.
struct Intrinsic_triangulation
{
  struct Edge
  {
    double length;
    Complex transport;  // from the lower vertex to the higher one
    int face[2];
  };
  std::vector<std::array<int, 3> > faces;
  std::unordered_map<std::uint64_t, Edge> edges;
  int flips = 0, refused = 0;

  static std::uint64_t key(int p, int q)
  {
    if(p > q) std::swap(p, q);
    return (std::uint64_t(p) << 32) | std::uint64_t(unsigned(q));
  }
  double length(int p, int q) const { return edges.at(key(p, q)).length; }
  Complex transport(int p, int q) const  // x_q ~ t x_p
  {
    const Complex t = edges.at(key(p, q)).transport;
    return p < q ? t : std::conj(t);
  }
  int opposite(int f, int p, int q) const
  {
    for(int v : faces[std::size_t(f)])
      if(v != p && v != q) return v;
    return -1;
  }
  // cot of the angle of face f opposite edge pq
  double cot_opposite(int f, int p, int q) const
  {
    const int o = opposite(f, p, q);
    const double a = length(p, q), b = length(q, o), c = length(o, p);
    const double s2 = (a + b + c) * (-a + b + c) * (a - b + c) * (a + b - c);
    return (b * b + c * c - a * a) / std::sqrt(std::max(s2, 1e-300));
  }
  double cot_sum(const Edge& e, int p, int q) const
  {
    double sum = cot_opposite(e.face[0], p, q);
    if(e.face[1] >= 0) sum += cot_opposite(e.face[1], p, q);
    return sum;
  }

  Intrinsic_triangulation(const Mesh& mesh, const Matrix& M)
  {
    for(auto f : mesh.faces())
    {
      std::array<int, 3> t;
      int k = 0;
      for(auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[std::size_t(k++)] = int(v.idx());
      faces.push_back(t);
      const int fi = int(faces.size() - 1);
      for(int c = 0; c < 3; ++c)
      {
        const int p = t[std::size_t(c)], q = t[std::size_t((c + 1) % 3)];
        auto it = edges.find(key(p, q));
        if(it != edges.end())
        {
          it->second.face[1] = fi;
          continue;
        }
        const double l = std::sqrt(CGAL::squared_distance(mesh.point(Mesh::Vertex_index(p)), mesh.point(Mesh::Vertex_index(q))));
        const int lo = std::min(p, q), hi = std::max(p, q);
        edges[key(p, q)] = {l, SI::unit(M.coeff(hi, lo)), {fi, -1}};
      }
    }
  }

  void replace_face(int p, int q, int from, int to)
  {
    Edge& e = edges.at(key(p, q));
    for(int& f : e.face)
      if(f == from)
      {
        f = to;
        return;
      }
  }

  // flips edge ab (faces f1 = a b v1, f2 = b a v2, counter-clockwise) to v1 v2
  bool flip(int a, int b)
  {
    const Edge e = edges.at(key(a, b));
    int f1 = e.face[0], f2 = e.face[1];
    // f1 must hold the halfedge a -> b
    const auto& t1 = faces[std::size_t(f1)];
    bool a_to_b = false;
    for(int c = 0; c < 3; ++c) a_to_b = a_to_b || (t1[std::size_t(c)] == a && t1[std::size_t((c + 1) % 3)] == b);
    if(!a_to_b) std::swap(f1, f2);
    const int v1 = opposite(f1, a, b), v2 = opposite(f2, a, b);
    if(v1 == v2 || edges.count(key(v1, v2))) return false;
    // the quad laid out in the plane: a = 0, b on the x axis, v1 above, v2 below
    const double lab = e.length;
    auto place = [&](int v, double side) {
      const double la = length(a, v), lb = length(b, v);
      const double x = (la * la - lb * lb + lab * lab) / (2. * lab);
      return std::array<double, 2>{x, side * std::sqrt(std::max(0., la * la - x * x))};
    };
    const auto p1 = place(v1, 1.), p2 = place(v2, -1.);
    const double l12 = std::hypot(p1[0] - p2[0], p1[1] - p2[1]);
    const Complex through_a = transport(a, v2) * transport(v1, a), through_b = transport(b, v2) * transport(v1, b);
    Complex t = SI::unit(through_a + through_b);  // v1 -> v2
    if(v1 > v2) t = std::conj(t);
    edges.erase(key(a, b));
    faces[std::size_t(f1)] = {v1, a, v2};
    faces[std::size_t(f2)] = {v2, b, v1};
    replace_face(b, v1, f1, f2);
    replace_face(a, v2, f2, f1);
    edges[key(v1, v2)] = {l12, t, {f1, f2}};
    return true;
  }

  void make_delaunay()
  {
    std::vector<std::uint64_t> queue;
    for(const auto& e : edges) queue.push_back(e.first);
    while(!queue.empty())
    {
      const std::uint64_t k = queue.back();
      queue.pop_back();
      auto it = edges.find(k);
      if(it == edges.end() || it->second.face[1] < 0) continue;
      const int a = int(k >> 32), b = int(k & 0xffffffffu);
      if(cot_sum(it->second, a, b) >= -1e-12) continue;
      const int v1 = opposite(it->second.face[0], a, b), v2 = opposite(it->second.face[1], a, b);
      if(!flip(a, b))
      {
        ++refused;
        continue;
      }
      ++flips;
      for(auto pq : {std::make_pair(a, v1), std::make_pair(a, v2), std::make_pair(b, v1), std::make_pair(b, v2)})
        queue.push_back(key(pq.first, pq.second));
    }
  }

  Matrix laplacian(Eigen::Index n, int& negative) const
  {
    std::vector<Eigen::Triplet<Complex> > t;
    Eigen::VectorXd diagonal = Eigen::VectorXd::Zero(n);
    negative = 0;
    for(const auto& entry : edges)
    {
      const int lo = int(entry.first >> 32), hi = int(entry.first & 0xffffffffu);
      const double w = 0.5 * cot_sum(entry.second, lo, hi);
      if(w < 0.) ++negative;
      t.emplace_back(hi, lo, -w * entry.second.transport);
      t.emplace_back(lo, hi, -w * std::conj(entry.second.transport));
      diagonal[lo] += w;
      diagonal[hi] += w;
    }
    for(Eigen::Index i = 0; i < n; ++i) t.emplace_back(i, i, diagonal[i]);
    Matrix L(n, n);
    L.setFromTriplets(t.begin(), t.end());
    return L;
  }
};

// The connection Laplacian of Intrinsic_triangulation plus epsilon M, on
// the mesh's edges or after the flips to the intrinsic Delaunay
// triangulation; prints the flips, the negative weights and the distance of
// the unflipped one from A.
static Matrix connection_laplacian(const Mesh& mesh, const Matrix& A, const Matrix& M, double epsilon, bool flip)
{
  const auto t = Clock::now();
  Intrinsic_triangulation triangulation(mesh, M);
  int negative_before = 0, negative_after = 0;
  const Matrix before = triangulation.laplacian(A.rows(), negative_before);
  if(flip) triangulation.make_delaunay();
  const Matrix L = triangulation.laplacian(A.rows(), negative_after) + epsilon * M;
  std::cout << "  intrinsic Delaunay: " << triangulation.flips << " flips (" << triangulation.refused
            << " refused), negative weights " << negative_before << " -> " << negative_after << " of "
            << triangulation.edges.size() << " edges, |L_mesh - A| / |A| = " << (before - A).norm() / A.norm()
            << ", " << ms_since(t) << " ms\n";
  return L;
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
    else if(a == "--patches") o.patches = v == "on";
    else if(a == "--coarse-size") o.coarse_size = std::max(2, std::atoi(v.c_str()));
    else if(a == "--operator")
    {
      o.delaunay = v == "delaunay" || v == "cotan" || v == "delaunay-guide";
      o.flip = v != "cotan";
      o.guide = v == "delaunay-guide";
    }
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
                 "[--damping fixed|spectral] [--patches off|on] [--coarse-size N] "
                 "[--operator mesh|cotan|delaunay|delaunay-guide]\n";
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
  const double lambda_1 = direct.components[0].eigenvalue.value();
  const double epsilon = o.shift_fraction > 0. && !o.scalar ? -o.shift_fraction * lambda_1 : 1e-8 * scale;

  t = Clock::now();
  Matrix B0 = A + epsilon * M, guide;
  if(o.delaunay) (o.guide ? guide : B0) = connection_laplacian(mesh, A, M, epsilon, o.flip);
  const Hierarchy h(B0, M, o.coarse_size, o, guide);
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
  std::cout << "\n  coarsest level: " << h.B.back().nonZeros() << " entries, factor (AMD, Eigen's LDLT) "
            << h.coarsest.matrixL().nestedExpression().nonZeros() << " entries";
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
