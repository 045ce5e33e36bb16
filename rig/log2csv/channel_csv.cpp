#include "rig/log2csv/channel_csv.h"

#include <array>
#include <vector>

#include "rig/rig_status_t.hpp"
#include "rig/signals_t.hpp"
#include "rig/vehicle_state_t.hpp"

namespace rig::log2csv {

namespace {

/// The LCM fingerprint that starts every encoded message (big endian).
std::int64_t fingerprint(const Event& event) {
  if (event.size < 8) return 0;
  std::uint64_t hash = 0;
  for (std::size_t i = 0; i < 8; ++i) hash = (hash << 8) | event.data[i];
  return static_cast<std::int64_t>(hash);
}

template <typename Message>
bool decode(const Event& event, Message& msg) {
  return msg.decode(event.data, 0, static_cast<int>(event.size)) >= 0;
}

std::string join(const std::vector<std::string>& columns) {
  std::string out;
  for (std::size_t i = 0; i < columns.size(); ++i) {
    if (i != 0) out.push_back(',');
    out += columns[i];
  }
  return out;
}

/// A per-unit/per-wheel/per-joint array: field `<group>_<suffix>` becomes the columns
/// `<group><i>_<suffix>`, e.g. wheel_spin_radps -> wheel0_spin_radps, wheel1_spin_radps, ...
struct ArrayColumn {
  const char* suffix;
  std::vector<double> rig::vehicle_state_t::*member;
};

using S = rig::vehicle_state_t;
constexpr std::array<ArrayColumn, 15> kUnitColumns{{
    {"x_m", &S::unit_x_m},
    {"y_m", &S::unit_y_m},
    {"z_m", &S::unit_z_m},
    {"roll_rad", &S::unit_roll_rad},
    {"pitch_rad", &S::unit_pitch_rad},
    {"yaw_rad", &S::unit_yaw_rad},
    {"vx_mps", &S::unit_vx_mps},
    {"vy_mps", &S::unit_vy_mps},
    {"vz_mps", &S::unit_vz_mps},
    {"wx_radps", &S::unit_wx_radps},
    {"wy_radps", &S::unit_wy_radps},
    {"wz_radps", &S::unit_wz_radps},
    {"ax_mps2", &S::unit_ax_mps2},
    {"ay_mps2", &S::unit_ay_mps2},
    {"az_mps2", &S::unit_az_mps2},
}};
constexpr std::array<ArrayColumn, 11> kWheelColumns{{
    {"spin_radps", &S::wheel_spin_radps},
    {"slip_x", &S::wheel_slip_x},
    {"slip_y", &S::wheel_slip_y},
    {"force_x_n", &S::wheel_force_x_n},
    {"force_y_n", &S::wheel_force_y_n},
    {"load_n", &S::wheel_load_n},
    {"x_e_m", &S::wheel_x_e_m},
    {"y_e_m", &S::wheel_y_e_m},
    {"steer_rad", &S::wheel_steer_rad},
    {"brake_torque_nm", &S::wheel_brake_torque_nm},
    {"drive_torque_nm", &S::wheel_drive_torque_nm},
}};
constexpr std::array<ArrayColumn, 5> kJointColumns{{
    {"force_x_n", &S::joint_force_x_n},
    {"force_y_n", &S::joint_force_y_n},
    {"force_z_n", &S::joint_force_z_n},
    {"violation_m", &S::joint_violation_m},
    {"rod_force_n", &S::joint_rod_force_n},
}};
constexpr std::array<std::pair<const char*, double S::*>, 12> kScalarColumns{{
    {"steering_wheel_angle_rad", &S::steering_wheel_angle_rad},
    {"steering_wheel_torque_nm", &S::steering_wheel_torque_nm},
    {"torsion_bar_torque_nm", &S::torsion_bar_torque_nm},
    {"rack_travel_m", &S::rack_travel_m},
    {"rack_force_n", &S::rack_force_n},
    {"assist_torque_nm", &S::assist_torque_nm},
    {"engine_speed_radps", &S::engine_speed_radps},
    {"engine_torque_nm", &S::engine_torque_nm},
    {"brake_pressure_fl_pa", &S::brake_pressure_fl_pa},
    {"brake_pressure_fr_pa", &S::brake_pressure_fr_pa},
    {"brake_pressure_rl_pa", &S::brake_pressure_rl_pa},
    {"brake_pressure_rr_pa", &S::brake_pressure_rr_pa},
}};

template <std::size_t N>
void add_array_headers(std::vector<std::string>& h, const char* group,
                       const std::array<ArrayColumn, N>& columns, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    for (const auto& c : columns) h.push_back(group + std::to_string(i) + "_" + c.suffix);
  }
}

template <std::size_t N>
void add_array_cells(CsvLine& line, const S& msg, const std::array<ArrayColumn, N>& columns,
                     std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    for (const auto& c : columns) {
      const auto& v = msg.*(c.member);
      if (i < v.size()) {
        line.add(v[i]);
      } else {
        line.add_empty();
      }
    }
  }
}

class VehicleStateCsv final : public ChannelCsv {
 public:
  [[nodiscard]] const char* type_name() const override { return "rig.vehicle_state_t"; }

  [[nodiscard]] std::string header() const override {
    std::vector<std::string> h{"timestamp_us", "sim_time_s", "monotonic_ns",  "cycle",
                               "lateness_ns",  "compute_ns", "deadline_miss", "num_units"};
    add_array_headers(h, "unit", kUnitColumns, units_);
    h.emplace_back("num_wheels");
    for (std::size_t i = 0; i < wheels_; ++i) h.push_back("wheel" + std::to_string(i) + "_unit");
    add_array_headers(h, "wheel", kWheelColumns, wheels_);
    for (const auto& c : kScalarColumns) h.emplace_back(c.first);
    h.emplace_back("gear");
    h.emplace_back("num_joints");
    add_array_headers(h, "joint", kJointColumns, joints_);
    return join(h);
  }

  bool row(const Event& event, CsvLine& line) override {
    if (!decode(event, msg_)) return false;
    if (!sized_) {
      units_ = msg_.unit_x_m.size();
      wheels_ = msg_.wheel_spin_radps.size();
      joints_ = msg_.joint_force_x_n.size();
      sized_ = true;
    }
    line.add(event.timestamp_us);
    line.add(msg_.sim_time_s);
    line.add(msg_.monotonic_ns);
    line.add(msg_.cycle);
    line.add(msg_.lateness_ns);
    line.add(msg_.compute_ns);
    line.add(std::int64_t{msg_.deadline_miss});
    line.add(std::int64_t{msg_.num_units});
    add_array_cells(line, msg_, kUnitColumns, units_);
    line.add(std::int64_t{msg_.num_wheels});
    for (std::size_t i = 0; i < wheels_; ++i) {
      if (i < msg_.wheel_unit.size()) {
        line.add(std::int64_t{msg_.wheel_unit[i]});
      } else {
        line.add_empty();
      }
    }
    add_array_cells(line, msg_, kWheelColumns, wheels_);
    for (const auto& c : kScalarColumns) line.add(msg_.*(c.second));
    line.add(std::int64_t{msg_.gear});
    line.add(std::int64_t{msg_.num_joints});
    add_array_cells(line, msg_, kJointColumns, joints_);
    return true;
  }

 private:
  rig::vehicle_state_t msg_{};
  bool sized_ = false;
  std::size_t units_ = 0, wheels_ = 0, joints_ = 0;
};

class SignalsCsv final : public ChannelCsv {
 public:
  [[nodiscard]] const char* type_name() const override { return "rig.signals_t"; }

  [[nodiscard]] std::string header() const override {
    std::vector<std::string> h{"timestamp_us", "sim_time_s", "monotonic_ns", "cycle"};
    for (std::size_t i = 0; i < names_.size(); ++i) {
      h.push_back(names_[i]);
      h.push_back(names_[i] + "_valid");
      if (is_input_[i] != 0) h.push_back(names_[i] + "_source");
    }
    return join(h);
  }

  bool row(const Event& event, CsvLine& line) override {
    if (!decode(event, msg_)) return false;
    if (names_.empty()) {
      names_ = msg_.name;
      is_input_ = msg_.is_input;
    }
    line.add(event.timestamp_us);
    line.add(msg_.sim_time_s);
    line.add(msg_.monotonic_ns);
    line.add(msg_.cycle);
    for (std::size_t i = 0; i < names_.size(); ++i) {
      const bool present = i < msg_.value.size() && msg_.name[i] == names_[i];
      if (present) {
        line.add(msg_.value[i]);
        line.add(std::int64_t{msg_.valid[i]});
      } else {
        line.add_empty();
        line.add_empty();
      }
      if (is_input_[i] != 0) {
        if (present) {
          line.add(source_name(msg_.source[i]));
        } else {
          line.add_empty();
        }
      }
    }
    return true;
  }

 private:
  static const char* source_name(std::int8_t source) {
    switch (source) {
      case rig::signals_t::SOURCE_DRIVER:
        return "driver";
      case rig::signals_t::SOURCE_CAN:
        return "can";
      default:
        return "model";
    }
  }

  rig::signals_t msg_{};
  std::vector<std::string> names_;
  std::vector<std::int8_t> is_input_;
};

class StatusCsv final : public ChannelCsv {
 public:
  [[nodiscard]] const char* type_name() const override { return "rig.rig_status_t"; }

  [[nodiscard]] std::string header() const override {
    std::vector<std::string> h{"timestamp_us",
                               "sim_time_s",
                               "monotonic_ns",
                               "cycles",
                               "deadline_misses",
                               "consecutive_misses",
                               "max_consecutive_misses",
                               "snapshots_dropped",
                               "window_cycles",
                               "window_misses",
                               "lateness_p50_ns",
                               "lateness_p99_ns",
                               "lateness_p999_ns",
                               "lateness_max_ns",
                               "compute_p50_ns",
                               "compute_p99_ns",
                               "compute_max_ns",
                               "period_s",
                               "offline",
                               "sched_fifo",
                               "priority",
                               "memory_locked",
                               "cpu",
                               "overrun_policy",
                               "bus_state",
                               "can_frames_received",
                               "can_frames_sent",
                               "can_timeouts",
                               "can_checksum_failures",
                               "can_counter_failures",
                               "can_bad_frames",
                               "can_unknown_frames",
                               "can_error_frames",
                               "can_out_of_range",
                               "can_send_no_buffer",
                               "can_send_dropped",
                               "can_reopens",
                               "can_rx_overflows"};
    for (const auto& name : inputs_) h.push_back("input_valid_" + name);
    return join(h);
  }

  bool row(const Event& event, CsvLine& line) override {
    if (!decode(event, m_)) return false;
    if (inputs_.empty()) inputs_ = m_.input_name;
    line.add(event.timestamp_us);
    line.add(m_.sim_time_s);
    for (std::int64_t v :
         {m_.monotonic_ns, m_.cycles, m_.deadline_misses, std::int64_t{m_.consecutive_misses},
          std::int64_t{m_.max_consecutive_misses}, m_.snapshots_dropped,
          std::int64_t{m_.window_cycles}, std::int64_t{m_.window_misses}, m_.lateness_p50_ns,
          m_.lateness_p99_ns, m_.lateness_p999_ns, m_.lateness_max_ns, m_.compute_p50_ns,
          m_.compute_p99_ns, m_.compute_max_ns}) {
      line.add(v);
    }
    line.add(m_.period_s);
    for (std::int64_t v :
         {std::int64_t{m_.offline}, std::int64_t{m_.sched_fifo}, std::int64_t{m_.priority},
          std::int64_t{m_.memory_locked}, std::int64_t{m_.cpu}}) {
      line.add(v);
    }
    line.add(m_.overrun_policy);
    line.add(bus_state_name(m_.bus_state));
    for (std::int64_t v :
         {m_.can_frames_received, m_.can_frames_sent, m_.can_timeouts, m_.can_checksum_failures,
          m_.can_counter_failures, m_.can_bad_frames, m_.can_unknown_frames, m_.can_error_frames,
          m_.can_out_of_range, m_.can_send_no_buffer, m_.can_send_dropped, m_.can_reopens,
          m_.can_rx_overflows}) {
      line.add(v);
    }
    for (std::size_t i = 0; i < inputs_.size(); ++i) {
      if (i < m_.input_valid.size() && m_.input_name[i] == inputs_[i]) {
        line.add(std::int64_t{m_.input_valid[i]});
      } else {
        line.add_empty();
      }
    }
    return true;
  }

 private:
  static const char* bus_state_name(std::int8_t state) {
    switch (state) {
      case rig::rig_status_t::BUS_UP:
        return "up";
      case rig::rig_status_t::BUS_DOWN:
        return "down";
      default:
        return "disabled";
    }
  }

  rig::rig_status_t m_{};
  std::vector<std::string> inputs_;
};

/// Any other type: when, where, how big.
class RawCsv final : public ChannelCsv {
 public:
  [[nodiscard]] const char* type_name() const override { return "raw"; }
  [[nodiscard]] std::string header() const override { return "timestamp_us,channel,size_bytes"; }
  bool row(const Event& event, CsvLine& line) override {
    line.add(event.timestamp_us);
    line.add(*event.channel);
    line.add(static_cast<std::int64_t>(event.size));
    return true;
  }
};

}  // namespace

std::unique_ptr<ChannelCsv> make_channel_csv(const Event& first) {
  const std::int64_t hash = fingerprint(first);
  if (hash == rig::vehicle_state_t::getHash()) return std::make_unique<VehicleStateCsv>();
  if (hash == rig::signals_t::getHash()) return std::make_unique<SignalsCsv>();
  if (hash == rig::rig_status_t::getHash()) return std::make_unique<StatusCsv>();
  return std::make_unique<RawCsv>();
}

}  // namespace rig::log2csv
