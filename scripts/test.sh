#!/usr/bin/env bash
# Installs the dependencies, builds, and runs every test. The README's test command.
#   bash scripts/test.sh              Release build in build/
#   bash scripts/test.sh --sanitize   AddressSanitizer + UndefinedBehaviorSanitizer, without OpenGL,
#                                     in build-sanitize/
#   bash scripts/test.sh --tsan       ThreadSanitizer on the threaded code's tests, in build-tsan/
#   bash scripts/test.sh --no-gl      Release without OpenGL (-DVISSORT_WITH_GL=OFF), in build-nogl/:
#                                     every test that exists there; no benchmarks
set -euo pipefail
cd "$(dirname "$0")/.."

build_dir=build
# The Python module and its tests: built for Debian's interpreter, whose numpy and pytest
# install-deps.sh installs (a python3 earlier on PATH, such as pyenv's, may lack them).
flags=(-DCMAKE_BUILD_TYPE=Release -DVISSORT_WITH_PYTHON=ON -DPython3_EXECUTABLE=/usr/bin/python3)
benchmarks=ON
targets=()
tests=()
timeout=600
if [ "${1:-}" = "--sanitize" ]; then
  build_dir=build-sanitize
  # Line tables only (-g1): the sanitizers' reports still name files and lines, and the build
  # links far less debug information. The library at -O2, the test sources at -O1
  # (tests/CMakeLists.txt). Measured on the 2-core VM, this stage: 1,586 s at -O2 everywhere,
  # 1,467 s at -O1 everywhere, 1,555 s this way (about 900 s of build, 660 s of tests): the
  # choice matters little; shorter CI needs fewer or smaller sanitized tests. No Google
  # Benchmarks: they measure, the suite checks.
  # Without OpenGL (-DVISSORT_WITH_GL=OFF): this stage is also CI's build without OpenGL, one
  # build fewer (the no-GL stage's own build and tests took 476 s of a 3,017 s CI run at 428e85b,
  # and CI has since grown past its 90 minutes on a slower VM). The GL code (the gl oracle, the GL renderers, the viewer) then runs its tests in
  # the release suite only; everything else, the exact model and the cpu oracle included, runs
  # here under both sanitizers.
  flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DVISSORT_SANITIZE=ON -DVISSORT_WITH_GL=OFF
         "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG")
  benchmarks=OFF
  # The slowest tests of the release suite (six times as long here) run there only: smaller
  # tests of the same code (the oracle passes on small viewports, collide on a few frames, bench
  # oracle with one GL frame, the every-frame check on the bunnies and the property scenes, the
  # touching-faces scenes for the IFC house, the coplanar faces for the boxes and walls) run here.
  tests=(-E "TouchingFaces.BoxesSharingFacesMakeNoCycle|TouchingFaces.WallsOnASlabMakeNoCycle|CpuOracle.LargeViewportWithBigTriangles|CpuOracle.SpotMeshBothProjections|Cli.CollideMatchesBruteForceOver300FramesOfBunnies|Cli.BenchOracleMeasuresEveryOracleInOneRun|EveryFrame.EveryOrderMatchesItsFramesGroundTruth/powerplant_|RealModels.FzkHouseHasTheExactCyclesAndExactTransparency")
elif [ "${1:-}" = "--tsan" ]; then
  # The threaded code: the rasterizer's banded passes (its tests run 1, 2 and 3 threads), the
  # collision detector's shared refits and pairs, and the volume methods' bands of rows and the
  # ray caster's rows (their tests compare 1 and 3 threads; Embree's own threads are not
  # instrumented: tests/tsan.supp).
  build_dir=build-tsan
  flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DVISSORT_TSAN=ON)
  targets=(--target raster_tests collide_tests volume_tests)
  # CpuOracle.SpotMeshBothProjections takes about 300 to 530 s alone under ThreadSanitizer (19 s
  # in the release build; its 640x480 queries of the whole mesh against itself arbitrate at
  # every pixel): the same banded passes run in the other CpuOracle tests at 1, 2 and 3 threads,
  # so it runs in the release suite only, as under the other sanitizers; so does
  # CpuOracle.LargeViewportWithBigTriangles (its longest test after that one: a 1600x1200
  # viewport's passes, which the banded tests run on smaller viewports at 1 to 3 threads).
  tests=(-R "CpuOracle|CollisionThreads|VolumeRenderer.ThreadCount|CellWalkRayCaster.ThreadCount"
         -E "CpuOracle.SpotMeshBothProjections|CpuOracle.LargeViewportWithBigTriangles")
  timeout=600
elif [ "${1:-}" = "--no-gl" ]; then
  build_dir=build-nogl
  flags=(-DCMAKE_BUILD_TYPE=Release -DVISSORT_WITH_GL=OFF)
  benchmarks=OFF
elif [ -n "${1:-}" ]; then
  echo "test.sh: unknown option '$1' (expected --sanitize, --tsan or --no-gl)" >&2
  exit 2
fi

bash scripts/install-deps.sh
cmake -S . -B "$build_dir" "${flags[@]}" -DVISSORT_BUILD_TESTS=ON \
  -DVISSORT_BUILD_BENCHMARKS="$benchmarks"
cmake --build "$build_dir" -j"$(nproc)" "${targets[@]}"
# Embree starts its own worker threads; LeakSanitizer cannot follow them reliably, and the suite
# checks memory errors, not leaks at exit (the tool frees everything it allocates per frame).
export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export TSAN_OPTIONS="halt_on_error=1 suppressions=$PWD/tests/tsan.supp"
ctest --test-dir "$build_dir" --output-on-failure -j"$(nproc)" --timeout "$timeout" "${tests[@]}"
