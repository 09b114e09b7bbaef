// Frame timing against hand-computed values: deltas, totals, clamping, fixed steps.
#include "app/StepTimer.h"

#include <gtest/gtest.h>

namespace firmament {
namespace {

TEST(StepTimer, MeasuresTheTimeBetweenTicks) {
    StepTimer timer;
    timer.tick(10.0);
    EXPECT_EQ(timer.deltaSeconds(), 0.0);  // the first frame has no previous one
    timer.tick(10.02);
    EXPECT_NEAR(timer.deltaSeconds(), 0.02, 1e-12);
    timer.tick(10.05);
    EXPECT_NEAR(timer.deltaSeconds(), 0.03, 1e-12);
    EXPECT_NEAR(timer.totalSeconds(), 0.05, 1e-12);
    EXPECT_EQ(timer.frameCount(), 3u);
}

TEST(StepTimer, ClampsLongStalls) {
    StepTimer timer;
    timer.tick(0.0);
    timer.tick(5.0);  // a breakpoint or a dragged window
    EXPECT_EQ(timer.deltaSeconds(), StepTimer::kMaxStepSeconds);
}

TEST(StepTimer, FixedStepIgnoresTheClock) {
    StepTimer timer;
    timer.setFixedStep(1.0 / 60.0);
    for (double t : {0.0, 3.0, 3.001, 100.0}) timer.tick(t);
    EXPECT_NEAR(timer.totalSeconds(), 4.0 / 60.0, 1e-12);
    EXPECT_NEAR(timer.framesPerSecond(), 60.0, 1e-9);
}

}  // namespace
}  // namespace firmament
