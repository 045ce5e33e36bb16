#pragma once
/// @file
/// The send half of the CAN mapping, independent of sockets: decides which messages are due in
/// this loop cycle (each at its GenMsgCycleTime, phase-aligned to the loop start), and encodes
/// them from the cycle's signals and report (catalogue bindings) with alive counter and checksum
/// filled in. The bridge only moves the resulting bytes to the transport.
///
/// RT-safe: due_frames() never allocates, never throws, does no string work.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "io/can/dbc/signal_codec.h"
#include "io/can/mapping/can_mapping.h"
#include "io/can/mapping/report_limiter.h"
#include "io/io_counters.h"
#include "model/signals.h"

namespace rig::io::can::mapping {

/// One frame to send. Plain data.
struct TxFrame {
  std::uint32_t id = 0;  ///< without flag bits
  bool extended = false;
  bool fd = false;  ///< length > 8
  std::uint8_t len = 0;
  std::array<std::uint8_t, 64> data{};
};

class TxScheduler {
 public:
  /// Compiles the TX bindings of `config` (load time).
  explicit TxScheduler(const CanConfig& config);

  /// Aligns the schedule: message k is due at loop_start_ns + n * period_k, n = 0, 1, ...
  void start(std::int64_t loop_start_ns);

  /// Encodes every message due at `now_ns` (pass the loop's nominal cycle time) into `out`,
  /// returns how many were written (at most out.size(); more due frames stay due for the next
  /// call). After an overrun a message is sent once, not in a burst, and its schedule skips to
  /// the next slot after now_ns on the same phase grid. Counts clamped values in
  /// counters.out_of_range (frames_sent is the transport's business).
  std::size_t due_frames(std::int64_t now_ns, const signals::CycleView& cycle,
                         std::span<TxFrame> out, io::IoCounters& counters);

  /// Encodes message i now, regardless of schedule (advances its counter). For tests/tools.
  void encode(std::size_t i, const signals::CycleView& cycle, TxFrame& frame,
              io::IoCounters& counters);

  /// Hands every due out-of-range report to `visit(const OutOfRangeReport&)` (direction "tx"):
  /// per signal the first clamp at once, then at most one a second with the count since.
  template <class Visitor>
  void take_out_of_range_reports(std::int64_t now_ns, Visitor&& visit) noexcept {
    for (Message& m : messages_) {
      for (std::size_t k = 0; k < m.bound.size(); ++k) {
        const std::uint64_t n = m.reports[k].take_due(now_ns);
        if (n == 0) continue;
        visit(OutOfRangeReport{.direction = "tx",
                               .message = m.name.c_str(),
                               .signal = m.names[k].c_str(),
                               .received = m.last_out_of_range[k],
                               .minimum = m.minimum[k],
                               .maximum = m.maximum[k],
                               .count = n});
      }
    }
  }

  [[nodiscard]] std::size_t message_count() const { return messages_.size(); }
  [[nodiscard]] std::int64_t period_ns(std::size_t i) const { return messages_[i].period_ns; }

 private:
  struct Message {
    std::uint32_t id = 0;
    bool extended = false;
    std::uint32_t length_bytes = 0;
    bool fd = false;
    dbc::MessageCodec codec;
    std::vector<double> physical;  ///< per DBC signal, start values preset
    std::vector<SignalBinding> bound;
    std::vector<double> minimum, maximum;  ///< per bound signal
    std::vector<bool> clamp;
    std::string name;                       ///< DBC message name, for reports
    std::vector<std::string> names;         ///< per bound signal: DBC signal name
    std::vector<ReportLimiter> reports;     ///< per bound signal
    std::vector<double> last_out_of_range;  ///< per bound signal
    std::vector<std::uint32_t> mux_pages;   ///< multiplexor values, round-robin per send
    std::size_t next_page = 0;
    std::optional<CounterSpec> counter;
    std::optional<ChecksumSpec> checksum;
    std::optional<e2e::E2eSpec> e2e;
    std::uint32_t counter_value = 0;
    std::int64_t period_ns = 0;
    std::int64_t next_due_ns = 0;
  };
  std::vector<Message> messages_;
  std::int64_t loop_start_ns_ = 0;
};

}  // namespace rig::io::can::mapping
