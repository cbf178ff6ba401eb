// The simulation's clock: fixed steps of 1/60 s, so that a run is the same whatever
// the frame rate. Live, the steps follow real time (at most five per drawn frame: a
// stall is not caught up); replayed, one step per drawn frame (deterministic).
#pragma once

#include <algorithm>
#include <chrono>

namespace pw::app {

class FixedStepClock {
 public:
  static constexpr double kStepS = 1.0 / 60.0;
  static constexpr int kMaxStepsPerFrame = 5;
  using Clock = std::chrono::steady_clock;

  explicit FixedStepClock(bool oneStepPerFrame) : oneStepPerFrame_(oneStepPerFrame) {}

  // How many steps to simulate before drawing the frame that starts at `now`.
  int stepsFor(Clock::time_point now = Clock::now()) {
    if (oneStepPerFrame_) return 1;
    accumulatorS_ = std::min(accumulatorS_ + std::chrono::duration<double>(now - previous_).count(),
                             kMaxStepsPerFrame * kStepS);
    previous_ = now;
    int steps = 0;
    while (accumulatorS_ >= kStepS) {
      accumulatorS_ -= kStepS;
      ++steps;
    }
    return steps;
  }

  // Forgets the time that passed since the last frame (the window was minimised).
  void restart(Clock::time_point now = Clock::now()) { previous_ = now; }

 private:
  bool oneStepPerFrame_;
  Clock::time_point previous_ = Clock::now();
  double accumulatorS_ = 0;
};

}  // namespace pw::app
