#pragma once
/// @file
/// A 10 s seat-pose history at 1 ms for the leaf spring's test and benchmark: a 1.5 Hz bounce of
/// +-40 mm about the static pose, a 50 ms pothole of 50 mm at 2 s (up to 3.1 m/s), 8 Hz axle
/// tramp of +-0.02 rad, braking wind-up of +-0.03 rad at 0.5 Hz, fore-aft +-5 mm at 3 Hz.

#include <cmath>
#include <numbers>

#include "model/vehicle/leaf_spring/leaf_spring.h"

namespace rig::test {

inline model::vehicle::leaf_spring::SeatPose leaf_history_pose(
    const model::vehicle::leaf_spring::SeatPose& stat, int step) {
  const double t = 1e-3 * step;
  const double two_pi = 2.0 * std::numbers::pi;
  double z = 0.04 * std::sin(two_pi * 1.5 * t);
  if (t >= 2.0 && t < 2.05) z += 0.025 * (1.0 - std::cos(two_pi * (t - 2.0) / 0.05));
  const double pitch = 0.03 * std::sin(two_pi * 0.5 * t) + 0.02 * std::sin(two_pi * 8.0 * t);
  const double x = 0.005 * std::sin(two_pi * 3.0 * t);
  return stat + model::vehicle::leaf_spring::SeatPose(x, z, pitch);
}

}  // namespace rig::test
