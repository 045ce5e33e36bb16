#include <lcm/lcm.h>

#include <gtest/gtest.h>

#include "io/lcm/lcm_publisher.h"
#include "io/lcm/snapshot_encoder.h"
#include "tests/io/lcm/synthetic_snapshot.h"
#include "tests/support/alloc_counter.h"

namespace rig::io {
namespace {

constexpr double kPeriod = 0.001;

template <typename Message>
Message decode(const lcm::EncodedMessage& m) {
  Message msg;
  EXPECT_GE(msg.decode(m.data, 0, static_cast<int>(m.size)), 0);
  return msg;
}

RunInfo run_info() {
  RunInfo info;
  info.period_s = kPeriod;
  info.sched_fifo = true;
  info.priority = 80;
  info.memory_locked = true;
  info.cpu = 1;
  info.policy = "catch-up";
  return info;
}

TEST(SnapshotEncoder, StateRoundTripsEveryField) {
  lcm::SnapshotEncoder encoder(lcm::LcmSettings{});
  encoder.start(run_info());
  const Snapshot s = test::make_synthetic_snapshot(1234, kPeriod);
  lcm::EncodedMessage out[3];
  const std::size_t n = encoder.encode(s, 0, out);
  ASSERT_EQ(n, 1u);  // cycle 1234: state only (signals every 10th, status every 100th)
  EXPECT_EQ(*out[0].channel, "RIG_STATE");
  const auto msg = decode<rig::vehicle_state_t>(out[0]);

  EXPECT_EQ(msg.cycle, 1234);
  EXPECT_DOUBLE_EQ(msg.sim_time_s, 1.234);
  EXPECT_EQ(msg.monotonic_ns, s.timing.wake_ns);
  EXPECT_EQ(msg.lateness_ns, 1234 % 97 * 1000);
  ASSERT_EQ(msg.num_units, 2);
  EXPECT_DOUBLE_EQ(msg.unit_x_m[1], 20.0 * 1.234 - 6.0);
  EXPECT_DOUBLE_EQ(msg.unit_yaw_rad[0], 0.0005 * 1234);
  EXPECT_DOUBLE_EQ(msg.unit_ay_mps2[1], -1.5);
  ASSERT_EQ(msg.num_wheels, 6);
  // Wheel 4 is the first wheel of unit 1 (formula identity k = 10).
  EXPECT_EQ(msg.wheel_unit[4], 1);
  EXPECT_DOUBLE_EQ(msg.wheel_spin_radps[4], 30.0 + 12.34 + 10.0);
  EXPECT_DOUBLE_EQ(msg.wheel_x_e_m[3], 3e-4);
  EXPECT_DOUBLE_EQ(msg.wheel_y_e_m[5], -11e-4);
  EXPECT_DOUBLE_EQ(msg.wheel_load_n[2], 4002.0);
  EXPECT_DOUBLE_EQ(msg.steering_wheel_angle_rad, 0.1234);
  EXPECT_DOUBLE_EQ(msg.torsion_bar_torque_nm, 3.0);
  EXPECT_DOUBLE_EQ(msg.assist_torque_nm, 4.0);
  EXPECT_DOUBLE_EQ(msg.rack_travel_m, 1234e-6);
  EXPECT_DOUBLE_EQ(msg.engine_speed_radps, 323.4);
  EXPECT_EQ(msg.gear, 2);
  EXPECT_DOUBLE_EQ(msg.brake_pressure_rr_pa, 0.6e5);
  ASSERT_EQ(msg.num_joints, 1);
  EXPECT_DOUBLE_EQ(msg.joint_force_x_n[0], 2234.0);
  EXPECT_DOUBLE_EQ(msg.joint_rod_force_n[0], -500.0 - 1234.0);
}

TEST(SnapshotEncoder, SignalsAndStatusCarryNamesSourcesCountersAndPercentiles) {
  lcm::LcmSettings settings;
  settings.channel_prefix = "R2_";
  lcm::SnapshotEncoder encoder(settings);
  encoder.start(run_info());
  lcm::EncodedMessage out[3];
  std::size_t n = 0;
  for (std::uint64_t c = 0; c <= 1000; ++c) {
    n = encoder.encode(test::make_synthetic_snapshot(c, kPeriod), c == 1000 ? 3 : 0, out);
  }
  ASSERT_EQ(n, 3u);  // cycle 1000: state, signals, status
  EXPECT_EQ(*out[1].channel, "R2_RIG_SIGNALS");
  EXPECT_EQ(*out[2].channel, "R2_RIG_STATUS");

  const auto sig = decode<rig::signals_t>(out[1]);
  ASSERT_EQ(sig.num_signals, static_cast<int>(model::kSignalCount));
  EXPECT_EQ(sig.name[0], "steering_wheel_angle_cmd_rad");
  EXPECT_EQ(sig.unit[0], "rad");
  const auto speed = model::index(model::Signal::kVehicleSpeed);
  EXPECT_EQ(sig.name[speed], "vehicle_speed_mps");
  EXPECT_DOUBLE_EQ(sig.value[speed], 7.0 + 0.001 * 1000);  // the synthetic snapshot's speed
  EXPECT_EQ(sig.valid[0], 0);  // index % 5 == 0 is invalid in the synthetic snapshot
  EXPECT_EQ(sig.valid[1], 1);
  EXPECT_EQ(sig.source[0], rig::signals_t::SOURCE_DRIVER);
  EXPECT_EQ(sig.source[1], rig::signals_t::SOURCE_CAN);
  EXPECT_EQ(sig.source[speed], rig::signals_t::SOURCE_MODEL);
  EXPECT_EQ(sig.is_input[speed], 0);

  const auto st = decode<rig::rig_status_t>(out[2]);
  EXPECT_EQ(st.cycles, 1004);  // 1001 snapshots seen + 3 dropped
  EXPECT_EQ(st.snapshots_dropped, 3);
  EXPECT_EQ(st.deadline_misses, 2);  // cycles 499 and 999
  EXPECT_EQ(st.max_consecutive_misses, 1);
  // Window: the last second, cycles 1..1000, lateness (c % 97) us. Counts: 0 ten times, 1..30
  // eleven times, 31..96 ten times; so at most v (v >= 30) lie 10 + 330 + 10 (v - 30).
  // Nearest rank 500 -> v = 46; rank 990 -> v = 95; rank 999 -> v = 96.
  EXPECT_EQ(st.window_cycles, 1000);
  EXPECT_EQ(st.window_misses, 2);
  EXPECT_EQ(st.lateness_p50_ns, 46'000);
  EXPECT_EQ(st.lateness_p99_ns, 95'000);
  EXPECT_EQ(st.lateness_p999_ns, 96'000);
  EXPECT_EQ(st.lateness_max_ns, 96'000);
  EXPECT_EQ(st.compute_max_ns, 212'000);
  EXPECT_EQ(st.period_s, kPeriod);
  EXPECT_EQ(st.sched_fifo, 1);
  EXPECT_EQ(st.priority, 80);
  EXPECT_EQ(st.cpu, 1);
  EXPECT_EQ(st.overrun_policy, "catch-up");
  EXPECT_EQ(st.bus_state, rig::rig_status_t::BUS_UP);
  EXPECT_EQ(st.can_frames_received, 3000);
  EXPECT_EQ(st.can_timeouts, 10);
  EXPECT_EQ(st.can_error_frames, 4);
  ASSERT_EQ(st.num_inputs, static_cast<int>(model::index(model::kFirstOutput)));
  EXPECT_EQ(st.input_name[2], "assist_torque_nm");
  EXPECT_EQ(st.input_valid[0], 0);
  EXPECT_EQ(st.input_valid[2], 1);
}

TEST(SnapshotEncoder, DoesNotAllocateOnceWarm) {
  lcm::SnapshotEncoder encoder(lcm::LcmSettings{});
  encoder.start(run_info());
  lcm::EncodedMessage out[3];
  for (std::uint64_t c = 0; c < 200; ++c) {
    encoder.encode(test::make_synthetic_snapshot(c, kPeriod), 0, out);
  }
  const Snapshot s = test::make_synthetic_snapshot(300, kPeriod);  // all three channels due
  test::AllocationCounter allocations;
  EXPECT_EQ(encoder.encode(s, 0, out), 3u);
  EXPECT_EQ(allocations.count(), 0u);
}

TEST(LcmPublisher, PublishesEveryDueMessage) {
  // memq:// is LCM's in-process provider: a real lcm_t and lcm_publish, no network needed.
  // (Delivery to an independent subscriber is tests/integration/lcm/, with lcm-logger.)
  lcm::LcmSettings settings;
  settings.url = "memq://";
  lcm::LcmPublisher publisher(settings);
  publisher.start(run_info());
  ASSERT_TRUE(publisher.active());
  for (std::uint64_t c = 0; c < 100; ++c) {
    publisher.consume(test::make_synthetic_snapshot(c, kPeriod), 0);
  }
  // 100 state + 10 signals + 1 status
  EXPECT_EQ(publisher.published(), 111u);
  publisher.stop();
  EXPECT_FALSE(publisher.active());
}

TEST(LcmPublisher, BadUrlTurnsItselfOffAndTheRunGoesOn) {
  lcm::LcmSettings settings;
  settings.url = "nosuchprovider://x";
  lcm::LcmPublisher publisher(settings);
  testing::internal::CaptureStderr();
  publisher.start(run_info());
  const std::string err = testing::internal::GetCapturedStderr();
  EXPECT_FALSE(publisher.active());
  EXPECT_NE(err.find("rig: LCM disabled"), std::string::npos) << err;
  for (std::uint64_t c = 0; c < 10; ++c) {
    publisher.consume(test::make_synthetic_snapshot(c, kPeriod), 0);
  }
  EXPECT_EQ(publisher.published(), 0u);
  publisher.stop();
}

}  // namespace
}  // namespace rig::io
