"""What a result holds beyond the first direction (normals, tangent frames, all n directions), pickling and
copying, one field whatever the order of a face's vertices, and strokes combined with curvature."""
import copy
import inspect
import json
import math
import pickle
import subprocess

import numpy as np
import pytest

import surface_mesh_direction_fields as smdf
from shapes import sphere, torus


def bumpy_sphere():
    V, F = sphere(3)
    V = V * (1 + 0.15 * np.sin(3 * V[:, :1] + 2 * V[:, 1:2]) * np.cos(V[:, 2:3]))
    return V, F


@pytest.mark.parametrize("degree", [1, 3, 4])
def test_normals_frames_and_all_directions(degree):
    V, F = bumpy_sphere()
    r = smdf.compute_globally_optimal_directions(V, F, degree=degree)
    assert r.normals.shape == V.shape and r.tangent_frames.shape == (len(V), 2, 3)
    e1, e2 = r.tangent_frames[:, 0], r.tangent_frames[:, 1]
    for a in (r.normals, e1, e2):
        assert np.allclose(np.linalg.norm(a, axis=1), 1)
    for a, b in ((r.normals, e1), (r.normals, e2), (e1, e2), (r.normals, r.directions)):
        assert np.abs(np.einsum("ij,ij->i", a, b)).max() < 1e-12
    assert np.allclose(np.cross(r.normals, e1), e2)
    # e1 points along the edge to the neighbour of smallest index
    neighbour = np.full(len(V), len(V))
    for f in F:
        for c in range(3):
            neighbour[f[c]] = min(neighbour[f[c]], f[(c + 1) % 3])
    edge = V[neighbour] - V
    assert np.einsum("ij,ij->i", edge, e1).min() > 0 and np.abs(np.einsum("ij,ij->i", edge, e2)).max() < 1e-12 + \
        np.abs(np.einsum("ij,ij->i", edge, r.normals)).max()
    everything = r.all_directions
    assert everything.shape == (len(V), degree, 3) and np.array_equal(everything[:, 0], r.directions)
    for k in range(degree):  # the k-th is the first turned by 2 pi k / n about the normal
        cos = np.einsum("ij,ij->i", everything[:, k], r.directions)
        sin = np.einsum("ij,ij->i", np.cross(r.directions, everything[:, k]), r.normals)
        assert np.allclose(np.arctan2(sin, cos) % (2 * math.pi), (2 * math.pi * k / degree) % (2 * math.pi),
                           atol=1e-12) or k == 0
    # the files show the same normals and directions
    arrays = smdf.field_arrays(V, F, r)
    assert np.array_equal(arrays["normals"], r.normals) and np.array_equal(arrays["directions"], everything)


def test_results_pickle_and_copy():
    V, F = torus()
    r = smdf.compute_globally_optimal_directions(V, F, degree=4, prescribed=[[0, 1], [5, -1]])
    face = smdf.compute_face_directions(V, F, degree=4, prescribed=[[0, 1], [30, -1]])
    for original in (r, face):
        for again in (pickle.loads(pickle.dumps(original)), copy.copy(original), copy.deepcopy(original)):
            assert type(again) is type(original) and repr(again) == repr(original)
            for name in dir(original):
                if name.startswith("_"):
                    continue
                a, b = getattr(original, name), getattr(again, name)
                if isinstance(a, np.ndarray):
                    assert np.array_equal(a, b) and a.dtype == b.dtype, name
                elif not callable(a):
                    assert repr(a) == repr(b), name  # exact, nan included
    deep = copy.deepcopy(r)
    assert not np.shares_memory(deep.directions, r.directions)  # a deep copy owns its arrays
    back = pickle.loads(pickle.dumps(r))
    assert back.index_sum == 0 and back.timings == r.timings and np.array_equal(back.all_directions, r.all_directions)
    with pytest.raises(RuntimeError):  # a state this module did not write
        smdf.Result.__new__(smdf.Result).__setstate__((1, 2))


def test_the_field_does_not_depend_on_where_each_face_starts():
    # rotating every row of F (the same faces, each started at another vertex)
    # gives the same digits: reference directions come from the numbering only
    V, F = bumpy_sphere()
    turned = np.roll(F, 1, axis=1)
    a = smdf.compute_globally_optimal_directions(V, F, degree=4)
    b = smdf.compute_globally_optimal_directions(V, turned, degree=4)
    assert np.array_equal(a.directions, b.directions) and np.array_equal(a.singular_faces, b.singular_faces)
    fa = smdf.compute_face_directions(V, F, degree=4)
    fb = smdf.compute_face_directions(V, turned, degree=4)
    assert np.array_equal(fa.face_directions, fb.face_directions)
    # side c of a turned row is side c - 1 of the original one
    assert np.array_equal(np.roll(fa.matching, 1, axis=1), fb.matching)


def angle_to_strokes(r, strokes, picked):
    """The angle (degrees) between each picked vertex's cross and its stroke projected onto the tangent plane,
    modulo a quarter turn."""
    normal = r.normals[picked]
    s = strokes[picked] - np.einsum("ij,ij->i", strokes[picked], normal)[:, None] * normal
    d, s = r.directions[picked], s / np.linalg.norm(s, axis=1)[:, None]
    cos = np.abs(np.einsum("ij,ij->i", d, s))
    sin = np.linalg.norm(np.cross(d, s), axis=1)
    angle = np.degrees(np.arctan2(sin, cos))
    return np.minimum(angle, 90 - angle)


@pytest.mark.parametrize("scale", [1e-3, 1.0, 1e3])
def test_strokes_with_curvature_are_followed_at_any_scale(scale):
    # an ellipsoid's curvature lines, and strokes at 30 degrees from them on a band
    V, F = sphere(4)
    V = V * [1.5, 1.0, 0.6]
    band = np.abs(V[:, 2]) < 0.1
    tangent = np.cross([0.0, 0.0, 1.0], V)
    strokes = np.where(band[:, None], tangent + 0.6 * np.cross(V, tangent) / np.linalg.norm(V, axis=1)[:, None], 0.)
    r = smdf.compute_globally_optimal_directions(V * scale, F, degree=4, align="curvature", guidance=strokes)
    assert np.median(angle_to_strokes(r, strokes, band)) < 5.0
    curvature = smdf.compute_globally_optimal_directions(V * scale, F, degree=4, align="curvature")
    assert np.median(angle_to_strokes(curvature, strokes, band)) > 25.0
    unscaled = smdf.compute_globally_optimal_directions(V, F, degree=4, align="curvature", guidance=strokes)
    cos = np.einsum("ij,ij->i", r.directions, unscaled.directions)
    assert np.abs(8 * cos**2 * (cos**2 - 1)).max() < 1e-9  # 1 - cos(4 theta): the same crosses


def test_default_degree_is_four_everywhere(program, tmp_path):
    V, F = sphere(2)
    assert inspect.signature(smdf.compute_globally_optimal_directions).parameters["degree"].default == 4
    assert smdf.compute_globally_optimal_directions(V, F).degree == 4
    assert smdf.compute_face_directions(V, F).degree == 4
    mesh = tmp_path / "s.off"
    with open(mesh, "w") as out:
        out.write(f"OFF\n{len(V)} {len(F)} 0\n" + "".join(f"{x!r} {y!r} {z!r}\n" for x, y, z in V) +
                  "".join(f"3 {a} {b} {c}\n" for a, b, c in F))
    ran = subprocess.run([program, str(mesh), "--json", "--quiet"], capture_output=True, text=True, check=True)
    assert json.loads(ran.stdout)["degree"] == 4


def test_result_arrays_are_read_only():
    # all_directions is made from directions and normals, copies share arrays: none can change another
    V, F = torus()
    r = smdf.compute_globally_optimal_directions(V, F, degree=4)
    face = smdf.compute_face_directions(V, F, degree=4)
    for result in (r, face, copy.copy(r), pickle.loads(pickle.dumps(face))):
        for name in dir(result):
            a = getattr(result, name) if not name.startswith("_") else None
            if isinstance(a, np.ndarray) and name != "all_directions":
                assert not a.flags.writeable, name
                with pytest.raises(ValueError):
                    a[(0,) * a.ndim] = 42
    assert np.array_equal(r.all_directions[:, 0], r.directions)


def crafted(result, position, value):
    """The pickled state of `result` with entry `position` replaced by `value`."""
    state = list(result.__getstate__())
    state[position] = value
    return tuple(state)


def test_crafted_pickles_are_refused():
    V, F = torus()
    r = smdf.compute_globally_optimal_directions(V, F, degree=4)
    nv = len(V)
    # directions, magnitudes, coefficients, normals, tangent_frames, singular_faces, loop_turns: each
    # replaced by an array that disagrees with the others (the crash and the uninitialised memory of before)
    for position, bad in [(0, np.zeros((1000, 3))), (0, np.zeros((nv, 2))), (1, np.zeros(nv + 1)),
                          (2, np.zeros(1, dtype=complex)), (3, np.zeros((1, 3))), (4, np.zeros((nv, 3, 2))),
                          (5, np.zeros((3, 3), dtype=np.int64)), (6, np.zeros(4, dtype=np.int64)),
                          (7, [0.0, 1.0])]:
        restored = smdf.Result.__new__(smdf.Result)
        with pytest.raises(ValueError):
            restored.__setstate__(crafted(r, position, bad))
    # a degree of 0 or a million in the report
    for degree in (0, 10 ** 6):
        report = list(r.__getstate__()[8])
        report[0] = degree
        restored = smdf.Result.__new__(smdf.Result)
        with pytest.raises(ValueError):
            restored.__setstate__(crafted(r, 8, tuple(report)))
    face = smdf.compute_face_directions(V, F, degree=4)
    for position, bad in [(0, np.zeros((5, 3))), (1, np.zeros((len(F), 4))), (2, np.zeros(3, dtype=np.int64)),
                          (3, np.zeros((len(F) + 1, 3), dtype=np.int64)), (4, np.zeros((2, 3), dtype=np.int64))]:
        restored = smdf.FaceField.__new__(smdf.FaceField)
        with pytest.raises(ValueError):
            restored.__setstate__(crafted(face, position, bad))


def test_a_progress_callback_cannot_call_back_into_its_object():
    V, F = torus()
    field = smdf.DirectionField(V, F)
    for reenter in (lambda: field.construction_ms, lambda: field.compute(degree=2), lambda: field.matrices()):
        def progress(fraction, reenter=reenter):
            reenter()
        with pytest.raises(RuntimeError, match="busy"):
            field.compute(degree=4, progress=progress)
    assert field.compute(degree=4).converged  # the object is usable after


def test_one_degree_limit_and_strict_types():
    V, F = torus()
    assert smdf.compute_globally_optimal_directions(V, F, degree=1000).degree == 1000
    for bad in (0, 1001, 10 ** 6):
        with pytest.raises(ValueError, match="from 1 to 1000"):
            smdf.compute_globally_optimal_directions(V, F, degree=bad)
        with pytest.raises(ValueError, match="from 1 to 1000"):
            smdf.compute_face_directions(V, F, degree=bad)
    field = smdf.DirectionField(V, F)
    for bad in (True, 4.0, "4"):
        with pytest.raises(TypeError):
            smdf.compute_globally_optimal_directions(V, F, degree=bad)
        with pytest.raises(TypeError):
            field.matrices(degree=bad)
    for bad_V in (V.astype(complex), V > 0, V.astype(object)):
        with pytest.raises(TypeError, match="V must be"):
            smdf.compute_globally_optimal_directions(bad_V, F)
    big = F.astype(np.uint64)
    big[0, 0] = np.iinfo(np.uint64).max
    with pytest.raises(ValueError, match="2\\^63"):
        smdf.compute_globally_optimal_directions(V, big)


def test_the_package_lists_only_its_own_names():
    assert not {"Any", "Callable", "Optional", "Tuple", "inspect"} & set(dir(smdf))
    assert {"compute_globally_optimal_directions", "DirectionField", "compute_face_directions", "read_mesh"} <= \
        set(dir(smdf))


@pytest.mark.parametrize("scale", [1e300, 1e155, 1e-200, 1e-300])
def test_face_fields_at_any_scale(scale):
    # the directions and pd2 unit and finite, and the same singular vertices, at coordinates near 1e+-300
    V, F = torus()
    plain = smdf.compute_face_directions(V, F, degree=4)
    r = smdf.compute_face_directions(V * scale, F, degree=4)
    for a in (r.face_directions, r.pd2):
        assert np.all(np.isfinite(a)) and np.allclose(np.linalg.norm(a, axis=1), 1, atol=1e-12)
    assert np.array_equal(np.sort(r.singular_vertices, axis=0), np.sort(plain.singular_vertices, axis=0))
