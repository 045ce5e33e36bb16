#include "io/lcm/message_builder.h"

#include <algorithm>
#include <string>

namespace rig::io::lcm {

namespace {

template <typename T>
void resize(std::vector<T>& v, std::size_t n) {
  if (v.size() != n) v.resize(n);
}

std::int32_t clamp_count(std::int32_t count, int max) { return std::clamp(count, 0, max); }

}  // namespace

void fill_vehicle_state(const Snapshot& snapshot, rig::vehicle_state_t& msg) {
  const auto& t = snapshot.timing;
  const auto& r = snapshot.report;
  msg.sim_time_s = t.sim_time_s;
  msg.monotonic_ns = t.wake_ns;
  msg.cycle = static_cast<std::int64_t>(t.cycle);
  msg.lateness_ns = t.lateness_ns;
  msg.compute_ns = t.compute_ns;
  msg.deadline_miss = t.deadline_miss ? 1 : 0;

  const std::int32_t units = clamp_count(r.unit_count, model::kMaxUnits);
  const auto nu = static_cast<std::size_t>(units);
  msg.num_units = units;
  for (auto* v : {&msg.unit_x_m, &msg.unit_y_m, &msg.unit_z_m, &msg.unit_roll_rad,
                  &msg.unit_pitch_rad, &msg.unit_yaw_rad, &msg.unit_vx_mps, &msg.unit_vy_mps,
                  &msg.unit_vz_mps, &msg.unit_wx_radps, &msg.unit_wy_radps, &msg.unit_wz_radps,
                  &msg.unit_ax_mps2, &msg.unit_ay_mps2, &msg.unit_az_mps2}) {
    resize(*v, nu);
  }
  std::size_t wheels = 0;
  for (std::size_t u = 0; u < nu; ++u) {
    const auto& unit = r.units[u];
    msg.unit_x_m[u] = unit.position_m[0];
    msg.unit_y_m[u] = unit.position_m[1];
    msg.unit_z_m[u] = unit.position_m[2];
    msg.unit_roll_rad[u] = unit.orientation_rad[0];
    msg.unit_pitch_rad[u] = unit.orientation_rad[1];
    msg.unit_yaw_rad[u] = unit.orientation_rad[2];
    msg.unit_vx_mps[u] = unit.velocity_mps[0];
    msg.unit_vy_mps[u] = unit.velocity_mps[1];
    msg.unit_vz_mps[u] = unit.velocity_mps[2];
    msg.unit_wx_radps[u] = unit.angular_velocity_radps[0];
    msg.unit_wy_radps[u] = unit.angular_velocity_radps[1];
    msg.unit_wz_radps[u] = unit.angular_velocity_radps[2];
    msg.unit_ax_mps2[u] = unit.acceleration_mps2[0];
    msg.unit_ay_mps2[u] = unit.acceleration_mps2[1];
    msg.unit_az_mps2[u] = unit.acceleration_mps2[2];
    wheels += static_cast<std::size_t>(clamp_count(unit.wheel_count, model::kMaxWheelsPerUnit));
  }

  msg.num_wheels = static_cast<std::int32_t>(wheels);
  resize(msg.wheel_unit, wheels);
  for (auto* v : {&msg.wheel_spin_radps, &msg.wheel_slip_x, &msg.wheel_slip_y, &msg.wheel_force_x_n,
                  &msg.wheel_force_y_n, &msg.wheel_load_n, &msg.wheel_x_e_m, &msg.wheel_y_e_m,
                  &msg.wheel_steer_rad, &msg.wheel_brake_torque_nm, &msg.wheel_drive_torque_nm}) {
    resize(*v, wheels);
  }
  std::size_t k = 0;
  for (std::size_t u = 0; u < nu; ++u) {
    const auto& unit = r.units[u];
    const auto count =
        static_cast<std::size_t>(clamp_count(unit.wheel_count, model::kMaxWheelsPerUnit));
    for (std::size_t w = 0; w < count; ++w, ++k) {
      const auto& wheel = unit.wheels[w];
      msg.wheel_unit[k] = static_cast<std::int8_t>(u);
      msg.wheel_spin_radps[k] = wheel.spin_radps;
      msg.wheel_slip_x[k] = wheel.slip_x;
      msg.wheel_slip_y[k] = wheel.slip_y;
      msg.wheel_force_x_n[k] = wheel.force_x_n;
      msg.wheel_force_y_n[k] = wheel.force_y_n;
      msg.wheel_load_n[k] = wheel.load_n;
      msg.wheel_x_e_m[k] = wheel.deflection_x_m;
      msg.wheel_y_e_m[k] = wheel.deflection_y_m;
      msg.wheel_steer_rad[k] = wheel.steer_angle_rad;
      msg.wheel_brake_torque_nm[k] = wheel.brake_torque_nm;
      msg.wheel_drive_torque_nm[k] = wheel.drive_torque_nm;
    }
  }

  msg.steering_wheel_angle_rad = r.steering.wheel_angle_rad;
  msg.steering_wheel_torque_nm = r.steering.wheel_torque_nm;
  msg.torsion_bar_torque_nm = r.steering.torsion_bar_torque_nm;
  msg.rack_travel_m = r.steering.rack_travel_m;
  msg.rack_force_n = r.steering.rack_force_n;
  msg.assist_torque_nm = r.steering.assist_torque_nm;

  msg.engine_speed_radps = r.drivetrain.engine_speed_radps;
  msg.engine_torque_nm = r.drivetrain.engine_torque_nm;
  msg.gear = r.drivetrain.gear;

  msg.brake_pressure_fl_pa = r.brake_pressure_pa[0];
  msg.brake_pressure_fr_pa = r.brake_pressure_pa[1];
  msg.brake_pressure_rl_pa = r.brake_pressure_pa[2];
  msg.brake_pressure_rr_pa = r.brake_pressure_pa[3];

  const std::int32_t joints = clamp_count(r.joint_count, model::kMaxJoints);
  const auto nj = static_cast<std::size_t>(joints);
  msg.num_joints = joints;
  for (auto* v : {&msg.joint_force_x_n, &msg.joint_force_y_n, &msg.joint_force_z_n,
                  &msg.joint_violation_m, &msg.joint_rod_force_n}) {
    resize(*v, nj);
  }
  for (std::size_t j = 0; j < nj; ++j) {
    msg.joint_force_x_n[j] = r.joints[j].force_n[0];
    msg.joint_force_y_n[j] = r.joints[j].force_n[1];
    msg.joint_force_z_n[j] = r.joints[j].force_n[2];
    msg.joint_violation_m[j] = r.joints[j].violation_m;
    msg.joint_rod_force_n[j] = r.joints[j].rod_force_n;
  }
}

void fill_signals(const Snapshot& snapshot, rig::signals_t& msg) {
  constexpr auto n = model::kSignalCount;
  if (msg.name.size() != n) {
    // Names, units and the input flag are constant: set them once.
    msg.num_signals = static_cast<std::int32_t>(n);
    msg.name.assign(n, std::string());
    msg.unit.assign(n, std::string());
    msg.is_input.assign(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      msg.name[i] = std::string(model::kSignalTable[i].name);
      msg.unit[i] = std::string(model::kSignalTable[i].unit);
      msg.is_input[i] = model::kSignalTable[i].is_input ? 1 : 0;
    }
    msg.value.assign(n, 0.0);
    msg.valid.assign(n, 0);
    msg.source.assign(n, 0);
  }
  msg.sim_time_s = snapshot.timing.sim_time_s;
  msg.monotonic_ns = snapshot.timing.wake_ns;
  msg.cycle = static_cast<std::int64_t>(snapshot.timing.cycle);
  const auto& s = snapshot.signals;
  for (std::size_t i = 0; i < n; ++i) {
    msg.value[i] = s.value[i];
    msg.valid[i] = s.valid[i] ? 1 : 0;
    switch (s.source[i]) {
      case model::SignalSource::kModel:
        msg.source[i] = rig::signals_t::SOURCE_MODEL;
        break;
      case model::SignalSource::kDriver:
        msg.source[i] = rig::signals_t::SOURCE_DRIVER;
        break;
      case model::SignalSource::kCan:
        msg.source[i] = rig::signals_t::SOURCE_CAN;
        break;
    }
  }
}

void fill_status(const Snapshot& snapshot, const RunInfo& info, const StatusTotals& totals,
                 const TimingPercentiles& window, rig::rig_status_t& msg) {
  constexpr auto n_inputs = model::index(model::kFirstOutput);
  if (msg.input_name.size() != n_inputs) {
    msg.num_inputs = static_cast<std::int32_t>(n_inputs);
    msg.input_name.assign(n_inputs, std::string());
    for (std::size_t i = 0; i < n_inputs; ++i) {
      msg.input_name[i] = std::string(model::kSignalTable[i].name);
    }
    msg.input_valid.assign(n_inputs, 0);
  }
  if (msg.overrun_policy != info.policy) msg.overrun_policy = info.policy;

  const auto& t = snapshot.timing;
  msg.sim_time_s = t.sim_time_s;
  msg.monotonic_ns = t.wake_ns;
  msg.cycles = totals.cycles;
  msg.deadline_misses = totals.deadline_misses;
  msg.consecutive_misses = static_cast<std::int32_t>(t.consecutive_misses);
  msg.max_consecutive_misses = totals.max_consecutive_misses;
  msg.snapshots_dropped = totals.snapshots_dropped;

  msg.window_cycles = window.cycles;
  msg.window_misses = window.misses;
  msg.lateness_p50_ns = window.lateness_p50_ns;
  msg.lateness_p99_ns = window.lateness_p99_ns;
  msg.lateness_p999_ns = window.lateness_p999_ns;
  msg.lateness_max_ns = window.lateness_max_ns;
  msg.compute_p50_ns = window.compute_p50_ns;
  msg.compute_p99_ns = window.compute_p99_ns;
  msg.compute_max_ns = window.compute_max_ns;

  msg.period_s = info.period_s;
  msg.offline = info.offline ? 1 : 0;
  msg.sched_fifo = info.sched_fifo ? 1 : 0;
  msg.priority = info.priority;
  msg.memory_locked = info.memory_locked ? 1 : 0;
  msg.cpu = info.cpu;

  const auto& c = snapshot.can;
  switch (c.bus_state) {
    case BusState::kDisabled:
      msg.bus_state = rig::rig_status_t::BUS_DISABLED;
      break;
    case BusState::kUp:
      msg.bus_state = rig::rig_status_t::BUS_UP;
      break;
    case BusState::kDown:
      msg.bus_state = rig::rig_status_t::BUS_DOWN;
      break;
  }
  const auto i64 = [](std::uint64_t v) { return static_cast<std::int64_t>(v); };
  msg.can_frames_received = i64(c.frames_received);
  msg.can_frames_sent = i64(c.frames_sent);
  msg.can_timeouts = i64(c.timeouts);
  msg.can_checksum_failures = i64(c.checksum_failures);
  msg.can_counter_failures = i64(c.counter_failures);
  msg.can_bad_frames = i64(c.bad_frames);
  msg.can_unknown_frames = i64(c.unknown_frames);
  msg.can_error_frames = i64(c.error_frames);
  msg.can_out_of_range = i64(c.out_of_range);
  msg.can_send_no_buffer = i64(c.send_no_buffer);
  msg.can_send_dropped = i64(c.send_dropped);
  msg.can_reopens = i64(c.reopens);
  msg.can_rx_overflows = i64(c.rx_overflows);

  for (std::size_t i = 0; i < n_inputs; ++i) {
    msg.input_valid[i] = snapshot.signals.valid[i] ? 1 : 0;
  }
}

}  // namespace rig::io::lcm
