#!/usr/bin/env bash
# Frame times of `vissort render` for several (build, method, level) configurations on the same
# frames, alternated run by run (this VM is noisy: medians). Prints, per configuration, the
# median ms a frame over the coherent frames (every frame but the first) of all runs: total,
# ordering and rendering.
#   bash scripts/compare-render-speed.sh RUNS SCENE "RENDER_OPTIONS" BIN:METHOD:LEVEL...
# e.g. bash scripts/compare-render-speed.sh 3 builtin:bunnies \
#        "--size 1024x1024 --path orbit --frames 8" \
#        old/vissort:vissort:multistage build/vissort:vissort:multistage \
#        build/vissort:linked-list:object
set -euo pipefail
runs=$1 scene=$2
read -r -a options <<<"$3"
shift 3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for run in $(seq "$runs"); do
  for c in $(seq "$#"); do
    IFS=: read -r bin method level <<<"${!c}"
    "$bin" render "$scene" "${options[@]}" --method "$method" --level "$level" \
      -o "$tmp/frame_%04d.png" --json "$tmp/$c.$run.json" >/dev/null
  done
done
python3 - "$tmp" "$runs" "$@" <<'PY'
import json, statistics, sys
tmp, runs, configs = sys.argv[1], int(sys.argv[2]), sys.argv[3:]
for c, config in enumerate(configs, 1):
    frames = []
    for run in range(1, runs + 1):
        frames += json.load(open(f"{tmp}/{c}.{run}.json"))["frames"][1:]
    if not frames:
        sys.exit("compare-render-speed: give --frames 2 or more (the first is not counted)")
    median = lambda key: statistics.median(f["ms"][key] for f in frames)
    print(f"{config}: {median('total'):.1f} ms a frame (order {median('order'):.1f}, "
          f"render {median('render'):.1f}), {len(frames)} frames")
PY
