#!/usr/bin/env python3
"""Levels of detail against full detail, frame by frame (docs/benchmarks.md, "Levels of detail").

Renders the same walkthrough frames with `vissort render` at full detail and at each error bound,
then counts, per frame, the pixels whose largest channel differs by more than 8/255 from the
full-detail picture. Prints a table, writes lod-fidelity.csv, a plot of the share of pixels
against the bound (lod-fidelity.png) and, for each bound, the worst frame beside its full-detail
picture and the difference (lod-worst-PX.png).

    python3 scripts/lod_fidelity.py [--scene S] [--size WxH] [--frames N] [--bounds 0.5,1,2,4]
                                    [--vissort build/vissort] [--out DIR]
"""

import argparse
import csv
import os
import subprocess
import sys

import numpy as np
from PIL import Image


def render(vissort, scene, size, frames, lod_error, folder):
    os.makedirs(folder, exist_ok=True)
    command = [vissort, "render", scene, "--path", "scene", "--size", size, "--frames",
               str(frames), "-o", os.path.join(folder, "f%04d.png"), "--lod-error",
               str(lod_error), "--csv", os.path.join(folder, "stats.csv"), "-q"]
    subprocess.run(command, check=True)
    with open(os.path.join(folder, "stats.csv")) as f:
        return list(csv.DictReader(f))


def picture(folder, frame):
    return np.asarray(Image.open(os.path.join(folder, "f%04d.png" % frame)).convert("RGB"),
                      dtype=np.int16)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scene", default="builtin:powerplant?scale=10")
    parser.add_argument("--size", default="1600x1200")
    parser.add_argument("--frames", type=int, default=60)
    parser.add_argument("--bounds", default="0.5,1,2,4")
    parser.add_argument("--vissort", default="build/vissort")
    parser.add_argument("--out", default="lod-fidelity")
    args = parser.parse_args()
    bounds = [float(b) for b in args.bounds.split(",")]

    full_dir = os.path.join(args.out, "full")
    full_stats = render(args.vissort, args.scene, args.size, args.frames, 0, full_dir)
    rows = []
    for bound in bounds:
        folder = os.path.join(args.out, "lod-%g" % bound)
        stats = render(args.vissort, args.scene, args.size, args.frames, bound, folder)
        shares, worst = [], (-1.0, 0, None)
        for f in range(args.frames):
            full, lod = picture(full_dir, f), picture(folder, f)
            difference = np.abs(full - lod).max(axis=2)
            share = float((difference > 8).mean())
            shares.append(share)
            if share > worst[0]:
                worst = (share, f, difference)
        triangles = [float(s["triangles"]) for s in stats[1:]]
        total_ms = [float(s["total_ms"]) for s in stats[1:]]
        full_ms = [float(s["total_ms"]) for s in full_stats[1:]]
        row = {"bound_px": bound,
               "median_share": float(np.median(shares)),
               "worst_share": worst[0],
               "worst_frame": worst[1],
               "median_triangles": float(np.median(triangles)),
               "median_ms": float(np.median(total_ms)),
               "full_median_ms": float(np.median(full_ms))}
        rows.append(row)
        # The worst frame: full detail, levels of detail, and the pixels over 8/255 in white.
        f = worst[1]
        strip = np.concatenate([picture(full_dir, f), picture(folder, f),
                                np.repeat(((worst[2] > 8) * 255)[:, :, None], 3, axis=2)],
                               axis=1).astype(np.uint8)
        Image.fromarray(strip).save(os.path.join(args.out, "lod-worst-%g.png" % bound))

    with open(os.path.join(args.out, "lod-fidelity.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print("bound px | pixels over 8/255: median, worst (frame) | triangles drawn | ms a frame "
          "(full detail)")
    for r in rows:
        print("%g | %.3f%%, %.3f%% (%d) | %.0f | %.0f (%.0f)" % (
            r["bound_px"], 100 * r["median_share"], 100 * r["worst_share"], r["worst_frame"],
            r["median_triangles"], r["median_ms"], r["full_median_ms"]))
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        figure, axis = plt.subplots(figsize=(7, 4))
        axis.plot(bounds, [100 * r["median_share"] for r in rows], "o-", label="median frame")
        axis.plot(bounds, [100 * r["worst_share"] for r in rows], "s-", label="worst frame")
        axis.axhline(0.5, color="grey", linestyle="--", label="target at 1 px: 0.5%")
        axis.set_xscale("log", base=2)
        axis.set_xlabel("--lod-error (pixels)")
        axis.set_ylabel("pixels off by more than 8/255 (%)")
        axis.set_title("%s, %s, frames 0-%d against full detail" % (args.scene, args.size,
                                                                   args.frames - 1))
        axis.legend()
        figure.tight_layout()
        figure.savefig(os.path.join(args.out, "lod-fidelity.png"), dpi=100)
    except ImportError:
        print("matplotlib missing: no plot", file=sys.stderr)


if __name__ == "__main__":
    main()
