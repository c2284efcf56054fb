"""Globally optimal smooth n-direction fields on triangle meshes (CGAL Surface_mesh_direction_fields)."""
from typing import Any, Dict, List, Optional, Tuple

import numpy as np
import numpy.typing as npt

__version__: str

class InvalidInputError(ValueError): ...
class SolverFailureError(RuntimeError): ...

class Result:
    directions: npt.NDArray[np.float64]      # (|V|, 3) unit tangent directions
    magnitudes: npt.NDArray[np.float64]      # (|V|,)
    singular_faces: npt.NDArray[np.int64]    # (k, 2): face, k (index k / n)
    eigenvalues: List[float]                 # per component
    @property
    def degree(self) -> int: ...
    @property
    def iterations(self) -> int: ...
    @property
    def residual(self) -> float: ...
    @property
    def converged(self) -> bool: ...
    @property
    def index_sum(self) -> int: ...
    @property
    def component_index_sums(self) -> List[int]: ...
    @property
    def component_euler_characteristics(self) -> List[int]: ...
    @property
    def timings(self) -> Dict[str, float]: ...

def compute_globally_optimal_directions(
    V: npt.ArrayLike, F: npt.ArrayLike, *, degree: int = 4, s: float = 0.0, align: Optional[str] = None,
    curvature_estimate: str = "quadric-fit", guidance: Optional[npt.ArrayLike] = None,
    lambda_t: Optional[float] = None, alignment_weight: Optional[float] = None, eigenvalue_bound: bool = False,
    constraints: Optional[Tuple[npt.ArrayLike, npt.ArrayLike]] = None, boundary: Optional[str] = None,
    feature_edges: Optional[npt.ArrayLike] = None, feature_angle: Optional[float] = None,
    prescribed: Optional[npt.ArrayLike] = None, max_iterations: int = 1000, tolerance: float = 1e-10,
    seed: int = 0) -> Result: ...

class DirectionField:
    def __init__(self, V: npt.ArrayLike, F: npt.ArrayLike) -> None: ...
    def compute(self, **options: Any) -> Result: ...

def read_mesh(path: str) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64], Dict[str, int]]: ...
