#pragma once
/// @file
/// Frame checksums used by the CAN mapping (load-time and RT-safe: pure functions, no state).
///
/// CRC-8 SAE J1850 (the preset of io/can/e2e/crc.h): polynomial 0x1D, init 0xFF, xorout 0xFF, not
/// reflected (check value over ASCII "123456789" = 0x4B). XOR: XOR of the covered bytes, initial 0.

#include <cstddef>
#include <cstdint>

namespace rig::io::can::mapping {

/// kCrc8SaeJ1850 is the preset of the generic CRC (io/can/e2e/crc.h) that kCrc configures.
enum class ChecksumType : std::uint8_t { kCrc8SaeJ1850, kXor, kCrc };

/// CRC-8 SAE J1850 (poly 0x1D, init 0xFF, xorout 0xFF, refin/refout false) over `len` bytes.
std::uint8_t crc8_sae_j1850(const std::uint8_t* data, std::size_t len) noexcept;

/// XOR of `len` bytes.
std::uint8_t xor8(const std::uint8_t* data, std::size_t len) noexcept;

}  // namespace rig::io::can::mapping
