// The AUTOSAR E2E profiles (io/can/e2e/e2e_profile.h) against frames protected by the
// independent Python reference (tests/io/can/e2e_reference.py, CRCs through python3-crcmod):
// e2e_vectors.inc, its configurations mirrored here in kConfigs (VECTOR_CONFIGS there).
#include "io/can/e2e/e2e_profile.h"

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace rig::io::can::e2e {
namespace {

E2eSpec p01(std::uint32_t id, DataIdMode mode, std::uint32_t crc_at = 0, std::uint32_t ctr_at = 8) {
  E2eSpec s;
  s.profile = Profile::kP01;
  s.data_id = id;
  s.data_id_mode = mode;
  s.crc_offset_bits = crc_at;
  s.counter_offset_bits = ctr_at;
  s.length_bytes = 8;
  return s;
}

E2eSpec p02() {
  E2eSpec s;
  s.profile = Profile::kP02;
  for (unsigned i = 0; i < 16; ++i)
    s.data_id_list[i] = static_cast<std::uint8_t>((17 * i + 3) & 0xFF);
  s.length_bytes = 8;
  return s;
}

E2eSpec header(Profile p, std::uint32_t id, std::uint32_t length, std::uint32_t offset) {
  E2eSpec s;
  s.profile = p;
  s.data_id = id;
  s.length_bytes = length;
  s.offset_bits = offset;
  return s;
}

const std::array<E2eSpec, 10> kConfigs = {
    p01(0x1234, DataIdMode::kBoth),
    p01(0x1234, DataIdMode::kAlt),
    p01(0x0042, DataIdMode::kLow),
    p01(0x0ABC, DataIdMode::kNibble),
    p01(0xBEEF, DataIdMode::kBoth, 56, 52),
    p02(),
    header(Profile::kP04, 0x0A0B0C0D, 16, 0),
    header(Profile::kP04, 0x12345678, 24, 64),
    header(Profile::kP05, 0x1234, 8, 0),
    header(Profile::kP05, 0xCAFE, 12, 40),
};

struct Vector {
  std::size_t config;
  std::uint32_t counter;
  std::size_t length;
  std::vector<std::uint8_t> frame;
};

const std::vector<Vector> kVectors = {
#include "tests/io/can/e2e/e2e_vectors.inc"
};

TEST(E2eProfiles, ProtectGivesTheReferenceFrames) {
  ASSERT_EQ(kVectors.size(), 8 * kConfigs.size());
  for (const Vector& v : kVectors) {
    const E2eSpec& s = kConfigs[v.config];
    ASSERT_EQ(v.length, s.length_bytes);
    std::vector<std::uint8_t> mine = v.frame;
    protect(s, mine.data(), v.counter);  // recomputes every E2E field from the data
    EXPECT_EQ(mine, v.frame) << "config " << v.config << " counter " << v.counter;
  }
}

TEST(E2eProfiles, CheckAcceptsTheReferenceFramesWithTheirCounter) {
  for (const Vector& v : kVectors) {
    const CheckResult r = check(kConfigs[v.config], v.frame.data());
    EXPECT_TRUE(r.crc_ok) << "config " << v.config;
    EXPECT_EQ(r.counter, v.counter) << "config " << v.config;
  }
}

TEST(E2eProfiles, CheckRejectsAFlippedBitAndAWrongDataId) {
  for (const Vector& v : kVectors) {
    E2eSpec s = kConfigs[v.config];
    for (std::size_t byte = 0; byte < v.length; ++byte) {
      std::vector<std::uint8_t> bad = v.frame;
      bad[byte] ^= 0x10;
      EXPECT_FALSE(check(s, bad.data()).crc_ok) << "config " << v.config << " byte " << byte;
    }
    if (s.profile == Profile::kP02) {
      s.data_id_list[v.counter] ^= 0x01;
    } else if (s.data_id_mode == DataIdMode::kAlt) {
      s.data_id ^= v.counter % 2 == 0 ? 0x0001u : 0x0100u;  // the byte this counter uses
    } else {
      s.data_id ^= 0x01;
    }
    EXPECT_FALSE(check(s, v.frame.data()).crc_ok) << "wrong Data ID, config " << v.config;
  }
}

TEST(E2eProfiles, P01CounterFifteenIsNoCounterValue) {
  EXPECT_EQ(counter_modulus(Profile::kP01), 15u);
  EXPECT_EQ(counter_modulus(Profile::kP02), 16u);
  EXPECT_EQ(counter_modulus(Profile::kP04), 65536u);
  EXPECT_EQ(counter_modulus(Profile::kP05), 256u);
}

TEST(E2eProfiles, FieldMasksCoverTheHeaders) {
  const auto p04 = field_mask(kConfigs[7]);  // 12 bytes from byte 8
  for (std::size_t i = 0; i < 24; ++i) EXPECT_EQ(p04[i], i >= 8 && i < 20 ? 0xFF : 0x00) << i;
  const auto nibble = field_mask(kConfigs[3]);  // CRC byte 0, counter and Data ID nibble byte 1
  EXPECT_EQ(nibble[0], 0xFF);
  EXPECT_EQ(nibble[1], 0xFF);
  EXPECT_EQ(nibble[2], 0x00);
}

}  // namespace
}  // namespace rig::io::can::e2e
