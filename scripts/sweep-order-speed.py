#!/usr/bin/env python3
"""Ordering speed of two vissort builds over a folder of real models (issue 57's sweep).

Every file with at least --min-objects objects (as `NEW info FILE` counts them; by default
Debian's assimp-testmodels, `apt-get install assimp-testmodels`) is ordered by both builds,
alternated run by run (this VM is noisy: medians), with `order FILE --level L --size WxH`.
Prints one line a file (the ordering milliseconds of each build from its JSON, the whole
process's seconds, the ratio new / baseline), then the geometric mean of the ratios, how many
files are over 1.5x and 2x, and the files either build refused or failed.

    python3 scripts/sweep-order-speed.py BASELINE_VISSORT NEW_VISSORT [--level object]
        [--size 512x512] [--runs 2] [--models /usr/share/assimp/models] [--tsv FILE]
        [--files RELATIVE_PATH ...] [--check build/check_every_frame]

--files measures those files of --models only (whatever their object count). --check also
checks NEW's order of every measured file, at the same level and size, against the exact
ground truth (the test build's check_every_frame, cpu oracle): a figure of a wrong order counts
for nothing, and the sweep exits 1.
"""

import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time


def run_order(tool, model, args, out):
    """(ordering ms summed over the frames, whole-process seconds), or None when it failed."""
    command = [tool, "order", model, "--level", args.level, "--size", args.size, "--quiet",
               "--json", out]
    start = time.perf_counter()
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout)
    except subprocess.TimeoutExpired:
        return None
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        return None
    with open(out, encoding="utf-8") as f:
        document = json.load(f)
    # One frame: its stats at the top; several: a list of frames.
    frames = document.get("frames", [document])
    return sum(frame["stats"]["ms"] for frame in frames), seconds


def order_is_exact(check_tool, model, args):
    """Whether the test build's every-frame check finds the cpu oracle's order exact."""
    command = [check_tool, model, "--size", args.size, "--oracles", "cpu", "--levels",
               args.level]
    try:
        return subprocess.run(command, capture_output=True, timeout=args.timeout * 4).returncode == 0
    except subprocess.TimeoutExpired:
        return False


def object_count(tool, model, timeout):
    try:
        done = subprocess.run([tool, "info", model, "--json", "-", "--quiet"],
                              capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return 0
    if done.returncode != 0:
        return 0
    return int(json.loads(done.stdout).get("objects", 0))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("baseline")
    parser.add_argument("new")
    parser.add_argument("--models", default="/usr/share/assimp/models")
    parser.add_argument("--level", default="object")
    parser.add_argument("--size", default="512x512")
    parser.add_argument("--runs", type=int, default=2)
    parser.add_argument("--min-objects", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=300)
    parser.add_argument("--tsv", help="also write the per-file figures here")
    parser.add_argument("--files", nargs="+", help="these files of --models only")
    parser.add_argument("--check", metavar="CHECK_EVERY_FRAME",
                        help="check NEW's orders against the exact ground truth with this tool")
    args = parser.parse_args()
    for tool in (args.baseline, args.new):
        if not os.access(tool, os.X_OK):
            sys.exit(f"sweep-order-speed: no vissort at {tool}")
    if not os.path.isdir(args.models):
        sys.exit(f"sweep-order-speed: no folder {args.models} (apt-get install assimp-testmodels)")
    if args.files:
        chosen = [os.path.join(args.models, name) for name in args.files]
        print(f"{len(chosen)} files; {args.runs} runs each, builds alternated", flush=True)
    else:
        models = sorted(os.path.join(root, name) for root, _, names in os.walk(args.models)
                        for name in names)
        chosen = [m for m in models
                  if object_count(args.new, m, args.timeout) >= args.min_objects]
        print(f"{len(chosen)} of {len(models)} files have {args.min_objects} or more objects; "
              f"{args.runs} runs each, builds alternated", flush=True)
    rows, failed = [], []
    with tempfile.TemporaryDirectory() as scratch:
        out = os.path.join(scratch, "order.json")
        for model in chosen:
            figures = {"baseline": [], "new": []}
            for _ in range(args.runs):
                for build, tool in (("baseline", args.baseline), ("new", args.new)):
                    result = run_order(tool, model, args, out)
                    if result is not None:
                        figures[build].append(result)
            if len(figures["baseline"]) < args.runs or len(figures["new"]) < args.runs:
                failed.append(model)
                print(f"failed {os.path.relpath(model, args.models)}", flush=True)
                continue
            base_ms = statistics.median(f[0] for f in figures["baseline"])
            new_ms = statistics.median(f[0] for f in figures["new"])
            base_s = statistics.median(f[1] for f in figures["baseline"])
            new_s = statistics.median(f[1] for f in figures["new"])
            ratio = new_ms / base_ms if base_ms > 0 else float("nan")
            if args.check and not order_is_exact(args.check, model, args):
                failed.append(model)
                print(f"wrong order (check_every_frame) {os.path.relpath(model, args.models)}",
                      flush=True)
                continue
            rows.append((os.path.relpath(model, args.models), base_ms, new_ms, base_s, new_s,
                         ratio))
            print(f"{ratio:7.2f}x  {base_ms:10.1f} -> {new_ms:10.1f} ms  ({base_s:.2f} -> "
                  f"{new_s:.2f} s)  {rows[-1][0]}", flush=True)
    ratios = [r[5] for r in rows if r[5] == r[5] and r[5] > 0]
    if ratios:
        geometric = math.exp(sum(math.log(r) for r in ratios) / len(ratios))
        print(f"\n{len(ratios)} files: geometric mean {geometric:.2f}x new / baseline; "
              f"{sum(r > 1.5 for r in ratios)} over 1.5x, {sum(r > 2 for r in ratios)} over 2x; "
              f"largest {max(ratios):.2f}x, smallest {min(ratios):.2f}x")
    if failed:
        print(f"{len(failed)} files failed in a build: " + ", ".join(
            os.path.relpath(m, args.models) for m in failed))
    if args.tsv:
        with open(args.tsv, "w", encoding="utf-8") as f:
            f.write("file\tbaseline_ms\tnew_ms\tbaseline_s\tnew_s\tratio\n")
            for row in rows:
                f.write("\t".join([row[0]] + [f"{v:.4g}" for v in row[1:]]) + "\n")
    if failed:
        sys.exit(1)


if __name__ == "__main__":
    main()
