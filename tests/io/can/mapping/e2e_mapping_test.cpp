// The E2E test bench mapping (tests/io/can/e2e/e2e-bench.toml) through the RX/TX engines: every
// frame the TxScheduler sends passes the profile check with the configured Data ID and counts
// up over the profile's counter range; frames protected with the (Python-verified) profiles are
// accepted and decoded; a wrong Data ID, a repeated and a skipped counter are rejected and
// counted; nothing allocates per frame.
#include <gtest/gtest.h>

#include <array>
#include <string>

#include "io/can/dbc/signal_codec.h"
#include "io/can/e2e/crc.h"
#include "io/can/mapping/rx_processor.h"
#include "io/can/mapping/tx_scheduler.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/legacy_cycle.h"

namespace rig::io::can {
namespace {

using model::Signal;
constexpr std::int64_t kMs = 1'000'000;

mapping::CanConfig bench() {
  return mapping::load_can_config(std::string(RIG_E2E_TEST_DIR) + "/e2e-bench.toml");
}

TEST(E2eMapping, BenchLoadsWithEveryProfile) {
  const mapping::CanConfig c = bench();
  ASSERT_EQ(c.mapping.rx.size(), 5u);
  ASSERT_EQ(c.mapping.tx.size(), 5u);
  EXPECT_EQ(c.mapping.rx[0].e2e->profile, e2e::Profile::kP01);
  EXPECT_EQ(c.mapping.rx[1].e2e->data_id_list[15], 2);
  EXPECT_EQ(c.mapping.rx[2].e2e->length_bytes, 16u);
  EXPECT_EQ(c.mapping.rx[3].e2e->max_delta_counter, 2u);
  EXPECT_EQ(c.mapping.tx[3].e2e->offset_bits, 40u);
  ASSERT_TRUE(c.mapping.rx[4].checksum.has_value());
  EXPECT_EQ(*c.mapping.rx[4].checksum->position_byte, 6u);
  EXPECT_EQ(c.mapping.rx[4].checksum->crc.params().poly, 0x1021u);
}

TEST(E2eMapping, SentFramesPassTheProfileCheckWithCountersCountingUp) {
  const mapping::CanConfig c = bench();
  mapping::TxScheduler tx(c);
  model::Signals signals;
  test::LegacyCycle legacy;
  signals.set(Signal::kVehicleSpeed, 20.0);
  IoCounters counters;
  for (std::size_t i = 0; i < 4; ++i) {
    const e2e::E2eSpec& spec = *c.mapping.tx[i].e2e;
    const std::uint32_t modulus = e2e::counter_modulus(spec.profile);
    for (std::uint32_t k = 0; k < 40; ++k) {
      mapping::TxFrame f;
      tx.encode(i, legacy.view(signals), f, counters);
      const e2e::CheckResult r = e2e::check(spec, f.data.data());
      EXPECT_TRUE(r.crc_ok) << "message " << i << " send " << k;
      EXPECT_EQ(r.counter, k % modulus) << "message " << i;
    }
  }
  mapping::TxFrame f;
  tx.encode(4, legacy.view(signals), f,
            counters);  // CRC-32 of bytes 0..3, big-endian in bytes 4..7
  const std::uint32_t crc = e2e::Crc(e2e::presets::kCrc32).compute(f.data.data(), 4);
  EXPECT_EQ(f.data[4], crc >> 24);
  EXPECT_EQ(f.data[7], crc & 0xFFu);
  EXPECT_NEAR((f.data[0] | (f.data[1] << 8)) * 0.01 / 3.6, 20.0, 0.01 / 3.6);
}

class E2eRx : public ::testing::Test {
 protected:
  E2eRx() : config_(bench()), rx_(config_) { rx_.reset(0, signals_); }

  /// A protected frame of RX message i carrying `physical` in its mapped signal.
  std::array<std::uint8_t, 64> frame(std::size_t i, double physical, std::uint32_t counter,
                                     std::uint32_t data_id_xor = 0) {
    const mapping::MessageBinding& b = config_.mapping.rx[i];
    const dbc::MessageDef& m = config_.database.messages[b.dbc_message];
    std::array<std::uint8_t, 64> d{};
    dbc::SignalCodec(m.signals[b.signals[0].dbc_signal]).encode(physical, d.data());
    e2e::E2eSpec spec = *b.e2e;
    spec.data_id ^= data_id_xor;
    if (data_id_xor != 0) spec.data_id_list[counter & 0x0Fu] ^= 0x01;
    e2e::protect(spec, d.data(), counter);
    return d;
  }
  mapping::RxResult feed(std::size_t i, const std::array<std::uint8_t, 64>& d, std::int64_t t) {
    const dbc::MessageDef& m = config_.database.messages[config_.mapping.rx[i].dbc_message];
    return rx_.on_frame(m.id, false,
                        m.is_fd() ? mapping::FrameFormat::kFd : mapping::FrameFormat::kClassic,
                        d.data(), m.length_bytes, t, signals_, counters_);
  }

  mapping::CanConfig config_;
  mapping::RxProcessor rx_;
  model::Signals signals_;
  test::LegacyCycle legacy_;
  IoCounters counters_;
};

TEST_F(E2eRx, ProtectedFramesAreDecoded) {
  ASSERT_EQ(feed(0, frame(0, 12.34, 0), kMs), mapping::RxResult::kAccepted);
  ASSERT_EQ(feed(1, frame(1, 0.5, 7), kMs), mapping::RxResult::kAccepted);
  ASSERT_EQ(feed(2, frame(2, 80.0, 65535), kMs), mapping::RxResult::kAccepted);
  ASSERT_EQ(feed(3, frame(3, 42.0, 200), kMs), mapping::RxResult::kAccepted);
  EXPECT_NEAR(signals_[Signal::kAssistTorque], 12.34, 1e-9);
  EXPECT_NEAR(signals_[Signal::kThrottlePedal], 0.5, 1e-9);
  EXPECT_NEAR(signals_[Signal::kBrakePressureFront], 80.0e5, 1e-3);
  EXPECT_NEAR(signals_[Signal::kBrakePressureRear], 42.0e5, 1e-3);
  EXPECT_EQ(counters_.checksum_failures + counters_.counter_failures, 0u);
}

TEST_F(E2eRx, WrongDataIdRepeatedAndSkippedCountersAreRejectedAndCounted) {
  for (std::size_t i = 0; i < 4; ++i) {
    const std::uint32_t step_limit = config_.mapping.rx[i].e2e->max_delta_counter;
    const IoCounters before = counters_;
    std::int64_t t = kMs;
    EXPECT_EQ(feed(i, frame(i, 1.0, 1), t), mapping::RxResult::kAccepted) << i;
    EXPECT_EQ(feed(i, frame(i, 1.0, 2, 0x0101), t += kMs), mapping::RxResult::kChecksumFailure)
        << "wrong Data ID, message " << i;
    EXPECT_EQ(feed(i, frame(i, 1.0, 2), t += kMs), mapping::RxResult::kAccepted) << i;
    EXPECT_EQ(feed(i, frame(i, 1.0, 2), t += kMs), mapping::RxResult::kCounterFailure)
        << "repeated, message " << i;
    EXPECT_EQ(feed(i, frame(i, 1.0, 3), t += kMs), mapping::RxResult::kAccepted) << i;
    EXPECT_EQ(feed(i, frame(i, 1.0, 4 + step_limit), t += kMs), mapping::RxResult::kCounterFailure)
        << "skipped, message " << i;
    EXPECT_EQ(counters_.checksum_failures - before.checksum_failures, 1u) << i;
    EXPECT_EQ(counters_.counter_failures - before.counter_failures, 2u) << i;
  }
}

TEST_F(E2eRx, P01CounterValueFifteenIsRejected) {
  EXPECT_EQ(feed(0, frame(0, 1.0, 14), kMs), mapping::RxResult::kAccepted);
  EXPECT_EQ(feed(0, frame(0, 1.0, 0), 2 * kMs), mapping::RxResult::kAccepted);  // 14 -> 0 wraps
  EXPECT_NE(feed(0, frame(0, 1.0, 15), 3 * kMs), mapping::RxResult::kAccepted);
}

TEST_F(E2eRx, GenericCrcAtAPosition) {
  std::array<std::uint8_t, 64> d{};
  d[0] = 0x10;  // 0x0010 * 0.01 = 0.16 N m
  const std::uint32_t crc = e2e::Crc(e2e::presets::kCrc16CcittFalse).compute(d.data(), 6);
  d[6] = static_cast<std::uint8_t>(crc >> 8);
  d[7] = static_cast<std::uint8_t>(crc);
  EXPECT_EQ(feed(4, d, kMs), mapping::RxResult::kAccepted);
  EXPECT_NEAR(signals_[Signal::kSteeringWheelTorqueCmd], 0.16, 1e-12);
  d[7] ^= 0x01;
  EXPECT_EQ(feed(4, d, 2 * kMs), mapping::RxResult::kChecksumFailure);
  EXPECT_EQ(counters_.checksum_failures, 1u);
}

TEST_F(E2eRx, NothingAllocatesPerFrame) {
  const auto p04 = frame(2, 10.0, 1);
  const auto p04_next = frame(2, 10.0, 2);
  mapping::TxScheduler tx(config_);
  mapping::TxFrame f;
  test::AllocationCounter allocations;
  feed(2, p04, kMs);
  feed(2, p04_next, 2 * kMs);
  tx.encode(2, legacy_.view(signals_), f, counters_);
  EXPECT_EQ(allocations.count(), 0u);
}

}  // namespace
}  // namespace rig::io::can
