#include "model/vehicle/vehicle_state.h"

#include <cmath>

namespace rig::model::vehicle {

VehicleState make_state(const VehicleParams& params, int driven_wheel_count) {
  VehicleState s;
  const Eigen::Index n = 6 + 2 * static_cast<Eigen::Index>(params.axles.size()) +
                         (params.frame.enabled ? 1 : 0);  // + the frame's twist, stored last
  s.framework_y = Eigen::VectorXd::Zero(n);
  s.framework_z = Eigen::VectorXd::Zero(n);
  s.shaft_twist_rad = Eigen::VectorXd::Zero(driven_wheel_count);
  for (auto& d : s.tire_deflection_m) d.setZero();
  place_at_rest(s, params, 0, 0, 0);
  return s;
}

void place_at_rest(VehicleState& s, const VehicleParams& params, double x_m, double y_m,
                   double yaw_rad) noexcept {
  s.time_s = 0;
  s.framework_y.setZero();
  s.framework_z.setZero();
  s.framework_y(0) = x_m;
  s.framework_y(1) = y_m;
  s.framework_y(2) = params.chassis.cg_height_m;
  s.framework_y(3) = yaw_rad;
  s.steering_y.setZero();
  s.steering_z.setZero();
  s.drivetrain_y.setZero();
  s.drivetrain_z << params.drivetrain.idle_speed_radps, 0;
  s.spin_radps.fill(0);
  for (std::size_t i = 0; i < kMaxFreeBodies; ++i) {
    s.free_body_y[i].setZero();
    s.free_body_z[i].setZero();
    s.seat_y[i].setZero();
    s.seat_z[i].setZero();
  }
  for (auto& d : s.tire_deflection_m) d.setZero();
  s.shaft_twist_rad.setZero();
  s.gear = 0;
  s.last_shift_s = -1e9;
  s.shift_from_gear = 0;
  s.shift_torque_first = true;
  s.shift_inertia_s = 0;
  s.lockup_fraction = 0;
  s.overlay_rad = 0;
  s.overlay_rate_radps = 0;
  s.overlay_motor_rad = 0;
  s.rack_actuator_force_n = 0;
  s.rack_servo_integral_n = 0;
  s.rack_at_wheel_m.fill(0);
  s.knuckle_rate_mps.fill(0);
  s.lateral_force_n.fill(0);
  s.long_force_n.fill(0);
  s.shaft_torque_nm.fill(0);
  s.bore_twist_rad.fill(0);
  s.bore_torque_nm.fill(0);
  s.acceleration_mps2.setZero();
}

bool is_finite(const VehicleState& s) noexcept {
  bool ok = std::isfinite(s.time_s) && s.framework_y.allFinite() && s.framework_z.allFinite() &&
            s.steering_y.allFinite() && s.steering_z.allFinite() && s.drivetrain_y.allFinite() &&
            s.drivetrain_z.allFinite() && s.shaft_twist_rad.allFinite() &&
            s.acceleration_mps2.allFinite();
  for (std::size_t i = 0; i < kMaxFreeBodies; ++i) {
    ok = ok && s.free_body_y[i].allFinite() && s.free_body_z[i].allFinite() &&
         s.seat_y[i].allFinite() && s.seat_z[i].allFinite();
  }
  for (std::size_t k = 0; k < s.spin_radps.size(); ++k) {
    ok = ok && std::isfinite(s.spin_radps[k]) && s.tire_deflection_m[k].allFinite() &&
         std::isfinite(s.rack_at_wheel_m[k]) && std::isfinite(s.knuckle_rate_mps[k]) &&
         std::isfinite(s.lateral_force_n[k]) && std::isfinite(s.long_force_n[k]) &&
         std::isfinite(s.shaft_torque_nm[k]) && std::isfinite(s.bore_twist_rad[k]) &&
         std::isfinite(s.bore_torque_nm[k]);
  }
  return ok;
}

}  // namespace rig::model::vehicle
