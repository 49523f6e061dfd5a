"""Running a batch's chunks: in this process one after the other, or as one Dask task each on
a distributed.Client's workers; either way the frames come back in frame order, with a progress
bar on long work (tqdm on a terminal when it is installed, else a line on standard error)."""

from __future__ import annotations

import sys
from typing import Any, Callable, List, Optional

from ._chunks import Chunk
from ._tasks import FrameResult, Job, run_chunk


class _Progress:
    """Chunks done out of a total: tqdm's bar when tqdm is installed, else a line rewritten on
    standard error; nothing when off."""

    def __init__(self, total: int, label: str, on: bool):
        self._bar = None
        self._total, self._done, self._label, self._on = total, 0, label, on
        if not on:
            return
        try:
            from tqdm import tqdm
        except ImportError:
            return
        self._bar = tqdm(total=total, desc=label, unit="chunk", file=sys.stderr)

    def advance(self) -> None:
        self._done += 1
        if self._bar is not None:
            self._bar.update(1)
        elif self._on:
            end = "\n" if self._done == self._total else ""
            print(f"\r{self._label}: {self._done}/{self._total} chunks", end=end, file=sys.stderr,
                  flush=True)

    def close(self) -> None:
        if self._bar is not None:
            self._bar.close()


def contiguous_runs(count: int, workers: int) -> List[List[int]]:
    """0..count-1 cut into at most `workers` contiguous runs of nearly equal length, the longer
    first: contiguous_runs(7, 2) is [[0, 1, 2, 3], [4, 5, 6]]; one run without workers."""
    runs = min(max(workers, 1), max(count, 1))
    size, longer = divmod(count, runs)
    out, start = [], 0
    for r in range(runs):
        length = size + (1 if r < longer else 0)
        out.append(list(range(start, start + length)))
        start += length
    return [run for run in out if run]


def progress_wanted(progress: Optional[bool]) -> bool:
    """progress as given, or when None: on when standard error is a terminal."""
    return sys.stderr.isatty() if progress is None else bool(progress)


def run(job: Job, chunks: List[Chunk], client: Any = None, progress: Optional[bool] = None,
        check: Callable[[], Any] = lambda: None,
        scene_data: Optional[bytes] = None) -> List[FrameResult]:
    """Every frame of chunks, in frame order. client: a distributed.Client (one task per chunk;
    a worker that dies has its chunks run again elsewhere, by Dask) or None (this process).
    check: raises when the batch cannot run; called before the first chunk here, or once the
    tasks are submitted (which are then cancelled). scene_data: a scene that travels as its
    pickled arrays (scene_key), sent to every worker once rather than with every task."""
    if client is None:
        check()
    bar = _Progress(len(chunks), f"vissort.batch {job.kind}", progress_wanted(progress))
    try:
        if client is None:
            per_chunk = []
            for chunk in chunks:
                per_chunk.append(run_chunk(job, chunk))
                bar.advance()
        else:
            from distributed import as_completed

            # Every worker holds the scene's arrays (broadcast), so that one that dies takes
            # none of them with it and one that joins copies them from a peer; they need a
            # worker to hold them first.
            data = None
            if scene_data is not None:
                client.wait_for_workers(1)
                data = client.scatter(scene_data, broadcast=True)
            addresses = sorted(client.scheduler_info().get("workers", {}))
            # A coherent job asks each worker for a contiguous run of chunks (a loose
            # restriction: Dask still moves them elsewhere when it dies or idles), so that its
            # next chunk follows its last one: no seed frame in between. Collisions have no
            # order to carry: Dask deals their chunks to whichever worker is free, which
            # balances frames of uneven cost. Without workers yet, no restriction either.
            # pure=False: two batches with the same arguments are still two runs (files may
            # have been removed in between).
            runs = (contiguous_runs(len(chunks), len(addresses)) if job.coherent
                    else [list(range(len(chunks)))])
            futures = [None] * len(chunks)
            for run_index, indices in enumerate(runs):
                where = (dict(workers=[addresses[run_index]], allow_other_workers=True)
                         if addresses and job.coherent else {})
                submitted = client.map(run_chunk, [job] * len(indices), [chunks[i] for i in indices],
                                       [data] * len(indices), pure=False, **where)
                for i, future in zip(indices, submitted):
                    futures[i] = future
            try:
                check()
            except BaseException:
                client.cancel(futures)
                raise
            # The results are gathered once all chunks are done: as_completed(with_results=True),
            # which would fetch each as it ends, hung a batch here (dask/distributed#7331).
            for future in as_completed(futures):
                if future.status == "error":  # the first failure ends the batch at once
                    error = future.exception()  # read before cancelling, which would lose it
                    client.cancel(futures)
                    raise error
                bar.advance()
            per_chunk = client.gather(futures)
    finally:
        bar.close()
    return [frame for results in per_chunk for frame in results]
