"""Globally optimal smooth n-direction fields (vector, line, cross fields) on
triangle meshes, after Knoeppel, Crane, Pinkall and Schroeder (2013), from
CGAL's Surface_mesh_direction_fields package.

The functions and classes are those of the compiled extension ``_core``; the
field's two entry points are wrapped here so that their keyword arguments,
with their defaults, are visible to ``inspect.signature`` and ``help()`` (the
type stubs, ``__init__.pyi`` with ``py.typed``, describe them for mypy and
editors).
"""
import inspect
from typing import Any, Callable, Dict, Optional, Tuple

from . import _core
from ._core import *  # noqa: F401,F403
from ._core import __version__  # noqa: F401


def _keywords(*, degree: int = 4, s: float = 0.0, align: Optional[str] = None,
              curvature_estimate: str = "quadric-fit", guidance: Any = None, lambda_t: Optional[float] = None,
              alignment_weight: Optional[float] = None, eigenvalue_bound: bool = False, constraints: Any = None,
              boundary: Optional[str] = None, feature_edges: Any = None, feature_angle: Optional[float] = None,
              feature_cleanup: int = 4, prescribed: Any = None, prescribed_loop_turns: Any = None,
              intrinsic_mollification: float = 1e-6, normals: Any = None, max_iterations: int = 1000,
              tolerance: float = 1e-10, seed: int = 0,
              progress: Optional[Callable[[float], None]] = None) -> None:
    """The keyword arguments of a computation, with the defaults the C++ side applies."""


def _signature(*positional: str) -> inspect.Signature:
    leading = [inspect.Parameter(name, inspect.Parameter.POSITIONAL_ONLY) for name in positional]
    return inspect.Signature(leading + list(inspect.signature(_keywords).parameters.values()),
                             return_annotation="Result")


def compute_globally_optimal_directions(V: Any, F: Any, /, **options: Any) -> "Result":
    return _core.compute_globally_optimal_directions(V, F, **options)


class DirectionField(_core.DirectionField):
    __doc__ = _core.DirectionField.__doc__

    def compute(self, /, **options: Any) -> "Result":
        return super().compute(**options)

    def matrices(self, *, degree: int = 4, s: float = 0.0, intrinsic_mollification: float = 1e-6) -> Tuple[Any, Any]:
        """The energy matrix A (the connection Laplacian at s = 0) and the mass matrix M of the fields of
        degree n and smoothness parameter s on this mesh, as scipy.sparse CSR matrices of complex128 (scipy is
        imported here, and only here). Both are Hermitian, indexed by vertex, empty at isolated vertices, in
        the mesh's units (M scales with area). They act on Result.coefficients: the smoothest field's satisfy
        A u = lambda M u on each component, lambda its entry of Result.eigenvalues."""
        import scipy.sparse
        arrays = self._matrices(degree=degree, s=s, intrinsic_mollification=intrinsic_mollification)
        made = []
        for data, indices, indptr, n in arrays:
            made.append(scipy.sparse.csc_matrix((data, indices, indptr), shape=(n, n)).tocsr())
        return made[0], made[1]


def _face_keywords(*, degree: int = 4, align: Optional[str] = None, guidance: Any = None,
                   lambda_t: Optional[float] = None, alignment_weight: Optional[float] = None, constraints: Any = None,
                   boundary: Optional[str] = None, feature_edges: Any = None, feature_angle: Optional[float] = None,
                   feature_cleanup: int = 4, prescribed: Any = None, singularity_cancellation_radius: float = 0.0,
                   intrinsic_mollification: float = 1e-6, max_iterations: int = 1000, tolerance: float = 1e-10,
                   seed: int = 0, vertex_point_index: Any = None) -> None:
    """The keyword arguments of a field on faces, with the defaults the C++ side applies."""


def compute_face_directions(V: Any, F: Any, /, **options: Any) -> "FaceField":
    return _core.compute_face_directions(V, F, **options)


def _point_set_keywords(*, normals: Any = None, degree: int = 4, s: float = 0.0, neighbors: int = 12,
                        tolerance: float = 1e-10) -> None:
    """The keyword arguments of a field on a point set, with the defaults the C++ side applies."""


def compute_point_set_directions(P: Any, /, **options: Any) -> "PointSetField":
    return _core.compute_point_set_directions(P, **options)


class MeshArrays(tuple):
    """A repaired triangle mesh as the pair (V, F), so that ``V, F = read_mesh(path)`` unpacks it:
    V float64 of shape (|V|, 3), F int64 of shape (|F|, 3), an oriented manifold that the field functions
    take as it is. ``repairs`` is a dict of what the repair changed (counts: merged_points,
    degenerate_faces_removed, polygons_triangulated, repeated_faces_removed, faces_reoriented,
    vertices_duplicated, faces_skipped, unused_vertices_removed); ``maps`` (None unless asked for with
    with_maps=True) a dict of int64 arrays between the input and the mesh: 'vertex_of_file_vertex' (-1: a
    point no face uses; merged points share a vertex), 'file_vertex_of_vertex' and 'file_face_of_face' (the
    input polygon each triangle comes from)."""

    def __new__(cls, V: Any, F: Any, repairs: Dict[str, int], maps: Optional[Dict[str, Any]] = None) -> "MeshArrays":
        made = super().__new__(cls, (V, F))
        made.repairs = repairs
        made.maps = maps
        return made

    @property
    def V(self) -> Any:
        """float64 (|V|, 3): the vertex positions"""
        return self[0]

    @property
    def F(self) -> Any:
        """int64 (|F|, 3): the triangles, rows of indices into V"""
        return self[1]

    def __reduce__(self) -> Tuple[Any, ...]:
        return (MeshArrays, (self[0], self[1], self.repairs, self.maps))


def read_mesh(path: Any, *, with_maps: bool = False) -> MeshArrays:
    """Reads an OFF, OBJ, PLY or STL file with the command-line program's readers and repair (the same mesh,
    hence the same field): ``V, F = read_mesh(path)``; the result's ``repairs`` (and ``maps`` with
    with_maps=True) say what the repair changed. A file that cannot be opened raises the OSError open()
    raises; one that holds no usable mesh, a one-line ValueError."""
    return MeshArrays(*_core._read_mesh(path, with_maps=with_maps))


def repair_mesh(V: Any, F: Any, /, *, with_maps: bool = False) -> MeshArrays:
    """Repairs arrays in memory as read_mesh() repairs a file's: V (|V|, 3) numbers, F an integer array of
    shape (|F|, k) with k >= 3, or a list of polygons of any sizes. Merges repeated points, drops degenerate
    and repeated faces, triangulates polygons, orients the faces consistently and splits non-manifold
    vertices: ``V, F = repair_mesh(V, F)``; ``repairs`` and ``maps`` as for read_mesh()."""
    return MeshArrays(*_core._repair_mesh(V, F, with_maps=with_maps))


compute_point_set_directions.__doc__ = _core.compute_point_set_directions.__doc__
compute_point_set_directions.__signature__ = inspect.Signature(  # type: ignore[attr-defined]
    [inspect.Parameter("P", inspect.Parameter.POSITIONAL_ONLY)] +
    list(inspect.signature(_point_set_keywords).parameters.values()), return_annotation="PointSetField")
compute_face_directions.__doc__ = _core.compute_face_directions.__doc__
compute_face_directions.__signature__ = inspect.Signature(  # type: ignore[attr-defined]
    [inspect.Parameter(name, inspect.Parameter.POSITIONAL_ONLY) for name in ("V", "F")] +
    list(inspect.signature(_face_keywords).parameters.values()), return_annotation="FaceField")
compute_globally_optimal_directions.__doc__ = _core._compute_doc
compute_globally_optimal_directions.__signature__ = _signature("V", "F")  # type: ignore[attr-defined]
DirectionField.compute.__doc__ = _core._compute_doc
DirectionField.compute.__signature__ = _signature("self")  # type: ignore[attr-defined]
__doc__ = _core.__doc__
# the names used above are not the package's: dir() lists only its own
del Any, Callable, Dict, Optional, Tuple, inspect
