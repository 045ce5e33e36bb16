#pragma once
/// @file
/// One CAN or CAN FD data frame as the SocketCAN transport hands it over: plain data, fixed size.

#include <array>
#include <cstdint>

namespace rig::io::can::transport {

struct TransportFrame {
  std::uint32_t id = 0;          ///< 11-bit or 29-bit identifier, without flag bits
  bool extended = false;         ///< 29-bit identifier
  bool fd = false;               ///< CAN FD frame (up to 64 data bytes)
  bool bit_rate_switch = false;  ///< CAN FD BRS flag
  bool remote = false;           ///< classic remote request (no data)
  std::uint8_t len = 0;          ///< data length in bytes (0..8 classic, 0..64 FD)
  std::array<std::uint8_t, 64> data{};
  std::int64_t rx_realtime_ns = 0;  ///< kernel receive timestamp (CLOCK_REALTIME), 0 if none
};

}  // namespace rig::io::can::transport
