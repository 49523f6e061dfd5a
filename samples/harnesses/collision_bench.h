#pragma once
// `vissort bench collision`: the paper's N-body collision benchmark (Govindaraju et al., I3D
// 2005, section 5.3: deforming bunnies) and a pile of thousands of small bodies, every method in
// the same run: ms per frame against the number of bodies, vissort and Bullet on the same
// threads, the candidates each stage passes on, and each method's misses and inventions against
// brute force, the ground truth.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "vissort/collision.h"

namespace vissort::bench {

/// A method measured: "vissort-2t" is the vissort method on two threads, "brute" and "fcl" run on
/// one.
struct CollisionContender {
    std::string name;
    CollisionSettings settings;
};

/// The contenders of methods (brute is always among them: the ground truth), vissort and bullet
/// once per thread count, in the order of the figures.
std::vector<CollisionContender> collisionContenders(const std::vector<CollisionMethod>& methods,
                                                    const std::vector<uint32_t>& threads);

/// One method on one scene over the timed frames.
struct CollisionBenchRow {
    uint32_t n = 0; // the scene's n: bodies
    std::size_t triangles = 0;
    std::string method;
    uint32_t threads = 1;
    double median_ms = 0;                                          // over the timed frames
    double object_pairs = 0, triangle_pairs = 0, intersecting = 0; // means per timed frame
    uint64_t missed = 0, invented = 0; // against brute, over every timed frame
};

struct CollisionBenchSettings {
    std::string scene = "bunnies";                    // a built-in scene whose n is the bodies
    std::vector<uint32_t> counts = {18, 36, 72, 144}; // n, each accepted by the scene
    int frames = 30; // timed frames (>= 1), after one untimed that builds what later ones refit
    std::vector<CollisionMethod> methods = {CollisionMethod::vissort, CollisionMethod::bullet,
                                            CollisionMethod::brute};
    std::vector<uint32_t> threads = {1, 2}; // vissort's and bullet's, each >= 1
};

/// Measures every contender on builtin:SCENE?n=N for each count; methods take turns in a
/// rotating order so that none always runs on a cold cache. on_count runs once each count's
/// scene is made, before it is measured, and on_row after each row (progress); both may be
/// empty. Throws std::runtime_error
/// with the scene's one-line error when a scene cannot be made.
std::vector<CollisionBenchRow>
runCollisionBench(const CollisionBenchSettings& settings,
                  const std::function<void(uint32_t n)>& on_count = {},
                  const std::function<void(const CollisionBenchRow&)>& on_row = {});

/// Bullet's median over vissort's on the same threads at one n: issue 38's figure.
struct CollisionSpeedup {
    uint32_t n = 0, threads = 1;
    double bullet_over_vissort = 0; // 0 when vissort's median is 0
};

/// Every (n, threads) of settings, in their order, where rows hold both vissort's and bullet's
/// median; none unless settings measured both methods.
std::vector<CollisionSpeedup> bulletOverVissort(const std::vector<CollisionBenchRow>& rows,
                                                const CollisionBenchSettings& settings);

} // namespace vissort::bench
