#pragma once
// Occlusion oracles that answer from triangles seen through a camera: the backends.

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "vissort/camera.h"
#include "vissort/geometry.h"
#include "vissort/occlusion_oracle.h"

namespace vissort {

/// Depth tolerance, in units of the depth d (camera.h): a fragment is "behind" only when its
/// depth exceeds the stored depth by more than this, so coplanar, touching and shared-edge
/// surfaces never count as occluding each other. Every oracle's default.
inline constexpr float kDepthTolerance = 1.0f / (1 << 20);

/// The tolerance for exact blending (transparency_renderer.h): negative, so that a fragment
/// counts as behind unless it is in front by more than 2^-16. Surfaces whose depths come that
/// close anywhere then occlude each other both ways: a cycle, which the renderer composites per
/// pixel with the GPU's own depths. The order is thus exact wherever the oracle's depths and the
/// GPU's differ by less than 2^-16, where near ties of the default tolerance could swap layers.
inline constexpr float kBlendingDepthTolerance = -1.0f / (1 << 16);

/// How a rasterizing oracle samples a triangle.
enum class RasterMode {
    /// Pixel centres, the top-left rule, the depth at the centre: answers that match the
    /// exact ray-cast reference up to sampling. For visibility ordering and transparency.
    exact,
    /// Every pixel whose square the triangle touches; draws write the nearest depth the plane
    /// takes over the square and queries test the farthest. It can only add "behind" answers,
    /// never remove one: for collision culling, which must not miss a contact.
    conservative,
};

class GeometryOracle : public OcclusionOracle {
public:
    /// Binds what later primitive ids refer to: primitive i is the triangles
    /// primitives[i] of positions, seen through view. The three must stay alive and unchanged
    /// until the next bind (the oracle keeps references, or copies what it needs).
    /// Also clears the depth buffer. Call again after positions change (a new frame).
    virtual void bind(const TrianglePositions& positions, const ViewProjection& view,
                      std::span<const PrimitiveRange> primitives) = 0;

    /// Sets the depth tolerance of later queries: anyBehind is true when some fragment's depth
    /// exceeds the stored depth + tolerance (a float sum). kDepthTolerance until set; negative
    /// values make near ties count as occlusion (kBlendingDepthTolerance). Must be finite.
    void setDepthTolerance(float tolerance) { depth_tolerance_ = tolerance; }
    float depthTolerance() const { return depth_tolerance_; }

protected:
    float depth_tolerance_ = kDepthTolerance;
};

enum class OracleKind {
    cpu,            // "cpu": the tiled CPU rasterizer (fast_cpu_oracle.h), the default
    cpu_reference,  // "cpu-reference": the plain rasterizer that defines the cpu answers
                    // (cpu_oracle.h); cpu gives identical answers, faster
    exact,          // "exact": ray casting at pixel centres in double (exact_oracle.h)
    gl,             // "gl": OpenGL occlusion queries through headless EGL (gl_oracle.h)
};

/// Parses "cpu", "cpu-reference", "exact" or "gl"; returns false when the name is unknown.
bool parseOracleKind(const std::string& name, OracleKind& kind);
const char* oracleName(OracleKind kind);

/// The oracle of that kind sampling in that mode. The exact and gl oracles have no conservative
/// mode: asking for one throws std::invalid_argument. The gl oracle uses the process's shared
/// context (GlContext::shared); when there is none, or vissort was built without OpenGL, it
/// throws std::runtime_error with a one-line message naming what is missing.
std::unique_ptr<GeometryOracle> makeOracle(OracleKind kind, RasterMode mode = RasterMode::exact);

/// The rasterizing oracles that `vissort bench oracle` compares (the exact oracle ray-casts every
/// pixel when bound, so it is a reference, not a contender).
std::vector<OracleKind> benchmarkedOracles();

} // namespace vissort
