#pragma once
/// @file
/// The van (config/vehicles/van-leaf.toml) for the leaf axle's cost: with its leaf-sprung rear
/// axle, or the same axle on SpringDamperAxleSuspension of the same rates (the leaf's
/// 96.2 kN/m per spring at the static load, spring_stiffness_npm of the file; the same
/// dampers, stops and tracks), and the inputs of one step: 0.5 Hz sine steer of +-0.5 rad at
/// the wheel, brake pulses to 40 bar at 1 Hz with throttle in between, so the leaves wind up and
/// unwind and the axle heaves and rolls.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "io/config/vehicle_file.h"
#include "model/vehicle/vehicle_params.h"
#include "tests/support/driver_inputs.h"

namespace rig::test {

inline model::vehicle::VehicleParams van_params(bool leaf) {
  model::vehicle::VehicleParams p =
      io::config::load_vehicle_file(RIG_SOURCE_DIR "/config/vehicles/van-leaf.toml");
  p.axles[1].has_leaf_spring = leaf;
  return p;
}

/// The inputs at time t [s].
inline void van_inputs(double t, model::Signals& s) {
  using model::Signal;
  const double two_pi = 2 * std::numbers::pi;
  s[Signal::kSteeringWheelAngleCmd] = 0.5 * std::sin(two_pi * 0.5 * t);
  const double brake = std::max(0.0, std::sin(two_pi * t));
  s[Signal::kBrakePressureFront] = 4e6 * brake;
  s[Signal::kBrakePressureRear] = 4e6 * brake;
  s[Signal::kThrottlePedal] = brake > 0 ? 0.0 : 0.4;
}

inline constexpr double kVanSpeedMps = 20.0;
inline constexpr int kVanWarmSteps = 2000;

}  // namespace rig::test
