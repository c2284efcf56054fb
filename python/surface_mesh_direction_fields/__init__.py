"""Globally optimal smooth n-direction fields (vector, line, cross fields) on
triangle meshes, after Knoeppel, Crane, Pinkall and Schroeder (2013), from
CGAL's Surface_mesh_direction_fields package.

The functions and classes are those of the compiled extension ``_core``; the
type stubs (``__init__.pyi``, ``py.typed``) describe them for mypy and editors.
"""
from ._core import *  # noqa: F401,F403
from ._core import __doc__ as _core_doc, __version__  # noqa: F401

__doc__ = _core_doc
