// `vissort bench collision`'s measurements (collision_bench.h).

#include "harnesses/collision_bench.h"

#include <algorithm>
#include <memory>
#include <stdexcept>

#include "harnesses/measurement.h"
#include "scenes/scene_library.h"
#include "vissort/collision_peers.h"
#include "vissort/frame_driver.h"
#include "vissort/scene.h"

namespace vissort::bench {
namespace {

struct Measured {
    std::vector<double> ms;                                        // per timed frame
    double object_pairs = 0, triangle_pairs = 0, intersecting = 0; // means per frame
    uint64_t missed = 0, invented = 0; // against brute, over every frame
};

// How many pairs of one sorted list the other lacks.
uint64_t pairsMissing(const std::vector<TrianglePair>& from, const std::vector<TrianglePair>& in) {
    uint64_t missing = 0;
    auto other = in.begin();
    for (const TrianglePair& p : from) {
        while (other != in.end() && *other < p)
            ++other;
        missing += other == in.end() || *other != p;
    }
    return missing;
}

// Frame 0 builds what later frames refit, so it is not timed; methods take turns in a rotating
// order so that none always runs on a cold cache.
std::vector<Measured> measure(const std::vector<CollisionContender>& methods,
                              const std::string& scene_name, uint32_t n, int frames,
                              std::size_t& triangles,
                              const std::function<void(uint32_t)>& on_count) {
    const Result<Scene> scene =
        samples::loadScene("builtin:" + scene_name + "?n=" + std::to_string(n));
    if (!scene)
        throw std::runtime_error(scene.error);
    if (on_count) // once the scene is made: an error is then the only line
        on_count(n);
    triangles = scene.value->triangleCount();
    const std::vector<PrimitiveRange> objects = scene.value->objectPrimitives();
    std::vector<std::unique_ptr<CollisionDetector>> detectors;
    std::size_t brute = 0;
    for (const CollisionContender& c : methods) {
        if (c.settings.method == CollisionMethod::brute)
            brute = detectors.size();
        detectors.push_back(std::make_unique<CollisionDetector>(objects, c.settings));
    }
    std::vector<Measured> measured(methods.size());
    std::vector<CollisionResult> results(methods.size());
    FrameDriver driver(*scene.value);
    for (int f = 0; f <= frames; ++f) {
        driver.seek(f);
        for (std::size_t k = 0; k < methods.size(); ++k) {
            const std::size_t i = (k + std::size_t(f)) % methods.size();
            detectors[i]->collide(driver.positions(), results[i]);
        }
        if (f == 0)
            continue;
        for (std::size_t i = 0; i < methods.size(); ++i) {
            const CollisionStats& s = results[i].stats;
            Measured& m = measured[i];
            m.ms.push_back(s.total_ms);
            m.object_pairs += double(s.object_pairs) / frames;
            m.triangle_pairs += double(s.triangle_pairs) / frames;
            m.intersecting += double(s.intersecting) / frames;
            m.missed += pairsMissing(results[brute].pairs, results[i].pairs);
            m.invented += pairsMissing(results[i].pairs, results[brute].pairs);
        }
    }
    return measured;
}

} // namespace

std::vector<CollisionContender> collisionContenders(const std::vector<CollisionMethod>& methods,
                                                    const std::vector<uint32_t>& threads) {
    std::vector<CollisionContender> list;
    for (CollisionMethod m : collisionMethods()) {
        const bool asked = std::find(methods.begin(), methods.end(), m) != methods.end();
        if (!asked && m != CollisionMethod::brute)
            continue;
        CollisionSettings settings;
        settings.method = m;
        if (m == CollisionMethod::vissort || m == CollisionMethod::bullet) {
            for (uint32_t t : threads) {
                settings.threads = t;
                list.push_back({std::string(collisionMethodName(m)) + "-" + std::to_string(t) + "t",
                                settings});
            }
        } else {
            list.push_back({collisionMethodName(m), settings});
        }
    }
    return list;
}

std::vector<CollisionBenchRow>
runCollisionBench(const CollisionBenchSettings& settings,
                  const std::function<void(uint32_t)>& on_count,
                  const std::function<void(const CollisionBenchRow&)>& on_row) {
    registerPeerColliders(); // Bullet and FCL are among the contenders
    const std::vector<CollisionContender> methods =
        collisionContenders(settings.methods, settings.threads);
    std::vector<CollisionBenchRow> rows;
    for (uint32_t n : settings.counts) {
        std::size_t triangles = 0;
        const std::vector<Measured> measured =
            measure(methods, settings.scene, n, settings.frames, triangles, on_count);
        for (std::size_t i = 0; i < methods.size(); ++i) {
            const Measured& m = measured[i];
            CollisionBenchRow row;
            row.n = n;
            row.triangles = triangles;
            row.method = methods[i].name;
            row.threads = methods[i].settings.threads;
            row.median_ms = median(m.ms);
            row.object_pairs = m.object_pairs;
            row.triangle_pairs = m.triangle_pairs;
            row.intersecting = m.intersecting;
            row.missed = m.missed;
            row.invented = m.invented;
            rows.push_back(row);
            if (on_row)
                on_row(rows.back());
        }
    }
    return rows;
}

std::vector<CollisionSpeedup> bulletOverVissort(const std::vector<CollisionBenchRow>& rows,
                                                const CollisionBenchSettings& settings) {
    const auto find = [&](uint32_t n, const std::string& method) -> const CollisionBenchRow* {
        for (const CollisionBenchRow& row : rows)
            if (row.n == n && row.method == method)
                return &row;
        return nullptr;
    };
    std::vector<CollisionSpeedup> speedups;
    for (uint32_t n : settings.counts)
        for (uint32_t threads : settings.threads) {
            const std::string suffix = std::to_string(threads) + "t";
            const CollisionBenchRow* vissort = find(n, std::string("vissort-") + suffix);
            const CollisionBenchRow* bullet = find(n, std::string("bullet-") + suffix);
            if (vissort == nullptr || bullet == nullptr)
                continue;
            speedups.push_back(
                {n, threads,
                 vissort->median_ms > 0 ? bullet->median_ms / vissort->median_ms : 0.0});
        }
    return speedups;
}

} // namespace vissort::bench
