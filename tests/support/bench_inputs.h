#pragma once
/// @file
/// The inputs of the step benchmarks and the step-cost probe: every input valid, automatic
/// gearbox, part throttle and a steady steering angle, so that a vehicle settles into a driven
/// turn in which every force law is active.

#include <cstddef>

#include "model/signals.h"

namespace rig::test {

inline model::Signals cornering_inputs() {
  model::Signals s;
  for (std::size_t i = 0; i < model::index(model::kFirstOutput); ++i) s.valid[i] = true;
  s[model::Signal::kGearRequest] = 99;
  s[model::Signal::kIgnition] = 2;  // on (valid, so 0 would be off)
  s[model::Signal::kThrottlePedal] = 0.3;
  s[model::Signal::kSteeringWheelAngleCmd] = 0.5;
  return s;
}

/// Straight ahead at part throttle (the road benchmarks: the sedan over the Belgian block and the
/// same on the plane).
inline model::Signals straight_inputs() {
  model::Signals s = cornering_inputs();
  s[model::Signal::kThrottlePedal] = 0.1;
  s[model::Signal::kSteeringWheelAngleCmd] = 0.0;
  return s;
}

/// The road benchmarks' speed [m/s] and steps: with the Belgian block (10 m long) starting just
/// behind the rear wheels (placement x = -1.7 m), 200 steps to settle and 1000 measured ones at
/// 5 m/s keep all four wheels on it (the front wheels leave it after 1.4 s).
inline constexpr double kRoadBenchSpeedMps = 5.0;
inline constexpr int kRoadBenchWarmSteps = 200;
inline constexpr int kRoadBenchSteps = 1000;
inline constexpr double kRoadBenchBlockX = -1.7;

}  // namespace rig::test
