#pragma once
/// @file
/// For tests that drive an adapter's transmit() with hand-set enum outputs (model::Signals, as
/// before the catalogue): a report holding those values where the catalogue reads them (a
/// two-axle vehicle, io/signals/catalogue.h), so that TX sees what the test set.

#include <cmath>

#include "io/signals/binding.h"
#include "model/report.h"
#include "model/signals.h"

namespace rig::test {

inline model::ModelReport legacy_report(const model::Signals& s) {
  using model::Signal;
  model::ModelReport r;
  r.unit_count = 1;
  model::UnitReport& u = r.units[0];
  u.wheel_count = 4;
  u.position_m = {s[Signal::kPositionX], s[Signal::kPositionY], 0.0};
  u.orientation_rad = {0.0, 0.0, s[Signal::kHeading]};
  u.velocity_mps[0] = s[Signal::kVehicleSpeed];
  u.angular_velocity_radps[2] = s[Signal::kYawRate];
  u.acceleration_mps2 = {s[Signal::kLongitudinalAccel], s[Signal::kLateralAccel], 0.0};
  const Signal spin[] = {Signal::kWheelSpeedFL, Signal::kWheelSpeedFR, Signal::kWheelSpeedRL,
                         Signal::kWheelSpeedRR};
  const Signal pressure[] = {Signal::kBrakePressureFL, Signal::kBrakePressureFR,
                             Signal::kBrakePressureRL, Signal::kBrakePressureRR};
  for (int i = 0; i < 4; ++i) {
    u.wheels[static_cast<std::size_t>(i)].spin_radps = s[spin[i]];
    u.wheels[static_cast<std::size_t>(i)].brake_pressure_pa = s[pressure[i]];
  }
  r.steering.wheel_angle_rad = s[Signal::kSteeringWheelAngle];
  r.steering.wheel_speed_radps = s[Signal::kSteeringWheelSpeed];
  r.steering.torsion_bar_torque_nm = s[Signal::kTorsionBarTorque];
  r.steering.rack_travel_m = s[Signal::kRackPosition];
  r.steering.rack_force_n = s[Signal::kRackForce];
  r.drivetrain.engine_speed_radps = s[Signal::kEngineSpeed];
  r.drivetrain.gear = static_cast<std::int32_t>(std::lround(s[Signal::kGear]));
  return r;
}

/// Keeps the report a CycleView refers to.
struct LegacyCycle {
  model::ModelReport report;
  io::signals::CycleView view(const model::Signals& s) {
    report = legacy_report(s);
    return {s, report};
  }
};

}  // namespace rig::test
