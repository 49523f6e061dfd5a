#pragma once
// The collision layer's peers, Bullet and FCL: CollisionMethod::bullet and ::fcl, measured
// against vissort's method in the same binary. They are a library of their own (the installed
// package's `peers` component, vissort::peers), so that a program that only uses the `vissort`
// and `brute` methods needs neither Bullet nor FCL.
//
// Layer: vissort::peers (the package's `peers` component; docs/architecture.md).

namespace vissort {

/// Makes CollisionMethod::bullet and ::fcl available to every CollisionDetector constructed
/// after the call (before it, constructing one of them throws std::invalid_argument naming this
/// function). Any number of calls from any threads; nothing to undo.
void registerPeerColliders();

} // namespace vissort
