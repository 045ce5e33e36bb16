// The acceptance closed loop: the vehicle model (angle mode, 60 km/h, steering-wheel angle step)
// exchanges signals over vcan with scripts/virtual-ecu through the CAN bridge. With the ECU's
// assist the torsion bar torque falls by the ECU's boost ratio k(v) compared with the same
// maneuver against an ECU that sends zero assist. Both runs share one loop (two buses).
#include <gtest/gtest.h>

#include <time.h>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "io/can/bridge/can_bridge.h"
#include "io/config/vehicle_file.h"
#include "model/vehicle/vehicle_model.h"
#include "tests/io/can/vcan/vcan_support.h"

namespace rig::io::can {
namespace {

using model::Signal;
using test::Child;

model::Signals driver_inputs() {
  model::Signals s{};
  for (std::size_t i = 0; i < model::index(model::kFirstOutput); ++i) {
    s.valid[i] = true;
    s.source[i] = model::SignalSource::kDriver;
  }
  s[Signal::kGearRequest] = 99;
  s[Signal::kIgnition] = 2;  // on (valid, so 0 would be off)
  s.source[model::index(Signal::kAssistTorque)] = model::SignalSource::kCan;
  return s;
}

TEST(ClosedLoopVcan, AssistFromVirtualEcuLowersTorsionBarTorqueByTheBoostRatio) {
  RIG_REQUIRE_VCAN();
  const std::string src = test::source_dir();
  const std::string dbc = src + "/config/can/steering-bench.dbc";
  auto ecu_cmd = [&](const char* ifname, const char* extra) {
    return "/usr/bin/python3 " + src + "/scripts/virtual-ecu --dbc " + dbc + " --interface " +
           ifname + " " + extra + " 2>/dev/null";
  };
  Child ecu_assist(ecu_cmd("vcan0", ""));
  Child ecu_zero(ecu_cmd("vcan1", "--no-assist"));
  auto ready = [](const std::string& l) { return l.find("\"ready\": true") != std::string::npos; };
  ASSERT_TRUE(ecu_assist.wait_for_line(ready, 90000));
  ASSERT_TRUE(ecu_zero.wait_for_line(ready, 90000));

  auto params = io::config::load_vehicle_file(src + "/config/vehicles/sedan.toml");
  params.steering.assist_from_input = true;  // [routing] assist_torque_nm = "can"
  constexpr double kSpeed = 60 / 3.6;
  model::vehicle::VehicleModel with(params, 1e-3);
  model::vehicle::VehicleModel without(params, 1e-3);
  with.set_forward_speed(kSpeed);
  without.set_forward_speed(kSpeed);
  can::transport::TransportSettings t0;
  t0.interface = "vcan0";
  can::transport::TransportSettings t1;
  t1.interface = "vcan1";
  const std::string mapping = src + "/config/can/steering-bench.toml";
  InputSet assist_from_can;  // [routing] assist_torque_nm = "can": the bridge feeds the assist
  assist_from_can.set(model::index(Signal::kAssistTorque));
  can::bridge::CanBridge bridge_with(can::mapping::load_can_config(mapping), t0, false,
                                     assist_from_can);
  can::bridge::CanBridge bridge_without(can::mapping::load_can_config(mapping), t1, false,
                                        assist_from_can);
  model::Signals s_with = driver_inputs();
  model::Signals s_without = driver_inputs();
  model::ModelReport report_with{}, report_without{};
  for (auto* s : {&s_with, &s_without}) {
    (*s)[Signal::kGearRequest] = 4;
    (*s)[Signal::kThrottlePedal] = 0.15;
  }
  // Steering-wheel angle: ramp to 0.6 rad over 0.5 s, hold; average over the last 0.5 s of 3 s.
  constexpr int kCycles = 3000;
  double tb_with = 0, tb_without = 0, assist = 0, speed = 0;
  int averaged = 0;
  const std::int64_t start = test::monotonic_ns();
  for (int k = 0; k < kCycles; ++k) {
    const std::int64_t t = start + std::int64_t{k} * 1'000'000;
    timespec ts{t / 1'000'000'000, t % 1'000'000'000};
    clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr);
    const double angle = 0.6 * std::min(1.0, k / 500.0);
    s_with[Signal::kSteeringWheelAngleCmd] = angle;
    s_without[Signal::kSteeringWheelAngleCmd] = angle;
    bridge_with.receive(t, s_with);
    bridge_without.receive(t, s_without);
    ASSERT_EQ(with.step(s_with), model::StepStatus::kOk);
    ASSERT_EQ(without.step(s_without), model::StepStatus::kOk);
    with.fill_report(report_with);
    without.fill_report(report_without);
    bridge_with.transmit(t, {s_with, report_with});
    bridge_without.transmit(t, {s_without, report_without});
    if (k >= kCycles - 500) {
      tb_with += s_with[Signal::kTorsionBarTorque];
      tb_without += s_without[Signal::kTorsionBarTorque];
      assist += s_with[Signal::kAssistTorque];
      speed += s_with[Signal::kVehicleSpeed];
      ++averaged;
    }
  }
  tb_with /= averaged;
  tb_without /= averaged;
  assist /= averaged;
  speed /= averaged;
  // virtual-ecu's documented boost curve: k(v) = 1 + 3 / (1 + (v / 15)^2).
  const double k_boost = 1.0 + 3.0 / (1.0 + (speed / 15.0) * (speed / 15.0));
  std::printf(
      "[ closed   ] 60 km/h, 0.6 rad: torsion bar %.3f N m without assist, %.3f N m with "
      "(assist %.3f N m); ratio %.3f, ECU boost ratio k(%.1f m/s) = %.3f\n",
      tb_without, tb_with, assist, tb_without / tb_with, speed, k_boost);
  IoCounters c;
  bridge_with.read_counters(c);
  EXPECT_EQ(c.checksum_failures, 0u);
  EXPECT_EQ(c.counter_failures, 0u);
  ASSERT_GT(std::abs(tb_without), 0.2) << "the maneuver must load the steering";
  // Through the loop the ECU's law holds: torsion bar + assist = k * torsion bar. Within 5 %: the
  // ECU (Python, in a VM that runs code ~5x slower, next to other tests) answers a torsion bar
  // torque and speed some cycles old; unloaded the law holds to 0.1 %, loaded it was seen 2.2 %
  // off.
  EXPECT_NEAR((tb_with + assist) / tb_with, k_boost, 0.05 * k_boost);
  // The torsion bar torque falls by about k. Not exactly: in angle mode the softer-loaded torsion
  // bar twists less, the pinion follows the wheel more closely and the rack load grows (measured
  // about 10 % here), so the fall is k / (load ratio). 15 % tolerance, and it must be a fall.
  EXPECT_NEAR(tb_without / tb_with, k_boost, 0.15 * k_boost);
  EXPECT_GT(tb_without / tb_with, 1.5);
  ecu_assist.terminate();
  ecu_zero.terminate();
}

}  // namespace
}  // namespace rig::io::can
