"""Cutting a batch's frames into chunks, one task each (docs/batch.md).

A chunk is a contiguous run of frames, so that the worker that renders it keeps the frame-to-frame
coherence of vissort's orders inside it; for orders and renders, each chunk but the batch's
first also computes the frame before it, whose result is thrown away, so that its first frame
starts from an order too (a seed). Collisions need no seed: a detector's state (its trees, refit
to each frame's positions) serves any frame alike."""

from __future__ import annotations

from dataclasses import dataclass
from typing import List, Optional

# Frames a chunk holds when the caller does not say: docs/batch.md measures the trade (more
# chunks balance the workers and lose less to a failure; each costs a task and a seed frame).
DEFAULT_CHUNK_FRAMES = 30


@dataclass(frozen=True)
class Chunk:
    """Frames [first, stop) of the batch, and the frame computed before them to seed their
    order (None for the batch's first chunk)."""

    first: int
    stop: int
    seed: Optional[int]

    @property
    def frames(self) -> range:
        return range(self.first, self.stop)


def cut(first: int, count: int, chunk_frames: Optional[int] = None,
        seeded: bool = True) -> List[Chunk]:
    """The chunks of frames [first, first + count), in order, each of at most chunk_frames
    frames (DEFAULT_CHUNK_FRAMES when None), each seeded by the frame before it when seeded.
    ValueError for a negative first frame, a count below 1 or a chunk size below 1."""
    if chunk_frames is None:
        chunk_frames = DEFAULT_CHUNK_FRAMES
    for name, value, least in (("first frame", first, 0), ("frames", count, 1),
                               ("chunk_frames", chunk_frames, 1)):
        if isinstance(value, bool) or not isinstance(value, int):
            raise ValueError(f"{name} must be an integer, got {value!r}")
        if value < least:
            raise ValueError(f"{name} must be at least {least}, got {value}")
    chunks = []
    for start in range(first, first + count, chunk_frames):
        stop = min(start + chunk_frames, first + count)
        chunks.append(Chunk(start, stop, start - 1 if seeded and start > first else None))
    return chunks
