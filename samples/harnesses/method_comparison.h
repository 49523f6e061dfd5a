#pragma once
// Every transparency method on one frame, each against linked-list (the exact reference), as
// one picture: `vissort render --method all`, which makes the strips of docs/benchmarks.md.
// Needs OpenGL (built only with VISSORT_WITH_GL).

#include <memory>
#include <vector>

#include "figures/comparison_strip.h"
#include "vissort/gl_context.h"
#include "vissort/image.h"
#include "vissort/scene.h"
#include "vissort/transparency_renderer.h"

namespace vissort::bench {

/// One method's picture of the frame, its costs (a second render: the first compiles its
/// programs) and its error against linked-list's picture.
struct MethodPicture {
    BlendMethod method{};
    std::vector<uint8_t> rgba;
    RenderStats stats;
    ImageError error;
};

struct MethodComparison {
    std::vector<MethodPicture> methods; // vissort, unsorted, centroid, peel, dual-peel,
                                        // linked-list, weighted
    /// The pictures side by side, each captioned with its method, time and passes, and below
    /// each its error map against linked-list with the largest error.
    samples::Strip strip;
};

/// Every method with `settings` (its method aside) on the scene at t = 0 through view.
MethodComparison compareEveryMethod(const std::shared_ptr<GlContext>& context, const Scene& scene,
                                    RenderSettings settings, const ViewProjection& view);

} // namespace vissort::bench
