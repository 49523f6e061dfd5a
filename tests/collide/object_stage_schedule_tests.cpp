// When the vissort method's object stage runs (src/collide/object_stage_schedule.h): adaptive
// waits that double while the stage costs more than it saves, reset once it pays; always and
// never as they say.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "collide/object_stage_schedule.h"

namespace vissort::detail {
namespace {

// Which of the next frames run the stage, each run recorded with what record_run gives.
template <class Record>
std::string runs(ObjectStageSchedule& schedule, int frames, Record record_run) {
    std::string pattern;
    for (int f = 0; f < frames; ++f) {
        const bool runs = schedule.runsThisFrame();
        pattern += runs ? 'R' : '.';
        if (runs)
            record_run(schedule);
    }
    return pattern;
}

void costsMoreThanItSaves(ObjectStageSchedule& schedule) {
    schedule.record(2.0, 0.1);
}
void savesMoreThanItCosts(ObjectStageSchedule& schedule) {
    schedule.record(1.0, 5.0);
}

TEST(ObjectStageSchedule, AdaptiveWaitsTwiceAsLongEachTimeItDoesNotPay) {
    ObjectStageSchedule schedule(ObjectStage::adaptive);
    EXPECT_EQ(runs(schedule, 1 + 2 + 1 + 4 + 1 + 8 + 1, costsMoreThanItSaves),
              "R..R....R........R");
    // The wait stops growing at kLongestWait frames.
    ObjectStageSchedule capped(ObjectStage::adaptive);
    std::string pattern = runs(capped, 2000, costsMoreThanItSaves);
    const std::size_t last_run = pattern.rfind('R');
    const std::size_t run_before = pattern.rfind('R', last_run - 1);
    EXPECT_EQ(last_run - run_before - 1, ObjectStageSchedule::kLongestWait);
}

TEST(ObjectStageSchedule, AdaptiveRunsEveryFrameWhileItPays) {
    ObjectStageSchedule schedule(ObjectStage::adaptive);
    EXPECT_EQ(runs(schedule, 10, savesMoreThanItCosts), "RRRRRRRRRR");
    // After waits, a frame where it pays brings it back to every frame.
    int calls = 0;
    EXPECT_EQ(runs(schedule, 12,
                   [&](ObjectStageSchedule& s) {
                       if (calls++ < 2)
                           costsMoreThanItSaves(s);
                       else
                           savesMoreThanItCosts(s);
                   }),
              "R..R....RRRR");
}

TEST(ObjectStageSchedule, SavingWhatItCostsIsEnough) {
    ObjectStageSchedule schedule(ObjectStage::adaptive);
    EXPECT_EQ(runs(schedule, 4, [](ObjectStageSchedule& s) { s.record(0.5, 0.5); }), "RRRR");
    EXPECT_EQ(runs(schedule, 4, [](ObjectStageSchedule& s) { s.record(0.5, 0.0); }), "R..R");
}

TEST(ObjectStageSchedule, AlwaysAndNeverIgnoreTheirCost) {
    ObjectStageSchedule always(ObjectStage::always), never(ObjectStage::never);
    EXPECT_EQ(runs(always, 6, costsMoreThanItSaves), "RRRRRR");
    EXPECT_EQ(runs(never, 6, savesMoreThanItCosts), "......");
}

} // namespace
} // namespace vissort::detail
