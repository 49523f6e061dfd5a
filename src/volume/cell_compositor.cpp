// Compositing cell segments: a cell's pixels are the centres inside its projected box whose
// rays cross it (tet_crossing.h), visited band of rows by band on worker threads (each band's
// pixels are composited in the order, whatever the other bands do). Cells in a cycle, and every
// cell for lists, go through per-pixel lists: (pixel, depth, colour) gathered, sorted, composited.
#include "volume/cell_compositor.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <mutex>
#include <thread>

namespace vissort::detail {
namespace {

// The pixels whose centres a cell's projection may cover: inclusive ranges, conservative by a
// pixel (the crossing test at each centre decides), and the projected corners, from which each
// row's span is cut (hull: false when a corner is at or behind the eye plane, where corners bound
// nothing: every pixel of the box is then tested).
struct PixelBox {
    int32_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
    bool hull = false;
    float corner_x[4] = {}, corner_y[4] = {};

    // The columns [first, last] of row y whose centres lie in the corners' convex hull, widened
    // by kHullMargin pixels (the corners are floats; the crossing test decides exactly): on a
    // horizontal line the hull spans the crossings of the six segments between the corners.
    void rowSpan(int32_t y, int32_t& first, int32_t& last) const {
        first = x0;
        last = x1;
        if (!hull)
            return;
        constexpr float kHullMargin = 1e-2f;
        const float centre = float(y) + 0.5f;
        float low = 1e30f, high = -1e30f;
        for (int a = 0; a < 4; ++a)
            for (int b = a + 1; b < 4; ++b) {
                const float ya = corner_y[a], yb = corner_y[b];
                if ((ya > centre + kHullMargin && yb > centre + kHullMargin) ||
                    (ya < centre - kHullMargin && yb < centre - kHullMargin))
                    continue; // the segment is wholly above or below the row
                float xa = corner_x[a], xb = corner_x[b];
                if (std::abs(yb - ya) > kHullMargin) { // where it crosses, clamped to it
                    const float u = std::clamp((centre - ya) / (yb - ya), 0.0f, 1.0f);
                    xa = xb = corner_x[a] + u * (corner_x[b] - corner_x[a]);
                }
                low = std::min({low, xa, xb});
                high = std::max({high, xa, xb});
            }
        if (!(low <= high)) {
            last = first - 1; // the row misses the hull
            return;
        }
        first = std::max(x0, int32_t(std::ceil(low - 0.5f - kHullMargin)));
        last = std::min(x1, int32_t(std::floor(high - 0.5f + kHullMargin)));
    }
};

PixelBox cellBox(const TetGrid& grid, const Tet& tet, const ViewProjection& view) {
    ScreenExtent extent;
    PixelBox box;
    for (int k = 0; k < 4; ++k) {
        const Vec3& p = grid.points[tet[k]];
        extent.add(view, p);
        const std::array<double, 4> clip = view.toClip(p);
        box.corner_x[k] = float((clip[0] / clip[3] + 1) * 0.5 * view.width);
        box.corner_y[k] = float((1 - clip[1] / clip[3]) * 0.5 * view.height);
    }
    if (extent.wraps)
        return {0, 0, int32_t(view.width) - 1, int32_t(view.height) - 1}; // the whole picture
    const auto clamp = [](double v, uint32_t size) {
        return int32_t(std::clamp(v, -1.0, double(size)));
    };
    box.x0 = clamp(std::floor(extent.low_x - 0.5) - 1, view.width);
    box.y0 = clamp(std::floor(extent.low_y - 0.5) - 1, view.height);
    box.x1 =
        std::min(clamp(std::ceil(extent.high_x - 0.5) + 1, view.width), int32_t(view.width) - 1);
    box.y1 =
        std::min(clamp(std::ceil(extent.high_y - 0.5) + 1, view.height), int32_t(view.height) - 1);
    box.hull = true;
    return box;
}

// A segment held in a per-pixel list.
struct ListSegment {
    uint32_t pixel;
    double depth;
    SegmentColour colour;
};

struct Band {
    uint32_t y0, y1; // rows [y0, y1)
};

class BandCompositor {
public:
    BandCompositor(const CompositeJob& job, Band band)
        : job_(job), band_(band), colours_(std::size_t(band.y1 - band.y0) * job.view.width) {}

    // Calls visit(pixel, from, to, planes) for each pixel of the band whose ray crosses cell c.
    template <class Visit> void forEachSegment(uint32_t c, const PixelBox& box, Visit&& visit) {
        const int32_t y_first = std::max<int32_t>(box.y0, int32_t(band_.y0));
        const int32_t y_last = std::min<int32_t>(box.y1, int32_t(band_.y1) - 1);
        if (y_first > y_last || box.x0 > box.x1)
            return;
        const TetPlanes planes(job_.grid, job_.grid.tets[c]);
        // Every ray of a perspective view leaves the eye, and every ray of an orthographic one
        // runs along the view: that half of each plane's crossing is the cell's, computed once
        // (the same bits as per pixel).
        double numerator[4], along[4];
        for (int f = 0; f < 4; ++f) {
            numerator[f] = planes.offset[f] - dot(planes.normal[f], job_.rays.origin[0]);
            along[f] = dot(planes.normal[f], job_.rays.direction[0]);
        }
        // The pixel loop once for each kind of view, so that the choice is not made per pixel.
        const auto walk = [&]<bool kSharedOrigin>() {
            for (int32_t y = y_first; y <= y_last; ++y) {
                int32_t x_first = 0, x_last = -1;
                box.rowSpan(y, x_first, x_last);
                for (int32_t x = std::max(x_first, 0); x <= x_last; ++x) {
                    const std::size_t pixel = std::size_t(y) * job_.view.width + uint32_t(x);
                    for (int f = 0; f < 4; ++f) {
                        if constexpr (kSharedOrigin)
                            along[f] = dot(planes.normal[f], job_.rays.direction[pixel]);
                        else
                            numerator[f] =
                                planes.offset[f] - dot(planes.normal[f], job_.rays.origin[pixel]);
                    }
                    const Crossing crossing = crossPlanes(numerator, along);
                    const double from = std::max(crossing.t_in, job_.rays.t_low[pixel]);
                    const double to = std::min(crossing.t_out, job_.rays.t_high[pixel]);
                    if (to > from)
                        visit(pixel, from, to, planes);
                }
            }
        };
        if (job_.view.projection == Projection::perspective)
            walk.template operator()<true>();
        else
            walk.template operator()<false>();
    }

    SegmentColour segmentColour(std::size_t pixel, double from, double to,
                                const TetPlanes& planes) const {
        const Vec3& o = job_.rays.origin[pixel];
        const Vec3& d = job_.rays.direction[pixel];
        return job_.law.segment(planes.scalarAt(o + d * from), planes.scalarAt(o + d * to),
                                to - from);
    }

    void composite(uint32_t c, const PixelBox& box) {
        forEachSegment(c, box,
                       [&](std::size_t pixel, double from, double to, const TetPlanes& planes) {
                           local(pixel).add(segmentColour(pixel, from, to, planes));
                           ++segments_;
                       });
    }

    void gather(uint32_t c, const PixelBox& box) {
        forEachSegment(
            c, box, [&](std::size_t pixel, double from, double to, const TetPlanes& planes) {
                list_.push_back({uint32_t(pixel), from, segmentColour(pixel, from, to, planes)});
            });
    }

    // Composites the gathered segments, each pixel's by depth, and empties the list.
    void compositeList() {
        std::sort(list_.begin(), list_.end(), [](const ListSegment& a, const ListSegment& b) {
            return a.pixel != b.pixel ? a.pixel < b.pixel : a.depth < b.depth;
        });
        for (const ListSegment& s : list_)
            local(s.pixel).add(s.colour);
        segments_ += list_.size();
        list_segments_ += list_.size();
        list_.clear();
    }

    void finish(Image& image) const {
        for (std::size_t i = 0; i < colours_.size(); ++i)
            colours_[i].finish(job_.background,
                               &image.rgba[(std::size_t(band_.y0) * job_.view.width + i) * 4]);
    }

    uint64_t segments() const { return segments_; }
    uint64_t listSegments() const { return list_segments_; }

private:
    FrontToBack& local(std::size_t pixel) {
        return colours_[pixel - std::size_t(band_.y0) * job_.view.width];
    }

    const CompositeJob& job_;
    Band band_;
    std::vector<FrontToBack> colours_;
    std::vector<ListSegment> list_;
    uint64_t segments_ = 0, list_segments_ = 0;
};

// Runs work(band) over bands of rows on the job's threads, then sums the bands' counts.
template <class Work>
Image runBands(const CompositeJob& job, VolumeFrameStats& stats, Work&& work) {
    Image image{job.view.width, job.view.height,
                std::vector<float>(std::size_t(job.view.width) * job.view.height * 4)};
    // Several bands a thread, so that a band dense with cells does not hold the others up.
    const uint32_t band_count =
        std::min<uint32_t>(job.view.height, std::max(1u, job.thread_count) * 8);
    std::atomic<uint32_t> next{0};
    std::mutex sum;
    const auto run = [&] {
        for (uint32_t b = next++; b < band_count; b = next++) {
            const Band band{uint32_t(uint64_t(job.view.height) * b / band_count),
                            uint32_t(uint64_t(job.view.height) * (b + 1) / band_count)};
            BandCompositor compositor(job, band);
            work(compositor);
            compositor.finish(image);
            const std::lock_guard lock(sum);
            stats.segments += compositor.segments();
            stats.list_segments += compositor.listSegments();
        }
    };
    std::vector<std::thread> threads;
    for (unsigned i = 1; i < job.thread_count; ++i)
        threads.emplace_back(run);
    run();
    for (std::thread& t : threads)
        t.join();
    return image;
}

std::vector<PixelBox> cellBoxes(const CompositeJob& job) {
    std::vector<PixelBox> boxes(job.grid.tets.size());
    for (std::size_t c = 0; c < boxes.size(); ++c)
        boxes[c] = cellBox(job.grid, job.grid.tets[c], job.view);
    return boxes;
}

} // namespace

Image compositeInOrder(const CompositeJob& job, std::span<const uint32_t> order,
                       std::span<const std::vector<uint32_t>> cycles, VolumeFrameStats& stats) {
    const std::vector<PixelBox> boxes = cellBoxes(job);
    std::vector<int32_t> cycle_of(job.grid.tets.size(), -1);
    for (std::size_t k = 0; k < cycles.size(); ++k)
        for (const uint32_t c : cycles[k])
            cycle_of[c] = int32_t(k);
    return runBands(job, stats, [&](BandCompositor& band) {
        std::vector<uint8_t> cycle_done(cycles.size(), 0);
        for (const uint32_t c : order) {
            const int32_t k = cycle_of[c];
            if (k < 0) {
                band.composite(c, boxes[c]);
                continue;
            }
            // A cycle's members come one after another: all of them at the first, by depth.
            if (cycle_done[std::size_t(k)])
                continue;
            cycle_done[std::size_t(k)] = 1;
            for (const uint32_t member : cycles[std::size_t(k)])
                band.gather(member, boxes[member]);
            band.compositeList();
        }
    });
}

Image compositeLists(const CompositeJob& job, VolumeFrameStats& stats) {
    const std::vector<PixelBox> boxes = cellBoxes(job);
    return runBands(job, stats, [&](BandCompositor& band) {
        for (uint32_t c = 0; c < job.grid.tets.size(); ++c)
            band.gather(c, boxes[c]);
        band.compositeList();
    });
}

} // namespace vissort::detail
