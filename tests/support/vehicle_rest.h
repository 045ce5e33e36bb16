#pragma once
/// @file
/// A vehicle standing as the static-load tests want it: in neutral with the brakes on (8 bar),
/// settled (VehicleModel::settle at rest), then `seconds` more steps - the preamble of the
/// rigid-axle, frame-torsion and leaf tests' hand-calculated axle loads.

#include <cmath>

#include <gtest/gtest.h>

#include "model/signals.h"
#include "model/vehicle/vehicle_model.h"

namespace rig::test {

inline void rest(model::vehicle::VehicleModel& m, model::Signals& s, double seconds) {
  s[model::Signal::kGearRequest] = 0;
  s[model::Signal::kBrakePressureFront] = 8e5;
  s[model::Signal::kBrakePressureRear] = 8e5;
  (void)m.settle(0.0, 0);
  const long n = std::lround(seconds / m.step_size_s());
  for (long k = 0; k < n; ++k) ASSERT_EQ(m.step(s), model::StepStatus::kOk);
}

}  // namespace rig::test
