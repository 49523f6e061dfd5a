#pragma once
// `vissort bench transparency`: the paper's figure 6, extended. Frame time against depth
// complexity for vissort and the methods it is measured against (depth peeling, dual depth
// peeling, per-pixel linked lists, weighted blended OIT, and centroid sorting), on builtin:slabs
// (depth complexity = layers) and the CAD-like builtin:plant (about 2 x layers), with each
// method's error against linked-list, every method in the same run through the same renderer.
// Needs OpenGL (built only with VISSORT_WITH_GL).

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "vissort/result.h"
#include "vissort/transparency_renderer.h"

namespace vissort::bench {

/// The methods measured, in the order shown; index kTransparencyVissort is the baseline of the
/// ratios, kTransparencyLinkedList the reference of the errors.
inline constexpr BlendMethod kTransparencyMethods[] = {
    BlendMethod::vissort,     BlendMethod::peel,     BlendMethod::dual_peel,
    BlendMethod::linked_list, BlendMethod::weighted, BlendMethod::centroid};
inline constexpr std::size_t kTransparencyVissort = 0, kTransparencyPeel = 1,
                             kTransparencyDualPeel = 2, kTransparencyLinkedList = 3;

/// A family of scenes by depth complexity D.
struct TransparencyFamily {
    const char* name;
    const char* description;
    std::string (*scene)(uint32_t depth); // the scene specification of depth D
};
/// slabs, then plant.
std::span<const TransparencyFamily> transparencyFamilies();

/// One method on one scene.
struct TransparencyMeasured {
    double ms = 0;       // median over the timed frames
    double order_ms = 0; // median over the timed frames
    uint32_t passes = 0; // the most in a frame
    uint64_t fragments = 0;
    int max_abs = 0; // against linked-list, the worst frame
    double rmse = 0; // against linked-list, the worst frame
};

/// Every method on one scene of a family.
struct TransparencyBenchRow {
    std::string family, specification;
    uint32_t depth = 0;
    uint32_t seen = 0; // the most transparent layers at a pixel: depth peeling's passes - 1
    std::vector<TransparencyMeasured> methods; // in kTransparencyMethods order, 1 sample a pixel
    /// With TransparencyBenchSettings::samples over 1: every method again at `samples` a pixel
    /// (errors against linked-list sampled the same way), in the same order; else empty.
    std::vector<TransparencyMeasured> sampled;
    uint32_t samples = 1;
};

struct TransparencyBenchSettings {
    std::shared_ptr<GlContext> context; // the renderers' (the caller's, non-null)
    uint32_t width = 1024, height = 1024;
    OrderLevel level = OrderLevel::multistage; // vissort's, with the cpu oracle
    int frames = 3;                            // on an orbit, the first untimed: 2..100
    std::vector<uint32_t> depths = {2, 4, 8, 16, 32, 64};
    /// Samples a pixel (RenderSettings::samples) to measure next to 1, in the same run: 1, 2, 4
    /// or 8; 1 measures one sample only.
    uint32_t samples = 1;
};

/// Renders every method on every family at every depth. on_family runs before a family's rows,
/// on_row after each row (progress); both may be empty. A one-line message when a scene cannot
/// be made.
Result<std::vector<TransparencyBenchRow>>
runTransparencyBench(const TransparencyBenchSettings& settings,
                     const std::function<void(const TransparencyFamily&)>& on_family = {},
                     const std::function<void(const TransparencyBenchRow&)>& on_row = {});

} // namespace vissort::bench
