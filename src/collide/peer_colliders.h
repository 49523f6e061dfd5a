#pragma once
// The peers' colliders (vissort_peers), one file each. Internal.

#include <memory>
#include <span>

#include "collide/collider.h"

namespace vissort::detail {

/// settings.threads and settings.pool as the vissort method takes them.
std::unique_ptr<Collider> makeBulletCollider(std::span<const PrimitiveRange> objects,
                                             const CollisionSettings& settings);
std::unique_ptr<Collider> makeFclCollider(std::span<const PrimitiveRange> objects);

} // namespace vissort::detail
