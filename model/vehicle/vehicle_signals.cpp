#include "model/vehicle/vehicle_signals.h"

#include <algorithm>
#include <cmath>

namespace rig::model::vehicle {

namespace {

/// A slot's value while valid and finite, else the fallback.
double slot_or(const Signals& s, std::size_t slot, double fallback) noexcept {
  const double v = s.value[slot];
  return s.valid[slot] && std::isfinite(v) ? v : fallback;
}

/// Each wheel's own pressure slot while valid, else its axle's circuit: the unit's circuit
/// slot, else the enum's (unit 0's) circuit, so that unrouted units brake as the first.
void read_brake_pressures(const VehicleParams& params, int unit, const Signals& s,
                          VehicleInputs& r) noexcept {
  const double front = slot_or(s, index(Signal::kBrakePressureFront), 0.0);
  const double rear = slot_or(s, index(Signal::kBrakePressureRear), 0.0);
  const double circuit[2] = {std::max(0.0, slot_or(s, brake_circuit_slot(unit, 0), front)),
                             std::max(0.0, slot_or(s, brake_circuit_slot(unit, 1), rear))};
  for (std::size_t k = 0; k < 2 * params.axles.size(); ++k) {
    const double axle = circuit[params.axles[k / 2].brake_circuit == 0 ? 0 : 1];
    const std::size_t slot = wheel_brake_slot(unit, static_cast<int>(k));
    r.brake_pressure_pa[k] =
        s.valid[slot] && std::isfinite(s.value[slot]) ? std::max(0.0, s.value[slot]) : axle;
  }
}

}  // namespace

VehicleInputs read_inputs(const VehicleParams& params, int unit, const Signals& s) noexcept {
  const auto in = [&](Signal id, double fallback) { return slot_or(s, index(id), fallback); };
  VehicleInputs r;
  r.throttle = std::clamp(in(Signal::kThrottlePedal, 0.0), 0.0, 1.0);
  read_brake_pressures(params, unit, s, r);
  r.steering_angle_cmd_rad = in(Signal::kSteeringWheelAngleCmd, 0.0);
  r.hand_torque_cmd_nm = in(Signal::kSteeringWheelTorqueCmd, 0.0);
  r.robot_released = params.steering.angle_from_input &&
                     !(s.valid[index(Signal::kSteeringWheelAngleCmd)] &&
                       std::isfinite(s.value[index(Signal::kSteeringWheelAngleCmd)]));
  // the assist input while valid when routed to it (SteeringParams::assist_from_input)
  r.assist_from_input = params.steering.assist_from_input && s.valid[index(Signal::kAssistTorque)];
  r.assist_input_nm = in(Signal::kAssistTorque, 0.0);
  r.overlay_angle_rad = in(Signal::kSteeringOverlayAngleCmd, 0.0);
  r.gear_request = static_cast<int>(std::lround(in(Signal::kGearRequest, 99.0)));
  // 0 off, 1 accessory: no engine, no assist; 2 on, 3 start (no starter: as on); unrouted: on
  r.ignition_on = std::lround(in(Signal::kIgnition, 2.0)) >= 2;
  // the driver's differential locks: 1 locks, anything else (or not routed) leaves them open
  r.lock_between = std::lround(in(Signal::kDifferentialLockBetweenCmd, 0.0)) == 1;
  r.lock_axle = std::lround(in(Signal::kDifferentialLockAxleCmd, 0.0)) == 1;
  const auto valid = [&](Signal id) {
    return s.valid[index(id)] && std::isfinite(s.value[index(id)]);
  };
  r.feedback_torque_cmd_nm = in(Signal::kSteeringWheelFeedbackTorqueCmd, 0.0);
  r.rack_force_cmd_valid = valid(Signal::kRackForceCmd);
  r.rack_force_cmd_n = in(Signal::kRackForceCmd, 0.0);
  r.rack_position_cmd_valid = valid(Signal::kRackPositionCmd);
  r.rack_position_cmd_m = in(Signal::kRackPositionCmd, 0.0);
  r.rack_measured_valid = valid(Signal::kRackPositionMeasured) && valid(Signal::kRackSpeedMeasured);
  r.rack_position_measured_m = in(Signal::kRackPositionMeasured, 0.0);
  r.rack_speed_measured_mps = in(Signal::kRackSpeedMeasured, 0.0);
  return r;
}

void write_outputs(const VehicleState& state, const VehicleInputs& in, const VehicleWorkspace& work,
                   Signals& s) noexcept {
  const auto& y = state.framework_y;
  const auto& z = state.framework_z;
  const int n = work.wheel_count;
  const auto spin = [&](int i) { return state.spin_radps[static_cast<std::size_t>(i)]; };
  const auto pressure = [&](int i) { return in.brake_pressure_pa[static_cast<std::size_t>(i)]; };
  s.set(Signal::kVehicleSpeed, z(0));
  s.set(Signal::kWheelSpeedFL, spin(0));
  s.set(Signal::kWheelSpeedFR, spin(1));
  s.set(Signal::kWheelSpeedRL, spin(n - 2));
  s.set(Signal::kWheelSpeedRR, spin(n - 1));
  s.set(Signal::kLongitudinalAccel, state.acceleration_mps2.x());
  s.set(Signal::kLateralAccel, state.acceleration_mps2.y());
  s.set(Signal::kYawRate, z(5));
  s.set(Signal::kSteeringWheelAngle, state.steering_y(0));
  s.set(Signal::kSteeringWheelSpeed, state.steering_z(0));
  s.set(Signal::kTorsionBarTorque, work.torsion_bar_torque_nm);
  s.set(Signal::kRackPosition, state.steering_y(1));
  s.set(Signal::kRackForce, work.rack_force_n);
  s.set(Signal::kEngineSpeed, state.drivetrain_z(0));
  s.set(Signal::kGear, state.gear);
  s.set(Signal::kBrakePressureFL, pressure(0));
  s.set(Signal::kBrakePressureFR, pressure(1));
  s.set(Signal::kBrakePressureRL, pressure(n - 2));
  s.set(Signal::kBrakePressureRR, pressure(n - 1));
  s.set(Signal::kPositionX, y(0));
  s.set(Signal::kPositionY, y(1));
  s.set(Signal::kHeading, y(3));
}

namespace {

void fill_wheel(const VehicleState& state, const VehicleInputs& in, const VehicleWorkspace& work,
                int i, WheelReport& r) {
  const auto k = static_cast<std::size_t>(i);
  const WheelWork& w = work.wheels[k];
  r.spin_radps = state.spin_radps[k];
  r.slip_x = w.out.slip_x;
  r.slip_y = w.out.slip_y;
  r.force_x_n = w.out.force_x_n;
  r.force_y_n = w.out.force_y_n;
  r.load_n = w.out.load_n;
  r.deflection_x_m = state.tire_deflection_m[k](0);
  r.deflection_y_m = state.tire_deflection_m[k](1);
  r.hub_travel_m = w.out.rigid_axle ? w.out.hub_travel_m : state.framework_y(6 + i);
  r.steer_angle_rad = w.steer_rad;
  r.brake_torque_nm = w.brake_torque_nm;
  r.brake_pressure_pa = in.brake_pressure_pa[k];
  r.drive_torque_nm = w.shaft_torque_nm;
  r.long_speed_mps = w.out.tire.long_speed_mps;
  r.lat_speed_mps = w.out.tire.lat_speed_mps;
  r.rolling_radius_m = w.out.tire.rolling_radius_m;
  r.tire_load_n = w.load_n;
  r.road_z_m = w.road_z_m;
  r.road_normal_x = w.road.normal.x();
  r.road_normal_y = w.road.normal.y();
  r.road_normal_z = w.road.normal.z();
  r.road_mu = w.road_friction;
  r.axle_heave_m = w.out.axle_heave_m;
  r.axle_roll_rad = w.out.axle_roll_rad;
}

/// The leaf-sprung axles' values on their wheels (the others keep 0).
void fill_leaf_axles(const VehicleState& state, UnitReport& u) {
  for (const LeafAxleState& s : state.leaf_axles) {
    if (s.axle < 0) continue;
    for (std::size_t side = 0; side < 2; ++side) {
      WheelReport& r = u.wheels[2 * static_cast<std::size_t>(s.axle) + side];
      r.leaf_windup_rad = s.pitch_rad - s.rest_pitch_rad;
      r.leaf_fore_aft_m = s.x_m - s.rest_x_m;
      r.leaf_shackle_rad = s.leaf[side].shackle_angle_rad();
      r.leaf_front_link_rad = s.leaf[side].internal(1);
      r.leaf_rear_link_rad = s.leaf[side].internal(3);
      r.leaf_iterations = s.iterations[side];
    }
  }
  for (const LeafBalanceState& b : state.leaf_balances) {
    if (b.first_axle < 0) continue;
    for (std::size_t w = 0; w < 4; ++w)  // both axles' wheels, left and right
      u.wheels[2 * static_cast<std::size_t>(b.first_axle) + w].leaf_rocker_rad = b.u(4 + w % 2);
  }
}

}  // namespace

void fill_report(const VehicleState& state, const VehicleInputs& in, const VehicleWorkspace& work,
                 ModelReport& report) noexcept {
  const auto& y = state.framework_y;
  const auto& z = state.framework_z;
  report.time_s = state.time_s;
  report.unit_count = 1;
  UnitReport& u = report.units[0];
  for (int k = 0; k < 3; ++k) {
    u.position_m[static_cast<std::size_t>(k)] = y(k);
    u.velocity_mps[static_cast<std::size_t>(k)] = z(k);
    u.angular_velocity_radps[static_cast<std::size_t>(k)] = z(3 + k);
    u.acceleration_mps2[static_cast<std::size_t>(k)] = state.acceleration_mps2(k);
  }
  u.orientation_rad = {y(5), y(4), y(3)};
  u.wheel_count = work.wheel_count;
  for (int i = 0; i < work.wheel_count; ++i)
    fill_wheel(state, in, work, i, u.wheels[static_cast<std::size_t>(i)]);
  fill_leaf_axles(state, u);
  report.steering.wheel_angle_rad = state.steering_y(0);
  report.steering.wheel_speed_radps = state.steering_z(0);
  report.steering.wheel_torque_nm = in.hand_torque_cmd_nm;
  report.steering.torsion_bar_torque_nm = work.torsion_bar_torque_nm;
  report.steering.rack_travel_m = state.steering_y(1);
  report.steering.rack_force_n = work.rack_force_n;
  report.steering.assist_torque_nm = work.assist_torque_nm;
  report.steering.tie_rod_force_left_n = work.tie_rod_force_left_n;
  report.steering.tie_rod_force_right_n = work.tie_rod_force_right_n;
  report.drivetrain.engine_speed_radps = state.drivetrain_z(0);
  report.drivetrain.engine_torque_nm = work.engine_torque_nm;
  report.drivetrain.gear = state.gear;
  const auto n = static_cast<std::size_t>(work.wheel_count);
  report.brake_pressure_pa = {in.brake_pressure_pa[0], in.brake_pressure_pa[1],
                              in.brake_pressure_pa[n - 2], in.brake_pressure_pa[n - 1]};
  report.joint_count = 0;
  report.differential_count = work.differential_count;
  for (int j = 0; j < work.differential_count; ++j)
    report.differentials[static_cast<std::size_t>(j)] =
        work.differentials[static_cast<std::size_t>(j)];
}

void mark_slip_validity(double mask_speed_mps, UnitReport& unit) noexcept {
  for (int i = 0; i < unit.wheel_count; ++i) {
    WheelReport& w = unit.wheels[static_cast<std::size_t>(i)];
    const double speed =
        std::max(std::abs(w.long_speed_mps), w.rolling_radius_m * std::abs(w.spin_radps));
    w.slip_valid = speed >= mask_speed_mps ? 1 : 0;
  }
}

}  // namespace rig::model::vehicle
