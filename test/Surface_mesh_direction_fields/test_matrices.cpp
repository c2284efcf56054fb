// The building blocks, checked against exact expectations:
//  * tangent spaces and connection: r_ji = conj(r_ij) across every interior
//    edge, exp(i Omega_t) = r_ij r_jk r_ki, and Gauss-Bonnet sum Omega = 2 pi n chi;
//  * on a planar mesh, the energy matrix is the cotan Laplacian, conjugated by
//    the phases of the vertex bases (A = P^* L P), and M is scale-covariant;
//  * A and M are Hermitian, A is positive semi-definite for s = -1, 0, 1;
//  * on a round sphere of radius R, lambda_1 = n (1 - s) / R^2 (pins every sign
//    and conjugation of the user manual, section "Local Matrices");
//  * the coarse estimate of the eigen-solve: the coarse matrices are P^* A P
//    and P^* M P, the bound is >= lambda_1, and the shifted factorization (or
//    its fallback, when the shift is too large) gives the eigenpair of the
//    unshifted solve, and a rejected trial shift prints nothing;
//  * the matrices handed to the solver: A + shift M, or its lower triangle for
//    the Cholesky solvers, equal to Eigen's sum bit for bit; the parallel
//    basis products of the eigen-solve equal Eigen's;
//  * the components: each vertex and face in exactly one, in a fixed order;
//  * the parallel solve with CHOLMOD's supernodal factor: CHOLMOD's solution,
//    the same bits on any number of threads, a plan of whole subtrees.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Surface_mesh_direction_fields.h>

#include "generated_meshes.h"
#include "test_support.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cmath>
#include <sstream>
#include <memory>
#include <fstream>
#include <cstdint>
#include <cstring>
#include <complex>
#include <iostream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace SMDF = CGAL::Surface_mesh_direction_fields;
namespace SI = CGAL::Surface_mesh_direction_fields::internal;
typedef std::complex<double> Complex;

static SI::Indexed_mesh index_mesh(const Mesh& mesh)
{
  return SI::make_indexed_mesh(
    mesh, [&](Mesh::Vertex_index v) { const auto& p = mesh.point(v); return SI::Vec3{p.x(), p.y(), p.z()}; },
    get(CGAL::vertex_index, mesh), get(CGAL::face_index, mesh));
}

static double max_abs(const SI::Complex_sparse_matrix& A)
{
  double m = 0.;
  for(Eigen::Index c = 0; c < A.outerSize(); ++c)
    for(SI::Complex_sparse_matrix::InnerIterator it(A, c); it; ++it) m = (std::max)(m, std::abs(it.value()));
  return m;
}

static double hermitian_defect(const SI::Complex_sparse_matrix& A)
{
  const SI::Complex_sparse_matrix D = A - SI::Complex_sparse_matrix(A.adjoint());
  return max_abs(D) / max_abs(A);
}

// Connection identities on every face and edge; Gauss-Bonnet when closed.
static void check_connection(Test_report& report, const std::string& name, const Mesh& mesh, int n)
{
  const SI::Indexed_mesh m = index_mesh(mesh);
  const SI::Tangent_spaces ts = SI::compute_tangent_spaces(m);
  const SI::Connection con = SI::compute_connection(m, ts, n);
  double worst_holonomy = 0., worst_opposite = 0., total = 0.;
  for(auto f : mesh.faces())
  {
    const std::size_t fi = f;
    const Complex loop = con.transport[3 * fi] * con.transport[3 * fi + 1] * con.transport[3 * fi + 2];
    worst_holonomy = (std::max)(worst_holonomy, std::abs(loop - std::polar(1., con.holonomy[fi])));
    total += con.holonomy[fi];
  }
  for(auto h : mesh.halfedges())
  {
    if(mesh.is_border(h) || mesh.is_border(mesh.opposite(h))) continue;
    auto corner_of = [&](Mesh::Halfedge_index g) {
      auto f = mesh.face(g);
      std::size_t c = 0;
      for(auto k = mesh.halfedge(f); k != g; k = mesh.next(k)) ++c;
      return 3 * std::size_t(f) + c;
    };
    const Complex r = con.transport[corner_of(h)], r_back = con.transport[corner_of(mesh.opposite(h))];
    worst_opposite = (std::max)(worst_opposite, std::abs(r_back - std::conj(r)));
  }
  report.check(worst_holonomy < 1e-11, name + ": exp(i Omega) = r_ij r_jk r_ki (" + std::to_string(worst_holonomy) + ")");
  report.check(worst_opposite < 1e-11, name + ": r_ji = conj(r_ij) (" + std::to_string(worst_opposite) + ")");
  if(CGAL::is_closed(mesh))
  {
    const long chi = long(mesh.number_of_vertices()) - long(mesh.number_of_edges()) + long(mesh.number_of_faces());
    report.check(std::abs(total - 2. * CGAL_PI * n * chi) < 1e-8 * (1. + mesh.number_of_faces() * 1e-3),
                 name + ": sum of Omega = 2 pi n chi");
  }
}

// On a plane, with beta_i the angle of vertex i's reference direction, the
// coefficient u_i is w_i exp(-i n beta_i) for the global complex value w_i, so
// A = P^* L P with P = diag(exp(i n beta_i)) and L the real cotan Laplacian.
static void check_planar_cotan_laplacian(Test_report& report, int n)
{
  Mesh mesh;
  make_disk(mesh, 8, 1.3);
  const SI::Indexed_mesh m = index_mesh(mesh);
  const SI::Tangent_spaces ts = SI::compute_tangent_spaces(m);
  const SI::Connection con = SI::compute_connection(m, ts, n);
  const SI::Components comps = SI::split_into_components(m);
  for(double s : {-1., 0., 1.})
  {
    const SI::Energy_and_mass em = SI::assemble_energy_and_mass(m, ts, con, comps.list[0], comps.local_index, s);
    const std::size_t nv = m.number_of_vertices();
    // cotan Laplacian, and the boundary term of E_s, which on a plane is the
    // signed area form: -s Im(conj(w_k) w_j) per boundary edge j -> k
    // (checked against quadrature in check_local_matrices_by_quadrature).
    Eigen::MatrixXcd L = Eigen::MatrixXcd::Zero(nv, nv);
    for(std::size_t f = 0; f < m.number_of_faces(); ++f)
      for(int c = 0; c < 3; ++c)
      {
        const std::size_t j = m.faces[f][(c + 1) % 3], k = m.faces[f][(c + 2) % 3];
        const double w = 0.5 / std::tan(ts.corner_angle[3 * f + c]);  // cot(alpha_i) / 2
        L(j, j) += w; L(k, k) += w; L(j, k) -= w; L(k, j) -= w;
      }
    for(auto h : mesh.halfedges())
    {
      if(!mesh.is_border(mesh.opposite(h))) continue;  // h: interior side of a boundary edge, j -> k
      const std::size_t j = mesh.source(h), k = mesh.target(h);
      L(k, j) -= Complex(0., 0.5 * s);
      L(j, k) += Complex(0., 0.5 * s);
    }
    Eigen::VectorXcd phase(nv);
    for(std::size_t v = 0; v < nv; ++v)
    {
      const std::size_t corner = m.fan_corners[m.fan_offsets[v]];
      const SI::Vec3 e = SI::operator-(m.points[m.faces[corner / 3][(corner + 1) % 3]], m.points[v]);
      phase[v] = std::polar(1., n * std::atan2(e[1], e[0]));
    }
    const Eigen::MatrixXcd expected = phase.conjugate().asDiagonal() * L * phase.asDiagonal();
    // A is indexed by the component's local vertex order
    Eigen::MatrixXcd A(nv, nv);
    const Eigen::MatrixXcd local_A = Eigen::MatrixXcd(em.energy);
    for(std::size_t a = 0; a < nv; ++a)
      for(std::size_t b = 0; b < nv; ++b)
        A(a, b) = local_A(Eigen::Index(comps.local_index[a]), Eigen::Index(comps.local_index[b]));
    const double err = (A - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff();
    report.check(err < 1e-12, "planar A = P^* (cotan Laplacian + boundary term) P, n = " + std::to_string(n) +
                              ", s = " + std::to_string(s) + " (error " + std::to_string(err) + ")");
  }
}

// The local matrices against a direct quadrature of their defining integrals.
// On a triangle (i, j, k) = (0,0), (1,0), (0,1) in parameter space, with a
// connection of constant curvature, gauge A = -Omega (x dy - y dx): the section
// transported along rays from a vertex is, in this gauge, phi_i = c_i,
// phi_j = c_j exp(i Omega y), phi_k = c_k exp(-i Omega x), with constants fixed
// by the transports along the edges (phi_j(v_k) = r_jk phi_k(v_k), ...). Then
// psi_a = b_a phi_a, and
//   M(a, b) = int conj(psi_a) psi_b,
//   A_s(a, b) = int 2 (1 - s) conj(d psi_a) d psi_b + 2 (1 + s) conj(dbar psi_a) dbar psi_b,
// with d = (nabla_E1 - i nabla_E2) / 2, dbar = (nabla_E1 + i nabla_E2) / 2 in an
// orthonormal frame (E1, E2 = J E1). A_0 is the Dirichlet matrix.
static void check_local_matrices_by_quadrature(Test_report& report)
{
  const Complex I(0., 1.);
  // Gauss-Legendre nodes on [0, 1] (Golub-Welsch), Duffy map to the triangle.
  const int N = 40;
  std::vector<double> xs(N), ws(N);
  {
    Eigen::MatrixXd J = Eigen::MatrixXd::Zero(N, N);
    for(int k = 1; k < N; ++k) J(k, k - 1) = J(k - 1, k) = k / std::sqrt(4. * k * k - 1.);
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(J);
    for(int k = 0; k < N; ++k) { xs[k] = (es.eigenvalues()[k] + 1.) / 2.; ws[k] = es.eigenvectors()(0, k) * es.eigenvectors()(0, k); }
  }
  const std::vector<std::array<SI::Vec3, 3> > triangles = {
    {SI::Vec3{0, 0, 0}, SI::Vec3{1.3, 0.2, 0}, SI::Vec3{0.4, 1.1, 0}},
    {SI::Vec3{0.2, -0.1, 0}, SI::Vec3{2.0, 0.1, 0}, SI::Vec3{1.9, 0.3, 0}},   // obtuse sliver
    {SI::Vec3{0, 0, 0}, SI::Vec3{0.01, 0, 0}, SI::Vec3{0.004, 0.012, 0}}};   // small
  double worst = 0.;
  for(const auto& tri : triangles)
    for(double omega : {-5.9, -2.5, -0.7, 1e-9, 0.3, 1.9, 3.1, 6.2})
      for(double s : {-1., -0.3, 0., 1.})
      {
        // A one-face mesh with a synthetic connection of holonomy omega.
        SI::Indexed_mesh m;
        m.points = {tri[0], tri[1], tri[2]};
        m.faces = {{0, 1, 2}};
        SI::Tangent_spaces ts;
        SI::compute_corner_angles_and_areas(m, ts);
        SI::Connection con;
        const Complex rij = std::polar(1., 0.7), rjk = std::polar(1., -1.9);
        con.transport = {rij, rjk, std::exp(I * omega) / (rij * rjk)};
        con.holonomy = {omega};
        const SI::Local_matrices lm = SI::local_matrices(m, ts, con, 0, s);
        Eigen::Matrix3cd A_closed = Eigen::Matrix3cd::Zero(), M_closed = Eigen::Matrix3cd::Zero();
        for(int c = 0; c < 3; ++c)
        {
          const int j = (c + 1) % 3, k = (c + 2) % 3;
          A_closed(c, c) = lm.energy_diagonal[c]; M_closed(c, c) = lm.mass_diagonal[c];
          A_closed(k, j) = lm.energy_pair[c]; A_closed(j, k) = std::conj(lm.energy_pair[c]);
          M_closed(k, j) = lm.mass_pair[c]; M_closed(j, k) = std::conj(lm.mass_pair[c]);
        }

        const SI::Vec3 e1 = SI::operator-(tri[1], tri[0]), e2 = SI::operator-(tri[2], tri[0]);
        const double g11 = SI::dot(e1, e1), g12 = SI::dot(e1, e2), g22 = SI::dot(e2, e2);
        const double area = ts.face_area[0];
        const Complex cj = rjk * std::exp(-I * omega), ci = rij * cj, ck = 1.;
        Eigen::Matrix3cd A_quad = Eigen::Matrix3cd::Zero(), M_quad = Eigen::Matrix3cd::Zero();
        for(int a = 0; a < N; ++a)
          for(int b = 0; b < N; ++b)
          {
            const double x = xs[a], y = (1. - xs[a]) * xs[b], w = ws[a] * ws[b] * (1. - xs[a]) * 2. * area;
            const double bary[3] = {1. - x - y, x, y}, dbx[3] = {-1., 1., 0.}, dby[3] = {-1., 0., 1.};
            const Complex phi[3] = {ci, cj * std::exp(I * omega * y), ck * std::exp(-I * omega * x)};
            const Complex dphix[3] = {0., 0., -I * omega * phi[2]}, dphiy[3] = {0., I * omega * phi[1], 0.};
            const Complex Ax = omega * y, Ay = -omega * x;
            Complex psi[3], d[3], dbar[3];
            for(int q = 0; q < 3; ++q)
            {
              psi[q] = bary[q] * phi[q];
              const Complex nx = dbx[q] * phi[q] + bary[q] * dphix[q] + I * Ax * psi[q];
              const Complex ny = dby[q] * phi[q] + bary[q] * dphiy[q] + I * Ay * psi[q];
              const Complex n1 = nx / std::sqrt(g11), n2 = (g11 * ny - g12 * nx) / (2. * area * std::sqrt(g11));
              d[q] = 0.5 * (n1 - I * n2);
              dbar[q] = 0.5 * (n1 + I * n2);
            }
            for(int r = 0; r < 3; ++r)
              for(int c = 0; c < 3; ++c)
              {
                A_quad(r, c) += w * (2. * (1. - s) * std::conj(d[r]) * d[c] + 2. * (1. + s) * std::conj(dbar[r]) * dbar[c]);
                M_quad(r, c) += w * std::conj(psi[r]) * psi[c];
              }
          }
        worst = (std::max)(worst, (A_quad - A_closed).cwiseAbs().maxCoeff() / A_quad.cwiseAbs().maxCoeff());
        worst = (std::max)(worst, (M_quad - M_closed).cwiseAbs().maxCoeff() / M_quad.cwiseAbs().maxCoeff());
        (void)g22;
      }
  std::cout << "local matrices vs quadrature: worst relative difference " << worst << "\n";
  report.check(worst < 1e-11, "local mass and energy matrices equal the quadrature of their integrals");
}

// Positive semi-definiteness: A + delta M has a positive LDL^T diagonal for a
// shift delta = 1e-9 trace(A)/trace(M), far below the eigenvalues it must not hide.
static void check_hermitian_and_psd(Test_report& report, const std::string& name, const Mesh& mesh, int n)
{
  const SI::Indexed_mesh m = index_mesh(mesh);
  const SI::Tangent_spaces ts = SI::compute_tangent_spaces(m);
  const SI::Connection con = SI::compute_connection(m, ts, n);
  const SI::Components comps = SI::split_into_components(m);
  for(double s : {-1., 0., 1.})
  {
    bool hermitian = true, psd = true;
    for(const auto& comp : comps.list)
    {
      const SI::Energy_and_mass em = SI::assemble_energy_and_mass(m, ts, con, comp, comps.local_index, s);
      hermitian = hermitian && hermitian_defect(em.energy) < 1e-14 && hermitian_defect(em.mass) < 1e-14;
      const double sigma = em.energy.diagonal().real().sum() / em.mass.diagonal().real().sum();
      Eigen::SimplicialLDLT<SI::Complex_sparse_matrix> ldlt(em.energy + 1e-9 * sigma * em.mass);
      psd = psd && ldlt.info() == Eigen::Success && ldlt.vectorD().real().minCoeff() > 0.;
      Eigen::SimplicialLDLT<SI::Complex_sparse_matrix> mass_ldlt(em.mass);
      psd = psd && mass_ldlt.info() == Eigen::Success && mass_ldlt.vectorD().real().minCoeff() > 0.;
    }
    report.check(hermitian, name + ": A and M Hermitian, s = " + std::to_string(s));
    report.check(psd, name + ": A positive semi-definite and M positive definite, n = " + std::to_string(n) +
                      ", s = " + std::to_string(s));
  }
}

// lambda_1 R^2 = n (1 - s) on a round sphere; the discretization error on the
// 10242-vertex icosphere is about 1e-3 relative (measured: see the output).
static void check_sphere_eigenvalues(Test_report& report)
{
  const double R = 3.;
  Mesh mesh;
  make_icosphere(mesh, 5, R);
  auto dir = mesh.add_property_map<Mesh::Vertex_index, Kernel::Vector_3>("v:d").first;
  for(int n = 1; n <= 4; ++n)
    for(double s : {-1., -0.5, 0., 0.5, 1.})
    {
      const SMDF::Direction_field_result r = SMDF::compute_globally_optimal_directions(
        mesh, dir, CGAL::parameters::degree(n).smoothness_parameter(s).number_of_iterations(300));
      const double got = r.components[0].eigenvalue * R * R, expected = n * (1. - s);
      std::cout << "sphere n = " << n << " s = " << s << ": lambda R^2 = " << got << " (exact " << expected << ")\n";
      report.check(std::abs(got - expected) <= 1.5e-3 * n + 1e-3 * expected,
                   "sphere eigenvalue n (1 - s) / R^2 for n = " + std::to_string(n) + ", s = " + std::to_string(s));
    }
}

// The gathering assembly (column by column, sizes taken from the fans) equals a
// plain scatter of the local matrices, face by face, into triplets -- also on a
// mesh whose fans meet a neighbour through two different edges (a multiple
// edge: the assembly must detect it and count the column sizes).
static void check_assembly_against_scatter(Test_report& report, const std::string& name, const Mesh& mesh)
{
  const SI::Indexed_mesh m = index_mesh(mesh);
  const SI::Tangent_spaces ts = SI::compute_tangent_spaces(m, 1e-6);
  const SI::Connection con = SI::compute_connection(m, ts, 4);
  const SI::Components comps = SI::split_into_components(m);
  const double s = 0.3;
  const SI::Energy_and_mass em = SI::assemble_energy_and_mass(m, ts, con, comps.list[0], comps.local_index, s);
  std::vector<Eigen::Triplet<SI::Complex> > energy, mass;
  for(std::size_t f = 0; f < m.number_of_faces(); ++f)
  {
    const SI::Local_matrices lm = SI::local_matrices(m, ts, con, f, s);
    for(int c = 0; c < 3; ++c)
    {
      const auto i = static_cast<Eigen::Index>(comps.local_index[m.faces[f][c]]);
      const auto j = static_cast<Eigen::Index>(comps.local_index[m.faces[f][(c + 1) % 3]]);
      const auto k = static_cast<Eigen::Index>(comps.local_index[m.faces[f][(c + 2) % 3]]);
      energy.emplace_back(i, i, lm.energy_diagonal[c]);
      mass.emplace_back(i, i, lm.mass_diagonal[c]);
      energy.emplace_back(k, j, lm.energy_pair[c]);
      energy.emplace_back(j, k, std::conj(lm.energy_pair[c]));
      mass.emplace_back(k, j, lm.mass_pair[c]);
      mass.emplace_back(j, k, std::conj(lm.mass_pair[c]));
    }
  }
  const Eigen::Index n = em.energy.rows();
  SI::Complex_sparse_matrix A(n, n), M(n, n);
  A.setFromTriplets(energy.begin(), energy.end());
  M.setFromTriplets(mass.begin(), mass.end());
  report.check(em.energy.nonZeros() == A.nonZeros() && em.mass.nonZeros() == M.nonZeros(),
               name + ": the assembled pattern has the scattered number of entries");
  report.check(max_abs(em.energy - A) <= 1e-14 * max_abs(A) && max_abs(em.mass - M) <= 1e-14 * max_abs(M),
               name + ": gathered A and M equal the scattered ones");
  // products with M taken from the faces (what a single call uses once A and M are freed)
  const SI::Mass_operator mass_operator(m, ts, con);
  SI::Complex_vector x(n);
  for(Eigen::Index i = 0; i < n; ++i) x[i] = SI::Complex(std::cos(1.7 * i), std::sin(0.3 * i * i));
  const SI::Complex_vector Mx = M * x;
  report.check((mass_operator.times(comps.list[0], comps.local_index, x) - Mx).norm() <= 1e-14 * Mx.norm(),
               name + ": the mass operator from the faces equals M x");
  // the matrix a single aligned solve factors, assembled without A and M: the
  // lower triangle of A + shift M as from A and M, bit for bit, and the same
  // trace(A) / trace(M)
  const double shift = -0.37;
  std::vector<SI::Shifted_lower_triangle> direct;
  const std::vector<SI::Energy_and_mass> none =
    SI::assemble_energy_and_mass(m, ts, con, comps, s, std::vector<double>(comps.list.size(), shift), &direct);
  const SI::Complex_sparse_matrix expected = SI::shifted_lower_triangle(em.energy, em.mass, shift);
  const SI::Complex_sparse_matrix& got = direct[0].matrix;
  report.check(none[0].energy.rows() == 0 && got.rows() == n && got.nonZeros() == expected.nonZeros() &&
                 std::equal(got.outerIndexPtr(), got.outerIndexPtr() + n + 1, expected.outerIndexPtr()) &&
                 std::equal(got.innerIndexPtr(), got.innerIndexPtr() + got.nonZeros(), expected.innerIndexPtr()) &&
                 std::equal(got.valuePtr(), got.valuePtr() + got.nonZeros(), expected.valuePtr()),
               name + ": lower(A + shift M) assembled directly equals the one from A and M, bit for bit");
  report.check(direct[0].eigenvalue_scale == SI::eigenvalue_scale(em.energy, em.mass),
               name + ": the direct assembly's trace(A) / trace(M) is eigenvalue_scale(A, M)");
}

// Discrete Poincare-Hopf holds for any coefficients, also when some are
// exactly zero (a symmetric smoothest field can vanish at a vertex).
static void check_index_sum_with_zero_coefficients(Test_report& report, const Mesh& sphere)
{
  const SI::Indexed_mesh m = index_mesh(sphere);
  const SI::Tangent_spaces ts = SI::compute_tangent_spaces(m);
  for(int n : {1, 2, 4})
  {
    const SI::Connection con = SI::compute_connection(m, ts, n);
    const SI::Complex_vector x = SI::random_start_vector(static_cast<Eigen::Index>(m.number_of_vertices()), 7);
    std::vector<SI::Complex> u(x.data(), x.data() + x.size());
    int zeros = 0;
    for(std::size_t v = 0; v < u.size(); v += 3, ++zeros) u[v] = SI::Complex(0., 0.);
    const std::vector<int> index = SI::face_indices(m, con, u);
    int sum = 0;
    for(int i : index) sum += i;
    report.check(sum == 2 * n, "index sum n chi with " + std::to_string(zeros) + " zero coefficients, n = " +
                                 std::to_string(n) + " (got " + std::to_string(sum) + ")");
  }
}

// The angle reduction of the index computation: odd bit for bit (so the
// rotations of the two sides of an edge cancel exactly), congruent to its
// argument modulo 2 pi, and in [-pi, pi] up to rounding, also next to the
// half turns and for large arguments.
static void check_angle_reduction(Test_report& report)
{
  const double pi = CGAL_PI, two_pi = 2. * CGAL_PI;
  std::vector<double> xs = {0., 1e-300, 0.5, pi, 3. * pi, 5. * pi, 1e3, 1e20, 1e300};
  for(double x : {pi, 3. * pi})
    for(double y = x, below = x; below > x - 1e-13; below = std::nextafter(below, 0.), y = std::nextafter(y, 10.))
    {
      xs.push_back(below);
      xs.push_back(y);
    }
  const SI::Complex_vector r = SI::random_start_vector(1000, 3);
  for(Eigen::Index i = 0; i < r.size(); ++i) xs.push_back(4. * pi * r[i].real());
  bool odd = true, congruent = true, in_range = true;
  for(double x : xs)
  {
    const double y = SI::reduce_angle(x), z = SI::reduce_angle(-x), minus_y = -y;
    odd = odd && std::memcmp(&z, &minus_y, sizeof(double)) == 0;
    const double turns = (x - y) / two_pi;  // an integer
    congruent = congruent && std::abs(turns - std::round(turns)) <= 1e-15 * (1. + std::abs(turns)) + 1e-12;
    in_range = in_range && std::abs(y) <= pi * (1. + 1e-15);
  }
  report.check(odd, "angle reduction is odd bit for bit (" + std::to_string(xs.size()) + " angles)");
  report.check(congruent && in_range, "angle reduction is congruent modulo 2 pi and lies in [-pi, pi]");
}

// The matrices handed to the solver: A + shift M with both triangles, and its
// lower triangle alone for the Cholesky solvers, which read nothing else; the
// same values, bit for bit, as Eigen's own sum (also when the patterns differ).
static void check_shifted_matrices(Test_report& report, const std::string& name, const SI::Complex_sparse_matrix& A,
                                   const SI::Complex_sparse_matrix& M)
{
  const double shift = -0.37 * A.diagonal().real().sum() / M.diagonal().real().sum();
  auto same = [](const SI::Complex_sparse_matrix& X, const SI::Complex_sparse_matrix& Y) {
    if(X.rows() != Y.rows() || X.cols() != Y.cols() || X.nonZeros() != Y.nonZeros()) return false;
    for(Eigen::Index j = 0; j < X.outerSize(); ++j)
    {
      SI::Complex_sparse_matrix::InnerIterator x(X, j), y(Y, j);
      for(; x && y; ++x, ++y)
        if(x.row() != y.row() || x.value() != y.value()) return false;
      if(x || y) return false;
    }
    return true;
  };
  const SI::Complex_sparse_matrix sum = A + shift * M;
  const SI::Complex_sparse_matrix lower = sum.triangularView<Eigen::Lower>();
  report.check(same(SI::shifted_matrix(A, M, shift), sum) && same(SI::shifted_lower_triangle(A, M, shift), lower),
               name + ": A + shift M and its lower triangle, as Eigen computes them");
  // a mass matrix with another pattern (its diagonal): Eigen's general sum
  const SI::Complex_sparse_matrix D = SI::Complex_sparse_matrix(M.diagonal().asDiagonal());
  const SI::Complex_sparse_matrix sum_d = A + shift * D;
  report.check(!SI::have_same_pattern(A, D) && same(SI::shifted_matrix(A, D, shift), sum_d) &&
                 same(SI::shifted_lower_triangle(A, D, shift), SI::Complex_sparse_matrix(sum_d.triangularView<Eigen::Lower>())),
               name + ": the same with a mass matrix of another pattern");
}

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
  options.shift_fraction = in_double.eigenvalue * (1. - 1e-9) / shifted.coarse_upper_bound;
  Solver close_solver;
  SI::Factored_matrix<Solver> close_factored(close_solver);
  const SI::Eigen_solve_result close = SI::smallest_eigenpair(A, M, close_factored, options);
  std::cout << name << ": shift at (1 - 1e-9) lambda_1: single " << close.single_precision << ", refactored "
            << close.refactored_in_double << ", solves " << close.iterations << "\n";
  report.check(same_eigenpair(close), name + ": a shift at (1 - 1e-9) lambda_1 still gives the eigenpair");

  // a stall declared after every solve that does not gain a factor 10: the
  // factor is replaced by a double-precision one, and the iteration goes on
  options.shift_fraction = shifted.shift / -shifted.coarse_upper_bound;
  options.stall_window = 1;
  options.max_reshifts = 0;
  Solver stalled_solver;
  SI::Factored_matrix<Solver> stalled_factored(stalled_solver);
  const SI::Eigen_solve_result stalled = SI::smallest_eigenpair(A, M, stalled_factored, options);
  report.check(stalled.single_precision && stalled.refactored_in_double && !stalled_factored.holds_single_precision() &&
                 stalled.shift == shifted.shift && same_eigenpair(stalled),
               name + ": after a stall, the same shifted matrix is factored in double precision and the eigenpair found");
  // with re-shifts: each stall moves the shift towards the best Ritz value, in double precision, and stays
  // below lambda_1 (else the factorization refuses it and the old shift is factored again)
  options.max_reshifts = 4;
  Solver reshifted_solver;
  SI::Factored_matrix<Solver> reshifted_factored(reshifted_solver);
  const SI::Eigen_solve_result reshifted = SI::smallest_eigenpair(A, M, reshifted_factored, options);
  report.check(reshifted.refactored_in_double && !reshifted_factored.holds_single_precision() &&
                 reshifted.shift <= shifted.shift && -reshifted.shift < in_double.eigenvalue &&
                 same_eigenpair(reshifted),
               name + ": after stalls the shift moves towards lambda_1 (" + std::to_string(-shifted.shift) + " -> " +
                 std::to_string(-reshifted.shift) + ", lambda_1 " + std::to_string(in_double.eigenvalue) +
                 ") and the eigenpair is found");
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
  Solver reference_solver;
  SI::Factored_matrix<Solver> reference_factored(reference_solver);
  const SI::Eigen_solve_result reference = SI::smallest_eigenpair(A, M, reference_factored, plain);
  report.check(reference.converged && std::isnan(reference.coarse_upper_bound) && reference.shift > 0.,
               name + ": without the coarse estimate, A + epsilon M is factored");

  auto same_eigenpair = [&](const SI::Eigen_solve_result& r) {
    const double overlap = std::abs(reference.vector.dot(M * r.vector));  // both M-normalized
    return r.converged && std::abs(r.eigenvalue - reference.eigenvalue) <= 1e-8 * reference.eigenvalue &&
           overlap >= 1. - 1e-8;
  };
  SI::Eigen_solve_options options;
  options.shift_fraction = SI::shift_fraction_for(s);
  Solver solver;
  SI::Factored_matrix<Solver> factored(solver);
  const SI::Eigen_solve_result shifted = SI::smallest_eigenpair(A, M, factored, options);
  std::cout << name << ": lambda_1 = " << reference.eigenvalue << ", bound " << shifted.coarse_upper_bound << " ("
            << shifted.coarse_upper_bound / reference.eigenvalue << " lambda_1), solves " << reference.iterations
            << " -> " << shifted.iterations << " (+ " << shifted.coarse_iterations << " coarse)\n";
  report.check(shifted.coarse_upper_bound >= reference.eigenvalue * (1. - 1e-12),
               name + ": the coarse estimate bounds lambda_1 from above");
  report.check(!shifted.shift_rejected && shifted.shift == -options.shift_fraction * shifted.coarse_upper_bound,
               name + ": A - 0.6 (1 - |s|) R M is factored");
  report.check(same_eigenpair(shifted), name + ": the shifted solve gives the eigenpair of the plain one");
  report.check(shifted.iterations < reference.iterations, name + ": and needs fewer solves");
  check_single_precision_eigen_solve<Solver>(report, name, A, M, options, shifted, same_eigenpair);

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

// The one process-wide setting the factorization makes (dense_kernels.h):
// OpenBLAS on one thread while the subtrees are factored. Outside the
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
  openblas_set_num_threads(original);
  report.check(by_package && both && after_one == 3 && after_two == 3,
               "OpenBLAS's number of threads (3) is given back after one factorization (" + std::to_string(after_one) +
                 ") and after two concurrent ones (" + std::to_string(after_two) + ")");
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

int main()
{
  Test_report report("matrices");
  check_huge_page_advice(report);
  check_components(report);

  {
    Mesh lumpy;
    make_lumpy_sphere(lumpy, 5);
    typedef CGAL::Eigen_solver_traits<Eigen::SimplicialLDLT<SI::Complex_sparse_matrix> > Ldlt;
    report.check(SI::Factored_matrix<Ldlt>::detects_indefinite, "Eigen's LDLT detects indefinite matrices");
    report.check(SI::Reads_lower_triangle<Eigen::SimplicialLDLT<SI::Complex_sparse_matrix> >::value &&
                   !SI::Reads_lower_triangle<Eigen::SimplicialLDLT<SI::Complex_sparse_matrix, Eigen::Upper> >::value &&
                   !SI::Reads_lower_triangle<Eigen::SparseLU<SI::Complex_sparse_matrix> >::value,
                 "only the solvers reading the lower triangle are given the lower triangle");
    check_shifted_eigen_solve<Ldlt>(report, "lumpy sphere, LDLT", lumpy, 4, 0.);
    check_shifted_eigen_solve<Ldlt>(report, "lumpy sphere, LDLT", lumpy, 1, 0.5);
#ifdef CGAL_SURFACE_MESH_DIRECTION_FIELDS_USE_CHOLMOD
    typedef CGAL::Eigen_solver_traits<Eigen::CholmodSupernodalLLT<SI::Complex_sparse_matrix> > Eigen_cholmod;
    report.check(SI::Factored_matrix<Eigen_cholmod>::detects_indefinite &&
                   SI::Factored_matrix<Eigen_cholmod>::factors_lower_triangle,
                 "Eigen's CHOLMOD LLT detects indefinite matrices and reads the lower triangle");
    check_shifted_eigen_solve<Eigen_cholmod>(report, "lumpy sphere, Eigen's CHOLMOD", lumpy, 4, 0.);
    typedef SMDF::Cholmod_supernodal_solver Cholmod;
    check_shifted_eigen_solve<Cholmod>(report, "lumpy sphere, CHOLMOD", lumpy, 4, 0.);
    check_shifted_eigen_solve<Cholmod>(report, "lumpy sphere, CHOLMOD", lumpy, 2, -0.5);
    check_parallel_supernodal_solve(report, 3);
    {
      // two one-column supernodes, the second with a row in the first: not a
      // postordered elimination tree, so no plan (CHOLMOD's solve is used)
      const int super[] = {0, 1, 2}, row_start[] = {0, 1, 3}, rows[] = {0, 1, 0}, value_start[] = {0, 1, 3};
      const Complex values[] = {1., 1., 0.5};
      SI::Supernodal_factor_view<int> view;
      view.n = 2;
      view.supernodes = 2;
      view.super = super;
      view.row_start = row_start;
      view.rows = rows;
      view.value_start = value_start;
      view.values = values;
      report.check(!SI::Supernodal_solve_plan(view).valid(), "parallel supernodal solve: a tree not in postorder is refused");
    }
    check_parallel_supernodal_solve(report, 200);
    check_cholmod_solver_concept(report);
    check_blas_threads_restored(report);
    check_parallel_factorization(report, 3);
    check_parallel_factorization(report, 40);
    check_parallel_factorization(report, 200);
    check_single_precision_factorization(report, 200);
#endif
  }

  {
    // the 32-bit indices of the indexed mesh read back as std::size_t, the sentinel included
    auto round_trip = [](std::size_t i) { return static_cast<std::size_t>(SI::Compact_index(i)) == i; };
    report.check(sizeof(SI::Compact_index) == 4 && round_trip(0) && round_trip(123456789) &&
                   round_trip(SI::Compact_index::largest) && round_trip(SI::no_index),
                 "compact indices: 4 bytes, 0, 123456789, the largest index and no_index read back unchanged");
  }

  {
    // the parallel basis products of the eigen-solve against Eigen's own, on
    // a row count that is not a multiple of the chunk size
    const Eigen::Index rows = 3 * static_cast<Eigen::Index>(SI::parallel_grain_size) + 17;
    const SI::Complex_dense_matrix V = SI::Complex_dense_matrix::Random(rows, 7),
                                   X = SI::Complex_dense_matrix::Random(rows, 2),
                                   Y = SI::Complex_dense_matrix::Random(rows, 1),
                                   C = SI::Complex_dense_matrix::Random(7, 3);
    SI::Complex_dense_matrix VX, VY, VC, W = X.leftCols(1);
    SI::adjoint_products(V, X, Y, VX, VY);
    SI::combine_columns(V, C, VC);
    SI::combine_columns(V.leftCols(2), C.topLeftCorner(2, 1), W, true);
    const SI::Complex_dense_matrix VX_ref = V.adjoint() * X, VY_ref = V.adjoint() * Y, VC_ref = V * C;
    const SI::Complex_dense_matrix W_ref = X.leftCols(1) - V.leftCols(2) * C.topLeftCorner(2, 1);
    report.check((VX - VX_ref).norm() <= 1e-13 * VX_ref.norm() && (VY - VY_ref).norm() <= 1e-13 * VY_ref.norm() &&
                   (VC - VC_ref).norm() <= 1e-14 * VC_ref.norm() && (W - W_ref).norm() <= 1e-14 * W_ref.norm() &&
                   SI::adjoint_product(V, X) == VX,
                 "basis products V^* X, V^* Y, V C and W - V C equal Eigen's");

    // the weighted products of the orthonormalization, and the orthonormalization
    // itself for one column (in place, in parallel) and for two (column by column)
    const Eigen::VectorXd d = Eigen::VectorXd::Random(rows).cwiseAbs() + Eigen::VectorXd::Constant(rows, 0.1);
    const SI::Complex_dense_matrix VDX_ref = V.adjoint() * d.asDiagonal() * X;
    Eigen::VectorXd norms_ref(2);
    for(Eigen::Index j = 0; j < 2; ++j) norms_ref[j] = std::sqrt(X.col(j).cwiseAbs2().dot(d));
    report.check((SI::weighted_adjoint_product(V, d, X) - VDX_ref).norm() <= 1e-13 * VDX_ref.norm() &&
                   (SI::weighted_column_norms(d, X) - norms_ref).norm() <= 1e-14 * norms_ref.norm(),
                 "weighted basis products V^* diag(d) X and column norms equal Eigen's");
    SI::Complex_dense_matrix B = SI::Complex_dense_matrix::Random(rows, 3);  // a d-orthonormal basis
    B.col(0) /= std::sqrt(B.col(0).cwiseAbs2().dot(d));
    for(Eigen::Index j = 1; j < 3; ++j)
    {
      for(int pass = 0; pass < 2; ++pass)
        B.col(j) -= B.leftCols(j) * (B.leftCols(j).adjoint() * d.asDiagonal() * B.col(j));
      B.col(j) /= std::sqrt(B.col(j).cwiseAbs2().dot(d));
    }
    for(Eigen::Index columns : {1, 2})
    {
      const SI::Complex_dense_matrix Q = SI::d_orthonormalize(d, B, X.leftCols(columns));
      const SI::Complex_dense_matrix gram = Q.adjoint() * d.asDiagonal() * Q, against = B.adjoint() * d.asDiagonal() * Q;
      const SI::Complex_dense_matrix span_error =  // X's columns lie in span(B, Q)
        X.leftCols(columns) - B * (B.adjoint() * d.asDiagonal() * X.leftCols(columns)) -
        Q * (Q.adjoint() * d.asDiagonal() * X.leftCols(columns));
      report.check(Q.cols() == columns &&
                     (gram - SI::Complex_dense_matrix::Identity(columns, columns)).norm() <= 1e-13 &&
                     against.norm() <= 1e-13 && span_error.norm() <= 1e-12 * X.leftCols(columns).norm(),
                   "d-orthonormalization of " + std::to_string(columns) +
                     " column(s) against a basis: orthonormal, orthogonal to it, same span");
    }
    report.check(SI::d_orthonormalize(d, B, B.col(1)).cols() == 0,
                 "d-orthonormalization drops a column inside the span of the basis");
  }

  Mesh sphere, torus, disk;
  make_icosphere(sphere, 3);
  make_torus(torus, 2., 0.7, 40, 20);
  make_disk(disk, 6);
  for(int n : {1, 2, 4, 7})
  {
    check_connection(report, "icosphere", sphere, n);
    check_connection(report, "torus", torus, n);
    check_connection(report, "disk", disk, n);
  }
  check_local_matrices_by_quadrature(report);
  check_index_sum_with_zero_coefficients(report, sphere);
  check_angle_reduction(report);
  {
    // A coarse torus with one edge collapsed across its 3 rings: the merged
    // vertex reaches a neighbour through two different edges.
    Mesh multiple;
    make_torus(multiple, 2., 0.7, 6, 3);
    CGAL::Euler::collapse_edge(multiple.edge(multiple.halfedge(Mesh::Vertex_index(0), Mesh::Vertex_index(1))), multiple);
    multiple.collect_garbage();
    report.check(CGAL::is_valid_polygon_mesh(multiple) && multiple.number_of_faces() == 34,
                 "the collapsed torus is a valid mesh of 34 faces");
    check_assembly_against_scatter(report, "torus with a multiple edge", multiple);
    check_assembly_against_scatter(report, "torus 40 x 20", torus);
    check_assembly_against_scatter(report, "disk", disk);
  }
  for(int n : {1, 3, 4})
    check_planar_cotan_laplacian(report, n);

  // Scaling the mesh by c leaves A unchanged and multiplies M by c^2.
  {
    Mesh big = torus;
    for(auto v : big.vertices()) big.point(v) = CGAL::ORIGIN + 1e3 * (big.point(v) - CGAL::ORIGIN);
    const SI::Indexed_mesh m1 = index_mesh(torus), m2 = index_mesh(big);
    const SI::Tangent_spaces t1 = SI::compute_tangent_spaces(m1), t2 = SI::compute_tangent_spaces(m2);
    const SI::Connection c1 = SI::compute_connection(m1, t1, 4), c2 = SI::compute_connection(m2, t2, 4);
    const SI::Components k1 = SI::split_into_components(m1), k2 = SI::split_into_components(m2);
    const SI::Energy_and_mass e1 = SI::assemble_energy_and_mass(m1, t1, c1, k1.list[0], k1.local_index, 0.5);
    const SI::Energy_and_mass e2 = SI::assemble_energy_and_mass(m2, t2, c2, k2.list[0], k2.local_index, 0.5);
    report.check(max_abs(e1.energy - e2.energy) < 1e-10 * max_abs(e1.energy), "A is scale invariant");
    report.check(max_abs(1e6 * e1.mass - e2.mass) < 1e-10 * max_abs(e2.mass), "M scales with the area");
  }

  for(const char* const* name = closed_shared_meshes(); *name; ++name)
  {
    const std::string path = shared_mesh_path(*name);
    if(path.empty()) continue;
    Mesh mesh;
    if(!report.check(CGAL::IO::read_polygon_mesh(path, mesh), std::string("read ") + *name)) continue;
    check_connection(report, *name, mesh, 4);
    if(mesh.number_of_vertices() <= 60000)
      for(int n : {1, 4})
        check_hermitian_and_psd(report, *name, mesh, n);
  }
  for(const char* const* name = open_shared_meshes(); *name; ++name)
  {
    const std::string path = shared_mesh_path(*name);
    if(path.empty()) continue;
    Mesh mesh;
    if(!report.check(CGAL::IO::read_polygon_mesh(path, mesh), std::string("read ") + *name)) continue;
    check_connection(report, *name, mesh, 4);
    for(int n : {1, 4})
      check_hermitian_and_psd(report, *name, mesh, n);
  }
  check_hermitian_and_psd(report, "disk", disk, 2);

  check_sphere_eigenvalues(report);
  return report.finish();
}
