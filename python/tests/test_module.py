"""The Python module against the C++ program, the math's invariants and bad input."""
import json
import math
import os
import pickle
import subprocess
import sys
import threading

import numpy as np
import pytest

import surface_mesh_direction_fields as smdf
from conftest import MISSING_INPUT
from shapes import octahedron, sphere, torus

# The program lets the factorization set OpenBLAS's threads; with the same
# setting the module gives the same digits (the module's default is off).
THREAD_CONTROL_BY_DEFAULT = smdf.openblas_thread_control()


def test_version_and_docs():
    assert isinstance(smdf.__version__, str) and smdf.__version__.count(".") == 2
    assert "degree" in smdf.compute_globally_optimal_directions.__doc__
    assert smdf.DirectionField.compute.__doc__ and smdf.read_mesh.__doc__


@pytest.mark.parametrize("degree", [1, 2, 3, 4, 6])
def test_index_sum_is_n_chi(degree):
    for (V, F), chi in [(sphere(), 2), (torus(), 0)]:
        r = smdf.compute_globally_optimal_directions(V, F, degree=degree)
        assert r.index_sum == degree * chi and r.singular_faces[:, 1].sum() == degree * chi
        assert r.directions.shape == V.shape and np.allclose(np.linalg.norm(r.directions, axis=1), 1)
        assert r.converged and r.degree == degree and len(r.eigenvalues) == 1


def run_program(program, mesh, out, *options):
    d = os.path.join(out, "d.txt")
    s = os.path.join(out, "s.txt")
    p = subprocess.run([program, mesh, "--directions", d, "--singularities", s, "--json"] + list(options),
                       capture_output=True, text=True, check=True)
    singular = np.array([[int(x) for x in l.split()] for l in open(s) if l.strip() and not l.startswith("#")])
    return np.loadtxt(d), singular.reshape(-1, 2), json.loads(p.stdout)


@pytest.mark.parametrize("options,python", [
    ([], {}),
    (["--degree", "2", "--s", "0.5"], {"degree": 2, "s": 0.5}),
    (["--align", "curvature", "--alignment-weight", "0.5"], {"align": "curvature", "alignment_weight": 0.5}),
    (["--feature-angle", "60"], {"feature_angle": 60.0}),
])
def test_same_field_as_the_program(program, shared, tmp_path, options, python):
    mesh = os.path.join(shared, "fandisk.off")
    V, F = loaded = smdf.read_mesh(mesh)
    repairs = loaded.repairs
    assert sum(repairs.values()) == 0
    directions, singular, report = run_program(program, mesh, str(tmp_path), *options)
    r = smdf.compute_globally_optimal_directions(V, F, **python)
    assert np.array_equal(r.directions, directions)  # bit for bit (17 digits written)
    assert np.array_equal(r.singular_faces, singular) and r.index_sum == report["index_sum"]


@pytest.mark.parametrize("name,options,python", [
    ("plane_holes.off", ["--constrain-boundary", "tangent"], {"boundary": "tangent"}),
    ("plane_holes.off", ["--constrain-boundary", "normal", "--degree", "2"], {"boundary": "normal", "degree": 2}),
    ("spot.off", ["--align", "min-curvature", "--lambda", "-5", "--curvature-estimate", "hopf"],
     {"align": "min-curvature", "lambda_t": -5.0, "curvature_estimate": "hopf"}),
    ("spot.off", ["--prescribe", "PRESCRIBE"], {"prescribed": "PRESCRIBE"}),
    ("spot.off", ["--guidance", "GUIDANCE", "--alignment-weight", "0.9"], {"guidance": "GUIDANCE", "alignment_weight": 0.9}),
])
def test_more_options_same_field_as_the_program(program, shared, tmp_path, name, options, python):
    mesh = os.path.join(shared, name)
    V, F = loaded = smdf.read_mesh(mesh)
    repairs = loaded.repairs
    if sum(repairs.values()) != 0:
        pytest.skip("the file needs repairs: its vertex order differs from the mesh's")
    if "GUIDANCE" in options:  # a stroke field: x on the upper half, nothing below
        g = np.where(V[:, 2:3] > np.median(V[:, 2]), [[1.0, 0.0, 0.0]], [[0.0, 0.0, 0.0]])
        np.savetxt(tmp_path / "g.txt", g, fmt="%.17g")
        options = [str(tmp_path / "g.txt") if o == "GUIDANCE" else o for o in options]
        python = dict(python, guidance=g)
    if "PRESCRIBE" in options:  # the smoothest field's own singularities, given back
        first = smdf.compute_globally_optimal_directions(V, F, degree=4)
        np.savetxt(tmp_path / "p.txt", first.singular_faces, fmt="%d")
        options = [str(tmp_path / "p.txt") if o == "PRESCRIBE" else o for o in options]
        python = dict(python, prescribed=first.singular_faces)
    directions, singular, report = run_program(program, mesh, str(tmp_path), *options)
    r = smdf.compute_globally_optimal_directions(V, F, **python)
    assert np.array_equal(r.directions, directions) and np.array_equal(r.singular_faces, singular)


def test_openblas_thread_control_is_on_as_in_the_program(shared):
    smdf.set_openblas_thread_control(True)
    if not smdf.openblas_thread_control():
        pytest.skip("OpenBLAS is not linked with its thread control")
    assert THREAD_CONTROL_BY_DEFAULT is True  # the program's setting: the same digits without a switch
    V, F = smdf.read_mesh(os.path.join(shared, "fandisk.off"))
    controlled = smdf.compute_globally_optimal_directions(V, F, degree=4)
    smdf.set_openblas_thread_control(False)
    try:
        assert not smdf.openblas_thread_control()
        left_alone = smdf.compute_globally_optimal_directions(V, F, degree=4)
    finally:
        smdf.set_openblas_thread_control(True)
    # the same field up to the last digits: only the order of the sums differs
    assert np.array_equal(controlled.singular_faces, left_alone.singular_faces)
    assert np.abs(controlled.directions - left_alone.directions).max() < 1e-8


def stub_parameters(function, cls=None):
    """The parameter names and defaults of a function of the stubs (__init__.pyi)."""
    import ast
    tree = ast.parse(open(os.path.join(os.path.dirname(smdf.__file__), "__init__.pyi")).read())
    scope = tree.body if cls is None else next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == cls).body
    f = next(n for n in scope if isinstance(n, ast.FunctionDef) and n.name == function)
    names = [a.arg for a in f.args.posonlyargs + f.args.args + f.args.kwonlyargs]
    defaults = {a.arg: ast.literal_eval(d) for a, d in zip(f.args.kwonlyargs, f.args.kw_defaults)}
    return names, defaults


def test_signatures_show_every_keyword_as_the_stubs_do():
    import inspect
    for function, stub in [(smdf.compute_globally_optimal_directions, stub_parameters("compute_globally_optimal_directions")),
                           (smdf.DirectionField.compute, stub_parameters("compute", "DirectionField"))]:
        parameters = inspect.signature(function).parameters
        assert list(parameters) == stub[0]
        assert {n: p.default for n, p in parameters.items() if p.default is not p.empty} == stub[1]
        assert "anti-holomorphic" in function.__doc__ and "intrinsic_mollification" in function.__doc__
    names, defaults = stub_parameters("compute_face_directions")
    parameters = inspect.signature(smdf.compute_face_directions).parameters
    assert list(parameters) == names
    assert {n: p.default for n, p in parameters.items() if p.default is not p.empty} == defaults
    # the keywords the C++ side accepts are exactly these
    V, F = refined_octahedron_arrays(1)
    for name in names[2:]:
        smdf.compute_face_directions(V, F, **{name: defaults[name]})
    with pytest.raises(TypeError, match="'s'"):
        smdf.compute_face_directions(V, F, s=0.0)


def refined_octahedron_arrays(levels):
    return sphere(levels)


def test_face_field_on_a_sphere():
    """Poincare-Hopf at the vertices, the matching closing to the indices, PD1 and PD2 in each face."""
    V, F = refined_octahedron_arrays(3)
    r = smdf.compute_face_directions(V, F, degree=4)
    assert r.index_sum == 8 and r.singular_vertices[:, 1].sum() == 8 and r.euler_characteristics == [2]
    assert r.boundary_indices == [0] and r.converged and abs(r.eigenvalues[0] - 4) < 0.2
    normals = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    for d in (r.face_directions, r.pd2):
        assert np.allclose(np.linalg.norm(d, axis=1), 1) and np.abs((d * normals).sum(axis=1)).max() < 1e-9
    assert np.abs((r.face_directions * r.pd2).sum(axis=1)).max() < 1e-9  # n = 4: a quarter turn
    assert np.array_equal(r.mismatch, r.matching % 4)
    assert matching_closes(r, V, F, 4)


def matching_closes(r, V, F, n):
    """Around every vertex the jumps of the matching add up to minus its index, modulo n."""
    # counter-clockwise around vertex F[f, c+1], edge c of f leads from f to the face across: sum the jumps
    turns = np.zeros(len(V), dtype=np.int64)
    for f in range(len(F)):
        for c in range(3):
            turns[F[f, (c + 1) % 3]] += r.matching[f, c]
    index = np.zeros(len(V), dtype=np.int64)
    index[r.singular_vertices[:, 0]] = r.singular_vertices[:, 1]
    return bool(np.all((turns + index) % n == 0))


def test_face_field_program_and_module_agree(shared, program, tmp_path):
    """The program's --on faces and the module find the same singular vertices on a shared mesh."""
    direction_field = program
    path = os.path.join(shared, "fertility.off")
    subprocess.run([direction_field, path, "--on", "faces", "--sing", str(tmp_path / "f.sing"), "--mesh-out",
                    str(tmp_path / "f.off"), "--quiet"], check=True, capture_output=True)
    V, F = smdf.read_mesh(str(tmp_path / "f.off"))
    r = smdf.compute_face_directions(V, F, degree=4)
    listed = np.loadtxt(tmp_path / "f.sing", skiprows=1, dtype=np.int64)
    assert np.array_equal(np.sort(listed, axis=0), np.sort(r.singular_vertices, axis=0))


def test_face_field_constraints_and_refusals():
    V, F = refined_octahedron_arrays(2)
    edge = V[F[0, 1]] - V[F[0, 0]]
    r = smdf.compute_face_directions(V, F, degree=1, constraints=(np.array([0]), edge[None, :]))
    assert np.allclose(r.face_directions[0], edge / np.linalg.norm(edge))
    with pytest.raises(smdf.InvalidInputError):
        smdf.compute_face_directions(V, F, degree=3, align="curvature")
    with pytest.raises(ValueError, match="face 99999"):
        smdf.compute_face_directions(V, F, constraints=(np.array([99999]), edge[None, :]))
    with pytest.raises(ValueError, match="shape"):
        smdf.compute_face_directions(V, F, guidance=np.ones((len(V), 3)))  # one row per face
    # a guidance per face: the field follows it (on a sphere still with the indices of n chi)
    guided = smdf.compute_face_directions(V, F, guidance=np.tile([1.0, 0.0, 0.0], (len(F), 1)), lambda_t=-10.0)
    assert guided.index_sum == 8


def cube_with_fin():
    """The surface of the unit cube (4 x 4 squares a side) and a 2 x 2 square fin standing on its top along
    y = 0.5: two non-manifold edges, three faces each."""
    points, faces = {}, []

    def point(p):
        return points.setdefault(tuple(np.round(p, 12)), len(points))
    for axis in range(3):
        for side in (0, 1):
            for i in range(4):
                for j in range(4):
                    def at(a, b):
                        p = np.zeros(3)
                        p[axis], p[(axis + 1) % 3], p[(axis + 2) % 3] = side, a / 4, b / 4
                        return point(p)
                    a, b, c, d = at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)
                    faces += [(a, b, c), (a, c, d)] if side else [(a, c, b), (a, d, c)]
    for i in range(2):
        for j in range(2):
            def at(a, b):
                return point((0.25 + 0.25 * a, 0.5, 1 + 0.25 * b))
            faces += [(at(i, j), at(i + 1, j), at(i + 1, j + 1)), (at(i, j), at(i + 1, j + 1), at(i, j + 1))]
    V = np.array(sorted(points, key=points.get), dtype=float)
    return V, np.array(faces, dtype=np.int64)


def test_face_field_on_a_non_manifold_mesh_kept_whole():
    """repair_mesh cuts the fin off the cube; vertex_point_index glues it back: one component whose cross
    field is parallel (eigenvalue 0), against two fields of their own when cut."""
    V, F = cube_with_fin()
    repaired = smdf.repair_mesh(V, F, with_maps=True)
    V2, F2 = repaired
    assert len(V2) > len(V) and repaired.repairs["vertices_duplicated"] > 0
    glued = smdf.compute_face_directions(V2, F2, vertex_point_index=repaired.maps["file_vertex_of_vertex"])
    cut = smdf.compute_face_directions(V2, F2)
    assert len(glued.eigenvalues) == 1 and len(cut.eigenvalues) == 2 and abs(glued.eigenvalues[0]) < 1e-10
    assert glued.glued_edges == 2 and cut.glued_edges == 0
    assert glued.index_sum + sum(glued.boundary_indices) == 4 * sum(glued.euler_characteristics)
    # the fin's field is the cube's, turned about the edge: its directions lie along the axes as the cube's do
    axis_aligned = np.abs(glued.face_directions).max(axis=1)
    assert np.ptp(axis_aligned) < 1e-8
    with pytest.raises(ValueError, match="one entry per vertex"):
        smdf.compute_face_directions(V2, F2, vertex_point_index=np.arange(3))
    with pytest.raises(smdf.InvalidInputError, match="glued"):
        smdf.compute_face_directions(V2, F2, vertex_point_index=repaired.maps["file_vertex_of_vertex"],
                                     singularity_cancellation_radius=0.1)


def test_face_field_prescribed_vertices():
    """Singularities placed at vertices come back exactly, an opposite pair at the ends of one edge included."""
    V, F = refined_octahedron_arrays(3)
    smooth = smdf.compute_face_directions(V, F, degree=4)
    back = smdf.compute_face_directions(V, F, degree=4, prescribed=smooth.singular_vertices)
    assert back.prescribed and not smooth.prescribed
    assert np.array_equal(np.sort(back.singular_vertices, axis=0), np.sort(smooth.singular_vertices, axis=0))
    singular = set(smooth.singular_vertices[:, 0].tolist())
    a, b = next((a, b) for a, b in zip(F[:, 0], F[:, 1]) if a not in singular and b not in singular)
    for k in (1, 8):  # 8: the power field turns by more than pi across the edge, so not the principal matching
        asked = np.vstack([smooth.singular_vertices, [[a, k], [b, -k]]])
        r = smdf.compute_face_directions(V, F, degree=4, prescribed=asked)
        assert np.array_equal(np.sort(r.singular_vertices, axis=0), np.sort(asked, axis=0))
        assert (r.non_principal_jumps > 0) == (k == 8)
        assert matching_closes(r, V, F, 4)
    # 12: each direction would turn by half a turn or more across some edge, which no direction with a
    # matching can show (a reader takes each direction's turn in (-pi, pi])
    with pytest.raises(smdf.InvalidInputError, match="half a turn"):
        smdf.compute_face_directions(V, F, degree=4, prescribed=np.vstack([smooth.singular_vertices,
                                                                           [[a, 12], [b, -12]]]))
    with pytest.raises(smdf.InvalidInputError, match="Poincare-Hopf"):
        smdf.compute_face_directions(V, F, degree=4, prescribed=[[0, 1]])
    with pytest.raises(ValueError, match="vertex 99999"):
        smdf.compute_face_directions(V, F, degree=4, prescribed=[[99999, 8]])
    with pytest.raises(ValueError, match="lambda_t"):
        smdf.compute_face_directions(V, F, degree=4, prescribed=smooth.singular_vertices, lambda_t=-1.0)


def test_defaults_given_explicitly_change_nothing():
    import inspect
    V, F = sphere()
    defaults = {n: p.default for n, p in inspect.signature(smdf.compute_globally_optimal_directions).parameters.items()
                if p.default is not p.empty}
    implicit, explicit = (smdf.compute_globally_optimal_directions(V, F, **kw) for kw in ({}, defaults))
    assert np.array_equal(implicit.directions, explicit.directions)
    assert np.array_equal(smdf.DirectionField(V, F).compute(**defaults).directions, implicit.directions)


def test_calls_fail_in_a_python_way():
    V, F = sphere()
    with pytest.raises(TypeError, match=r"takes 2 positional arguments but 3 were given"):
        smdf.compute_globally_optimal_directions(V, F, 4)
    with pytest.raises(TypeError, match=r"takes 1 positional argument but 2 were given"):
        smdf.DirectionField(V, F).compute(4)
    with pytest.raises(TypeError, match=r"unexpected keyword argument 'degre'"):
        smdf.compute_globally_optimal_directions(V, F, degre=4)
    # the library's messages name the Python keywords
    with pytest.raises(ValueError, match=r"^lambda_t must be a finite number"):
        smdf.compute_globally_optimal_directions(V, F, align="curvature", lambda_t=float("inf"))
    with pytest.raises(ValueError, match=r"^the intrinsic mollification must be a non-negative number"):
        smdf.compute_globally_optimal_directions(V, F, intrinsic_mollification=-1.0)
    r = smdf.compute_globally_optimal_directions(V, F, degree=4)
    assert repr(r) == f"<Result degree=4, {len(V)} vertices, {len(r.singular_faces)} singular faces, index_sum=8>"
    assert repr(smdf.DirectionField(V, F)) == f"<DirectionField {len(V)} vertices, {len(F)} faces>"


def test_a_field_that_did_not_converge_warns():
    V, F = sphere()
    with pytest.warns(RuntimeWarning, match=r"did not converge in 1 iterations") as caught:
        r = smdf.compute_globally_optimal_directions(V, F, degree=4, max_iterations=1)
    assert not r.converged and repr(r).endswith(", not converged>")
    assert caught[0].filename == __file__  # the warning points at the caller's line
    with pytest.warns(RuntimeWarning) as caught:
        smdf.DirectionField(V, F).compute(degree=4, max_iterations=1)
    assert caught[0].filename == __file__
    import warnings
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        smdf.compute_globally_optimal_directions(V, F, degree=4)  # converged: no warning


def test_intrinsic_mollification_keyword():
    # an octahedron whose top vertex moved onto the edge of its first face: that face has zero area,
    # mollified by default, refused with 0
    V, F = octahedron()
    V[4] = (V[0] + V[2]) / 2
    r = smdf.compute_globally_optimal_directions(V, F, degree=1)
    assert r.index_sum == 2
    with pytest.raises(ValueError, match=r"zero"):
        smdf.compute_globally_optimal_directions(V, F, degree=1, intrinsic_mollification=0.0)


def test_mesh_options_of_the_class():
    """DirectionField.compute() honours the options of the C++ class's construction: intrinsic_mollification
    (the mesh work is redone when it changes) and normals (C++ vertex_normal_map)."""
    V, F = octahedron()
    V[4] = (V[0] + V[2]) / 2  # a face of zero area: mollified by default, refused with 0
    field = smdf.DirectionField(V, F)
    assert field.compute(degree=1).index_sum == 2
    with pytest.raises(ValueError, match=r"zero"):
        field.compute(degree=1, intrinsic_mollification=0.0)
    assert field.compute(degree=1).index_sum == 2
    V, F = sphere()
    free = smdf.compute_globally_optimal_directions(V, F, degree=4)
    unit = V / np.linalg.norm(V, axis=1)[:, None]  # the sphere's exact normals
    given = smdf.compute_globally_optimal_directions(V, F, degree=4, normals=unit)
    kept = smdf.DirectionField(V, F)
    assert np.array_equal(kept.compute(degree=4, normals=unit).directions, given.directions)
    assert np.abs((given.directions * unit).sum(axis=1)).max() < 1e-12  # tangent to the given normals
    assert not np.array_equal(given.directions, free.directions)
    assert given.index_sum == free.index_sum == 8
    with pytest.raises(ValueError, match="normals row 3 is zero"):
        smdf.compute_globally_optimal_directions(V, F, normals=np.where(np.arange(len(V))[:, None] == 3, 0.0, unit))
    with pytest.raises(ValueError, match="shape"):
        smdf.compute_globally_optimal_directions(V, F, normals=unit[:-1])


def test_progress_and_stopping():
    V, F = sphere(4)
    fractions = []
    r = smdf.compute_globally_optimal_directions(V, F, degree=4, progress=fractions.append)
    assert fractions[0] == 0.0 and fractions[-1] == 1.0 and fractions == sorted(fractions)
    assert len(fractions) >= r.iterations + 4  # every step and every solve

    class Stop(Exception):
        pass

    def stop_at_third(fraction, calls=[]):
        calls.append(fraction)
        if len(calls) == 3:
            raise Stop()

    field = smdf.DirectionField(V, F)
    with pytest.raises(Stop):
        field.compute(degree=6, s=0.5, progress=stop_at_third)
    # the object stays usable: its next field is a fresh object's
    again = field.compute(degree=6, s=0.5)
    assert np.array_equal(again.directions, smdf.DirectionField(V, F).compute(degree=6, s=0.5).directions)
    with pytest.raises(TypeError, match="progress must be a callable"):
        field.compute(progress=3)


def test_ctrl_c_interrupts_a_long_computation(shared):
    """SIGINT 0.3 s into a computation of about a second: KeyboardInterrupt, raised by the
    computation itself (not after it), and the module usable afterwards."""
    import signal
    path = os.path.join(shared, "nefertiti_sub4.off")
    if not os.path.exists(path):
        pytest.skip(MISSING_INPUT + "nefertiti_sub4.off")
    V, F = smdf.read_mesh(path)
    timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
    seen = []
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            smdf.compute_globally_optimal_directions(V, F, degree=4, progress=seen.append)
    finally:
        timer.cancel()
    assert 1.0 not in seen  # stopped before the end
    r = smdf.compute_globally_optimal_directions(*sphere(), degree=4)
    assert r.index_sum == 8


def test_a_factorization_asks_the_progress_callable_and_stops(shared):
    """The factorization, the longest step without a solve, asks the progress callable (with the fraction
    reached before it) every few milliseconds: an exception raised there stops it, and the object computes
    its next field as a fresh one."""
    path = os.path.join(shared, "nefertiti_sub4.off")
    if not os.path.exists(path):
        pytest.skip(MISSING_INPUT + "nefertiti_sub4.off")
    V, F = smdf.read_mesh(path)
    seen = []
    smdf.compute_globally_optimal_directions(V, F, degree=4, progress=seen.append)
    assert seen.count(0.2) > 4  # asked again and again during the factorization (0.2: before it)

    class Stop(Exception):
        pass

    def stop_in_factorization(fraction):
        seen.append(fraction)
        if seen.count(0.2) == 4:
            raise Stop()
    field = smdf.DirectionField(V, F)
    seen.clear()
    with pytest.raises(Stop):
        field.compute(degree=4, progress=stop_in_factorization)
    assert max(seen) == 0.2
    again = field.compute(degree=4)
    assert np.array_equal(again.directions, smdf.DirectionField(V, F).compute(degree=4).directions)


def test_field_arrays_all_directions_and_normals():
    V, F = sphere()
    for n in (1, 4, 6):
        r = smdf.compute_globally_optimal_directions(V, F, degree=n)
        a = smdf.field_arrays(V, F, r)
        N, D = a["normals"], a["directions"]
        assert N.shape == (len(V), 3) and D.shape == (len(V), n, 3) and a["face_directions"].shape == (len(F), 3)
        assert np.array_equal(D[:, 0], r.directions)
        assert np.allclose(np.linalg.norm(N, axis=1), 1.0) and np.abs(np.einsum("ij,ikj->ik", N, D)).max() < 1e-12
        for k in range(n):  # the k-th: the first turned by 2 pi k / n about the normal
            turned = np.cos(2 * np.pi * k / n) * D[:, 0] + np.sin(2 * np.pi * k / n) * np.cross(N, D[:, 0])
            assert np.abs(D[:, k] - turned).max() < 1e-12


def test_read_mesh_maps_between_file_and_mesh(tmp_path):
    # a quad (triangulated), a point given twice (merged), a point no face uses
    off = tmp_path / "m.off"
    off.write_text("OFF\n7 5 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n9 9 9\n0.5 0.5 1\n1 0 0\n"
                   "4 3 2 1 0\n3 0 1 5\n3 6 2 5\n3 2 3 5\n3 3 0 5\n")
    loaded = smdf.read_mesh(off, with_maps=True)
    (V, F), repairs, maps = loaded, loaded.repairs, loaded.maps
    assert repairs["merged_points"] == 1 and repairs["polygons_triangulated"] == 1
    file_points = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [9, 9, 9], [0.5, 0.5, 1], [1, 0, 0]])
    of_file = maps["vertex_of_file_vertex"]
    assert len(of_file) == 7 and of_file[4] == -1 and of_file[1] == of_file[6]
    used = of_file >= 0
    assert np.array_equal(V[of_file[used]], file_points[used])
    assert np.array_equal(file_points[maps["file_vertex_of_vertex"]], V)
    assert len(maps["file_face_of_face"]) == len(F) == 6 and sorted(set(maps["file_face_of_face"])) == [0, 1, 2, 3, 4]
    assert list(maps["file_face_of_face"]).count(0) == 2  # the quad's two triangles
    assert len(smdf.read_mesh(off)) == 2 and smdf.read_mesh(off).maps is None


def test_a_mesh_that_is_not_an_oriented_manifold_is_named():
    V, F = octahedron()
    flipped = F.copy()
    flipped[5] = flipped[5][::-1]
    with pytest.raises(ValueError, match=r"F rows [0-9]+ and 5 run along the edge [0-9]+-[0-9]+ in the same "
                                         r"direction: one of them is flipped.*read_mesh\(\) repairs"):
        smdf.compute_globally_optimal_directions(V, flipped)
    V3 = np.vstack([V, [[0.5, 0.5, 0.5]]])
    fin = np.vstack([F, [[0, 2, 6]]])  # a third face on the edge 0-2
    with pytest.raises(ValueError, match=r"the edge 0-2 belongs to 3 faces \(F rows 0, 4, 8\)"):
        smdf.DirectionField(V3, fin)


def test_options_change_the_field():
    V, F = sphere()
    base = smdf.compute_globally_optimal_directions(V, F, degree=4).directions
    guidance = np.tile([0.0, 0.0, 1.0], (len(V), 1))
    for options in [dict(align="curvature", lambda_t=-10.0), dict(guidance=guidance, lambda_t=-10.0),
                    dict(constraints=(np.array([0]), np.array([[0.0, 1.0, 0.0]]))), dict(s=1.0)]:
        r = smdf.compute_globally_optimal_directions(V, F, degree=4, **options)
        assert not np.allclose(r.directions, base), options
    r = smdf.compute_globally_optimal_directions(V, F, degree=1, constraints=(np.array([0]), np.array([[0.0, 1.0, 0.0]])))
    assert np.allclose(r.directions[0], [0, 1, 0])


def test_prescribed_singularities():
    V, F = sphere()
    first = smdf.compute_globally_optimal_directions(V, F, degree=4)
    r = smdf.compute_globally_optimal_directions(V, F, degree=4, prescribed=first.singular_faces)
    assert np.array_equal(r.singular_faces, first.singular_faces)
    with pytest.raises(ValueError):
        smdf.compute_globally_optimal_directions(V, F, degree=4, prescribed=np.array([[0, 1]]))


@pytest.mark.parametrize("name,degree", [("fertility.off", 4), ("eight.off", 100)])
def test_a_field_given_back_with_its_loop_turns(shared, name, degree):
    V, F = smdf.read_mesh(os.path.join(shared, name))
    field = smdf.DirectionField(V, F)
    first = field.compute(degree=degree)
    assert first.loop_turns.shape[1] == 2 and len(first.loop_turns) > 0
    back = field.compute(degree=degree, prescribed=first.singular_faces, prescribed_loop_turns=first.loop_turns)
    assert np.array_equal(back.singular_faces, first.singular_faces)
    assert np.array_equal(back.loop_turns, first.loop_turns)
    with pytest.raises(ValueError, match="prescribed"):
        field.compute(degree=degree, prescribed_loop_turns=first.loop_turns)
    with pytest.raises(ValueError, match="names loop"):
        field.compute(degree=degree, prescribed=first.singular_faces, prescribed_loop_turns=np.array([[10**6, 1]]))


def test_class_reuses_and_matches_fresh_calls():
    V, F = sphere()
    field = smdf.DirectionField(V, F)
    a = field.compute(degree=4)
    b = field.compute(degree=2, s=0.3)
    c = field.compute(degree=4)
    assert np.array_equal(a.directions, c.directions)
    assert np.array_equal(b.directions, smdf.compute_globally_optimal_directions(V, F, degree=2, s=0.3).directions)


def test_two_threads_give_the_same_results():
    meshes = [sphere(4), torus(60, 30)]
    alone = [smdf.compute_globally_optimal_directions(V, F, degree=4).directions for V, F in meshes]
    together = [None, None]
    def work(i):
        together[i] = smdf.compute_globally_optimal_directions(*meshes[i], degree=4).directions
    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(np.array_equal(a, b) for a, b in zip(alone, together))


CONCURRENT = """
import sys, threading, numpy as np
import surface_mesh_direction_fields as smdf
meshes = [smdf.read_mesh(path) for path in sys.argv[1:]]
alone = [smdf.compute_globally_optimal_directions(V, F, degree=4, align="curvature").directions for V, F in meshes]
for trial in range(2):
    out = [None] * len(meshes)
    def work(i):
        out[i] = smdf.compute_globally_optimal_directions(*meshes[i], degree=4, align="curvature").directions
    threads = [threading.Thread(target=work, args=(i,)) for i in range(len(meshes))]
    for t in threads: t.start()
    for t in threads: t.join()
    assert all(np.array_equal(a, b) for a, b in zip(alone, out)), "trial %d differs" % trial
"""


def run_with_blas_threads(script, shared):
    """Runs `script` on nefertiti and fertility with OpenBLAS's own threads
    (the test suite otherwise runs it on one): its thread count is
    process-wide, so concurrent factorizations must not change each other's
    (meshes large enough for OpenBLAS to use threads)."""
    env = {k: v for k, v in os.environ.items() if k != "OPENBLAS_NUM_THREADS"}
    paths = [os.path.join(shared, name) for name in ("nefertiti.off", "fertility.off")]
    if not all(os.path.exists(p) for p in paths):
        pytest.skip(MISSING_INPUT + "nefertiti.off or fertility.off")
    r = subprocess.run([sys.executable, "-c", script] + paths, env=env, capture_output=True, text=True)
    assert r.returncode == 0, r.stderr[-2000:]


def test_two_threads_with_blas_threads_give_the_same_digits(shared):
    run_with_blas_threads(CONCURRENT, shared)


PRESCRIBED_CONCURRENT = """
import sys, threading, numpy as np
import surface_mesh_direction_fields as smdf
meshes = [smdf.read_mesh(path) for path in sys.argv[1:]]
edits = [smdf.compute_globally_optimal_directions(V, F, degree=4).singular_faces for V, F in meshes]
def prescribed(i):
    return smdf.compute_globally_optimal_directions(*meshes[i], degree=4, prescribed=edits[i]).directions
def aligned(i):
    return smdf.compute_globally_optimal_directions(*meshes[i], degree=4, align="curvature").directions
jobs = [(prescribed, i) for i in range(len(meshes))] * 2 + [(aligned, i) for i in range(len(meshes))]
alone = [f(i) for f, i in jobs]
for trial in range(2):
    out = [None] * len(jobs)
    def work(k):
        out[k] = jobs[k][0](jobs[k][1])
    threads = [threading.Thread(target=work, args=(k,)) for k in range(len(jobs))]
    for t in threads: t.start()
    for t in threads: t.join()
    assert all(np.array_equal(a, b) for a, b in zip(alone, out)), "trial %d differs" % trial
"""


def test_prescribed_fields_in_threads_give_the_same_digits(shared):
    # the prescription's factorization (CHOLMOD, which calls the BLAS) under the
    # same one-at-a-time rule as the others
    run_with_blas_threads(PRESCRIBED_CONCURRENT, shared)


V0, F0 = octahedron()
BAD = [
    (np.zeros((0, 3)), F0, ValueError), (V0, np.zeros((0, 3), dtype=np.int64), ValueError),
    (V0[:, :2], F0, ValueError), (V0, F0[:, :2], ValueError), (V0.ravel(), F0, ValueError),
    (np.where(np.arange(18).reshape(6, 3) == 4, np.nan, V0), F0, ValueError),
    (np.where(np.arange(18).reshape(6, 3) == 4, np.inf, V0), F0, ValueError),
    (V0, np.where(F0 == 5, -1, F0), ValueError), (V0, np.where(F0 == 5, 6, F0), ValueError),
    (V0, np.vstack([F0, F0[:1]]), ValueError),                  # a repeated face
    (V0, np.vstack([F0, [[0, 2, 1]]]), ValueError),             # an edge of three faces
    (V0, F0[:, ::-1][[0, 1, 2, 3, 4, 5, 6]].tolist() + [F0[7].tolist()], ValueError),  # inconsistent orientation
    (V0, np.array([[0, 0, 1]] + F0[1:].tolist()), ValueError),   # a degenerate face
    (np.vstack([V0, V0 + 3]), np.vstack([F0, np.where(F0 == 0, 0, F0 + 6)]), ValueError),  # two closed fans at vertex 0
    (V0[:5], np.array([[0, 1, 2], [0, 3, 4]]), ValueError),     # two open fans at vertex 0 (a bowtie)
    (np.vstack([V0, V0[:2] + 3]), np.vstack([F0, [[0, 6, 7]]]), ValueError),  # an open fan at a closed one's vertex
    (V0, np.asfortranarray(F0), None), (np.asfortranarray(V0), F0[::-1], None),  # strided: converted once
    ("not an array", F0, (TypeError, ValueError)), (V0, [["a", "b", "c"]], (TypeError, ValueError)),
    (V0.astype(np.float32), F0, None), (V0, F0.astype(np.int32), None),      # converted once, accepted
]


@pytest.mark.parametrize("V,F,error", BAD)
def test_bad_meshes(V, F, error):
    if error is None:
        assert smdf.compute_globally_optimal_directions(V, F).index_sum == 8
        return
    with pytest.raises(error) as e:
        smdf.compute_globally_optimal_directions(V, F)
    assert "\n" not in str(e.value) and str(e.value)


@pytest.mark.parametrize("options,error", [
    (dict(degree=0), ValueError), (dict(degree=-3), ValueError), (dict(s=2.0), ValueError),
    (dict(s=float("nan")), ValueError), (dict(align="sideways"), ValueError), (dict(align="curvature", degree=3), ValueError),
    (dict(boundary="up"), ValueError), (dict(curvature_estimate="guess"), ValueError),
    (dict(lambda_t=-1.0, alignment_weight=0.5), ValueError), (dict(alignment_weight=1.5, align="curvature"), ValueError),
    (dict(guidance=np.zeros((5, 3))), ValueError), (dict(guidance=np.full((6, 3), np.nan)), ValueError),
    (dict(constraints=(np.array([9]), np.array([[1.0, 0, 0]]))), ValueError),
    (dict(constraints=(np.array([0, 1]), np.array([[1.0, 0, 0]]))), ValueError),
    (dict(feature_edges=np.array([[0, 1]])), ValueError), (dict(feature_angle=200.0), ValueError),
    (dict(prescribed=np.array([[99, 1]])), ValueError), (dict(max_iterations=-1), ValueError),
    (dict(max_iterations=2**32 + 3), ValueError), (dict(max_iterations=2**40), ValueError),
    (dict(max_iterations=3.0), TypeError), (dict(seed=2**32), ValueError),
    (dict(lambda_t=0.5), ValueError), (dict(alignment_weight=0.5), ValueError),           # nothing to align to
    (dict(prescribed=np.array([[0.9, 1.0]])), ValueError),                               # not truncated to face 0
    (dict(constraints=(np.array([0.9]), np.array([[1.0, 0, 0]]))), ValueError),
    (dict(constraints=(np.array([1, 1]), np.array([[1.0, 0, 0], [0, 1.0, 0]]))), ValueError),  # listed twice
    (dict(frobnicate=1), TypeError), (dict(degree="four"), TypeError),
])
def test_bad_options(options, error):
    with pytest.raises(error) as e:
        smdf.compute_globally_optimal_directions(V0, F0, **options)
    assert "\n" not in str(e.value)


def test_read_mesh_repairs_and_refuses(tmp_path):
    quads = tmp_path / "cube.off"
    quads.write_text("OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                     "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n")
    V, F = loaded = smdf.read_mesh(str(quads))
    repairs = loaded.repairs
    assert V.shape == (8, 3) and F.shape == (12, 3) and repairs["polygons_triangulated"] == 6
    assert smdf.compute_globally_optimal_directions(V, F).index_sum == 8
    for text in ["", "OFF\n3 1 0\n0 0 0\n1 0 0\n"]:
        bad = tmp_path / "bad.off"
        bad.write_text(text)
        with pytest.raises(ValueError):
            smdf.read_mesh(str(bad))
    with pytest.raises(FileNotFoundError):  # as open() raises it
        smdf.read_mesh(str(tmp_path / "missing.off"))
    with pytest.raises(IsADirectoryError):
        smdf.read_mesh(str(tmp_path))


def test_repair_mesh_in_memory_is_read_mesh_of_the_file(tmp_path):
    # a cube of quads with a flipped quad, a repeated point and a point no face uses: the arrays
    # repaired in memory are the file's repaired mesh, bit for bit, with the same maps
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1],
                  [7, 7, 7], [1, 0, 0]], dtype=float)
    F = np.array([[0, 3, 2, 1], [7, 6, 5, 4], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]])
    F[3] = [9, 2, 6, 5]  # vertex 1 by its repeated point
    path = tmp_path / "cube.off"
    path.write_text("OFF\n10 6 0\n" + "".join("%r %r %r\n" % tuple(p) for p in V) +
                    "".join("4 %d %d %d %d\n" % tuple(f) for f in F))
    from_file = smdf.read_mesh(path, with_maps=True)
    repaired = smdf.repair_mesh(V, F, with_maps=True)
    assert isinstance(repaired, tuple) and len(repaired) == 2
    assert np.array_equal(repaired.V, from_file.V) and np.array_equal(repaired.F, from_file.F)
    assert repaired.repairs == from_file.repairs
    assert repaired.repairs["merged_points"] == 1 and repaired.repairs["faces_reoriented"] == 2
    assert repaired.repairs["polygons_triangulated"] == 6 and repaired.repairs["unused_vertices_removed"] == 2
    for key in from_file.maps:
        assert np.array_equal(repaired.maps[key], from_file.maps[key])
    assert smdf.compute_globally_optimal_directions(*repaired).index_sum == 8
    # polygons of several sizes as a list; pickling keeps what the repair said
    listed = smdf.repair_mesh(V[:8], [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5], [0, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6],
                                      [3, 0, 4, 7]])
    assert listed.F.shape == (12, 3) and listed.repairs["polygons_triangulated"] == 5
    again = pickle.loads(pickle.dumps(listed))
    assert np.array_equal(again.F, listed.F) and again.repairs == listed.repairs and again.maps is None


def test_repair_mesh_keeps_a_clean_mesh(shared):
    V, F = smdf.read_mesh(os.path.join(shared, "spot.off"))
    W, G = repaired = smdf.repair_mesh(V, F)
    assert np.array_equal(V, W) and np.array_equal(F, G) and sum(repaired.repairs.values()) == 0


@pytest.mark.parametrize("V,F,error", [
    ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 3]], ValueError),
    ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1]], ValueError),
    ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2], [0, 1]], ValueError),
    ([[0, 0, 0], [1, 0, 0], [np.nan, 1, 0]], [[0, 1, 2]], ValueError),
    ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 1]], ValueError),
    ([[0, 0], [1, 0], [0, 1]], [[0, 1, 2]], ValueError),
    ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], np.zeros((0, 3), dtype=int), ValueError),
    ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2.5]], ValueError),
    ([[0, 0, 0], [1, 0, 0], [0, 1, 0]], "abc", TypeError),
])
def test_repair_mesh_refuses_in_one_line(V, F, error):
    with pytest.raises(error) as caught:
        smdf.repair_mesh(np.array(V, dtype=float), F)
    assert "\n" not in str(caught.value)


def test_random_arrays_never_crash():
    rng = np.random.default_rng(5)
    for _ in range(200):
        nv, nf = rng.integers(0, 8, size=2)
        V = rng.normal(size=(nv, 3)) * 10.0 ** rng.integers(-5, 5)
        F = rng.integers(-1, max(nv, 1) + 1, size=(nf, 3))
        try:
            r = smdf.compute_globally_optimal_directions(V, F, degree=int(rng.integers(1, 5)))
            assert np.all(np.isfinite(r.directions))
        except (ValueError, RuntimeError):
            pass


def test_meshio_example(tmp_path):
    meshio = pytest.importorskip("meshio")
    V, F = sphere()
    mesh = tmp_path / "sphere.off"
    meshio.write(str(mesh), meshio.Mesh(V, [("triangle", F)]))
    script = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "Surface_mesh_direction_fields", "python",
                          "cross_field_meshio.py")
    out = tmp_path / "field.vtu"
    subprocess.run([sys.executable, script, str(mesh), str(out)], check=True, capture_output=True)
    m = meshio.read(str(out))
    assert m.point_data["direction_0"].shape == V.shape
    assert abs(m.cell_data["singularity_index"][0].sum() - 2) < 1e-12  # chi = 2


@pytest.mark.parametrize("writer,option,name", [
    ("write_vtk", "--vtk", "f.vtu"), ("write_vtk", "--vtk", "f.vtk"),
    ("write_vtk_singularities", "--vtk-singularities", "s.vtu"), ("write_ply", "--ply", "f.ply"),
    ("write_rosy", "--rosy", "f.rosy"), ("write_ffield", "--ffield", "f.ffield"),
    ("write_singularity_list", "--singularity-list", "f.txt")])
def test_writers_write_the_programs_files(program, shared, tmp_path, writer, option, name):
    mesh = os.path.join(shared, "spot.off")
    V, F = smdf.read_mesh(mesh)
    r = smdf.compute_globally_optimal_directions(V, F, degree=4)
    ours, theirs = tmp_path / ("py_" + name), tmp_path / ("cli_" + name)
    getattr(smdf, writer)(str(ours), V, F, r)
    subprocess.run([program, mesh, option, str(theirs), "--quiet"], check=True, capture_output=True)
    assert ours.read_bytes() == theirs.read_bytes()
    assert sorted(os.listdir(tmp_path)) == sorted(["py_" + name, "cli_" + name])


@pytest.mark.parametrize("writer,option,name", [
    ("write_vtk", "--vtk", "f.vtu"), ("write_vtk", "--vtk", "f.vtk"),
    ("write_vtk_singularities", "--vtk-singularities", "s.vtk"), ("write_rosy", "--rosy", "f.rosy"),
    ("write_ffield", "--ffield", "f.ffield"), ("write_rawfield", "--rawfield", "f.rawfield"),
    ("write_sing", "--sing", "f.sing"), ("write_matching", "--matching", "f.matching")])
def test_face_field_writers_write_the_programs_files(program, shared, tmp_path, writer, option, name):
    mesh = os.path.join(shared, "spot.off")
    V, F = smdf.read_mesh(mesh)
    field = smdf.compute_face_directions(V, F, degree=4)
    ours, theirs = tmp_path / ("py_" + name), tmp_path / ("cli_" + name)
    assert getattr(smdf, writer)(str(ours), V, F, field) is True
    subprocess.run([program, mesh, "--on", "faces", option, str(theirs), "--quiet"], check=True, capture_output=True)
    assert ours.read_bytes() == theirs.read_bytes()


def test_singularity_cancellation_as_the_program(program, shared, tmp_path):
    mesh = os.path.join(shared, "cow.off")
    V, F = smdf.read_mesh(mesh)
    smooth = smdf.compute_face_directions(V, F)
    fewer = smdf.compute_face_directions(V, F, singularity_cancellation_radius=0.07)
    assert fewer.cancelled_pairs > 0 and fewer.prescribed and fewer.solves == ["parallel section"]
    assert len(fewer.singular_vertices) + 2 * fewer.cancelled_pairs == len(smooth.singular_vertices)
    assert fewer.index_sum == smooth.index_sum == 8
    assert set(map(tuple, fewer.singular_vertices.tolist())) <= set(map(tuple, smooth.singular_vertices.tolist()))
    out = subprocess.run([program, mesh, "--on", "faces", "--cancel-singularities", "0.07", "--json"],
                         check=True, capture_output=True, text=True).stdout
    d = json.loads(out)
    assert d["cancelled_pairs"] == fewer.cancelled_pairs and d["singular_vertices"] == len(fewer.singular_vertices)
    assert pickle.loads(pickle.dumps(fewer)).cancelled_pairs == fewer.cancelled_pairs
    # with features the field is turned, not replaced: the faces along the features keep their directions
    aligned = smdf.compute_face_directions(V, F, feature_angle=35.0)
    turned = smdf.compute_face_directions(V, F, singularity_cancellation_radius=0.1, feature_angle=35.0)
    assert turned.cancelled_pairs > 0 and not turned.prescribed
    assert len(turned.singular_vertices) + 2 * turned.cancelled_pairs == len(aligned.singular_vertices)
    assert turned.index_sum == aligned.index_sum == 8
    assert set(map(tuple, turned.singular_vertices.tolist())) <= set(map(tuple, aligned.singular_vertices.tolist()))
    sharp = tmp_path / "cow.sharp"
    out = subprocess.run([program, mesh, "--on", "faces", "--feature-angle", "35", "--cancel-singularities", "0.1",
                          "--sharp", str(sharp), "--json"], check=True, capture_output=True, text=True).stdout
    assert json.loads(out)["cancelled_pairs"] == turned.cancelled_pairs
    along = np.unique([int(line.split(",")[1]) for line in sharp.read_text().split()[1:]])
    assert len(along) > 100 and np.abs(turned.face_directions[along] - aligned.face_directions[along]).max() < 1e-12
    with pytest.raises(ValueError, match="non-negative"):
        smdf.compute_face_directions(V, F, singularity_cancellation_radius=-1.0)


def test_face_field_files_for_viewers(tmp_path):
    V, F = sphere(2)
    field = smdf.compute_face_directions(V, F, degree=4)
    assert smdf.write_vtk(str(tmp_path / "f.vtu"), V, F, field) is True
    text = (tmp_path / "f.vtu").read_text()
    assert '<CellData Vectors="direction_0">' in text and "singularity_index" in text
    with pytest.raises(ValueError, match="a FaceField is written by write_vtk"):
        smdf.write_ply(str(tmp_path / "f.ply"), V, F, field)
    with pytest.raises(ValueError, match="another mesh"):
        smdf.write_vtk(str(tmp_path / "g.vtu"), *octahedron(), field)
    assert sorted(os.listdir(tmp_path)) == ["f.vtu"]


def test_markers_of_a_field_without_singularities(tmp_path):
    V, F = torus()
    r = smdf.compute_globally_optimal_directions(V, F, degree=4, prescribed=np.zeros((0, 2), dtype=np.int64))
    assert len(r.singular_faces) == 0
    older = tmp_path / "s.vtu"
    older.write_text("an older file")
    assert smdf.write_vtk_singularities(str(older), V, F, r) is False  # meshio reads no .vtu without points
    assert os.listdir(tmp_path) == []
    assert smdf.write_vtk_singularities(str(tmp_path / "s.vtk"), V, F, r) is True
    assert smdf.write_vtk(str(tmp_path / "f.vtu"), V, F, r) is True


def test_writers_refuse(tmp_path):
    V, F = sphere(1)
    r = smdf.compute_globally_optimal_directions(V, F, degree=2)
    with pytest.raises(OSError):
        smdf.write_vtk(str(tmp_path / "no_folder" / "f.vtu"), V, F, r)
    with pytest.raises(ValueError):
        smdf.write_rosy(str(tmp_path / "f.rosy"), V, F, r)          # rosy holds crosses (n = 4) only
    with pytest.raises(ValueError):
        smdf.write_vtk(str(tmp_path / "f.vtu"), *octahedron(), r)  # computed on another mesh
    assert os.listdir(tmp_path) == []


def folded_grid(size=6):
    """A flat grid with one vertex pushed over the opposite side of a triangle of its fan."""
    V = np.array([[i, j, 0.0] for j in range(size) for i in range(size)], dtype=np.float64)
    F = []
    for j in range(size - 1):
        for i in range(size - 1):
            a, b, c, d = j * size + i, j * size + i + 1, (j + 1) * size + i + 1, (j + 1) * size + i
            F += [[a, b, c], [a, c, d]]
    centre = 2 * size + 2
    V[centre, :2] += [1.3, 0.4]  # past the side (3,2)-(3,3) of its triangle (2,2),(3,2),(3,3)
    return V, np.array(F, dtype=np.int64)


def test_folded_triangles_laid_out_in_the_tangent_plane():
    V, F = folded_grid()
    normals = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]])
    assert (normals[:, 2] < 0).any()  # the grid is folded
    r = smdf.compute_globally_optimal_directions(V, F, degree=4)
    assert r.tangent_plane_vertices >= 3
    assert np.allclose(np.linalg.norm(r.directions, axis=1), 1.0)
    assert np.allclose(r.directions[:, 2], 0.0, atol=1e-12)  # in the plane's tangent plane, also at the fold
    flat_V, flat_F = folded_grid()
    flat_V[2 * 6 + 2, :2] = [2.0, 2.0]
    assert smdf.compute_globally_optimal_directions(flat_V, flat_F, degree=4).tangent_plane_vertices == 0


def test_integer_arrays_are_not_truncated():
    with pytest.raises(ValueError) as e:
        smdf.compute_globally_optimal_directions(V0, F0 + 0.7)
    assert "integers" in str(e.value)
    whole = smdf.compute_globally_optimal_directions(V0, F0.astype(np.float64), degree=4)  # whole numbers: taken
    assert np.array_equal(whole.directions, smdf.compute_globally_optimal_directions(V0, F0, degree=4).directions)
    with pytest.raises(TypeError):
        smdf.compute_globally_optimal_directions(V0, F0.astype(str))


def test_a_constraint_on_an_isolated_vertex_is_refused():
    V = np.vstack([V0, [[5.0, 5.0, 5.0]]])  # vertex 6 belongs to no face
    with pytest.raises(ValueError) as e:
        smdf.compute_globally_optimal_directions(V, F0, constraints=(np.array([6]), np.array([[1.0, 0, 0]])))
    assert "no face" in str(e.value)


def test_threads_sharing_one_object_get_their_own_fields():
    V, F = sphere(2)
    degrees = [1, 2, 4, 6]
    expected = {n: smdf.compute_globally_optimal_directions(V, F, degree=n) for n in degrees}
    field = smdf.DirectionField(V, F)
    wrong = []
    def work(n):
        for _ in range(15):
            r = field.compute(degree=n)
            if not (r.degree == n and np.array_equal(r.directions, expected[n].directions) and
                    np.array_equal(r.magnitudes, expected[n].magnitudes) and
                    np.array_equal(r.singular_faces, expected[n].singular_faces)):
                wrong.append(n)
    threads = [threading.Thread(target=work, args=(n,)) for n in degrees]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert wrong == []


def test_an_object_made_without_init_is_refused():
    bare = smdf.DirectionField.__new__(smdf.DirectionField)
    with pytest.raises(TypeError):
        bare.compute(degree=4)
    with pytest.raises(TypeError):
        bare.construction_ms


def test_writers_write_through_links_devices_and_pipes(tmp_path):
    V, F = sphere(1)
    r = smdf.compute_globally_optimal_directions(V, F, degree=4)
    smdf.write_vtk(tmp_path / "plain.vtk", V, F, r)  # an os.PathLike
    expected = (tmp_path / "plain.vtk").read_bytes()
    (tmp_path / "target.vtk").write_text("old")
    os.symlink("target.vtk", tmp_path / "link.vtk")
    smdf.write_vtk(str(tmp_path / "link.vtk"), V, F, r)
    assert os.path.islink(tmp_path / "link.vtk") and (tmp_path / "target.vtk").read_bytes() == expected
    smdf.write_vtk("/dev/null", V, F, r)
    assert os.path.exists("/dev/null") and not os.path.isfile("/dev/null")
    fifo = tmp_path / "pipe.vtk"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(open(fifo, "rb").read()))
    reader.start()
    smdf.write_vtk(str(fifo), V, F, r)
    reader.join()
    assert got == [expected] and not os.path.isfile(fifo)
    assert sorted(os.listdir(tmp_path)) == ["link.vtk", "pipe.vtk", "plain.vtk", "target.vtk"]


def test_writers_leave_other_files_alone(tmp_path):
    V, F = sphere(1)
    r = smdf.compute_globally_optimal_directions(V, F, degree=4)
    (tmp_path / "out.vtk.partial").write_text("the user's")
    (tmp_path / "victim").write_text("keep")
    with pytest.raises(ValueError):
        smdf.write_vtk(str(tmp_path / "victim") + "\x00.vtu", V, F, r)
    with pytest.raises(ValueError):
        smdf.write_rosy(str(tmp_path / "out.vtk"), V, F, smdf.compute_globally_optimal_directions(V, F, degree=2))
    assert (tmp_path / "victim").read_text() == "keep"
    assert (tmp_path / "out.vtk.partial").read_text() == "the user's"
    failures = []
    def work():
        for _ in range(10):
            try:
                smdf.write_vtk(str(tmp_path / "out.vtk"), V, F, r)
            except OSError as e:
                failures.append(e)
    threads = [threading.Thread(target=work) for _ in range(3)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert failures == []
    assert sorted(os.listdir(tmp_path)) == ["out.vtk", "out.vtk.partial", "victim"]
