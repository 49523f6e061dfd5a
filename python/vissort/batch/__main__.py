"""python3 -m vissort.batch {order,render,collide} SCENE --frames N ...: a batch from the shell,
in this process, on K local worker processes (--local-workers) or on a running Dask scheduler
(--scheduler ADDRESS). docs/batch.md."""

from __future__ import annotations

import argparse
import csv
import sys
from typing import Any, List, Optional

import numpy as np

from . import _outputs, collide, order, render


def _size(text: str) -> tuple:
    try:
        width, height = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"size must be WxH, got '{text}'") from None
    return width, height


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="python3 -m vissort.batch",
        description="Orders, renders or collisions of many frames, chunked over Dask workers.")
    parser.add_argument("kind", choices=["order", "render", "collide"])
    parser.add_argument("scene", help="builtin:NAME?key=value or a file every worker can read")
    parser.add_argument("--frames", type=int, default=1, help="number of frames (default 1)")
    parser.add_argument("--first", type=int, default=0, help="the first frame (default 0)")
    parser.add_argument("--path", default="static",
                        help="camera path: static, orbit, flythrough or scene (order, render)")
    parser.add_argument("--size", type=_size, default=(1024, 1024), help="WxH (order, render)")
    parser.add_argument("-o", "--output",
                        help="render: image pattern such as out/frame_%%04d.png (required); "
                        "order, collide: an .npz file with one array per frame")
    parser.add_argument("--csv", help="write the per-frame statistics as CSV")
    parser.add_argument("--chunk-frames", type=int, help="frames per task (default 30)")
    parser.add_argument("--method", help="render: vissort, peel, ...; collide: vissort, brute, "
                        "bullet or fcl")
    parser.add_argument("--samples", type=int, help="render: samples a pixel, 1, 2, 4 or 8")
    parser.add_argument("--level", help="order, render: object, triangle or multistage")
    parser.add_argument("--oracle", help="order, render: cpu, cpu-reference, exact or gl")
    parser.add_argument("--threads", type=int, help="collide: threads per task (default 1)")
    where = parser.add_mutually_exclusive_group()
    where.add_argument("--scheduler", metavar="ADDRESS",
                       help="a running Dask scheduler (tcp://host:8786)")
    where.add_argument("--local-workers", type=int, metavar="K",
                       help="start K single-threaded worker processes here")
    parser.add_argument("-q", "--quiet", action="store_true", help="no progress bar")
    return parser


def _client(args: argparse.Namespace) -> Any:
    if args.scheduler is None and args.local_workers is None:
        return None
    from distributed import Client, LocalCluster

    if args.scheduler is not None:
        return Client(args.scheduler)
    if args.local_workers < 1:
        raise ValueError(f"--local-workers must be at least 1, got {args.local_workers}")
    return Client(LocalCluster(n_workers=args.local_workers, threads_per_worker=1,
                               processes=True, dashboard_address=":0"))


def _options(args: argparse.Namespace, names: List[str]) -> dict:
    return {name: getattr(args, name) for name in names if getattr(args, name) is not None}


def main(argv: Optional[List[str]] = None) -> int:
    args = _parser().parse_args(argv)
    try:
        if args.kind == "render" and args.output is None:
            raise ValueError("render needs -o, an image pattern such as out/frame_%04d.png")
        _check_outputs(args)
        client = _client(args)
        try:
            common = dict(first=args.first, chunk_frames=args.chunk_frames, client=client,
                          progress=None if not args.quiet else False)
            if args.kind == "order":
                result = order(args.scene, args.frames, path=args.path, size=args.size,
                               **_options(args, ["level", "oracle"]), **common)
            elif args.kind == "render":
                result = render(args.scene, args.frames, path=args.path, size=args.size,
                                output=args.output,
                                **_options(args, ["method", "samples", "level", "oracle"]),
                                **common)
            else:
                result = collide(args.scene, args.frames, **_options(args, ["method", "threads"]),
                                 **common)
        finally:
            if client is not None:
                client.close()
        # Each file whole or not at all: a killed run leaves the old one.
        if args.kind != "render" and args.output is not None:
            arrays = {f"frame_{f:06d}": np.asarray(v) for f, v in
                      zip(result.frame_numbers, result.results)}
            _outputs.write_whole(_npz_path(args.output), lambda path: _write_npz(path, arrays))
        if args.csv is not None:
            _outputs.write_whole(args.csv, lambda path: _write_csv(path, result.stats))
    except (ValueError, OSError, RuntimeError) as error:
        print(f"vissort.batch: {error}", file=sys.stderr)
        return 1
    if not args.quiet:
        print(f"vissort.batch {args.kind}: {len(result)} frames of {args.scene}")
    return 0


def _npz_path(output: str) -> str:
    """Where numpy saves an archive named output: it adds .npz when the name lacks it."""
    return output if output.endswith(".npz") else output + ".npz"


def _check_outputs(args: argparse.Namespace) -> None:
    """Before any work: no output is the scene's file or the other output."""
    outputs = []
    if args.output is not None and args.kind == "render":
        frames = range(args.first, args.first + args.frames)
        outputs.append(_outputs.FileUse("-o", args.output, frames))
    elif args.output is not None:
        outputs.append(_outputs.FileUse("-o", _npz_path(args.output)))
    if args.csv is not None:
        outputs.append(_outputs.FileUse("--csv", args.csv))
    _outputs.check(_outputs.scene_inputs(None, args.scene), outputs)


def _write_npz(path: str, arrays: dict) -> None:
    # Through a file object: numpy adds .npz to a name without it, such as a temporary file's.
    with open(path, "wb") as out:
        np.savez_compressed(out, **arrays)


def _write_csv(path: str, stats: Any) -> None:
    rows = stats.to_dict("records") if hasattr(stats, "to_dict") else stats
    columns: List[str] = []
    for row in rows:
        columns += [c for c in row if c not in columns]
    with open(path, "w", encoding="utf-8", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=columns)
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    sys.exit(main())
