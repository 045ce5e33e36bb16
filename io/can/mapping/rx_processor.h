#pragma once
/// @file
/// The receive half of the CAN mapping, independent of sockets: validates a received frame
/// (format, length, checksum, alive counter), decodes its mapped signals, clamps them to the DBC
/// range, converts them to SI and writes them into model::Signals. Watches message timeouts.
/// Clamped values are reported per signal, rate-limited (take_out_of_range_reports()).
///
/// RT-safe: on_frame() and check_timeouts() never allocate, never throw, do no string work.
/// Use one clock for all times (e.g. the loop's CLOCK_MONOTONIC cycle time).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "io/can/dbc/signal_codec.h"
#include "io/can/mapping/can_mapping.h"
#include "io/can/mapping/report_limiter.h"
#include "io/can/mapping/sequence_checker.h"
#include "io/io_counters.h"
#include "model/signals.h"

namespace rig::io::can::mapping {

/// How a frame came off the bus.
enum class FrameFormat : std::uint8_t {
  kClassic,  ///< classic CAN data frame (0..8 bytes)
  kFd,       ///< CAN FD data frame (0..64 bytes)
  kRemote,   ///< classic remote request (RTR): no data
};

/// What on_frame() did with a frame (also counted in IoCounters).
enum class RxResult : std::uint8_t {
  kAccepted,         ///< decoded and written
  kUnknownId,        ///< id/extended flag not in the RX mapping (unknown_frames)
  kBadLength,        ///< length differs from the DBC length (bad_frames)
  kRemoteFrame,      ///< a remote request on a mapped id: carries no data (bad_frames)
  kWrongFormat,      ///< CAN FD frame on a classic message's id or vice versa (bad_frames)
  kChecksumFailure,  ///< checksum or E2E CRC/Data ID wrong (checksum_failures), rejected
  kCounterFailure,   ///< counter (or E2E counter) repeated, skipped or latched (counter_failures)
};

class RxProcessor {
 public:
  /// Compiles the RX bindings of `config` (load time; keeps a pointer to nothing in config).
  explicit RxProcessor(const CanConfig& config);

  /// Applies every fallback with valid = false and starts every timeout clock at `now_ns`.
  /// Call once before the first cycle (and after the bus comes back, if wanted).
  void reset(std::int64_t now_ns, model::Signals& signals);

  /// Handles one received frame. `id` without flag bits; `len` in bytes. A mapped message must
  /// come as a data frame of its DBC format (CAN FD if longer than 8 bytes, else classic).
  /// Counts into `counters`: unknown_frames, bad_frames, checksum_failures, counter_failures,
  /// out_of_range (each clamped or non-finite value). frames_received is the transport's count,
  /// not touched here. A rejected frame changes no signal and does not reset the timeout. The
  /// alive counter is checked by a SequenceChecker per message (sequence_checker.h): a
  /// repeated, frozen or skipping counter latches the message until the counter moves properly.
  RxResult on_frame(std::uint32_t id, bool extended, FrameFormat format, const std::uint8_t* data,
                    std::size_t len, std::int64_t time_ns, model::Signals& signals,
                    io::IoCounters& counters);

  /// Applies the fallback (valid = false) of every message whose last accepted frame is older
  /// than its timeout. Counts one `timeouts` per message per timeout episode. Call every cycle.
  void check_timeouts(std::int64_t now_ns, model::Signals& signals, io::IoCounters& counters);

  /// Hands every due out-of-range report to `visit(const OutOfRangeReport&)`: per signal the
  /// first clamp at once, then at most one report a second with the count since the last one.
  template <class Visitor>
  void take_out_of_range_reports(std::int64_t now_ns, Visitor&& visit) noexcept {
    for (Message& m : messages_) {
      for (Bound& b : m.bound) {
        const std::uint64_t n = b.reports.take_due(now_ns);
        if (n == 0) continue;
        visit(OutOfRangeReport{.direction = "rx",
                               .message = m.name.c_str(),
                               .signal = b.name.c_str(),
                               .received = b.last_out_of_range,
                               .minimum = b.minimum,
                               .maximum = b.maximum,
                               .count = n});
      }
    }
  }

  /// Number of RX messages; their ids (for kernel receive filters).
  [[nodiscard]] std::size_t message_count() const { return messages_.size(); }
  [[nodiscard]] std::uint32_t message_id(std::size_t i) const { return messages_[i].id; }
  [[nodiscard]] bool message_extended(std::size_t i) const { return messages_[i].extended; }
  /// True while message i is timed out (or has not arrived since reset()).
  [[nodiscard]] bool timed_out(std::size_t i) const { return messages_[i].timed_out; }

 private:
  struct Bound {
    std::size_t codec_signal;
    std::size_t slot;  ///< the input slot (model/signals.h)
    double scale, offset, fallback, minimum, maximum;
    bool clamp;
    std::string name;  // DBC signal name, for reports
    ReportLimiter reports{};
    double last_out_of_range = 0.0;
  };
  struct Message {
    std::uint32_t id = 0;
    bool extended = false;
    std::uint32_t length_bytes = 0;
    bool fd = false;
    std::string name;
    dbc::MessageCodec codec;
    std::vector<Bound> bound;
    std::optional<CounterSpec> counter;
    std::optional<ChecksumSpec> checksum;
    std::optional<e2e::E2eSpec> e2e;
    std::int64_t timeout_ns = 0;
    std::int64_t last_ns = 0;
    bool timed_out = true;
    bool timeout_counted = false;
    SequenceChecker sequence{};
  };
  void apply_fallback(Message& message, model::Signals& signals);
  static RxResult check_e2e(Message& m, const std::uint8_t* data, std::int64_t time_ns,
                            model::Signals& signals, io::IoCounters& counters) noexcept;
  static void accept(Message& m, const std::uint8_t* data, std::int64_t time_ns,
                     model::Signals& signals, io::IoCounters& counters) noexcept;
  static void decode(Message& m, const std::uint8_t* data, model::Signals& signals,
                     io::IoCounters& counters) noexcept;

  std::vector<Message> messages_;
};

}  // namespace rig::io::can::mapping
