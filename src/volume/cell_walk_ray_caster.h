#pragma once
// The cell-walking ray caster prepared for one grid: its face neighbours, its boundary faces and
// Embree's tree over them, built once and used for every frame (castVolume makes one per call;
// VolumeRenderer keeps one). Internal to src/volume/.

#include <memory>
#include <vector>

#include "exact/embree_device.h"
#include "volume/tet_crossing.h"
#include "volume/volume_law.h"

namespace vissort::detail {

class CellWalkCaster {
public:
    /// Fails (one line) on a grid that is not conforming, or when no Embree device can be made.
    static Result<std::unique_ptr<CellWalkCaster>> make(const TetGrid& grid);

    /// The picture of the rays of `rays` through the grid by `law` over `background`, on
    /// thread_count threads (at least 1; the picture is the same for any); adds the segments
    /// composited to `segments`.
    Image render(const VolumeLaw& law, const Rgba& background, const PixelRayTable& rays,
                 unsigned thread_count, uint64_t& segments) const;

    /// A face of the grid's boundary: its tetrahedron and which face.
    struct BoundaryFace {
        uint32_t tet;
        uint8_t face;
    };
    /// What Embree's bounds callback reads.
    struct BoundsData {
        const TetGrid* grid;
        const std::vector<BoundaryFace>* boundary;
        float margin;
    };

private:
    CellWalkCaster(const TetGrid& grid, std::vector<TetNeighbours> neighbours, RTCDevice device);

    const TetGrid& grid_;
    std::vector<TetNeighbours> neighbours_;
    std::vector<BoundaryFace> boundary_;
    BoundsData bounds_data_;
    EmbreeScene scene_;
};

} // namespace vissort::detail
