#pragma once
/// @file
/// The receive half of the CAN mapping, independent of sockets: validates a received frame
/// (length, checksum, alive counter), decodes its mapped signals, clamps them to the DBC range,
/// converts them to SI and writes them into model::Signals. Watches message timeouts.
///
/// RT-safe: on_frame() and check_timeouts() never allocate, never throw, do no string work.
/// Use one clock for all times (e.g. the loop's CLOCK_MONOTONIC cycle time).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "io/can/dbc/signal_codec.h"
#include "io/can/mapping/can_mapping.h"
#include "io/io_counters.h"
#include "model/signals.h"

namespace rig::io::can::mapping {

/// What on_frame() did with a frame (also counted in IoCounters).
enum class RxResult : std::uint8_t {
  kAccepted,         ///< decoded and written
  kUnknownId,        ///< id/extended flag not in the RX mapping (unknown_frames)
  kBadLength,        ///< length differs from the DBC length (bad_frames)
  kChecksumFailure,  ///< checksum wrong (checksum_failures), frame rejected
  kCounterFailure,   ///< counter frozen or jumped (counter_failures), frame rejected
};

class RxProcessor {
 public:
  /// Compiles the RX bindings of `config` (load time; keeps a pointer to nothing in config).
  explicit RxProcessor(const CanConfig& config);

  /// Applies every fallback with valid = false and starts every timeout clock at `now_ns`.
  /// Call once before the first cycle (and after the bus comes back, if wanted).
  void reset(std::int64_t now_ns, model::Signals& signals);

  /// Handles one received data frame. `id` without flag bits; `len` in bytes.
  /// Counts into `counters`: unknown_frames, bad_frames, checksum_failures, counter_failures,
  /// out_of_range (each clamped or non-finite value). frames_received is the transport's count,
  /// not touched here. A rejected frame changes no signal and does not reset the timeout.
  RxResult on_frame(std::uint32_t id, bool extended, const std::uint8_t* data, std::size_t len,
                    std::int64_t time_ns, model::Signals& signals, io::IoCounters& counters);

  /// Applies the fallback (valid = false) of every message whose last accepted frame is older
  /// than its timeout. Counts one `timeouts` per message per timeout episode. Call every cycle.
  void check_timeouts(std::int64_t now_ns, model::Signals& signals, io::IoCounters& counters);

  /// Number of RX messages; their ids (for kernel receive filters).
  [[nodiscard]] std::size_t message_count() const { return messages_.size(); }
  [[nodiscard]] std::uint32_t message_id(std::size_t i) const { return messages_[i].id; }
  [[nodiscard]] bool message_extended(std::size_t i) const { return messages_[i].extended; }
  /// True while message i is timed out (or has not arrived since reset()).
  [[nodiscard]] bool timed_out(std::size_t i) const { return messages_[i].timed_out; }

 private:
  struct Bound {
    std::size_t codec_signal;
    model::Signal model;
    double scale, offset, fallback, minimum, maximum;
    bool clamp;
  };
  struct Message {
    std::uint32_t id = 0;
    bool extended = false;
    std::uint32_t length_bytes = 0;
    dbc::MessageCodec codec;
    std::vector<Bound> bound;
    std::optional<CounterSpec> counter;
    std::optional<ChecksumSpec> checksum;
    std::int64_t timeout_ns = 0;
    std::int64_t last_ns = 0;
    bool timed_out = true;
    bool timeout_counted = false;
    bool have_counter = false;
    std::uint32_t last_counter = 0;
  };
  void apply_fallback(Message& message, model::Signals& signals);

  std::vector<Message> messages_;
};

}  // namespace rig::io::can::mapping
