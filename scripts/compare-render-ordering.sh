#!/usr/bin/env bash
# Ordering inside `vissort render` against `vissort order` on the same view, for two builds,
# alternated (this VM is noisy: take medians). Prints per run: build, order's stats.ms, render's
# ms.order and its groups composited per pixel.
#   bash scripts/compare-render-ordering.sh OLD_VISSORT NEW_VISSORT [RUNS] [MODEL]
# MODEL defaults to the IFC house of Debian's assimp-testmodels (docs/robustness.md).
set -euo pipefail
old=$1 new=$2 runs=${3:-5}
model=${4:-/usr/share/assimp/models/IFC/AC14-FZK-Haus.ifc}
view=(--ortho-dir -0.3,-0.5,-1 --size 256x256 --level triangle)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for _ in $(seq "$runs"); do
  for build in old new; do
    bin=$old
    [ "$build" = new ] && bin=$new
    "$bin" order "$model" "${view[@]}" --json "$tmp/order.json" >/dev/null
    "$bin" render "$model" "${view[@]}" --all-transparent --alpha 0.4 -o "$tmp/render.png" \
      --json "$tmp/render.json" >/dev/null
    python3 - "$build" "$tmp" <<'PY'
import json, sys
build, tmp = sys.argv[1], sys.argv[2]
order = json.load(open(f"{tmp}/order.json"))
render = json.load(open(f"{tmp}/render.json"))
print(build, round(order["stats"]["ms"], 1), round(render["ms"]["order"], 1), render["groups"])
PY
  done
done
