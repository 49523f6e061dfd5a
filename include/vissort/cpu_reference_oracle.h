#pragma once
// The reference CPU depth rasterizer as an occlusion oracle. Plain rather than fast: a faster
// rasterizer must give the same answers, and the same depth buffer, bit for bit. Its answers
// under the default depth tolerance (0) are the exact fragment model's (docs/robustness.md, "The
// exact model"), found with a float rasterizer whose every uncertain call goes to exact
// arithmetic. The rules:
//
//  1. Transform, once per bind: clip = M (x, y, z, 1) in double, with M = projection_matrix * view
//     (column-major; each entry and each clip coordinate summed in index order 0..3, no FMA).
//  2. Clip in homogeneous space (Sutherland-Hodgman), planes in this order: z >= 0, z <= w,
//     x >= -G w, x <= G w, y >= -G w, y <= G w with the guard band G = 32; keep a vertex when its
//     signed distance is >= 0; cut an edge at p + t (q - p), t = dist(p) / (dist(p) - dist(q)),
//     where p is the lexicographically smaller endpoint in (x, y, z, w), so shared edges are cut
//     identically. Nothing is drawn when a coordinate is non-finite or a result has w <= 0.
//  3. Fan the polygon out from its first vertex: triangles (p0, p_i, p_i+1), i = 1..n-2.
//  4. Screen: sx = (x / w + 1) * 0.5 * width, sy = (1 - y / w) * 0.5 * height (row 0 on top),
//     d = z / w. Snap sx and sy to 24.8 fixed point: llround(s * 256).
//  5. Coverage: doubled area A = (x1 - x0)(y2 - y0) - (y1 - y0)(x2 - x0) in int64_t; A < 0 swaps
//     vertices 1 and 2 (both windings are drawn). Edge i runs from vertex i to vertex
//     (i + 1) % 3, E_i(p) = (xj - xi)(py - yi) - (yj - yi)(px - xi); pixel (px, py) is sampled at
//     its centre (256 px + 128, 256 py + 128). The pixel range is the snapped box grown by one
//     sub-pixel unit and the bind's screen error (screenErrorsOf in src/raster/cpu_rasterizer.h:
//     the rounding of the transform, the divide and the pixel rays, from the coordinates' size
//     against the near plane).
//     - The exact rule (tolerance 0): a centre with every E_i > m is covered, m the set-up's
//       margin (2 L + 4 plus the screen error's share, L the sum of |dx| + |dy| over its edges:
//       more than snapping and that error can move an edge function), so it lies inside the
//       unsnapped triangle; one with some E_i < -m is not; every other one (a band pixel, at
//       most a few hundredths of a pixel from an edge) is covered when the exact model says the
//       original triangle covers it. A triangle of no snapped area (A == 0) has only band pixels,
//       near its longest edge. So each triangle's fragments are exactly the model's.
//     - The blending rule (a negative tolerance) and the GPU: A == 0 draws nothing; covered when
//       every E_i > 0, or == 0 on a top edge (dy == 0, dx > 0: horizontal, interior below) or a
//       left edge (dy < 0: the interior to its right). Y points down. A mesh tiling a region
//       covers each centre once.
//  6. Depth: the plane through the fan triangle's unsnapped (sx, sy, d), vertices in the order of
//     rule 5: e1 = v1 - v0, e2 = v2 - v0, det = e1x e2y - e2x e1y, ddx = (e1d e2y - e2d e1y) / det,
//     ddy = (e2d e1x - e1d e2x) / det, its snap slack s = max(|ddx|, |ddy|) 2^-8 (snapping moves
//     a vertex by at most 2^-9 pixels per axis: what the blending rule's extrapolation may add;
//     s is what OpenGL's polygon offset applies: gl_oracle.h), and its error bound e
//     (fragmentError: the plane's rounding, which grows with a sliver's conditioning, the screen
//     error along the slopes, and the float rounding of rule 7, 2^-24). Where det == 0 or s is
//     not finite: ddx = ddy = 0, d0 the middle of the vertex depths, s half their range, e
//     infinite. The value at the centre (cx, cy) = (px + 0.5, py + 0.5):
//     c = d0 + ddx (cx - x0) + ddy (cy - y0), all in double. No clamping.
//  7. Fragments and the depth buffer: one float per pixel, row-major from the top row, cleared to
//     +infinity. The exact rule: a fragment is float(c); draw writes it when frag < stored, and
//     every draw raises the pixel's error to the largest e drawn there since the clear. anyBehind
//     compares each fragment with the stored depth within the band B = e + the pixel's error
//     (decisionBand, with the float sums' rounding): frag > stored + B is exactly behind (done),
//     frag <= stored - B exactly not; in between, after every fragment of the query, the exact
//     model decides: is some triangle drawn since the clear at that centre strictly nearer than
//     the query's? (GeometryOracle's rule: strictly farther, ties never.)
//     The blending rule: a draw's fragment is float(c - s) and a query's float(c + s)
//     (exactFragmentOffset), and anyBehind is true when some fragment has frag > stored + t (float
//     sum, t the negative tolerance), so near ties count both ways. docs/robustness.md, "Depth
//     precision".
//
// Viewports up to kMaxViewportSize = 65536 on a side keep every edge function exact in int64_t.
//
// Layer: vissort::raster (the package's `order` component; docs/architecture.md).

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "vissort/geometry_oracle.h"

namespace vissort::detail {
class DepthArbiter; // src/raster/depth_arbiter.h
} // namespace vissort::detail

namespace vissort {

/// What the oracle did since bind (or resetStats), for benchmarks and tests.
struct CpuReferenceOracleStats {
    uint64_t draws = 0;            // draw calls
    uint64_t queries = 0;          // anyBehind calls
    uint64_t fragments_drawn = 0;  // covered pixel centres visited by draw
    uint64_t fragments_tested = 0; // covered pixel centres visited by anyBehind (stops early)
    uint64_t arbitrations = 0;     // (fragment, pixel) pairs the exact model decided (rule 7)
};

class CpuReferenceOracle final : public GeometryOracle {
public:
    CpuReferenceOracle();
    ~CpuReferenceOracle() override;

    /// See GeometryOracle::bind. Copies the primitives and the clip-space corners it needs.
    /// The view's width and height must be in [1, 65536]; every range must lie within positions.
    void bind(PositionsView positions, const ViewProjection& view,
              std::span<const PrimitiveRange> primitives) override;

    uint32_t primitiveCount() const override { return uint32_t(primitives_.size()); }
    void clear() override;
    /// Depth test LESS, writes on. primitive must be < primitiveCount().
    void draw(uint32_t primitive) override;
    /// True when a fragment lies behind the stored depth (rule 7). primitive must be <
    /// primitiveCount(). Leaves the buffer unchanged.
    bool anyBehind(uint32_t primitive) override;

    /// The depth buffer: width() * height() floats, row-major from the top row.
    std::span<const float> depthBuffer() const { return depth_; }
    uint32_t width() const { return width_; }
    uint32_t height() const { return height_; }

    const CpuReferenceOracleStats& stats() const { return stats_; }
    void resetStats() { stats_ = {}; }

private:
    struct ClipCorner {
        double x, y, z, w;
    };

    /// The exact rule's draw and query (rules 5-7).
    void drawExact(uint32_t primitive);
    bool anyBehindExact(uint32_t primitive);
    /// Whether triangle's fragment at pixel (px, py) lies strictly behind one of a triangle
    /// drawn since the clear, by the exact model; `candidates` are the drawn triangles whose
    /// bounds meet the triangle's (arbitrationCandidates), thinned here of those never nearer.
    bool behindSomethingDrawn(uint32_t triangle, uint32_t px, uint32_t py,
                              std::vector<uint32_t>& candidates);
    /// The triangles drawn since the clear, other than triangle, whose pixel bounds meet its own;
    /// with drop_copies, one of each set of copies and none of triangle's own.
    std::vector<uint32_t> arbitrationCandidates(uint32_t triangle, bool drop_copies);

    uint32_t width_ = 0, height_ = 0;
    std::vector<PrimitiveRange> primitives_;
    std::vector<ClipCorner> corners_; // 3 per triangle, clip space
    std::vector<float> depth_;
    std::vector<float> error_; // per pixel, the largest error bound drawn there since the clear
    // What the exact rule needs: the world corners (the bind's view of them), the exact model
    // and its arbitration, the bind's screen errors, each triangle's pixel bounds (x_min > x_max
    // when it has none; current where its stamp is the bind's number, made by boundsOf on first
    // need), and the primitives drawn since the clear (each once).
    PositionsView positions_;
    std::unique_ptr<detail::DepthArbiter> arbiter_;
    double screen_position_error_ = 0, screen_depth_error_ = 0; // detail::ScreenErrors
    struct PixelBounds {
        int32_t x_min, x_max, y_min, y_max;
    };
    std::vector<PixelBounds> triangle_bounds_;
    std::vector<uint32_t> bounds_stamps_;
    uint32_t bind_number_ = 0;
    const PixelBounds& boundsOf(uint32_t triangle);
    std::vector<uint32_t> drawn_;
    std::vector<uint8_t> is_drawn_;
    CpuReferenceOracleStats stats_;
};

} // namespace vissort
