#pragma once
/// @file
/// Snapshots whose every value is a known function of the cycle number, so that what comes out
/// of LCM (a subscriber, a log, a CSV) can be checked against it. tests/integration/lcm/
/// check_csv.py mirrors these formulas; keep them in step.

#include <cstdint>

#include "io/snapshot.h"

namespace rig::test {

inline constexpr int kSyntheticUnits = 2;
inline constexpr int kSyntheticWheels[kSyntheticUnits] = {4, 2};
inline constexpr int kSyntheticJoints = 1;

inline io::Snapshot make_synthetic_snapshot(std::uint64_t cycle, double period_s) {
  io::Snapshot s;
  const double c = static_cast<double>(cycle);
  const double t = c * period_s;
  auto& timing = s.timing;
  timing.cycle = cycle;
  timing.sim_time_s = t;
  timing.deadline_ns = 1'000'000'000 + static_cast<std::int64_t>(cycle) * 1'000'000;
  timing.lateness_ns = static_cast<std::int64_t>(cycle % 97) * 1'000;
  timing.wake_ns = timing.deadline_ns + timing.lateness_ns;
  timing.compute_ns = 200'000 + static_cast<std::int64_t>(cycle % 13) * 1'000;
  timing.deadline_miss = cycle % 500 == 499;
  timing.consecutive_misses = timing.deadline_miss ? 1 : 0;

  auto& r = s.report;
  r.time_s = t;
  r.unit_count = kSyntheticUnits;
  for (int u = 0; u < kSyntheticUnits; ++u) {
    auto& unit = r.units[static_cast<std::size_t>(u)];
    const double du = static_cast<double>(u);
    unit.position_m = {20.0 * t - 6.0 * du, 0.001 * c + du, 0.5 + 0.1 * du};
    unit.orientation_rad = {0.01 * du, 0.02, 0.0005 * c};
    unit.velocity_mps = {20.0, 0.1 * du, 0.0};
    unit.angular_velocity_radps = {0.0, 0.0, 0.5};
    unit.acceleration_mps2 = {0.001 * c, -0.5 - du, 9.0};
    unit.wheel_count = kSyntheticWheels[u];
    for (int w = 0; w < unit.wheel_count; ++w) {
      auto& wheel = unit.wheels[static_cast<std::size_t>(w)];
      const double k = static_cast<double>(10 * u + w);  // a wheel's identity in the formulas
      wheel.spin_radps = 30.0 + 0.01 * c + k;
      wheel.slip_x = 0.001 * k;
      wheel.slip_y = -0.002 * k + 1e-6 * c;
      wheel.force_x_n = 100.0 * k;
      wheel.force_y_n = -50.0 * k;
      wheel.load_n = 4000.0 + k;
      wheel.deflection_x_m = 1e-4 * k;
      wheel.deflection_y_m = -1e-4 * k;
      wheel.steer_angle_rad = 0.001 * k;
      wheel.brake_torque_nm = 10.0 * k;
      wheel.drive_torque_nm = 20.0 * k;
    }
  }
  r.steering.wheel_angle_rad = 0.0001 * c;
  r.steering.wheel_torque_nm = 2.5;
  r.steering.torsion_bar_torque_nm = 3.0;
  r.steering.rack_travel_m = 1e-6 * c;
  r.steering.rack_force_n = -1200.0;
  r.steering.assist_torque_nm = 4.0;
  r.drivetrain.engine_speed_radps = 200.0 + 0.1 * c;
  r.drivetrain.engine_torque_nm = 150.0;
  r.drivetrain.gear = 1 + static_cast<std::int32_t>(cycle / 1000);
  r.brake_pressure_pa = {1e5, 1.1e5, 0.5e5, 0.6e5};
  r.joint_count = kSyntheticJoints;
  r.joints[0].force_n = {1000.0 + c, -20.0, 300.0};
  r.joints[0].violation_m = 1e-9;
  r.joints[0].rod_force_n = -500.0 - c;

  for (std::size_t i = 0; i < model::kSignalCount; ++i) {
    s.signals.value[i] = static_cast<double>(i) + 0.001 * c;
    s.signals.valid[i] = i % 5 != 0;
    s.signals.source[i] = !model::kSignalTable[i].is_input ? model::SignalSource::kModel
                          : i % 2 == 0                     ? model::SignalSource::kDriver
                                                           : model::SignalSource::kCan;
  }
  // the checks name this one (lcm_log_test, check_csv.py): not tied to the table's order
  s.signals.set(model::Signal::kVehicleSpeed, 7.0 + 0.001 * c);

  s.can.bus_state = io::BusState::kUp;
  s.can.frames_received = 3 * cycle;
  s.can.frames_sent = 2 * cycle;
  s.can.timeouts = cycle / 100;
  s.can.checksum_failures = 1;
  s.can.counter_failures = 2;
  s.can.bad_frames = 3;
  s.can.error_frames = 4;
  return s;
}

}  // namespace rig::test
