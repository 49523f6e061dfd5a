#!/usr/bin/env python3
"""The figures of docs/batch.md: vissort.batch against the plain module loop, and on 1 and 2
local Dask workers (single-threaded processes), in turns, medians of the rounds.

    PYTHONPATH=build/python python3 scripts/bench-batch.py [--frames 300] [--rounds 3]

render: builtin:bunnies at 1024x768 (exact transparency, one sample), every frame written as a
PNG (the plain loop too); collide: builtin:bunnies?n=144 (the vissort method, one thread a
task), the pairs returned. Each timing includes loading the scene, as a user's run does; the
clusters are started before (and their start is reported). "Two plain loops at once" is the
machine's ceiling for two workers without Dask: two processes (started before), each running the
plain loop over half the frames."""

import argparse
import multiprocessing
import os
import statistics
import sys
import tempfile
import time

import vissort
import vissort.batch as batch
from distributed import Client, LocalCluster

RENDER_SCENE, RENDER_SIZE = "builtin:bunnies", (1024, 768)
COLLIDE_SCENE = "builtin:bunnies?n=144"


def plain(kind, frames, pattern, first=0, count=None):
    """The plain module loop over frames [first, first + count) of a batch of `frames`."""
    count = frames - first if count is None else count
    if kind == "render":
        scene = vissort.load(RENDER_SCENE)
        base = vissort.Camera.default(scene, RENDER_SIZE, frames=frames)
        renderer = vissort.Renderer(scene)
        for f in range(first, first + count):
            image = renderer.render(base.on_path(scene, "static", f), RENDER_SIZE,
                                    time=f * vissort.FRAME_INTERVAL)
            vissort.write_image(pattern % f, image)
    else:
        scene = vissort.load(COLLIDE_SCENE)
        detector = vissort.CollisionDetector(scene)
        for f in range(first, first + count):
            detector.collide(scene, time=f * vissort.FRAME_INTERVAL)


def plain_halves(pool, kind, frames, pattern):
    """The machine's own ceiling for two workers: two plain loops at once in two processes
    (started before), each over half the frames, no Dask."""
    half = frames // 2
    pool.starmap(plain, [(kind, frames, pattern, 0, half),
                         (kind, frames, pattern, half, frames - half)])


def batched(kind, frames, client, chunk_frames, pattern):
    if kind == "render":
        batch.render(RENDER_SCENE, frames, size=RENDER_SIZE, client=client, output=pattern,
                     chunk_frames=chunk_frames, progress=False)
    else:
        batch.collide(COLLIDE_SCENE, frames, client=client, chunk_frames=chunk_frames,
                      progress=False)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--frames", type=int, default=300)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--kinds", default="render,collide")
    parser.add_argument("--chunks", default="30", help="chunk sizes to measure, comma-separated")
    args = parser.parse_args()
    chunk_sizes = [int(c) for c in args.chunks.split(",")]
    clusters = {}
    for workers in (1, 2):
        started = time.perf_counter()
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                               dashboard_address=":0")
        clusters[workers] = (cluster, Client(cluster))
        print(f"cluster of {workers} started in {time.perf_counter() - started:.1f} s",
              file=sys.stderr)
    pool = multiprocessing.get_context("spawn").Pool(2)
    pool.starmap(time.sleep, [(0,), (0,)])  # both processes up
    times = {}
    folder = tempfile.mkdtemp(prefix="vissort-bench-batch.")
    pattern = os.path.join(folder, "frame_%04d.png")
    for round_ in range(args.rounds):
        for kind in args.kinds.split(","):
            runs = [("plain loop", lambda: plain(kind, args.frames, pattern)),
                    ("two plain loops at once, half the frames each",
                     lambda: plain_halves(pool, kind, args.frames, pattern))]
            for chunk in chunk_sizes:
                runs.append((f"batch, here, chunks of {chunk}",
                             lambda c=chunk: batched(kind, args.frames, None, c, pattern)))
                for workers in (1, 2):
                    runs.append((f"batch, {workers} worker{'s' if workers > 1 else ''}, "
                                 f"chunks of {chunk}",
                                 lambda w=workers, c=chunk: batched(kind, args.frames,
                                                                    clusters[w][1], c, pattern)))
            for name, run in runs:
                started = time.perf_counter()
                run()
                seconds = time.perf_counter() - started
                times.setdefault((kind, name), []).append(seconds)
                print(f"round {round_ + 1} {kind} {name}: {seconds:.2f} s", file=sys.stderr)
    pool.close()
    for _, client in clusters.values():
        client.close()
    for cluster, _ in clusters.values():
        cluster.close()
    print(f"| work | run | median s ({args.rounds} rounds) | frames/s | against the plain loop |")
    print("| --- | --- | ---: | ---: | ---: |")
    for (kind, name), seconds in times.items():
        median = statistics.median(seconds)
        reference = statistics.median(times[(kind, "plain loop")])
        print(f"| {kind} | {name} | {median:.2f} | {args.frames / median:.1f} | "
              f"{reference / median:.2f}x |")
    # The two figures (docs/batch.md), and the machine's ceiling beside the first.
    median = lambda kind, name: statistics.median(times[(kind, name)])
    for kind in args.kinds.split(","):
        ceiling = (median(kind, "plain loop") /
                   median(kind, "two plain loops at once, half the frames each"))
        for chunk in chunk_sizes:
            one = median(kind, f"batch, 1 worker, chunks of {chunk}")
            two = median(kind, f"batch, 2 workers, chunks of {chunk}")
            print(f"{kind}, chunks of {chunk}: 2 workers / 1 = {one / two:.2f}x (two plain "
                  f"processes / one: {ceiling:.2f}x); 1 worker over the plain loop: "
                  f"{100 * (one / median(kind, 'plain loop') - 1):+.1f}%")


if __name__ == "__main__":
    main()
