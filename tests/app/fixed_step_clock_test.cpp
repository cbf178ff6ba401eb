// The simulation clock: steps of 1/60 s following real time, at most five a frame;
// one a frame when replaying.
#include "editor/app/fixed_step_clock.h"

#include <gtest/gtest.h>

namespace pw::app {
namespace {

using Clock = FixedStepClock::Clock;
using std::chrono::microseconds;

TEST(FixedStepClock, LiveStepsFollowRealTimeAndCarryTheRemainder) {
  FixedStepClock clock(false);
  const Clock::time_point t0 = Clock::now();
  clock.restart(t0);
  EXPECT_EQ(clock.stepsFor(t0 + microseconds(10000)), 0);  // 10 ms: not yet a step
  EXPECT_EQ(clock.stepsFor(t0 + microseconds(20000)), 1);  // 20 ms: one, 3.3 ms left over
  EXPECT_EQ(clock.stepsFor(t0 + microseconds(55000)), 2);  // 55 ms: three in all, 5 ms left over
  // A stall of a second is not caught up: five steps at most.
  EXPECT_EQ(clock.stepsFor(t0 + microseconds(1050000)), FixedStepClock::kMaxStepsPerFrame);
  // After a restart (the window was minimised) the time away does not count.
  clock.restart(t0 + microseconds(9000000));
  EXPECT_EQ(clock.stepsFor(t0 + microseconds(9010000)), 0);
}

TEST(FixedStepClock, ReplayTakesOneStepPerFrameWhateverTheTime) {
  FixedStepClock clock(true);
  const Clock::time_point t0 = Clock::now();
  EXPECT_EQ(clock.stepsFor(t0), 1);
  EXPECT_EQ(clock.stepsFor(t0 + microseconds(1000000)), 1);
  EXPECT_EQ(clock.stepsFor(t0 + microseconds(1000001)), 1);
}

}  // namespace
}  // namespace pw::app
