/// The handoff between the loop and the dispatcher (offline back-pressure, real-time drops), the
/// one overrun decision a snapshot carries, phases by name and I/O counters summed over every
/// adapter.

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "rig/event_log.h"
#include "rig/executive.h"
#include "tests/rig/fake_clock.h"
#include "tests/rig/test_model.h"

namespace rig {
namespace {

using test::FakeClock;

constexpr std::int64_t kNeverNs = 600'000'000'000;  // a hang shows as a ctest timeout

/// Keeps the timing of every snapshot, checks that cycles arrive in order from cycle 0.
class RecordingSink final : public io::SnapshotSink {
 public:
  void start(const io::RunInfo&) override { started = true; }
  void consume(const io::Snapshot& s, std::uint64_t dropped_before) override {
    in_order = in_order && s.timing.cycle == timings.size();  // no drop before the last
    lost += dropped_before;
    timings.push_back(s.timing);
    counters = s.can;
    if (hold != nullptr) {
      while (!hold->load()) std::this_thread::yield();
    }
  }
  void stop() override { stopped = true; }
  std::vector<io::CycleTiming> timings;
  io::IoCounters counters{};
  std::uint64_t lost = 0;
  bool in_order = true, started = false, stopped = false;
  const std::atomic<bool>* hold = nullptr;  ///< consume() waits until it is true
};

/// An I/O adapter with fixed counters.
class FakeIo final : public io::CycleIo {
 public:
  explicit FakeIo(io::IoCounters c) : counters_(c) {}
  void receive(std::int64_t, model::Signals&) noexcept override { ++received; }
  void transmit(std::int64_t, const io::signals::CycleView&) noexcept override {}
  void read_counters(io::IoCounters& c) const noexcept override { c = counters_; }
  std::uint64_t received = 0;

 private:
  io::IoCounters counters_;
};

TEST(Handoff, OfflineBackPressureDeliversEveryCycleInOrder) {
  rt::VirtualClock clock;
  test::OscillatorModel model(0.001);
  EventLog log("");
  RecordingSink sink;
  ExecutiveParams p;
  p.offline = true;
  p.duration_s = 3.0;
  p.snapshot_capacity = 4;  // far fewer slots than cycles: the loop waits for the dispatcher
  Executive exec(p, clock, model, nullptr, {}, {&sink}, log, {});
  exec.prepare("test");
  exec.go();
  EXPECT_EQ(exec.join(), StopReason::kDuration);
  EXPECT_EQ(exec.cycles(), 3000u);
  EXPECT_EQ(sink.timings.size(), 3000u);
  EXPECT_TRUE(sink.in_order);
  EXPECT_EQ(sink.lost, 0u);
  EXPECT_EQ(exec.snapshots_dropped(), 0u);
  EXPECT_TRUE(sink.started);
  EXPECT_TRUE(sink.stopped);  // the run ends once the last snapshot is written
}

TEST(Handoff, RealTimeDropsOnAFullRingAndCountsIt) {
  FakeClock clock;
  test::OscillatorModel model(0.001);
  EventLog log("");
  RecordingSink sink;
  ExecutiveParams p;
  p.duration_s = 0.01;  // 10 cycles into 4 slots, nobody draining
  p.snapshot_capacity = 4;
  Executive exec(p, clock, model, nullptr, {}, {&sink}, log, {});
  EXPECT_EQ(exec.run_loop(), StopReason::kDuration);
  EXPECT_EQ(exec.cycles(), 10u);
  EXPECT_EQ(exec.snapshots_dropped(), 6u);
  EXPECT_EQ(exec.drain_snapshots(), 4u);
  ASSERT_EQ(sink.timings.size(), 4u);
  EXPECT_EQ(sink.timings.back().cycle, 3u);  // the first four; the loop never waited
  EXPECT_EQ(sink.lost, 6u);
}

TEST(Handoff, StopRequestWakesAnOfflineLoopWaitingForTheDispatcher) {
  rt::VirtualClock clock;
  test::OscillatorModel model(0.001);
  EventLog log("");
  std::atomic<bool> hold{false};
  RecordingSink sink;
  sink.hold = &hold;  // the dispatcher is stuck in the first consume()
  ExecutiveParams p;
  p.offline = true;  // duration 0: forever
  p.snapshot_capacity = 4;
  Executive exec(p, clock, model, nullptr, {}, {&sink}, log, {});
  exec.prepare("test");
  exec.go();
  while (exec.cycles() < 4) std::this_thread::yield();  // the ring is full: the loop waits
  exec.request_stop();
  while (!exec.finished()) exec.wait_finished(kNeverNs);
  hold = true;
  EXPECT_EQ(exec.join(), StopReason::kRequested);
  EXPECT_TRUE(sink.in_order);
  EXPECT_TRUE(sink.stopped);
}

TEST(Executive, SnapshotCarriesTheCyclesOneOverrunDecision) {
  FakeClock clock;
  test::OscillatorModel model(0.001);
  EventLog log("");
  RecordingSink sink;
  ExecutiveParams p;
  p.duration_s = 0.05;
  p.policy = OverrunPolicy::kCatchUp;
  Executive exec(p, clock, model, nullptr, {}, {&sink}, log, {});
  // Cycle 10's model step takes 2.5 ms: it misses. Catch-up keeps the grid, so cycle 11 wakes
  // 1.5 ms late and ends 1.6 ms after its deadline (a miss); cycle 12 wakes 0.6 ms late and ends
  // 0.7 ms after its deadline (on time).
  model.on_step = [&](std::uint64_t n) { clock.advance(n == 10 ? 2'500'000 : 100'000); };
  exec.run_loop();
  exec.drain_snapshots();
  ASSERT_EQ(sink.timings.size(), 50u);
  const io::CycleTiming& t9 = sink.timings[9];
  const io::CycleTiming& t10 = sink.timings[10];
  const io::CycleTiming& t11 = sink.timings[11];
  const io::CycleTiming& t12 = sink.timings[12];
  EXPECT_FALSE(t9.deadline_miss);
  EXPECT_TRUE(t10.deadline_miss);
  EXPECT_EQ(t10.consecutive_misses, 1u);
  EXPECT_EQ(t10.phase_ns[io::index(io::Phase::kModel)], 2'500'000);
  EXPECT_EQ(t10.phase_ns[io::index(io::Phase::kHandoff)], 0);
  EXPECT_EQ(t10.compute_ns, 2'500'000);  // the sum of the phases, handoff included
  EXPECT_EQ(t11.lateness_ns, 1'500'000);
  EXPECT_TRUE(t11.deadline_miss);
  EXPECT_EQ(t11.consecutive_misses, 2u);
  EXPECT_EQ(t12.lateness_ns, 600'000);
  EXPECT_FALSE(t12.deadline_miss);
  EXPECT_EQ(t12.consecutive_misses, 0u);
  EXPECT_EQ(exec.deadline_misses(), 2u);  // the statistics count what the snapshots carry
}

TEST(Executive, IoCountersAreSummedOverEveryAdapter) {
  FakeClock clock;
  test::OscillatorModel model(0.001);
  EventLog log("");
  RecordingSink sink;
  io::IoCounters a{}, b{};
  a.bus_state = io::BusState::kDisabled;  // e.g. an adapter without a bus, listed first
  a.frames_received = 3;
  a.timeouts = 1;
  b.bus_state = io::BusState::kUp;
  b.frames_received = 5;
  b.frames_sent = 7;
  FakeIo first(a), second(b);
  ExecutiveParams p;
  p.duration_s = 0.003;
  Executive exec(p, clock, model, nullptr, {&first, &second}, {&sink}, log, {});
  exec.run_loop();
  exec.drain_snapshots();
  EXPECT_EQ(first.received, 3u);
  EXPECT_EQ(second.received, 3u);
  const io::IoCounters sum = exec.io_counters();
  EXPECT_EQ(sum.bus_state, io::BusState::kUp);
  EXPECT_EQ(sum.frames_received, 8u);
  EXPECT_EQ(sum.frames_sent, 7u);
  EXPECT_EQ(sum.timeouts, 1u);
  EXPECT_EQ(sink.counters.frames_received, 8u);  // and so does every snapshot
  EXPECT_EQ(sink.counters.bus_state, io::BusState::kUp);
  io::IoCounters down{};
  down.bus_state = io::BusState::kDown;
  io::IoCounters total = sum;
  total += down;
  EXPECT_EQ(total.bus_state, io::BusState::kDown);  // the worst bus state wins
}

}  // namespace
}  // namespace rig
