#include "io/can/dbc/signal_codec.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <string>

#include "io/can/dbc/dbc_parser.h"
#include "tests/support/alloc_counter.h"

namespace rig::io::can::dbc {
namespace {

SignalDef make(std::uint32_t start, std::uint32_t length, ByteOrder order, bool is_signed,
               double factor = 1.0, double offset = 0.0) {
  SignalDef s;
  s.start_bit = start;
  s.length_bits = length;
  s.byte_order = order;
  s.is_signed = is_signed;
  s.factor = factor;
  s.offset = offset;
  return s;
}

// Motorola 7|16: MSB at bit 7 of byte 0, so the raw value is simply bytes 0..1 big endian.
TEST(SignalCodec, MotorolaByteAligned) {
  const SignalCodec c(make(7, 16, ByteOrder::kMotorola, false));
  std::array<std::uint8_t, 8> d{};
  c.insert_raw(0x1234, d.data());
  EXPECT_EQ(d[0], 0x12);
  EXPECT_EQ(d[1], 0x34);
  EXPECT_EQ(c.extract_raw(d.data()), 0x1234u);
  EXPECT_EQ(c.required_bytes(), 2u);
}

// Motorola 15|10 (sawtooth): bits 15..8 of byte 1 hold raw bits 9..2, then bits 7..6 of byte 2
// hold raw bits 1..0. Raw 0x2AD = 10 1010 1101b -> byte1 = 1010 1011b = 0xAB, byte2 = 01xx xxxx.
TEST(SignalCodec, MotorolaSawtoothAcrossBytes) {
  const SignalCodec c(make(15, 10, ByteOrder::kMotorola, false));
  std::array<std::uint8_t, 8> d{};
  c.insert_raw(0x2AD, d.data());
  EXPECT_EQ(d[1], 0xAB);
  EXPECT_EQ(d[2], 0x40);
  EXPECT_EQ(c.extract_raw(d.data()), 0x2ADu);
  EXPECT_EQ(c.required_bytes(), 3u);
}

// Motorola 3|12: MSB at bit 3 of byte 0 -> raw bits 11..8 in byte 0 bits 3..0, bits 7..0 in
// byte 1.
TEST(SignalCodec, MotorolaMidByteStart) {
  const SignalCodec c(make(3, 12, ByteOrder::kMotorola, false));
  std::array<std::uint8_t, 8> d{};
  d.fill(0xFF);
  c.insert_raw(0x5A3, d.data());
  EXPECT_EQ(d[0], 0xF5);  // upper nibble untouched
  EXPECT_EQ(d[1], 0xA3);
  EXPECT_EQ(d[2], 0xFF);
}

// Intel 4|12: raw bits 3..0 in byte 0 bits 7..4, raw bits 11..4 in byte 1.
TEST(SignalCodec, IntelAcrossBytes) {
  const SignalCodec c(make(4, 12, ByteOrder::kIntel, false));
  std::array<std::uint8_t, 8> d{};
  c.insert_raw(0xABC, d.data());
  EXPECT_EQ(d[0], 0xC0);
  EXPECT_EQ(d[1], 0xAB);
  EXPECT_EQ(c.extract_raw(d.data()), 0xABCu);
}

TEST(SignalCodec, SignExtensionFactorOffset) {
  const SignalCodec c(make(0, 12, ByteOrder::kIntel, true, 0.5, 10.0));
  EXPECT_EQ(c.raw_to_physical(0xFFF), -0.5 + 10.0);
  EXPECT_EQ(c.raw_to_physical(0x800), -2048 * 0.5 + 10.0);
  EXPECT_EQ(c.raw_to_physical(0x7FF), 2047 * 0.5 + 10.0);
  EXPECT_EQ(c.physical_to_raw(-0.5 + 10.0), 0xFFFu);
  // Saturation at the raw range, NaN -> 0.
  EXPECT_EQ(c.physical_to_raw(1e9), 0x7FFu);
  EXPECT_EQ(c.physical_to_raw(-1e9), 0x800u);
  EXPECT_EQ(c.physical_to_raw(std::nan("")), 0u);
  const SignalCodec u(make(0, 8, ByteOrder::kIntel, false));
  EXPECT_EQ(u.physical_to_raw(-3.0), 0u);
  EXPECT_EQ(u.physical_to_raw(300.0), 255u);
  EXPECT_EQ(u.physical_to_raw(2.6), 3u);  // rounded to nearest
}

TEST(SignalCodec, SixtyFourBitSignals) {
  SignalDef s = make(0, 64, ByteOrder::kIntel, true);
  const SignalCodec i64(s);
  std::array<std::uint8_t, 8> d{};
  i64.encode(-2.0, d.data());
  EXPECT_EQ(d[7], 0xFF);
  EXPECT_EQ(i64.decode(d.data()), -2.0);
  EXPECT_EQ(i64.physical_to_raw(1e30), 0x7FFFFFFFFFFFFFFFu);
  s.value_type = ValueType::kFloat64;
  const SignalCodec f64(s);
  f64.encode(-12345.678, d.data());
  EXPECT_EQ(f64.decode(d.data()), -12345.678);
  const SignalCodec m64(make(7, 64, ByteOrder::kMotorola, false));
  m64.insert_raw(0x0102030405060708u, d.data());
  EXPECT_EQ(d[0], 0x01);
  EXPECT_EQ(d[7], 0x08);
}

TEST(SignalCodec, Float32Reinterpretation) {
  SignalDef s = make(0, 32, ByteOrder::kIntel, true);
  s.value_type = ValueType::kFloat32;
  const SignalCodec c(s);
  std::array<std::uint8_t, 8> d{};
  c.encode(12.5, d.data());
  // 12.5f = 0x41480000, little endian.
  EXPECT_EQ(d[0], 0x00);
  EXPECT_EQ(d[2], 0x48);
  EXPECT_EQ(d[3], 0x41);
  EXPECT_EQ(c.decode(d.data()), 12.5);
  c.encode(1e300, d.data());  // saturates to FLT_MAX, no UB
  EXPECT_EQ(c.decode(d.data()), static_cast<double>(3.4028234663852886e38f));
}

/// Round trip of every signal of the example DBC at random raw values: encode(decode(raw)) ==
/// raw, other bits untouched, and no allocation in the message codec.
TEST(MessageCodec, ExampleDatabaseRoundTripWithoutAllocation) {
  const Database db = load_dbc(std::string(RIG_CAN_CONFIG_DIR) + "/steering-bench.dbc");
  std::mt19937_64 rng(42);
  for (const MessageDef& m : db.messages) {
    const MessageCodec codec(m);
    std::vector<double> physical(m.signals.size());
    bool present[64];
    std::array<std::uint8_t, 64> frame{}, again{};
    for (int round = 0; round < 200; ++round) {
      for (std::uint32_t b = 0; b < m.length_bytes; ++b)
        frame[b] = static_cast<std::uint8_t>(rng());
      for (std::size_t i = 0; i < m.signals.size(); ++i) {
        if (m.signals[i].value_type == ValueType::kFloat32) {
          codec.signal(i).insert_raw(0x3F800000u + (rng() & 0xFFFF), frame.data());  // finite
        }
        if (m.signals[i].value_type == ValueType::kFloat64) {
          codec.signal(i).insert_raw(0x4000000000000000u + (rng() & 0xFFFFFF), frame.data());
        }
      }
      test::AllocationCounter allocations;
      ASSERT_TRUE(codec.decode(frame.data(), m.length_bytes, physical,
                               std::span<bool>(present, m.signals.size())));
      codec.encode(physical, again.data());
      EXPECT_EQ(allocations.count(), 0u);
      // Every bit covered by a present signal must come back identical.
      const std::uint64_t mux =
          codec.multiplexor_index() >= 0
              ? codec.signal(static_cast<std::size_t>(codec.multiplexor_index()))
                    .extract_raw(frame.data())
              : 0;
      for (std::size_t i = 0; i < m.signals.size(); ++i) {
        if (!codec.present(i, mux)) continue;
        EXPECT_EQ(codec.signal(i).extract_raw(again.data()),
                  codec.signal(i).extract_raw(frame.data()))
            << m.name << "." << m.signals[i].name;
      }
    }
  }
}

TEST(MessageCodec, MultiplexedPagesAndShortFrames) {
  const Database db = parse_dbc(R"(BO_ 1 M: 4 A
 SG_ Sw M : 0|2@1+ (1,0) [0|3] "" B
 SG_ Always : 8|8@1+ (1,0) [0|0] "" B
 SG_ P0 m0 : 16|8@1+ (1,0) [0|0] "" B
 SG_ P1 m1 : 16|16@1- (1,0) [0|0] "" B
)",
                                "t.dbc");
  const MessageCodec c(db.messages[0]);
  std::array<double, 4> physical{1.0, 7.0, 5.0, -300.0};
  std::array<std::uint8_t, 4> d{};
  c.encode(physical, d.data());
  EXPECT_EQ(d[0], 0x01);
  EXPECT_EQ(d[1], 7);
  EXPECT_EQ(static_cast<std::int16_t>(d[2] | (d[3] << 8)), -300);  // page 1, not P0
  std::array<double, 4> out{};
  bool present[4];
  ASSERT_TRUE(c.decode(d.data(), 4, out, present));
  EXPECT_FALSE(present[2]);
  EXPECT_TRUE(present[3]);
  EXPECT_EQ(out[3], -300.0);
  EXPECT_FALSE(c.decode(d.data(), 3, out, present));  // too short: nothing decoded
}

}  // namespace
}  // namespace rig::io::can::dbc
