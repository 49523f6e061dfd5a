#include "render/scene_geometry.h"

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "render/shading.h"
#include "render/view_culling.h"

namespace vissort::detail {
namespace {

GlBuffer createBuffer() {
    GLuint name = 0;
    glCreateBuffers(1, &name);
    return GlBuffer(name);
}

} // namespace

SceneGeometry::SceneGeometry(const Scene& scene, std::span<const float> part_colours)
    : mesh_(scene), object_bounds_(scene.objects.size()) {
    GLuint name = 0;
    glCreateVertexArrays(1, &name);
    vertex_array_ = GlVertexArray(name);
    vertices_ = createBuffer();
    parts_ = createBuffer();
    colours_ = createBuffer();
    elements_ = createBuffer();
    subset_elements_ = createBuffer();
    tints_ = createBuffer();
    highlighted_.assign(scene.triangleCount(), 0);
    cycle_tints_.assign(scene.triangleCount(), kNoTint);
    glNamedBufferStorage(tints_.get(), GLsizeiptr(scene.triangleCount() * sizeof(uint32_t) + 4),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
    // Zero-size storage is an error in OpenGL: every buffer gets a few spare bytes.
    // The shaders need a corner's colour only: its part's (an object's, when it has no parts).
    const std::vector<uint32_t>& corner_parts = mesh_.cornerParts();
    glNamedBufferStorage(parts_.get(), GLsizeiptr(corner_parts.size() * sizeof(uint32_t) + 4),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
    glNamedBufferSubData(parts_.get(), 0, GLsizeiptr(corner_parts.size() * sizeof(uint32_t)),
                         corner_parts.data());
    glNamedBufferStorage(colours_.get(), GLsizeiptr(part_colours.size() * sizeof(float) + 16),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
    glNamedBufferSubData(colours_.get(), 0, GLsizeiptr(part_colours.size() * sizeof(float)),
                         part_colours.data());

    const GLuint va = vertex_array_.get();
    glVertexArrayVertexBuffer(va, 0, vertices_.get(), 0, 6 * sizeof(float));
    glVertexArrayVertexBuffer(va, 1, parts_.get(), 0, sizeof(uint32_t));
    for (GLuint attribute : {0u, 1u}) { // position, normal
        glEnableVertexArrayAttrib(va, attribute);
        glVertexArrayAttribFormat(va, attribute, 3, GL_FLOAT, GL_FALSE,
                                  attribute * 3 * sizeof(float));
        glVertexArrayAttribBinding(va, attribute, 0);
    }
    glEnableVertexArrayAttrib(va, 2); // drawn part
    glVertexArrayAttribIFormat(va, 2, 1, GL_UNSIGNED_INT, 0);
    glVertexArrayAttribBinding(va, 2, 1);
    glVertexArrayElementBuffer(va, elements_.get());
}

void SceneGeometry::upload(PositionsView positions) {
    // A static scene's frames, or the same frame again: the normals and the buffer are current.
    const auto same = [](std::span<const float> a, const std::vector<float>& b) {
        return std::equal(a.begin(), a.end(), b.begin(), b.end());
    };
    if (same(positions.x, uploaded_.x) && same(positions.y, uploaded_.y) &&
        same(positions.z, uploaded_.z))
        return;
    uploaded_.x.assign(positions.x.begin(), positions.x.end());
    uploaded_.y.assign(positions.y.begin(), positions.y.end());
    uploaded_.z.assign(positions.z.begin(), positions.z.end());
    mesh_.update(positions, vertex_data_);
    const std::vector<uint32_t>& corner_objects = mesh_.cornerObjects();
    std::fill(object_bounds_.begin(), object_bounds_.end(), Bounds{});
    for (std::size_t c = 0; c < corner_objects.size(); ++c)
        object_bounds_[corner_objects[c]].add(positions.corner(c));
    glNamedBufferData(vertices_.get(), GLsizeiptr(vertex_data_.size() * sizeof(float)),
                      vertex_data_.data(), GL_STREAM_DRAW);
}

namespace {

// The corners of the opaque triangles, then of the transparent ones, into buffer.
void uploadElements(std::span<const uint32_t> opaque, std::span<const uint32_t> transparent,
                    std::vector<uint32_t>& data, const GlBuffer& buffer) {
    data.clear();
    data.reserve((opaque.size() + transparent.size()) * 3);
    for (std::span<const uint32_t> list : {opaque, transparent})
        for (uint32_t t : list)
            for (uint32_t k = 0; k < 3; ++k)
                data.push_back(t * 3 + k);
    glNamedBufferData(buffer.get(), GLsizeiptr(data.size() * sizeof(uint32_t)), data.data(),
                      GL_STREAM_DRAW);
}

void drawElements(std::size_t first_triangle, std::size_t count) {
    if (count == 0)
        return;
    glDrawElements(GL_TRIANGLES, GLsizei(count * 3), GL_UNSIGNED_INT,
                   reinterpret_cast<const void*>(first_triangle * 3 * sizeof(uint32_t)));
}

} // namespace

void SceneGeometry::setTriangles(std::span<const uint32_t> opaque,
                                 std::span<const uint32_t> transparent) {
    // Frame after frame only the transparent order changes: when the opaque list and the
    // transparent count are the buffer's, only the transparent part is written (on the power
    // plant, 0.3 of the 2.4M corners' 10 MB).
    const std::size_t opaque_corners = opaque.size() * 3;
    bool same_opaque = element_data_.size() == opaque_corners + transparent.size() * 3 &&
                       opaque.size() == opaque_count_;
    for (std::size_t i = 0; same_opaque && i < opaque.size(); ++i)
        same_opaque = element_data_[i * 3] == opaque[i] * 3;
    if (same_opaque) {
        for (std::size_t i = 0; i < transparent.size(); ++i)
            for (uint32_t k = 0; k < 3; ++k)
                element_data_[opaque_corners + i * 3 + k] = transparent[i] * 3 + k;
        glNamedBufferSubData(elements_.get(), GLintptr(opaque_corners * sizeof(uint32_t)),
                             GLsizeiptr(transparent.size() * 3 * sizeof(uint32_t)),
                             element_data_.data() + opaque_corners);
        return;
    }
    uploadElements(opaque, transparent, element_data_, elements_);
    opaque_count_ = opaque.size();
    transparent_count_ = transparent.size();
    // The opaque list's runs of one object each, for drawOpaque's culling.
    opaque_runs_.clear();
    const std::vector<uint32_t>& corner_objects = mesh_.cornerObjects();
    for (uint32_t i = 0; i < opaque.size(); ++i) {
        const uint32_t object = corner_objects[std::size_t(opaque[i]) * 3];
        if (opaque_runs_.empty() || opaque_runs_.back().object != object)
            opaque_runs_.push_back({object, i, 0});
        ++opaque_runs_.back().count;
    }
}

void SceneGeometry::setSubset(std::span<const uint32_t> transparent) {
    uploadElements({}, transparent, subset_data_, subset_elements_);
    subset_count_ = transparent.size();
}

void SceneGeometry::drawTransparentSubset() const {
    glVertexArrayElementBuffer(vertex_array_.get(), subset_elements_.get());
    drawElements(0, subset_count_);
    glVertexArrayElementBuffer(vertex_array_.get(), elements_.get());
}

void SceneGeometry::setHighlighted(std::span<const uint32_t> triangles) {
    std::fill(highlighted_.begin(), highlighted_.end(), uint8_t(0));
    for (uint32_t t : triangles)
        if (t < highlighted_.size())
            highlighted_[t] = 1;
    uploadTints();
}

void SceneGeometry::setCycleColours(std::span<const std::vector<uint32_t>> groups) {
    if (groups.empty() && cycle_triangles_.empty())
        return; // the common frame: no cycles then, none now
    for (uint32_t t : cycle_triangles_)
        cycle_tints_[t] = kNoTint;
    cycle_triangles_.clear();
    for (std::size_t g = 0; g < groups.size(); ++g)
        for (uint32_t t : groups[g])
            if (t < cycle_tints_.size()) {
                cycle_tints_[t] = kCycleTint + uint32_t(g);
                cycle_triangles_.push_back(t);
            }
    uploadTints();
}

void SceneGeometry::uploadTints() {
    tint_data_.resize(cycle_tints_.size());
    bool any = false, any_highlight = false;
    for (std::size_t t = 0; t < tint_data_.size(); ++t) {
        tint_data_[t] = highlighted_[t] ? kHighlightTint : cycle_tints_[t];
        any |= tint_data_[t] != kNoTint;
        any_highlight |= highlighted_[t] != 0;
    }
    glNamedBufferSubData(tints_.get(), 0, GLsizeiptr(tint_data_.size() * sizeof(uint32_t)),
                         tint_data_.data());
    tinting_ = any;
    dimming_ = any_highlight;
}

void SceneGeometry::setView(GLuint program, const ViewProjection& view) const {
    const glm::mat4 rounded(clipTransform(view)); // rounded once

    glProgramUniformMatrix4fv(program, glGetUniformLocation(program, "view_projection"), 1,
                              GL_FALSE, glm::value_ptr(rounded));
    glProgramUniform3f(program, glGetUniformLocation(program, "eye"), float(view.eye_position.x),
                       float(view.eye_position.y), float(view.eye_position.z));
    glProgramUniform3f(program, glGetUniformLocation(program, "view_direction"),
                       float(view.forward.x), float(view.forward.y), float(view.forward.z));
    glProgramUniform1i(program, glGetUniformLocation(program, "orthographic"),
                       view.projection == Projection::orthographic ? 1 : 0);
    glProgramUniform1i(program, glGetUniformLocation(program, "shading"), int(shading_));
    glProgramUniform1i(program, glGetUniformLocation(program, "tinting"), tinting_ ? 1 : 0);
    glProgramUniform1i(program, glGetUniformLocation(program, "dimming"), dimming_ ? 1 : 0);
}

void SceneGeometry::use(GLuint program, const ViewProjection& view) const {
    setView(program, view);
    glUseProgram(program);
    bind();
}

void SceneGeometry::bind() const {
    glBindVertexArray(vertex_array_.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, colours_.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 5, tints_.get());
}

void SceneGeometry::drawOpaque(const ViewProjection& view) {
    draw_counts_.clear();
    draw_offsets_.clear();
    uint32_t end = 0; // where the last range drawn ends, in triangles
    for (const ObjectRun& run : opaque_runs_) {
        if (boxOutsideView(object_bounds_[run.object], view))
            continue;
        if (!draw_counts_.empty() && end == run.first) {
            draw_counts_.back() += GLsizei(run.count * 3);
        } else {
            draw_counts_.push_back(GLsizei(run.count * 3));
            draw_offsets_.push_back(
                reinterpret_cast<const void*>(std::size_t(run.first) * 3 * sizeof(uint32_t)));
        }
        end = run.first + run.count;
    }
    if (!draw_counts_.empty())
        glMultiDrawElements(GL_TRIANGLES, draw_counts_.data(), GL_UNSIGNED_INT,
                            draw_offsets_.data(), GLsizei(draw_counts_.size()));
}

void SceneGeometry::drawTransparent(std::size_t first, std::size_t count) const {
    drawElements(opaque_count_ + first, count);
}

} // namespace vissort::detail
