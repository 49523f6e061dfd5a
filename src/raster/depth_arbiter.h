#pragma once
// The exact rule's arbitration (cpu_reference_oracle.h, rule 7), shared by the rasterizing oracles:
// at one pixel, whether a triangle drawn there lies strictly nearer than a query triangle, by the
// exact fragment model (geometry/exact_fragments.h). What settles it for a whole pair of triangles
// is kept for the bind: one triangle wholly on one side of the other's plane (or both in one plane)
// orders them the same way at every pixel they share, so touching and coplanar faces, whose
// every shared pixel is a tie the floats cannot see, cost a hash lookup per pixel after the
// first, not exact arithmetic.

#include <cstdint>
#include <mutex>
#include <optional>
#include <vector>

#include "geometry/exact_fragments.h"

namespace vissort::detail {

class DepthArbiter {
public:
    /// Prepares for a bind: the view's model, the positions' corners (kept as a view: they must
    /// outlive the bind), and an empty cache.
    void bind(const ViewProjection& view, PositionsView positions);

    const ExactFragments& model() const { return *model_; }

    /// A query triangle's fragment at one pixel, which it must have (the exact model's).
    struct Query {
        PixelRay ray;
        uint32_t triangle;
        TriangleCorners corners;
        RayHit hit;
    };
    Query query(uint32_t triangle, uint32_t px, uint32_t py) const;

    /// Whether triangle `drawn` has a fragment at the query's pixel strictly nearer than the
    /// query's (nearer), or not at this pixel (not_here), or at no pixel at all (never: the
    /// query's own triangle, a copy of it, and pairs decided whole by their planes: touching
    /// and coplanar faces), which a caller arbitrating many pixels of one query can stop asking
    /// about. Safe to call from several threads at once.
    enum class Nearness : uint8_t { nearer, not_here, never };
    Nearness nearness(const Query& query, uint32_t drawn);
    /// nearness for a drawn triangle known to cover the query's pixel (by its draws' coverage,
    /// which is the exact model's): the coverage test skipped.
    Nearness nearnessCovering(const Query& query, uint32_t drawn);

    /// Whether this bind already found that triangle `drawn` is nearer than triangle `query`
    /// at no pixel they share (the pair decided whole by their planes: touching, coplanar and
    /// one-sided pairs), so that a caller can settle many pixels without asking about each.
    bool knownNeverNearer(uint32_t query, uint32_t drawn);

    /// Whether a candidate's triangle is nearer at the query's pixel: candidates are a caller's
    /// entries (triangles, set-ups) for the query, triangleOf(entry) their triangle, and
    /// irrelevant(entry) true where one cannot decide this pixel (outside it, certainly
    /// farther). The entries never nearer are removed, so that a query arbitrating pixel after
    /// pixel against a stack of ties asks about each only once.
    template <class TriangleOf, class Irrelevant>
    bool anyNearer(const Query& query, std::vector<uint32_t>& candidates, TriangleOf&& triangleOf,
                   Irrelevant&& irrelevant) {
        for (std::size_t i = 0; i < candidates.size();) {
            if (irrelevant(candidates[i])) {
                ++i;
                continue;
            }
            switch (nearness(query, triangleOf(candidates[i]))) {
            case Nearness::nearer:
                return true;
            case Nearness::never:
                candidates[i] = candidates.back();
                candidates.pop_back();
                break;
            case Nearness::not_here:
                ++i;
                break;
            }
        }
        return false;
    }

private:
    Nearness nearness(const Query& query, uint32_t drawn, bool known_to_cover);
    // How two triangles order at every pixel they share, or kPerPixel.
    enum Order : uint8_t { kDrawnNearer, kNotNearer, kPerPixel };
    Order pairOrder(const Query& query, uint32_t drawn, const TriangleCorners& corners,
                    const RayHit& hit);

    std::optional<ExactFragments> model_; // in place: a bind allocates nothing
    PositionsView positions_;
    // The pairs' orders this bind: (query << 32 | drawn) -> its order, by open addressing in a
    // table kept across binds (a coherent frame's pairs allocate nothing; a node per pair did).
    static constexpr uint64_t kNoPair = ~uint64_t(0); // no triangle index is 2^32 - 1
    struct Slot {
        uint64_t key = kNoPair;
        Order order = kPerPixel;
    };
    const Order* findOrder(uint64_t key) const;
    void addOrder(uint64_t key, Order order);
    std::mutex mutex_;
    std::vector<Slot> orders_; // a power of two long, at most half full
    std::size_t order_count_ = 0;
};

} // namespace vissort::detail
