// castVolume: the reference picture of a tetrahedral grid, one ray per pixel walked from cell to
// cell (the cell-walking ray caster of Garrity, "Raytracing irregular volume data", 1990, with
// Embree finding where each ray enters the grid: Wald, Woop, Benthin, Johnson, Ernst, SIGGRAPH
// 2014). Inside a tetrahedron the ray's entry and exit are where it crosses the planes of the
// faces it enters and leaves (Platis and Theoharis, "Fast ray-tetrahedron intersection using
// Plücker coordinates" give the same points; planes suffice here). The exit face names the next
// cell; a boundary face ends the walk, and the next boundary face the ray enters through (a
// concavity) starts another. Everything but finding the boundary faces is in double precision.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <thread>

#include "volume/cell_walk_ray_caster.h"

namespace vissort {
namespace detail {
namespace {

using BoundaryFace = CellWalkCaster::BoundaryFace;
using BoundsData = CellWalkCaster::BoundsData;

// What the intersection callback needs; Embree hands it the context pointer, so it comes first.
struct HitCollector {
    RTCIntersectContext context;
    Vec3 origin, direction;
    const TetGrid* grid;
    const std::vector<BoundaryFace>* boundary;
    std::vector<std::pair<double, uint32_t>>* hits; // (t, boundary face)
};

// Records every boundary face the double-precision ray meets through its inner side, edges
// included (a ray through an edge then enters by both faces; the walk skips the second).
void recordEntry(const RTCIntersectFunctionNArguments* args) {
    if (!args->valid[0])
        return;
    auto* collector = reinterpret_cast<HitCollector*>(args->context);
    const BoundaryFace& bf = (*collector->boundary)[args->primID];
    const Tet& tet = collector->grid->tets[bf.tet];
    const auto& points = collector->grid->points;
    const Vec3& a = points[tet[kTetFaceCorners[bf.face][0]]];
    const Vec3& b = points[tet[kTetFaceCorners[bf.face][1]]];
    const Vec3& c = points[tet[kTetFaceCorners[bf.face][2]]];
    const Vec3& o = collector->origin;
    const Vec3& d = collector->direction;
    const Vec3 normal = cross(b - a, c - a);
    const double along = dot(normal, d);
    if (!(along > 0))
        return; // leaving by it, or grazing it
    // Inside the triangle: the ray passes each directed edge on the inner side (or on it).
    constexpr double kSlack = -1e-12;
    const auto side = [&](const Vec3& p, const Vec3& q) {
        return dot(cross(p - o, q - o), d) / (length(p - o) * length(q - o) + 1e-300);
    };
    const double sab = side(a, b), sbc = side(b, c), sca = side(c, a);
    const bool inside = (sab >= kSlack && sbc >= kSlack && sca >= kSlack) ||
                        (sab <= -kSlack && sbc <= -kSlack && sca <= -kSlack);
    if (!inside)
        return;
    collector->hits->push_back({dot(normal, a - o) / along, args->primID});
}

void faceBounds(const RTCBoundsFunctionArguments* args) {
    const auto* data = static_cast<const BoundsData*>(args->geometryUserPtr);
    const BoundaryFace& bf = (*data->boundary)[args->primID];
    const Tet& tet = data->grid->tets[bf.tet];
    Bounds box;
    for (int k = 0; k < 3; ++k)
        box.add(data->grid->points[tet[kTetFaceCorners[bf.face][k]]]);
    *args->bounds_o = {float(box.min.x) - data->margin, float(box.min.y) - data->margin,
                       float(box.min.z) - data->margin, 0.0f,
                       float(box.max.x) + data->margin, float(box.max.y) + data->margin,
                       float(box.max.z) + data->margin, 0.0f};
}

} // namespace

Result<std::unique_ptr<CellWalkCaster>> CellWalkCaster::make(const TetGrid& grid) {
    using R = Result<std::unique_ptr<CellWalkCaster>>;
    Result<std::vector<TetNeighbours>> neighbours = faceNeighbours(grid);
    if (!neighbours)
        return R::failure(neighbours.error);
    RTCDevice device = nullptr;
    try {
        device = sharedEmbreeDevice();
    } catch (const std::exception& e) {
        return R::failure(e.what());
    }
    return R{std::unique_ptr<CellWalkCaster>(
                 new CellWalkCaster(grid, std::move(*neighbours.value), device)),
             {}};
}

CellWalkCaster::CellWalkCaster(const TetGrid& grid, std::vector<TetNeighbours> neighbours,
                               RTCDevice device)
    : grid_(grid), neighbours_(std::move(neighbours)), scene_(rtcNewScene(device)) {
    for (uint32_t t = 0; t < grid.tets.size(); ++t)
        for (uint8_t f = 0; f < 4; ++f)
            if (neighbours_[t][f] == kNoNeighbour)
                boundary_.push_back({t, f});
    const GridMeasures measures(grid);
    // Far more than a float box's rounding at the grid's scale.
    bounds_data_ = {
        &grid, &boundary_,
        float((length(measures.bounds.centre()) + 2 * measures.bounds.radius() + 1) * 0x1p-16)};
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, unsigned(boundary_.size()));
    rtcSetGeometryUserData(geometry, &bounds_data_);
    rtcSetGeometryBoundsFunction(geometry, faceBounds, nullptr);
    rtcSetGeometryIntersectFunction(geometry, recordEntry);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_.get(), geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_.get());
}

Image CellWalkCaster::render(const VolumeLaw& law, const Rgba& background,
                             const PixelRayTable& rays, unsigned thread_count,
                             uint64_t& segments) const {
    const TetGrid& grid = grid_;
    const std::vector<BoundaryFace>& boundary = boundary_;
    Image image;
    image.width = rays.width;
    image.height = rays.height;
    image.rgba.assign(std::size_t(rays.width) * rays.height * 4, 0.0f);
    std::atomic<uint32_t> next_row{0};
    std::atomic<uint64_t> segment_count{0};
    const auto work = [&] {
        std::vector<std::pair<double, uint32_t>> hits;
        HitCollector collector{};
        collector.grid = &grid;
        collector.boundary = &boundary;
        collector.hits = &hits;
        uint64_t walked_segments = 0;
        for (uint32_t py = next_row++; py < rays.height; py = next_row++) {
            for (uint32_t px = 0; px < rays.width; ++px) {
                const std::size_t pixel = std::size_t(py) * rays.width + px;
                const Vec3& o = rays.origin[pixel];
                const Vec3& d = rays.direction[pixel];
                const double t_low = rays.t_low[pixel], t_high = rays.t_high[pixel];
                hits.clear();
                rtcInitIntersectContext(&collector.context);
                collector.origin = o;
                collector.direction = d;
                RTCRayHit ray{};
                ray.ray.org_x = float(o.x);
                ray.ray.org_y = float(o.y);
                ray.ray.org_z = float(o.z);
                ray.ray.dir_x = float(d.x);
                ray.ray.dir_y = float(d.y);
                ray.ray.dir_z = float(d.z);
                ray.ray.tnear = 0;
                ray.ray.tfar = std::numeric_limits<float>::infinity();
                ray.ray.mask = 0xFFFFFFFF;
                ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
                rtcIntersect1(scene_.get(), &collector.context, &ray);
                std::sort(hits.begin(), hits.end());

                FrontToBack colour;
                double walked_to = -std::numeric_limits<double>::infinity();
                for (const auto& [t_hit, face] : hits) {
                    if (t_hit < walked_to)
                        continue; // a cell already walked through
                    uint32_t tet = boundary[face].tet;
                    // Every step moves forwards or ends the walk; the step limit only guards
                    // against a cycle of zero-length steps that rounding could make.
                    for (std::size_t steps = 0; steps <= grid.tets.size(); ++steps) {
                        const TetPlanes planes(grid, grid.tets[tet]);
                        const Crossing c = crossTet(planes, o, d);
                        if (c.exit_face < 0 || c.t_out < walked_to)
                            break;
                        const double from = std::max({c.t_in, t_low, walked_to});
                        const double to = std::min(c.t_out, t_high);
                        if (to > from) {
                            const double s_in = planes.scalarAt(o + d * from);
                            const double s_out = planes.scalarAt(o + d * to);
                            colour.add(law.segment(s_in, s_out, to - from));
                            ++walked_segments;
                        }
                        walked_to = std::max(walked_to, c.t_out);
                        tet = neighbours_[tet][c.exit_face];
                        if (tet == kNoNeighbour)
                            break;
                    }
                }
                colour.finish(background, &image.rgba[pixel * 4]);
            }
        }
        segment_count += walked_segments;
    };
    std::vector<std::thread> pool;
    for (unsigned i = 1; i < thread_count; ++i)
        pool.emplace_back(work);
    work();
    for (std::thread& t : pool)
        t.join();
    segments += segment_count;
    return image;
}

} // namespace detail

Status validateVolumeSettings(const TetGrid& grid, const VolumeSettings& settings) {
    if (grid.scalars.empty())
        return Status::failure(grid.name +
                               " has no point scalars to render (volume rendering maps a "
                               "scalar per point through the transfer function)");
    if (Status tf = validateTransferFunction(settings.transfer); !tf)
        return tf;
    if (!std::isfinite(settings.density) || settings.density < 0)
        return Status::failure("the density must be a finite number >= 0");
    const Rgba& bg = settings.background;
    for (const float c : {bg.r, bg.g, bg.b, bg.a})
        if (!(c >= 0 && c <= 1))
            return Status::failure("the background's channels must be within [0, 1]");
    return Status::ok();
}

Result<Image> castVolume(const TetGrid& grid, const VolumeSettings& settings,
                         const ViewProjection& view, unsigned thread_count) {
    if (Status valid = validateVolumeSettings(grid, settings); !valid)
        return Result<Image>::failure(valid.error);
    Result<std::unique_ptr<detail::CellWalkCaster>> caster = detail::CellWalkCaster::make(grid);
    if (!caster)
        return Result<Image>::failure(caster.error);
    const detail::GridMeasures measures(grid);
    uint64_t segments = 0;
    return {(*caster.value)
                ->render(detail::VolumeLaw(measures, settings), settings.background,
                         detail::PixelRayTable(view),
                         thread_count == 0 ? std::max(1u, std::thread::hardware_concurrency())
                                           : thread_count,
                         segments),
            {}};
}

} // namespace vissort
