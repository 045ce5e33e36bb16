#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "tests/support/legacy_cycle.h"
#include "io/can/dbc/dbc_parser.h"
#include "io/can/mapping/rx_processor.h"
#include "io/can/mapping/tx_scheduler.h"
#include "tests/support/alloc_counter.h"

namespace rig::io::can {
namespace {

using model::Signal;
constexpr std::int64_t kMs = 1'000'000;

/// Builds RX frames of the example database by hand: signal values, counter, checksum.
class RxTest : public ::testing::Test {
 protected:
  RxTest()
      : config_(can::mapping::load_can_config(std::string(RIG_CAN_CONFIG_DIR) +
                                              "/steering-bench.toml")),
        rx_(config_) {
    rx_.reset(0, signals_);
  }

  const dbc::MessageDef& message(const char* name) { return *config_.database.find_message(name); }

  /// A frame of `name` with the given physical values, counter and a correct checksum.
  std::array<std::uint8_t, 8> frame(const char* name,
                                    std::vector<std::pair<const char*, double>> values,
                                    std::uint32_t counter, bool crc = true) {
    const dbc::MessageDef& m = message(name);
    std::array<std::uint8_t, 8> d{};
    for (const auto& [signal, value] : values) {
      dbc::SignalCodec(*m.find_signal(signal)).encode(value, d.data());
    }
    for (const auto& s : m.signals) {
      if (s.name.find("Counter") != std::string::npos)
        dbc::SignalCodec(s).insert_raw(counter, d.data());
    }
    const std::uint8_t sum =
        crc ? can::mapping::crc8_sae_j1850(d.data(), 7) : can::mapping::xor8(d.data(), 7);
    d[7] = sum;  // every checksum of the example lives in byte 7 and covers bytes 0..6
    return d;
  }

  can::mapping::RxResult feed(std::uint32_t id, const std::array<std::uint8_t, 8>& d,
                              std::int64_t t_ns, bool extended = false) {
    return rx_.on_frame(id, extended, can::mapping::FrameFormat::kClassic, d.data(), d.size(), t_ns,
                        signals_, counters_);
  }

  can::mapping::CanConfig config_;
  can::mapping::RxProcessor rx_;
  model::Signals signals_;
  test::LegacyCycle legacy_;
  IoCounters counters_;
};

TEST_F(RxTest, ResetAppliesFallbackInvalid) {
  EXPECT_EQ(signals_[Signal::kAssistTorque], 0.0);
  EXPECT_FALSE(signals_.valid[model::index(Signal::kAssistTorque)]);
  EXPECT_TRUE(rx_.timed_out(0));
}

TEST_F(RxTest, AcceptedFrameWritesConvertedValues) {
  EXPECT_EQ(feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", -3.5}}, 0), 1 * kMs),
            can::mapping::RxResult::kAccepted);
  EXPECT_DOUBLE_EQ(signals_[Signal::kAssistTorque], -3.5);
  EXPECT_TRUE(signals_.valid[model::index(Signal::kAssistTorque)]);
  // XOR checksum, bar -> Pa.
  EXPECT_EQ(feed(0x220,
                 frame("ESC_BrakePressure",
                       {{"BrakePressureFront", 100.0}, {"BrakePressureRear", 42.5}}, 0, false),
                 1 * kMs),
            can::mapping::RxResult::kAccepted);
  EXPECT_DOUBLE_EQ(signals_[Signal::kBrakePressureFront], 100.0e5);
  EXPECT_DOUBLE_EQ(signals_[Signal::kBrakePressureRear], 42.5e5);
  // 29-bit id, percent -> ratio.
  EXPECT_EQ(feed(0x18FF0102, frame("PCM_Pedal", {{"AccelPedal", 50.0}}, 0), 1 * kMs, true),
            can::mapping::RxResult::kAccepted);
  EXPECT_DOUBLE_EQ(signals_[Signal::kThrottlePedal], 0.5);
  EXPECT_EQ(counters_.checksum_failures + counters_.counter_failures + counters_.bad_frames, 0u);
}

TEST_F(RxTest, RejectsBadChecksumLengthUnknownId) {
  auto d = frame("EPS_Status", {{"EPS_MotorTorque", 2.0}}, 0);
  d[7] ^= 0x01;
  EXPECT_EQ(feed(0x200, d, 1 * kMs), can::mapping::RxResult::kChecksumFailure);
  EXPECT_EQ(counters_.checksum_failures, 1u);
  EXPECT_FALSE(signals_.valid[model::index(Signal::kAssistTorque)]);  // nothing written
  // XOR expected, CRC given.
  EXPECT_EQ(feed(0x220, frame("ESC_BrakePressure", {{"BrakePressureFront", 1.0}}, 0, true), 1),
            can::mapping::RxResult::kChecksumFailure);
  EXPECT_EQ(counters_.checksum_failures, 2u);
  const auto good = frame("EPS_Status", {{"EPS_MotorTorque", 2.0}}, 0);
  EXPECT_EQ(rx_.on_frame(0x200, false, can::mapping::FrameFormat::kClassic, good.data(), 7, 1,
                         signals_, counters_),
            can::mapping::RxResult::kBadLength);
  EXPECT_EQ(counters_.bad_frames, 1u);
  EXPECT_EQ(feed(0x7FF, good, 1), can::mapping::RxResult::kUnknownId);
  EXPECT_EQ(feed(0x200, good, 1, true), can::mapping::RxResult::kUnknownId);  // same number, 29-bit
  EXPECT_EQ(counters_.unknown_frames, 2u);
}

TEST_F(RxTest, AliveCounterFrozenAndJump) {
  EXPECT_EQ(feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 1.0}}, 14), 1 * kMs),
            can::mapping::RxResult::kAccepted);
  EXPECT_EQ(feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 1.5}}, 15), 2 * kMs),
            can::mapping::RxResult::kAccepted);
  EXPECT_EQ(feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 2.0}}, 0), 3 * kMs),
            can::mapping::RxResult::kAccepted);  // wraps at modulus 16
  EXPECT_DOUBLE_EQ(signals_[Signal::kAssistTorque], 2.0);
  EXPECT_EQ(feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 9.0}}, 0), 4 * kMs),
            can::mapping::RxResult::kCounterFailure);  // frozen
  EXPECT_EQ(feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 9.0}}, 0), 5 * kMs),
            can::mapping::RxResult::kCounterFailure);
  EXPECT_EQ(feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 9.0}}, 5), 6 * kMs),
            can::mapping::RxResult::kCounterFailure);  // jump by 5
  EXPECT_EQ(counters_.counter_failures, 3u);
  EXPECT_DOUBLE_EQ(signals_[Signal::kAssistTorque], 2.0);  // rejected frames change nothing
  EXPECT_EQ(feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 4.0}}, 6), 7 * kMs),
            can::mapping::RxResult::kAccepted);  // resynchronised on 5
  EXPECT_DOUBLE_EQ(signals_[Signal::kAssistTorque], 4.0);
}

TEST_F(RxTest, FrozenCounterStaysRejectedAcrossTimeouts) {
  // Before the latch, each timeout started a new sequence and let one frame of a frozen sender
  // through: with frames every 10 ms and a 30 ms timeout, 1 in 4 read valid.
  EXPECT_EQ(feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 1.0}}, 3), 0),
            can::mapping::RxResult::kAccepted);
  int accepted = 0;
  for (int k = 1; k <= 200; ++k) {
    const std::int64_t t = k * 10 * kMs;
    rx_.check_timeouts(t, signals_, counters_);
    if (feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 9.0}}, 3), t) ==
        can::mapping::RxResult::kAccepted)
      ++accepted;
  }
  EXPECT_EQ(accepted, 0);
  EXPECT_EQ(counters_.counter_failures, 200u);
  rx_.check_timeouts(2001 * kMs, signals_, counters_);
  EXPECT_FALSE(signals_.valid[model::index(Signal::kAssistTorque)]);
  EXPECT_DOUBLE_EQ(signals_[Signal::kAssistTorque], 0.0);  // the fallback, not 9 Nm
  // The counter moves again (one proper step from the frozen 3): accepted.
  EXPECT_EQ(feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 2.0}}, 4), 2010 * kMs),
            can::mapping::RxResult::kAccepted);
  EXPECT_DOUBLE_EQ(signals_[Signal::kAssistTorque], 2.0);
}

TEST_F(RxTest, RemoteAndWrongFormatFramesAreBadFrames) {
  const auto good = frame("EPS_Status", {{"EPS_MotorTorque", 3.0}}, 0);
  using can::mapping::FrameFormat;
  const std::array<std::uint8_t, 8> zeros{};
  EXPECT_EQ(
      rx_.on_frame(0x200, false, FrameFormat::kRemote, zeros.data(), 8, 1, signals_, counters_),
      can::mapping::RxResult::kRemoteFrame);
  EXPECT_EQ(rx_.on_frame(0x200, false, FrameFormat::kFd, good.data(), 8, 2, signals_, counters_),
            can::mapping::RxResult::kWrongFormat);  // FD frame on a classic message's id
  EXPECT_EQ(counters_.bad_frames, 2u);
  EXPECT_FALSE(signals_.valid[model::index(Signal::kAssistTorque)]);  // nothing decoded
  EXPECT_EQ(
      rx_.on_frame(0x7FF, false, FrameFormat::kRemote, zeros.data(), 0, 3, signals_, counters_),
      can::mapping::RxResult::kUnknownId);  // an id the mapping does not know
  EXPECT_EQ(feed(0x200, good, 4), can::mapping::RxResult::kAccepted);
  EXPECT_DOUBLE_EQ(signals_[Signal::kAssistTorque], 3.0);
}

TEST_F(RxTest, OutOfRangeReportsNameTheSignalRateLimited) {
  std::vector<can::mapping::OutOfRangeReport> reports;
  const auto take = [&](std::int64_t now) {
    rx_.take_out_of_range_reports(
        now, [&](const can::mapping::OutOfRangeReport& r) { reports.push_back(r); });
  };
  // 1 kHz of 20 Nm frames for 2.5 s: the first report at once, then one a second.
  for (int k = 0; k < 2500; ++k) {
    const std::int64_t t = k * kMs;
    feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 20.0}}, k % 16), t);
    take(t);
  }
  ASSERT_EQ(reports.size(), 3u);
  EXPECT_STREQ(reports[0].message, "EPS_Status");
  EXPECT_STREQ(reports[0].signal, "EPS_MotorTorque");
  EXPECT_DOUBLE_EQ(reports[0].received, 20.0);
  EXPECT_DOUBLE_EQ(reports[0].minimum, -15.0);
  EXPECT_DOUBLE_EQ(reports[0].maximum, 15.0);
  EXPECT_EQ(reports[0].count, 1u);
  EXPECT_EQ(reports[1].count, 1000u);  // t = 1 ms .. 1000 ms
  EXPECT_EQ(reports[2].count, 1000u);
  EXPECT_EQ(counters_.out_of_range, 2500u);  // the counter keeps every one
}

TEST_F(RxTest, OutOfRangeIsClampedAndCounted) {
  // EPS_MotorTorque range [-15, 15] Nm; raw 2000 = 20 Nm.
  EXPECT_EQ(feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 20.0}}, 0), 1 * kMs),
            can::mapping::RxResult::kAccepted);
  EXPECT_DOUBLE_EQ(signals_[Signal::kAssistTorque], 15.0);
  EXPECT_EQ(feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", -300.0}}, 1), 2 * kMs),
            can::mapping::RxResult::kAccepted);
  EXPECT_DOUBLE_EQ(signals_[Signal::kAssistTorque], -15.0);
  EXPECT_EQ(counters_.out_of_range, 2u);
}

TEST_F(RxTest, TimeoutAtThreeCycleTimesFallbackAndRecovery) {
  feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 5.0}}, 0), 100 * kMs);
  rx_.check_timeouts(129 * kMs, signals_, counters_);
  EXPECT_DOUBLE_EQ(signals_[Signal::kAssistTorque], 5.0);
  EXPECT_FALSE(rx_.timed_out(0));
  // Brake and pedal never arrived since reset(0): they time out at 30 and 60 ms.
  EXPECT_EQ(counters_.timeouts, 2u);
  rx_.check_timeouts(130 * kMs, signals_, counters_);  // 3 x 10 ms after the last frame
  EXPECT_TRUE(rx_.timed_out(0));
  EXPECT_DOUBLE_EQ(signals_[Signal::kAssistTorque], 0.0);  // fallback: no assist
  EXPECT_FALSE(signals_.valid[model::index(Signal::kAssistTorque)]);
  EXPECT_EQ(counters_.timeouts, 3u);
  rx_.check_timeouts(200 * kMs, signals_, counters_);
  EXPECT_EQ(counters_.timeouts, 3u);  // one per episode
  // Recovery: any counter value starts a new sequence after a timeout.
  EXPECT_EQ(feed(0x200, frame("EPS_Status", {{"EPS_MotorTorque", 6.0}}, 9), 201 * kMs),
            can::mapping::RxResult::kAccepted);
  EXPECT_TRUE(signals_.valid[model::index(Signal::kAssistTorque)]);
  rx_.check_timeouts(202 * kMs, signals_, counters_);
  EXPECT_DOUBLE_EQ(signals_[Signal::kAssistTorque], 6.0);
}

TEST_F(RxTest, MultiplexedPagesAndNoAllocation) {
  // Page 1 of EPS_Status: motor torque (plain signal) still decoded.
  auto d = frame("EPS_Status",
                 {{"EPS_MotorTorque", 1.25}, {"EPS_Page", 1}, {"EPS_MotorCurrent", -20}}, 0);
  test::AllocationCounter allocations;
  EXPECT_EQ(feed(0x200, d, 1 * kMs), can::mapping::RxResult::kAccepted);
  rx_.check_timeouts(2 * kMs, signals_, counters_);
  EXPECT_EQ(allocations.count(), 0u);
  EXPECT_DOUBLE_EQ(signals_[Signal::kAssistTorque], 1.25);
}

class TxTest : public ::testing::Test {
 protected:
  TxTest()
      : config_(can::mapping::load_can_config(std::string(RIG_CAN_CONFIG_DIR) +
                                              "/steering-bench.toml")),
        tx_(config_) {}
  can::mapping::CanConfig config_;
  can::mapping::TxScheduler tx_;
  model::Signals signals_;
  test::LegacyCycle legacy_;
  IoCounters counters_;
};

TEST_F(TxTest, PeriodsPhaseAlignedCountersChecksums) {
  const std::int64_t t0 = 5'000 * kMs;
  tx_.start(t0);
  std::array<can::mapping::TxFrame, 16> out;
  std::vector<std::vector<std::int64_t>> sent(tx_.message_count());
  std::vector<std::vector<can::mapping::TxFrame>> frames(tx_.message_count());
  std::size_t allocations_in_loop = 0;
  for (int k = 0; k < 100; ++k) {  // 100 loop cycles of 1 ms
    const std::int64_t now = t0 + k * kMs;
    test::AllocationCounter allocations;
    const std::size_t n = tx_.due_frames(now, legacy_.view(signals_), out, counters_);
    allocations_in_loop += allocations.count();
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t m = 0; m < tx_.message_count(); ++m) {
        if (config_.database.messages[config_.mapping.tx[m].dbc_message].id == out[i].id) {
          sent[m].push_back(now - t0);
          frames[m].push_back(out[i]);
        }
      }
    }
  }
  EXPECT_EQ(allocations_in_loop, 0u);
  for (std::size_t m = 0; m < tx_.message_count(); ++m) {
    const std::int64_t period = tx_.period_ns(m);
    ASSERT_EQ(static_cast<std::int64_t>(sent[m].size()), 100 * kMs / period) << m;
    for (std::size_t j = 0; j < sent[m].size(); ++j) {
      EXPECT_EQ(sent[m][j], static_cast<std::int64_t>(j) * period);  // on the grid from t0
    }
    const can::mapping::MessageBinding& b = config_.mapping.tx[m];
    const dbc::MessageDef& def = config_.database.messages[b.dbc_message];
    for (std::size_t j = 0; j < frames[m].size(); ++j) {
      const can::mapping::TxFrame& f = frames[m][j];
      EXPECT_EQ(f.len, def.length_bytes);
      EXPECT_EQ(f.fd, def.length_bytes > 8);
      if (b.counter) {
        EXPECT_EQ(dbc::SignalCodec(def.signals[b.counter->dbc_signal]).extract_raw(f.data.data()),
                  j % 16);
      }
      if (b.checksum) {
        EXPECT_EQ(f.data[7], can::mapping::crc8_sae_j1850(f.data.data(), 7));
      }
    }
  }
}

TEST_F(TxTest, OverrunSendsOnceAndStaysOnGrid) {
  tx_.start(0);
  std::array<can::mapping::TxFrame, 16> out;
  EXPECT_EQ(tx_.due_frames(0, legacy_.view(signals_), out, counters_), 5u);
  EXPECT_EQ(tx_.due_frames(1 * kMs, legacy_.view(signals_), out, counters_), 0u);
  // A 35 ms stall: every message once, not a burst.
  EXPECT_EQ(tx_.due_frames(35 * kMs, legacy_.view(signals_), out, counters_), 5u);
  EXPECT_EQ(tx_.due_frames(39 * kMs, legacy_.view(signals_), out, counters_), 0u);
  EXPECT_EQ(tx_.due_frames(40 * kMs, legacy_.view(signals_), out, counters_), 5u);  // 10 ms and 20 ms grids
  EXPECT_EQ(tx_.due_frames(50 * kMs, legacy_.view(signals_), out, counters_), 3u);  // 10 ms messages only
  // A too small output array leaves the rest due for the next call.
  std::array<can::mapping::TxFrame, 2> small;
  EXPECT_EQ(tx_.due_frames(60 * kMs, legacy_.view(signals_), small, counters_), 2u);
  EXPECT_EQ(tx_.due_frames(60 * kMs, legacy_.view(signals_), small, counters_), 2u);
  EXPECT_EQ(tx_.due_frames(60 * kMs, legacy_.view(signals_), small, counters_), 1u);
}

TEST_F(TxTest, ValuesConvertedAndClamped) {
  signals_[Signal::kSteeringWheelAngle] = 0.5;                        // rad
  signals_[Signal::kVehicleSpeed] = 100.0;                            // m/s = 360 km/h > 320
  signals_[Signal::kYawRate] = -0.25;                                 // rad/s
  signals_[Signal::kEngineSpeed] = 2000.0 * std::numbers::pi / 30.0;  // 2000 rpm
  signals_[Signal::kPositionX] = -1234.5678;
  can::mapping::TxFrame f;
  const auto find = [&](const char* name) {
    for (std::size_t m = 0; m < tx_.message_count(); ++m) {
      if (config_.database.messages[config_.mapping.tx[m].dbc_message].name == name) return m;
    }
    return std::size_t{0};
  };
  const auto decode = [&](std::size_t m, const char* signal) {
    const auto& def = config_.database.messages[config_.mapping.tx[m].dbc_message];
    return dbc::SignalCodec(*def.find_signal(signal)).decode(f.data.data());
  };
  tx_.encode(find("RIG_SteeringWheel"), legacy_.view(signals_), f, counters_);
  EXPECT_NEAR(decode(find("RIG_SteeringWheel"), "SWA_Angle"), 0.5 * 180.0 / std::numbers::pi, 0.05);
  tx_.encode(find("RIG_VehicleSpeed"), legacy_.view(signals_), f, counters_);
  EXPECT_DOUBLE_EQ(decode(find("RIG_VehicleSpeed"), "VehicleSpeed"), 320.0);
  EXPECT_EQ(counters_.out_of_range, 1u);
  std::vector<can::mapping::OutOfRangeReport> reports;
  tx_.take_out_of_range_reports(
      0, [&](const can::mapping::OutOfRangeReport& r) { reports.push_back(r); });
  ASSERT_EQ(reports.size(), 1u);  // the clamped signal, named
  EXPECT_STREQ(reports[0].direction, "tx");
  EXPECT_STREQ(reports[0].message, "RIG_VehicleSpeed");
  EXPECT_STREQ(reports[0].signal, "VehicleSpeed");
  EXPECT_GT(reports[0].received, 320.0);
  EXPECT_DOUBLE_EQ(reports[0].maximum, 320.0);
  EXPECT_EQ(reports[0].count, 1u);
  tx_.encode(find("RIG_VehicleDynamics"), legacy_.view(signals_), f, counters_);
  EXPECT_FLOAT_EQ(static_cast<float>(decode(find("RIG_VehicleDynamics"), "YawRate")),
                  static_cast<float>(-0.25 * 180.0 / std::numbers::pi));
  tx_.encode(find("RIG_Chassis"), legacy_.view(signals_), f, counters_);
  EXPECT_EQ(f.len, 16);
  EXPECT_TRUE(f.fd);
  EXPECT_DOUBLE_EQ(decode(find("RIG_Chassis"), "EngineSpeed"), 2000.0);
  EXPECT_DOUBLE_EQ(decode(find("RIG_Chassis"), "PositionX"), -1234.5678);
  EXPECT_DOUBLE_EQ(decode(find("RIG_Chassis"), "Gear"), 0.0);
}

/// A vehicle fault held ([rig] on_vehicle_fault = "hold") flags every model output invalid: the
/// wheel speeds (mapped with `invalid = 0xFFFF`) go out as that SNA raw value, the vehicle speed
/// (no `invalid`) as the value it holds, the model's last valid output.
TEST_F(TxTest, InvalidOutputSendsItsInvalidRawValue) {
  const auto find = [&](const char* name) {
    for (std::size_t m = 0; m < tx_.message_count(); ++m) {
      if (config_.database.messages[config_.mapping.tx[m].dbc_message].name == name) return m;
    }
    return std::size_t{0};
  };
  const std::size_t wheels = find("RIG_WheelSpeeds");
  const std::size_t speed = find("RIG_VehicleSpeed");
  const auto& wdef = config_.database.messages[config_.mapping.tx[wheels].dbc_message];
  const auto& sdef = config_.database.messages[config_.mapping.tx[speed].dbc_message];
  const dbc::SignalCodec fl(*wdef.find_signal("WheelSpeed_FL"));
  const dbc::SignalCodec rr(*wdef.find_signal("WheelSpeed_RR"));
  const dbc::SignalCodec vs(*sdef.find_signal("VehicleSpeed"));
  signals_.set(Signal::kWheelSpeedFL, 100.0);  // rad/s = 954.9 rpm
  signals_.set(Signal::kWheelSpeedRR, 100.0);
  signals_.set(Signal::kVehicleSpeed, 30.0);  // m/s = 108 km/h
  can::mapping::TxFrame f;
  tx_.encode(wheels, legacy_.view(signals_), f, counters_);
  EXPECT_NEAR(fl.decode(f.data.data()), 100.0 * 30.0 / std::numbers::pi, 0.05);
  signals_.valid[model::index(Signal::kWheelSpeedFL)] = false;
  signals_.valid[model::index(Signal::kVehicleSpeed)] = false;
  tx_.encode(wheels, legacy_.view(signals_), f, counters_);
  EXPECT_EQ(fl.extract_raw(f.data.data()), 0xFFFFu);                             // SNA
  EXPECT_NEAR(rr.decode(f.data.data()), 100.0 * 30.0 / std::numbers::pi, 0.05);  // still valid
  tx_.encode(speed, legacy_.view(signals_), f, counters_);
  EXPECT_NEAR(vs.decode(f.data.data()), 108.0, 0.01);          // no `invalid`: the held value
  EXPECT_EQ(counters_.out_of_range, 0u);                       // the SNA value is not clamped
  signals_.valid[model::index(Signal::kWheelSpeedFL)] = true;  // valid again
  tx_.encode(wheels, legacy_.view(signals_), f, counters_);
  EXPECT_NEAR(fl.decode(f.data.data()), 100.0 * 30.0 / std::numbers::pi, 0.05);
}

}  // namespace
}  // namespace rig::io::can

namespace rig::io::can {
namespace {

/// The catalogue binding of `name` (the two-axle vehicle's).
signals::Binding binding(const char* name) {
  return signals::Catalogue::two_axle_vehicle().find(name)->binding;
}

/// A multiplexed message sent by the rig: pages go out round-robin, each frame carries only its
/// page's signals; received, only the present page's signal is written.
TEST(TxMultiplexed, PagesRoundRobinAndRxPerPage) {
  can::mapping::CanConfig c;
  c.database = dbc::parse_dbc(R"(BO_ 16 Mux: 4 RIG
 SG_ Page M : 0|2@1+ (1,0) [0|3] "" ECU
 SG_ Speed m0 : 8|16@1+ (0.01,0) [0|600] "km/h" ECU
 SG_ Yaw m2 : 8|16@1- (0.1,0) [-300|300] "deg/s" ECU
BA_DEF_ BO_ "GenMsgCycleTime" INT 0 1000;
BA_ "GenMsgCycleTime" BO_ 16 10;
)",
                              "mux.dbc");
  can::mapping::MessageBinding b;
  b.dbc_message = 0;
  b.period_ns = 10'000'000;
  b.timeout_ns = 30'000'000;
  b.signals.push_back(can::mapping::SignalBinding{
      .dbc_signal = 1, .model = binding("vehicle_speed_mps"), .scale = 1 / 3.6});
  b.signals.push_back(can::mapping::SignalBinding{
      .dbc_signal = 2, .model = binding("yaw_rate_radps"), .scale = std::numbers::pi / 180});
  c.mapping.tx.push_back(b);
  can::mapping::TxScheduler tx(c);
  model::Signals out;
  test::LegacyCycle legacy;
  out[Signal::kVehicleSpeed] = 10.0;  // 36 km/h
  out[Signal::kYawRate] = -0.1;       // -5.73 deg/s
  IoCounters counters;
  can::mapping::TxFrame f0, f1, f2;
  tx.encode(0, legacy.view(out), f0, counters);
  tx.encode(0, legacy.view(out), f1, counters);
  tx.encode(0, legacy.view(out), f2, counters);
  EXPECT_EQ(f0.data[0] & 3, 0);
  EXPECT_EQ(f0.data[1] | (f0.data[2] << 8), 3600);  // 36 km/h / 0.01
  EXPECT_EQ(f1.data[0] & 3, 2);
  EXPECT_EQ(static_cast<std::int16_t>(f1.data[1] | (f1.data[2] << 8)), -57);  // -5.73 / 0.1
  EXPECT_EQ(f2.data[0] & 3, 0);

  // The same mapping as RX (model outputs allowed here: built by hand, not from TOML).
  can::mapping::CanConfig rc = c;
  rc.mapping.rx = rc.mapping.tx;
  rc.mapping.tx.clear();
  can::mapping::RxProcessor rx(rc);
  model::Signals in;
  rx.reset(0, in);
  EXPECT_EQ(rx.on_frame(16, false, can::mapping::FrameFormat::kClassic, f1.data.data(), 4, 1, in,
                        counters),
            can::mapping::RxResult::kAccepted);
  EXPECT_NEAR(in[Signal::kYawRate], -5.7 * std::numbers::pi / 180, 1e-12);
  EXPECT_FALSE(in.valid[model::index(Signal::kVehicleSpeed)]);  // page 0 not seen yet
  EXPECT_EQ(rx.on_frame(16, false, can::mapping::FrameFormat::kClassic, f0.data.data(), 4, 2, in,
                        counters),
            can::mapping::RxResult::kAccepted);
  EXPECT_NEAR(in[Signal::kVehicleSpeed], 10.0, 1e-12);
}

}  // namespace
}  // namespace rig::io::can
