#pragma once
/// @file
/// The one table of what rig.vehicle_state_t (channel RIG_STATE) carries of the model's report:
/// one row per quantity, {LCM member, unit, source in model/report.h, LCM member pointer}. The
/// message builder (message_builder.cpp) fills the message from these rows and rig-log2csv
/// writes a CSV column (arrays: one per element) for each, in the order of the rows.
///
/// A new logged quantity is one row here plus its field in lcmtypes/vehicle_state_t.lcm, e.g.
/// for a new double per wheel `model::WheelReport::camber_rad`:
///     {"wheel_camber_rad", "rad", member<&W::camber_rad>, &S::wheel_camber_rad, "camber_rad"},
///     double  wheel_camber_rad[num_wheels];          (in vehicle_state_t.lcm)
/// tests/io/lcm/field_table_test.py fails until the .lcm, this table and the CSV agree.

#include <cstdint>
#include <string_view>

#include "io/lcm/field_table.h"
#include "model/report.h"
#include "rig/vehicle_state_t.hpp"

namespace rig::io::lcm {

/// The rows, grouped by what they repeat over; groups and rows are in CSV column order.
struct VehicleStateFields {
  using S = rig::vehicle_state_t;
  using R = model::ModelReport;
  using U = model::UnitReport;
  using W = model::WheelReport;
  using J = model::JointReport;
  using D = model::DifferentialReport;
  using B = model::FreeBodyReport;
  using Steering = model::SteeringReport;
  using Drivetrain = model::DrivetrainReport;

  /// Per unit (num_units, tractor first): position and orientation in the road frame,
  /// velocities and accelerations in the unit's body axes.
  static constexpr ArrayField<S, U> kUnit[] = {
      {"unit_x_m", "m", element<&U::position_m, 0>, &S::unit_x_m, "position_x_m"},
      {"unit_y_m", "m", element<&U::position_m, 1>, &S::unit_y_m, "position_y_m"},
      {"unit_z_m", "m", element<&U::position_m, 2>, &S::unit_z_m, "position_z_m"},
      {"unit_roll_rad", "rad", element<&U::orientation_rad, 0>, &S::unit_roll_rad, "roll_rad"},
      {"unit_pitch_rad", "rad", element<&U::orientation_rad, 1>, &S::unit_pitch_rad, "pitch_rad"},
      {"unit_yaw_rad", "rad", element<&U::orientation_rad, 2>, &S::unit_yaw_rad, "yaw_rad"},
      {"unit_vx_mps", "m/s", element<&U::velocity_mps, 0>, &S::unit_vx_mps, "speed_x_mps"},
      {"unit_vy_mps", "m/s", element<&U::velocity_mps, 1>, &S::unit_vy_mps, "speed_y_mps"},
      {"unit_vz_mps", "m/s", element<&U::velocity_mps, 2>, &S::unit_vz_mps, "speed_z_mps"},
      {"unit_wx_radps", "rad/s", element<&U::angular_velocity_radps, 0>, &S::unit_wx_radps,
       "roll_rate_radps"},
      {"unit_wy_radps", "rad/s", element<&U::angular_velocity_radps, 1>, &S::unit_wy_radps,
       "pitch_rate_radps"},
      {"unit_wz_radps", "rad/s", element<&U::angular_velocity_radps, 2>, &S::unit_wz_radps,
       "yaw_rate_radps"},
      {"unit_ax_mps2", "m/s^2", element<&U::acceleration_mps2, 0>, &S::unit_ax_mps2,
       "accel_x_mps2"},
      {"unit_ay_mps2", "m/s^2", element<&U::acceleration_mps2, 1>, &S::unit_ay_mps2,
       "accel_y_mps2"},
      {"unit_az_mps2", "m/s^2", element<&U::acceleration_mps2, 2>, &S::unit_az_mps2,
       "accel_z_mps2"},
      {"unit_frame_twist_rad", "rad", member<&U::frame_twist_rad>, &S::unit_frame_twist_rad,
       "frame_twist_rad"},
      {"unit_frame_twist_rate_radps", "rad/s", member<&U::frame_twist_rate_radps>,
       &S::unit_frame_twist_rate_radps, "frame_twist_rate_radps"},
      {"unit_frame_torsion_moment_nm", "N m", member<&U::frame_torsion_moment_nm>,
       &S::unit_frame_torsion_moment_nm, "frame_torsion_moment_nm"},
  };

  /// Per wheel (num_wheels: every unit's wheels, front to rear, left before right).
  static constexpr ArrayField<S, W> kWheel[] = {
      {"wheel_spin_radps", "rad/s", member<&W::spin_radps>, &S::wheel_spin_radps, "spin_radps"},
      {"wheel_slip_x", "1", member<&W::slip_x>, &S::wheel_slip_x, "slip_x"},
      {"wheel_slip_y", "1", member<&W::slip_y>, &S::wheel_slip_y, "slip_y"},
      {"wheel_force_x_n", "N", member<&W::force_x_n>, &S::wheel_force_x_n, "force_x_n"},
      {"wheel_force_y_n", "N", member<&W::force_y_n>, &S::wheel_force_y_n, "force_y_n"},
      {"wheel_load_n", "N", member<&W::load_n>, &S::wheel_load_n, "load_n"},
      {"wheel_x_e_m", "m", member<&W::deflection_x_m>, &S::wheel_x_e_m, "deflection_x_m"},
      {"wheel_y_e_m", "m", member<&W::deflection_y_m>, &S::wheel_y_e_m, "deflection_y_m"},
      {"wheel_steer_rad", "rad", member<&W::steer_angle_rad>, &S::wheel_steer_rad,
       "steer_angle_rad"},
      {"wheel_brake_torque_nm", "N m", member<&W::brake_torque_nm>, &S::wheel_brake_torque_nm,
       "brake_torque_nm"},
      {"wheel_brake_pressure_pa", "Pa", member<&W::brake_pressure_pa>, &S::wheel_brake_pressure_pa,
       "applied_brake_pressure_pa"},
      {"wheel_drive_torque_nm", "N m", member<&W::drive_torque_nm>, &S::wheel_drive_torque_nm,
       "drive_torque_nm"},
      {"wheel_hub_travel_m", "m", member<&W::hub_travel_m>, &S::wheel_hub_travel_m, "hub_travel_m"},
      {"wheel_long_speed_mps", "m/s", member<&W::long_speed_mps>, &S::wheel_long_speed_mps,
       "long_speed_mps"},
      {"wheel_lat_speed_mps", "m/s", member<&W::lat_speed_mps>, &S::wheel_lat_speed_mps,
       "lat_speed_mps"},
      {"wheel_rolling_radius_m", "m", member<&W::rolling_radius_m>, &S::wheel_rolling_radius_m,
       "rolling_radius_m"},
      {"wheel_tire_load_n", "N", member<&W::tire_load_n>, &S::wheel_tire_load_n, "tire_load_n"},
      {"wheel_road_z_m", "m", member<&W::road_z_m>, &S::wheel_road_z_m, "road_z_m"},
      {"wheel_road_normal_x", "1", member<&W::road_normal_x>, &S::wheel_road_normal_x,
       "road_normal_x"},
      {"wheel_road_normal_y", "1", member<&W::road_normal_y>, &S::wheel_road_normal_y,
       "road_normal_y"},
      {"wheel_road_normal_z", "1", member<&W::road_normal_z>, &S::wheel_road_normal_z,
       "road_normal_z"},
      {"wheel_road_mu", "1", member<&W::road_mu>, &S::wheel_road_mu, "road_mu"},
      {"wheel_axle_heave_m", "m", member<&W::axle_heave_m>, &S::wheel_axle_heave_m, "axle_heave_m"},
      {"wheel_axle_roll_rad", "rad", member<&W::axle_roll_rad>, &S::wheel_axle_roll_rad,
       "axle_roll_rad"},
      {"wheel_leaf_windup_rad", "rad", member<&W::leaf_windup_rad>, &S::wheel_leaf_windup_rad,
       "leaf_windup_rad"},
      {"wheel_leaf_fore_aft_m", "m", member<&W::leaf_fore_aft_m>, &S::wheel_leaf_fore_aft_m,
       "leaf_fore_aft_m"},
      {"wheel_leaf_shackle_rad", "rad", member<&W::leaf_shackle_rad>, &S::wheel_leaf_shackle_rad,
       "leaf_shackle_rad"},
      {"wheel_leaf_front_link_rad", "rad", member<&W::leaf_front_link_rad>,
       &S::wheel_leaf_front_link_rad, "leaf_front_link_rad"},
      {"wheel_leaf_rear_link_rad", "rad", member<&W::leaf_rear_link_rad>,
       &S::wheel_leaf_rear_link_rad, "leaf_rear_link_rad"},
      {"wheel_leaf_iterations", "1", member<&W::leaf_iterations>, &S::wheel_leaf_iterations,
       "leaf_iterations"},
      {"wheel_leaf_rocker_rad", "rad", member<&W::leaf_rocker_rad>, &S::wheel_leaf_rocker_rad,
       "leaf_rocker_rad"},
  };

  /// Per wheel, flags: 1 valid, 0 not.
  static constexpr ArrayField<S, W, std::int8_t> kWheelFlag[] = {
      {"wheel_slip_valid", "1", member<&W::slip_valid>, &S::wheel_slip_valid, "slip_valid"},
  };

  /// Once per message: steering, drive train, the first unit's brake pressures.
  static constexpr ScalarField<S, R> kVehicle[] = {
      {"steering_wheel_angle_rad", "rad", member<&R::steering, &Steering::wheel_angle_rad>,
       &S::steering_wheel_angle_rad, "steering.wheel_angle_rad"},
      {"steering_wheel_speed_radps", "rad/s", member<&R::steering, &Steering::wheel_speed_radps>,
       &S::steering_wheel_speed_radps, "steering.wheel_speed_radps"},
      {"steering_wheel_torque_nm", "N m", member<&R::steering, &Steering::wheel_torque_nm>,
       &S::steering_wheel_torque_nm, "steering.wheel_torque_nm"},
      {"torsion_bar_torque_nm", "N m", member<&R::steering, &Steering::torsion_bar_torque_nm>,
       &S::torsion_bar_torque_nm, "steering.torsion_bar_torque_nm"},
      {"rack_travel_m", "m", member<&R::steering, &Steering::rack_travel_m>, &S::rack_travel_m,
       "steering.rack_travel_m"},
      {"rack_force_n", "N", member<&R::steering, &Steering::rack_force_n>, &S::rack_force_n,
       "steering.rack_force_n"},
      {"assist_torque_nm", "N m", member<&R::steering, &Steering::assist_torque_nm>,
       &S::assist_torque_nm, "steering.assist_torque_nm"},
      {"tie_rod_force_left_n", "N", member<&R::steering, &Steering::tie_rod_force_left_n>,
       &S::tie_rod_force_left_n, "steering.tie_rod_force_left_n"},
      {"tie_rod_force_right_n", "N", member<&R::steering, &Steering::tie_rod_force_right_n>,
       &S::tie_rod_force_right_n, "steering.tie_rod_force_right_n"},
      {"engine_speed_radps", "rad/s", member<&R::drivetrain, &Drivetrain::engine_speed_radps>,
       &S::engine_speed_radps, "drivetrain.engine_speed_radps"},
      {"engine_torque_nm", "N m", member<&R::drivetrain, &Drivetrain::engine_torque_nm>,
       &S::engine_torque_nm, "drivetrain.engine_torque_nm"},
      {"brake_pressure_fl_pa", "Pa", element<&R::brake_pressure_pa, 0>, &S::brake_pressure_fl_pa,
       ""},
      {"brake_pressure_fr_pa", "Pa", element<&R::brake_pressure_pa, 1>, &S::brake_pressure_fr_pa,
       ""},
      {"brake_pressure_rl_pa", "Pa", element<&R::brake_pressure_pa, 2>, &S::brake_pressure_rl_pa,
       ""},
      {"brake_pressure_rr_pa", "Pa", element<&R::brake_pressure_pa, 3>, &S::brake_pressure_rr_pa,
       ""},
  };
  /// Integers once per message (CSV: after the doubles).
  static constexpr ScalarField<S, R, std::int32_t> kVehicleInt[] = {
      {"gear", "1", member<&R::drivetrain, &Drivetrain::gear>, &S::gear, "drivetrain.gear"},
      {"model_valid", "1", member<&R::valid>, &S::model_valid, ""},
      {"model_fault_kind", "1", member<&R::fault_kind>, &S::model_fault_kind, ""},
      {"model_fault_unit", "1", member<&R::fault_unit>, &S::model_fault_unit, ""},
  };

  /// Per joint of a combination (num_joints; joint i couples unit i and unit i + 1): the
  /// constraint force on the leading unit, road frame.
  static constexpr ArrayField<S, J> kJoint[] = {
      {"joint_force_x_n", "N", element<&J::force_n, 0>, &S::joint_force_x_n, "force_x_n"},
      {"joint_force_y_n", "N", element<&J::force_n, 1>, &S::joint_force_y_n, "force_y_n"},
      {"joint_force_z_n", "N", element<&J::force_n, 2>, &S::joint_force_z_n, "force_z_n"},
      {"joint_violation_m", "m", member<&J::violation_m>, &S::joint_violation_m, "violation_m"},
      {"joint_rod_force_n", "N", member<&J::rod_force_n>, &S::joint_rod_force_n, "rod_force_n"},
  };

  /// Per differential of the first unit (num_diffs; 0 without [[drivetrain.differential]]).
  static constexpr ArrayField<S, D> kDiff[] = {
      {"diff_input_speed_radps", "rad/s", member<&D::input_speed_radps>, &S::diff_input_speed_radps,
       "input_speed_radps"},
      {"diff_output_a_speed_radps", "rad/s", member<&D::output_a_speed_radps>,
       &S::diff_output_a_speed_radps, "output_a_speed_radps"},
      {"diff_output_b_speed_radps", "rad/s", member<&D::output_b_speed_radps>,
       &S::diff_output_b_speed_radps, "output_b_speed_radps"},
  };
  /// Per differential, integers: 1 locked, 0 not.
  static constexpr ArrayField<S, D, std::int32_t> kDiffFlag[] = {
      {"diff_locked", "1", member<&D::locked>, &S::diff_locked, "locked"},
  };

  /// Per free body of the leading unit (num_bodies, `[[free_body]]` order; model/vehicle/
  /// free_body): its motion relative to the chassis. Absent (no CSV columns) without bodies.
  static constexpr ArrayField<S, B> kBody[] = {
      {"body_x_m", "m", element<&B::position_m, 0>, &S::body_x_m, "x_m"},
      {"body_y_m", "m", element<&B::position_m, 1>, &S::body_y_m, "y_m"},
      {"body_z_m", "m", element<&B::position_m, 2>, &S::body_z_m, "z_m"},
      {"body_roll_rad", "rad", element<&B::orientation_rad, 0>, &S::body_roll_rad, "roll_rad"},
      {"body_pitch_rad", "rad", element<&B::orientation_rad, 1>, &S::body_pitch_rad, "pitch_rad"},
      {"body_yaw_rad", "rad", element<&B::orientation_rad, 2>, &S::body_yaw_rad, "yaw_rad"},
      {"body_vx_mps", "m/s", element<&B::velocity_mps, 0>, &S::body_vx_mps, "speed_x_mps"},
      {"body_vy_mps", "m/s", element<&B::velocity_mps, 1>, &S::body_vy_mps, "speed_y_mps"},
      {"body_vz_mps", "m/s", element<&B::velocity_mps, 2>, &S::body_vz_mps, "speed_z_mps"},
      {"body_wx_radps", "rad/s", element<&B::angular_velocity_radps, 0>, &S::body_wx_radps,
       "roll_rate_radps"},
      {"body_wy_radps", "rad/s", element<&B::angular_velocity_radps, 1>, &S::body_wy_radps,
       "pitch_rate_radps"},
      {"body_wz_radps", "rad/s", element<&B::angular_velocity_radps, 2>, &S::body_wz_radps,
       "yaw_rate_radps"},
  };

  /// Per free body, flags: 1 on its stops, 0 not.
  static constexpr ArrayField<S, B, std::int8_t> kBodyFlag[] = {
      {"body_on_stop", "1", member<&B::on_stop>, &S::body_on_stop, "on_stop"},
  };

  /// The message's frame, written by the builder and rig-log2csv themselves: the cycle's
  /// timing (io::CycleTiming), the group counts and each wheel's unit.
  static constexpr std::string_view kFrame[] = {
      "sim_time_s", "monotonic_ns", "cycle",      "lateness_ns", "compute_ns", "deadline_miss",
      "num_units",  "num_wheels",   "wheel_unit", "num_joints",  "num_diffs",  "num_bodies",
  };
};

}  // namespace rig::io::lcm
