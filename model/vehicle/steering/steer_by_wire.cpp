#include "model/vehicle/steering/steer_by_wire.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rig::model::vehicle {

namespace {
double reflected_rack_mass_kg(const SteeringParams& p) {
  const double r = p.rack_actuator_ratio_m_per_rad;
  return p.rack_mass_kg + p.rack_actuator_inertia_kgm2 / (r * r);
}
}  // namespace

// The position servo on m = m_rack + J / r^2, an I-PD controller F = F_I - k_p u - k_d u'
// with F_I' = k_i (u_cmd - u): m s^3 + k_d s^2 + k_p s + k_i = m (s^3 + 2 w s^2 + 2 w^2 s + w^3),
// the 3rd-order Butterworth lag k_i / (...), whose -3 dB point is w = 2 pi f_bw (k_d includes
// the actuator's viscous friction). The tires' rack
// stiffness would add to k_p: the load feedforward (servo_force_n) takes it out.
SteerByWire::SteerByWire(const SteeringParams& p, VehicleState& state, const VehicleInputs& inputs,
                         const VehicleWorkspace& work)
    : p_(p),
      state_(state),
      inputs_(inputs),
      work_(work),
      rack_mass_kg_(reflected_rack_mass_kg(p)),
      servo_w_radps_(2 * std::numbers::pi * p.rack_actuator_bandwidth_hz),
      servo_stiffness_npm_(2 * rack_mass_kg_ * servo_w_radps_ * servo_w_radps_),
      // the actuator's own damping is part of the loop's k_d (none added beyond it)
      servo_damping_nspm_(
          std::max(0.0, 2 * rack_mass_kg_ * servo_w_radps_ - p.rack_actuator_damping_nspm)) {}

void SteerByWire::begin_step(double h) noexcept {
  // force command: the motor's force follows it as a first-order lag, exact over the step;
  // without a valid force command (or under a position command) it decays to 0
  const double fmax = p_.rack_actuator_force_max_n;
  const double target = inputs_.rack_force_cmd_valid && !inputs_.rack_position_cmd_valid
                            ? std::clamp(inputs_.rack_force_cmd_n, -fmax, fmax)
                            : 0.0;
  state_.rack_actuator_force_n +=
      -std::expm1(-h / p_.rack_actuator_time_constant_s) * (target - state_.rack_actuator_force_n);
  // position servo: its integral advances explicitly (slow against h); bumpless handover (F_I =
  // k_p u: no force at the rest where the command becomes valid); no wind-up beyond the limit
  const double u = state_.steering_y(1);
  if (!inputs_.rack_position_cmd_valid) {
    state_.rack_servo_integral_n = servo_stiffness_npm_ * u;
    return;
  }
  const double ki = rack_mass_kg_ * servo_w_radps_ * servo_w_radps_ * servo_w_radps_;
  const double f_i = state_.rack_servo_integral_n + ki * h * (inputs_.rack_position_cmd_m - u);
  const double kp_u = servo_stiffness_npm_ * u;
  state_.rack_servo_integral_n = std::clamp(f_i, kp_u - fmax, kp_u + fmax);
}

void SteerByWire::mass_matrix(const Vector& y, Matrix& m) const noexcept {
  (void)y;
  m << p_.wheel_inertia_kgm2, 0, 0, rack_mass_kg_;
}

double SteerByWire::hand_torque_nm(const Vector& y, const Vector& z) const noexcept {
  if (p_.torque_input) return inputs_.hand_torque_cmd_nm;
  return p_.robot_stiffness_nmpr * (inputs_.steering_angle_cmd_rad - y(0)) -
         p_.robot_damping_nmspr * z(0);
}

// + the load feedforward: the tie rods' force on the rack as the actuator measured it in the
// last step (its rack force sensor / motor-current estimate), so that the tires' rack stiffness
// does not shift the designed bandwidth
double SteerByWire::servo_force_n(const Vector& y, const Vector& z) const noexcept {
  return state_.rack_servo_integral_n - servo_stiffness_npm_ * y(1) - servo_damping_nspm_ * z(1) +
         work_.rack_force_n;
}

double SteerByWire::rack_actuator_force_n(const Vector& y, const Vector& z) const noexcept {
  if (!inputs_.rack_position_cmd_valid) return state_.rack_actuator_force_n;
  const double fmax = p_.rack_actuator_force_max_n;
  return std::clamp(servo_force_n(y, z), -fmax, fmax);
}

void SteerByWire::applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept {
  const double tmax = p_.feedback_torque_max_nm;
  const double feedback = std::clamp(inputs_.feedback_torque_cmd_nm, -tmax, tmax);
  q(0) = hand_torque_nm(y, z) + feedback - p_.column_damping_nmspr * z(0);
  q(1) = rack_actuator_force_n(y, z) - p_.rack_actuator_damping_nspm * z(1);
}

void SteerByWire::force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                                  Matrix& dq_dz) const noexcept {
  const double robot_c = p_.torque_input ? 0.0 : p_.robot_stiffness_nmpr;
  const double robot_d = p_.torque_input ? 0.0 : p_.robot_damping_nmspr;
  // the servo is stiff (that is why it is implicit); saturated it is a constant force
  const bool servo_linear = inputs_.rack_position_cmd_valid &&
                            std::abs(servo_force_n(y, z)) < p_.rack_actuator_force_max_n;
  const double kp = servo_linear ? servo_stiffness_npm_ : 0.0;
  const double kd = servo_linear ? servo_damping_nspm_ : 0.0;
  dq_dy << -robot_c, 0, 0, -kp;
  dq_dz << -robot_d - p_.column_damping_nmspr, 0, 0, -kd - p_.rack_actuator_damping_nspm;
}

double SteerByWire::torsion_bar_torque_nm(const Vector& y, const Vector& z) const noexcept {
  return hand_torque_nm(y, z);  // the hand-wheel's torque sensor: the rim's torque
}

double SteerByWire::assist_torque_nm(const Vector& y, const Vector& z) const noexcept {
  return rack_actuator_force_n(y, z) * p_.rack_per_pinion_m_per_rad;
}

}  // namespace rig::model::vehicle
