#pragma once
/// @file
/// A fixed-size, plain-data picture of the model's state for tools (LCM, logs, plots). Filled by
/// the model after each step on request; copied by value through the snapshot ring.

#include <array>
#include <cstdint>

namespace rig::model {

inline constexpr int kMaxUnits = 4;              ///< vehicles in a combination
inline constexpr int kMaxWheelsPerUnit = 12;     ///< up to 6 axles with 2 wheels
inline constexpr int kMaxJoints = 3;             ///< couplings between units
inline constexpr int kMaxDifferentials = 8;      ///< of a drive train (model/vehicle/differential)
inline constexpr int kMaxFreeBodiesPerUnit = 4;  ///< cab, engine, seat, ... (`[[free_body]]`)

struct WheelReport {
  double spin_radps = 0;      ///< wheel spin rate
  double slip_x = 0;          ///< longitudinal slip [-]
  double slip_y = 0;          ///< lateral slip [-]
  double force_x_n = 0;       ///< longitudinal tire force
  double force_y_n = 0;       ///< lateral tire force
  double load_n = 0;          ///< vertical tire force
  double deflection_x_m = 0;  ///< tire deflection x_e, eq. (24)
  double deflection_y_m = 0;  ///< tire deflection y_e
  double hub_travel_m = 0;    ///< suspension travel
  double steer_angle_rad = 0;
  double brake_torque_nm = 0;
  double brake_pressure_pa = 0;  ///< the pressure the model applied (wheel input or circuit)
  double drive_torque_nm = 0;
  // what the tire saw (model/tire's TireKinematics and the load of its characteristic): with
  // the road's mu and the deflections these reproduce force_x_n, force_y_n exactly
  double long_speed_mps = 0;    ///< contact point velocity along the tire's heading, v_x
  double lat_speed_mps = 0;     ///< contact point velocity lateral, v_y
  double rolling_radius_m = 0;  ///< dynamic rolling radius r_D
  double tire_load_n = 0;       ///< F_z of the step's start, where the characteristic was taken
  // the road under the wheel: its local plane of the step (road frame; the plane road: z = 0,
  // e_z, whose grade and bank tilt gravity instead)
  double road_z_m = 0;       ///< the road's height under the wheel: the plane at the probes' centre
  double road_normal_x = 0;  ///< upward unit normal of the road there, road frame
  double road_normal_y = 0;
  double road_normal_z = 1;
  double road_mu = 1;  ///< the friction scale the tire takes (1: its data as given)
  /// The wheel's rigid axle (model/vehicle/rigid_axle.h): heave (up +) and roll (+ left wheel up)
  /// against the body, alike for both its wheels; 0 on an independent axle.
  double axle_heave_m = 0;
  double axle_roll_rad = 0;
  /// A rigid axle on leaf springs (model/vehicle/leaf_axle.h), else 0: the axle's wind-up
  /// (pitch against the frame, about +y) and fore-aft travel from rest (alike for both wheels);
  /// this side's leaf: shackle angle from the vertical, its eye links' directions (front A-E,
  /// rear B-R, rad from +x towards +z), Newton iterations in the step's balance.
  double leaf_windup_rad = 0;
  double leaf_fore_aft_m = 0;
  double leaf_shackle_rad = 0;
  double leaf_front_link_rad = 0;
  double leaf_rear_link_rad = 0;
  double leaf_iterations = 0;
  /// A leaf balance's axle (model/vehicle/leaf_balance.h), else 0: this side's rocker angle from
  /// level [rad, front end up +], the same on both axles of the tandem.
  double leaf_rocker_rad = 0;
  /// 1: slip_x, slip_y mean a slip (the wheel moves at least slip_mask_speed_mps); 0: stand-still
  /// or creeping, the raw values are kept but are not slips an ECU should act on
  std::int8_t slip_valid = 1;
};

struct UnitReport {
  std::array<double, 3> position_m{};              ///< CG in the road frame
  std::array<double, 3> orientation_rad{};         ///< roll, pitch, yaw
  std::array<double, 3> velocity_mps{};            ///< CG velocity, body axes
  std::array<double, 3> angular_velocity_radps{};  ///< body axes
  std::array<double, 3> acceleration_mps2{};       ///< CG acceleration, body axes
  /// Frame torsion (`[frame]`, model/vehicle/frame): the rear part's roll against the front
  /// (+ left side up), its rate, the moment the frame transmits; 0 without [frame].
  double frame_twist_rad = 0;
  double frame_twist_rate_radps = 0;
  double frame_torsion_moment_nm = 0;
  std::int32_t wheel_count = 0;
  std::array<WheelReport, kMaxWheelsPerUnit> wheels{};
};

struct SteeringReport {
  double wheel_angle_rad = 0;
  double wheel_speed_radps = 0;
  double wheel_torque_nm = 0;  ///< driver hand torque
  double torsion_bar_torque_nm = 0;
  double rack_travel_m = 0;
  double rack_force_n = 0;
  double assist_torque_nm = 0;
  /// The drag links' / tie rods' forces on the rack from the first steered axle's left and right
  /// wheels (F_S1, F_S2 of Fig. 7), resisting positive rack travel [N]; their sum is rack_force_n
  /// for a one-steered-axle vehicle. What a rack-in-the-loop bench's load actuators apply.
  double tie_rod_force_left_n = 0;
  double tie_rod_force_right_n = 0;
};

struct DrivetrainReport {
  double engine_speed_radps = 0;
  double engine_torque_nm = 0;
  std::int32_t gear = 0;
};

/// A configured differential (model/vehicle/differential/README.md): its speeds at the wheels'
/// scale (after the final drive) and whether it turns as one.
struct DifferentialReport {
  double input_speed_radps = 0;
  double output_a_speed_radps = 0;  ///< side a: the left wheel, or the first group of axles
  double output_b_speed_radps = 0;  ///< side b: the right wheel, or the second group
  std::int32_t locked = 0;          ///< 1: locked (by its kind or the driver) or its clutch sticks
};

struct JointReport {
  std::array<double, 3> force_n{};  ///< constraint force on the leading unit, road frame
  double violation_m = 0;           ///< |g|
  double rod_force_n = 0;           ///< tow bar: the rod force, tension positive (else 0)
  std::int32_t newton_iterations = 0;
};

/// A free body (model/vehicle/free_body) relative to its chassis: its CG from the design
/// position and roll, pitch, yaw (chassis axes), their rates (the relative angular velocity,
/// chassis axes). A seat: z and its rate only.
struct FreeBodyReport {
  std::array<double, 3> position_m{};
  std::array<double, 3> orientation_rad{};  ///< roll, pitch, yaw
  std::array<double, 3> velocity_mps{};
  std::array<double, 3> angular_velocity_radps{};
  std::int8_t on_stop = 0;  ///< 1: a mount beyond its stop clearance
};

/// Everything a tool may want to see of the model at one instant.
struct ModelReport {
  double time_s = 0;
  std::int32_t unit_count = 0;
  std::array<UnitReport, kMaxUnits> units{};
  SteeringReport steering{};
  DrivetrainReport drivetrain{};
  /// The first unit's differentials as configured ([[drivetrain.differential]], then the
  /// implicit open axle differentials); 0 without any configured (open differentials throughout).
  std::int32_t differential_count = 0;
  std::array<DifferentialReport, kMaxDifferentials> differentials{};
  std::array<double, 4> brake_pressure_pa{};  ///< FL, FR, RL, RR of the first unit
  std::int32_t joint_count = 0;
  std::array<JointReport, kMaxJoints> joints{};
  /// The leading unit's free bodies, in `[[free_body]]` order (0: none).
  std::int32_t body_count = 0;
  std::array<FreeBodyReport, kMaxFreeBodiesPerUnit> bodies{};
  // ---- validity (written by the rig's executive each cycle, not by the model) ----
  /// 1: the model's current state; 0: after a vehicle fault, the last fault-free state (held
  /// or stopped), every quantity above is then invalid.
  std::int32_t valid = 1;
  std::int32_t fault_kind = 0;   ///< model::FaultKind of the fault (0: none)
  std::int32_t fault_unit = -1;  ///< its unit (-1: none, or the coupling of a combination)
};

}  // namespace rig::model
