"""vissort.batch: orders, renders and collisions of many frames of a scene, in this process or
on a Dask cluster (docs/batch.md).

The frames are cut into contiguous chunks, one task each, so that each keeps vissort's
frame-to-frame coherence (a chunk of an order or render computes the frame before it first, to
seed its order). A scene travels as what every process can load: a builtin specification, a
file's path, or a static vissort.Scene's arrays (sent to each worker once). Results come back in
frame order with one table of per-frame statistics: a pandas DataFrame when pandas is installed,
else a list of dicts.

    import vissort.batch
    from distributed import Client
    result = vissort.batch.render("builtin:bunnies", frames=300, size=(1024, 768),
                                  path="orbit", output="out/frame_%04d.png", client=Client())
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any, List, Optional, Sequence, Tuple, Union

import vissort
from vissort import _vissort

from . import _outputs
from ._chunks import DEFAULT_CHUNK_FRAMES, Chunk, cut
from ._runner import run
from ._tasks import FrameResult, Job, keep_scene, load_scene, scene_key

__all__ = ["BatchResult", "DEFAULT_CHUNK_FRAMES", "collide", "order", "render"]

SceneSpec = Union[str, "os.PathLike[str]", vissort.Scene]


@dataclass
class BatchResult:
    """A batch's frames in order: their numbers, their results (orders, pair arrays, images or
    image files) and one row of statistics each (frame, time_s, then the call's stats)."""

    frame_numbers: List[int]
    results: List[Any]
    stats: Any  # a pandas DataFrame when pandas is installed, else a list of dicts
    cycles: Optional[List[List[Any]]] = None  # order: each frame's cycles (uint32 id arrays)

    def __len__(self) -> int:
        return len(self.results)


def _table(rows: List[dict]) -> Any:
    try:
        import pandas
    except ImportError:
        return rows
    return pandas.DataFrame(rows)


@dataclass(frozen=True)
class _SceneSource:
    """How a batch's scene reaches the workers: spec, a builtin specification or a path (loaded
    by each worker; here too, while the tasks start: see _run), or for a loaded static Scene its
    content key with its pickled arrays (data)."""

    spec: str
    data: Optional[bytes] = None


def _scene_source(scene: Any) -> _SceneSource:
    if isinstance(scene, vissort.Scene):
        if scene.is_dynamic:
            raise ValueError(f"the dynamic scene '{scene.name}' cannot travel as arrays (its "
                             "motion is code): give its builtin specification or file path")
        key, data = scene_key(scene)
        keep_scene(key, scene)  # a batch run here uses the caller's scene as it is
        return _SceneSource(key, data)
    if not isinstance(scene, (str, os.PathLike)):
        raise ValueError("scene must be a builtin specification, a path or a static "
                         f"vissort.Scene, got {scene!r}")
    return _SceneSource(os.fspath(scene))


def _size(size: Sequence[int]) -> Tuple[int, int]:
    if (len(size) != 2 or any(isinstance(v, bool) or not isinstance(v, int) or v < 1
                              for v in size)):
        raise ValueError(f"size must be (width, height), two positive integers, got {size!r}")
    return int(size[0]), int(size[1])


def _check_pattern(output: str, frames: int) -> None:
    # The command line's patterns: one %d field (flags 0-9 only), no other '%'.
    if not _vissort._is_frame_pattern(output):
        raise ValueError(f"output must hold one integer field such as %04d for the frame, got "
                         f"'{output}'")
    folder = os.path.dirname(output % 0) or "."
    if not os.path.isdir(folder):
        raise ValueError(f"output folder '{folder}' does not exist")


def _check_inputs_kept(scene: Any, source: _SceneSource, output: str, frames: range) -> None:
    """ValueError before any work when a frame file would replace a file the scene reads (a
    file's scene is loaded here first, so that a JSON scene's meshes are known: load_scene
    keeps it for a batch run in this process)."""
    if not isinstance(scene, vissort.Scene) and not source.spec.startswith("builtin:"):
        scene = load_scene(source.spec)
    _outputs.check(_outputs.scene_inputs(scene, source.spec),
                   [_outputs.FileUse("output", output, frames)])


def _run(job: Job, source: _SceneSource, first: int, frames: int, chunk_frames: Optional[int],
         client: Any, progress: Optional[bool]) -> BatchResult:
    chunks: List[Chunk] = cut(first, frames, chunk_frames, seeded=job.coherent)
    # The scene is loaded here as well, so that one that cannot be loaded fails the batch at once
    # with the loader's one-line error rather than once per task: before anything runs when the
    # batch runs here (which then uses it), while the workers start on it otherwise. A scene
    # given as a Scene is already loaded, and travels as its arrays.
    done: List[FrameResult] = run(job, chunks, client=client, progress=progress,
                                  check=lambda: load_scene(job.scene, source.data),
                                  scene_data=source.data if client is not None else None)
    rows = [dict(frame=r.frame, time_s=r.time_s, **r.stats) for r in done]
    cycles = [r.cycles for r in done] if job.kind == "order" else None
    return BatchResult([r.frame for r in done], [r.value for r in done], _table(rows), cycles)


def order(scene: SceneSpec, frames: int, *, first: int = 0, path: str = "static",
          size: Sequence[int] = (1024, 1024), level: str = "object", oracle: str = "cpu",
          chunk_frames: Optional[int] = None, client: Any = None,
          progress: Optional[bool] = None) -> BatchResult:
    """The visibility orders of frames [first, first + frames) of scene, each from the camera
    the command line picks (Camera.default over the batch's frames) moved along path (static,
    orbit, flythrough or scene). results: each frame's order (uint32 ids, front to back);
    cycles: each frame's cycles.
    scene: a builtin specification or a path every worker can load, or a static vissort.Scene
    (Scene(positions, objects, ...) or a loaded file), which travels as its arrays.
    client: a distributed.Client, or None to run here. chunk_frames: frames per task (default
    DEFAULT_CHUNK_FRAMES). progress: a bar on standard error (None: when it is a terminal)."""
    source = _scene_source(scene)
    job = Job("order", source.spec, path, _size(size), first + frames,
              dict(level=level, oracle=oracle))
    return _run(job, source, first, frames, chunk_frames, client, progress)


def render(scene: SceneSpec, frames: int, *, first: int = 0, path: str = "static",
           size: Sequence[int] = (1024, 1024), output: Optional[str] = None,
           chunk_frames: Optional[int] = None, client: Any = None,
           progress: Optional[bool] = None, **options: Any) -> BatchResult:
    """Frames [first, first + frames) of scene rendered with transparency, as order's cameras.
    output: a file pattern with one integer field (out/frame_%04d.png, .png or .jpg): each frame
    is written there atomically and results are the files; None: results are the (H, W, 4) uint8
    images. options: Renderer's (method, samples, level, oracle, shading, ...)."""
    source = _scene_source(scene)
    if output is not None:
        output = os.fspath(output)
        _check_pattern(output, frames)
        _check_inputs_kept(scene, source, output, range(first, first + frames))
    job = Job("render", source.spec, path, _size(size), first + frames, dict(options), output)
    try:
        return _run(job, source, first, frames, chunk_frames, client, progress)
    finally:
        if output is not None:  # the tasks are over: no running writer's file is taken
            _outputs.remove_leftovers(output, range(first, first + frames))


def collide(scene: SceneSpec, frames: int, *, first: int = 0, method: str = "vissort",
            threads: int = 1, chunk_frames: Optional[int] = None, client: Any = None,
            progress: Optional[bool] = None, **options: Any) -> BatchResult:
    """The intersecting triangle pairs of frames [first, first + frames) of scene. results: each
    frame's (K, 2) uint32 pairs. method and threads (per task), and options (size, min_cull,
    object_stage): CollisionDetector's."""
    source = _scene_source(scene)
    job = Job("collide", source.spec, options=dict(method=method, threads=threads, **options))
    return _run(job, source, first, frames, chunk_frames, client, progress)
