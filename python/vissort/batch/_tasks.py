"""What one chunk of a batch does, on whichever process runs it: load the scene (once per
process), compute the chunk's seed frame (unless this process has just computed it) and then its
frames in order with one orderer, renderer or collision detector (so each frame starts from the
last one's order), and return each frame's result and statistics. Everything here travels to Dask workers by pickling: the job is
plain data, never a vissort object."""

from __future__ import annotations

import ctypes
import ctypes.util
import hashlib
import os
import pickle
from collections import OrderedDict
from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Tuple

import vissort

from ._chunks import Chunk

KINDS = ("order", "render", "collide")


@dataclass(frozen=True)
class Job:
    """A batch, as plain data. scene: a builtin specification, a path every worker can read, or
    the key of a scene that travels as its pickled arrays beside the job (scene_key).
    camera_frames: the frames the default camera is framed over (the whole batch's, so that
    every chunk frames the same camera). output: render's file pattern (printf style, one
    integer field) or None to return the images."""

    kind: str
    scene: str
    path: str = "static"
    size: Tuple[int, int] = (1024, 1024)
    camera_frames: int = 1
    options: Dict[str, Any] = field(default_factory=dict)
    output: Optional[str] = None

    @property
    def coherent(self) -> bool:
        """Whether a frame's work starts from the last frame's result (an order), so that
        chunks want seeds and to follow one another on a worker; collisions do not."""
        return self.kind != "collide"


@dataclass
class FrameResult:
    """One frame: its number, its time in seconds, its result (an order, a pair array, an image
    or the image's file) and the statistics of the call that made it."""

    frame: int
    time_s: float
    value: Any
    stats: Dict[str, Any]
    cycles: Optional[List[Any]] = None  # an order's cycles (uint32 id arrays)


# The scenes this process has loaded, most recent last: a worker keeps the scene of its chunks
# (loading the power plant takes seconds), two at most.
_scenes: "OrderedDict[str, vissort.Scene]" = OrderedDict()
_KEPT_SCENES = 2


_ARRAYS = "arrays:"


def scene_key(scene: vissort.Scene) -> Tuple[str, bytes]:
    """A loaded static scene as what travels: its pickled arrays and a key naming them by
    content (so that a worker unpickles a scene once, and two batches of it share the key)."""
    data = pickle.dumps(scene, protocol=pickle.HIGHEST_PROTOCOL)
    return f"{_ARRAYS}{scene.name}:{hashlib.blake2b(data, digest_size=16).hexdigest()}", data


def keep_scene(key: str, scene: vissort.Scene) -> None:
    """Makes scene this process's scene of key (a batch in this process uses the caller's)."""
    _scenes[key] = scene
    _scenes.move_to_end(key)
    while len(_scenes) > _KEPT_SCENES:
        _scenes.popitem(last=False)


def load_scene(spec: str, data: Optional[bytes] = None) -> vissort.Scene:
    """The scene spec names, loaded once per process; for a scene_key, unpickled from data."""
    if spec in _scenes:
        _scenes.move_to_end(spec)
        return _scenes[spec]
    if spec.startswith(_ARRAYS):
        if data is None:
            raise RuntimeError(f"vissort.batch: the arrays of scene {spec} did not reach this "
                               "process")
        scene = pickle.loads(data)
    else:
        scene = vissort.load(spec)
    keep_scene(spec, scene)
    return scene


_allocator_tuned = False


def _keep_freed_memory() -> None:
    """Undoes, in this process, what Dask's nanny sets for its workers: MALLOC_TRIM_THRESHOLD_=
    65536 (distributed.nanny.pre-spawn-environ) makes glibc give memory back to the system at
    every free and fixes its mmap threshold at 128 KiB, so a renderer's large per-frame buffers
    are mapped and zeroed again every frame: 9% slower renders on the bunnies at 1024x768
    (docs/batch.md). The thresholds are set to the largest glibc's own adaptive ones reach.
    Nothing happens elsewhere (no such variable, or not glibc)."""
    global _allocator_tuned
    if _allocator_tuned or "MALLOC_TRIM_THRESHOLD_" not in os.environ:
        return
    _allocator_tuned = True
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        mallopt = libc.mallopt
    except (OSError, AttributeError):
        return
    m_trim_threshold, m_mmap_threshold = -1, -3  # malloc.h
    mallopt(m_mmap_threshold, 32 * 1024 * 1024)
    mallopt(m_trim_threshold, 64 * 1024 * 1024)


class _Engine:
    """What a process keeps between the chunks of one job: the scene, the base camera, and the
    orderer, renderer or detector, with the last frame it computed. A worker given the next
    chunk goes on where it stopped (no seed frame, no trees or GL context made again)."""

    def __init__(self, job: Job, scene_data: Optional[bytes]):
        _keep_freed_memory()
        self.scene = load_scene(job.scene, scene_data)
        self.last_frame: Optional[int] = None
        self.base = None
        if job.kind == "collide":
            self.worker = vissort.CollisionDetector(self.scene, **job.options)
            return
        self.base = vissort.Camera.default(self.scene, job.size, frames=job.camera_frames)
        # One oracle thread a task unless asked, whatever the module's default: the workers are
        # the batch's parallelism, and each using every core would oversubscribe the machine.
        options = {"threads": 1, **job.options}
        if job.kind == "order":
            self.worker = vissort.Orderer(self.scene, **options)
        else:
            self.worker = vissort.Renderer(self.scene, **options)


# The engine of the last job this process ran chunks of (one: a renderer holds a GL context).
_engine: Optional[Tuple[Job, _Engine]] = None


def _engine_for(job: Job, scene_data: Optional[bytes]) -> _Engine:
    global _engine
    if _engine is None or _engine[0] != job:
        _engine = None  # the old one goes first: one GL context at a time
        _engine = (job, _Engine(job, scene_data))
    return _engine[1]


def _frame(job: Job, engine: _Engine, f: int, keep: bool) -> FrameResult:
    t = f * vissort.FRAME_INTERVAL
    scene, cycles = engine.scene, None
    if job.kind == "collide":
        value = engine.worker.collide(scene, time=t)
        stats = dict(engine.worker.stats)
    else:
        camera = engine.base.on_path(scene, job.path, f)
        if job.kind == "order":
            result = engine.worker.order(scene, camera, job.size, time=t)
            value, stats, cycles = result.order, dict(result.stats), result.cycles
            stats["cycles"] = len(cycles)
        else:
            value = engine.worker.render(camera, job.size, time=t)
            stats = dict(engine.worker.stats)
            if job.output is not None and keep:
                # Whole or not at all (write_image's temporary file, renamed): a retried chunk
                # replaces its frames whole; a killed writer's leftover goes at the batch's end.
                path = job.output % f
                vissort.write_image(path, value)
                value = path
    engine.last_frame = f
    return FrameResult(f, t, value, stats, cycles)


def run_chunk(job: Job, chunk: Chunk, scene_data: Optional[bytes] = None) -> List[FrameResult]:
    """The results of chunk's frames, in order. The seed frame is computed first (and dropped)
    unless this process has just computed it. scene_data: the pickled scene of a job whose scene
    travels as arrays (scene_key)."""
    if job.kind not in KINDS:
        raise ValueError(f"unknown batch kind '{job.kind}' (expected {', '.join(KINDS)})")
    engine = _engine_for(job, scene_data)
    if chunk.seed is not None and engine.last_frame != chunk.seed:
        _frame(job, engine, chunk.seed, keep=False)
    return [_frame(job, engine, f, keep=True) for f in chunk.frames]
