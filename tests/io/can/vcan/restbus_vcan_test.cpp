// The restbus on vcan: the worked example's mapping (tests/io/can/restbus/ecu-mapping.toml)
// stands in for the gateway GW of ecu.dbc. Every frame the bridge sends is logged with the loop
// cycle that produced it (its per-cycle send count against candump's ordered recording), and an
// independent python checker (canmatrix, crcmod, the E2E reference e2e_reference.py) judges
// periods in cycles, start values, counters, checksums and the E2E P01 message. The VM is slow:
// nothing here depends on wall time.
#include <gtest/gtest.h>

#include <time.h>

#include <algorithm>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "io/can/bridge/can_bridge.h"
#include "tests/io/can/vcan/vcan_support.h"
#include "tests/support/alloc_counter.h"
#include "tests/support/legacy_cycle.h"

namespace rig::io::can {
namespace {

using test::Child;
using test::sh;
using test::sleep_ms;

constexpr std::int64_t kCycleNs = 1'000'000;
constexpr int kCycles = 3000;  // three sends of the 1000 ms message

std::string restbus_dir() { return test::source_dir() + "/tests/io/can/restbus"; }

/// The frame part (`ID#DATA`) of a `candump -L` line, "" for the sync marker.
std::string frame_of(const std::string& line) {
  const auto at = line.rfind(' ');
  const std::string frame = at == std::string::npos ? line : line.substr(at + 1);
  return frame.rfind("7FF#", 0) == 0 ? "" : frame;
}

bool sync_candump(Child& candump, const char* ifname) {
  can::transport::TransportSettings t;
  t.interface = ifname;
  can::transport::SocketCanTransport tx(t);
  can::transport::TransportFrame marker;
  marker.id = 0x7FF;
  for (int i = 0; i < 400; ++i) {
    tx.send(marker);
    if (candump.wait_for_line(
            [](const std::string& l) { return l.find("7FF#") != std::string::npos; }, 50)) {
      return true;
    }
  }
  return false;
}

TEST(RestbusVcan, GatewayMessagesAtTheirCyclesWithStartValuesCountersChecksums) {
  RIG_REQUIRE_VCAN();
  can::transport::TransportSettings t;
  t.interface = "vcan0";
  InputSet fed;
  fed.set(model::index(model::Signal::kAssistTorque));
  auto bridge = std::make_unique<can::bridge::CanBridge>(
      can::mapping::load_can_config(restbus_dir() + "/ecu-mapping.toml"), t, false, fed);
  Child candump("candump -L vcan0");
  ASSERT_TRUE(sync_candump(candump, "vcan0"));
  model::Signals in{};
  model::Signals out{};
  out[model::Signal::kVehicleSpeed] = 12.5;           // GW_RefSpeed is `set` to it
  std::vector<std::uint64_t> sent_after(kCycles, 0);  // frames_sent after each cycle
  const std::int64_t t0 = test::monotonic_ns();
  std::uint64_t allocations = 0;
  test::LegacyCycle legacy;
  const io::signals::CycleView view = legacy.view(out);
  {
    test::AllocationCounter count;
    for (int k = 0; k < kCycles; ++k) {
      const std::int64_t now = t0 + k * kCycleNs;
      timespec ts{now / 1'000'000'000, now % 1'000'000'000};
      clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr);
      bridge->receive(now, in);
      bridge->transmit(now, view);
      IoCounters c;
      bridge->read_counters(c);
      sent_after[static_cast<std::size_t>(k)] = c.frames_sent;
    }
    allocations = count.count();
  }
  EXPECT_EQ(allocations, 0u);
  IoCounters c;
  bridge->read_counters(c);
  EXPECT_EQ(c.send_no_buffer, 0u);  // so every frame went out in the cycle that encoded it
  EXPECT_EQ(c.send_dropped, 0u);
  std::vector<std::string> frames;
  for (int i = 0; i < 300 && frames.size() < c.frames_sent; ++i) {
    candump.poll();
    frames.clear();
    for (const auto& l : candump.lines()) {
      if (const std::string f = frame_of(l); !f.empty()) frames.push_back(f);
    }
    sleep_ms(20);
  }
  candump.terminate();
  ASSERT_EQ(frames.size(), c.frames_sent);
  // 3 s: the two 10 ms [[tx]] (300 each) + GW at 10, 20, 50, 100, 1000 ms and E2E at 20 ms.
  EXPECT_EQ(c.frames_sent, 2u * 300u + 300u + 150u + 60u + 30u + 3u + 150u);
  const std::string log = std::string(RIG_BINARY_DIR) + "/vcan-out/restbus-sent.log";
  sh("mkdir -p " + std::string(RIG_BINARY_DIR) + "/vcan-out");
  {
    std::ofstream f(log);
    std::size_t cycle = 0;
    for (std::size_t i = 0; i < frames.size(); ++i) {
      while (sent_after[cycle] <= i) ++cycle;  // frame i came out in the first cycle past it
      f << cycle << ' ' << frames[i] << '\n';
    }
  }
  EXPECT_EQ(
      sh("/usr/bin/python3 " + restbus_dir() + "/restbus_check.py --mapping " + restbus_dir() +
         "/ecu-mapping.toml --node GW --log " + log + " --cycles 3000 --value GW_RefSpeed=12.5"),
      0)
      << "the independent checker refused " << log;
}

}  // namespace
}  // namespace rig::io::can
