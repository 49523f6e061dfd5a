// CollisionDetector (collision.h): checks the settings, runs the chosen method, sorts its pairs
// and times the frame.

#include <algorithm>
#include <atomic>
#include <bit>
#include <chrono>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "collide/collider.h"

namespace vissort {
namespace {

// Set once by registerPeerColliders (the peers library); read by every detector made after.
std::atomic<detail::PeerColliderFactory> peer_collider_factory{nullptr};

// Whether no value is an infinity or a NaN (an exponent of all ones). The bits are or-ed over
// the whole span, without an early exit, so that the loop vectorizes: std::isfinite with a
// branch per value cost about as much as a whole frame's refit.
bool allFinite(std::span<const float> values) {
    uint32_t special = 0;
    for (float v : values)
        special |= uint32_t((std::bit_cast<uint32_t>(v) & 0x7f800000u) == 0x7f800000u);
    return special == 0;
}

} // namespace

void detail::setPeerColliderFactory(PeerColliderFactory factory) {
    peer_collider_factory.store(factory, std::memory_order_release);
}

std::vector<Vec3> defaultCollisionDirections() {
    return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {1, 1, -1}, {1, -1, 1}, {-1, 1, 1}};
}

std::vector<CollisionMethod> collisionMethods() {
    std::vector<CollisionMethod> methods;
    for (const EnumName<CollisionMethod>& entry : kCollisionMethodNames)
        methods.push_back(entry.value);
    return methods;
}

static std::string collisionSettingsProblem(const CollisionSettings& settings) {
    for (const auto& [size, what] :
         {std::pair{settings.width, "width"}, {settings.height, "height"}})
        if (size < 1 || size > 4096)
            return std::string("collision view ") + what + " must be 1 to 4096 pixels, got " +
                   std::to_string(size);
    if (!(settings.min_cull_fraction >= 0 && settings.min_cull_fraction <= 1))
        return "collision min_cull_fraction must be in [0, 1]";
    for (const Vec3& d : settings.directions) {
        const double length2 = dot(d, d);
        if (!(length2 > 0) || !std::isfinite(length2))
            return "collision direction must be finite and non-zero";
    }
    return {};
}

CollisionDetector::CollisionDetector(std::span<const PrimitiveRange> objects,
                                     const CollisionSettings& settings)
    : settings_(settings) {
    if (Status valid = validateCollisionSettings(settings_); !valid)
        throw std::invalid_argument(valid.error);
    for (const PrimitiveRange& o : objects)
        triangles_needed_ =
            std::max<uint64_t>(triangles_needed_, uint64_t(o.first_triangle) + o.triangle_count);
    // A triangle in two objects would be reported as colliding with itself.
    std::vector<uint32_t> by_first(objects.size());
    std::iota(by_first.begin(), by_first.end(), 0u);
    std::sort(by_first.begin(), by_first.end(), [&](uint32_t a, uint32_t b) {
        return objects[a].first_triangle < objects[b].first_triangle;
    });
    for (uint32_t o : by_first)
        if (objects[o].triangle_count > 0)
            object_starts_.emplace_back(objects[o].first_triangle, o);
    for (std::size_t k = 1; k < by_first.size(); ++k) {
        const PrimitiveRange& before = objects[by_first[k - 1]];
        if (uint64_t(before.first_triangle) + before.triangle_count >
            objects[by_first[k]].first_triangle)
            throw std::invalid_argument(
                "collision objects " + std::to_string(std::min(by_first[k - 1], by_first[k])) +
                " and " + std::to_string(std::max(by_first[k - 1], by_first[k])) +
                " share triangles (each triangle belongs to one object)");
    }
    switch (settings_.method) {
    case CollisionMethod::vissort:
        collider_ = detail::makeVisibilityCollider(objects, settings_);
        break;
    case CollisionMethod::brute:
        collider_ = detail::makeBruteForceCollider(objects);
        break;
    case CollisionMethod::bullet:
    case CollisionMethod::fcl:
        if (detail::PeerColliderFactory make_peer =
                peer_collider_factory.load(std::memory_order_acquire))
            collider_ = make_peer(objects, settings_);
        else
            throw std::invalid_argument(std::string("collision method '") +
                                        collisionMethodName(settings_.method) +
                                        "' is a peer: link vissort::peers (Bullet, FCL) and call "
                                        "vissort::registerPeerColliders() first");
        break;
    }
}

CollisionDetector::~CollisionDetector() = default;

void CollisionDetector::collide(PositionsView positions, CollisionResult& result) {
    const auto start = std::chrono::steady_clock::now();
    checkTriangleCount(positions);
    // What makes bad input an error instead of a wrong answer; written to vectorize, as it reads
    // every coordinate of every frame.
    for (std::span<const float> axis : {positions.x, positions.y, positions.z})
        if (!allFinite(axis))
            throw std::invalid_argument("collision positions must be finite");
    run(positions, start, result);
}

void CollisionDetector::collide(const VertexPositionsView& vertices, CollisionResult& result) {
    const auto start = std::chrono::steady_clock::now();
    // The gather refuses coordinates that are not finite, so they are not looked at again.
    if (Status gathered = gatherPositions(vertices, gathered_); !gathered)
        throw std::invalid_argument("collision vertex positions: " + gathered.error);
    checkTriangleCount(gathered_.view());
    run(gathered_.view(), start, result);
}

void CollisionDetector::checkTriangleCount(PositionsView positions) const {
    if (positions.y.size() != positions.x.size() || positions.z.size() != positions.x.size() ||
        positions.x.size() % 3 != 0 || positions.triangleCount() < triangles_needed_)
        throw std::invalid_argument(
            "collision positions hold " + std::to_string(positions.triangleCount()) +
            " triangles; the objects need " + std::to_string(triangles_needed_));
}

void CollisionDetector::run(PositionsView positions, std::chrono::steady_clock::time_point start,
                            CollisionResult& result) {
    result.pairs.clear();
    result.stats = {};
    collider_->collide(positions, result);
    std::sort(result.pairs.begin(), result.pairs.end());
    result.stats.intersecting = result.pairs.size();
    // The objects of each pair's triangles (every triangle of a pair is some object's).
    const auto objectOf = [&](uint32_t triangle) {
        const auto after = std::upper_bound(object_starts_.begin(), object_starts_.end(),
                                            std::pair(triangle, UINT32_MAX));
        return std::prev(after)->second;
    };
    result.object_pairs.clear();
    for (const TrianglePair& p : result.pairs) {
        const uint32_t a = objectOf(p.first), b = objectOf(p.second);
        result.object_pairs.push_back({std::min(a, b), std::max(a, b)});
    }
    std::sort(result.object_pairs.begin(), result.object_pairs.end());
    result.object_pairs.erase(std::unique(result.object_pairs.begin(), result.object_pairs.end()),
                              result.object_pairs.end());
    result.stats.colliding_object_pairs = result.object_pairs.size();
    result.stats.total_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

CollisionResult CollisionDetector::collide(PositionsView positions) {
    CollisionResult result;
    collide(positions, result);
    return result;
}

std::vector<uint32_t> collidingTriangles(std::span<const TrianglePair> pairs) {
    std::vector<uint32_t> triangles;
    triangles.reserve(2 * pairs.size());
    for (const TrianglePair& p : pairs) {
        triangles.push_back(p.first);
        triangles.push_back(p.second);
    }
    std::sort(triangles.begin(), triangles.end());
    triangles.erase(std::unique(triangles.begin(), triangles.end()), triangles.end());
    return triangles;
}

Status validateCollisionSettings(const CollisionSettings& settings) {
    return Status{collisionSettingsProblem(settings)};
}

} // namespace vissort
