#!/usr/bin/env bash
# Checks vissort's installed CMake package: builds vissort (Release: the libraries and the CLI,
# no tests or benchmarks), installs it into a temporary prefix, then configures, builds and runs
# every consumer project in examples/ against that prefix (CMAKE_PREFIX_PATH) and checks what
# each prints. Fails on the first error.
#   bash scripts/check-install.sh [cmake options for vissort, e.g. -DVISSORT_WITH_GL=OFF]
# Work directory: $VISSORT_CHECK_DIR if set (kept), else a temporary one (removed).
# VISSORT_CHECK_BUILD_DIR=DIR builds vissort in DIR (an existing build tree to reuse) instead.
set -euo pipefail
cd "$(dirname "$0")/.."
source_dir=$PWD

if [ -n "${VISSORT_CHECK_DIR:-}" ]; then
  work=$VISSORT_CHECK_DIR
  mkdir -p "$work"
else
  work=$(mktemp -d "${TMPDIR:-/tmp}/vissort-check-install.XXXXXX")
  trap 'rm -rf "$work"' EXIT
fi
prefix=$work/prefix
build=$(realpath -m "${VISSORT_CHECK_BUILD_DIR:-$work/build}")
jobs=$(nproc)

bash scripts/install-deps.sh
echo "== check-install: building vissort in $build"
cmake -S "$source_dir" -B "$build" -DCMAKE_BUILD_TYPE=Release -DVISSORT_BUILD_TESTS=OFF \
  -DVISSORT_BUILD_BENCHMARKS=OFF "$@"
cmake --build "$build" -j"$jobs"
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix"

for f in lib/cmake/vissort/vissortConfig.cmake lib/cmake/vissort/vissortConfigVersion.cmake \
         lib/cmake/vissort/vissort-order-targets.cmake lib/cmake/vissort/vissort-all-targets.cmake include/vissort/vis_sort.h bin/vissort; do
  [ -e "$prefix/$f" ] || { echo "check-install: $f was not installed" >&2; exit 1; }
done
# Nothing of the source or build tree may leak into the installed package.
if grep -rl -e "$source_dir" -e "$build" "$prefix/lib/cmake/vissort"; then
  echo "check-install: the package above names the source or build tree" >&2
  exit 1
fi

# Every id 0..n-1 exactly once on the line "order: ..." of the output in file $1.
check_permutation() {
  local ids
  ids=$(sed -n 's/^order://p' "$1" | tr ' ' '\n' | sed '/^$/d')
  local n
  n=$(printf '%s\n' "$ids" | wc -l)
  if [ -z "$ids" ] || [ "$(printf '%s\n' "$ids" | sort -n | tr '\n' ' ')" != "$(seq 0 $((n - 1)) | tr '\n' ' ')" ]; then
    echo "check-install: the order printed is not a permutation of 0..$((n - 1)):" >&2
    cat "$1" >&2
    return 1
  fi
}

for example in examples/*/; do
  [ -f "$example/CMakeLists.txt" ] || continue # examples/scenes/ holds scene files, no project
  name=$(basename "$example")
  # A vissort built without OpenGL installs no render component.
  if [ "$name" = render_transparent ] &&
     [ ! -e "$prefix/lib/cmake/vissort/vissort-render-targets.cmake" ]; then
    echo "== check-install: example $name skipped (no render component: built without OpenGL)"
    continue
  fi
  echo "== check-install: example $name"
  cmake -S "$example" -B "$work/examples/$name" -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_PREFIX_PATH="$prefix"
  cmake --build "$work/examples/$name" -j"$jobs"
done

run() {  # run OUTPUT_FILE PROGRAM ARGS...: runs one example, keeps its output and shows its start
  local out=$1
  shift
  echo "\$ $(basename "$1") ${*:2}"
  "$@" >"$out"
  cut -c1-100 "$out"
}
bin=$work/examples
run "$work/out.txt" "$bin/order_mesh/order_mesh" examples/scenes/pinwheel_cycle.json
check_permutation "$work/out.txt"
grep -q '^examples/scenes/pinwheel_cycle.json: 4 objects' "$work/out.txt"
grep -qx 'cycles: 1, queries: [0-9]*' "$work/out.txt" ||
  { echo "check-install: order_mesh: expected the pinwheel's one cycle" >&2; exit 1; }
run "$work/out.txt" "$bin/order_mesh/order_mesh" assets/models/bunny-lowres.obj triangle
check_permutation "$work/out.txt"
# order_mesh uses the command line's camera policy (view_choice.h): its order is the one
# `vissort order` prints for the same scene and level.
for args in "examples/scenes/teapot_in_glass.json object" "assets/models/bunny-lowres.obj triangle"; do
  set -- $args
  run "$work/out.txt" "$bin/order_mesh/order_mesh" "$1" "$2"
  cli_order=$("$prefix/bin/vissort" order "$1" --level "$2" --json - -q |
    sed -n 's/.*"order":\[\([0-9,]*\)\].*/\1/p' | tr ',' ' ')
  [ -n "$cli_order" ] && [ "$(sed -n 's/^order: //p' "$work/out.txt")" = "$cli_order" ] ||
    { echo "check-install: order_mesh $1 $2: not the order vissort order prints ($cli_order)" >&2; exit 1; }
done
run "$work/out.txt" "$bin/order_triangles/order_triangles"
check_permutation "$work/out.txt"
grep -qx 'order: 1 3 0 2 4' "$work/out.txt" || { echo "check-install: order_triangles: expected order: 1 3 0 2 4" >&2; exit 1; }
run "$work/out.txt" "$bin/order_frames/order_frames"
grep -qx 'order: 0 1 2' "$work/out.txt" || { echo "check-install: order_frames: expected order: 0 1 2" >&2; exit 1; }
# collide_objects: the crossed bars (one bar through the other) collide, as vissort collide says.
run "$work/out.txt" "$bin/collide_objects/collide_objects" tests/data/scenes/crossed_bars.json
grep -qx "  0 'bar_x' and 1 'bar_y'" "$work/out.txt" ||
  { echo "check-install: collide_objects: expected the bars 0 and 1 to collide" >&2; exit 1; }
"$prefix/bin/vissort" collide tests/data/scenes/crossed_bars.json -q --json - |
  grep -q '"object_pairs_colliding":\[\[0,1\]\]' ||
  { echo "check-install: vissort collide does not say the bars collide as collide_objects does" >&2; exit 1; }
# render_transparent (with OpenGL only): the PNG `vissort render` writes, byte for byte.
if [ -x "$bin/render_transparent/render_transparent" ]; then
  run "$work/out.txt" "$bin/render_transparent/render_transparent" \
    examples/scenes/teapot_in_glass.json "$work/example.png" 160x120
  "$prefix/bin/vissort" render examples/scenes/teapot_in_glass.json --size 160x120 \
    -o "$work/cli.png" -q
  cmp "$work/example.png" "$work/cli.png" ||
    { echo "check-install: render_transparent's picture is not vissort render's" >&2; exit 1; }
fi
# Each example found only the dependencies of the components it names: order_frames (order)
# none of Embree, assimp, Bullet, FCL or OpenGL, order_triangles (oracles) no assimp or peers.
forbidden_in() {  # forbidden_in EXAMPLE KEY...: fails if the example's cache has a KEY* entry
  local cache=$work/examples/$1/CMakeCache.txt
  shift
  for key in "$@"; do
    if grep -q "^$key" "$cache"; then
      echo "check-install: the example $(basename "$(dirname "$cache")") found $key, which its components do not need" >&2
      exit 1
    fi
  done
}
forbidden_in order_frames embree_DIR assimp_DIR fcl_DIR Bullet_DIR BULLET_ nlohmann_json_DIR OPENGL_
forbidden_in order_triangles assimp_DIR fcl_DIR Bullet_DIR BULLET_ nlohmann_json_DIR
forbidden_in collide_objects fcl_DIR Bullet_DIR BULLET_ OPENGL_
# ... and a consumer of everything did find them (the check above can fail).
grep -q '^embree_DIR' "$work/examples/order_mesh/CMakeCache.txt" ||
  { echo "check-install: order_mesh did not find Embree" >&2; exit 1; }
# A bad file is one line on stderr and a non-zero exit; so is a built-in scene, which is the
# samples' (the vissort command's), not the installed library's.
if "$bin/order_mesh/order_mesh" no-such-file.obj 2>/dev/null; then
  echo "check-install: order_mesh accepted a missing file" >&2
  exit 1
fi
if "$bin/order_mesh/order_mesh" builtin:slabs 2>"$work/err.txt" ||
   ! grep -q "no built-in scenes here" "$work/err.txt" || [ "$(wc -l <"$work/err.txt")" != 1 ]; then
  echo "check-install: order_mesh: builtin:slabs is not one line saying the library has none:" >&2
  cat "$work/err.txt" >&2
  exit 1
fi
echo "== check-install: the installed package builds and runs every example"
