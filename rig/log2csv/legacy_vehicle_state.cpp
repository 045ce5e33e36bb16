#include "rig/log2csv/legacy_vehicle_state.h"

#include "rig/vehicle_state_v1_t.hpp"
#include "rig/vehicle_state_v2_t.hpp"
#include "rig/vehicle_state_v3_t.hpp"
#include "rig/vehicle_state_v4_t.hpp"

namespace rig::log2csv {

namespace {

using State = rig::vehicle_state_t;
using V1 = rig::vehicle_state_v1_t;
using V2 = rig::vehicle_state_v2_t;
using V3 = rig::vehicle_state_v3_t;
using V4 = rig::vehicle_state_v4_t;

bool decode_current(const Event& event, State& msg) {
  return msg.decode(event.data, 0, static_cast<int>(event.size)) >= 0;
}

bool has_every_row(std::string_view /*name*/) { return true; }

// ---- v1: before the per-wheel road fields (issue 16); v2: before the differentials (issue
// 17); v3: before the frame torsion and the leaf springs (issue 17); v4: before the leaf
// balance (issue 17). The members all share, then the later ones'. ----

/// Rows no layout before v4 had.
bool frame_or_leaf(std::string_view name) {
  return name.starts_with("unit_frame_") || name.starts_with("wheel_leaf_");
}

template <typename Legacy>
void copy_frame_and_units(const Legacy& a, State& b) {
  b.sim_time_s = a.sim_time_s;
  b.monotonic_ns = a.monotonic_ns;
  b.cycle = a.cycle;
  b.lateness_ns = a.lateness_ns;
  b.compute_ns = a.compute_ns;
  b.deadline_miss = a.deadline_miss;
  b.num_units = a.num_units;
  b.unit_x_m = a.unit_x_m;
  b.unit_y_m = a.unit_y_m;
  b.unit_z_m = a.unit_z_m;
  b.unit_roll_rad = a.unit_roll_rad;
  b.unit_pitch_rad = a.unit_pitch_rad;
  b.unit_yaw_rad = a.unit_yaw_rad;
  b.unit_vx_mps = a.unit_vx_mps;
  b.unit_vy_mps = a.unit_vy_mps;
  b.unit_vz_mps = a.unit_vz_mps;
  b.unit_wx_radps = a.unit_wx_radps;
  b.unit_wy_radps = a.unit_wy_radps;
  b.unit_wz_radps = a.unit_wz_radps;
  b.unit_ax_mps2 = a.unit_ax_mps2;
  b.unit_ay_mps2 = a.unit_ay_mps2;
  b.unit_az_mps2 = a.unit_az_mps2;
}

template <typename Legacy>
void copy_wheels(const Legacy& a, State& b) {
  b.num_wheels = a.num_wheels;
  b.wheel_unit = a.wheel_unit;
  b.wheel_spin_radps = a.wheel_spin_radps;
  b.wheel_slip_x = a.wheel_slip_x;
  b.wheel_slip_y = a.wheel_slip_y;
  b.wheel_force_x_n = a.wheel_force_x_n;
  b.wheel_force_y_n = a.wheel_force_y_n;
  b.wheel_load_n = a.wheel_load_n;
  b.wheel_x_e_m = a.wheel_x_e_m;
  b.wheel_y_e_m = a.wheel_y_e_m;
  b.wheel_steer_rad = a.wheel_steer_rad;
  b.wheel_brake_torque_nm = a.wheel_brake_torque_nm;
  b.wheel_brake_pressure_pa = a.wheel_brake_pressure_pa;
  b.wheel_drive_torque_nm = a.wheel_drive_torque_nm;
  b.wheel_hub_travel_m = a.wheel_hub_travel_m;
  b.wheel_long_speed_mps = a.wheel_long_speed_mps;
  b.wheel_lat_speed_mps = a.wheel_lat_speed_mps;
  b.wheel_rolling_radius_m = a.wheel_rolling_radius_m;
  b.wheel_tire_load_n = a.wheel_tire_load_n;
  b.wheel_slip_valid = a.wheel_slip_valid;
}

/// The road under each wheel (issue 16; v2 on).
template <typename Legacy>
void copy_road(const Legacy& a, State& b) {
  b.wheel_road_z_m = a.wheel_road_z_m;
  b.wheel_road_normal_x = a.wheel_road_normal_x;
  b.wheel_road_normal_y = a.wheel_road_normal_y;
  b.wheel_road_normal_z = a.wheel_road_normal_z;
  b.wheel_road_mu = a.wheel_road_mu;
}

template <typename Legacy>
void copy_vehicle_and_joints(const Legacy& a, State& b) {
  b.steering_wheel_angle_rad = a.steering_wheel_angle_rad;
  b.steering_wheel_speed_radps = a.steering_wheel_speed_radps;
  b.steering_wheel_torque_nm = a.steering_wheel_torque_nm;
  b.torsion_bar_torque_nm = a.torsion_bar_torque_nm;
  b.rack_travel_m = a.rack_travel_m;
  b.rack_force_n = a.rack_force_n;
  b.assist_torque_nm = a.assist_torque_nm;
  b.tie_rod_force_left_n = a.tie_rod_force_left_n;
  b.tie_rod_force_right_n = a.tie_rod_force_right_n;
  b.engine_speed_radps = a.engine_speed_radps;
  b.engine_torque_nm = a.engine_torque_nm;
  b.gear = a.gear;
  b.brake_pressure_fl_pa = a.brake_pressure_fl_pa;
  b.brake_pressure_fr_pa = a.brake_pressure_fr_pa;
  b.brake_pressure_rl_pa = a.brake_pressure_rl_pa;
  b.brake_pressure_rr_pa = a.brake_pressure_rr_pa;
  b.model_valid = a.model_valid;
  b.model_fault_kind = a.model_fault_kind;
  b.model_fault_unit = a.model_fault_unit;
  b.num_joints = a.num_joints;
  b.joint_force_x_n = a.joint_force_x_n;
  b.joint_force_y_n = a.joint_force_y_n;
  b.joint_force_z_n = a.joint_force_z_n;
  b.joint_violation_m = a.joint_violation_m;
  b.joint_rod_force_n = a.joint_rod_force_n;
}

template <typename Legacy>
void copy_bodies(const Legacy& a, State& b) {
  b.num_bodies = a.num_bodies;
  b.body_x_m = a.body_x_m;
  b.body_y_m = a.body_y_m;
  b.body_z_m = a.body_z_m;
  b.body_roll_rad = a.body_roll_rad;
  b.body_pitch_rad = a.body_pitch_rad;
  b.body_yaw_rad = a.body_yaw_rad;
  b.body_vx_mps = a.body_vx_mps;
  b.body_vy_mps = a.body_vy_mps;
  b.body_vz_mps = a.body_vz_mps;
  b.body_wx_radps = a.body_wx_radps;
  b.body_wy_radps = a.body_wy_radps;
  b.body_wz_radps = a.body_wz_radps;
  b.body_on_stop = a.body_on_stop;
}

bool decode_v1(const Event& event, State& msg) {
  V1 v1;
  if (v1.decode(event.data, 0, static_cast<int>(event.size)) < 0) return false;
  copy_frame_and_units(v1, msg);
  copy_wheels(v1, msg);
  copy_vehicle_and_joints(v1, msg);
  return true;
}

bool v1_has_row(std::string_view name) {
  return !name.starts_with("wheel_road_") && !name.starts_with("wheel_axle_") &&
         !frame_or_leaf(name) && !name.starts_with("diff_") && name != "num_diffs";
}

bool decode_v2(const Event& event, State& msg) {
  V2 v2;
  if (v2.decode(event.data, 0, static_cast<int>(event.size)) < 0) return false;
  copy_frame_and_units(v2, msg);
  copy_wheels(v2, msg);
  copy_road(v2, msg);
  copy_vehicle_and_joints(v2, msg);
  return true;
}

bool v2_has_row(std::string_view name) {
  return !name.starts_with("wheel_axle_") && !frame_or_leaf(name) && !name.starts_with("diff_") &&
         name != "num_diffs";
}

/// The members v3 and v4 share.
template <typename Legacy>
void copy_v3(const Legacy& a, State& b) {
  copy_frame_and_units(a, b);
  copy_wheels(a, b);
  copy_road(a, b);
  b.wheel_axle_heave_m = a.wheel_axle_heave_m;
  b.wheel_axle_roll_rad = a.wheel_axle_roll_rad;
  copy_vehicle_and_joints(a, b);
  b.num_diffs = a.num_diffs;
  b.diff_input_speed_radps = a.diff_input_speed_radps;
  b.diff_output_a_speed_radps = a.diff_output_a_speed_radps;
  b.diff_output_b_speed_radps = a.diff_output_b_speed_radps;
  b.diff_locked = a.diff_locked;
  copy_bodies(a, b);
}

bool decode_v3(const Event& event, State& msg) {
  V3 v3;
  if (v3.decode(event.data, 0, static_cast<int>(event.size)) < 0) return false;
  copy_v3(v3, msg);
  return true;
}

bool v3_has_row(std::string_view name) { return !frame_or_leaf(name); }

bool decode_v4(const Event& event, State& msg) {
  V4 v4;
  if (v4.decode(event.data, 0, static_cast<int>(event.size)) < 0) return false;
  copy_v3(v4, msg);
  msg.unit_frame_twist_rad = v4.unit_frame_twist_rad;
  msg.unit_frame_twist_rate_radps = v4.unit_frame_twist_rate_radps;
  msg.unit_frame_torsion_moment_nm = v4.unit_frame_torsion_moment_nm;
  msg.wheel_leaf_windup_rad = v4.wheel_leaf_windup_rad;
  msg.wheel_leaf_fore_aft_m = v4.wheel_leaf_fore_aft_m;
  msg.wheel_leaf_shackle_rad = v4.wheel_leaf_shackle_rad;
  msg.wheel_leaf_front_link_rad = v4.wheel_leaf_front_link_rad;
  msg.wheel_leaf_rear_link_rad = v4.wheel_leaf_rear_link_rad;
  msg.wheel_leaf_iterations = v4.wheel_leaf_iterations;
  return true;
}

bool v4_has_row(std::string_view name) { return name != "wheel_leaf_rocker_rad"; }

constexpr VehicleStateLayout kCurrent{"rig.vehicle_state_t", decode_current, has_every_row};
constexpr VehicleStateLayout kV1{"rig.vehicle_state_t (v1: before the wheel_road_ fields)",
                                 decode_v1, v1_has_row};
constexpr VehicleStateLayout kV2{"rig.vehicle_state_t (v2: before the diff_ fields)", decode_v2,
                                 v2_has_row};
constexpr VehicleStateLayout kV3{
    "rig.vehicle_state_t (v3: before the unit_frame_ and wheel_leaf_ fields)", decode_v3,
    v3_has_row};
constexpr VehicleStateLayout kV4{"rig.vehicle_state_t (v4: before wheel_leaf_rocker_rad)",
                                 decode_v4, v4_has_row};

}  // namespace

const VehicleStateLayout& current_vehicle_state_layout() { return kCurrent; }

const VehicleStateLayout* legacy_vehicle_state_layout(std::int64_t hash) {
  if (hash == V1::getHash()) return &kV1;
  if (hash == V2::getHash()) return &kV2;
  if (hash == V3::getHash()) return &kV3;
  if (hash == V4::getHash()) return &kV4;
  return nullptr;
}

}  // namespace rig::log2csv
