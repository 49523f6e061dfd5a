#pragma once
// Occlusion oracles that answer from triangles seen through a camera: the backends.
//
// Layer: vissort::geometry (the package's `order` component; docs/architecture.md).

#include <span>

#include "vissort/camera.h"
#include "vissort/geometry.h"
#include "vissort/occlusion_oracle.h"

namespace vissort {

/// The default depth tolerance, 0: "behind" is the exact fragment model's (docs/robustness.md,
/// "The exact model"). A fragment is behind when the pixel centre's ray meets it strictly farther
/// than something drawn there, decided exactly on the float corners: touching, coplanar and
/// shared-edge surfaces never count as occluding each other, and nothing else is a tie. The
/// `gl` oracle, which cannot decide inside the driver, counts what it cannot decide as behind.
inline constexpr float kDepthTolerance = 0.0f;

class GeometryOracle : public OcclusionOracle {
public:
    /// Binds what later primitive ids refer to: primitive i is the triangles
    /// primitives[i] of positions, seen through view. The three must stay alive and unchanged
    /// until the next bind (the oracle keeps references, or copies what it needs).
    /// Also clears the depth buffer. Call again after positions change (a new frame).
    virtual void bind(PositionsView positions, const ViewProjection& view,
                      std::span<const PrimitiveRange> primitives) = 0;

    /// bind, for a caller whose positions and view are those of the last bind and have not
    /// changed since (multi-stage ordering binds each group of a frame after the frame's
    /// objects): an oracle may reuse per-triangle work of that bind. The same answers as bind.
    virtual void rebind(PositionsView positions, const ViewProjection& view,
                        std::span<const PrimitiveRange> primitives) {
        bind(positions, view, primitives);
    }

    /// Sets the depth tolerance of later queries: 0 (kDepthTolerance, the default) is the exact
    /// rule above. Any other t is an approximate rule, in float with the GPU's coverage (the
    /// top-left rule): anyBehind is true when some fragment exceeds the stored depth + t, so a
    /// negative t (kBlendingDepthTolerance, the renderer's rule without its check) counts near
    /// ties both ways, and a positive one counts them neither way. Must be finite.
    void setDepthTolerance(float tolerance) { depth_tolerance_ = tolerance; }
    float depthTolerance() const { return depth_tolerance_; }

protected:
    float depth_tolerance_ = kDepthTolerance;
};

} // namespace vissort
