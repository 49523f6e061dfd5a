#pragma once
// The scene on the GPU, shared by every blending method: one vertex stream (position, normal,
// drawn part per corner, RenderMesh), the parts' colours, and an element buffer holding the opaque
// triangles and then the transparent ones in the frame's draw order.

#include <cstdint>
#include <span>
#include <vector>

#include "gl/gl_objects.h"
#include "render/render_mesh.h"
#include "vissort/camera.h"
#include "vissort/scene.h"
#include "vissort/transparency_renderer.h" // Shading

namespace vissort::detail {

class SceneGeometry {
public:
    /// part_colours: 4 floats (r, g, b, alpha) per drawn part of scene (RenderMesh::cornerParts),
    /// as shaded (shading.h).
    SceneGeometry(const Scene& scene, std::span<const float> part_colours);

    /// Uploads the vertices of a frame: positions has the scene's triangle count. Positions equal
    /// to the last ones uploaded cost a comparison.
    void upload(PositionsView positions);
    /// The triangles to draw (scene triangle ids): opaque ones in any order, transparent ones in
    /// the order drawTransparent's ranges refer to.
    void setTriangles(std::span<const uint32_t> opaque, std::span<const uint32_t> transparent);

    /// Sets a program's view and shading uniforms (those of kShadeVertexShader).
    void setView(GLuint program, const ViewProjection& view) const;
    /// How triangles are shaded (shading.h); lit unless set.
    void setShading(Shading shading) { shading_ = shading; }
    /// Draws these triangles (scene triangle ids) in the highlight colour and the untinted rest
    /// dimmed (shading.h); empty: none. Highlights are drawn over cycle colours.
    void setHighlighted(std::span<const uint32_t> triangles);
    /// Draws the triangles of each group (scene triangle ids) in a colour of the cycle palette
    /// (shading.h), group g in colour g modulo the palette; empty: none. Replaces the last call's.
    void setCycleColours(std::span<const std::vector<uint32_t>> groups);
    /// Binds the vertex stream, the colours (SSBO binding 0) and the tints (binding 5) for the
    /// draws below.
    void bind() const;
    /// Sets program's view (setView), makes it current and binds the geometry (bind): what
    /// every draw below needs first.
    void use(GLuint program, const ViewProjection& view) const;
    /// Draws the opaque triangles with the bound program and state, but for the objects wholly
    /// out of view (view: the one the program's uniforms were set for).
    void drawOpaque(const ViewProjection& view);
    /// Draws transparent triangles [first, first + count) of setTriangles' order.
    void drawTransparent(std::size_t first, std::size_t count) const;
    std::size_t transparentCount() const { return transparent_count_; }

    /// A second list of transparent triangles (scene ids), drawn on their own by the call below:
    /// the few a repair redraws (verified_blending.h), without touching the frame's list.
    void setSubset(std::span<const uint32_t> transparent);
    void drawTransparentSubset() const;

private:
    /// Uploads the tints: a highlight where one is set, else the triangle's cycle colour.
    void uploadTints();

    RenderMesh mesh_;
    GlVertexArray vertex_array_;
    GlBuffer vertices_, parts_, colours_, elements_, subset_elements_, tints_;
    TrianglePositions uploaded_; // what the vertex buffer holds
    std::vector<float> vertex_data_;
    std::vector<uint32_t> element_data_;
    std::size_t opaque_count_ = 0, transparent_count_ = 0;
    std::vector<uint32_t> subset_data_;
    std::size_t subset_count_ = 0;
    struct ObjectRun {
        uint32_t object, first, count; // triangles [first, first + count) of the opaque list
    };
    std::vector<ObjectRun> opaque_runs_;
    std::vector<Bounds> object_bounds_; // of the positions uploaded
    std::vector<GLsizei> draw_counts_;  // drawOpaque's ranges, reused from frame to frame
    std::vector<const void*> draw_offsets_;
    std::vector<uint8_t> highlighted_;      // one per triangle
    std::vector<uint32_t> cycle_tints_;     // one per triangle: kNoTint or kCycleTint + group
    std::vector<uint32_t> cycle_triangles_; // those with a cycle tint, to clear it cheaply
    std::vector<uint32_t> tint_data_;       // what the tint buffer holds
    Shading shading_ = Shading::lit;
    bool tinting_ = false;
    bool dimming_ = false; // some triangle is highlighted: the untinted ones are dimmed
};

} // namespace vissort::detail
