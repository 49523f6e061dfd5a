#pragma once
// `vissort bench collision`: the paper's N-body collision benchmark (Govindaraju et al., I3D
// 2005, section 5.3: deforming bunnies), every method in the same run: ms per frame against the
// number of bunnies, the candidates each stage passes on, and each method's misses and
// inventions against brute force, the ground truth.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "vissort/collision.h"

namespace vissort::bench {

/// A method measured: vissort on every core ("vissort") and on one ("vissort-1t"), the peers.
struct CollisionContender {
    std::string name;
    CollisionSettings settings;
};

/// Every method, vissort on every core and on one, in the order of the figures.
std::vector<CollisionContender> collisionContenders();

/// One method on builtin:bunnies?n=N over the timed frames.
struct CollisionBenchRow {
    uint32_t bunnies = 0;
    std::size_t triangles = 0;
    std::string method;
    double median_ms = 0;                                          // over the timed frames
    double object_pairs = 0, triangle_pairs = 0, intersecting = 0; // means per timed frame
    uint64_t missed = 0, invented = 0; // against brute, over every timed frame
};

struct CollisionBenchSettings {
    std::vector<uint32_t> counts = {18, 36, 72, 144}; // bunnies, each 1..1000
    int frames = 30; // timed frames (>= 1), after one untimed that builds what later ones refit
};

/// Measures every contender on builtin:bunnies?n=N for each count; methods take turns in a
/// rotating order so that none always runs on a cold cache. on_count runs before each count is
/// measured and on_row after each row (progress); both may be empty. Throws std::runtime_error
/// when a scene cannot be made.
std::vector<CollisionBenchRow>
runCollisionBench(const CollisionBenchSettings& settings,
                  const std::function<void(uint32_t bunnies)>& on_count = {},
                  const std::function<void(const CollisionBenchRow&)>& on_row = {});

} // namespace vissort::bench
