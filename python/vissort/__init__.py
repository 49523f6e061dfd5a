"""vissort: visibility orderings of triangles from occlusion queries, exact order-independent
transparency and collision detection, on numpy arrays (docs/python.md)."""

from . import _vissort
from ._vissort import *  # noqa: F401,F403 (the classes and functions, typed in __init__.pyi)

__version__ = _vissort.__version__
__all__ = sorted(name for name in dir(_vissort) if not name.startswith("_")) + ["__version__"]
