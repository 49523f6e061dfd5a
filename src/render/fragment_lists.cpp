#include "render/fragment_lists.h"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "gl/gl_program.h"
#include "render/shading.h"

namespace vissort::detail {
namespace {

// Node i: its colour in one buffer (vec4), its depth and link in another (uvec2), its triangle
// id in a third (uint).
constexpr uint64_t kColourBytes = 16, kLinkBytes = 8, kIdBytes = 4;
static_assert(kColourBytes + kLinkBytes + kIdBytes == FragmentLists::kBytesPerFragment);
constexpr uint64_t kInitialNodesPerPixel = 4;
constexpr uint64_t kHuge = uint64_t(1) << 32;
constexpr GLuint kEnd = 0xFFFFFFFFu;

// Every fragment that passes the depth and stencil tests (early, so that they happen before the
// stores) and lies in front of the opaque surfaces is pushed on its pixel's list. Past the capacity
// a fragment is only counted; the caller grows the buffers or splits the rectangle and draws again.
// `huge` records a count past 2^31, before the 32-bit counter could wrap.
constexpr const char* kBuildFragmentShader = R"(#version 450 core
layout(early_fragment_tests) in;
in vec4 shaded;
flat in uint triangle;
layout(binding = 0, r32ui) uniform coherent uimage2D heads;
layout(std430, binding = 1) buffer Counter { uint fragment_count; uint huge; };
layout(std430, binding = 2) writeonly buffer NodeColours { vec4 node_colours[]; };
layout(std430, binding = 3) writeonly buffer NodeLinks { uvec2 node_links[]; };  // depth, next
layout(std430, binding = 6) writeonly buffer NodeTriangles { uint node_triangles[]; };
layout(binding = 1) uniform sampler2D opaque_depth;
uniform bool test_opaque;  // the framebuffer's depth is not the opaque one: test here
uniform uint capacity;
void main() {
    if (test_opaque && gl_FragCoord.z >= texelFetch(opaque_depth, ivec2(gl_FragCoord.xy), 0).r)
        discard;
    uint node = atomicAdd(fragment_count, 1u);
    if (node >= 0x80000000u) huge = 1u;
    if (node >= capacity) return;
    node_colours[node] = shaded;
    node_triangles[node] = triangle;
    uint next = imageAtomicExchange(heads, ivec2(gl_FragCoord.xy), node);
    node_links[node] = uvec2(floatBitsToUint(gl_FragCoord.z), next);
}
)";

// Sorts each pixel's list by depth and blends it back to front onto the pixel, exactly as
// blending in the draw would (colour = alpha * source + (1 - alpha) * colour, the pixel's alpha
// kept). Lists of up to kLocal fragments are sorted in registers by insertion; longer ones are
// walked by repeated selection of the farthest remaining fragment: slower, never dropping one.
// Equal depths: the lower triangle id in front (the tie rule of every exact method:
// docs/robustness.md), whatever order the fragments were drawn or stored in.
constexpr const char* kResolveBody = R"(
layout(binding = 0, r32ui) uniform readonly uimage2D heads;
layout(binding = 1, rgba32f) uniform image2D target;
layout(std430, binding = 2) readonly buffer NodeColours { vec4 node_colours[]; };
layout(std430, binding = 3) readonly buffer NodeLinks { uvec2 node_links[]; };
layout(std430, binding = 6) readonly buffer NodeTriangles { uint node_triangles[]; };
const uint kEnd = 0xFFFFFFFFu;
const int kLocal = 128;
uint sorted_node[kLocal];
float sorted_depth[kLocal];
// Is (d, n) nearer than (e, m)?
bool nearer(float d, uint n, float e, uint m) {
    return d < e || (d == e && node_triangles[n] < node_triangles[m]);
}
vec3 over(vec3 c, vec4 fragment) { return fragment.a * fragment.rgb + (1.0 - fragment.a) * c; }
void main() {
    ivec2 pixel;
    if (!rectanglePixel(pixel)) return;
    uint head = imageLoad(heads, pixel).r;
    if (head == kEnd) return;
    int count = 0;
    for (uint n = head; n != kEnd; n = node_links[n].y) ++count;
    vec4 destination = imageLoad(target, pixel);
    vec3 c = destination.rgb;
    if (count <= kLocal) {
        int k = 0;
        for (uint n = head; n != kEnd; n = node_links[n].y, ++k) {
            float d = uintBitsToFloat(node_links[n].x);
            int j = k;
            while (j > 0 && nearer(d, n, sorted_depth[j - 1], sorted_node[j - 1])) {
                sorted_depth[j] = sorted_depth[j - 1];
                sorted_node[j] = sorted_node[j - 1];
                --j;
            }
            sorted_depth[j] = d;
            sorted_node[j] = n;
        }
        // Nearest first: blend from the back.
        for (int i = count - 1; i >= 0; --i) c = over(c, node_colours[sorted_node[i]]);
    } else {
        float last_depth = uintBitsToFloat(0x7F800000u);  // +infinity: nothing taken yet
        uint last_node = kEnd;
        for (int i = 0; i < count; ++i) {
            // The farthest fragment nearer than the last one taken.
            float best_depth = 0.0;
            uint best_node = kEnd;
            for (uint n = head; n != kEnd; n = node_links[n].y) {
                float d = uintBitsToFloat(node_links[n].x);
                if ((last_node == kEnd || nearer(d, n, last_depth, last_node)) &&
                    (best_node == kEnd || nearer(best_depth, best_node, d, n))) {
                    best_depth = d;
                    best_node = n;
                }
            }
            c = over(c, node_colours[best_node]);
            last_depth = best_depth;
            last_node = best_node;
        }
    }
    imageStore(target, pixel, vec4(c, destination.a));
}
)";

// The most nodes: within max_bytes, within the driver's largest storage block (the colours are
// the larger array), and addressable by the 32-bit counter and links.
uint64_t mostNodes(uint64_t max_bytes) {
    GLint64 block = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &block);
    const uint64_t bytes = max_bytes != 0 ? max_bytes : FragmentLists::kDefaultMaxBytes;
    return std::max<uint64_t>(
        1, std::min({uint64_t(std::max<GLint64>(block, 0)) / kColourBytes,
                     bytes / FragmentLists::kBytesPerFragment, uint64_t(0xFFFFFFFEu)}));
}

} // namespace

FragmentLists::FragmentLists(uint64_t max_bytes)
    : build_program_(linkProgram(kShadeVertexShader, kBuildFragmentShader)),
      resolve_program_(linkPixelProgram(kResolveBody)), max_nodes_(mostNodes(max_bytes)) {
    GLuint name = 0;
    glCreateBuffers(1, &name);
    counter_ = GlBuffer(name);
    glCreateBuffers(1, &name);
    tiles_ = GlBuffer(name);
    glNamedBufferStorage(counter_.get(), 2 * sizeof(GLuint), nullptr,
                         GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
}

void FragmentLists::allocate(uint64_t nodes) {
    while (glGetError() != GL_NO_ERROR) {
    } // only this call's errors count below
    GLuint name = 0;
    glCreateBuffers(1, &name);
    colours_ = GlBuffer(name);
    glNamedBufferStorage(colours_.get(), GLsizeiptr(nodes * kColourBytes), nullptr, 0);
    glCreateBuffers(1, &name);
    links_ = GlBuffer(name);
    glNamedBufferStorage(links_.get(), GLsizeiptr(nodes * kLinkBytes), nullptr, 0);
    glCreateBuffers(1, &name);
    triangles_ = GlBuffer(name);
    glNamedBufferStorage(triangles_.get(), GLsizeiptr(nodes * kIdBytes), nullptr, 0);
    if (glGetError() == GL_OUT_OF_MEMORY)
        throw std::runtime_error("the OpenGL driver cannot hold " + std::to_string(nodes) +
                                 " fragments (" + std::to_string(nodes * kBytesPerFragment >> 20) +
                                 " MiB)");
    capacity_ = nodes;
}

uint64_t FragmentLists::build(PixelRect rect, GLuint opaque_depth,
                              const std::function<void()>& draw) {
    const GLuint end = kEnd;
    const GLuint zero[2] = {0, 0};
    glClearTexSubImage(heads_.get(), 0, GLint(rect.x), GLint(rect.y), 0, GLsizei(rect.width),
                       GLsizei(rect.height), 1, GL_RED_INTEGER, GL_UNSIGNED_INT, &end);
    glNamedBufferSubData(counter_.get(), 0, sizeof(zero), zero);
    glBindImageTexture(0, heads_.get(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32UI);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, counter_.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, colours_.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, links_.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, triangles_.get());
    glProgramUniform1ui(build_program_.get(),
                        glGetUniformLocation(build_program_.get(), "capacity"), GLuint(capacity_));
    glProgramUniform1i(build_program_.get(),
                       glGetUniformLocation(build_program_.get(), "test_opaque"),
                       opaque_depth != 0);
    if (opaque_depth != 0)
        glBindTextureUnit(1, opaque_depth);
    glEnable(GL_SCISSOR_TEST);
    glScissor(GLint(rect.x), GLint(rect.y), GLsizei(rect.width), GLsizei(rect.height));
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glDisable(GL_BLEND);
    draw();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_SCISSOR_TEST);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    GLuint counts[2] = {0, 0};
    glGetNamedBufferSubData(counter_.get(), 0, sizeof(counts), counts);
    return counts[1] != 0 ? kHuge : counts[0];
}

FragmentLists::Result
FragmentLists::composite(const RenderTarget& target, PixelRect rect, GLuint opaque_depth,
                         const std::function<void()>& draw,
                         std::optional<std::span<const uint32_t>> tile_origins) {
    Result result;
    if (rect.empty())
        return result;
    if (target.width() != width_ || target.height() != height_) {
        heads_ = makeTexture(GL_R32UI, target.width(), target.height());
        width_ = target.width();
        height_ = target.height();
    }
    if (capacity_ == 0)
        allocate(
            std::min(max_nodes_, std::max<uint64_t>(rect.area() * kInitialNodesPerPixel, 1024)));
    std::vector<PixelRect> pending{rect};
    while (!pending.empty()) {
        const PixelRect r = pending.back();
        pending.pop_back();
        const uint64_t stored = build(r, opaque_depth, draw);
        ++result.passes;
        if (stored <= capacity_) {
            glBindImageTexture(0, heads_.get(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
            glBindImageTexture(1, target.colourTexture(), 0, GL_FALSE, 0, GL_READ_WRITE,
                               GL_RGBA32F);
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, colours_.get());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, links_.get());
            glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 6, triangles_.get());
            if (tile_origins)
                runPixelProgramOnTiles(resolve_program_.get(), r, *tile_origins, tiles_);
            else
                runPixelProgram(resolve_program_.get(), r);
            result.fragments += stored;
            continue;
        }
        if (stored <= max_nodes_) { // grow (a quarter more, for the frames to come) and redo
            allocate(std::min(max_nodes_, stored + stored / 4));
            pending.push_back(r);
            continue;
        }
        // More than any buffer holds: bands of rows (columns for a single row), each expected to
        // hold at most 3/4 of the largest buffer; a band still too full is split again.
        if (capacity_ < max_nodes_)
            allocate(max_nodes_);
        if (r.area() == 1)
            throw std::runtime_error("a pixel has more than " + std::to_string(max_nodes_) +
                                     " transparent fragments, more than the fragment lists may "
                                     "hold (--list-memory, and the driver's largest buffer)");
        const uint64_t per_band = std::max<uint64_t>(1, max_nodes_ * 3 / 4);
        const uint64_t wanted = (stored + per_band - 1) / per_band;
        const bool by_rows = r.height > 1;
        const uint32_t side = by_rows ? r.height : r.width;
        const uint32_t bands = uint32_t(std::clamp<uint64_t>(wanted, 2, side));
        for (uint32_t b = 0; b < bands; ++b) {
            const uint32_t from = uint32_t(uint64_t(side) * b / bands);
            const uint32_t to = uint32_t(uint64_t(side) * (b + 1) / bands);
            pending.push_back(by_rows ? PixelRect{r.x, r.y + from, r.width, to - from}
                                      : PixelRect{r.x + from, r.y, to - from, r.height});
        }
    }
    return result;
}

} // namespace vissort::detail
