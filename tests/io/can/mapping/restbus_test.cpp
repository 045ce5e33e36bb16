// [[restbus]]: the expansion of a DBC node into TX bindings (messages, periods, start values,
// `set`, overrides, the warning, every error), on the test DBC tests/io/can/restbus/ecu.dbc.
// Expected bytes are worked out by hand from the DBC's GenSigStartValue (raw) and bit layout.
#include "io/can/mapping/restbus.h"
#include "tests/support/legacy_cycle.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "io/can/mapping/checksum.h"
#include "io/can/mapping/tx_scheduler.h"

namespace rig::io::can::mapping {
namespace {

using ::testing::HasSubstr;

const std::string kDir = RIG_RESTBUS_DIR;

const MessageBinding* find(const CanConfig& c, const std::string& name) {
  for (const auto& b : c.mapping.tx) {
    if (c.database.messages[b.dbc_message].name == name) return &b;
  }
  return nullptr;
}

std::size_t tx_index(const CanConfig& c, const std::string& name) {
  for (std::size_t i = 0; i < c.mapping.tx.size(); ++i) {
    if (c.database.messages[c.mapping.tx[i].dbc_message].name == name) return i;
  }
  return c.mapping.tx.size();
}

/// Writes a mapping (`dbc = ecu.dbc` + body), one file per test, and loads it.
std::string write_mapping(const std::string& body) {
  std::string file = ::testing::TempDir() + "/rig_restbus_test_" +
                     ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".toml";
  std::ofstream out(file);
  out << "dbc = \"" << kDir << "/ecu.dbc\"\n" << body;
  return file;
}

std::string error_of(const std::string& body) {
  try {
    (void)load_can_config(write_mapping(body));
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(Restbus, ExampleSendsEveryCyclicGatewayMessageAtItsCycleTime) {
  const CanConfig c = load_can_config(kDir + "/ecu-mapping.toml");
  ASSERT_EQ(c.mapping.tx.size(), 2u + 6u);  // ESC_Vehicle, SAS_Steering + six GW messages
  const std::array<std::pair<const char*, std::int64_t>, 6> expected{{{"GW_Ignition", 10},
                                                                      {"GW_VehicleMode", 20},
                                                                      {"GW_Engine", 50},
                                                                      {"GW_Body", 100},
                                                                      {"GW_Time", 1000},
                                                                      {"GW_Chassis", 20}}};
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const MessageBinding& b = c.mapping.tx[2 + k];  // after the [[tx]], in DBC order
    EXPECT_EQ(c.database.messages[b.dbc_message].name, expected[k].first);
    EXPECT_EQ(b.period_ns, expected[k].second * 1'000'000);
  }
  EXPECT_EQ(find(c, "GW_Diag"), nullptr);  // no GenMsgCycleTime
  ASSERT_EQ(c.mapping.warnings.size(), 1u);
  EXPECT_THAT(c.mapping.warnings[0],
              HasSubstr("ecu-mapping.toml:44: restbus node GW: 1 message(s) without "
                        "GenMsgCycleTime not sent: GW_Diag"));
  // Overrides: the protection as for a [[tx]].
  const MessageBinding* ign = find(c, "GW_Ignition");
  ASSERT_TRUE(ign->counter && ign->checksum);
  EXPECT_EQ(ign->counter->modulus, 16u);
  EXPECT_EQ(ign->checksum->type, ChecksumType::kCrc8SaeJ1850);
  EXPECT_EQ(ign->checksum->bytes, (std::vector<std::uint8_t>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(find(c, "GW_VehicleMode")->checksum->type, ChecksumType::kXor);
  EXPECT_TRUE(find(c, "GW_Engine")->counter.has_value());
  EXPECT_FALSE(find(c, "GW_Engine")->checksum.has_value());
  EXPECT_FALSE(find(c, "GW_Body")->counter.has_value());
  const MessageBinding* chassis = find(c, "GW_Chassis");  // e2e: read as for a [[tx]]
  ASSERT_TRUE(chassis->e2e.has_value());
  EXPECT_EQ(chassis->e2e->profile, e2e::Profile::kP01);
  EXPECT_EQ(chassis->e2e->data_id, 0x0123u);
  EXPECT_FALSE(chassis->counter.has_value());
  // set: a constant and a model signal (convert "none": scale 1, offset 0).
  const MessageBinding* mode = find(c, "GW_VehicleMode");
  ASSERT_EQ(mode->signals.size(), 2u);
  EXPECT_FALSE(mode->signals[0].model.has_value());
  EXPECT_EQ(mode->signals[0].constant, 4.0);
  ASSERT_TRUE(mode->signals[1].model.has_value());  // vehicle_speed_mps: the enum output's slot
  EXPECT_EQ(mode->signals[1].model->slot, model::index(model::Signal::kVehicleSpeed));
  EXPECT_EQ(mode->signals[1].scale, 1.0);
  EXPECT_EQ(mode->signals[1].offset, 0.0);
  EXPECT_TRUE(find(c, "GW_Time")->signals.empty());
}

TEST(Restbus, FramesCarryTheStartValuesRawTheSetValuesCountersAndChecksums) {
  const CanConfig c = load_can_config(kDir + "/ecu-mapping.toml");
  TxScheduler tx(c);
  model::Signals signals{};
  signals[model::Signal::kVehicleSpeed] = 12.5;
  test::LegacyCycle legacy;  // m/s -> GW_RefSpeed raw 1250
  IoCounters counters;
  TxFrame f;
  tx.encode(tx_index(c, "GW_Ignition"), legacy.view(signals), f, counters);
  EXPECT_EQ(f.id, 256u);
  EXPECT_EQ(f.data[0], 0x12);  // GW_IgnitionState 2 | GW_Terminal15 1 << 4
  EXPECT_EQ(f.data[1], 0x00);  // counter, first frame
  EXPECT_EQ(f.data[7], crc8_sae_j1850(f.data.data(), 7));
  tx.encode(tx_index(c, "GW_Ignition"), legacy.view(signals), f, counters);
  EXPECT_EQ(f.data[1], 0x01);  // counter advances
  EXPECT_EQ(f.data[7], crc8_sae_j1850(f.data.data(), 7));
  tx.encode(tx_index(c, "GW_VehicleMode"), legacy.view(signals), f, counters);
  EXPECT_EQ(f.data[0], 4);                      // set GW_Mode = 4 (start value 3)
  EXPECT_EQ(f.data[1] | f.data[2] << 8, 1250);  // set GW_RefSpeed = vehicle_speed_mps
  EXPECT_EQ(f.data[7], xor8(f.data.data(), 7));
  tx.encode(tx_index(c, "GW_Engine"), legacy.view(signals), f, counters);
  EXPECT_EQ(f.data[0] | f.data[1] << 8, 3200);  // GW_EngineSpeed raw 3200 = 800 rpm
  EXPECT_EQ(f.data[2], 130);                    // GW_EngineTemp raw 130 = 90 degC
  EXPECT_EQ(f.data[3], 1);                      // GW_EngineRunning
  tx.encode(tx_index(c, "GW_Body"), legacy.view(signals), f, counters);
  EXPECT_EQ(f.data[0], 1);
  EXPECT_EQ(f.data[1], 100);                                        // 10 degC
  EXPECT_EQ(f.data[2] | f.data[3] << 8 | f.data[4] << 16, 123456);  // 12345.6 km
  tx.encode(tx_index(c, "GW_Time"), legacy.view(signals), f, counters);
  EXPECT_EQ(f.id, 992u);
  EXPECT_EQ(f.data[0], 12);
  EXPECT_EQ(f.data[1], 34);
  EXPECT_EQ(f.data[2], 56);
  EXPECT_EQ(f.data[3] | f.data[4] << 8, 2026);
  tx.encode(tx_index(c, "GW_Chassis"), legacy.view(signals), f, counters);
  EXPECT_EQ(f.data[2], 5);         // GW_ChassisStatus
  EXPECT_EQ(f.data[3], 1);         // GW_ParkBrake
  EXPECT_EQ(f.data[1] & 0x0F, 0);  // E2E P01 counter, first frame (its CRC: the python check)
  EXPECT_EQ(counters.out_of_range, 0u);
}

TEST(Restbus, SchedulerSendsEachMessageAtItsPeriod) {
  const CanConfig c = load_can_config(kDir + "/ecu-mapping.toml");
  TxScheduler tx(c);
  tx.start(0);
  model::Signals signals{};
  IoCounters counters;
  std::array<TxFrame, 16> out{};
  std::array<int, 1024> sends{};  // per CAN id
  test::LegacyCycle legacy;
  const io::signals::CycleView view = legacy.view(signals);
  for (std::int64_t k = 0; k < 2000; ++k) {  // 2 s of 1 ms cycles
    const std::size_t n = tx.due_frames(k * 1'000'000, view, out, counters);
    for (std::size_t i = 0; i < n; ++i) ++sends[out[i].id];
  }
  EXPECT_EQ(sends[256], 200);  // 10 ms
  EXPECT_EQ(sends[384], 100);  // 20 ms
  EXPECT_EQ(sends[512], 40);   // 50 ms
  EXPECT_EQ(sends[640], 20);   // 100 ms
  EXPECT_EQ(sends[992], 2);    // 1000 ms
  EXPECT_EQ(sends[704], 100);  // 20 ms, E2E P01
  EXPECT_EQ(sends[416], 200);  // [[tx]] ESC_Vehicle, the same scheduler
}

// The scheduler's frames, each logged with its cycle, judged by the python checker of the vcan
// suite (canmatrix, crcmod): the checker itself is tested here without a CAN socket.
TEST(Restbus, IndependentCheckerAcceptsTheScheduledFrames) {
  const CanConfig c = load_can_config(kDir + "/ecu-mapping.toml");
  TxScheduler tx(c);
  tx.start(0);
  model::Signals signals{};
  signals[model::Signal::kVehicleSpeed] = 12.5;
  test::LegacyCycle legacy;
  const io::signals::CycleView view = legacy.view(signals);
  IoCounters counters;
  std::array<TxFrame, 16> out{};
  const std::string log = ::testing::TempDir() + "/rig_restbus_test_sent.log";
  {
    std::ofstream f(log);
    for (std::int64_t k = 0; k < 3000; ++k) {
      const std::size_t n = tx.due_frames(k * 1'000'000, view, out, counters);
      for (std::size_t i = 0; i < n; ++i) {
        char line[160];
        int at = std::snprintf(line, sizeof line, "%lld %03X#", static_cast<long long>(k),
                               static_cast<unsigned>(out[i].id));
        for (std::size_t b = 0; b < out[i].len; ++b)
          at += std::snprintf(line + at, sizeof line - static_cast<std::size_t>(at), "%02X",
                              static_cast<unsigned>(out[i].data[b]));
        f << line << '\n';
      }
    }
  }
  const std::string cmd = "/usr/bin/python3 " + kDir + "/restbus_check.py --mapping " + kDir +
                          "/ecu-mapping.toml --node GW --log " + log +
                          " --cycles 3000 --value GW_RefSpeed=12.5 >/dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  // A broken frame is refused: the checker is not a yes-man.
  {
    std::ofstream f(log, std::ios::app);
    f << "3000 280#0000000000000000\n";  // GW_Body off its grid, start values lost
  }
  EXPECT_NE(std::system(cmd.c_str()), 0);
}

TEST(Restbus, NodeAloneSendsStartValuesAndTxWins) {
  const CanConfig c = load_can_config(
      write_mapping("[[tx]]\nmessage = \"GW_Body\"\n[[tx.signal]]\ndbc = \"GW_Odometer\"\n"
                    "constant = 7.5\n[[restbus]]\nnode = \"GW\"\n"));
  ASSERT_EQ(c.mapping.tx.size(), 6u);  // GW_Body once: from the [[tx]]
  EXPECT_EQ(c.database.messages[c.mapping.tx[0].dbc_message].name, "GW_Body");
  EXPECT_EQ(c.mapping.tx[0].signals.size(), 1u);
  for (std::size_t i = 1; i < c.mapping.tx.size(); ++i) {
    EXPECT_NE(c.database.messages[c.mapping.tx[i].dbc_message].name, "GW_Body");
    EXPECT_TRUE(c.mapping.tx[i].signals.empty());
    EXPECT_FALSE(c.mapping.tx[i].counter.has_value());
  }
  EXPECT_EQ(c.mapping.warnings.size(), 1u);
}

TEST(Restbus, ErrorsNameTheLineAndWhatIsWrong) {
  EXPECT_THAT(error_of("[[restbus]]\nnode = \"GATEWAY\"\n"),
              HasSubstr(":3: [can mapping].restbus[0] node: no node 'GATEWAY' in " + kDir +
                        "/ecu.dbc (its nodes: ECU, ESC, SAS, GW)"));
  EXPECT_THAT(error_of("[[restbus]]\nnode = \"GW\"\nset = { GW_Nope = 1 }\n"),
              HasSubstr(":4: [set] GW_Nope: no signal 'GW_Nope' in the messages the restbus of "
                        "node GW sends"));
  // A signal of a message the restbus does not send (GW_Diag has no cycle time).
  EXPECT_THAT(error_of("[[restbus]]\nnode = \"GW\"\nset = { GW_DiagRequest = 1 }\n"),
              HasSubstr("no signal 'GW_DiagRequest'"));
  EXPECT_THAT(error_of("[[restbus]]\nnode = \"GW\"\nset = { GW_Mode = \"mode_of_vehicle\" }\n"),
              HasSubstr(":4: [set] GW_Mode: no model signal 'mode_of_vehicle'"));
  EXPECT_THAT(error_of("[[restbus]]\nnode = \"GW\"\nset = { GW_Mode = true }\n"),
              HasSubstr(":4: [set] GW_Mode: expected a number or a model signal name"));
  EXPECT_THAT(error_of("[[rx]]\nmessage = \"GW_Engine\"\n[[rx.signal]]\ndbc = \"GW_EngineSpeed\"\n"
                       "model = \"throttle_pedal\"\n[[restbus]]\nnode = \"GW\"\n"),
              HasSubstr(":8: [can mapping].restbus[0] node: message GW_Engine of node GW is "
                        "received ([[rx]]): the restbus cannot also send it"));
  EXPECT_THAT(error_of("[[restbus]]\nnode = \"GW\"\n[[restbus]]\nnode = \"GW\"\n"),
              HasSubstr(":5: [can mapping].restbus[1] node: node GW has a [[restbus]] already"));
  EXPECT_THAT(error_of("[[restbus]]\nnode = \"GW\"\n[[restbus.message]]\nname = \"GW_Diag\"\n"),
              HasSubstr(":5: [can mapping].restbus[0].message[0] name: 'GW_Diag' is not a "
                        "message the restbus of node GW sends"));
  EXPECT_THAT(error_of("[[restbus]]\nnode = \"GW\"\n[[restbus.message]]\nname = \"GW_Engine\"\n"
                       "[[restbus.message]]\nname = \"GW_Engine\"\n"),
              HasSubstr("message GW_Engine is given twice"));
  EXPECT_THAT(
      error_of("[[restbus]]\nnode = \"GW\"\nset = { GW_IgnCounter = 3 }\n"
               "[[restbus.message]]\nname = \"GW_Ignition\"\n"
               "counter = { signal = \"GW_IgnCounter\", modulus = 16 }\n"),
      HasSubstr(
          "[set] GW_IgnCounter: signal GW_IgnCounter is the counter, checksum or E2E field of "
          "GW_Ignition, it cannot be set"));
  EXPECT_THAT(error_of("[[restbus]]\nnode = \"GW\"\n[[restbus.message]]\nname = \"GW_Ignition\"\n"
                       "counter = { signal = \"GW_IgnCounter\", modulus = 17 }\n"),
              HasSubstr("modulus"));
  EXPECT_THAT(error_of("[[restbus]]\nnode = \"GW\"\nspeling = 1\n"),
              HasSubstr("unknown key 'speling'"));
  EXPECT_THAT(error_of("[[restbus]]\nset = { GW_Mode = 1 }\n"),
              HasSubstr("node: missing required key"));
}

}  // namespace
}  // namespace rig::io::can::mapping
