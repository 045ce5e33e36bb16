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

}  // namespace rig::test
