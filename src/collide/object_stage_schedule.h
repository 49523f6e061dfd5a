#pragma once
// When the vissort method's object stage runs (CollisionSettings::object_stage). The stage pays
// only when the tree descents of the pairs it culls would cost more than the stage itself; on a
// CPU that depends on the scene (docs/collision.md: on the bunnies and the pile, the pairs it
// culls are ones the trees separate at their roots). Adaptive: after a frame where it cost more
// than it saved, it is skipped for 2 frames, then 4, 8, ... up to 32 while that holds, and tried
// again after each wait, so a scene whose contacts change gets it back within 32 frames. The
// pairs never depend on it: every stage is conservative. Internal.

#include <algorithm>
#include <cstdint>

#include "vissort/collision.h"

namespace vissort::detail {

class ObjectStageSchedule {
public:
    static constexpr uint32_t kLongestWait = 32;

    explicit ObjectStageSchedule(ObjectStage mode) : mode_(mode) {}

    /// Whether the stage runs this frame; call once a frame.
    bool runsThisFrame() {
        if (mode_ != ObjectStage::adaptive)
            return mode_ == ObjectStage::always;
        if (frames_to_skip_ == 0)
            return true;
        --frames_to_skip_;
        return false;
    }

    /// After a frame where it ran: its milliseconds, and the milliseconds of descents it saved
    /// (an estimate: the collider's).
    void record(double stage_ms, double saved_ms) {
        if (saved_ms >= stage_ms) {
            wait_ = 0;
            return;
        }
        wait_ = std::min(wait_ == 0 ? 2 : 2 * wait_, kLongestWait);
        frames_to_skip_ = wait_;
    }

private:
    ObjectStage mode_;
    uint32_t wait_ = 0;           // the last wait; 0 while the stage pays
    uint32_t frames_to_skip_ = 0; // left of the current wait
};

} // namespace vissort::detail
