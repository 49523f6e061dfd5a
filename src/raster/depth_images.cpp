// The per-primitive depth images of CpuOracle (depth_images.h).

#include "raster/depth_images.h"

#include <algorithm>
#include <cassert>
#include <limits>

namespace vissort::detail {
namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

} // namespace

void DepthImages::reset(uint32_t slot_count) {
    state_.assign(slot_count, State::unbuilt);
    first_.resize(slot_count);
    count_.resize(slot_count);
    tiles_.clear();
    bounds_.clear();
    depths_.clear();
}

void DepthImages::begin(uint32_t slot) {
    assert(state_[slot] == State::unbuilt);
    building_ = slot;
    first_[slot] = uint32_t(tiles_.size());
    count_[slot] = 0;
}

void DepthImages::addTile(uint32_t tile, const float* rasterized) {
    // The least rasterized depth: the near image's least, the negated far image's greatest.
    const float least = *std::min_element(rasterized, rasterized + kTileFloats);
    if (least == kInfinity)
        return; // no fragment here
    tiles_.push_back(tile);
    const std::size_t at = depths_.size();
    depths_.insert(depths_.end(), rasterized, rasterized + kTileFloats);
    if (kind_ == Kind::near) {
        bounds_.push_back(least);
    } else {
        for (std::size_t i = at; i < depths_.size(); ++i)
            depths_[i] = -depths_[i];
        bounds_.push_back(-least);
    }
    ++count_[building_];
}

bool DepthImages::finish(std::size_t budget_bytes) {
    if (bytes() <= budget_bytes) {
        state_[building_] = State::built;
        return true;
    }
    const std::size_t first = first_[building_];
    tiles_.resize(first);
    bounds_.resize(first);
    depths_.resize(first * kTileFloats);
    count_[building_] = 0;
    state_[building_] = State::direct;
    return false;
}

std::size_t DepthImages::bytes() const {
    return tiles_.size() * (sizeof(uint32_t) + sizeof(float) + kTileFloats * sizeof(float));
}

void drawImageTile(const float* image, float* stored, float& stored_min, float& stored_max) {
    float least = kInfinity, greatest = -kInfinity;
    for (std::size_t i = 0; i < kTileFloats; ++i) {
        // LESS: the image's depth replaces the stored one only when strictly nearer.
        const float depth = image[i] < stored[i] ? image[i] : stored[i];
        stored[i] = depth;
        least = std::min(least, depth);
        greatest = std::max(greatest, depth);
    }
    stored_min = least;
    stored_max = greatest;
}

QueryResult queryImageTile(const float* image, const float* stored, float behind_above,
                           float undecided_above) {
    bool behind = false, undecided = false;
    for (std::size_t i = 0; i < kTileFloats; ++i) {
        behind |= image[i] > stored[i] + behind_above;
        undecided |= image[i] > stored[i] + undecided_above;
    }
    return behind ? QueryResult::behind : undecided ? QueryResult::undecided : QueryResult::none;
}

} // namespace vissort::detail
