#!/usr/bin/env bash
# Runs two vissort binaries on the same scenes and cameras and compares what they write: orders
# and collision pairs (JSON without the timing fields) and rendered PNGs (byte for byte). For
# changes that must not change behaviour (a restructuring, a speed-up).
#   bash scripts/compare-builds.sh OLD_VISSORT NEW_VISSORT [WORK_DIR]
# Prints one line per comparison and exits 1 when any output differs.
set -euo pipefail
old=$1
new=$2
work=${3:-$(mktemp -d)}
mkdir -p "$work/old" "$work/new"
export LP_NUM_THREADS=0
failed=0

# The JSON minus every "ms" value (wall times differ between any two runs).
strip_times() {
  python3 -c '
import json, sys
def strip(v):
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items() if k not in ("ms", "milliseconds")}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v
print(json.dumps(strip(json.load(open(sys.argv[1]))), sort_keys=True))' "$1"
}

compare() {  # NAME KIND(json|png|text) ARGS...: runs both, compares their output file
  local name=$1 kind=$2
  shift 2
  for side in old new; do
    local bin=$old
    [ "$side" = new ] && bin=$new
    local out="$work/$side/$name.$kind"
    local args=("$@")
    args=("${args[@]//@OUT@/$out}")
    if [ "$kind" = text ]; then
      "$bin" "${args[@]}" > "$out" 2>&1 || true
    else
      "$bin" "${args[@]}" > /dev/null 2>&1 || echo "  ($side exited non-zero)"
    fi
  done
  local same=1
  if [ ! -s "$work/old/$name.$kind" ] || [ ! -s "$work/new/$name.$kind" ]; then
    echo "MISSING   $name"
    failed=1
    return
  fi
  case $kind in
    json) [ "$(strip_times "$work/old/$name.json")" = "$(strip_times "$work/new/$name.json")" ] || same=0 ;;
    *) cmp -s "$work/old/$name.$kind" "$work/new/$name.$kind" || same=0 ;;
  esac
  if [ $same = 1 ]; then echo "same      $name"; else echo "DIFFERENT $name"; failed=1; fi
}

for level in object triangle multistage; do
  for oracle in cpu cpu-reference exact gl; do
    compare "order-bunnies-$level-$oracle" json order builtin:bunnies --size 128x128 --frames 4 \
      --path orbit --level "$level" --oracle "$oracle" --json @OUT@
  done
done
compare order-plant-object json order "builtin:plant?layers=8" --size 256x192 --frames 3 --path flythrough --json @OUT@
compare order-slabs-multistage json order "builtin:slabs?layers=32" --size 128x128 --frames 3 --path orbit --level multistage --json @OUT@
compare order-soup-triangle json order "builtin:soup" --size 128x128 --level triangle --json @OUT@
for method in vissort unsorted centroid peel dual-peel linked-list weighted; do
  compare "render-bunnies-$method" png render builtin:bunnies --size 160x120 --all-transparent \
    --method "$method" -o @OUT@
done
compare render-bunnies-multistage-gl png render builtin:bunnies --size 160x120 --all-transparent --level multistage --oracle gl -o @OUT@
compare render-slabs-flat png render "builtin:slabs?layers=32" --size 128x128 --all-transparent --shading flat -o @OUT@
compare render-plant-highlight png render "builtin:bunnies?n=6" --size 128x128 --highlight-collisions -o @OUT@
for method in vissort brute bullet fcl; do
  compare "collide-bunnies-$method" json collide builtin:bunnies --frames 5 --method "$method" --json @OUT@
done
compare info-bunnies text info builtin:bunnies --size 128x128
compare info-plant text info "builtin:plant?layers=8" --size 128x128
exit $failed
