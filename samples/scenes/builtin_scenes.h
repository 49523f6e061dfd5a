#pragma once
// Internal declarations of the built-in scenes (scene_library.h) and the random numbers they share.

#include "scenes/scene_library.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>

namespace vissort::detail {

/// The most triangles a built-in scene may have (scene_library.h: "absurd values").
inline constexpr std::size_t kMaxBuiltinTriangles = 10'000'000;

/// Random numbers that are the same on every platform for a given seed. std::mt19937_64's output
/// is fixed by the standard, but the distributions (uniform_real_distribution, ...) are not, so
/// the mappings to ranges are written here.
class SceneRandom {
public:
    explicit SceneRandom(uint64_t seed) : engine_(seed) {}

    /// Uniform in [0, 1): the top 53 bits of one draw, so every double is exact.
    double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
    /// Uniform in [low, high).
    double uniform(double low, double high) { return low + (high - low) * uniform(); }
    /// Uniform in [0, count), count < 2^32: multiply-shift, bias below 2^-32.
    uint32_t index(uint32_t count) {
        return static_cast<uint32_t>(((engine_() >> 32) * count) >> 32);
    }
    /// Uniform on the unit sphere (Archimedes: z uniform in [-1, 1], longitude uniform).
    Vec3 unitVector() {
        const double z = uniform(-1.0, 1.0);
        const double longitude = uniform(0.0, 2 * std::numbers::pi);
        const double ring = std::sqrt(std::max(0.0, 1 - z * z));
        return {ring * std::cos(longitude), ring * std::sin(longitude), z};
    }
    /// A rotation uniform on SO(3) as a unit quaternion (w, x, y, z).
    /// Shoemake, "Uniform random rotations", Graphics Gems III, 1992.
    std::array<double, 4> rotation() {
        const double u1 = uniform(), u2 = uniform(0.0, 2 * std::numbers::pi),
                     u3 = uniform(0.0, 2 * std::numbers::pi);
        const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
        return {b * std::cos(u3), a * std::sin(u2), a * std::cos(u2), b * std::sin(u3)};
    }
    /// A saturated, bright colour with a random hue.
    Rgba colour(float alpha) { return hueColour(uniform(), alpha); }

    static Rgba hueColour(double hue, float alpha) {
        // HSV with s = 0.65, v = 0.95: piecewise-linear hue ramp.
        const double h = (hue - std::floor(hue)) * 6;
        const auto channel = [h](double offset) {
            const double k = std::fmod(offset + h, 6.0);
            const double ramp = std::clamp(std::min(k, 4 - k), 0.0, 1.0);
            return static_cast<float>(0.95 * (1 - 0.65 * ramp));
        };
        return {channel(5), channel(3), channel(1), alpha};
    }

    static constexpr double kPi = 3.14159265358979323846;

private:
    std::mt19937_64 engine_;
};

/// n (18), seed (1): the paper's dynamic scene, bouncing and deforming Stanford bunnies.
Result<Scene> makeBunniesScene(const SceneParameters& parameters);
/// n (1000), seed (1): small rigid and deforming bodies falling into a pile on a floor and
/// settling, for collision benchmarks.
Result<Scene> makePileScene(const SceneParameters& parameters);
/// layers (8), seed (1): rows of pipe racks, tanks and steel; depth complexity about 2 layers.
Result<Scene> makePlantScene(const SceneParameters& parameters);
/// scale (1), seed (1): a multi-storey process plant with the paper's power plant's proportions
/// (about 730K opaque and 90K transparent triangles at scale 1) and a walkthrough path.
Result<Scene> makePowerplantScene(const SceneParameters& parameters);
/// layers (8), seed (1): a stack of tilted, non-intersecting quads along z.
Result<Scene> makeSlabsScene(const SceneParameters& parameters);
/// n (1000), seed (1): random triangles, one per cell of a jittered grid, never intersecting.
Result<Scene> makeSoupScene(const SceneParameters& parameters);

/// The rigid part of the bunnies' motion, exposed so tests can check the bounding spheres.
/// Bunny i's bounding sphere (radius 1 at rest, 1 + kBunnyWobble deformed) is centred at
/// bunnyCentreAt(animation, i, t). Returns false when `animation` is not a bunnies animation.
bool bunnyCentreAt(const Animation& animation, std::size_t bunny, double t, Vec3& centre);

/// Amplitude of the bunnies' deformation along the vertex normals (model units).
inline constexpr double kBunnyWobble = 0.05;

} // namespace vissort::detail
