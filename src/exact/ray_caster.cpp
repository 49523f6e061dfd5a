// All-hits ray casting with Embree 3 (Wald, Woop, Benthin, Johnson, Ernst: "Embree: A Kernel
// Framework for Efficient CPU Ray Tracing", SIGGRAPH 2014). The triangles are Embree user
// geometry whose boxes are enlarged by a margin: the BVH then proposes every triangle the exact
// ray can meet (Embree's ray is its float copy), the intersection callback decides with the exact
// fragment model (geometry/exact_fragments.h) and records the triangle without committing a hit,
// so that traversal goes on to the end of the ray. Built-in triangles would be faster, but their
// float test may miss a triangle whose edge passes within rounding of the centre. Barycentric
// coordinates for the robust flag come from a double-precision re-intersection (Moller,
// Trumbore: "Fast, Minimum Storage Ray/Triangle Intersection", JGT 1997).

#include "exact/ray_caster.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>

#include <embree3/rtcore.h>

#include "exact/embree_device.h"

#include "geometry/exact_fragments.h"

namespace vissort::detail {
namespace {

// What the intersection callback needs: the exact ray it stands for (Embree's is its float copy),
// the model, the triangles, and where to record them. Embree hands the callback the context
// pointer it was given, so the context must come first.
struct CandidateCollector {
    RTCIntersectContext context;
    const PixelRay* ray;
    const ExactFragments* model;
    PositionsView positions;
    const uint32_t* triangles; // the triangle of each primitive id, or null: the id is it
    std::vector<uint32_t>* candidates;
};

void recordCovering(const RTCIntersectFunctionNArguments* args) {
    assert(args->N == 1);
    if (!args->valid[0])
        return;
    auto* collector = reinterpret_cast<CandidateCollector*>(args->context);
    const uint32_t triangle =
        collector->triangles != nullptr ? collector->triangles[args->primID] : args->primID;
    const TriangleCorners corners = TriangleCorners::of(collector->positions, triangle);
    if (collector->model->covers(*collector->ray, corners))
        collector->candidates->push_back(triangle);
    // No hit is committed: tfar stays infinite and every later triangle is still proposed.
}

// What the bounds callback needs.
struct BoundsData {
    PositionsView positions;
    float margin;
    std::span<const uint32_t> triangles; // the triangle of each primitive id; empty: all of them
    uint32_t count() const {
        return uint32_t(triangles.empty() ? positions.triangleCount() : triangles.size());
    }
};

void triangleBounds(const RTCBoundsFunctionArguments* args) {
    const auto* data = static_cast<const BoundsData*>(args->geometryUserPtr);
    const std::size_t first =
        3 * std::size_t(data->triangles.empty() ? args->primID : data->triangles[args->primID]);
    RTCBounds& box = *args->bounds_o;
    float lower[3] = {0, 0, 0}, upper[3] = {0, 0, 0};
    bool finite = true;
    for (std::size_t k = first; k < first + 3; ++k)
        finite = finite && std::isfinite(data->positions.x[k]) &&
                 std::isfinite(data->positions.y[k]) && std::isfinite(data->positions.z[k]);
    if (finite) { // a triangle with a non-finite corner is never hit: a point box at the origin
        const std::span<const float> axes[3] = {data->positions.x, data->positions.y,
                                                data->positions.z};
        for (int a = 0; a < 3; ++a) {
            lower[a] = std::min({axes[a][first], axes[a][first + 1], axes[a][first + 2]});
            upper[a] = std::max({axes[a][first], axes[a][first + 1], axes[a][first + 2]});
            lower[a] -= data->margin;
            upper[a] += data->margin;
        }
    }
    box = {lower[0], lower[1], lower[2], 0.0f, upper[0], upper[1], upper[2], 0.0f};
}

// The boxes' margin: far more than the distance between the exact ray and its float copy at any
// point of the scene (a few units in the last place of the coordinates and of the distance from
// the origin of the ray), so that the BVH proposes every triangle the exact ray meets.
float boxMargin(PositionsView positions, const ViewProjection& view) {
    // The largest finite coordinate (a triangle with another corner is never hit).
    float largest = 0;
    for (const std::span<const float> axis : {positions.x, positions.y, positions.z})
        for (float v : axis)
            largest = std::abs(v) <= 3.0e38f ? std::max(largest, std::abs(v)) : largest;
    const double scale = length(view.eye_position) + 4.0 * double(largest) + 1.0;
    return float(scale * 0x1p-16);
}

void addTriangles(RTCDevice device, RTCScene scene, BoundsData& bounds) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, bounds.count());
    rtcSetGeometryUserData(geometry, &bounds);
    rtcSetGeometryBoundsFunction(geometry, triangleBounds, nullptr);
    rtcSetGeometryIntersectFunction(geometry, recordCovering);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry); // the scene holds its own reference
}

// Moller-Trumbore for the ray o + t dir against triangle (a, b, c), in double precision and
// before the division by det: the hit's barycentrics are u = u_det / det, v = v_det / det, its
// distance t = t_det / det; det is 0 (or not finite) when the ray is parallel to the plane.
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
    uint32_t rank;
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
    BlockCaster(RTCScene scene, PositionsView positions, std::span<const uint32_t> triangles,
                const ExactFragments& model, const ViewProjection& view, bool mark_near_edges)
        : scene_(scene), positions_(positions),
          triangles_(triangles.empty() ? nullptr : triangles.data()), model_(model),
          depth_of_(view), width_(view.width), mark_near_edges_(mark_near_edges) {}

    void cast(uint32_t first_row, uint32_t end_row, RowBlock& block) {
        block.hit_counts.clear();
        block.hits.clear();
        block.near_edge.clear();
        for (uint32_t py = first_row; py < end_row; ++py) {
            for (uint32_t px = 0; px < width_; ++px) {
                const std::size_t before = block.hits.size();
                uint8_t near_edge = 0;
                castPixel(px, py, block.hits, near_edge);
                block.hit_counts.push_back(uint32_t(block.hits.size() - before));
                block.near_edge.push_back(near_edge);
            }
        }
    }

private:
    // Every triangle with a fragment at ray, into `into` (cleared first), ascending.
    void collect(const PixelRay& ray, std::vector<uint32_t>& into) {
        into.clear();
        CandidateCollector collector;
        rtcInitIntersectContext(&collector.context);
        collector.ray = &ray;
        collector.model = &model_;
        collector.positions = positions_;
        collector.triangles = triangles_;
        collector.candidates = &into;

        RTCRayHit ray_hit{};
        ray_hit.ray.org_x = float(ray.origin.x);
        ray_hit.ray.org_y = float(ray.origin.y);
        ray_hit.ray.org_z = float(ray.origin.z);
        ray_hit.ray.dir_x = float(ray.direction.x);
        ray_hit.ray.dir_y = float(ray.direction.y);
        ray_hit.ray.dir_z = float(ray.direction.z);
        // Every hit in the depth range lies at least near in front of the eye (perspective), or
        // beyond the eye plane 2 r before the scene (orthographic): far beyond the distance
        // between the float origin and the exact one. The model decides the range itself.
        ray_hit.ray.tnear = 0.0f;
        ray_hit.ray.tfar = std::numeric_limits<float>::infinity();
        ray_hit.ray.mask = ~0u;
        ray_hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &collector.context, &ray_hit);
        std::sort(into.begin(), into.end());
        // Embree may propose a triangle twice (it can sit in several leaves).
        into.erase(std::unique(into.begin(), into.end()), into.end());
    }

    // Is some triangle with a fragment at the ray through screen point (sx, sy) missing from
    // the centre ray's?
    bool meetsAnother(double sx, double sy) {
        collect(model_.rays().at(sx, sy), corner_candidates_);
        for (uint32_t t : corner_candidates_)
            if (!std::binary_search(candidates_.begin(), candidates_.end(), t))
                return true;
        return false;
    }

    void castPixel(uint32_t px, uint32_t py, std::vector<PixelHit>& out, uint8_t& near_edge) {
        const PixelRay ray = model_.rays().centre(px, py);
        collect(ray, candidates_);

        // Front to back by the exact model, ties by triangle id.
        order_.clear();
        for (uint32_t t : candidates_) {
            const TriangleCorners corners = TriangleCorners::of(positions_, t);
            order_.push_back({t, corners, model_.hit(ray, corners)});
        }
        std::sort(order_.begin(), order_.end(), [&](const Ordered& a, const Ordered& b) {
            const int c = model_.compare(ray, a.corners, a.hit, b.corners, b.hit);
            return c != 0 ? c < 0 : a.triangle < b.triangle;
        });

        // Rays through the corners of a square of side 2 * kRobustPixelMargin around the centre.
        PixelRay corner_rays[4];
        for (int i = 0; i < 4; ++i)
            corner_rays[i] =
                model_.rays().at(px + 0.5 + ((i & 1) ? kRobustPixelMargin : -kRobustPixelMargin),
                                 py + 0.5 + ((i & 2) ? kRobustPixelMargin : -kRobustPixelMargin));
        uint32_t rank = 0;
        for (std::size_t i = 0; i < order_.size(); ++i) {
            const Ordered& o = order_[i];
            if (i > 0 && model_.compare(ray, order_[i - 1].corners, order_[i - 1].hit, o.corners,
                                        o.hit) != 0)
                ++rank;
            const Vec3 a = positions_.corner(3 * std::size_t(o.triangle)),
                       b = positions_.corner(3 * std::size_t(o.triangle) + 1),
                       c = positions_.corner(3 * std::size_t(o.triangle) + 2);
            const RayTriangle hit = rayTriangle(ray.origin, ray.direction, a, b, c);
            // Robust only when well inside and the triangle covers the whole square: then the
            // pixel centre is at least the margin away from every edge in screen space, farther
            // than any rasterizer's sub-pixel snapping moves an edge.
            bool robust = false;
            if (hit.det != 0 && std::isfinite(hit.det)) {
                const double u = hit.u_det / hit.det, v = hit.v_det / hit.det;
                robust = u > kRobustBarycentric && v > kRobustBarycentric &&
                         1.0 - u - v > kRobustBarycentric;
            }
            for (int k = 0; robust && k < 4; ++k)
                robust = coversApproximately(corner_rays[k], a, b, c);
            const double t = o.hit.parameter();
            out.push_back({o.triangle, rank, depth_of_(ray.origin + t * ray.direction), robust});
        }
        if (!mark_near_edges_)
            return;
        near_edge = 0;
        for (int i = 0; i < 4 && !near_edge; ++i)
            near_edge =
                meetsAnother(px + 0.5 + ((i & 1) ? kRobustPixelMargin : -kRobustPixelMargin),
                             py + 0.5 + ((i & 2) ? kRobustPixelMargin : -kRobustPixelMargin));
    }

    static bool coversApproximately(const PixelRay& ray, const Vec3& a, const Vec3& b,
                                    const Vec3& c) {
        const RayTriangle hit = rayTriangle(ray.origin, ray.direction, a, b, c);
        if (hit.det == 0.0 || !std::isfinite(hit.det))
            return false;
        const double u = hit.u_det / hit.det;
        const double v = hit.v_det / hit.det;
        return u > 0 && v > 0 && 1.0 - u - v > 0;
    }

    struct Ordered {
        uint32_t triangle;
        TriangleCorners corners;
        RayHit hit;
    };

    RTCScene scene_;
    PositionsView positions_;
    const uint32_t* triangles_; // CandidateCollector::triangles
    const ExactFragments& model_;
    DepthFunction depth_of_;
    uint32_t width_;
    bool mark_near_edges_;
    std::vector<uint32_t> candidates_, corner_candidates_;
    std::vector<Ordered> order_;
};

// Enough rows per block to amortise the scheduling, few enough to balance two to 64 threads.
constexpr uint32_t kRowsPerBlock = 4;
// Below this many pixels, starting threads costs more than it saves.
constexpr std::size_t kParallelThreshold = 64 * 64;

// castAllHits over the triangles listed (empty: every triangle of positions).
AllHits castHits(PositionsView positions, std::span<const uint32_t> triangles,
                 const ViewProjection& view, unsigned thread_count, bool mark_near_edges) {
    assert(positions.x.size() == positions.y.size() && positions.x.size() == positions.z.size());
    assert(positions.x.size() % 3 == 0);
    assert(positions.triangleCount() < std::numeric_limits<uint32_t>::max());

    AllHits result;
    result.width = view.width;
    result.height = view.height;
    result.offsets.assign(result.pixelCount() + 1, 0);
    if (positions.triangleCount() == 0 || result.pixelCount() == 0)
        return result;
    assert(std::all_of(triangles.begin(), triangles.end(),
                       [&](uint32_t t) { return t < positions.triangleCount(); }));

    const RTCDevice device = sharedEmbreeDevice();
    EmbreeScene scene(rtcNewScene(device));
    rtcSetSceneFlags(scene.get(), RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene.get(), RTC_BUILD_QUALITY_HIGH);
    BoundsData bounds{positions, boxMargin(positions, view), triangles};
    addTriangles(device, scene.get(), bounds);
    rtcCommitScene(scene.get());
    if (const RTCError error = rtcGetDeviceError(device); error != RTC_ERROR_NONE)
        throw std::runtime_error("Embree failed to build the scene (error " +
                                 std::to_string(int(error)) + ")");

    const uint32_t block_count = (view.height + kRowsPerBlock - 1) / kRowsPerBlock;
    std::vector<RowBlock> blocks(block_count);
    std::atomic<uint32_t> next_block{0};
    const ExactFragments model(view);
    const auto work = [&] {
        BlockCaster caster(scene.get(), positions, triangles, model, view, mark_near_edges);
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
    result.ranks.reserve(total_hits);
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
            result.ranks.push_back(hit.rank);
            result.depths.push_back(hit.depth);
            result.robust.push_back(hit.robust ? 1 : 0);
        }
    }
    assert(pixel == result.pixelCount());
    return result;
}

} // namespace

AllHits castAllHits(PositionsView positions, const ViewProjection& view, unsigned thread_count,
                    bool mark_near_edges) {
    return castHits(positions, {}, view, thread_count, mark_near_edges);
}

AllHits castHitsOf(PositionsView positions, std::span<const PrimitiveRange> ranges,
                   const ViewProjection& view, unsigned thread_count) {
    std::vector<uint32_t> triangles;
    for (const PrimitiveRange& range : ranges)
        for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count;
             ++t)
            triangles.push_back(t);
    if (triangles.empty()) // none: an empty list would mean all
        return castHits(PositionsView{}, {}, view, thread_count, false);
    return castHits(positions, triangles, view, thread_count, false);
}

} // namespace vissort::detail
