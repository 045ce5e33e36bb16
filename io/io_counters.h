#pragma once
/// @file
/// Counters of the I/O adapters, plain data, visible in the summary JSON and on LCM.

#include <cstdint>

namespace rig::io {

/// In order of severity (summing counters keeps the worst). kErrorPassive: the controller
/// reported errors (any CAN error frame) and has not reported error-active since; kBusOff: it
/// reported bus-off and no restart since; kDown: the interface is down or gone.
enum class BusState : std::uint8_t { kDisabled, kUp, kErrorPassive, kBusOff, kDown };

/// "disabled", "up", "error-passive", "bus-off", "down".
constexpr const char* bus_state_name(BusState s) noexcept {
  switch (s) {
    case BusState::kDisabled:
      return "disabled";
    case BusState::kUp:
      return "up";
    case BusState::kErrorPassive:
      return "error-passive";
    case BusState::kBusOff:
      return "bus-off";
    case BusState::kDown:
      return "down";
  }
  return "?";
}

struct IoCounters {
  BusState bus_state = BusState::kDisabled;
  std::uint64_t frames_received = 0;
  std::uint64_t rx_overflows = 0;  ///< frames the kernel dropped at our socket (SO_RXQ_OVFL)
  std::uint64_t frames_sent = 0;
  std::uint64_t timeouts = 0;  ///< message timeouts (fallback applied)
  std::uint64_t checksum_failures = 0;
  std::uint64_t counter_failures = 0;  ///< alive counter frozen or jumped
  std::uint64_t bad_frames = 0;        ///< wrong DLC and the like
  std::uint64_t unknown_frames = 0;    ///< IDs not in the mapping
  std::uint64_t error_frames = 0;      ///< CAN_ERR_FLAG frames (set bus_state error-passive)
  std::uint64_t out_of_range = 0;      ///< physical values clamped
  std::uint64_t send_no_buffer = 0;    ///< ENOBUFS on send
  std::uint64_t send_dropped = 0;
  std::uint64_t reopens = 0;  ///< interface down/vanished and reopened
};

/// Sums the counters of several adapters: counts add up; the bus state is the worst one
/// (disabled < up < down), so one adapter without a bus does not hide another's.
constexpr IoCounters& operator+=(IoCounters& sum, const IoCounters& c) noexcept {
  if (c.bus_state > sum.bus_state) sum.bus_state = c.bus_state;
  sum.frames_received += c.frames_received;
  sum.rx_overflows += c.rx_overflows;
  sum.frames_sent += c.frames_sent;
  sum.timeouts += c.timeouts;
  sum.checksum_failures += c.checksum_failures;
  sum.counter_failures += c.counter_failures;
  sum.bad_frames += c.bad_frames;
  sum.unknown_frames += c.unknown_frames;
  sum.error_frames += c.error_frames;
  sum.out_of_range += c.out_of_range;
  sum.send_no_buffer += c.send_no_buffer;
  sum.send_dropped += c.send_dropped;
  sum.reopens += c.reopens;
  return sum;
}
static_assert(sizeof(IoCounters) == 8 + 13 * sizeof(std::uint64_t),
              "a new counter must be summed in operator+=");

}  // namespace rig::io
