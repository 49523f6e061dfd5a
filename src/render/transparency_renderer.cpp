// The transparency renderer (transparency_renderer.h): opaque objects with depth, then the
// transparent triangles composited by the chosen method onto the same float framebuffer.

#include "vissort/transparency_renderer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "gl/gl_api.h"
#include "gl/gl_program.h"
#include "render/depth_peeling.h"
#include "render/draw_sequence.h"
#include "render/dual_depth_peeling.h"
#include "render/fragment_lists.h"
#include "render/render_target.h"
#include "render/sample_resolve.h"
#include "render/scene_geometry.h"
#include "render/shading.h"
#include "render/verified_blending.h"
#include "render/weighted_blended.h"

namespace vissort {
namespace {

// markSelfOverlapping's depth tolerance: triangles of one object count as overlapping only
// where one lies behind another by more than this (in depth d).
constexpr float kFoldTolerance = 1.0f / (1 << 20);

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
        .count();
}

void copyCorners(PositionsView from, std::span<const uint32_t> triangles, TrianglePositions& to) {
    to.resize(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (std::size_t k = 0; k < 3; ++k) {
            const std::size_t c = std::size_t(triangles[t]) * 3 + k;
            to.x[t * 3 + k] = from.x[c];
            to.y[t * 3 + k] = from.y[c];
            to.z[t * 3 + k] = from.z[c];
        }
}

// The transparent objects, for ordering: their triangle ranges renumbered from 0 in object
// order, with the map back to the scene's triangle ids. Opaque surfaces hide transparent
// fragments but never change the order of the visible ones, so they are left out.
struct TransparentPart {
    std::vector<PrimitiveRange> objects;  // each transparent object's range of part triangles
    std::vector<uint32_t> scene_triangle; // part triangle -> scene triangle
    bool whole = false;                   // every triangle, in order: the scene's own positions
};

TransparentPart transparentPart(const Scene& scene, const std::vector<uint8_t>& transparent) {
    TransparentPart part;
    for (uint32_t o = 0; o < scene.objects.size(); ++o) {
        if (!transparent[o])
            continue;
        const SceneObject& object = scene.objects[o];
        part.objects.push_back({uint32_t(part.scene_triangle.size()), object.triangle_count});
        for (uint32_t t = 0; t < object.triangle_count; ++t)
            part.scene_triangle.push_back(object.first_triangle + t);
    }
    part.whole = part.scene_triangle.size() == scene.triangleCount();
    return part;
}

bool ordersPerFrame(BlendMethod method) {
    return method == BlendMethod::vissort || method == BlendMethod::centroid;
}

// The view of the samples: the same camera on a raster grid.columns x grid.rows times as fine,
// each pixel's samples a block of its texels.
ViewProjection sampledView(const ViewProjection& view, const SampleGrid& grid) {
    ViewProjection sampled = view;
    sampled.width = view.width * grid.columns;
    sampled.height = view.height * grid.rows;
    return sampled;
}

} // namespace

struct TransparencyRenderer::Impl {
    std::shared_ptr<GlContext> context;
    RenderSettings settings;
    SampleGrid grid{1, 1}; // settings.samples' grid
    uint32_t triangle_count = 0;
    std::vector<uint32_t> opaque_triangles;
    std::vector<uint8_t> transparent; // per object: drawn transparent
    TransparentPart part;
    std::vector<PrimitiveRange> primitives; // the part's, at the ordering level
    // vissort's ordering, over the transparent part only.
    std::unique_ptr<GeometryOracle> oracle;
    std::unique_ptr<SceneOrderer> orderer;
    TrianglePositions part_positions; // this frame's, unless the part is the whole scene
    FrameOrder frame_order;           // this frame's order, its buffers reused from frame to frame
    std::vector<uint32_t> group_of;   // per primitive: its per-pixel group, or kNoGroup
    detail::DrawSequence sequence;    // transparent triangles back to front, scene ids
    std::vector<uint32_t> repair_transparent;           // triangles a repair draws again
    std::vector<std::vector<uint32_t>> cycle_triangles; // colour_cycles: each cycle's, scene ids
    bool triangles_uploaded = false;
    // Levels of detail (settings.lod_error > 0): the levels' scene is the one drawn; each frame
    // chooses every object's range of it.
    std::unique_ptr<DetailSelection> selection;
    bool levels_uploaded = false;           // the levels' own positions are the geometry's
    const LevelsOfDetail* levels = nullptr; // selection's
    std::vector<uint32_t> highlighted;      // the highlights in the levels' scene's ids

    std::unique_ptr<detail::SceneGeometry> geometry;
    detail::GlProgram shade_program;
    detail::RenderTarget target;
    // Each method's GL resources, made on first use.
    std::unique_ptr<detail::FragmentLists> lists;
    std::unique_ptr<detail::DepthPeeling> peeling;
    std::unique_ptr<detail::DualDepthPeeling> dual_peeling;
    std::unique_ptr<detail::WeightedBlended> weighted;
    std::unique_ptr<detail::VerifiedBlending> verified;
    std::unique_ptr<detail::SampleResolve> resolve; // more than one sample a pixel

    // Levels of detail: this frame's positions of the levels' scene (source: the source scene's
    // frame), every object's level chosen through view, and the opaque triangles and the
    // transparent part made of the chosen levels. An object out of view keeps its place in the
    // part with no triangles, so that the orderer's object ids keep their meaning.
    PositionsView chooseLevels(PositionsView source_positions, const ViewProjection& view,
                               RenderStats& stats) {
        const Scene& scene = levels->scene();
        selection->select(source_positions, view);
        opaque_triangles.clear();
        part.objects.clear();
        part.scene_triangle.clear();
        part.whole = false;
        stats.triangles += selection->triangles();
        stats.boxed_objects += selection->boxedObjects();
        stats.culled_objects += selection->culledObjects();
        for (uint32_t o = 0; o < scene.objects.size(); ++o) {
            std::vector<uint32_t>& into = transparent[o] ? part.scene_triangle : opaque_triangles;
            const uint32_t first = uint32_t(into.size());
            for (const PrimitiveRange& range : selection->chosenRanges(o))
                for (uint32_t t = 0; t < range.triangle_count; ++t)
                    into.push_back(range.first_triangle + t);
            if (transparent[o])
                part.objects.push_back({first, uint32_t(into.size()) - first});
        }
        const uint32_t part_triangles = uint32_t(part.scene_triangle.size());
        primitives = levelPrimitives(part.objects, part_triangles, settings.level);
        if (orderer)
            orderer->setObjects(part.objects, part_triangles);
        if (settings.method == BlendMethod::unsorted) {
            sequence.clear();
            sequence.triangles = part.scene_triangle;
            if (part_triangles > 0)
                sequence.segments.push_back({0, part_triangles, false, {}});
        }
        return selection->levelsPositions();
    }

    // This frame's back-to-front sequence of transparent triangles (scene triangle ids), for the
    // methods that order per frame: ordered through view, its pixels; its groups' rectangles in
    // sampled's (the render target's).
    void buildSequence(PositionsView positions, const ViewProjection& view,
                       const ViewProjection& sampled, RenderStats& stats) {
        sequence.clear();
        if (part.scene_triangle.empty())
            return;
        if (!part.whole)
            copyCorners(positions, part.scene_triangle, part_positions);
        PositionsView ordered = part.whole ? positions : part_positions;
        // Checked, the order is made at pixel resolution (the check finds what differs at the
        // samples); unchecked, at the samples', so that its groups are found where they show.
        const ViewProjection& order_view = checked() ? view : sampled;
        if (settings.method == BlendMethod::centroid) {
            std::vector<uint32_t> order =
                detail::centroidBackToFront(ordered, primitives, order_view);
            std::reverse(order.begin(), order.end());
            detail::sequenceFromOrder(order, primitives, {}, sequence);
        } else {
            orderer->orderFrame(ordered, order_view, frame_order);
            stats.order = frame_order.stats;
            group_of.assign(primitives.size(), detail::kNoGroup);
            for (uint32_t g = 0; g < frame_order.cycles.size(); ++g)
                for (uint32_t p : frame_order.cycles[g])
                    group_of[p] = g;
            if (settings.level == OrderLevel::object) {
                if (checked())
                    groupEveryObject(group_of);
                else
                    markSelfOverlapping(ordered, order_view, group_of);
            }
            detail::sequenceFromOrder(frame_order.order, primitives, group_of, sequence);
        }
        for (uint32_t& t : sequence.triangles)
            t = part.scene_triangle[t];
        if (settings.method != BlendMethod::vissort)
            return;
        if (checked()) {
            stats.groups = uint32_t(frame_order.cycles.size());
            detail::blendGroupsInSequence(positions, sampled, sequence);
            return;
        }
        for (detail::DrawSegment& segment : sequence.segments) {
            if (!segment.per_pixel)
                continue;
            ++stats.groups;
            segment.rect =
                detail::screenRectOf(positions,
                                     std::span(sequence.triangles)
                                         .subspan(segment.first_triangle, segment.triangle_count),
                                     sampled);
        }
    }

    // Checked, at object level: every object of more than one triangle outside the cycles is
    // a group of its own, its triangles put back to front by centroid depth
    // (blendGroupsInSequence) so that the repair has few pixels where it overlaps itself. On the
    // bunnies at 1024x1024 that took 2 ms, and finding the objects that overlap themselves with
    // the oracle (markSelfOverlapping) 8 ms, for the same marked pixels.
    void groupEveryObject(std::vector<uint32_t>& group_of) const {
        for (uint32_t p = 0; p < primitives.size(); ++p)
            if (group_of[p] == detail::kNoGroup && primitives[p].triangle_count > 1)
                group_of[p] = uint32_t(primitives.size()) + p; // distinct from every cycle
    }

    // Unchecked: an object whose own triangles overlap on screen (beyond the depth tolerance) is,
    // alone, a group to composite per pixel. Found with the oracle: draw the object, then ask
    // whether any of it lies behind what was drawn.
    void markSelfOverlapping(PositionsView ordered, const ViewProjection& view,
                             std::vector<uint32_t>& group_of) {
        oracle->bind(ordered, view, primitives); // object level: one primitive an object
        // An approximate rule that counts near ties neither way: the blending one would find
        // every object behind itself, and the exact one would have to decide every pixel of it
        // (each a tie with itself). Triangles of one object whose depths nearly tie are
        // neighbours at a fold, where both take their colours from the shared corners: their
        // order hardly shows.
        oracle->setDepthTolerance(kFoldTolerance);
        uint8_t behind = 0;
        for (uint32_t p = 0; p < primitives.size(); ++p) {
            if (group_of[p] != detail::kNoGroup)
                continue;
            oracle->queryAgainst(std::span(&p, 1), std::span(&p, 1), std::span(&behind, 1));
            if (behind)
                group_of[p] = uint32_t(primitives.size()) + p; // distinct from every cycle
        }
        oracle->setDepthTolerance(orderTolerance());
    }

    // colour_cycles: this frame's cycles as scene triangles, coloured by the shading.
    void colourCycles() {
        cycle_triangles.resize(frame_order.cycles.size());
        for (std::size_t g = 0; g < frame_order.cycles.size(); ++g) {
            cycle_triangles[g].clear();
            for (uint32_t p : frame_order.cycles[g]) {
                const PrimitiveRange range = primitives[p];
                for (uint32_t t = range.first_triangle;
                     t < range.first_triangle + range.triangle_count; ++t)
                    cycle_triangles[g].push_back(part.scene_triangle[t]);
            }
        }
        geometry->setCycleColours(cycle_triangles);
    }

    // Whether every pixel of the order's blend is checked and repaired (verified_blending.h).
    bool checked() const {
        using Check = RenderSettings::OrderCheck;
        return settings.check == Check::on ||
               (settings.check == Check::automatic && settings.method == BlendMethod::vissort);
    }

    // The oracle's tolerance for vissort's order. Checked, the default one: the check finds
    // every fragment blended after one in front of it or tied with it, and the repair
    // composites those pixels from lists, so near ties need no groups (the blending tolerance
    // makes every touching face a cycle: 0.73 s of ordering where 0.09 s do on the IFC house).
    // Unchecked, the blending tolerance, so that near ties are groups composited per pixel.
    float orderTolerance() const { return checked() ? kDepthTolerance : kBlendingDepthTolerance; }

    // Draws transparent triangles [first, first + count) with program, its view set.
    void drawTransparent(GLuint program, const ViewProjection& view, std::size_t first,
                         std::size_t count) const {
        geometry->use(program, view);
        geometry->drawTransparent(first, count);
    }

    // Blending in sequence order, unchecked: the engines' way (unsorted, centroid).
    void blendSequence(const ViewProjection& view, RenderStats& stats) {
        if (sequence.triangles.empty())
            return;
        target.bind();
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_FALSE);
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        // Colour: source over destination; the buffer's alpha stays 1 (opaque background).
        glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        drawTransparent(shade_program.get(), view, 0, sequence.triangles.size());
        glDisable(GL_BLEND);
        stats.passes = 1;
    }

    detail::FragmentLists& fragmentLists() {
        if (!lists)
            lists = std::make_unique<detail::FragmentLists>(settings.list_bytes);
        return *lists;
    }

    // The order blended, every pixel checked and the marked ones composited again (repair), or
    // unchecked with its groups per pixel. positions: the scene's, as uploaded.
    void blendVerified(PositionsView positions, const ViewProjection& view, bool repair,
                       RenderStats& stats) {
        if (!verified)
            verified = std::make_unique<detail::VerifiedBlending>();
        const bool has_opaque = !opaque_triangles.empty();
        const detail::VerifiedBlending::Result blended =
            verified->blend(target, fragmentLists(), sequence, has_opaque,
                            [&](GLuint program, std::size_t first, std::size_t count) {
                                drawTransparent(program, view, first, count);
                            });
        stats.passes = sequence.triangles.empty() ? 0 : 1 + blended.extra_passes;
        stats.fragments = blended.fragments;
        if (!repair)
            return;
        const detail::MarkedPixels marked = verified->marked();
        if (marked.count() == 0)
            return;
        // Only the triangles that may cover a marked pixel are drawn again.
        detail::trianglesCovering(positions, sequence.triangles, view, marked, repair_transparent);
        geometry->setSubset(repair_transparent);
        const detail::VerifiedBlending::Result repaired =
            verified->repair(target, fragmentLists(), marked, has_opaque, [&](GLuint program) {
                geometry->use(program, view);
                geometry->drawTransparentSubset();
            });
        stats.passes += repaired.extra_passes;
        stats.fragments += repaired.fragments;
        stats.repaired_pixels = repaired.repaired_pixels;
    }

    // The render target at the samples' size, or why the driver cannot make it.
    void resizeTarget(const ViewProjection& sampled) {
        try {
            target.resize(sampled.width, sampled.height);
        } catch (const std::runtime_error& error) {
            if (grid.samples() == 1)
                throw;
            throw std::runtime_error(std::string(error.what()) + " (" +
                                     std::to_string(grid.samples()) + " samples a pixel)");
        }
    }

    // The image: the target's colour, each pixel's samples averaged.
    std::vector<float> readImage() {
        if (grid.samples() == 1)
            return target.readColour();
        if (!resolve)
            resolve = std::make_unique<detail::SampleResolve>();
        return resolve->resolve(target, grid);
    }

    // view: the samples' (the render target's).
    void compositeTransparent(PositionsView positions, const ViewProjection& view,
                              RenderStats& stats) {
        const std::size_t all = geometry->transparentCount();
        if (all == 0)
            return;
        switch (settings.method) {
        case BlendMethod::unsorted:
        case BlendMethod::centroid:
        case BlendMethod::vissort: {
            const bool check = checked();
            // vissort's groups are composited per pixel even unchecked.
            if (check || settings.method == BlendMethod::vissort)
                blendVerified(positions, view, check, stats);
            else
                blendSequence(view, stats);
            return;
        }
        case BlendMethod::linked_list: {
            target.bind();
            glEnable(GL_DEPTH_TEST); // the opaque surfaces hide fragments
            glDepthFunc(GL_LESS);
            const detail::FragmentLists::Result listed =
                fragmentLists().composite(target, target.whole(), 0, [&] {
                    drawTransparent(lists->buildProgram(), view, 0, all);
                });
            stats.fragments = listed.fragments;
            stats.passes = listed.passes;
            return;
        }
        case BlendMethod::peel:
            if (!peeling)
                peeling = std::make_unique<detail::DepthPeeling>();
            stats.passes = peeling->composite(
                target, [&] { drawTransparent(peeling->program(), view, 0, all); });
            return;
        case BlendMethod::dual_peel:
            if (!dual_peeling)
                dual_peeling = std::make_unique<detail::DualDepthPeeling>();
            stats.passes = dual_peeling->composite(
                target, [&](GLuint program) { drawTransparent(program, view, 0, all); });
            return;
        case BlendMethod::weighted:
            if (!weighted)
                weighted = std::make_unique<detail::WeightedBlended>();
            weighted->composite(target,
                                [&] { drawTransparent(weighted->program(), view, 0, all); });
            stats.passes = 1;
            return;
        }
    }
};

TransparencyRenderer::TransparencyRenderer(std::shared_ptr<GlContext> context, const Scene& scene,
                                           const RenderSettings& settings,
                                           std::shared_ptr<const LevelsOfDetail> levels) {
    if (!(settings.alpha > 0.0f && settings.alpha <= 1.0f))
        throw std::invalid_argument("alpha must be in (0, 1], got " +
                                    std::to_string(settings.alpha));
    const Result<SampleGrid> grid = sampleGridOf(settings.samples);
    if (!grid)
        throw std::invalid_argument(grid.error);
    if (!(settings.lod_error >= 0.0f) || !std::isfinite(settings.lod_error))
        throw std::invalid_argument("the level of detail's error must be 0 (off) or a positive "
                                    "number of pixels, got " +
                                    std::to_string(settings.lod_error));
    if (context == nullptr)
        throw std::invalid_argument("no OpenGL context");
    if (scene.triangleCount() > std::size_t(std::numeric_limits<GLint>::max()) / 3)
        throw std::runtime_error("the renderer draws at most 715,827,882 triangles");
    context->makeCurrent();
    impl_ = std::make_unique<Impl>();
    Impl& d = *impl_;
    d.context = std::move(context);
    d.settings = settings;
    d.grid = *grid.value;
    d.triangle_count = uint32_t(scene.triangleCount());
    if (settings.lod_error > 0.0f) {
        if (!levels)
            levels = std::make_shared<const LevelsOfDetail>(LevelsOfDetail::build(scene));
        d.selection =
            std::make_unique<DetailSelection>(scene, std::move(levels), settings.lod_error);
        d.levels = &d.selection->levels();
    }
    // With levels, the levels' scene is drawn: its objects are the scene's, each with its levels.
    const Scene& drawn = d.levels ? d.levels->scene() : scene;

    std::vector<uint8_t>& transparent = d.transparent;
    transparent.assign(drawn.objects.size(), 0);
    std::vector<float> colours;
    for (uint32_t o = 0; o < drawn.objects.size(); ++o) {
        const SceneObject& object = drawn.objects[o];
        const bool is_transparent = drawnTransparent(object, settings);
        transparent[o] = is_transparent ? 1 : 0;
        for (const ObjectPart& part : object.drawnParts()) {
            // An opaque mesh of a transparent object: alpha 1, opaque where blended.
            const float alpha = settings.all_transparent ? settings.alpha
                                : is_transparent         ? part.colour.a
                                                         : 1.0f;
            colours.insert(colours.end(), {part.colour.r, part.colour.g, part.colour.b, alpha});
        }
        if (!is_transparent && !d.levels) // with levels: chosen per frame
            for (uint32_t t = 0; t < object.triangle_count; ++t)
                d.opaque_triangles.push_back(object.first_triangle + t);
    }
    // With levels, the part starts as every object at level 0; frames choose their own.
    d.part = transparentPart(scene, transparent);
    d.primitives =
        levelPrimitives(d.part.objects, uint32_t(d.part.scene_triangle.size()), settings.level);
    if (settings.method == BlendMethod::unsorted && !d.part.scene_triangle.empty()) {
        // Submission order, every frame the same.
        d.sequence.triangles = d.part.scene_triangle;
        d.sequence.segments.push_back({0, uint32_t(d.part.scene_triangle.size()), false, {}});
    }
    if (settings.method == BlendMethod::vissort && !d.part.scene_triangle.empty()) {
        Result<std::unique_ptr<GeometryOracle>> oracle =
            makeOracle(settings.oracle, settings.oracle_options);
        if (!oracle)
            throw std::runtime_error(oracle.error);
        d.oracle = std::move(*oracle.value);
        d.oracle->setDepthTolerance(d.orderTolerance());
        d.orderer = std::make_unique<SceneOrderer>(
            d.part.objects, uint32_t(d.part.scene_triangle.size()), settings.level, *d.oracle);
        d.context->makeCurrent(); // a gl oracle made it current too; the same context
    }
    d.geometry = std::make_unique<detail::SceneGeometry>(drawn, colours);
    d.geometry->setShading(settings.shading);
    d.shade_program = detail::linkProgram(detail::kShadeVertexShader, detail::kShadeFragmentShader);
}

void TransparencyRenderer::setOrderProgress(std::function<void(double fraction)> report) {
    if (impl_->orderer)
        impl_->orderer->setProgress(std::move(report));
}

const DetailSelection* TransparencyRenderer::levelSelection() const {
    return impl_->selection.get();
}

const LevelsOfDetail* TransparencyRenderer::levels() const {
    return impl_->levels;
}

void TransparencyRenderer::setHighlightedTriangles(std::span<const uint32_t> triangles) {
    Impl& d = *impl_;
    d.context->makeCurrent();
    if (!d.levels) {
        d.geometry->setHighlighted(triangles);
        return;
    }
    // The scene's triangles are the levels' scene's level 0: a coarser level has no triangle of
    // its own to light up.
    d.highlighted.clear();
    for (uint32_t t : triangles)
        if (t < d.triangle_count)
            d.highlighted.push_back(d.levels->detailedTriangleOf(t));
    d.geometry->setHighlighted(d.highlighted);
}

TransparencyRenderer::~TransparencyRenderer() {
    if (impl_)
        impl_->context->makeCurrent(); // GL objects are deleted in their context
}

Image TransparencyRenderer::render(PositionsView positions, const ViewProjection& view,
                                   RenderStats& stats) {
    Impl& d = *impl_;
    if (positions.triangleCount() != d.triangle_count)
        throw std::invalid_argument("positions have " + std::to_string(positions.triangleCount()) +
                                    " triangles, the scene " + std::to_string(d.triangle_count));
    // The samples' buffers take what the largest image's pixels may (about 40 bytes each).
    if (uint64_t(view.width) * view.height * d.grid.samples() > kMaxImagePixels)
        throw std::invalid_argument(
            std::to_string(view.width) + "x" + std::to_string(view.height) + " at " +
            std::to_string(d.grid.samples()) + " samples a pixel is more than the " +
            std::to_string(kMaxImagePixels) + " samples the renderer draws");
    stats = {};
    // Every method draws on the samples as on pixels; only the order is made through view.
    const ViewProjection sampled = sampledView(view, d.grid);
    const auto start = std::chrono::steady_clock::now();
    if (d.levels) // the levels' scene from here on
        positions = d.chooseLevels(positions, view, stats);
    else
        stats.triangles = d.triangle_count;
    if (ordersPerFrame(d.settings.method)) {
        d.buildSequence(positions, view, sampled, stats);
        stats.order_ms = millisecondsSince(start);
    }

    const auto render_start = std::chrono::steady_clock::now();
    d.context->makeCurrent();
    // The levels' scene of a static source is the levels' own, immutable: uploaded once, not
    // compared frame after frame (10M triangles at the power plant's scale 10, 80 ms a frame).
    const bool own_levels = d.levels && !d.levels->scene().isDynamic() &&
                            positions.x.data() == d.levels->scene().positions.x.data();
    if (!own_levels || !d.levels_uploaded)
        d.geometry->upload(positions);
    d.levels_uploaded = own_levels;
    if (ordersPerFrame(d.settings.method)) {
        d.geometry->setTriangles(d.opaque_triangles, d.sequence.triangles);
        if (d.settings.colour_cycles && d.settings.method == BlendMethod::vissort)
            d.colourCycles();
    } else if (!d.triangles_uploaded || d.levels) { // submission order, every frame the same
        d.geometry->setTriangles(d.opaque_triangles, d.part.scene_triangle);
        d.triangles_uploaded = true;
    }

    d.resizeTarget(sampled);
    d.target.bind();
    glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE); // the oracles' conventions (gl_oracle.h)
    glDisable(GL_CULL_FACE);
    glDisable(GL_SCISSOR_TEST);
    const float background[4] = {d.settings.background.r, d.settings.background.g,
                                 d.settings.background.b, 1.0f};
    d.target.clear(background);

    // Opaque objects: depth written, no blending.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    d.geometry->use(d.shade_program.get(), sampled);
    d.geometry->drawOpaque(sampled);

    // Transparent ones: tested against the opaque depth, never written.
    glDepthMask(GL_FALSE);
    d.compositeTransparent(positions, sampled, stats);

    Image image;
    image.width = view.width;
    image.height = view.height;
    image.rgba = d.readImage(); // waits for the GPU
    stats.render_ms = millisecondsSince(render_start);
    stats.total_ms = millisecondsSince(start);
    return image;
}

} // namespace vissort
