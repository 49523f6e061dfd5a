#pragma once
// An occlusion oracle for primitives that are closed convex polyhedra (a grid's cells), over
// another oracle: a draw rasterizes only the faces turned towards the eye, a query only those
// turned away. Where a ray crosses a convex cell it enters by a front face and leaves by a back
// one, so the front faces alone leave the nearest depths a draw of every face leaves, and the
// back faces alone hold the farthest fragment a query can find behind the stored depths: the
// same answers for about half the rasterizing (the fronts' and the backs' projections both tile
// the cell's silhouette, their shared silhouette edges covered alike by the top-left rule). A
// face whose facing is too close to call in double, and every face of a cell reaching the near
// plane (clipped there, its fronts no longer cover its pixels), is drawn and queried both ways,
// which is what the whole cell would do. Internal to src/volume/.

#include <cstdint>
#include <vector>

#include "vissort/geometry_oracle.h"

namespace vissort::detail {

class ConvexFacingOracle final : public GeometryOracle {
public:
    /// inner answers the split primitives (its depth tolerance is the one used) and must outlive
    /// this oracle.
    explicit ConvexFacingOracle(GeometryOracle& inner) : inner_(inner) {}

    /// Every range must be a closed convex polyhedron's faces (its corners' mean inside it).
    void bind(PositionsView positions, const ViewProjection& view,
              std::span<const PrimitiveRange> primitives) override;

    uint32_t primitiveCount() const override { return count_; }
    void clear() override { inner_.clear(); }
    void draw(uint32_t primitive) override { inner_.draw(2 * primitive); }
    bool anyBehind(uint32_t primitive) override { return inner_.anyBehind(2 * primitive + 1); }

    /// Faces bound on the last bind: drawn (fronts) and queried (backs), for tests and benches.
    uint64_t frontFaces() const { return front_faces_; }
    uint64_t backFaces() const { return back_faces_; }

private:
    GeometryOracle& inner_;
    uint32_t count_ = 0;
    TrianglePositions split_;            // each primitive's fronts, then its backs
    std::vector<PrimitiveRange> ranges_; // primitive p: 2p its fronts, 2p + 1 its backs
    uint64_t front_faces_ = 0, back_faces_ = 0;
    std::vector<uint8_t> facing_; // each bound face's: front, back or both
};

} // namespace vissort::detail
