// Ordering scenes at a level (scene_orderer.h): the frame's entry point. Its parts have files of
// their own: scene_orderer_sort.h (one Vis-sort over a start order, the oracle bound in it),
// scene_orderer_coherence.cpp (stage 1 from last frame's order and cycles) and
// scene_orderer_multistage.cpp (the triangles of each object or object cycle).

#include <algorithm>
#include <cassert>
#include <chrono>
#include <stdexcept>
#include <string>

#include "vissort/scene_orderer.h"

namespace vissort {

std::vector<PrimitiveRange> levelPrimitives(std::span<const PrimitiveRange> objects,
                                            uint32_t triangle_count, OrderLevel level) {
    if (level == OrderLevel::object)
        return {objects.begin(), objects.end()};
    std::vector<PrimitiveRange> triangles(triangle_count);
    for (uint32_t t = 0; t < triangle_count; ++t)
        triangles[t] = {t, 1};
    return triangles;
}

SceneOrderer::SceneOrderer(std::span<const PrimitiveRange> objects, uint32_t triangle_count,
                           OrderLevel level, GeometryOracle& oracle)
    : objects_(objects.begin(), objects.end()), triangle_count_(triangle_count), level_(level),
      oracle_(oracle) {
    indexObjects();
}

void SceneOrderer::setObjects(std::span<const PrimitiveRange> objects, uint32_t triangle_count) {
    if (objects.size() != objects_.size())
        throw std::invalid_argument("SceneOrderer::setObjects: " + std::to_string(objects.size()) +
                                    " objects, the orderer orders " +
                                    std::to_string(objects_.size()));
    const bool same = triangle_count == triangle_count_ &&
                      std::equal(objects.begin(), objects.end(), objects_.begin(),
                                 [](const PrimitiveRange& a, const PrimitiveRange& b) {
                                     return a.first_triangle == b.first_triangle &&
                                            a.triangle_count == b.triangle_count;
                                 });
    if (same)
        return;
    objects_.assign(objects.begin(), objects.end());
    triangle_count_ = triangle_count;
    // Object ids keep their meaning: last frame's object order still seeds this one. Triangle
    // ids do not: orders of triangles start again from the depth-key order.
    previous_triangle_order_.clear();
    if (level_ == OrderLevel::triangle) {
        previous_order_.clear();
        sorted_.cycles.clear();
        sorted_.cycle_witnesses.clear();
    }
    indexObjects();
}

void SceneOrderer::indexObjects() {
    object_of_triangle_.clear();
    if (level_ != OrderLevel::multistage)
        return;
    object_of_triangle_.assign(triangle_count_, kNoObject);
    for (uint32_t o = 0; o < objects_.size(); ++o)
        for (uint32_t t = objects_[o].first_triangle;
             t < objects_[o].first_triangle + objects_[o].triangle_count; ++t) {
            if (object_of_triangle_[t] != kNoObject) {
                // Objects sharing triangles: a triangle has no single group to be dealt to;
                // every frame starts from the depth-key order (buildGroupStarts).
                object_of_triangle_.clear();
                return;
            }
            object_of_triangle_[t] = o;
        }
}

void SceneOrderer::orderFrame(PositionsView positions, const ViewProjection& view,
                              FrameOrder& out) {
    assert(positions.triangleCount() == triangle_count_);
    const auto start = std::chrono::steady_clock::now();
    out.level = level_;
    out.stats = {};
    if (level_ == OrderLevel::multistage) {
        orderMultistage(positions, view, out);
    } else {
        sortStage1(positions, view);
        out.order = previous_order_; // copy-assignments: the vectors keep their capacity
        out.cycles = sorted_.cycles;
        out.stats = sorted_.stats;
    }
    out.milliseconds =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

FrameOrder SceneOrderer::orderFrame(PositionsView positions, const ViewProjection& view) {
    FrameOrder frame;
    orderFrame(positions, view, frame);
    return frame;
}

void SceneOrderer::orderFrame(const VertexPositionsView& vertices, const ViewProjection& view,
                              FrameOrder& out) {
    if (Status gathered = gatherPositions(vertices, gathered_); !gathered)
        throw std::invalid_argument("vertex positions: " + gathered.error);
    if (gathered_.triangleCount() != triangle_count_)
        throw std::invalid_argument(
            "vertex positions hold " + std::to_string(gathered_.triangleCount()) +
            " triangles; the orderer was made for " + std::to_string(triangle_count_));
    orderFrame(gathered_.view(), view, out);
}

void SceneOrderer::setProgress(std::function<void(double fraction)> report) {
    progress_ = std::move(report);
}

} // namespace vissort
