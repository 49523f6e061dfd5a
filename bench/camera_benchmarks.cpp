// The default view's cost: framingCamera over the corners of builtin:soup (random triangles
// filling a cube) of 100K and 1M triangles, as `vissort render MESH` pays it once per run
// for a mesh file without a camera; a wide image (16:9), so the vertical extent does not bind
// and the horizontal one is centred.

#include <benchmark/benchmark.h>

#include "scenes/scene_library.h"
#include "vissort/camera.h"
#include "vissort/scene.h"

namespace vissort {
namespace {

void BM_FramingCamera(benchmark::State& state) {
    const Result<Scene> soup =
        samples::loadScene("builtin:soup?n=" + std::to_string(state.range(0)));
    if (!soup) {
        state.SkipWithError(soup.error.c_str());
        return;
    }
    for (auto _ : state)
        benchmark::DoNotOptimize(framingCamera(soup.value->positions, 16.0 / 9.0));
    state.SetItemsProcessed(state.iterations() * int64_t(soup.value->positions.x.size()));
}
BENCHMARK(BM_FramingCamera)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace vissort

BENCHMARK_MAIN();
