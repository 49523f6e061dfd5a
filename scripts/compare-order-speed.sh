#!/usr/bin/env bash
# Ordering speed of two vissort builds on the same frames, alternated run by run (this VM is
# noisy: medians). Prints the median ms and queries a frame over the coherent frames (every frame
# but the first) of all runs, the ratio, and whether both builds gave the same cycles and the same
# orders (a cycle's members may come out in another order, or a cycle at another place among the
# primitives it neither occludes nor is occluded by: both orders valid).
#   bash scripts/compare-order-speed.sh OLD_VISSORT NEW_VISSORT RUNS SCENE [ORDER_OPTIONS...]
# e.g. bash scripts/compare-order-speed.sh old/vissort build/vissort 3 builtin:bunnies \
#        --path orbit --frames 30 --size 1024x768 --level object
set -euo pipefail
old=$1 new=$2 runs=$3 scene=$4
shift 4
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for run in $(seq "$runs"); do
  for build in old new; do
    bin=$old
    [ "$build" = new ] && bin=$new
    "$bin" order "$scene" "$@" --json "$tmp/$build.$run.json" >/dev/null
  done
done
python3 - "$tmp" "$runs" <<'PY'
import json, statistics, sys
tmp, runs = sys.argv[1], int(sys.argv[2])
def load(build):
    ms, queries, orders, cycles = [], [], None, None
    for run in range(1, runs + 1):
        frames = json.load(open(f"{tmp}/{build}.{run}.json"))["frames"]
        ms += [f["stats"]["ms"] for f in frames[1:]]
        queries += [f["stats"]["queries"] for f in frames[1:]]
        orders = orders or [f["order"] for f in frames]
        cycles = cycles or [sorted(f["cycles"]) for f in frames]
    if not ms:
        sys.exit("no coherent frame: ask for --frames 2 or more")
    return statistics.median(ms), statistics.median(queries), orders, cycles
old, new = load("old"), load("new")
print(f"old {old[0]:.2f} ms, new {new[0]:.2f} ms a frame: {old[0] / new[0]:.2f}x; "
      f"queries {old[1]:g} and {new[1]:g}; same cycles: {old[3] == new[3]}, "
      f"same orders: {old[2] == new[2]}")
PY
