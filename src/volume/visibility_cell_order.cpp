// VisibilityCellOrder: Vis-sort at cell level (Govindaraju et al., I3D 2005, applied to the
// cells of a grid as the paper proposes): each tetrahedron is one primitive of its four faces,
// ordered by the scene orderer's occlusion queries with coherence from frame to frame; a cell is
// drawn by its front faces and queried by its back faces (ConvexFacingOracle).
#include "volume/cell_orders.h"

namespace vissort::detail {

Result<std::unique_ptr<VisibilityCellOrder>> VisibilityCellOrder::make(const TetGrid& grid,
                                                                       OracleKind kind) {
    using R = Result<std::unique_ptr<VisibilityCellOrder>>;
    Result<std::vector<TetNeighbours>> neighbours = faceNeighbours(grid);
    if (!neighbours)
        return R::failure(neighbours.error);
    Result<std::unique_ptr<GeometryOracle>> oracle = makeOracle(kind);
    if (!oracle)
        return R::failure(oracle.error);
    return {std::unique_ptr<VisibilityCellOrder>(new VisibilityCellOrder(
                grid, std::move(*neighbours.value), std::move(*oracle.value))),
            {}};
}

namespace {

// Neighbouring cells share faces: drawn once as the back of one and once as the front of the
// other, with their corners in other orders, so their depths tie to within a few units in the
// last place. The exact rule (tolerance 0) decides every such tie exactly, which costs most of
// a frame; cells' interiors are disjoint, so a tie is always "not behind", and a tolerance above
// float noise answers it so in float, without the exact model. What the float rule can
// miss: a cell behind another by less than the tolerance at every pixel they share, and pixels
// where the rasterizer's coverage (the top-left rule on float corners) and the exact crossing of
// the compositor disagree, next to a silhouette edge. Either way the rays there cross the cells
// over very short segments: the tests hold vissort to 1/255 against brute force on every frame
// (docs/volume.md, "Exactness").
constexpr float kCellDepthTolerance = 1e-6f;

} // namespace

std::vector<PrimitiveRange> cellRanges(std::size_t cells) {
    std::vector<PrimitiveRange> ranges(cells);
    for (uint32_t c = 0; c < cells; ++c)
        ranges[c] = {4 * c, 4};
    return ranges;
}

TrianglePositions cellFaces(const TetGrid& grid) {
    TrianglePositions faces;
    faces.resize(4 * grid.tets.size());
    std::size_t corner = 0;
    for (const Tet& tet : grid.tets)
        for (int f = 0; f < 4; ++f)
            for (int k = 0; k < 3; ++k, ++corner) {
                const Vec3& p = grid.points[tet[kTetFaceCorners[f][k]]];
                faces.x[corner] = float(p.x);
                faces.y[corner] = float(p.y);
                faces.z[corner] = float(p.z);
            }
    return faces;
}

VisibilityCellOrder::VisibilityCellOrder(const TetGrid& grid, std::vector<TetNeighbours> neighbours,
                                         std::unique_ptr<GeometryOracle> oracle)
    : grid_(grid), neighbours_(std::move(neighbours)), faces_(cellFaces(grid)),
      cells_(cellRanges(grid.tets.size())), oracle_(std::move(oracle)), facing_(*oracle_),
      orderer_(cells_, uint32_t(4 * grid.tets.size()), OrderLevel::object, facing_) {
    oracle_->setDepthTolerance(kCellDepthTolerance);
}

const FrameOrder& VisibilityCellOrder::order(const ViewProjection& view) {
    // Vis-sort starts from a list the shared faces agree with (each orders its two cells exactly,
    // by the side the eye is on: MPVO's rule), otherwise in last frame's order (coherence: the
    // cells across a concavity, which no face orders), or on the first frame the cells'
    // centres' (on graded grids the depth key, the nearest corner, misorders large cells against
    // the small ones they hold). The queries then find and mend what that list has wrong; where
    // it has nothing wrong, they cost one a cell (pass 1 finds the whole list monotone).
    // docs/volume.md, "Speed".
    if (first_frame_)
        preferred_ = centroidOrder(grid_, view);
    else
        preferred_.swap(frame_.order);
    orderer_.seed(faceConsistentOrder(grid_, neighbours_, view, preferred_).order);
    first_frame_ = false;
    orderer_.orderFrame(faces_, view, frame_);
    return frame_;
}

} // namespace vissort::detail
