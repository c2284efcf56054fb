"""Fields on point sets from Python (user manual, "Point Sets"): Poincare-Hopf on
a sampled sphere, the mesh's field from the mesh's own vertices, the program's
digits, rigid motions, and the refusals."""
import copy
import json
import math
import pickle
import subprocess

import numpy as np
import pytest

import surface_mesh_direction_fields as smdf

from shapes import sphere


def fibonacci_sphere(n):
    i = np.arange(n)
    z = 1 - (2 * i + 1) / n
    r = np.sqrt(1 - z * z)
    phi = math.pi * (3 - math.sqrt(5)) * i
    return np.column_stack([r * np.cos(phi), r * np.sin(phi), z])


def test_sphere_index_sum_and_arrays():
    P = fibonacci_sphere(1500)
    for n in (1, 4):
        f = smdf.compute_point_set_directions(P, normals=P, degree=n)
        assert f.surface_is_closed and f.surface_euler_characteristic == 2
        assert f.index_sum == 2 * n and int(f.singular_triangles[:, 1].sum()) == 2 * n
        assert f.directions.shape == (1500, 3) and f.triangles.shape[1] == 3
        assert np.allclose(np.linalg.norm(f.directions, axis=1), 1.0)
        assert np.abs(np.sum(f.directions * P, axis=1)).max() < 1e-12  # orthogonal to the given normals
        assert f.on_surface.dtype == np.bool_ and f.on_surface[f.singular_triangles[:, 0]].all()
        assert not f.normals_estimated and f.points_without_triangles == 0 and f.converged
        assert abs(f.eigenvalues[0] - n) < 0.05 * n
        with pytest.raises(ValueError):
            f.directions[0, 0] = 1.0  # read-only


def test_pickle_and_copy_keep_everything():
    f = smdf.compute_point_set_directions(fibonacci_sphere(600), degree=4)
    for g in (pickle.loads(pickle.dumps(f)), copy.deepcopy(f)):
        for name in ("directions", "normals", "magnitudes", "triangles", "holders", "on_surface", "singular_triangles"):
            assert np.array_equal(getattr(g, name), getattr(f, name)) and not getattr(g, name).flags.writeable
        assert (g.degree, g.index_sum, g.surface_euler_characteristic, g.surface_is_closed, g.normals_estimated,
                g.points_without_triangles, g.eigenvalues, g.converged) == \
            (f.degree, f.index_sum, f.surface_euler_characteristic, f.surface_is_closed, f.normals_estimated,
             f.points_without_triangles, f.eigenvalues, f.converged)
    state = list(f.__getstate__())
    state[6] = np.array([[len(f.triangles) + 5, 1]])  # a singular triangle that is not one
    with pytest.raises(ValueError, match="singular_triangles"):
        smdf.PointSetField.__new__(smdf.PointSetField).__setstate__(tuple(state))
    state = list(f.__getstate__())
    state[4] = state[4][:-1]  # holders: one fewer than the triangles
    with pytest.raises(ValueError, match="holders"):
        smdf.PointSetField.__new__(smdf.PointSetField).__setstate__(tuple(state))


def test_estimated_normals_and_rigid_motion():
    P = fibonacci_sphere(1200)
    f = smdf.compute_point_set_directions(P)
    assert f.normals_estimated and f.index_sum == 8
    assert np.abs(np.abs(np.sum(f.normals * P, axis=1)) - 1).max() < 1e-3
    c, s = math.cos(0.4), math.sin(0.4)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    g = smdf.compute_point_set_directions(1e6 * P @ R.T + [1, 2, 3], normals=P @ R.T)
    h = smdf.compute_point_set_directions(P, normals=P)
    assert np.abs(h.directions @ R.T - g.directions).max() < 1e-4
    assert np.array_equal(h.singular_triangles, g.singular_triangles)


def test_mesh_vertices_give_the_mesh_field():
    V, F = sphere(4)
    V = V * (1 + 0.2 * np.sin(3 * V[:, :1] + 0.4) * np.cos(2 * V[:, 1:2] + V[:, 2:3]))  # no symmetry
    mesh = smdf.compute_globally_optimal_directions(V, F)
    cloud = smdf.compute_point_set_directions(V)
    assert abs(cloud.eigenvalues[0] - mesh.eigenvalues[0]) < 0.05 * mesh.eigenvalues[0]
    assert cloud.index_sum == 8
    N = cloud.normals
    a = mesh.directions - np.sum(mesh.directions * N, axis=1, keepdims=True) * N
    turn = 4 * np.arctan2(np.sum(np.cross(a, cloud.directions) * N, axis=1), np.sum(a * cloud.directions, axis=1))
    off = np.abs(np.angle(np.exp(1j * turn) / np.sum(np.exp(1j * turn)))) / 4  # up to one global turn
    assert np.mean(off < math.radians(5)) > 0.95


def test_same_digits_as_the_program(program, tmp_path):
    P = fibonacci_sphere(800)
    np.savetxt(tmp_path / "s.xyz", P, fmt="%.17g")
    subprocess.run([program, str(tmp_path / "s.xyz"), "--directions", str(tmp_path / "d.txt"), "--json-file",
                    str(tmp_path / "s.json"), "--quiet"], check=True, stdout=subprocess.DEVNULL)
    f = smdf.compute_point_set_directions(np.loadtxt(tmp_path / "s.xyz"))
    assert np.array_equal(np.loadtxt(tmp_path / "d.txt"), f.directions)
    assert json.load(open(tmp_path / "s.json"))["index_sum"] == f.index_sum


def test_refusals():
    P = fibonacci_sphere(100)
    with pytest.raises(ValueError, match="3 points"):
        smdf.compute_point_set_directions(P[:2])
    with pytest.raises(ValueError, match="no triangle"):
        smdf.compute_point_set_directions(np.column_stack([np.arange(10.0), 2 * np.arange(10.0), np.zeros(10)]))
    bad = P.copy()
    bad[5, 1] = np.nan
    with pytest.raises(ValueError, match="not finite"):
        smdf.compute_point_set_directions(bad)
    with pytest.raises(ValueError, match="number_of_neighbors"):
        smdf.compute_point_set_directions(P, neighbors=2)
    with pytest.raises(ValueError, match="shape"):
        smdf.compute_point_set_directions(P, normals=P[:10])
    with pytest.raises(TypeError, match="unexpected keyword"):
        smdf.compute_point_set_directions(P, neighbours=8)
    with pytest.raises(ValueError):
        smdf.compute_point_set_directions(P[:, :2])


def test_curvature_alignment_on_a_torus():
    """align= follows the principal curvatures fitted on the points: the maximum curvature of a torus
    (R = 2, r = 1) runs along its meridians, with normals given or estimated; odd degrees are refused."""
    rng = np.random.default_rng(5)
    u, v = rng.uniform(0, 2 * math.pi, (2, 3000))
    N = np.column_stack([np.cos(u) * np.cos(v), np.sin(u) * np.cos(v), np.sin(v)])
    P = np.column_stack([2 * np.cos(u), 2 * np.sin(u), np.zeros(3000)]) + N
    meridian = np.cross(N, np.column_stack([-np.sin(u), np.cos(u), np.zeros(3000)]))
    for normals in (N, None):
        f = smdf.compute_point_set_directions(P, normals=normals, degree=2, align="max-curvature",
                                              alignment_weight=0.99, eigenvalue_bound=True)
        assert abs(f.alignment_weights[0] - 0.99) < 1e-3 and f.eigenvalues[0] > 0
        assert (np.abs((f.directions * meridian).sum(axis=1)) > math.cos(math.radians(3))).mean() >= 0.99
    with pytest.raises(ValueError, match="even degree"):
        smdf.compute_point_set_directions(P, degree=3, align="curvature")
    with pytest.raises(ValueError, match="align"):
        smdf.compute_point_set_directions(P, align="sideways")


def test_constraints_on_points():
    """constraints=(ids, directions) fixes those points' directions exactly (hard constraints, as on a mesh)."""
    P = fibonacci_sphere(1500)
    ids = np.array([7, 307, 907])
    wanted = np.cross(P[ids], [0.3, -0.5, 0.8])
    f = smdf.compute_point_set_directions(P, normals=P, constraints=(ids, wanted))
    t = wanted / np.linalg.norm(wanted, axis=1)[:, None]
    turn = np.arctan2((np.cross(f.directions[ids], t) * P[ids]).sum(axis=1), (f.directions[ids] * t).sum(axis=1))
    assert np.abs(np.angle(np.exp(4j * turn))).max() < 1e-10
    with pytest.raises(ValueError, match="not a point"):
        smdf.compute_point_set_directions(P, constraints=([1500], [[1, 0, 0]]))
    with pytest.raises(ValueError, match="listed twice"):
        smdf.compute_point_set_directions(P, constraints=([3, 3], [[1, 0, 0], [0, 1, 0]]))
    with pytest.raises(ValueError, match="zero or along"):
        smdf.compute_point_set_directions(P, normals=P, constraints=([0], [P[0]]))


def test_guidance_along_the_parallels():
    """A guidance per point gives the aligned field, as on a mesh: on a sphere guided along its parallels
    with weight 0.9 the crosses follow them away from the poles, and the weight is reached."""
    P = fibonacci_sphere(2000)
    along = np.column_stack([-P[:, 1], P[:, 0], np.zeros(len(P))])
    f = smdf.compute_point_set_directions(P, normals=P, guidance=along, alignment_weight=0.9)
    assert abs(f.alignment_weights[0] - 0.9) < 1e-3
    t = along - (along * P).sum(axis=1)[:, None] * P
    turn = np.arctan2((np.cross(f.directions, t) * P).sum(axis=1), (f.directions * t).sum(axis=1))
    off = np.abs(np.angle(np.exp(4j * turn))) / 4
    counted = (along ** 2).sum(axis=1) > 0.25
    assert (off[counted] < math.radians(5)).mean() >= 0.95
    assert smdf.compute_point_set_directions(P, normals=P).alignment_weights == [0.0]
    with pytest.raises(ValueError, match="needs a guidance"):
        smdf.compute_point_set_directions(P, alignment_weight=0.5)
    with pytest.raises(ValueError, match="lambda_1"):
        smdf.compute_point_set_directions(P, normals=P, guidance=along, lambda_t=1e6)
