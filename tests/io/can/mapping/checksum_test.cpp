#include "io/can/mapping/checksum.h"

#include <gtest/gtest.h>

#include <array>
#include <cstring>

namespace rig::io::can {
namespace {

// CRC-8 SAE J1850: poly 0x1D, init 0xFF, xorout 0xFF, not reflected.
TEST(Crc8SaeJ1850, CheckValueOf123456789Is0x4B) {
  const char* text = "123456789";
  EXPECT_EQ(
      can::mapping::crc8_sae_j1850(reinterpret_cast<const std::uint8_t*>(text), std::strlen(text)),
      0x4B);
}

// Test vectors of the AUTOSAR CRC library specification (SWS_Crc, "8-bit SAE J1850 CRC").
TEST(Crc8SaeJ1850, AutosarVectors) {
  const std::array<std::uint8_t, 4> a{0x00, 0x00, 0x00, 0x00};
  const std::array<std::uint8_t, 3> b{0xF2, 0x01, 0x83};
  const std::array<std::uint8_t, 4> c{0x0F, 0xAA, 0x00, 0x55};
  const std::array<std::uint8_t, 4> d{0x00, 0xFF, 0x55, 0x11};
  const std::array<std::uint8_t, 9> e{0x33, 0x22, 0x55, 0xAA, 0xBB, 0xCC, 0xDD, 0xEE, 0xFF};
  const std::array<std::uint8_t, 3> f{0x92, 0x6B, 0x55};
  const std::array<std::uint8_t, 4> g{0xFF, 0xFF, 0xFF, 0xFF};
  EXPECT_EQ(can::mapping::crc8_sae_j1850(a.data(), a.size()), 0x59);
  EXPECT_EQ(can::mapping::crc8_sae_j1850(b.data(), b.size()), 0x37);
  EXPECT_EQ(can::mapping::crc8_sae_j1850(c.data(), c.size()), 0x79);
  EXPECT_EQ(can::mapping::crc8_sae_j1850(d.data(), d.size()), 0xB8);
  EXPECT_EQ(can::mapping::crc8_sae_j1850(e.data(), e.size()), 0xCB);
  EXPECT_EQ(can::mapping::crc8_sae_j1850(f.data(), f.size()), 0x8C);
  EXPECT_EQ(can::mapping::crc8_sae_j1850(g.data(), g.size()), 0x74);
}

TEST(Crc8SaeJ1850, EmptyInputIsInitXorOut) {
  EXPECT_EQ(can::mapping::crc8_sae_j1850(nullptr, 0), 0x00);
}

TEST(Xor8, XorOfBytes) {
  const std::array<std::uint8_t, 4> a{0x12, 0x34, 0x56, 0x78};
  EXPECT_EQ(can::mapping::xor8(a.data(), a.size()), 0x12 ^ 0x34 ^ 0x56 ^ 0x78);
  EXPECT_EQ(can::mapping::xor8(a.data(), 0), 0x00);
}

}  // namespace
}  // namespace rig::io::can
