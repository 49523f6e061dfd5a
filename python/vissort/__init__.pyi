"""vissort: visibility orderings of triangles from occlusion queries, exact order-independent
transparency and collision detection, on numpy arrays (docs/python.md).

Type stubs for the compiled module vissort._vissort (python/src/*.cpp), which the package
re-exports. Keep them in step with the bindings.
"""

import os
from typing import (
    Any,
    Literal,
    Optional,
    Sequence,
    SupportsFloat,
    SupportsIndex,
    TypedDict,
    Union,
)

import numpy as np
import numpy.typing as npt

__all__ = [
    "Camera",
    "CollisionDetector",
    "FRAME_INTERVAL",
    "Grid",
    "OrderResult",
    "Orderer",
    "Renderer",
    "Scene",
    "SceneObject",
    "VolumeRenderer",
    "__version__",
    "builtin",
    "builtin_scenes",
    "collide",
    "has_gl",
    "load",
    "load_grid",
    "order",
    "render",
    "render_volume",
    "write_image",
]

# The library's version, as `vissort --version` prints it.
__version__: str
# Seconds between frames: frame f of a run is at time f * FRAME_INTERVAL (1/30), as the command
# line's --frames.
FRAME_INTERVAL: float
# Whether the module was built with OpenGL: without it, render(), Renderer and the "gl" oracle
# raise RuntimeError.
has_gl: bool

# Names of the choices the bindings accept (anything else is a ValueError naming them).
_Level = Literal["object", "triangle", "multistage"]
_Oracle = Literal["cpu", "cpu-reference", "exact", "gl"]
_RenderMethod = Literal[
    "vissort", "unsorted", "centroid", "peel", "dual-peel", "linked-list", "weighted"
]
_Shading = Literal["lit", "flat", "membrane"]
_Samples = Literal[1, 2, 4, 8]
_Check = Literal["auto", "on", "off"]
_CollisionMethod = Literal["vissort", "brute", "bullet", "fcl"]
_VolumeMethod = Literal["vissort", "centroid", "mpvo", "lists", "raycast"]
_TransferPreset = Literal["cool-warm", "fire", "grey", "bands"]
# A transfer function: a preset, a JSON file's path, or rows (scalar, r, g, b, extinction).
_Transfer = Union[_TransferPreset, str, npt.ArrayLike]

# (width, height): any sequence of two integers (not bools), each side 1..16384, at most
# 67108864 (16384 * 16384 / 4) pixels; anything else is a ValueError.
_Size = Sequence[SupportsIndex]
_Vec3 = tuple[float, float, float]
# A colour: (r, g, b) or (r, g, b, a), each in [0, 1].
_Colour = Union[tuple[float, float, float], tuple[float, float, float, float]]
# time=: seconds, any number (int, float, a numpy scalar); anything else is a ValueError.
_Seconds = Union[SupportsFloat, SupportsIndex]

# The stats dicts (plain dicts at run time). Written as assignments, not classes, so that every
# class of this file is one of the module's.
_OrderStats = TypedDict(
    "_OrderStats",
    {
        "queries": int,
        "draws": int,
        "clears": int,
        "iterations": int,
        "stuck_iterations": int,
        "cycle_queries": int,
        "cycle_draws": int,
        "ms": float,
    },
)
# Empty until the first frame is rendered.
_RenderStats = TypedDict(
    "_RenderStats",
    {
        "order_ms": float,
        "render_ms": float,
        "total_ms": float,
        "passes": int,
        "fragments": int,
        "groups": int,
        "repaired_pixels": int,
        "triangles": int,
        "boxed_objects": int,
        "culled_objects": int,
        "queries": int,
        "draws": int,
        "clears": int,
        "iterations": int,
        "stuck_iterations": int,
        "cycle_queries": int,
        "cycle_draws": int,
        "hinted_cycles": int,
        "graph_passes": int,
        # With highlight_collisions only.
        "colliding_pairs": int,
        "colliding_triangles": int,
        "collision_ms": float,
    },
    total=False,
)
# Empty until the first frame is collided.
_CollisionStats = TypedDict(
    "_CollisionStats",
    {
        "box_object_pairs": int,
        "object_pairs": int,
        "box_triangle_pairs": int,
        "triangle_pairs": int,
        "intersecting": int,
        "colliding_object_pairs": int,
        "candidate_objects": int,
        "directions": int,
        "queries": int,
        "update_ms": float,
        "cull_ms": float,
        "exact_ms": float,
        "total_ms": float,
    },
    total=False,
)

class SceneObject:
    """One object of a scene: a range of its triangles."""

    @property
    def name(self) -> str: ...
    @property
    def colour(self) -> tuple[float, float, float, float]:
        """(r, g, b, a), each in [0, 1]."""
    @property
    def transparent(self) -> bool: ...
    @property
    def first_triangle(self) -> int: ...
    @property
    def triangle_count(self) -> int: ...
    @property
    def parts(self) -> list[dict[str, Any]]:
        """The meshes an object is made of (load(objects='node' or 'file')), each a dict of
        name, colour, first_triangle, triangle_count; empty for an object of one mesh."""
    def __repr__(self) -> str: ...

class Scene:
    """Objects made of triangles, with colours, transparency, cameras and, for a dynamic scene,
    motion; load() and builtin() make one, Scene(positions, objects, ...) one from arrays. A
    static scene pickles as its arrays (to another process, a Dask worker); a dynamic one
    raises TypeError (its motion is code: pass its specification instead)."""

    def __init__(
        self,
        positions: npt.ArrayLike,
        objects: Optional[npt.ArrayLike] = None,
        *,
        triangles: Optional[npt.ArrayLike] = None,
        colours: Optional[Union[_Colour, Sequence[_Colour], npt.ArrayLike]] = None,
        transparent: Optional[Union[bool, npt.ArrayLike]] = None,
        names: Optional[Sequence[str]] = None,
        camera: Optional[Camera] = None,
        name: str = "arrays",
    ) -> None:
        """A static scene from arrays: positions (T, 3, 3), or vertices (V, 3) with triangles
        (T, 3); objects (K, 2) (first triangle, count) or (K,) counts tiling the triangles in
        order (None: one object); colours one (r, g, b[, a]) or one per object, in [0, 1]
        (None: grey); transparent one bool or one per object (None: alpha below 1); names one
        string per object (None: "object 0", ...); camera the scene's own. ValueError naming
        the problem."""

    @property
    def name(self) -> str: ...
    @property
    def triangle_count(self) -> int: ...
    @property
    def objects(self) -> list[SceneObject]:
        """Every object, in object id order."""
    @property
    def object_ranges(self) -> npt.NDArray[np.uint32]:
        """(K, 2) uint32: each object's first triangle and triangle count."""
    @property
    def positions(self) -> npt.NDArray[np.float32]:
        """(T, 3, 3) float32: the corners of every triangle at time 0 (a copy)."""
    @property
    def triangles(self) -> npt.NDArray[np.uint32]:
        """(T, 3) uint32: each triangle's vertices in positions.reshape(-1, 3) (scenes keep
        every triangle's own corners)."""
    @property
    def is_dynamic(self) -> bool: ...
    @property
    def source_files(self) -> list[str]:
        """Every file loading the scene read (a mesh file and what its reader opened beside it,
        a JSON scene and its meshes' files); empty for built-in scenes and arrays.
        vissort.batch refuses an output that is one of them."""
    def frame(self, t: float) -> npt.NDArray[np.float32]:
        """(T, 3, 3) float32: the corners at time t seconds (static scenes: t = 0)."""
    @property
    def bounds(self) -> tuple[_Vec3, _Vec3]:
        """((min x, y, z), (max x, y, z)) at time 0."""
    @property
    def camera(self) -> Optional[Camera]:
        """The scene's own camera (a mesh file's first usable one), or None."""
    @property
    def cameras(self) -> list[tuple[str, Optional[Camera], str]]:
        """The cameras a mesh file stores: (name, Camera or None, problem) each."""
    def __repr__(self) -> str: ...

def load(path: Union[str, os.PathLike[str]], *,
         objects: Optional[Literal["mesh", "node", "file"]] = None) -> Scene:
    """A scene from a mesh file (OBJ, PLY, STL, glTF, Collada, ... through assimp), a JSON
    scene, or a 'builtin:NAME?key=value' specification, as the command line reads it. path: a
    str or an os.PathLike (a pathlib.Path). objects: how a mesh file's meshes become objects,
    'mesh' (one each, the default), 'node' or 'file' (the command line's --objects). ValueError
    naming the problem when it cannot be read."""

def builtin(name: str, **parameters: Union[int, float, str]) -> Scene:
    """A built-in scene by name with its parameters: builtin('bunnies', n=18, seed=1);
    builtin_scenes() lists them. True and False are passed as 1 and 0."""

def builtin_scenes() -> dict[str, str]:
    """Every built-in scene's name and its one-line description."""

class Camera:
    """A camera: perspective (eye, target, up, vertical field of view) or orthographic along a
    direction, framing the geometry's bounding sphere; the command line's
    --eye/--target/--up/--fov and --ortho-dir. Made by perspective(), orthographic() and
    default()."""

    @staticmethod
    def perspective(
        eye: npt.ArrayLike,
        target: npt.ArrayLike,
        up: npt.ArrayLike = (0, 1, 0),
        fov_deg: float = 45.0,
    ) -> Camera:
        """Looks from eye at target; fov_deg is the vertical field of view in (0, 180)."""
    @staticmethod
    def orthographic(direction: npt.ArrayLike, scene: Optional[Scene] = None) -> Camera:
        """Looks along direction, framing the bounding sphere of the geometry each call is
        given (as the command line does, frame by frame), or of scene at time 0 if given.
        ValueError when scene is neither a Scene nor None."""
    @staticmethod
    def default(scene: Scene, size: _Size = (1024, 1024), frames: int = 1) -> Camera:
        """The command line's camera when none is given: the scene's own, else its geometry
        framed for an image of that size (a dynamic scene over its first `frames` frames, as
        the command line's --frames N).
        ValueError for frames outside 1 to 100000."""
    @staticmethod
    def of_scene(
        scene: Scene,
        *,
        camera: Union[str, int, None] = None,
        eye: Optional[_Vec3] = None,
        target: Optional[_Vec3] = None,
        up: Optional[_Vec3] = None,
        fov_deg: Optional[float] = None,
        ortho_dir: Optional[_Vec3] = None,
        azimuth: Optional[float] = None,
        elevation: Optional[float] = None,
        distance: Optional[float] = None,
        size: _Size = (1024, 1024),
        frames: int = 1,
    ) -> Camera:
        """The camera the command line chooses for these options (--camera, --eye, --target,
        --up, --fov, --ortho-dir, --azimuth, --elevation, --distance, --size, --frames): the
        same policy and the same errors (ValueError), named as these keywords. camera: a
        camera the file stores, by name or index (Scene.cameras)."""
    def on_path(
        self, scene: Scene, path: Literal["static", "orbit", "flythrough", "scene"], frame: int
    ) -> Camera:
        """This camera moved to frame `frame` (>= 0) of a camera path over scene, as the command
        line's --path with --frames: the path turns about the scene's bounds at time 0; scene
        follows its own key frames. ValueError for another path, a negative frame or a camera the
        path makes unusable."""
    @property
    def projection(self) -> Literal["perspective", "orthographic"]: ...
    @property
    def eye(self) -> Optional[_Vec3]:
        """None for an orthographic camera."""
    @property
    def target(self) -> Optional[_Vec3]:
        """None for an orthographic camera."""
    @property
    def up(self) -> Optional[_Vec3]:
        """None for an orthographic camera."""
    @property
    def fov_deg(self) -> Optional[float]:
        """None for an orthographic camera."""
    @property
    def direction(self) -> _Vec3:
        """The view direction."""
    def __repr__(self) -> str: ...

class OrderResult:
    """A visibility order and what it cost."""

    @property
    def order(self) -> npt.NDArray[np.uint32]:
        """uint32 ids front to back: objects at object level, else triangles (at multistage,
        those of the objects)."""
    @property
    def cycles(self) -> list[npt.NDArray[np.uint32]]:
        """Each cycle the order met: its ids, ascending (uint32 arrays)."""
    @property
    def stats(self) -> _OrderStats:
        """queries, draws, clears, iterations, stuck_iterations, cycle_queries, cycle_draws,
        ms: as the command line's --json."""
    @property
    def level(self) -> _Level: ...
    @property
    def camera(self) -> Camera:
        """The camera the order was computed for."""
    def __repr__(self) -> str: ...

class Orderer:
    """Orders successive frames of the same objects, each frame starting from the last one's
    order: about linear work on coherent frames. One call at a time: a second thread waits."""

    def __init__(
        self,
        objects: Union[Scene, npt.ArrayLike, None] = None,
        *,
        level: _Level = "object",
        oracle: _Oracle = "cpu",
        threads: int = 1,
    ) -> None:
        """objects: a Scene (kept alive by the orderer), integer (first, count) ranges (K, 2)
        or counts (K,), or None: the objects of the Scene the first frame
        is, else every triangle its own object. level: object, triangle or multistage. oracle:
        cpu, cpu-reference, exact or gl. threads: the cpu oracle's, the calling one included
        (default 1; 0: one per core; the order never depends on it)."""
    def order(
        self,
        positions: Union[Scene, npt.ArrayLike, None] = None,
        camera: Optional[Camera] = None,
        size: _Size = (1024, 1024),
        *,
        triangles: Optional[npt.ArrayLike] = None,
        time: Optional[_Seconds] = None,
    ) -> OrderResult:
        """Orders positions front to back. positions: a Scene (at time, default 0) or triangle
        corners, float (T, 3, 3) or (V, 3) with triangles=(T, 3) indices; None: the orderer's
        Scene. camera: a Camera (ValueError for anything else but None); default the command
        line's (a scene's own, else the geometry framed), a scene's kept while the scene and
        size stay the same. size: (width, height) of the oracle's image. Releases the GIL."""

def order(
    positions: Union[Scene, npt.ArrayLike],
    objects: Optional[npt.ArrayLike] = None,
    camera: Optional[Camera] = None,
    size: _Size = (1024, 1024),
    level: _Level = "object",
    oracle: _Oracle = "cpu",
    *,
    triangles: Optional[npt.ArrayLike] = None,
    time: Optional[_Seconds] = None,
    threads: int = 1,
) -> OrderResult:
    """One frame's order (Orderer keeps it for the next). objects as Orderer's (None with a
    Scene, which brings its own). Orders positions front to back. positions: a Scene (at time,
    default 0) or triangle corners, float (T, 3, 3) or (V, 3) with triangles=(T, 3) indices.
    camera: a Camera (ValueError for anything else but None); default the command line's (a
    scene's own, else the geometry framed). size: (width, height) of the oracle's image.
    threads as Orderer's. Releases the GIL."""

class Renderer:
    """Renders frames of one scene with transparency; each frame starts from the last one's
    order. Needs OpenGL (has_gl); RuntimeError without it."""

    def __init__(
        self,
        scene: Scene,
        *,
        method: _RenderMethod = "vissort",
        level: _Level = "object",
        oracle: _Oracle = "cpu",
        all_transparent: bool = False,
        alpha: float = 0.5,
        shading: _Shading = "lit",
        samples: _Samples = 1,
        check: _Check = "auto",
        background: npt.ArrayLike = (0.3, 0.32, 0.36, 1.0),
        highlight_collisions: bool = False,
        lod_error: float = 0.0,
        threads: int = 1,
    ) -> None:
        """method: vissort, unsorted, centroid, peel, dual-peel, linked-list or weighted. level
        and oracle: vissort's ordering (centroid's unit). all_transparent with alpha: every
        object transparent. shading: lit, flat or membrane. samples: 1, 2, 4 or 8 a pixel,
        averaged (anti-aliasing). check: auto, on or off (vissort's per-pixel check and repair).
        background: (r, g, b[, a]) in [0, 1]. highlight_collisions: the triangles that
        intersect another object's in magenta, each frame (stats then count the collisions).
        lod_error: levels of detail within that many pixels, objects out of view left out (0:
        every triangle; stats count the triangles drawn). threads: the cpu oracle's, the
        calling one included (default 1; 0: one per core; the picture never depends on it). As
        the command line's render options."""
    def render(
        self,
        camera: Optional[Camera] = None,
        size: _Size = (1024, 1024),
        *,
        time: Optional[_Seconds] = None,
        positions: Optional[npt.ArrayLike] = None,
        triangles: Optional[npt.ArrayLike] = None,
    ) -> npt.NDArray[np.uint8]:
        """An (H, W, 4) uint8 RGBA image, row 0 at the top: the scene at time (default 0), or
        at positions ((T, 3, 3), or (V, 3) with triangles) of its triangle count. camera:
        default the scene's default (Camera.default), kept while the size stays the same.
        Releases the GIL."""
    @property
    def stats(self) -> _RenderStats:
        """The last frame's costs (empty before the first frame)."""

def render(
    scene: Scene,
    camera: Optional[Camera] = None,
    size: _Size = (1024, 1024),
    *,
    method: _RenderMethod = "vissort",
    level: _Level = "object",
    oracle: _Oracle = "cpu",
    all_transparent: bool = False,
    alpha: float = 0.5,
    shading: _Shading = "lit",
    samples: _Samples = 1,
    check: _Check = "auto",
    background: npt.ArrayLike = (0.3, 0.32, 0.36, 1.0),
    highlight_collisions: bool = False,
    lod_error: float = 0.0,
    threads: int = 1,
    time: Optional[_Seconds] = None,
    positions: Optional[npt.ArrayLike] = None,
    triangles: Optional[npt.ArrayLike] = None,
) -> npt.NDArray[np.uint8]:
    """One frame as an (H, W, 4) uint8 RGBA image, row 0 at the top (Renderer renders many):
    the scene at time (default 0), or at positions ((T, 3, 3), or (V, 3) with triangles) of
    its triangle count.
    method: vissort, unsorted, centroid, peel, dual-peel, linked-list or weighted. level and
    oracle: vissort's ordering (centroid's unit). all_transparent with alpha: every object
    transparent. shading: lit, flat or membrane. samples: 1, 2, 4 or 8 a pixel, averaged
    (anti-aliasing). check: auto, on or off (vissort's per-pixel check and repair). background: (r, g, b[, a]) in [0, 1]. threads as Renderer's. As the command line's render options.
    Needs OpenGL (has_gl); RuntimeError without it. Releases the GIL."""

class CollisionDetector:
    """Finds the intersecting triangle pairs of the same objects frame after frame, reusing
    what each frame learnt. One call at a time: a second thread waits."""

    def __init__(
        self,
        objects: Union[Scene, npt.ArrayLike],
        *,
        method: _CollisionMethod = "vissort",
        threads: int = 1,
        size: _Size = (64, 64),
        min_cull: float = 0.25,
        object_stage: Literal["adaptive", "always", "never"] = "adaptive",
    ) -> None:
        """objects: a Scene (kept alive by the detector), or integer (first, count) ranges
        (K, 2) or counts (K,) of disjoint objects (triangles in none never collide). method:
        vissort, brute, bullet or fcl. The settings, as the command line's collide options:
        threads (vissort and bullet; the calling one included; 0: one per core), and vissort's
        size (each object-stage view, 1..4096 pixels a side), min_cull (in [0, 1]: the next
        direction only while the last culled at least this fraction of its object pairs) and
        object_stage (when the object stage runs: while it pays, every frame, or never). The
        pairs never depend on them."""
    def collide(
        self,
        positions: Union[Scene, npt.ArrayLike, None] = None,
        triangles: Optional[npt.ArrayLike] = None,
        *,
        time: Optional[_Seconds] = None,
    ) -> npt.NDArray[np.uint32]:
        """Every pair of intersecting triangles of different objects (touching counts), as a
        (K, 2) uint32 array of triangle ids, first < second, ascending. positions: a Scene (at
        time, default 0) or corners (T, 3, 3), or (V, 3) with triangles=(T, 3); None: the
        detector's Scene. Releases the GIL."""
    @property
    def stats(self) -> _CollisionStats:
        """The last frame's costs and culling (empty before the first frame)."""
    @property
    def object_pairs(self) -> Optional[npt.NDArray[np.uint32]]:
        """The last frame's colliding objects: (M, 2) object indices, first < second,
        ascending, with some intersecting triangle pair between them; None before a frame."""

def collide(
    positions: Union[Scene, npt.ArrayLike],
    objects: Optional[npt.ArrayLike] = None,
    method: _CollisionMethod = "vissort",
    *,
    triangles: Optional[npt.ArrayLike] = None,
    time: Optional[_Seconds] = None,
    threads: int = 1,
    size: _Size = (64, 64),
    min_cull: float = 0.25,
    object_stage: Literal["adaptive", "always", "never"] = "adaptive",
) -> npt.NDArray[np.uint32]:
    """One frame's pairs (CollisionDetector follows frames). objects as CollisionDetector's
    (None with a Scene, which brings its own). Every pair of intersecting triangles of
    different objects (touching counts), as a (K, 2) uint32 array of triangle ids,
    first < second, ascending. positions: a Scene (at time, default 0) or corners (T, 3, 3),
    or (V, 3) with triangles=(T, 3). threads, size, min_cull and object_stage as
    CollisionDetector's.
    Releases the GIL."""


_VolumeStats = TypedDict(
    "_VolumeStats",
    {
        "order_ms": float,
        "composite_ms": float,
        "cells": int,
        "queries": int,
        "cycles": int,
        "cells_in_cycles": int,
        "segments": int,
        "list_segments": int,
    },
)


class Grid:
    """A tetrahedral grid with a scalar per point: load_grid(path) or Grid(points, cells,
    scalars); hexahedra, wedges and pyramids are split into tetrahedra (docs/volume.md)."""

    def __init__(
        self,
        points: npt.ArrayLike,
        cells: npt.ArrayLike,
        scalars: Optional[npt.ArrayLike] = None,
        name: str = "grid",
    ) -> None:
        """points (N, 3); cells (M, 4) tetrahedra, (M, 5) pyramids, (M, 6) wedges or (M, 8)
        hexahedra, corners in VTK's order; scalars (N,) or None. ValueError naming the
        problem (an index out of range, a degenerate or inverted cell, a non-conforming grid)."""
    @property
    def name(self) -> str: ...
    @property
    def scalar_name(self) -> str: ...
    @property
    def points(self) -> npt.NDArray[np.float64]:
        """(N, 3) float64, a copy."""
    @property
    def tets(self) -> npt.NDArray[np.uint32]:
        """(M, 4) uint32: the tetrahedra, positively oriented, a copy."""
    @property
    def scalars(self) -> Optional[npt.NDArray[np.float64]]:
        """(N,) float64, a copy; None when the grid has none."""
    def facts(self) -> dict[str, Any]:
        """points, tetrahedra, file_cells, skipped_cells, bounds ((min), (max)), scalar_range
        ((min, max) or None), boundary_faces, convex: what `vissort info GRID` prints."""


def write_image(path: Union[str, os.PathLike[str]], image: npt.NDArray[np.uint8]) -> None:
    """Writes an (H, W, 4) uint8 RGBA image, row 0 at the top (as render returns it), as PNG or
    JPEG by path's extension (.png, .jpg, .jpeg). ValueError naming the problem: another shape
    or dtype, another extension, a file that cannot be written."""

def load_grid(spec: Union[str, os.PathLike[str]]) -> Grid:
    """A grid from a file (.vtk, .vtu, tetgen .node/.ele, Medit .mesh) or
    builtin:cube|torus|knot?n=CELLS; ValueError with the loader's one-line message."""


class VolumeRenderer:
    """Frames of one grid by one method, keeping vissort's last order for the next frame
    (coherence)."""

    def __init__(
        self,
        grid: Grid,
        method: _VolumeMethod = "vissort",
        *,
        oracle: _Oracle = "cpu",
        threads: int = 0,
    ) -> None: ...
    def render(
        self,
        camera: Optional[Camera] = None,
        *,
        size: _Size = (512, 512),
        tf: _Transfer = "cool-warm",
        tf_range: Literal["normalized", "absolute"] = "normalized",
        density: float = 4.0,
        background: Sequence[float] = (0.3, 0.32, 0.36, 1.0),
    ) -> npt.NDArray[np.uint8]:
        """The picture as (H, W, 4) uint8; camera None frames the grid. Releases the GIL."""
    @property
    def stats(self) -> _VolumeStats:
        """The last frame's costs."""


def render_volume(
    grid: Grid,
    camera: Optional[Camera] = None,
    *,
    size: _Size = (512, 512),
    method: _VolumeMethod = "vissort",
    tf: _Transfer = "cool-warm",
    tf_range: Literal["normalized", "absolute"] = "normalized",
    density: float = 4.0,
    background: Sequence[float] = (0.3, 0.32, 0.36, 1.0),
    oracle: _Oracle = "cpu",
) -> npt.NDArray[np.uint8]:
    """One frame by one method (VolumeRenderer follows frames), as (H, W, 4) uint8: emission and
    absorption with the transfer function tf (docs/volume.md's law). Releases the GIL."""
