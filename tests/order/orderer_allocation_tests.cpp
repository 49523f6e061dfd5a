// SceneOrderer::orderFrame(positions, view, out) allocates nothing in steady state: after the
// first frames have grown the orderer's, Vis-sort's, the oracle's and out's buffers, a coherent
// frame reuses them. Its own executable, because it replaces the global operator new and delete
// with counting versions.
//
// The scene and camera are chosen so that no frame has a cycle, at either stage: Vis-sort's cycle
// search (src/core/source_cycle.cpp: its walk's path and the sources it returns are vectors of
// vectors) and VisibilityOrder::cycles allocate on a frame that meets a cycle: 9 to 16
// allocations a frame with builtin:bunnies?n=4 (one object cycle every frame) at 64x64. Three
// bunnies with seed 2 have none, so the test asserts that no frame it counts has one at object
// level, where a cycle would show (multistage's stage-1 cycles are not in its output).
#include <atomic>
#include <cstdlib>
#include <iostream>
#include <new>

#include <gtest/gtest.h>

#include "test_scene_loading.h"
#include "vissort/oracles.h"
#include "vissort/scene_orderer.h"

namespace {

std::atomic<bool> g_counting{false};
std::atomic<uint64_t> g_allocations{0};

void* allocate(std::size_t size, std::size_t alignment) {
    if (g_counting.load(std::memory_order_relaxed))
        g_allocations.fetch_add(1, std::memory_order_relaxed);
    if (size == 0)
        size = 1;
    void* p = alignment <= alignof(std::max_align_t)
                  ? std::malloc(size)
                  : std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
    return p;
}

} // namespace

void* operator new(std::size_t size) {
    if (void* p = allocate(size, alignof(std::max_align_t)))
        return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
    return operator new(size);
}
void* operator new(std::size_t size, std::align_val_t alignment) {
    if (void* p = allocate(size, std::size_t(alignment)))
        return p;
    throw std::bad_alloc();
}
void* operator new[](std::size_t size, std::align_val_t alignment) {
    return operator new(size, alignment);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    return allocate(size, alignof(std::max_align_t));
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    return allocate(size, alignof(std::max_align_t));
}
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return allocate(size, std::size_t(alignment));
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
    return allocate(size, std::size_t(alignment));
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept {
    std::free(p);
}

namespace vissort {
namespace {

constexpr int kFrames = 8;

class OrdererAllocations : public testing::TestWithParam<OrderLevel> {};

TEST_P(OrdererAllocations, SteadyStateFramesAllocateNothing) {
    const Scene scene = test::loadTestScene("builtin:bunnies?n=3&seed=2");
    ASSERT_TRUE(scene.isDynamic());
    Result<std::unique_ptr<GeometryOracle>> oracle = makeOracle(OracleKind::cpu, {.threads = 1});
    ASSERT_TRUE(oracle) << oracle.error;
    SceneOrderer orderer(scene.objectPrimitives(), uint32_t(scene.triangleCount()), GetParam(),
                         **oracle.value);
    const CameraSpec camera = scene.camera.value_or(defaultCamera(scene.positions.bounds()));
    TrianglePositions positions;
    FrameOrder frame;
    for (int f = 0; f < kFrames; ++f) {
        scene.frame(f / 30.0, positions);
        const ViewProjection view = frameCamera(camera, positions.bounds(), 64, 64);
        g_allocations = 0;
        g_counting = true;
        orderer.orderFrame(positions, view, frame);
        g_counting = false;
        const uint64_t allocations = g_allocations;
        std::cout << orderLevelName(GetParam()) << " frame " << f << ": " << allocations
                  << " allocations, " << frame.cycles.size() << " cycles, " << frame.stats.queries
                  << " queries\n";
        ASSERT_EQ(frame.order.size(),
                  GetParam() == OrderLevel::object ? scene.objects.size() : scene.triangleCount());
        ASSERT_TRUE(frame.cycles.empty()) << "frame " << f << ": the scene must have no cycle";
        if (f >= 2)
            EXPECT_EQ(allocations, 0u) << "frame " << f;
    }
}

INSTANTIATE_TEST_SUITE_P(Levels, OrdererAllocations,
                         testing::Values(OrderLevel::object, OrderLevel::multistage),
                         [](const testing::TestParamInfo<OrderLevel>& info) {
                             return std::string(orderLevelName(info.param));
                         });

} // namespace
} // namespace vissort
