#!/usr/bin/env bash
# Makes the comparison strips of docs/transparency.md: every transparency method on the same
# view, with its error map against linked-list below it (vissort render --method all), and the
# README's picture of the bunnies.
#   bash scripts/comparison-strip.sh [BUILD_DIR]     (default build/, as scripts/test.sh builds)
set -euo pipefail
cd "$(dirname "$0")/.."
tool="${1:-build}/vissort"
if [ ! -x "$tool" ]; then
  echo "comparison-strip: no $tool; build first (bash scripts/test.sh)" >&2
  exit 1
fi
mkdir -p docs/images
# The paper's dynamic scene: intersecting, deforming bunnies (cycles at every level), with the
# paper's membrane shading and 4 samples a pixel (its figure 4), alone and then every method.
"$tool" render builtin:bunnies --size 800x600 --fov 34 --shading membrane --samples 4 \
  -o docs/images/bunnies-membrane.png
"$tool" render builtin:bunnies --size 320x320 --fov 24 --level multistage --method all \
  --shading membrane --samples 4 \
  -o docs/images/comparison-bunnies.png --json docs/images/comparison-bunnies.json --pretty
# The CAD-like plant: opaque steel, transparent pipes and tanks, depth complexity up to 16.
"$tool" render 'builtin:plant?layers=8' --size 384x256 --fov 20 --level multistage --method all \
  -o docs/images/comparison-plant.png --json docs/images/comparison-plant.json --pretty
# Nested boxes around Suzanne, with an opaque core: one cycle at object level.
"$tool" render tests/data/scenes/nested.json --size 320x320 --level object --method all \
  -o docs/images/comparison-nested.png --json docs/images/comparison-nested.json --pretty
