#pragma once
/// @file
/// Constant parameters of the SocketCAN transport.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rig::io::can::transport {

struct TransportSettings {
  std::string interface = "vcan0";  ///< e.g. can0, vcan0
  bool fd = true;                   ///< CAN_RAW_FD_FRAMES: receive and send CAN FD frames too
  /// Kernel filter (CAN_RAW_FILTER): exact identifiers to receive; standard ids < 0x800 are
  /// matched as 11-bit, `extended_filter_ids` as 29-bit. Both empty = receive everything (then
  /// the bridge sees, and counts, unknown identifiers).
  std::vector<std::uint32_t> filter_ids;
  std::vector<std::uint32_t> extended_filter_ids;
  bool use_filter = false;                        ///< install the filter above (else receive all)
  std::int64_t reopen_interval_ns = 100'000'000;  ///< bounded reopen rate while the bus is down
  std::size_t max_frames_per_drain = 4096;        ///< bound on one cycle's work under a flood
  int receive_buffer_bytes = 0;                   ///< SO_RCVBUF, 0 = kernel default
};

}  // namespace rig::io::can::transport
