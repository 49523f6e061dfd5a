#!/usr/bin/env python3
"""Medians of several `vissort bench transparency --json` runs, as the Markdown tables of
docs/benchmarks.md: ms a frame per scene, depth and method, linked-list over vissort, and the
largest error of each method over the runs. With --before, a column of another build's vissort
medians (runs of that build, alternated with these in the same session).
    python3 scripts/bench-transparency-medians.py new1.json new2.json ... [--before old1.json ...]
"""
import argparse
import json
import statistics

METHODS = ["vissort", "peel", "dual-peel", "linked-list", "weighted", "centroid"]
WRONG = ["vissort", "peel", "dual-peel", "weighted", "centroid"]


def rows_of(paths):
    rows = {}
    for path in paths:
        for row in json.load(open(path))["rows"]:
            rows.setdefault((row["scene"], row["depth"], row["method"]), []).append(row)
    return rows


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--before", nargs="*", default=[])
    args = parser.parse_args()
    rows, before = rows_of(args.runs), rows_of(args.before)
    median = lambda table, key: statistics.median(r["ms"] for r in table[key])
    for scene in sorted({k[0] for k in rows}, key=["slabs", "plant"].index):
        depths = sorted({k[1] for k in rows if k[0] == scene})
        head = [f"{scene}, D", "seen"] + (["vissort before"] if before else []) + METHODS
        head += ["linked-list / vissort", "max error: " + ", ".join(WRONG)]
        print("| " + " | ".join(head) + " |")
        print("|" + " ---: |" * (len(head) - 1) + " --- |")
        for d in depths:
            ms = {m: median(rows, (scene, d, m)) for m in METHODS}
            cells = [str(d), str(rows[(scene, d, "vissort")][0]["depth_seen"])]
            if before:
                cells.append(f"{median(before, (scene, d, 'vissort')):,.1f}")
            cells += [f"{ms[m]:,.1f}" for m in METHODS]
            cells.append(f"{ms['linked-list'] / ms['vissort']:.1f}x")
            cells.append(", ".join(str(max(r["error"]["max_abs"] for r in rows[(scene, d, m)]))
                                   for m in WRONG))
            print("| " + " | ".join(cells) + " |")
        print()


if __name__ == "__main__":
    main()
