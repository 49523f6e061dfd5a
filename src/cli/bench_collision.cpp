// `vissort bench collision`: the paper's N-body collision benchmark (Govindaraju et al., I3D
// 2005, section 5.3: deforming bunnies), every method in the same run: ms per frame against the
// number of bunnies, the candidates each stage passes on, and each method's misses and
// inventions against brute force, the ground truth.

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <thread>

#include <nlohmann/json.hpp>

#include "cli/bench_common.h"
#include "cli/commands.h"
#include "cli/json_output.h"
#include "cli/line_plot.h"
#include "vissort/camera_path.h"
#include "vissort/collision.h"
#include "vissort/transparency_renderer.h"

namespace vissort::cli {
namespace {

// The contenders: every method, vissort on every core and on one.
struct Contender {
    std::string name;
    CollisionSettings settings;
};

std::vector<Contender> contenders() {
    std::vector<Contender> list;
    for (CollisionMethod m : collisionMethods()) {
        CollisionSettings settings;
        settings.method = m;
        if (m == CollisionMethod::vissort) {
            settings.threads = 0;
            list.push_back({"vissort", settings});
            settings.threads = 1;
            list.push_back({"vissort-1t", settings});
        } else {
            list.push_back({collisionMethodName(m), settings});
        }
    }
    return list;
}

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
std::vector<Measured> measure(const std::vector<Contender>& methods, uint32_t bunnies, int frames,
                              std::size_t& triangles) {
    const Result<Scene> scene = loadScene("builtin:bunnies?n=" + std::to_string(bunnies));
    if (!scene)
        throw std::runtime_error(scene.error);
    triangles = scene.value->triangleCount();
    const std::vector<PrimitiveRange> objects = scene.value->objectPrimitives();
    std::vector<std::unique_ptr<CollisionDetector>> detectors;
    std::size_t brute = 0;
    for (const Contender& c : methods) {
        if (c.settings.method == CollisionMethod::brute)
            brute = detectors.size();
        detectors.push_back(std::make_unique<CollisionDetector>(objects, c.settings));
    }
    std::vector<Measured> measured(methods.size());
    std::vector<CollisionResult> results(methods.size());
    TrianglePositions positions;
    for (int f = 0; f <= frames; ++f) {
        scene.value->frame(f * kFrameInterval, positions);
        for (std::size_t k = 0; k < methods.size(); ++k) {
            const std::size_t i = (k + std::size_t(f)) % methods.size();
            detectors[i]->collide(positions, results[i]);
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

int runCollisionBench(const BenchOptions& options) {
    std::vector<uint32_t> counts;
    if (!parseCounts(options.counts, counts))
        return fail(kExitUsage,
                    "--counts must be bunny counts from 1 to 1000, comma-separated, got '" +
                        options.counts + "'");
    const int frames = options.frames.value_or(30);
    if (frames < 1)
        return fail(kExitUsage, "--frames must be at least 1");
    const std::vector<Contender> methods = contenders();

    std::cout << "bench collision: builtin:bunnies?n=N, " << frames
              << " timed frames each after one untimed; " << machineName() << ", "
              << std::thread::hardware_concurrency()
              << " cores (vissort-1t and the peers: one thread)\n";
    std::cout << std::setw(5) << "N" << std::setw(12) << "method" << std::setw(11) << "median ms"
              << std::setw(13) << "object pairs" << std::setw(15) << "triangle pairs"
              << std::setw(13) << "intersecting" << std::setw(8) << "missed" << std::setw(10)
              << "invented" << '\n';
    nlohmann::json rows = nlohmann::json::array();
    std::vector<PlotSeries> series(methods.size());
    for (std::size_t i = 0; i < methods.size(); ++i)
        series[i].name = methods[i].name;
    for (uint32_t n : counts) {
        std::cerr << "bench collision: " << n << " bunnies..." << std::endl;
        std::size_t triangles = 0;
        const std::vector<Measured> measured = measure(methods, n, frames, triangles);
        for (std::size_t i = 0; i < methods.size(); ++i) {
            const Measured& m = measured[i];
            const double ms = median(m.ms);
            std::cout << std::setw(5) << n << std::setw(12) << methods[i].name << std::setw(11)
                      << std::fixed << std::setprecision(2) << ms << std::setw(13)
                      << std::setprecision(1) << m.object_pairs << std::setw(15)
                      << std::setprecision(0) << m.triangle_pairs << std::setw(13) << m.intersecting
                      << std::setw(8) << m.missed << std::setw(10) << m.invented << std::endl;
            std::cout.unsetf(std::ios::fixed);
            rows.push_back({{"bunnies", n},
                            {"triangles", triangles},
                            {"method", methods[i].name},
                            {"median_ms", ms},
                            {"object_pairs", m.object_pairs},
                            {"triangle_pairs", m.triangle_pairs},
                            {"intersecting", m.intersecting},
                            {"missed", m.missed},
                            {"invented", m.invented}});
            series[i].x.push_back(n);
            series[i].y.push_back(ms);
        }
    }
    if (!options.json_path.empty()) {
        const nlohmann::json document = {{"benchmark", "collision"},
                                         {"machine", machineName()},
                                         {"cores", std::thread::hardware_concurrency()},
                                         {"frames", frames},
                                         {"rows", rows}};
        if (const int code = writeJsonFile(options.json_path, document); code != kExitOk)
            return code;
    }
    if (!options.plot_path.empty()) {
        const Strip plot =
            plotLines(series, "collision: ms per frame, deforming bunnies (" + machineName() + ")",
                      "bunnies N (builtin:bunnies?n=N)", "ms per frame", 900, 560);
        if (Status error = writePng(options.plot_path, plot.width, plot.height, plot.rgba);
            !error)
            return fail(kExitFailure, error.error);
    }
    return kExitOk;
}

} // namespace vissort::cli
