#pragma once
/// @file
/// Counters of the I/O adapters, plain data, visible in the summary JSON and on LCM.

#include <cstdint>

namespace rig::io {

enum class BusState : std::uint8_t { kDisabled, kUp, kDown };

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
  std::uint64_t error_frames = 0;      ///< CAN_ERR_FLAG frames
  std::uint64_t out_of_range = 0;      ///< physical values clamped
  std::uint64_t send_no_buffer = 0;    ///< ENOBUFS on send
  std::uint64_t send_dropped = 0;
  std::uint64_t reopens = 0;  ///< interface down/vanished and reopened
};

}  // namespace rig::io
