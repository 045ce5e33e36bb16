#include "io/can/mapping/checksum.h"

#include <array>

namespace rig::io::can::mapping {
namespace {

/// Table of the MSB-first CRC-8 with polynomial 0x1D (x^8 + x^4 + x^3 + x^2 + 1).
constexpr std::array<std::uint8_t, 256> make_crc8_table() {
  std::array<std::uint8_t, 256> table{};
  for (unsigned i = 0; i < 256; ++i) {
    unsigned crc = i;
    for (int bit = 0; bit < 8; ++bit) {
      crc = (crc & 0x80u) != 0 ? ((crc << 1) ^ 0x1Du) : (crc << 1);
    }
    table[i] = static_cast<std::uint8_t>(crc & 0xFFu);
  }
  return table;
}

constexpr std::array<std::uint8_t, 256> kCrc8Table = make_crc8_table();

}  // namespace

std::uint8_t crc8_sae_j1850(const std::uint8_t* data, std::size_t len) noexcept {
  std::uint8_t crc = 0xFF;
  for (std::size_t i = 0; i < len; ++i) crc = kCrc8Table[static_cast<std::uint8_t>(crc ^ data[i])];
  return static_cast<std::uint8_t>(crc ^ 0xFF);
}

std::uint8_t xor8(const std::uint8_t* data, std::size_t len) noexcept {
  std::uint8_t x = 0;
  for (std::size_t i = 0; i < len; ++i) x = static_cast<std::uint8_t>(x ^ data[i]);
  return x;
}

}  // namespace rig::io::can::mapping
