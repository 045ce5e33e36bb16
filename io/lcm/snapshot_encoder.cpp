#include "io/lcm/snapshot_encoder.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rig::io::lcm {

void RateDivider::configure(double rate_hz, double period_s) {
  if (!(rate_hz > 0.0) || !(period_s > 0.0)) {
    divisor_ = 0;
    return;
  }
  const double cycles_per_message = 1.0 / (rate_hz * period_s);
  divisor_ = static_cast<std::uint64_t>(std::max(1.0, std::round(cycles_per_message)));
}

SnapshotEncoder::SnapshotEncoder(LcmSettings settings)
    : settings_(std::move(settings)),
      state_channel_(settings_.state_channel()),
      status_channel_(settings_.status_channel()),
      signals_channel_(settings_.signals_channel()) {}

void SnapshotEncoder::start(const RunInfo& info) {
  info_ = info;
  state_rate_.configure(settings_.state_rate_hz, info.period_s);
  status_rate_.configure(settings_.status_rate_hz, info.period_s);
  signals_rate_.configure(settings_.signals_rate_hz, info.period_s);
  const double cycles_per_second = info.period_s > 0.0 ? 1.0 / info.period_s : 1000.0;
  window_.reset(static_cast<std::size_t>(std::max(1.0, std::round(cycles_per_second))));
  totals_ = StatusTotals{};
}

template <typename Message>
EncodedMessage SnapshotEncoder::encode_message(const Message& msg, const std::string& channel,
                                               std::vector<std::uint8_t>& buffer) {
  const int size = msg.getEncodedSize();
  if (buffer.size() < static_cast<std::size_t>(size)) buffer.resize(static_cast<std::size_t>(size));
  const int written = msg.encode(buffer.data(), 0, size);
  if (written < 0) return {};
  return {&channel, buffer.data(), static_cast<std::size_t>(written)};
}

std::size_t SnapshotEncoder::encode(const Snapshot& snapshot, std::uint64_t dropped_before,
                                    EncodedMessage (&out)[3]) {
  const auto& t = snapshot.timing;
  totals_.snapshots_dropped += static_cast<std::int64_t>(dropped_before);
  totals_.cycles += 1 + static_cast<std::int64_t>(dropped_before);
  if (t.deadline_miss) ++totals_.deadline_misses;
  totals_.max_consecutive_misses =
      std::max(totals_.max_consecutive_misses, static_cast<std::int32_t>(t.consecutive_misses));
  window_.push(t.lateness_ns, t.compute_ns, t.deadline_miss);

  std::size_t n = 0;
  if (state_rate_.due(t.cycle)) {
    fill_vehicle_state(snapshot, state_msg_);
    out[n] = encode_message(state_msg_, state_channel_, state_buffer_);
    if (out[n].data != nullptr) ++n;
  }
  if (signals_rate_.due(t.cycle)) {
    fill_signals(snapshot, settings_.signals, signals_msg_);
    out[n] = encode_message(signals_msg_, signals_channel_, signals_buffer_);
    if (out[n].data != nullptr) ++n;
  }
  if (status_rate_.due(t.cycle)) {
    fill_status(snapshot, info_, totals_, window_.percentiles(), status_msg_);
    out[n] = encode_message(status_msg_, status_channel_, status_buffer_);
    if (out[n].data != nullptr) ++n;
  }
  return n;
}

}  // namespace rig::io::lcm
