#include "io/can/bridge/can_bridge.h"

#include <cstring>
#include <span>
#include <utility>

namespace rig::io::can::bridge {

can::transport::TransportSettings CanBridge::with_filter(can::transport::TransportSettings settings,
                                                         const can::mapping::CanConfig& config,
                                                         bool kernel_filter) {
  settings.use_filter = kernel_filter;
  settings.filter_ids.clear();
  settings.extended_filter_ids.clear();
  if (kernel_filter) {
    for (const auto& binding : config.mapping.rx) {
      const auto& message = config.database.messages[binding.dbc_message];
      (message.extended ? settings.extended_filter_ids : settings.filter_ids).push_back(message.id);
    }
  }
  return settings;
}

CanBridge::CanBridge(can::mapping::CanConfig config,
                     can::transport::TransportSettings transport_settings, bool kernel_filter,
                     const io::InputSet& feeds)
    : config_(std::move(config)),
      rx_(config_),
      tx_(config_),
      transport_(with_filter(std::move(transport_settings), config_, kernel_filter)),
      feeds_(feeds) {}

void CanBridge::start(std::int64_t monotonic_ns) noexcept {
  rx_.reset(monotonic_ns, rx_signals_);
  tx_.start(monotonic_ns);
  started_ = true;
}

void CanBridge::receive(std::int64_t monotonic_ns, model::Signals& inputs) noexcept {
  if (!started_) start(monotonic_ns);
  transport_.service(monotonic_ns);
  transport_.drain([&](const can::transport::TransportFrame& f) {
    rx_.on_frame(f.id, f.extended, f.data.data(), f.len, monotonic_ns, rx_signals_,
                 engine_counters_);
  });
  rx_.check_timeouts(monotonic_ns, rx_signals_, engine_counters_);
  for (std::size_t i = 0; i < model::index(model::kFirstOutput); ++i) {
    if (!feeds_[i]) continue;
    inputs.value[i] = rx_signals_.value[i];
    inputs.valid[i] = rx_signals_.valid[i];
  }
}

void CanBridge::transmit(std::int64_t monotonic_ns, const model::Signals& outputs) noexcept {
  if (!started_) start(monotonic_ns);
  const std::size_t n = tx_.due_frames(
      monotonic_ns, outputs, std::span<can::mapping::TxFrame>(tx_frames_), engine_counters_);
  for (std::size_t i = 0; i < n; ++i) {
    const can::mapping::TxFrame& in = tx_frames_[i];
    can::transport::TransportFrame out;
    out.id = in.id;
    out.extended = in.extended;
    out.fd = in.fd;
    out.len = in.len;
    std::memcpy(out.data.data(), in.data.data(), in.len);
    transport_.send(out);
  }
}

void CanBridge::read_counters(IoCounters& counters) const noexcept {
  counters = engine_counters_;  // timeouts, checksum/counter failures, bad/unknown, out_of_range
  const can::transport::TransportCounters& t = transport_.counters();
  counters.bus_state = transport_.state();
  counters.frames_received = t.frames_received;
  counters.rx_overflows = t.rx_overflows;
  counters.frames_sent = t.frames_sent;
  counters.error_frames = t.error_frames;
  counters.bad_frames += t.malformed;
  counters.send_no_buffer = t.send_no_buffer;
  counters.send_dropped = t.send_dropped;
  counters.reopens = t.reopens;
}

}  // namespace rig::io::can::bridge
