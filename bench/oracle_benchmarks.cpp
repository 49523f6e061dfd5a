// Occlusion oracle throughput: CpuOracle beside the reference CpuReferenceOracle, measured in the
// same run on the same inputs.
//  - setup-bound: random right triangles with 10 px legs at 1920 x 1080, drawn back to front
//    (every one passes the depth test), and queried against a far background (every answer
//    false, so the reference visits every fragment): triangles per second (items_per_second);
//  - fill-bound: the same with 100 px and 500 px legs at 1600 x 1200: pixels per second;
//  - real workload: triangle-level Vis-sort of builtin:bunnies (18 bunnies) at 1024 x 768 over
//    10 coherent frames of an orbit (SceneOrderer): ms per frame, queries and iterations per frame.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "harnesses/oracle_workloads.h"
#include "scenes/scene_library.h"
#include "vissort/camera_path.h"
#include "vissort/cpu_oracle.h"
#include "vissort/cpu_reference_oracle.h"
#include "vissort/frame_driver.h"
#include "vissort/scene.h"
#include "vissort/scene_orderer.h"

namespace vissort {
namespace {

/// Covered pixels of one back-to-front draw of every random triangle, by the reference.
uint64_t fieldPixels(const ScreenTriangleWorkload& field) {
    CpuReferenceOracle oracle;
    oracle.bind(field.positions, field.view, field.primitives);
    for (uint32_t i = 0; i < field.background; ++i)
        oracle.draw(i);
    return oracle.stats().fragments_drawn;
}

template <class Oracle>
void drawBackToFront(benchmark::State& state, uint32_t count, double leg, uint32_t width,
                     uint32_t height) {
    const ScreenTriangleWorkload field = makeRightTriangleWorkload(count, leg, width, height);
    const uint64_t pixels = fieldPixels(field);
    Oracle oracle;
    oracle.bind(field.positions, field.view, field.primitives);
    for (auto _ : state) {
        oracle.clear();
        for (uint32_t i = 0; i < field.background; ++i)
            oracle.draw(i);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(int64_t(state.iterations()) * count);
    state.counters["pixels_per_second"] = benchmark::Counter(
        double(pixels) * double(state.iterations()), benchmark::Counter::kIsRate);
}

template <class Oracle>
void queryAgainstBackground(benchmark::State& state, uint32_t count, double leg, uint32_t width,
                            uint32_t height) {
    const ScreenTriangleWorkload field = makeRightTriangleWorkload(count, leg, width, height);
    const uint64_t pixels = fieldPixels(field);
    Oracle oracle;
    oracle.bind(field.positions, field.view, field.primitives);
    oracle.draw(field.background);
    uint64_t behind = 0;
    for (auto _ : state)
        for (uint32_t i = 0; i < field.background; ++i)
            behind += oracle.anyBehind(i);
    if (behind != 0)
        state.SkipWithError("a triangle in front of the background answered behind");
    state.SetItemsProcessed(int64_t(state.iterations()) * count);
    state.counters["pixels_per_second"] = benchmark::Counter(
        double(pixels) * double(state.iterations()), benchmark::Counter::kIsRate);
}

// Setup-bound: 10 px legs at 1920 x 1080.
void BM_SetupBoundDraw_Cpu(benchmark::State& s) {
    drawBackToFront<CpuReferenceOracle>(s, 100000, 10, 1920, 1080);
}
void BM_SetupBoundDraw_Fast(benchmark::State& s) {
    drawBackToFront<CpuOracle>(s, 100000, 10, 1920, 1080);
}
void BM_SetupBoundQuery_Cpu(benchmark::State& s) {
    queryAgainstBackground<CpuReferenceOracle>(s, 100000, 10, 1920, 1080);
}
void BM_SetupBoundQuery_Fast(benchmark::State& s) {
    queryAgainstBackground<CpuOracle>(s, 100000, 10, 1920, 1080);
}
BENCHMARK(BM_SetupBoundDraw_Cpu)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SetupBoundDraw_Fast)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SetupBoundQuery_Cpu)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SetupBoundQuery_Fast)->Unit(benchmark::kMillisecond);

// Fill-bound: 100 px and 500 px legs at 1600 x 1200.
template <class Oracle> void fillDraw(benchmark::State& s) {
    const double leg = double(s.range(0));
    drawBackToFront<Oracle>(s, leg >= 500 ? 200 : 2000, leg, 1600, 1200);
}
template <class Oracle> void fillQuery(benchmark::State& s) {
    const double leg = double(s.range(0));
    queryAgainstBackground<Oracle>(s, leg >= 500 ? 200 : 2000, leg, 1600, 1200);
}
BENCHMARK(fillDraw<CpuReferenceOracle>)
    ->Name("BM_FillBoundDraw_Cpu")
    ->Arg(100)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(fillDraw<CpuOracle>)
    ->Name("BM_FillBoundDraw_Fast")
    ->Arg(100)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(fillQuery<CpuReferenceOracle>)
    ->Name("BM_FillBoundQuery_Cpu")
    ->Arg(100)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(fillQuery<CpuOracle>)
    ->Name("BM_FillBoundQuery_Fast")
    ->Arg(100)
    ->Arg(500)
    ->Unit(benchmark::kMillisecond);

// Real workload: triangle-level Vis-sort of the 18 bunnies along an orbit, 10 coherent frames.
template <class Oracle> void bunniesOrbit(benchmark::State& state) {
    const Result<Scene> loaded = samples::loadScene("builtin:bunnies");
    if (!loaded) {
        state.SkipWithError(loaded.error.c_str());
        return;
    }
    const Scene& scene = *loaded.value;
    constexpr int kFrames = 10;
    constexpr uint32_t kWidth = 1024, kHeight = 768;
    const CameraSpec base = scene.camera
                                ? *scene.camera
                                : defaultCamera(scene.positions.bounds(), double(kWidth) / kHeight);
    // Every frame made before timing: the loop measures ordering alone.
    FrameDriver driver(scene, base, CameraPath::orbit, kWidth, kHeight);
    std::vector<TrianglePositions> positions(kFrames);
    std::vector<ViewProjection> views(kFrames);
    for (int f = 0; f < kFrames; ++f) {
        driver.seek(f);
        const PositionsView frame = driver.positions();
        positions[f].x.assign(frame.x.begin(), frame.x.end());
        positions[f].y.assign(frame.y.begin(), frame.y.end());
        positions[f].z.assign(frame.z.begin(), frame.z.end());
        views[f] = driver.view();
    }
    uint64_t queries = 0, iterations = 0, frames = 0;
    double milliseconds = 0;
    for (auto _ : state) {
        Oracle oracle;
        SceneOrderer orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()),
                             OrderLevel::triangle, oracle);
        for (int f = 0; f < kFrames; ++f) {
            const FrameOrder order = orderer.orderFrame(positions[f], views[f]);
            queries += order.stats.queries;
            iterations += order.stats.iterations;
            milliseconds += order.milliseconds;
            ++frames;
        }
    }
    state.counters["ms_per_frame"] = milliseconds / double(frames);
    state.counters["queries_per_frame"] = double(queries) / double(frames);
    state.counters["iterations_per_frame"] = double(iterations) / double(frames);
    state.counters["triangles"] = double(scene.triangleCount());
}
BENCHMARK(bunniesOrbit<CpuReferenceOracle>)
    ->Name("BM_BunniesOrbitTriangles_Cpu")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);
BENCHMARK(bunniesOrbit<CpuOracle>)
    ->Name("BM_BunniesOrbitTriangles_Fast")
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1);

} // namespace
} // namespace vissort

BENCHMARK_MAIN();
