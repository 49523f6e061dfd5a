#pragma once
// The methods behind CollisionDetector (collision.h), one implementation each. Internal.

#include <chrono>
#include <cstdint>
#include <memory>
#include <span>

#include "vissort/collision.h"
#include "vissort/geometry.h"

namespace vissort::detail {

class Collider {
public:
    virtual ~Collider() = default;
    /// Every intersecting pair of triangles of different objects at positions, appended to
    /// result.pairs (cleared by the caller; any order, no duplicates, first < second), and the
    /// stage figures of result.stats (zeroed by the caller): box_object_pairs, object_pairs,
    /// box_triangle_pairs, triangle_pairs, candidate_objects, and update_ms / cull_ms /
    /// exact_ms. The caller sorts and sets intersecting and total_ms.
    virtual void collide(PositionsView positions, CollisionResult& result) = 0;
};

std::unique_ptr<Collider> makeBruteForceCollider(std::span<const PrimitiveRange> objects);
std::unique_ptr<Collider> makeVisibilityCollider(std::span<const PrimitiveRange> objects,
                                                 const CollisionSettings& settings);

/// The peers (Bullet, FCL) are a library of their own, vissort_peers (the package's `peers`
/// component), so that a consumer of the collision layer needs neither: it makes the bullet and
/// fcl colliders once registerPeerColliders (collision_peers.h) has put its factory here.
using PeerColliderFactory = std::unique_ptr<Collider> (*)(std::span<const PrimitiveRange> objects,
                                                          const CollisionSettings& settings);
void setPeerColliderFactory(PeerColliderFactory factory);

/// Milliseconds since construction or the last lap, for the stage timings.
class StageClock {
public:
    double lap() {
        const auto now = std::chrono::steady_clock::now();
        const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
        last_ = now;
        return ms;
    }

private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

} // namespace vissort::detail
