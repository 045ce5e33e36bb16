#include "io/can/mapping/checksum.h"

#include "io/can/e2e/crc.h"

namespace rig::io::can::mapping {
namespace {

constexpr e2e::Crc kCrc8SaeJ1850(e2e::presets::kCrc8SaeJ1850);

}  // namespace

std::uint8_t crc8_sae_j1850(const std::uint8_t* data, std::size_t len) noexcept {
  return static_cast<std::uint8_t>(kCrc8SaeJ1850.compute(data, len));
}

std::uint8_t xor8(const std::uint8_t* data, std::size_t len) noexcept {
  std::uint8_t x = 0;
  for (std::size_t i = 0; i < len; ++i) x = static_cast<std::uint8_t>(x ^ data[i]);
  return x;
}

}  // namespace rig::io::can::mapping
