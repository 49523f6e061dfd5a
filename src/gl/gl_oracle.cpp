// The OpenGL occlusion oracle (gl_oracle.h): Vis-sort's queries (Govindaraju, Henson, Lin,
// Manocha, I3D 2005, section 4) as GL_ANY_SAMPLES_PASSED occlusion queries, pass 2's dependent
// draws as conditional rendering (OpenGL 3.0, NV_conditional_render). Depth tolerance 0 draws
// through bounded_fragments.h's program, any other through the plain one below.

#include "vissort/gl_oracle.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "gl/bounded_fragments.h"
#include "gl/gl_api.h"
#include "gl/gl_objects.h"
#include "gl/gl_program.h"

namespace vissort {
namespace {

// For a non-zero depth tolerance. x, y and z come from three float arrays of one buffer
// (TrianglePositions' layout); depth_offset moves a query's fragments nearer by the tolerance
// after the divide (gl_oracle.h).
constexpr const char* kVertexShader = R"(#version 450 core
layout(location = 0) in float x;
layout(location = 1) in float y;
layout(location = 2) in float z;
uniform mat4 view_projection;
uniform float depth_offset;
void main() {
    vec4 clip = view_projection * vec4(x, y, z, 1.0);
    clip.z += depth_offset * clip.w;
    gl_Position = clip;
}
)";

// Depth only: no colour is written (the framebuffer has none).
constexpr const char* kFragmentShader = R"(#version 450 core
void main() {}
)";

} // namespace

struct GlOracle::Impl {
    std::shared_ptr<GlContext> context;
    detail::GlProgram program; // a non-zero tolerance's
    GLint matrix_location = -1, offset_location = -1;
    detail::BoundedFragmentProgram bounded; // tolerance 0's, on the same vertex array
    detail::GlVertexArray vertex_array;
    detail::GlBuffer corners;        // x of every corner, then y, then z
    std::size_t corner_capacity = 0; // corners the buffer holds
    detail::GlFramebuffer framebuffer;
    detail::GlRenderbuffer depth;
    uint32_t width = 0, height = 0;
    std::vector<PrimitiveRange> primitives;
    std::vector<GLuint> queries;         // one per element of a pass, reused
    std::vector<uint32_t> single_groups; // singleGroups' 0, 1, 2, ...
    // Draws waiting to go out as one glMultiDrawArrays, and the state they and queries need.
    std::vector<GLint> first_corners;
    std::vector<GLsizei> corner_counts;
    enum class Mode { unset, draw, query } mode = Mode::unset;
    float tolerance = kDepthTolerance; // the oracle's, taken at every call
    bool exact() const { return tolerance == 0; }
    // glPolygonOffset's factor for the snap slack: the driver moves a fragment by factor times
    // max(|dz/dx|, |dz/dy|), the CPU's slack with factor 2^-(subpixel bits) (cpu_rasterizer.h).
    // Set at the first call (the context is current then).
    float slope_factor = -1;
    GlOracleStats stats;

    void setMode(Mode wanted) {
        if (mode == wanted)
            return;
        mode = wanted;
        const bool query = wanted == Mode::query;
        glDepthFunc(query ? GL_GREATER : GL_LESS);
        glDepthMask(query ? GL_FALSE : GL_TRUE);
        if (exact()) {
            // Draws write their fragments' depth bounds from below, queries from above.
            bounded.setQuery(query);
            return;
        }
        glProgramUniform1f(program.get(), offset_location, query ? -tolerance : 0.0f);
        // The snap slack (cpu_reference_oracle.h, rule 7) as a slope-scaled polygon offset: towards
        // "not behind" for a tolerance >= 0 (draws farther, queries nearer), else the other way.
        glPolygonOffset(query == (tolerance >= 0) ? -slope_factor : slope_factor, 0.0f);
    }

    // Queues primitive p's draw (LESS, writes on).
    void queueDraw(uint32_t p) {
        assert(p < primitives.size());
        ++stats.draws;
        if (primitives[p].triangle_count == 0)
            return;
        first_corners.push_back(GLint(primitives[p].first_triangle * 3));
        corner_counts.push_back(GLsizei(primitives[p].triangle_count * 3));
    }

    // Sends the queued draws, in order.
    void flushDraws() {
        if (first_corners.empty())
            return;
        setMode(Mode::draw);
        glMultiDrawArrays(GL_TRIANGLES, first_corners.data(), corner_counts.data(),
                          GLsizei(first_corners.size()));
        ++stats.draw_calls;
        first_corners.clear();
        corner_counts.clear();
    }

    // Draws primitive p alone in the current mode.
    void drawNow(uint32_t p) {
        assert(p < primitives.size());
        if (primitives[p].triangle_count == 0)
            return;
        glDrawArrays(GL_TRIANGLES, GLint(primitives[p].first_triangle * 3),
                     GLsizei(primitives[p].triangle_count * 3));
        ++stats.draw_calls;
    }

    // Queries primitive p into query object q (GREATER, writes off; tolerance 0: the depths'
    // upper bounds, else nearer by the tolerance).
    void issueQuery(uint32_t p, GLuint q) { issueQuery(std::span(&p, 1), q); }

    // Queries the union of primitives ps into one query object: any sample of any of them.
    void issueQuery(std::span<const uint32_t> ps, GLuint q) {
        flushDraws();
        setMode(Mode::query);
        stats.queries += ps.size();
        glBeginQuery(GL_ANY_SAMPLES_PASSED, q);
        for (uint32_t p : ps)
            drawNow(p);
        glEndQuery(GL_ANY_SAMPLES_PASSED);
    }

    bool answer(GLuint q) const {
        GLuint passed = 0;
        glGetQueryObjectuiv(q, GL_QUERY_RESULT, &passed);
        return passed != 0;
    }

    void ensureQueries(std::size_t count) {
        if (queries.size() >= count)
            return;
        const std::size_t old = queries.size();
        queries.resize(count);
        glGenQueries(GLsizei(count - old), queries.data() + old);
    }

    // Ends a public call: the polygon offset (a non-zero tolerance's) is this oracle's alone, not
    // the shared context's other users' (the renderer draws without one).
    struct [[nodiscard]] Scope {
        Scope() = default;
        Scope(const Scope&) = delete;
        Scope& operator=(const Scope&) = delete;
        ~Scope() { glDisable(GL_POLYGON_OFFSET_FILL); }
    };

    Scope begin(float depth_tolerance) {
        tolerance = depth_tolerance;
        context->makeCurrent();
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer.get());
        glUseProgram(exact() ? bounded.get() : program.get());
        glBindVertexArray(vertex_array.get());
        glViewport(0, 0, GLsizei(width), GLsizei(height));
        // Every call: another user of the shared context (the renderer) may have changed these.
        // Depth d of camera.h in window z, clipping to 0 <= z <= w, row 0 at the top.
        glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
        glEnable(GL_DEPTH_TEST);
        glDisable(GL_BLEND);
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_CULL_FACE); // tolerance 0's coverage polygons wind either way
        glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        glClearDepth(1.0);
        if (slope_factor < 0) {
            GLint bits = 8;
            glGetIntegerv(GL_SUBPIXEL_BITS, &bits);
            slope_factor = std::ldexp(1.0f, -std::clamp(bits, 4, 12));
        }
        if (exact())
            glDisable(GL_POLYGON_OFFSET_FILL); // the fragment shader writes the depth
        else
            glEnable(GL_POLYGON_OFFSET_FILL);
        mode = Mode::unset;
        return {};
    }

    void clearDepth() {
        first_corners.clear();
        corner_counts.clear();
        setMode(Mode::draw); // glClear leaves the depth buffer alone while depth writes are off
        glClear(GL_DEPTH_BUFFER_BIT);
    }

    // A pass or a group query, after begin: an empty depth buffer and query objects for `count`
    // answers.
    void beginPass(std::size_t count) {
        clearDepth();
        ensureQueries(count);
    }

    // 0, 1, ..., count: the group starts of count groups of one member.
    std::span<const uint32_t> singleGroups(std::size_t count) {
        if (single_groups.size() < count + 1) {
            single_groups.resize(count + 1);
            std::iota(single_groups.begin(), single_groups.end(), 0u);
        }
        return std::span(single_groups).first(count + 1);
    }

    // Reads the answers once, after every query of the pass has been issued.
    void readAnswers(std::span<const uint8_t> query, std::span<uint8_t> behind) const {
        for (std::size_t i = 0; i < behind.size(); ++i)
            if (query.empty() || query[i])
                behind[i] = answer(queries[i]) ? 1 : 0;
    }
};

GlOracle::GlOracle(std::shared_ptr<GlContext> context) : impl_(std::make_unique<Impl>()) {
    assert(context != nullptr);
    impl_->context = std::move(context);
    impl_->context->makeCurrent();
    impl_->program = detail::linkProgram(kVertexShader, kFragmentShader);
    impl_->matrix_location = glGetUniformLocation(impl_->program.get(), "view_projection");
    impl_->offset_location = glGetUniformLocation(impl_->program.get(), "depth_offset");
    impl_->bounded = detail::BoundedFragmentProgram::link();
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    impl_->vertex_array = detail::GlVertexArray(name);
    glCreateBuffers(1, &name);
    impl_->corners = detail::GlBuffer(name);
    glCreateFramebuffers(1, &name);
    impl_->framebuffer = detail::GlFramebuffer(name);
    glCreateRenderbuffers(1, &name);
    impl_->depth = detail::GlRenderbuffer(name);
    for (GLuint attribute = 0; attribute < 3; ++attribute) {
        glEnableVertexArrayAttrib(impl_->vertex_array.get(), attribute);
        glVertexArrayAttribFormat(impl_->vertex_array.get(), attribute, 1, GL_FLOAT, GL_FALSE, 0);
        glVertexArrayAttribBinding(impl_->vertex_array.get(), attribute, attribute);
    }
}

GlOracle::~GlOracle() {
    impl_->context->makeCurrent();
    if (!impl_->queries.empty())
        glDeleteQueries(GLsizei(impl_->queries.size()), impl_->queries.data());
}

void GlOracle::bind(PositionsView positions, const ViewProjection& view,
                    std::span<const PrimitiveRange> primitives) {
    Impl& d = *impl_;
    d.context->makeCurrent();
    const std::size_t corners = positions.x.size();
    if (corners > std::size_t(std::numeric_limits<GLint>::max()))
        throw std::runtime_error(
            "the OpenGL oracle draws at most 2^31 - 1 corners; the scene has " +
            std::to_string(corners));
    if (view.width != d.width || view.height != d.height) {
        GLint largest = 0;
        glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &largest);
        if (view.width > uint32_t(largest) || view.height > uint32_t(largest))
            throw std::runtime_error("the OpenGL driver's framebuffers reach " +
                                     std::to_string(largest) + " pixels on a side, not " +
                                     std::to_string(view.width) + "x" +
                                     std::to_string(view.height));
        glNamedRenderbufferStorage(d.depth.get(), GL_DEPTH_COMPONENT32F, GLsizei(view.width),
                                   GLsizei(view.height));
        glNamedFramebufferRenderbuffer(d.framebuffer.get(), GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                       d.depth.get());
        glNamedFramebufferDrawBuffer(d.framebuffer.get(), GL_NONE);
        glNamedFramebufferReadBuffer(d.framebuffer.get(), GL_NONE);
        if (glCheckNamedFramebufferStatus(d.framebuffer.get(), GL_FRAMEBUFFER) !=
            GL_FRAMEBUFFER_COMPLETE)
            throw std::runtime_error(
                "the OpenGL driver cannot render to a 32-bit float depth buffer");
        d.width = view.width;
        d.height = view.height;
    }
    // The corners: three float arrays, x then y then z, each `corners` long.
    const GLsizeiptr array_bytes = GLsizeiptr(corners * sizeof(float));
    if (corners > d.corner_capacity) {
        glNamedBufferData(d.corners.get(), 3 * array_bytes, nullptr, GL_DYNAMIC_DRAW);
        d.corner_capacity = corners;
    }
    if (corners > 0) {
        glNamedBufferSubData(d.corners.get(), 0, array_bytes, positions.x.data());
        glNamedBufferSubData(d.corners.get(), array_bytes, array_bytes, positions.y.data());
        glNamedBufferSubData(d.corners.get(), 2 * array_bytes, array_bytes, positions.z.data());
    }
    for (GLuint attribute = 0; attribute < 3; ++attribute)
        glVertexArrayVertexBuffer(d.vertex_array.get(), attribute, d.corners.get(),
                                  GLintptr(attribute) * array_bytes, sizeof(float));
    const glm::dmat4 matrix =
        glm::make_mat4(view.projection_matrix.data()) * glm::make_mat4(view.view.data());
    const glm::mat4 rounded(matrix);
    glProgramUniformMatrix4fv(d.program.get(), d.matrix_location, 1, GL_FALSE,
                              glm::value_ptr(rounded));
    d.bounded.setView(view);
    d.primitives.assign(primitives.begin(), primitives.end());
    for ([[maybe_unused]] const PrimitiveRange& range : d.primitives)
        assert(uint64_t(range.first_triangle) + range.triangle_count <= positions.triangleCount());
    const Impl::Scope scope = d.begin(depth_tolerance_);
    d.clearDepth();
}

uint32_t GlOracle::primitiveCount() const {
    return uint32_t(impl_->primitives.size());
}

void GlOracle::clear() {
    const Impl::Scope scope = impl_->begin(depth_tolerance_);
    impl_->clearDepth();
}

void GlOracle::draw(uint32_t primitive) {
    Impl& d = *impl_;
    const Impl::Scope scope = d.begin(depth_tolerance_);
    d.queueDraw(primitive);
    d.flushDraws();
}

bool GlOracle::anyBehind(uint32_t primitive) {
    Impl& d = *impl_;
    const Impl::Scope scope = d.begin(depth_tolerance_);
    d.ensureQueries(1);
    d.issueQuery(primitive, d.queries[0]);
    return d.answer(d.queries[0]);
}

// The plain passes are the group passes over groups of one (singleGroups).
void GlOracle::backToFrontPass(std::span<const uint32_t> sequence, std::span<const uint8_t> query,
                               std::span<uint8_t> behind) {
    assert(query.size() == sequence.size() && behind.size() == sequence.size());
    backToFrontGroupPass(sequence, impl_->singleGroups(sequence.size()), query, behind);
}

void GlOracle::frontToBackPass(std::span<const uint32_t> sequence, std::span<const uint8_t> query,
                               std::span<uint8_t> behind) {
    assert(query.size() == sequence.size() && behind.size() == sequence.size());
    frontToBackGroupPass(sequence, impl_->singleGroups(sequence.size()), query, behind);
}

void GlOracle::backToFrontGroupPass(std::span<const uint32_t> members,
                                    std::span<const uint32_t> first, std::span<const uint8_t> query,
                                    std::span<uint8_t> behind) {
    assert(first.size() == query.size() + 1 && behind.size() == query.size());
    Impl& d = *impl_;
    const Impl::Scope scope = d.begin(depth_tolerance_);
    d.beginPass(query.size());
    for (std::size_t g = query.size(); g-- > 0;) {
        const std::span<const uint32_t> group = members.subspan(first[g], first[g + 1] - first[g]);
        if (query[g])
            d.issueQuery(group, d.queries[g]);
        for (uint32_t p : group)
            d.queueDraw(p);
    }
    d.flushDraws();
    d.readAnswers(query, behind);
}

void GlOracle::frontToBackGroupPass(std::span<const uint32_t> members,
                                    std::span<const uint32_t> first, std::span<const uint8_t> query,
                                    std::span<uint8_t> behind) {
    assert(first.size() == query.size() + 1 && behind.size() == query.size());
    Impl& d = *impl_;
    const Impl::Scope scope = d.begin(depth_tolerance_);
    d.beginPass(query.size());
    for (std::size_t g = 0; g < query.size(); ++g) {
        const std::span<const uint32_t> group = members.subspan(first[g], first[g + 1] - first[g]);
        if (!query[g]) {
            for (uint32_t p : group)
                d.queueDraw(p);
            continue;
        }
        // Drawn only when the group's own query found a fragment behind: the GPU decides.
        d.issueQuery(group, d.queries[g]);
        d.setMode(Impl::Mode::draw);
        d.stats.draws += group.size();
        glBeginConditionalRender(d.queries[g], GL_QUERY_WAIT);
        for (uint32_t p : group)
            d.drawNow(p);
        glEndConditionalRender();
    }
    d.flushDraws();
    d.readAnswers(query, behind);
}

void GlOracle::queryAgainst(std::span<const uint32_t> occluders, std::span<const uint32_t> targets,
                            std::span<uint8_t> behind) {
    assert(behind.size() == targets.size());
    Impl& d = *impl_;
    const Impl::Scope scope = d.begin(depth_tolerance_);
    d.beginPass(targets.size());
    for (uint32_t p : occluders)
        d.queueDraw(p);
    for (std::size_t i = 0; i < targets.size(); ++i)
        d.issueQuery(targets[i], d.queries[i]);
    d.readAnswers({}, behind); // every target was queried
}

std::vector<float> GlOracle::depthBuffer() const {
    const Impl& d = *impl_;
    d.context->makeCurrent();
    std::vector<float> depths(std::size_t(d.width) * d.height);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, d.framebuffer.get());
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, GLsizei(d.width), GLsizei(d.height), GL_DEPTH_COMPONENT, GL_FLOAT,
                 depths.data());
    return depths;
}

const GlContext& GlOracle::context() const {
    return *impl_->context;
}
const GlOracleStats& GlOracle::stats() const {
    return impl_->stats;
}
void GlOracle::resetStats() {
    impl_->stats = {};
}

} // namespace vissort
