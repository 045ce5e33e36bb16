#include "model/vehicle/steering/column_steering.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rig::model::vehicle {

ColumnSteering::ColumnSteering(const SteeringParams& p, VehicleState& state,
                               const VehicleInputs& inputs)
    : p_(p), state_(state), inputs_(inputs) {}

void ColumnSteering::begin_step(double h) noexcept {
  // The overriding gear: the command is the overlay at the pinion; its position-controlled motor
  // (a first-order lag at overlay_bandwidth_hz, exact over the step; none at 0) moves it, at
  // most at its speed limit.
  double want = inputs_.overlay_angle_rad - state_.overlay_rad;
  if (p_.overlay_bandwidth_hz > 0)
    want *= -std::expm1(-2 * std::numbers::pi * p_.overlay_bandwidth_hz * h);
  const double max_step = p_.overlay_rate_max_radps * h;
  const double move = std::clamp(want, -max_step, max_step);
  state_.overlay_rad += move;
  state_.overlay_rate_radps = move / h;
  // the superposition gear: pinion angle = wheel-side angle + motor angle / i_ov
  state_.overlay_motor_rad = p_.overlay_ratio * state_.overlay_rad;
}

void ColumnSteering::mass_matrix(const Vector& y, Matrix& m) const noexcept {
  (void)y;
  m << p_.wheel_inertia_kgm2, 0, 0, p_.rack_mass_kg;
}

double ColumnSteering::torsion_bar_torque_nm(const Vector& y, const Vector& z) const noexcept {
  const double i = p_.rack_per_pinion_m_per_rad;
  // the overriding gear turns the pinion against the torsion bar's lower end: that end is at
  // u / i_SB - overlay (the overlay as its rate limit lets it follow the command)
  return p_.torsion_bar_stiffness_nmpr * (y(0) - y(1) / i + state_.overlay_rad) +
         p_.torsion_bar_damping_nmspr * (z(0) - z(1) / i + state_.overlay_rate_radps);
}

double ColumnSteering::assist_for_torsion_bar_nm(double torsion_bar_nm) const noexcept {
  if (!inputs_.ignition_on) return 0.0;  // the EPS is not powered
  if (inputs_.assist_from_input) return inputs_.assist_input_nm;
  return p_.assist_max_nm * std::tanh(p_.assist_gain * torsion_bar_nm / p_.assist_max_nm);
}

double ColumnSteering::active_return_speed_weight() const noexcept {
  const ActiveReturnParams& r = p_.active_return;
  if (r.torque_max_nm <= 0 || !inputs_.ignition_on || inputs_.assist_from_input) return 0.0;
  // f(v): the trapezoid over the vehicle's speed
  const double v = std::abs(state_.framework_z(0));
  const auto ramp = [](double x, double from, double to) {
    return to > from ? std::clamp((x - from) / (to - from), 0.0, 1.0) : (x >= to ? 1.0 : 0.0);
  };
  return ramp(v, r.speed_mps[0], r.speed_mps[1]) * (1.0 - ramp(v, r.speed_mps[2], r.speed_mps[3]));
}

double ColumnSteering::active_return_demand_nm(const Vector& y, const Vector& z) const noexcept {
  const ActiveReturnParams& r = p_.active_return;
  const double i = p_.rack_per_pinion_m_per_rad;
  const double theta = y(1) / i, theta_rate = z(1) / i;  // the pinion (the EPS motor's sensor)
  return -(r.torque_max_nm * std::clamp(theta / r.saturation_angle_rad, -1.0, 1.0) +
           r.damping_nmspr * theta_rate);
}

double ColumnSteering::active_return_nm(const Vector& y, const Vector& z,
                                        double torsion_bar_nm) const noexcept {
  const double f_v = active_return_speed_weight();
  if (f_v == 0.0) return 0.0;
  // the driver's hands fade it out
  const double hands = std::max(0.0, 1.0 - std::abs(torsion_bar_nm) / p_.active_return.hands_off_nm);
  return f_v * hands * active_return_demand_nm(y, z);
}

double ColumnSteering::assist_torque_nm(const Vector& y, const Vector& z) const noexcept {
  const double tb = torsion_bar_torque_nm(y, z);
  return assist_for_torsion_bar_nm(tb) + active_return_nm(y, z, tb);
}

void ColumnSteering::applied_forces(const Vector& y, const Vector& z, Vector& q) const noexcept {
  const double tb = torsion_bar_torque_nm(y, z);
  double hand = inputs_.hand_torque_cmd_nm;
  if (!p_.torque_input && !inputs_.robot_released) {
    hand = p_.robot_stiffness_nmpr * (inputs_.steering_angle_cmd_rad - y(0)) -
           p_.robot_damping_nmspr * z(0);
  }
  q(0) = hand - tb - p_.column_damping_nmspr * z(0);
  q(1) = (tb + assist_for_torsion_bar_nm(tb) + active_return_nm(y, z, tb)) /
         p_.rack_per_pinion_m_per_rad;
}

SteeringFriction ColumnSteering::dry_friction(const Vector& y, const Vector& z) const noexcept {
  (void)y;
  (void)z;
  return {.column_nm = p_.column_friction_nm, .rack_n = p_.rack_friction_n};
}

void ColumnSteering::force_jacobians(const Vector& y, const Vector& z, Matrix& dq_dy,
                                     Matrix& dq_dz) const noexcept {
  const double i = p_.rack_per_pinion_m_per_rad;
  const double c = p_.torsion_bar_stiffness_nmpr, d = p_.torsion_bar_damping_nmspr;
  double dassist = p_.assist_gain;  // d T_a / d T_tb of the boost curve
  if (inputs_.assist_from_input || !inputs_.ignition_on) {
    dassist = 0;
  } else {
    const double t = std::tanh(p_.assist_gain * torsion_bar_torque_nm(y, z) / p_.assist_max_nm);
    dassist = p_.assist_gain * (1 - t * t);
  }
  const bool robot = !p_.torque_input && !inputs_.robot_released;
  const double robot_c = robot ? p_.robot_stiffness_nmpr : 0.0;
  const double robot_d = robot ? p_.robot_damping_nmspr : 0.0;
  const double g = (1 + dassist) / i;
  dq_dy << -robot_c - c, c / i, g * c, -g * c / i;
  dq_dz << -robot_d - d - p_.column_damping_nmspr, d / i, g * d, -g * d / i;
  // the active return: its slope and damping on the pinion angle, and its fade with the
  // torsion-bar torque (a slope on T_tb like the boost curve's)
  const double f_v = active_return_speed_weight();
  if (f_v > 0) {
    const ActiveReturnParams& r = p_.active_return;
    const double tb = torsion_bar_torque_nm(y, z);
    const double hands = std::max(0.0, 1.0 - std::abs(tb) / r.hands_off_nm);
    const double dhands_dtb = hands > 0 ? -std::copysign(1.0, tb) / r.hands_off_nm : 0.0;
    const double dreturn_dtb = f_v * dhands_dtb * active_return_demand_nm(y, z);
    dq_dy.row(1) += dreturn_dtb / i * Eigen::RowVector2d(c, -c / i);
    dq_dz.row(1) += dreturn_dtb / i * Eigen::RowVector2d(d, -d / i);
    const double theta = y(1) / i;
    const double slope =
        std::abs(theta) < r.saturation_angle_rad ? r.torque_max_nm / r.saturation_angle_rad : 0.0;
    dq_dy(1, 1) -= f_v * hands * slope / (i * i);
    dq_dz(1, 1) -= f_v * hands * r.damping_nmspr / (i * i);
  }
}

}  // namespace rig::model::vehicle
