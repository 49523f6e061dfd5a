"""The Python module's overhead over the command line: the same frames ordered by
`vissort order --json` (its per-frame orderFrame time) and by vissort.Orderer from Python: the
whole call (with time=t: the scene's deformed frame, which the command line computes outside
its timing; with an array: reading the corners), the orderFrame inside it (stats["ms"]), and
the difference, the binding's own cost. Arrays are passed as the scene gives them (float32) and
as float64, which the module first copies to float32 before the gather reads it (the cost of
that second copy is the difference between the two rows). Runs alternated, medians over the coherent frames (the
first frame of each run left out); the orders must equal the command line's.

  PYTHONPATH=build/python python3 bench/python/order_overhead.py build/vissort [runs]
"""

import json
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import vissort

SCENE, LEVEL, FRAMES, SIZE = "builtin:bunnies", "triangle", 30, (1024, 768)


def cli_run(cli):
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / "order.json"
        subprocess.run([cli, "order", SCENE, "--level", LEVEL, "--frames", str(FRAMES),
                        "--size", f"{SIZE[0]}x{SIZE[1]}", "--path", "static", "--quiet",
                        "--json", str(path)], check=True)
        frames = json.loads(path.read_text())["frames"]
    return [f["stats"]["ms"] for f in frames[1:]], [f["order"] for f in frames]


def python_run(scene, arrays):
    orderer = vissort.Orderer(scene if arrays is None else scene.object_ranges, level=LEVEL)
    camera = vissort.Camera.default(scene, size=SIZE)
    times, inside, orders = [], [], []
    for f in range(FRAMES):
        positions = None if arrays is None else arrays[f]
        start = time.perf_counter()
        if arrays is None:
            result = orderer.order(time=f / 30, camera=camera, size=SIZE)
        else:
            result = orderer.order(positions, camera=camera, size=SIZE)
        times.append((time.perf_counter() - start) * 1000)
        inside.append(result.stats["ms"])
        orders.append(result.order.tolist())
    return times[1:], inside[1:], orders


def main():
    cli = sys.argv[1]
    runs = int(sys.argv[2]) if len(sys.argv) > 2 else 3
    scene = vissort.load(SCENE)
    arrays = [scene.frame(f / 30) for f in range(FRAMES)]
    cli_ms = []
    arrays64 = [a.astype("float64") for a in arrays]
    # whole calls, and orderFrame inside them
    calls = {"time": ([], []), "array": ([], []), "array64": ([], [])}
    for _ in range(runs):
        ms, cli_orders = cli_run(cli)
        cli_ms += ms
        for name, source in (("time", None), ("array", arrays), ("array64", arrays64)):
            whole, inside, orders = python_run(scene, source)
            calls[name][0].extend(whole)
            calls[name][1].extend(inside)
            assert orders == cli_orders, "the module's orders differ from the command line's"
    base = statistics.median(cli_ms)
    print(f"{SCENE}, {LEVEL} level, {SIZE[0]}x{SIZE[1]}, {FRAMES} frames x {runs} runs; "
          "medians of the coherent frames; orders identical to the command line's")
    print(f"  vissort order: orderFrame                  {base:8.2f} ms")
    for name, label in (("time", "Orderer.order(time=t)"),
                        ("array", "Orderer.order(float32 (T, 3, 3))"),
                        ("array64", "Orderer.order(float64 (T, 3, 3))")):
        whole, inside = calls[name]
        call, order = statistics.median(whole), statistics.median(inside)
        overhead = statistics.median(w - i for w, i in zip(whole, inside))
        print(f"  {label:31s} whole call {call:8.2f} ms ({100 * (call / base - 1):+.1f}% of the "
              f"CLI's orderFrame); orderFrame inside {order:.2f} ms "
              f"({100 * (order / base - 1):+.1f}%); the call around it {overhead:.2f} ms "
              f"({100 * overhead / order:.1f}%)")


if __name__ == "__main__":
    main()
