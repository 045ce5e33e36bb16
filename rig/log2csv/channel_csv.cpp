#include "rig/log2csv/channel_csv.h"

#include <vector>

#include "rig/log2csv/vehicle_state_csv.h"
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
    return join_columns(h);
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
    return join_columns(h);
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
      case rig::rig_status_t::BUS_ERROR_PASSIVE:
        return "error-passive";
      case rig::rig_status_t::BUS_OFF:
        return "bus-off";
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
  if (hash == rig::vehicle_state_t::getHash())
    return make_vehicle_state_csv(current_vehicle_state_layout());
  if (const VehicleStateLayout* legacy = legacy_vehicle_state_layout(hash))
    return make_vehicle_state_csv(*legacy);
  if (hash == rig::signals_t::getHash()) return std::make_unique<SignalsCsv>();
  if (hash == rig::rig_status_t::getHash()) return std::make_unique<StatusCsv>();
  return std::make_unique<RawCsv>();
}

}  // namespace rig::log2csv
