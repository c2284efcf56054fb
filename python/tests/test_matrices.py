"""The energy and mass matrices as scipy.sparse (DirectionField.matrices()) and the coefficients they act on
(Result.coefficients): the smoothest field is their eigenvector, scipy's own eigen-solver finds the same
eigenvalue, the units and the convention of the coefficients are the manual's."""
import numpy as np
import pytest

import surface_mesh_direction_fields as smdf
from shapes import sphere, torus

scipy_sparse = pytest.importorskip("scipy.sparse")
scipy_linalg = pytest.importorskip("scipy.sparse.linalg")


def bumpy_sphere():
    V, F = sphere(3)
    return V * (1 + 0.15 * np.sin(3 * V[:, :1] + 2 * V[:, 1:2]) * np.cos(V[:, 2:3])), F


def plane(k=8):
    """A flat square of k x k cells, two triangles each, slightly sheared: interior angle sums are 2 pi."""
    V = np.array([[i + 0.3 * j, j, 0.0] for j in range(k + 1) for i in range(k + 1)], dtype=np.float64)
    F = []
    for j in range(k):
        for i in range(k):
            a, b, c, d = j * (k + 1) + i, j * (k + 1) + i + 1, (j + 1) * (k + 1) + i + 1, (j + 1) * (k + 1) + i
            F += [(a, b, c), (a, c, d)]
    return V, np.array(F)


def relative(x, y):
    return np.linalg.norm(x - y) / max(np.linalg.norm(y), 1e-300)


@pytest.mark.parametrize("degree,s", [(1, 0.0), (4, 0.0), (4, 0.5), (6, -1.0)])
def test_the_smoothest_field_is_the_eigenvector_of_the_matrices(degree, s):
    V, F = bumpy_sphere()
    field = smdf.DirectionField(V, F)
    r = field.compute(degree=degree, s=s)
    A, M = field.matrices(degree=degree, s=s)
    assert isinstance(A, scipy_sparse.csr_matrix) and A.shape == (len(V), len(V)) and A.dtype == np.complex128
    for X in (A, M):
        assert abs(X - X.getH()).max() <= 1e-15 * abs(X).max()
    u = r.coefficients
    assert u.dtype == np.complex128 and np.allclose(np.abs(u), r.magnitudes, rtol=1e-14, atol=0)
    lam = r.eigenvalues[0]
    assert relative(A @ u, lam * (M @ u)) < 1e-7
    rayleigh = np.vdot(u, A @ u).real / np.vdot(u, M @ u).real
    assert abs(rayleigh - lam) <= 1e-9 * abs(lam)
    # scipy's shift-invert Lanczos on the same pair: the same smallest eigenvalue
    smallest = scipy_linalg.eigsh(A.tocsc(), k=1, M=M.tocsc(), sigma=-0.01 * lam, which="LM",
                                  return_eigenvectors=False)[0]
    assert abs(smallest - lam) <= 1e-8 * abs(lam)


def test_units_the_mass_scales_with_area_the_energy_not():
    V, F = torus()
    A1, M1 = smdf.DirectionField(V, F).matrices(degree=4)
    A2, M2 = smdf.DirectionField(1000.0 * V, F).matrices(degree=4)
    assert relative(A2.toarray(), A1.toarray()) < 1e-12
    assert relative(M2.toarray(), 1e6 * M1.toarray()) < 1e-12
    # M is the mass: 1^H M 1 is the area at n = 0's limit, here its quadratic form is positive
    x = np.exp(1j * np.arange(len(V)))
    assert np.vdot(x, M1 @ x).real > 0 and np.vdot(x, A1 @ x).real > 0


def test_components_and_isolated_vertices():
    V1, F1 = sphere(2)
    V2, F2 = torus(12, 6)
    V = np.vstack([V1, V2 + 5.0, [[9.0, 9.0, 9.0]]])  # the last vertex is in no face
    F = np.vstack([F1, F2 + len(V1)])
    field = smdf.DirectionField(V, F)
    r = field.compute(degree=4)
    A, M = field.matrices(degree=4)
    first, second = np.arange(len(V1)), np.arange(len(V1), len(V1) + len(V2))
    assert abs(A[first][:, second]).sum() == 0 and abs(M[first][:, second]).sum() == 0
    isolated = len(V) - 1
    assert A[isolated].nnz == 0 and M[isolated].nnz == 0 and r.coefficients[isolated] == 0
    for part, lam in zip((first, second), r.eigenvalues):
        u = r.coefficients[part]
        Ap, Mp = A[part][:, part], M[part][:, part]
        assert relative(Ap @ u, lam * (Mp @ u)) < 1e-7


def test_coefficients_follow_the_directions_on_a_flat_patch():
    V, F = plane()
    degree = 3
    r = smdf.compute_globally_optimal_directions(V, F, degree=degree, align=None,
                                                 guidance=np.tile([1.0, 0.4, 0.0], (len(V), 1)))
    k = 9
    interior = [j * k + i for j in range(1, k - 1) for i in range(1, k - 1)]
    e1, e2 = r.tangent_frames[interior, 0], r.tangent_frames[interior, 1]
    angle = np.angle(r.coefficients[interior]) / degree  # in (-pi/n, pi/n]: the first direction lies in [0, 2pi/n)
    angle = np.where(angle < 0, angle + 2 * np.pi / degree, angle)
    expected = np.cos(angle)[:, None] * e1 + np.sin(angle)[:, None] * e2
    assert np.abs(expected - r.directions[interior]).max() < 1e-12


def test_prescribed_fields_have_unit_coefficients_and_the_matrices_refuse_bad_values():
    V, F = sphere(2)
    field = smdf.DirectionField(V, F)
    r = field.compute(degree=4, prescribed=[[f, 1] for f in range(0, len(F), len(F) // 8)])  # one per octant
    assert np.allclose(np.abs(r.coefficients), 1.0, rtol=0, atol=1e-14)
    for bad in ({"degree": 0}, {"s": 2.0}, {"intrinsic_mollification": -1.0}):
        with pytest.raises(ValueError):
            field.matrices(**bad)
    with pytest.raises(ValueError, match=r"\bs\b"):
        field.matrices(s=float("nan"))
