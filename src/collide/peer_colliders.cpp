// registerPeerColliders (collision_peers.h): hands the collision layer the factory of the
// Bullet and FCL colliders, which live in this library so that the layer itself needs neither.

#include "collide/peer_colliders.h"

#include <stdexcept>

#include "vissort/collision_peers.h"

namespace vissort {
namespace {

std::unique_ptr<detail::Collider> makePeerCollider(std::span<const PrimitiveRange> objects,
                                                   const CollisionSettings& settings) {
    const CollisionMethod method = settings.method;
    switch (method) {
    case CollisionMethod::bullet:
        return detail::makeBulletCollider(objects, settings);
    case CollisionMethod::fcl:
        return detail::makeFclCollider(objects);
    case CollisionMethod::vissort:
    case CollisionMethod::brute:
        break;
    }
    throw std::invalid_argument(std::string("collision method '") + collisionMethodName(method) +
                                "' is not a peer");
}

} // namespace

void registerPeerColliders() {
    detail::setPeerColliderFactory(&makePeerCollider);
}

} // namespace vissort
