// Every test of collide_tests may use the peers (Bullet, FCL): registered before main runs.
// collide_core_tests, which links the collision layer alone, does not have this file.

#include "vissort/collision_peers.h"

namespace {

const bool peers_registered = (vissort::registerPeerColliders(), true);

} // namespace
