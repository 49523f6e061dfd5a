// All-hits ray casting with Embree 3 (Wald, Woop, Benthin, Johnson, Ernst: "Embree: A Kernel
// Framework for Efficient CPU Ray Tracing", SIGGRAPH 2014): an intersection filter records every
// candidate and rejects it so that traversal goes on to the end of the ray. Each candidate is
// then re-intersected in double precision (Moller, Trumbore: "Fast, Minimum Storage Ray/Triangle
// Intersection", JGT 1997) for its depth and barycentric coordinates.

#include "exact/ray_caster.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

#include <embree3/rtcore.h>

namespace vissort::detail {
namespace {

// Owns one Embree handle (device or scene) and releases it once: non-copyable RAII.
template <class Handle, void (*release)(Handle)> class EmbreeHandle {
public:
    explicit EmbreeHandle(Handle handle) : handle_(handle) {}
    ~EmbreeHandle() {
        if (handle_)
            release(handle_);
    }
    EmbreeHandle(const EmbreeHandle&) = delete;
    EmbreeHandle& operator=(const EmbreeHandle&) = delete;

    Handle get() const { return handle_; }

private:
    Handle handle_;
};

using EmbreeDevice = EmbreeHandle<RTCDevice, rtcReleaseDevice>;
using EmbreeScene = EmbreeHandle<RTCScene, rtcReleaseScene>;

// One device for the process: creating one starts Embree's thread pool, too costly per frame.
RTCDevice sharedDevice() {
    static const EmbreeDevice device(rtcNewDevice(nullptr));
    if (!device.get()) {
        throw std::runtime_error("cannot create an Embree device (error " +
                                 std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    }
    return device.get();
}

struct Candidate {
    uint32_t triangle;
    float embree_distance; // used only when the double-precision test finds the ray parallel
};

// Embree hands the filter the context pointer it was given, so the context must come first.
struct CandidateCollector {
    RTCIntersectContext context;
    std::vector<Candidate>* candidates;
};

void recordAndReject(const RTCFilterFunctionNArguments* args) {
    assert(args->N == 1);
    if (!args->valid[0])
        return;
    auto* collector = reinterpret_cast<CandidateCollector*>(args->context);
    // During the filter call the ray's tfar holds the candidate's distance.
    collector->candidates->push_back(
        {RTCHitN_primID(args->hit, 1, 0), RTCRayN_tfar(args->ray, 1, 0)});
    args->valid[0] = 0; // rejecting keeps tfar, so every later triangle is still found
}

bool isFinite(float x, float y, float z) {
    return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

void addTriangles(RTCDevice device, RTCScene scene, PositionsView positions) {
    const std::size_t triangle_count = positions.triangleCount();
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), 3 * triangle_count));
    auto* indices = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(uint32_t), triangle_count));
    if (!vertices || !indices) {
        rtcReleaseGeometry(geometry);
        throw std::runtime_error("Embree could not allocate the geometry buffers");
    }
    for (std::size_t t = 0; t < triangle_count; ++t) {
        bool finite = true;
        for (std::size_t k = 3 * t; k < 3 * t + 3; ++k)
            finite = finite && isFinite(positions.x[k], positions.y[k], positions.z[k]);
        for (std::size_t k = 3 * t; k < 3 * t + 3; ++k) {
            // A triangle with a non-finite corner collapses to a point, which is never hit.
            vertices[3 * k + 0] = finite ? positions.x[k] : 0.0f;
            vertices[3 * k + 1] = finite ? positions.y[k] : 0.0f;
            vertices[3 * k + 2] = finite ? positions.z[k] : 0.0f;
            indices[k] = uint32_t(k);
        }
    }
    rtcSetGeometryIntersectFilterFunction(geometry, recordAndReject);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry); // the scene holds its own reference
}

// Moller-Trumbore for the ray o + t dir against triangle (a, b, c), in double precision and
// before the division by det: the hit's barycentrics are u = u_det / det, v = v_det / det, its
// distance t = t_det / det; det is 0 (or not finite) when the ray is parallel to the plane.
// Callers scale by det themselves: the robustness test divides, intersect multiplies by 1 / det.
struct RayTriangle {
    double det, u_det, v_det, t_det;
};
RayTriangle rayTriangle(const Vec3& o, const Vec3& dir, const Vec3& a, const Vec3& b,
                        const Vec3& c) {
    const Vec3 e1 = b - a, e2 = c - a;
    const Vec3 p = cross(dir, e2);
    const Vec3 s = o - a;
    const Vec3 q = cross(s, e1);
    return {dot(e1, p), dot(s, p), dot(dir, q), dot(e2, q)};
}

// Depth d of a world point in closed form (same as ViewProjection::depthOf, without building
// matrices per hit): the eye-space distance is minus the third row of the view matrix.
class DepthFunction {
public:
    explicit DepthFunction(const ViewProjection& view)
        : row_{view.view[2], view.view[6], view.view[10], view.view[14]},
          perspective_(view.projection == Projection::perspective), near_(view.near),
          far_(view.far) {}

    double operator()(const Vec3& p) const {
        const double z = -(row_[0] * p.x + row_[1] * p.y + row_[2] * p.z + row_[3]);
        return perspective_ ? 1.0 - near_ / z : (z - near_) / (far_ - near_);
    }

private:
    double row_[4];
    bool perspective_;
    double near_, far_;
};

struct PixelHit {
    uint32_t triangle;
    double depth;
    bool robust;
};

struct RowBlock {
    std::vector<uint32_t> hit_counts; // one per pixel of the block
    std::vector<PixelHit> hits;
    std::vector<uint8_t> near_edge; // one per pixel of the block
};

class BlockCaster {
public:
    BlockCaster(RTCScene scene, PositionsView positions, const ViewProjection& view,
                bool mark_near_edges)
        : scene_(scene), positions_(positions), view_(view), depth_of_(view),
          mark_near_edges_(mark_near_edges) {}

    void cast(uint32_t first_row, uint32_t end_row, RowBlock& block) {
        block.hit_counts.clear();
        block.hits.clear();
        block.near_edge.clear();
        for (uint32_t py = first_row; py < end_row; ++py) {
            for (uint32_t px = 0; px < view_.width; ++px) {
                const std::size_t before = block.hits.size();
                uint8_t near_edge = 0;
                castPixel(px, py, block.hits, near_edge);
                block.hit_counts.push_back(uint32_t(block.hits.size() - before));
                block.near_edge.push_back(near_edge);
            }
        }
    }

private:
    // Every triangle the ray from origin along direction meets, into `into` (cleared first).
    void collect(const Vec3& origin, const Vec3& direction, std::vector<Candidate>& into) {
        into.clear();
        CandidateCollector collector;
        rtcInitIntersectContext(&collector.context);
        collector.candidates = &into;

        RTCRayHit ray_hit{};
        ray_hit.ray.org_x = float(origin.x);
        ray_hit.ray.org_y = float(origin.y);
        ray_hit.ray.org_z = float(origin.z);
        ray_hit.ray.dir_x = float(direction.x);
        ray_hit.ray.dir_y = float(direction.y);
        ray_hit.ray.dir_z = float(direction.z);
        ray_hit.ray.tnear = 0.0f;
        ray_hit.ray.tfar = std::numeric_limits<float>::infinity();
        ray_hit.ray.mask = ~0u;
        ray_hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &collector.context, &ray_hit);
    }

    // Is some triangle that the ray through screen point (sx, sy) meets within [0, 1] in depth
    // missing from the centre ray's candidates?
    bool meetsAnother(double sx, double sy) {
        Vec3 origin, direction;
        view_.pixelRay(sx, sy, origin, direction);
        collect(origin, direction, corner_candidates_);
        const Vec3& o = origin;
        const Vec3& dir = direction;
        for (const Candidate& corner : corner_candidates_) {
            const bool at_centre =
                std::any_of(candidates_.begin(), candidates_.end(),
                            [&](const Candidate& c) { return c.triangle == corner.triangle; });
            if (at_centre)
                continue;
            const double depth = intersect(corner, o, dir).depth;
            if (depth >= 0.0 && depth <= 1.0)
                return true;
        }
        return false;
    }

    void castPixel(uint32_t px, uint32_t py, std::vector<PixelHit>& out, uint8_t& near_edge) {
        Vec3 origin, direction;
        view_.pixelRay(px + 0.5, py + 0.5, origin, direction);
        collect(origin, direction, candidates_);

        const std::size_t first = out.size();
        const Vec3& o = origin;
        const Vec3& dir = direction;
        // Rays through the corners of a square of side 2 * kRobustPixelMargin around the centre.
        Vec3 corner_origins[4], corner_directions[4];
        for (int i = 0; i < 4; ++i)
            view_.pixelRay(px + 0.5 + ((i & 1) ? kRobustPixelMargin : -kRobustPixelMargin),
                           py + 0.5 + ((i & 2) ? kRobustPixelMargin : -kRobustPixelMargin),
                           corner_origins[i], corner_directions[i]);
        for (const Candidate& candidate : candidates_) {
            PixelHit hit = intersect(candidate, o, dir);
            // Robust only when the triangle covers the whole square: then the pixel centre is at
            // least the margin away from every edge in screen space, farther than any
            // rasterizer's sub-pixel snapping moves an edge.
            for (int i = 0; hit.robust && i < 4; ++i)
                hit.robust = covers(candidate, corner_origins[i], corner_directions[i]);
            if (hit.depth >= 0.0 && hit.depth <= 1.0)
                out.push_back(hit);
        }
        std::sort(out.begin() + first, out.end(), [](const PixelHit& a, const PixelHit& b) {
            return a.depth != b.depth ? a.depth < b.depth : a.triangle < b.triangle;
        });
        // Embree may report a triangle twice (it can sit in several leaves); the double-precision
        // re-intersection gives both reports the same depth, so duplicates are neighbours.
        out.erase(std::unique(out.begin() + first, out.end(),
                              [](const PixelHit& a, const PixelHit& b) {
                                  return a.triangle == b.triangle;
                              }),
                  out.end());
        if (!mark_near_edges_)
            return;
        near_edge = 0;
        for (int i = 0; i < 4 && !near_edge; ++i)
            near_edge =
                meetsAnother(px + 0.5 + ((i & 1) ? kRobustPixelMargin : -kRobustPixelMargin),
                             py + 0.5 + ((i & 2) ? kRobustPixelMargin : -kRobustPixelMargin));
    }

    RayTriangle rayCandidate(const Candidate& candidate, const Vec3& o, const Vec3& dir) const {
        const std::size_t k = 3 * std::size_t(candidate.triangle);
        return rayTriangle(o, dir, positions_.corner(k), positions_.corner(k + 1),
                           positions_.corner(k + 2));
    }

    bool covers(const Candidate& candidate, const Vec3& o, const Vec3& dir) const {
        const RayTriangle hit = rayCandidate(candidate, o, dir);
        if (hit.det == 0.0 || !std::isfinite(hit.det))
            return false;
        const double u = hit.u_det / hit.det;
        const double v = hit.v_det / hit.det;
        return u > 0 && v > 0 && 1.0 - u - v > 0;
    }

    PixelHit intersect(const Candidate& candidate, const Vec3& o, const Vec3& dir) const {
        const RayTriangle hit = rayCandidate(candidate, o, dir);
        if (hit.det == 0.0 || !std::isfinite(hit.det)) {
            // Embree saw a hit that double precision calls parallel: an edge-on grazing hit.
            const double t = candidate.embree_distance;
            return {candidate.triangle, depth_of_(o + t * dir), false};
        }
        const double inverse = 1.0 / hit.det;
        const double u = hit.u_det * inverse;
        const double v = hit.v_det * inverse;
        const double t = hit.t_det * inverse;
        const double w = 1.0 - u - v;
        const bool robust =
            u > kRobustBarycentric && v > kRobustBarycentric && w > kRobustBarycentric;
        return {candidate.triangle, depth_of_(o + t * dir), robust};
    }

    RTCScene scene_;
    PositionsView positions_;
    const ViewProjection& view_;
    DepthFunction depth_of_;
    bool mark_near_edges_;
    std::vector<Candidate> candidates_, corner_candidates_;
};

// Enough rows per block to amortise the scheduling, few enough to balance two to 64 threads.
constexpr uint32_t kRowsPerBlock = 4;
// Below this many pixels, starting threads costs more than it saves.
constexpr std::size_t kParallelThreshold = 64 * 64;

} // namespace

AllHits castAllHits(PositionsView positions, const ViewProjection& view, unsigned thread_count,
                    bool mark_near_edges) {
    assert(positions.x.size() == positions.y.size() && positions.x.size() == positions.z.size());
    assert(positions.x.size() % 3 == 0);
    assert(positions.triangleCount() < std::numeric_limits<uint32_t>::max());

    AllHits result;
    result.width = view.width;
    result.height = view.height;
    result.offsets.assign(result.pixelCount() + 1, 0);
    if (positions.triangleCount() == 0 || result.pixelCount() == 0)
        return result;

    const RTCDevice device = sharedDevice();
    EmbreeScene scene(rtcNewScene(device));
    rtcSetSceneFlags(scene.get(), RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene.get(), RTC_BUILD_QUALITY_HIGH);
    addTriangles(device, scene.get(), positions);
    rtcCommitScene(scene.get());
    if (const RTCError error = rtcGetDeviceError(device); error != RTC_ERROR_NONE)
        throw std::runtime_error("Embree failed to build the scene (error " +
                                 std::to_string(int(error)) + ")");

    const uint32_t block_count = (view.height + kRowsPerBlock - 1) / kRowsPerBlock;
    std::vector<RowBlock> blocks(block_count);
    std::atomic<uint32_t> next_block{0};
    const auto work = [&] {
        BlockCaster caster(scene.get(), positions, view, mark_near_edges);
        for (uint32_t b = next_block++; b < block_count; b = next_block++) {
            caster.cast(b * kRowsPerBlock, std::min(view.height, (b + 1) * kRowsPerBlock),
                        blocks[b]);
        }
    };
    if (thread_count == 0)
        thread_count = std::max(1u, std::thread::hardware_concurrency());
    if (result.pixelCount() < kParallelThreshold)
        thread_count = 1;
    thread_count = std::min(thread_count, block_count);
    std::vector<std::thread> helpers;
    for (unsigned i = 1; i < thread_count; ++i)
        helpers.emplace_back(work);
    work();
    for (std::thread& helper : helpers)
        helper.join();

    // Blocks are stitched in row order, so the layout does not depend on which thread cast what.
    std::size_t total_hits = 0;
    for (const RowBlock& block : blocks)
        total_hits += block.hits.size();
    result.triangles.reserve(total_hits);
    result.depths.reserve(total_hits);
    result.robust.reserve(total_hits);
    if (mark_near_edges)
        result.near_edge.reserve(result.pixelCount());
    std::size_t pixel = 0;
    for (const RowBlock& block : blocks) {
        if (mark_near_edges)
            result.near_edge.insert(result.near_edge.end(), block.near_edge.begin(),
                                    block.near_edge.end());
        for (uint32_t count : block.hit_counts) {
            result.offsets[pixel + 1] = result.offsets[pixel] + count;
            ++pixel;
        }
        for (const PixelHit& hit : block.hits) {
            result.triangles.push_back(hit.triangle);
            result.depths.push_back(hit.depth);
            result.robust.push_back(hit.robust ? 1 : 0);
        }
    }
    assert(pixel == result.pixelCount());
    return result;
}

} // namespace vissort::detail
