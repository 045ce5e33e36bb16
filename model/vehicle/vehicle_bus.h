#pragma once
/// @file
/// The newest shared quantities of the vehicle's blocks within one step (who reads what is
/// the sequential order of eq. 8: force elements, subsystems, framework). Plain data owned by
/// VehicleModel; every block holds a reference.

#include <array>
#include <cmath>

#include "model/report.h"
#include "model/vehicle/chassis_kinematics.h"
#include "model/vehicle/tmeasy.h"

namespace rig::model::vehicle {

inline constexpr int kMaxWheels = kMaxWheelsPerUnit;

/// One wheel's state as seen by the other blocks.
struct WheelBus {
  // contact kinematics at the start of the step (y_V(k), z_V(k))
  double vx_mps = 0;
  double vy_mps = 0;
  double load_n = 0;
  double radius_dynamic_m = 0.3;
  TmeasyLoadCurves curves{};
  double f_per_slip = 0;  ///< f(s) of eq. (16) at the start of the step (used by eq. 24)
  // subsystems
  double spin_radps = 0;       ///< wheel spin state (owned by WheelSpinStage)
  double steer_rad = 0;        ///< gamma of eq. (29): toe + steer from the rack (tie rod)
  double tie_rod_force_n = 0;  ///< resisting rack force from this wheel's aligning torque
  // suspension kinematics of eq. (29) at the start of the step (SuspensionKinematics::update)
  double hub_travel_m = 0;  ///< z(k), where the pose was evaluated
  double hub_x_m = 0;       ///< wheel-centre offset from the design position, body x
  double hub_y_m = 0;       ///< body y
  double hub_dx_ds = 0;     ///< dx/dz: the centre moves along (dx/dz, dy/dz, 1)
  double hub_dy_ds = 0;     ///< dy/dz
  double camber_rad = 0;    ///< alpha (rotation about body x)
  /// Wheel spin axis in body axes, Rz(steer) Rx(camber) e_y (set_wheel_orientation).
  Vec3 spin_axis = Vec3::UnitY();
  double steer_kinematic_rad = 0;  ///< gamma(z(k), u(k))
  double steer_d_du = 0;           ///< dgamma/du at (z(k), u(k))
  double steer_at_rack_m = 0;      ///< u(k), where gamma was evaluated
  double rack_at_wheel_m = 0;      ///< rack travel at the wheel after the tie-rod compliance
  double shaft_torque_nm = 0;      ///< half-shaft torque on the wheel
  double brake_capacity_nm = 0;    ///< from the wheel brake pressure
  double brake_pressure_pa = 0;
  double brake_torque_nm = 0;  ///< applied brake torque (signed, on the wheel)
  // tire forces of the last framework step (for reports and the aligning torque)
  double force_x_n = 0;
  double force_y_n = 0;
  double slip_x = 0;
  double slip_y = 0;
};

/// Sets steer (gamma) and camber (alpha) of a wheel and its spin axis Rz(gamma) Rx(alpha) e_y,
/// once per change, so that the contact kinematics need no trigonometry.
inline void set_wheel_orientation(WheelBus& w, double steer_rad, double camber_rad) noexcept {
  w.steer_rad = steer_rad;
  w.camber_rad = camber_rad;
  const double cos_camber = std::cos(camber_rad);
  w.spin_axis = Vec3(-std::sin(steer_rad) * cos_camber, std::cos(steer_rad) * cos_camber,
                     std::sin(camber_rad));
}

struct VehicleBus {
  int wheel_count = 0;
  std::array<WheelBus, kMaxWheels> wheels{};
  std::array<double, std::size_t{kMaxWheels} * 2>
      deflection_m{};  ///< x_e, y_e per wheel (tire elements)
  // drivetrain
  double throttle = 0;
  int gear = 0;
  double total_ratio = 0;          ///< gear ratio x final drive (signed; 0 in neutral)
  double carrier_speed_radps = 0;  ///< differential input speed in wheel units
  double engine_torque_nm = 0;
  // steering
  double steering_angle_cmd_rad = 0;
  double hand_torque_cmd_nm = 0;
  bool assist_from_input = false;
  double assist_input_nm = 0;
  double assist_torque_nm = 0;  ///< applied (input or boost curve)
  double torsion_bar_torque_nm = 0;
  double rack_force_n = 0;
};

}  // namespace rig::model::vehicle
