#pragma once
/// @file
/// Decides which LCM messages a snapshot produces (rate division by cycle number) and encodes
/// them into reused buffers. Shared by the live publisher and the log writer, so that a log file
/// holds exactly what would have gone on the wire.

#include <cstdint>
#include <string>
#include <vector>

#include "io/lcm/lcm_settings.h"
#include "io/lcm/message_builder.h"
#include "io/lcm/timing_window.h"
#include "io/snapshot_sink.h"

namespace rig::io::lcm {

/// Publishes every `divisor`-th cycle (cycle % divisor == 0), so that dropped snapshots do not
/// shift the phase. Disabled when the rate is 0.
class RateDivider {
 public:
  void configure(double rate_hz, double period_s);
  [[nodiscard]] bool enabled() const { return divisor_ > 0; }
  [[nodiscard]] std::uint64_t divisor() const { return divisor_; }
  [[nodiscard]] bool due(std::uint64_t cycle) const {
    return divisor_ > 0 && cycle % divisor_ == 0;
  }

 private:
  std::uint64_t divisor_ = 0;
};

/// One encoded message, valid until the next call to encode().
struct EncodedMessage {
  const std::string* channel = nullptr;
  const std::uint8_t* data = nullptr;
  std::size_t size = 0;
};

class SnapshotEncoder {
 public:
  explicit SnapshotEncoder(LcmSettings settings);

  /// Sizes the timing window to one second of cycles and sets up the rate dividers.
  void start(const RunInfo& info);

  /// Accounts for the snapshot (totals, timing window) and returns the messages it produces,
  /// in the order state, signals, status. `out` must hold 3 entries; returns how many are set.
  std::size_t encode(const Snapshot& snapshot, std::uint64_t dropped_before,
                     EncodedMessage (&out)[3]);

  [[nodiscard]] const LcmSettings& settings() const { return settings_; }
  [[nodiscard]] const StatusTotals& totals() const { return totals_; }

 private:
  template <typename Message>
  EncodedMessage encode_message(const Message& msg, const std::string& channel,
                                std::vector<std::uint8_t>& buffer);

  LcmSettings settings_;
  std::string state_channel_, status_channel_, signals_channel_;
  RunInfo info_;
  RateDivider state_rate_, status_rate_, signals_rate_;
  TimingWindow window_;
  StatusTotals totals_;
  rig::vehicle_state_t state_msg_{};
  rig::signals_t signals_msg_{};
  rig::rig_status_t status_msg_{};
  std::vector<std::uint8_t> state_buffer_, signals_buffer_, status_buffer_;
};

}  // namespace rig::io::lcm
