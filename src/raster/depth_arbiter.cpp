// The exact rule's arbitration (depth_arbiter.h).

#include "raster/depth_arbiter.h"

#include <algorithm>
#include <functional>

#include "geometry/exact_predicates.h"

namespace vissort::detail {

void DepthArbiter::bind(const ViewProjection& view, PositionsView positions) {
    model_.emplace(view);
    positions_ = positions;
    const std::lock_guard<std::mutex> lock(mutex_);
    std::fill(orders_.begin(), orders_.end(), Slot{});
    order_count_ = 0;
}

const DepthArbiter::Order* DepthArbiter::findOrder(uint64_t key) const {
    if (orders_.empty())
        return nullptr;
    const std::size_t mask = orders_.size() - 1;
    for (std::size_t i = std::hash<uint64_t>{}(key * 0x9E3779B97F4A7C15ull) & mask;;
         i = (i + 1) & mask) {
        if (orders_[i].key == key)
            return &orders_[i].order;
        if (orders_[i].key == kNoPair)
            return nullptr;
    }
}

void DepthArbiter::addOrder(uint64_t key, Order order) {
    if (2 * (order_count_ + 1) > orders_.size()) {
        std::vector<Slot> old(std::max<std::size_t>(64, 2 * orders_.size()));
        old.swap(orders_);
        order_count_ = 0;
        for (const Slot& slot : old)
            if (slot.key != kNoPair)
                addOrder(slot.key, slot.order);
    }
    const std::size_t mask = orders_.size() - 1;
    std::size_t i = std::hash<uint64_t>{}(key * 0x9E3779B97F4A7C15ull) & mask;
    while (orders_[i].key != kNoPair && orders_[i].key != key)
        i = (i + 1) & mask;
    if (orders_[i].key == kNoPair)
        ++order_count_;
    orders_[i] = {key, order};
}

bool DepthArbiter::knownNeverNearer(uint32_t query, uint32_t drawn) {
    const std::lock_guard<std::mutex> lock(mutex_);
    const Order* found = findOrder(uint64_t(query) << 32 | drawn);
    return found != nullptr && *found == kNotNearer;
}

DepthArbiter::Query DepthArbiter::query(uint32_t triangle, uint32_t px, uint32_t py) const {
    Query q;
    q.ray = model_->rays().centre(px, py);
    q.triangle = triangle;
    q.corners = TriangleCorners::of(positions_, triangle);
    q.hit = model_->hit(q.ray, q.corners);
    return q;
}

DepthArbiter::Nearness DepthArbiter::nearness(const Query& query, uint32_t drawn) {
    return nearness(query, drawn, false);
}

DepthArbiter::Nearness DepthArbiter::nearnessCovering(const Query& query, uint32_t drawn) {
    return nearness(query, drawn, true);
}

DepthArbiter::Nearness DepthArbiter::nearness(const Query& query, uint32_t drawn,
                                              bool known_to_cover) {
    if (drawn == query.triangle)
        return Nearness::never; // a fragment is never in front of itself
    const TriangleCorners corners = TriangleCorners::of(positions_, drawn);
    // A copy of the query's triangle ties with it everywhere: cheaper to see than to arbitrate.
    if (corners.sameCornersAs(query.corners))
        return Nearness::never;
    if (!known_to_cover && !model_->covers(query.ray, corners))
        return Nearness::not_here;
    const RayHit hit = model_->hit(query.ray, corners);
    switch (pairOrder(query, drawn, corners, hit)) {
    case kDrawnNearer:
        return Nearness::nearer;
    case kNotNearer:
        return Nearness::never;
    case kPerPixel:
        break;
    }
    return model_->compare(query.ray, query.corners, query.hit, corners, hit) > 0
               ? Nearness::nearer
               : Nearness::not_here;
}

DepthArbiter::Order DepthArbiter::pairOrder(const Query& query, uint32_t drawn,
                                            const TriangleCorners& corners, const RayHit& hit) {
    const uint64_t key = uint64_t(query.triangle) << 32 | drawn;
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        if (const Order* found = findOrder(key))
            return *found;
    }
    // Which way a triangle faces every ray that meets it: the sign of Q = n . D, the same for
    // every such ray (they all start at the eye, or share one direction). Both triangles cover
    // this ray, so neither Q is 0: the bound settles it, or the exact model does.
    const auto facing = [&](const TriangleCorners& t, const RayHit& h) {
        const int sign = h.q.certainSign();
        return sign != 0 ? sign : model_->facing(query.ray, t);
    };
    const int query_facing = facing(query.corners, query.hit);
    const int drawn_facing = facing(corners, hit);
    // A point lies beyond a triangle's plane along these rays (farther than where they meet the
    // plane) when orient3d against the plane has the sign of its facing: +1 beyond, -1 before,
    // 0 in the plane. A triangle wholly (weakly) on one side orders every shared pixel alike.
    const auto sides = [](const TriangleCorners& plane, int plane_facing,
                          const TriangleCorners& points, int(&out)[3]) {
        for (int k = 0; k < 3; ++k)
            out[k] = orient3d(plane.p[0], plane.p[1], plane.p[2], points.p[k]) * plane_facing;
    };
    int query_side[3], drawn_side[3];
    sides(corners, drawn_facing, query.corners, query_side);
    sides(query.corners, query_facing, corners, drawn_side);
    const auto all = [](const int(&s)[3], auto&& test) {
        return test(s[0]) && test(s[1]) && test(s[2]);
    };
    Order order = kPerPixel;
    if (all(query_side, [](int s) { return s > 0; }) ||
        all(drawn_side, [](int s) { return s < 0; }))
        order = kDrawnNearer; // the query wholly beyond the drawn's plane, or the drawn wholly
                              // before the query's: strictly, at every shared pixel
    else if (all(query_side, [](int s) { return s <= 0; }) ||
             all(drawn_side, [](int s) { return s >= 0; }))
        order = kNotNearer; // the query before or in the drawn's plane (coplanar: a tie), or the
                            // drawn beyond or in the query's
    const std::lock_guard<std::mutex> lock(mutex_);
    addOrder(key, order);
    return order;
}

} // namespace vissort::detail
