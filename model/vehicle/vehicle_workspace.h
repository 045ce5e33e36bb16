#pragma once
/// @file
/// What one step derives and hands from block to block (the sequential order of eq. 8: force
/// elements, subsystems, framework), apart from the state: the suspension pose of eq. (29) and
/// the tire contacts at the start of the step, the subsystems' torques and forces within it, and
/// the outputs at its end. Each field has one writer (named in its comment); the blocks read it.

#include <array>
#include <cmath>

#include "model/tire/tmeasy_tire.h"
#include "model/vehicle/local_road_plane.h"
#include "model/vehicle/vehicle_state.h"

namespace rig::model::vehicle {

/// What one wheel contributes at one framework state (the framework's wheel_forces()).
struct WheelForces {
  double load_n = 0;
  double force_x_n = 0;
  double force_y_n = 0;
  double slip_x = 0;
  double slip_y = 0;
  double suspension_n = 0;  ///< pushes the wheel down (compression +)
  // a wheel of a rigid axle (rigid_axle.h): its hub travel and the axle's heave and roll
  bool rigid_axle = false;
  double hub_travel_m = 0;
  double axle_heave_m = 0;
  double axle_roll_rad = 0;
  tire::TireKinematics tire{};  ///< what the tire saw: v_x, v_y, omega, r_D
};

struct WheelWork {
  // ---- eq. (29) at y_V(k) (SuspensionKinematics::update) ----
  double hub_travel_m = 0;         ///< z(k), where the pose was evaluated
  double hub_x_m = 0;              ///< wheel-centre offset from the design position, body x
  double hub_y_m = 0;              ///< body y
  double hub_dx_ds = 0;            ///< dx/dz: the centre moves along (dx/dz, dy/dz, 1)
  double hub_dy_ds = 0;            ///< dy/dz
  double camber_rad = 0;           ///< alpha (rotation about body x)
  double steer_kinematic_rad = 0;  ///< gamma(z(k), u(k))
  double steer_d_du = 0;           ///< dgamma/du at (z(k), u(k))
  double steer_at_rack_m = 0;      ///< u(k), where gamma was evaluated
  // ---- orientation (kinematics, then the wheel-spin stage's tie rods): set_wheel_orientation
  double steer_rad = 0;            ///< gamma: toe + steer from the rack
  Vec3 spin_axis = Vec3::UnitY();  ///< Rz(steer) Rx(camber) e_y, body axes
  // ---- the road under the wheel (VehicleBlocks::update_contacts at y_V(k)) ----
  /// The step's local road plane (local_road_plane.h; every contact evaluation of the step uses
  /// it). On the plane road (road::Road::is_plane) it stays z = 0, e_z: the road is asked directly.
  LocalRoadPlane road{};
  ProbeHints probe_hints{};  ///< the four probes' last cells (speed only, not results)
  double road_z_m = 0;       ///< the road's height under the wheel (update_outputs)
  // ---- the tire at the start of the step (VehicleModel's contacts) ----
  double load_n = 0;         ///< F_z at y_V(k), z_V(k)
  double road_friction = 1;  ///< mu of the road under the wheel (the bore torque's limit)
  tire::TireContact tire{};  ///< characteristic at F_z and mu, kinematics, f
  // ---- subsystems within the step (WheelSpinStage) ----
  double tie_rod_force_n = 0;  ///< resisting rack force from this wheel's aligning torque
  double shaft_torque_nm = 0;  ///< half-shaft torque on the wheel
  double brake_torque_nm = 0;  ///< applied brake (+ rolling resistance) torque, signed
  // ---- at the end of the step (VehicleModel::finish_step) ----
  WheelForces out{};
};

/// Sets steer (gamma) and camber (alpha) of a wheel and its spin axis Rz(gamma) Rx(alpha) e_y,
/// once per change, so that the contact kinematics need no trigonometry.
inline void set_wheel_orientation(WheelWork& w, double steer_rad, double camber_rad) noexcept {
  w.steer_rad = steer_rad;
  w.camber_rad = camber_rad;
  const double cos_camber = std::cos(camber_rad);
  w.spin_axis = Vec3(-std::sin(steer_rad) * cos_camber, std::cos(steer_rad) * cos_camber,
                     std::sin(camber_rad));
}

struct VehicleWorkspace {
  int wheel_count = 0;
  /// The step's look-ahead h (VehicleBlocks::update_contacts; 0 for outputs): a subsystem that
  /// reads the chassis (the free bodies) takes it at y_V(k) + h K^-1 z_V(k), as the step
  /// evaluates its own forces at its predicted coordinates (eq. 6).
  double lookahead_s = 0;
  std::array<WheelWork, kMaxWheels> wheels{};
  // drive train (VehicleModel::begin_step from the step's start state: frozen over the step;
  // the wheel-spin stage for the carrier speed)
  double turbine_ratio =
      0;  ///< turbine speed / carrier speed: gear x final drive (signed; 0 neutral)
  double output_ratio = 0;     ///< carrier torque / turbine torque (before efficiency); in a shift
                               ///< it differs from turbine_ratio by the slipping clutch's share
  double lockup_fraction = 0;  ///< lock-up clutch engagement [0..1]
  double engine_torque_cut_nm = 0;  ///< the shift's engine torque reduction (inertia phase)
  double carrier_speed_radps = 0;   ///< differential input speed in wheel units, newest
  // steering (the wheel-spin stage for the rack force; finish_step for the rest)
  double rack_force_n = 0;  ///< sum of the tie-rod forces on the rack
  /// d(rack force)/d(rack travel) of the sticking bore torques through the tie rods (the
  /// simple model's implicit partial of its lagged rack force) [N/m]
  double rack_bore_stiffness_npm = 0;
  double rack_force_at_m = 0;  ///< the rack travel where rack_force_n was evaluated
  /// The first steered axle's left and right tie-rod forces on the rack (ModelReport).
  double tie_rod_force_left_n = 0;
  double tie_rod_force_right_n = 0;
  double torsion_bar_torque_nm = 0;
  double assist_torque_nm = 0;  ///< applied (input or boost curve)
  double engine_torque_nm = 0;
  /// The configured differentials' speeds and locks at the end of the step (0: none configured).
  int differential_count = 0;
  std::array<DifferentialReport, kMaxDifferentials> differentials{};
};

}  // namespace rig::model::vehicle
