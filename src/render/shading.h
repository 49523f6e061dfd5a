#pragma once
// The one shading every method uses, so that methods differ only in how they composite: a
// vertex shader computing each corner's colour (like the paper's vertex shader), and the GLSL
// pieces the methods' own shaders share.

#include <cstdint>

namespace vissort::detail {

// Per-vertex shading (Shading, transparency_renderer.h), as the paper shades in a vertex shader:
//  - lit: a headlight, two-sided so that the inner surfaces of transparent objects are lit too;
//  - flat: each object's colour and alpha as they are, unlit: what a ray-cast reference can
//    reproduce;
//  - membrane: lit, and transparent surfaces as thin layers of their alpha seen at an angle
//    (Govindaraju et al., I3D 2005, section 5.2): light crosses 1 / |n . v| times the layer's
//    thickness, so alpha' = 1 - (1 - alpha)^(1 / max(|n . v|, kMembraneFacing)): surfaces seen
//    edge-on grow opaque, the rim of a soap bubble. Opaque surfaces (alpha 1) stay opaque.
// Inputs: SceneGeometry's vertex stream (position, unit normal, drawn part) and per-part colours
// (SSBO binding 0); `shading` is the Shading's index. Output: `shaded`, straight (not
// premultiplied) colour and alpha, interpolated across the triangle.
// With `tinting`, each triangle's tint in SSBO binding 5 (one uint per triangle; corners are
// unindexed, so a corner's index / 3 is its triangle) replaces its object's colour: kHighlightTint
// a strong magenta, opaque (colliding triangles); kCycleTint + g the colour g (modulo 8) of a
// palette without magenta, at the object's alpha (the primitives of the order's cycle g). With
// `dimming` (some triangle is highlighted), every untinted triangle is dimmed so that the
// highlights stand out, even behind it: its colour 60% of the way to grey 0.5, and a
// transparent one's alpha 0.3 of its own (colliding triangles are mostly inside other
// objects: drawn only in magenta, 1,014 highlighted triangles of the bunnies changed 669 pixels).
// In every method alike: the methods stay comparable.
inline constexpr uint32_t kNoTint = 0, kHighlightTint = 1, kCycleTint = 2;
inline constexpr const char* kShadeVertexShader = R"(#version 450 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in uint part;  // its colour's index
layout(std430, binding = 0) readonly buffer Colours { vec4 colours[]; };
layout(std430, binding = 5) readonly buffer Tints { uint tints[]; };
uniform mat4 view_projection;
uniform vec3 eye;             // perspective: the eye
uniform vec3 view_direction;  // orthographic: the direction of view
uniform bool orthographic;
uniform int shading;  // Shading: 0 lit, 1 flat, 2 membrane
uniform bool tinting;
uniform bool dimming;
out vec4 shaded;
// The most a layer seen edge-on thickens: 20 times (alpha 0.25 becomes 0.997).
const float kMembraneFacing = 0.05;
const vec3 kCyclePalette[8] = vec3[8](
    vec3(1.0, 0.55, 0.0), vec3(0.1, 0.75, 0.2), vec3(0.15, 0.4, 1.0), vec3(1.0, 0.9, 0.0),
    vec3(0.0, 0.85, 0.9), vec3(0.9, 0.1, 0.1), vec3(0.5, 0.25, 0.85), vec3(0.55, 0.35, 0.1));
flat out uint triangle;  // the scene's triangle id: the tie rule of the fragment lists
invariant gl_Position;  // the same depths in every program: vissort's repair tests equality
void main() {
    gl_Position = view_projection * vec4(position, 1.0);
    triangle = uint(gl_VertexID) / 3u;  // elements are 3 t + k (SceneGeometry)
    vec4 base = colours[part];
    uint tint = tinting ? tints[gl_VertexID / 3] : 0u;
    if (tint == 1u)
        base = vec4(1.0, 0.1, 0.55, 1.0);  // kHighlightTint
    else if (tint >= 2u)
        base = vec4(kCyclePalette[(tint - 2u) % 8u], base.a);  // kCycleTint + group
    else if (dimming)
        base = vec4(mix(base.rgb, vec3(0.5), 0.6), base.a < 1.0 ? base.a * 0.3 : 1.0);
    if (shading == 1) {  // flat
        shaded = base;
        return;
    }
    vec3 to_eye = orthographic ? -view_direction : normalize(eye - position);
    float facing = length(normal) > 0.0 ? abs(dot(normal, to_eye)) : 1.0;
    vec3 rgb = base.rgb * (0.3 + 0.7 * facing);
    float alpha = base.a;
    if (shading == 2 && alpha < 1.0)  // membrane
        alpha = 1.0 - pow(1.0 - alpha, 1.0 / max(facing, kMembraneFacing));
    shaded = vec4(rgb, alpha);
}
)";

// Opaque draws and sorted blending: the colour as shaded (blending, when on, does the rest).
inline constexpr const char* kShadeFragmentShader = R"(#version 450 core
in vec4 shaded;
layout(location = 0) out vec4 colour;
void main() { colour = shaded; }
)";

// The full-screen compositing steps run as compute shaders over pixel rectangles, one
// invocation per pixel (runPixelProgram, render_target.h): exact per-pixel work with no
// rasterization rules in the way; or over a list of 8x8 tiles of a rectangle, one work group a
// tile (runPixelProgramOnTiles), where only a few scattered pixels need the work. Each program is
// this header followed by its body.
inline constexpr const char* kPixelComputeHeader = R"(#version 450 core
layout(local_size_x = 8, local_size_y = 8) in;
uniform ivec2 origin;  // the rectangle's top-left pixel
uniform ivec2 extent;  // its width and height
uniform bool tiled;    // one work group per tile of tile_origins
uniform uint tile_count;
layout(std430, binding = 7) readonly buffer TileOrigins { uvec2 tile_origins[]; };
// This invocation's pixel; false for the invocations beyond the rectangle's edges.
bool rectanglePixel(out ivec2 pixel) {
    uvec2 local = gl_GlobalInvocationID.xy;
    if (tiled) {
        uint tile = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
        // A tile left of or above the rectangle wraps to a huge offset, outside the extent.
        local = tile < tile_count ? tile_origins[tile] - uvec2(origin) + gl_LocalInvocationID.xy
                                  : uvec2(extent);
    }
    pixel = origin + ivec2(local);
    return all(lessThan(local, uvec2(extent)));
}
)";
inline constexpr unsigned kPixelGroupSide = 8;

} // namespace vissort::detail
