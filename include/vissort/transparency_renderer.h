#pragma once
// Order-independent transparency, the paper's first application (Govindaraju, Henson, Lin,
// Manocha, I3D 2005, section 5): opaque objects first with depth, then the transparent primitives
// blended back to front in a visibility order, next to the methods it is measured against, all in
// one OpenGL renderer (headless EGL, gl_context.h) with the same shading.
//
// Every method blends into a 32-bit float colour buffer; the image becomes 8 bits once, at the
// end (Image::toRgba8), so rounding does not accumulate over dozens of layers.
//
// Methods (docs/transparency.md):
//   vissort      blends in the visibility order from a GeometryOracle at a level (scene_orderer.h);
//                the primitives it cannot separate (those of a cycle, and at object level an
//                object whose own triangles overlap on screen) are blended per pixel from
//                fragment lists holding only them, at their place in the order: exact;
//   unsorted     submission order: the common wrong answer;
//   centroid     objects (object level) or triangles (otherwise) sorted by the depth of their
//                centroid, back to front: what most engines do, wrong where they overlap;
//   peel         depth peeling (Everitt 2001), as many passes as the depth complexity needs;
//   dual-peel    dual depth peeling (Bavoil and Myers 2008), two layers a pass;
//   linked-list  per-pixel linked lists of every fragment, sorted per pixel (Yang et al. 2010),
//                grown and drawn again until no fragment is dropped: the exact reference;
//   weighted     weighted blended OIT (McGuire and Bavoil 2013): one pass, approximate.
//
// Layer: vissort::render (the package's `render` component; docs/architecture.md).

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "vissort/camera.h"
#include "vissort/enum_names.h"
#include "vissort/geometry_oracle.h"
#include "vissort/gl_context.h"
#include "vissort/image.h"
#include "vissort/levels_of_detail.h"
#include "vissort/oracles.h"
#include "vissort/scene.h"
#include "vissort/scene_orderer.h"

namespace vissort {

enum class BlendMethod { vissort, unsorted, centroid, peel, dual_peel, linked_list, weighted };

inline constexpr EnumName<BlendMethod> kBlendMethodNames[] = {
    {BlendMethod::vissort, "vissort"},     {BlendMethod::unsorted, "unsorted"},
    {BlendMethod::centroid, "centroid"},   {BlendMethod::peel, "peel"},
    {BlendMethod::dual_peel, "dual-peel"}, {BlendMethod::linked_list, "linked-list"},
    {BlendMethod::weighted, "weighted"},
};
/// A method by name, or "unknown method 'NAME' (expected ...)".
inline Result<BlendMethod> parseBlendMethod(std::string_view name) {
    return parseEnum<BlendMethod>(kBlendMethodNames, name, "method");
}
inline const char* blendMethodName(BlendMethod method) {
    return enumName<BlendMethod>(kBlendMethodNames, method);
}
/// Every method's name, comma-separated, for help and error messages.
inline std::string blendMethodNames() {
    return enumNames<BlendMethod>(kBlendMethodNames);
}

/// The oracle's depth tolerance for exact blending without the check (OrderCheck::off): negative,
/// so that a fragment counts as behind unless it is in front by more than 2^-16. Surfaces whose
/// depths come that close anywhere then occlude each other both ways: a cycle, which the renderer
/// composites per pixel with the GPU's own depths. The order is thus exact wherever the oracle's
/// depths and the GPU's differ by less than 2^-16, where near ties of the default tolerance
/// (kDepthTolerance) could swap layers. With the check (the default for vissort) the renderer
/// orders with kDepthTolerance: the check finds near ties blended in the wrong order, and ties,
/// and the repair composites their pixels, far cheaper than ordering every touching face as a
/// cycle.
inline constexpr float kBlendingDepthTolerance = -1.0f / (1 << 16);

/// How every method shades a triangle, per vertex (the same shading in each, so that methods
/// stay comparable): lit, a two-sided headlight; flat, each object's colour and alpha, unlit, so
/// that a ray-cast reference can reproduce every pixel; membrane, lit, with each transparent
/// surface a thin layer of its alpha seen at an angle (the paper's membrane shading, section
/// 5.2): alpha' = 1 - (1 - alpha)^(1 / max(|n . v|, 0.05)), opaque where seen edge-on.
enum class Shading { lit, flat, membrane };
inline constexpr EnumName<Shading> kShadingNames[] = {
    {Shading::lit, "lit"},
    {Shading::flat, "flat"},
    {Shading::membrane, "membrane"},
};
/// A shading by name, or "unknown shading 'NAME' (expected lit, flat or membrane)".
inline Result<Shading> parseShading(std::string_view name) {
    return parseEnum<Shading>(kShadingNames, name, "shading");
}
inline const char* shadingName(Shading shading) {
    return enumName<Shading>(kShadingNames, shading);
}

/// How the samples of a pixel (RenderSettings::samples) are laid out: a grid of columns x rows
/// inside the pixel, each sample at the centre of its cell.
struct SampleGrid {
    uint32_t columns, rows;
    constexpr uint32_t samples() const { return columns * rows; }
};
/// The grids of 1, 2, 4 and 8 samples: the counts RenderSettings::samples may ask for.
inline constexpr SampleGrid kSampleGrids[] = {{1, 1}, {2, 1}, {2, 2}, {4, 2}};
/// The grid of `samples` a pixel, or "samples must be 1, 2, 4 or 8, got N".
inline Result<SampleGrid> sampleGridOf(int64_t samples) {
    for (const SampleGrid& grid : kSampleGrids)
        if (grid.samples() == samples)
            return {grid, {}};
    return Result<SampleGrid>::failure("samples must be 1, 2, 4 or 8, got " +
                                       std::to_string(samples));
}

struct RenderSettings {
    BlendMethod method = BlendMethod::vissort;
    OrderLevel level = OrderLevel::object; // vissort's ordering level; centroid's unit
    OracleKind oracle = OracleKind::cpu;   // vissort's oracle
    OracleOptions oracle_options;          // its threads and SIMD (the answers never change)
    bool all_transparent = false;          // every object transparent with alpha below
    float alpha = 0.5f;                    // with all_transparent, in (0, 1]
    Rgba background = kDefaultBackground;  // each channel in [0, 1]
    Shading shading = Shading::lit;
    /// Samples a pixel, 1, 2, 4 or 8 (the paper's images: 4): every method renders, blends,
    /// checks, repairs and composites its cycles on each sample as on a pixel of its own, and
    /// the samples of a pixel are averaged once, at the end (supersampling on the grid
    /// sampleGridOf gives; docs/transparency.md). vissort orders once a frame, at pixel resolution:
    /// the check finds what differs at the samples. Costs about samples times the pixels' work.
    uint32_t samples = 1;
    /// vissort: the primitives of each of the order's cycles drawn in a colour of their own (a
    /// palette of 8, cycle g in colour g modulo 8) at their object's alpha, to see where the
    /// order needed per-pixel compositing. Highlighted triangles stay highlighted.
    bool colour_cycles = false;
    /// Memory for fragment lists (linked-list, vissort's per-pixel groups), in bytes, 28 per
    /// fragment; 0: 3 GiB. Never exceeded: more fragments are drawn in bands of rows, one band
    /// at a time (each band draws the geometry again).
    uint64_t list_bytes = 0;
    /// Checks every pixel of an ordered blend (vissort, unsorted, centroid) against the GPU's own
    /// depths and composites again from fragment lists where the order was wrong. Automatic: on
    /// for vissort (exact even where its oracle's rasterizer and the GPU's disagree on a pixel),
    /// off for unsorted and centroid (measured as the wrong answers they are). The other methods
    /// ignore it.
    enum class OrderCheck { automatic, on, off } check = OrderCheck::automatic;
    /// Levels of detail (levels_of_detail.h, docs/lod.md): each object drawn, and ordered, at the
    /// coarsest level whose geometric error projects to at most this many pixels, and objects
    /// wholly out of view left out; 0: every triangle of every object, as without levels.
    float lod_error = 0.0f;

    /// Every setting equal: a renderer made with one renders the other's images (the viewer
    /// keeps its renderer while the settings stay the same).
    friend bool operator==(const RenderSettings&, const RenderSettings&) = default;
};

inline constexpr EnumName<RenderSettings::OrderCheck> kOrderCheckNames[] = {
    {RenderSettings::OrderCheck::automatic, "auto"},
    {RenderSettings::OrderCheck::on, "on"},
    {RenderSettings::OrderCheck::off, "off"},
};
/// "auto", "on" or "off", or "unknown order check 'NAME' (expected ...)".
inline Result<RenderSettings::OrderCheck> parseOrderCheck(std::string_view name) {
    return parseEnum<RenderSettings::OrderCheck>(kOrderCheckNames, name, "order check");
}

/// Whether the renderer draws an object transparent: every object with all_transparent, else
/// one marked transparent whose alpha is below 1 (SceneObject::colour: its parts' least).
inline bool drawnTransparent(const SceneObject& object, const RenderSettings& settings) {
    return settings.all_transparent || (object.transparent && object.colour.a < 1.0f);
}

/// What one frame cost.
struct RenderStats {
    double order_ms = 0;  // computing the order (vissort, centroid); 0 for the others
    double render_ms = 0; // OpenGL work, up to the colour read back (which waits for it)
    double total_ms = 0;
    uint32_t passes = 0;    // geometry passes over the transparent primitives (or some of them)
    uint64_t fragments = 0; // fragments blended from fragment lists (linked-list, vissort's
                            // per-pixel groups); 0 for the other methods
    uint32_t groups = 0;    // vissort: groups composited per pixel: the order's cycles
                            // (checked, in the repair's list pass; unchecked, each at its place,
                            // with the objects that overlap themselves at object level)
    uint64_t repaired_pixels = 0; // vissort: pixels where the GPU's depths contradicted the
                                  // order (near an edge, or a tie), composited again
    VisSortStats order;           // vissort: the ordering's statistics
    uint64_t triangles = 0;       // triangles drawn (opaque and transparent), every level chosen
    uint32_t boxed_objects = 0;   // with lod_error: objects drawn as their bounding box
    uint32_t culled_objects = 0;  // with lod_error: objects wholly out of view, not drawn
};

/// Every field of RenderStats but `order` (whose own table is vis_sort.h's) by name, in one
/// list: the command line's JSON and CSV and the Python module's dicts are written from it.
template <class Visit> void forEachStat(const RenderStats& s, Visit&& visit) {
    visit("order_ms", s.order_ms);
    visit("render_ms", s.render_ms);
    visit("total_ms", s.total_ms);
    visit("passes", s.passes);
    visit("fragments", s.fragments);
    visit("groups", s.groups);
    visit("repaired_pixels", s.repaired_pixels);
    visit("triangles", s.triangles);
    visit("boxed_objects", s.boxed_objects);
    visit("culled_objects", s.culled_objects);
}

class TransparencyRenderer {
public:
    /// A renderer of scene through context. Throws std::invalid_argument for bad settings (alpha
    /// outside (0, 1], samples not 1, 2, 4 or 8, lod_error negative or not finite) and
    /// std::runtime_error when OpenGL lacks what a method needs. With settings.lod_error, levels
    /// are scene's levels of detail (LevelsOfDetail::build(scene), shared by the renderers of
    /// one scene: building them takes a while), built here when null.
    TransparencyRenderer(std::shared_ptr<GlContext> context, const Scene& scene,
                         const RenderSettings& settings,
                         std::shared_ptr<const LevelsOfDetail> levels = nullptr);
    ~TransparencyRenderer();
    TransparencyRenderer(const TransparencyRenderer&) = delete;
    TransparencyRenderer& operator=(const TransparencyRenderer&) = delete;

    /// Renders the scene at `positions` (scene.frame(t)) through view: a view.width x
    /// view.height image, each pixel the mean of its samples (settings.samples). Successive
    /// frames reuse the previous order (coherence), as SceneOrderer does. Throws
    /// std::invalid_argument beyond kMaxImagePixels samples (pixels times samples) and
    /// std::runtime_error when the driver cannot hold the samples' framebuffer.
    Image render(PositionsView positions, const ViewProjection& view, RenderStats& stats);

    /// Draws these triangles (scene triangle ids, e.g. collidingTriangles() of a collision
    /// result) in a strong magenta, opaque, in every method, from the next render on, and the
    /// rest dimmed so that they show (greyer, transparent ones fainter: alpha 0.3 of theirs);
    /// empty: none, nothing dimmed. Ids beyond the scene are ignored. Drawn over colour_cycles'
    /// colours, which are not dimmed.
    void setHighlightedTriangles(std::span<const uint32_t> triangles);

    /// With levels of detail: the last frame's choice (each piece's level, the triangles drawn
    /// of each object: DetailSelection::chosenRanges), and the levels; null without
    /// (RenderSettings::lod_error 0).
    const DetailSelection* levelSelection() const;
    const LevelsOfDetail* levels() const;

    /// Reports the share of a frame's order done (SceneOrderer::setProgress) while vissort
    /// orders; other methods order nothing and never call it.
    void setOrderProgress(std::function<void(double fraction)> report);

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace vissort
