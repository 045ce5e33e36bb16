#include "io/can/mapping/can_mapping.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

namespace rig::io::can {
namespace {

using ::testing::HasSubstr;

const std::string kConfigDir = RIG_CAN_CONFIG_DIR;

TEST(CanMapping, ExampleMappingLoads) {
  const can::mapping::CanConfig c =
      can::mapping::load_can_config(kConfigDir + "/steering-bench.toml");
  ASSERT_EQ(c.mapping.rx.size(), 3u);
  ASSERT_EQ(c.mapping.tx.size(), 5u);
  const can::mapping::MessageBinding& eps = c.mapping.rx[0];
  EXPECT_EQ(c.database.messages[eps.dbc_message].name, "EPS_Status");
  EXPECT_EQ(eps.timeout_ns, 30'000'000);  // 3 x GenMsgCycleTime 10 ms
  ASSERT_TRUE(eps.counter.has_value());
  EXPECT_EQ(eps.counter->modulus, 16u);
  ASSERT_TRUE(eps.checksum.has_value());
  EXPECT_EQ(eps.checksum->type, can::mapping::ChecksumType::kCrc8SaeJ1850);
  EXPECT_EQ(eps.checksum->bytes, (std::vector<std::uint8_t>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(eps.signals[0].model->slot, model::index(model::Signal::kAssistTorque));
  const can::mapping::MessageBinding& esc = c.mapping.rx[1];
  EXPECT_EQ(esc.checksum->type, can::mapping::ChecksumType::kXor);
  EXPECT_EQ(esc.signals[0].scale, 1e5);               // bar -> Pa
  EXPECT_EQ(c.mapping.rx[2].timeout_ns, 60'000'000);  // explicit timeout_ms
  const can::mapping::MessageBinding& swa = c.mapping.tx[0];
  EXPECT_EQ(swa.period_ns, 10'000'000);
  EXPECT_DOUBLE_EQ(swa.signals[0].scale, std::numbers::pi / 180.0);
  EXPECT_DOUBLE_EQ(c.mapping.tx[1].signals[0].scale, 1.0 / 3.6);
  EXPECT_FALSE(c.mapping.tx[1].signals[0].invalid_raw.has_value());
  EXPECT_EQ(c.mapping.tx[2].signals[0].invalid_raw, 0xFFFFu);  // wheel speeds: SNA
}

// The steer-by-wire bench (issue 15): the ECU's feedback torque and rack commands come in,
// each its own message (the one the ECU does not send times out: invalid, no actuator force).
TEST(CanMapping, SteerByWireMappingLoads) {
  const can::mapping::CanConfig c =
      can::mapping::load_can_config(kConfigDir + "/steer-by-wire-bench.toml");
  ASSERT_EQ(c.mapping.rx.size(), 3u);
  ASSERT_EQ(c.mapping.tx.size(), 3u);
  EXPECT_EQ(c.mapping.rx[0].signals[0].model->slot,
            model::index(model::Signal::kSteeringWheelFeedbackTorqueCmd));
  EXPECT_EQ(c.mapping.rx[1].signals[0].model->slot, model::index(model::Signal::kRackForceCmd));
  EXPECT_EQ(c.mapping.rx[2].signals[0].model->slot, model::index(model::Signal::kRackPositionCmd));
  for (const auto& rx : c.mapping.rx) EXPECT_EQ(rx.timeout_ns, 30'000'000);  // 3 x 10 ms
}

class CanMappingErrors : public ::testing::Test {
 protected:
  /// Writes `body` after a `dbc = ...` line and returns the config::ConfigError text of loading it.
  static std::string error_of(const std::string& body) {
    // one file per test: ctest runs the tests of this file in parallel processes
    const std::string file = ::testing::TempDir() + "/rig_can_mapping_test_" +
                             ::testing::UnitTest::GetInstance()->current_test_info()->name() +
                             ".toml";
    {
      std::ofstream out(file);
      out << "dbc = \"" << kConfigDir << "/steering-bench.dbc\"\n" << body;
    }
    try {
      (void)can::mapping::load_can_config(file);
    } catch (const config::ConfigError& e) {
      return e.what();
    }
    return "";
  }
};

TEST_F(CanMappingErrors, UnknownNamesAndBadValuesNameTheLine) {
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"Nope\"\n"),
              HasSubstr(":3: [can mapping].rx[0] message: no message 'Nope'"));
  EXPECT_THAT(
      error_of("[[rx]]\nmessage = \"EPS_Status\"\n[[rx.signal]]\ndbc = \"X\"\n"
               "model = \"assist_torque_nm\"\n"),
      HasSubstr(":5: [can mapping].rx[0].signal[0] dbc: no signal 'X' in message EPS_Status"));
  EXPECT_THAT(
      error_of("[[rx]]\nmessage = \"EPS_Status\"\n[[rx.signal]]\ndbc = \"EPS_MotorTorque\"\n"
               "model = \"assist_torque\"\n"),
      HasSubstr(":6: [can mapping].rx[0].signal[0] model: no model signal 'assist_torque'"));
  EXPECT_THAT(
      error_of("[[rx]]\nmessage = \"EPS_Status\"\n[[rx.signal]]\ndbc = \"EPS_MotorTorque\"\n"
               "model = \"vehicle_speed_mps\"\n"),
      HasSubstr("is a model output"));
  EXPECT_THAT(
      error_of("[[rx]]\nmessage = \"EPS_Status\"\n[[rx.signal]]\ndbc = \"EPS_MotorTorque\"\n"
               "model = \"assist_torque_nm\"\nconvert = \"furlongs\"\n"),
      HasSubstr(":7: [can mapping].rx[0].signal[0] convert"));
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\n"
                       "checksum = { signal = \"EPS_MotorTorque\" }\n"),
              HasSubstr("must be a plain 8-bit integer"));
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\n"
                       "checksum = { signal = \"EPS_Checksum\", bytes = [0, 9] }\n"),
              HasSubstr("outside message EPS_Status"));
  // More covered bytes than the message has (they are gathered into a 64-byte stack buffer):
  // refused before any is read, as is a byte listed twice.
  std::string bytes_65 = "[0";
  for (int i = 1; i < 65; ++i) bytes_65 += ", 0";
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\n"
                       "checksum = { signal = \"EPS_Checksum\", bytes = " +
                       bytes_65 + "] }\n"),
              HasSubstr(":4: [checksum] bytes: 65 entries, at most 8"));
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\n"
                       "checksum = { signal = \"EPS_Checksum\", bytes = [2, 0, 2] }\n"),
              HasSubstr(":4: [checksum] bytes: byte 2 is listed twice"));
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\n"
                       "counter = { signal = \"EPS_Counter\", modulus = 17 }\n"),
              HasSubstr("modulus"));
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\nspeling = 1\n"), HasSubstr("speling"));
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\n[[rx]]\nmessage = \"EPS_Status\"\n"),
              HasSubstr("mapped twice"));
  EXPECT_EQ(error_of("[[rx]]\nmessage = \"EPS_Status\"\n"), "");
}

TEST_F(CanMappingErrors, TxInvalidRawMustFitTheSignal) {
  const std::string head =
      "[[tx]]\nmessage = \"RIG_VehicleSpeed\"\n[[tx.signal]]\ndbc = \"VehicleSpeed\"\n"
      "model = \"vehicle_speed_mps\"\n";
  EXPECT_EQ(error_of(head + "invalid = 0xFFFF\n"), "");
  EXPECT_THAT(error_of(head + "invalid = 65536\n"),
              HasSubstr(":7: [can mapping].tx[0].signal[0] invalid: raw value 65536 does not fit "
                        "the 16 bits of VehicleSpeed"));
  EXPECT_THAT(error_of(head + "invalid = -1\n"), HasSubstr(":7:"));
  EXPECT_THAT(error_of(head + "invalid = 1.5\n"), HasSubstr("expected an integer"));
  // RX has no `invalid` (its timeout has `fallback`)
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\n[[rx.signal]]\n"
                       "dbc = \"EPS_MotorTorque\"\nmodel = \"assist_torque_nm\"\ninvalid = 1\n"),
              HasSubstr("invalid"));
}

// Settings that contradict each other are errors with the line (issue 13), not a silent winner.
TEST_F(CanMappingErrors, ContradictorySettingsNameTheLine) {
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\n"
                       "counter = { signal = \"EPS_Checksum\", modulus = 16 }\n"
                       "checksum = { signal = \"EPS_Checksum\" }\n"),
              HasSubstr(":5: [can mapping].rx[0] checksum: counter EPS_Checksum and checksum "
                        "EPS_Checksum share bits of message EPS_Status"));
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\n"
                       "checksum = { signal = \"EPS_Checksum\", bytes = [0, 1, 0] }\n"),
              HasSubstr("byte 0 is listed twice"));
  // 65 entries (a list the stack buffer of issue 13 overflowed): refused by its length
  std::string many = "0";
  for (int i = 1; i < 65; ++i) many += ", " + std::to_string(i % 7);
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\n"
                       "checksum = { signal = \"EPS_Checksum\", bytes = [" +
                       many + "] }\n"),
              HasSubstr(":4: [checksum] bytes: 65 entries, at most 8"));
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\n"
                       "checksum = { signal = \"EPS_Checksum\", bytes = [0, 1.0] }\n"),
              HasSubstr("expected an array of integers"));
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\n"
                       "counter = { signal = \"EPS_Counter\", modulus = 15.5 }\n"),
              HasSubstr(":4: [counter] modulus: expected an integer, not 15.5"));
  EXPECT_THAT(
      error_of("[[rx]]\nmessage = \"EPS_Status\"\n[[rx.signal]]\n"
               "dbc = \"EPS_MotorTorque\"\nmodel = \"assist_torque_nm\"\n"
               "convert = \"deg_to_rad\"\nscale = 2.0\n"),
      HasSubstr(":8: [can mapping].rx[0].signal[0] scale: give convert or scale, not both"));
  EXPECT_THAT(error_of("[[tx]]\nmessage = \"RIG_VehicleSpeed\"\n[[tx.signal]]\n"
                       "dbc = \"VehicleSpeed\"\nmodel = \"vehicle_speed_mps\"\nconstant = 1.0\n"),
              HasSubstr(":7: [can mapping].tx[0].signal[0] constant: give model or constant"));
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"EPS_Status\"\n[[tx]]\nmessage = \"EPS_Status\"\n"),
              HasSubstr("message EPS_Status is both received ([[rx]]) and sent ([[tx]])"));
}

}  // namespace
}  // namespace rig::io::can
