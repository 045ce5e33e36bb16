#pragma once
/// @file
/// Everything of one vehicle that evolves from step to step, in one struct (as MuJoCo's mjData
/// state part): the framework's coordinates and speeds (eq. 1), the subsystems' (eq. 2), the
/// force elements' states (eq. 3), the gearbox's discrete state and the quasi-static memory that
/// one step hands to the next. Saving, restoring, checking and resetting are one line each; the
/// blocks of model/vehicle hold references into it and own no state of their own.

#include <array>

#include <Eigen/Core>

#include "model/report.h"
#include "model/vehicle/chassis_kinematics.h"
#include "model/vehicle/leaf_axle_state.h"
#include "model/vehicle/leaf_balance_state.h"
#include "model/vehicle/vehicle_params.h"

namespace rig::model::vehicle {

inline constexpr int kMaxWheels = kMaxWheelsPerUnit;

struct VehicleState {
  double time_s = 0;
  // ---- framework (eq. 1), sized 6 + wheel count ----
  Eigen::VectorXd framework_y;  ///< x, y, z (CG, road frame), yaw, pitch, roll, hub travel s_i
  Eigen::VectorXd framework_z;  ///< body velocity and angular velocity (body axes), s_i'
  // ---- subsystems (eq. 2) ----
  Eigen::Vector2d steering_y = Eigen::Vector2d::Zero();    ///< steering wheel angle, rack travel
  Eigen::Vector2d steering_z = Eigen::Vector2d::Zero();    ///< their rates
  Eigen::Vector2d drivetrain_y = Eigen::Vector2d::Zero();  ///< engine and carrier angle
  Eigen::Vector2d drivetrain_z = Eigen::Vector2d::Zero();  ///< engine speed w_e, carrier w_c
  std::array<double, kMaxWheels> spin_radps{};             ///< wheel spin rates
  /// Free bodies (model/vehicle/free_body), slot = `[[free_body]]` index: a cab's or engine's
  /// [x, y, z (road frame), yaw, pitch, roll] and [v, omega] (own axes); a seat's height and rate.
  std::array<Eigen::Matrix<double, 6, 1>, kMaxFreeBodies> free_body_y{};
  std::array<Eigen::Matrix<double, 6, 1>, kMaxFreeBodies> free_body_z{};
  std::array<Eigen::Matrix<double, 1, 1>, kMaxFreeBodies> seat_y{};
  std::array<Eigen::Matrix<double, 1, 1>, kMaxFreeBodies> seat_z{};
  // ---- force elements (eq. 3) ----
  std::array<Eigen::Vector2d, kMaxWheels> tire_deflection_m{};  ///< x_e, y_e (eqs. 22-24)
  Eigen::VectorXd shaft_twist_rad;                              ///< one per driven wheel
  // ---- discrete: the automatic gearbox ----
  int gear = 0;                    ///< engaged, or being engaged during a shift
  double last_shift_s = -1e9;      ///< start of the last shift
  int shift_from_gear = 0;         ///< the gear being left while a timed shift runs, else 0
  bool shift_torque_first = true;  ///< phase order: torque phase first (power-on upshift)
  double shift_inertia_s = 0;      ///< the running shift's inertia phase (stretched at part load)
  double lockup_fraction = 0;      ///< the lock-up clutch's engagement [0..1] (ramped in)
  /// The overriding gear's angle at the pinion and its rate over the last step: the overlay
  /// command, followed at most at SteeringParams::overlay_rate_max_radps.
  double overlay_rad = 0;
  double overlay_rate_radps = 0;
  /// The overlay motor's angle behind the superposition gear: overlay_ratio x overlay_rad.
  double overlay_motor_rad = 0;
  /// Steer-by-wire: the road-wheel actuator's force on the rack under a force command (its
  /// first-order lag; 0 without a valid force command) [N].
  double rack_actuator_force_n = 0;
  /// Steer-by-wire: the position servo's integral term (with k_p u of the handover) [N].
  double rack_servo_integral_n = 0;
  // ---- quasi-static memory of the last step ----
  /// Rack travel at the wheel after the tie-rod compliance: where eq. (29) is evaluated next.
  /// (Enhanced steering: the knuckle's coordinate, its steer as rack-equivalent travel.)
  std::array<double, kMaxWheels> rack_at_wheel_m{};
  /// Enhanced steering: each knuckle's speed d(rack_at_wheel_m)/dt (0 with the simple model).
  std::array<double, kMaxWheels> knuckle_rate_mps{};
  /// Tire lateral force: its aligning torque loads the rack in the next step.
  std::array<double, kMaxWheels> lateral_force_n{};
  /// Tire longitudinal force and half-shaft torque: their moments about the steering axis load
  /// the rack in the next step (steering_axis.h).
  std::array<double, kMaxWheels> long_force_n{};
  std::array<double, kMaxWheels> shaft_torque_nm{};
  /// The contact patch's torsional deflection phi of the bore torque (model/tire/tmeasy_bore.h).
  std::array<double, kMaxWheels> bore_twist_rad{};
  /// Its torque at the end of the last step [N m] (the enhanced model takes it at the step's
  /// start).
  std::array<double, kMaxWheels> bore_torque_nm{};
  /// Rigid axles on leaf springs (leaf_axle.h), in axle order: the leaves' warm starts and the
  /// condensed fore-aft travel and wind-up (set at rest by the axle's element on a reset).
  std::array<LeafAxleState, kMaxLeafAxles> leaf_axles{};
  /// Leaf balances (leaf_balance.h): the rocker angles and the group's warm start (at rest after
  /// a reset, as the leaf axles).
  std::array<LeafBalanceState, kMaxLeafBalances> leaf_balances{};
  /// CG acceleration over the last step, body axes (from z(k+1) - z(k)).
  Vec3 acceleration_mps2 = Vec3::Zero();
};

/// A state sized for the vehicle (allocates; construction time only).
[[nodiscard]] VehicleState make_state(const VehicleParams& params, int driven_wheel_count);

/// At rest at the design position at (x, y, yaw) with the engine idling, gear 0 (no allocation).
void place_at_rest(VehicleState& s, const VehicleParams& params, double x_m, double y_m,
                   double yaw_rad) noexcept;

/// Every entry finite (the step's NaN/inf guard).
[[nodiscard]] bool is_finite(const VehicleState& s) noexcept;

}  // namespace rig::model::vehicle
