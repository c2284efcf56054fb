// Part of test_matrices.cpp (one program, one compilation of the package):
// The method's matrices: connection, local matrices, A and M, their assembly, the indices and the shifted matrices.
#ifndef SURFACE_MESH_DIRECTION_FIELDS_TEST_MATRICES_METHOD_H
#define SURFACE_MESH_DIRECTION_FIELDS_TEST_MATRICES_METHOD_H

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
    auto corner_of = [&](Mesh::Halfedge_index g) {  // the corner whose first side is g
      const std::size_t f = std::size_t(mesh.face(g));
      std::size_t c = 0;
      while(std::size_t(m.faces[f][c]) != std::size_t(mesh.source(g))) ++c;
      return 3 * f + c;
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
      const double got = r.components[0].eigenvalue.value() * R * R, expected = n * (1. - s);
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
    SI::assemble_energy_and_mass(m, ts, con, comps, s, std::vector<std::optional<double> >(comps.list.size(), shift),
                                 &direct);
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

#endif // SURFACE_MESH_DIRECTION_FIELDS_TEST_MATRICES_METHOD_H
