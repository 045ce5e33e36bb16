#pragma once
/// @file
/// Frame checksums used by the CAN mapping (load-time and RT-safe: pure functions, no state).
///
/// CRC-8 SAE J1850: polynomial 0x1D, initial value 0xFF, final XOR 0xFF, not reflected
/// (check value over ASCII "123456789" = 0x4B). XOR: XOR of the covered bytes, initial 0.

#include <cstddef>
#include <cstdint>

namespace rig::io::can::mapping {

enum class ChecksumType : std::uint8_t { kCrc8SaeJ1850, kXor };

/// CRC-8 SAE J1850 (poly 0x1D, init 0xFF, xorout 0xFF, refin/refout false) over `len` bytes.
std::uint8_t crc8_sae_j1850(const std::uint8_t* data, std::size_t len) noexcept;

/// XOR of `len` bytes.
std::uint8_t xor8(const std::uint8_t* data, std::size_t len) noexcept;

}  // namespace rig::io::can::mapping
