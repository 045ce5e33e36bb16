#pragma once
/// @file
/// What the transport counts (plain data). The bridge copies these into io::IoCounters.

#include <cstdint>

namespace rig::io::can::transport {

struct TransportCounters {
  std::uint64_t frames_received = 0;  ///< data frames handed over
  std::uint64_t frames_sent = 0;
  std::uint64_t error_frames = 0;  ///< CAN_ERR_FLAG frames (CAN_RAW_ERR_FILTER)
  std::uint64_t malformed = 0;     ///< reads that are neither CAN_MTU nor CANFD_MTU long
  std::uint64_t rx_overflows = 0;  ///< frames the kernel dropped, socket buffer full (SO_RXQ_OVFL)
  std::uint64_t send_no_buffer = 0;  ///< ENOBUFS/EAGAIN on send (frame kept for one retry)
  std::uint64_t send_dropped =
      0;  ///< frames given up: second refusal, queue full, bus down, EINVAL
  std::uint64_t bus_down_events = 0;  ///< ENETDOWN/ENODEV seen while up
  std::uint64_t reopens = 0;          ///< successful reopens after the bus was down
  std::uint64_t other_errors = 0;     ///< unexpected errno from recv/send
};

}  // namespace rig::io::can::transport
