/// rig run --lockstep and the cycle numbers of the answers (issue 15 item 6): a scripted rack
/// bench on a fake clock (no CAN).

#include <gtest/gtest.h>

#include <cstdint>
#include <set>

#include "rig/event_log.h"
#include "rig/executive.h"
#include "tests/rig/fake_clock.h"
#include "tests/rig/test_model.h"

namespace rig {
namespace {

/// The bench's rack: it answers each tie-rod frame with a position frame after `answer_ns`
/// (the first one unprompted); in the cycles of `lost` its frame never comes. The rig sends its
/// tie-rod frame in the cycle of the step, except in the cycles of `deferred` (none sent).
class RackBench final : public io::CycleIo {
 public:
  RackBench(test::FakeClock& clock, std::int64_t answer_ns)
      : clock_(clock), answer_ns_(answer_ns) {}
  void set_cycle_frames(std::int64_t period_ns) noexcept override { period_ns_ = period_ns; }
  io::CycleFrameWait wait_cycle_frame(std::int64_t, std::int64_t timeout_ns) noexcept override {
    if (lost.count(cycle_) != 0) {
      clock_.advance(timeout_ns);
      return io::CycleFrameWait::kTimeout;
    }
    clock_.advance(answer_ns_);  // the bench's time: the VM integrating the rack
    frame_ = true;
    return io::CycleFrameWait::kReceived;
  }
  void receive(std::int64_t, model::Signals&) noexcept override {
    received_ = frame_;
    frame_ = false;
  }
  void transmit(std::int64_t, const io::signals::CycleView&) noexcept override {
    sent_ = deferred.count(cycle_) == 0;
    ++cycle_;
  }
  void read_counters(io::IoCounters& c) const noexcept override { c = io::IoCounters{}; }
  [[nodiscard]] bool cycle_frame_received() const noexcept override { return received_; }
  [[nodiscard]] bool cycle_frame_sent() const noexcept override { return sent_; }

  std::set<std::uint64_t> lost, deferred;
  std::int64_t period_ns_ = 0;

 private:
  test::FakeClock& clock_;
  std::int64_t answer_ns_;
  std::uint64_t cycle_ = 0;
  bool frame_ = false, received_ = false, sent_ = false;
};

struct Bench {
  explicit Bench(bool lockstep, std::int64_t answer_ns) : rack(clock, answer_ns) {
    p.duration_s = 0.2;  // 200 cycles
    p.lockstep = lockstep;
  }
  Executive& start() {
    exec = std::make_unique<Executive>(p, clock, model, nullptr, std::vector<io::CycleIo*>{&rack},
                                       std::vector<io::SnapshotSink*>{}, log, Executive::Sources{});
    model.on_step = [&](std::uint64_t) { clock.advance(200'000); };  // 0.2 ms compute
    return *exec;
  }
  ExecutiveParams p;
  test::FakeClock clock;
  test::OscillatorModel model{0.001};
  EventLog log{""};
  RackBench rack;
  std::unique_ptr<Executive> exec;
};

// The VM needs 5 ms per rack step: every cycle waits for it, none is a deadline miss; three
// frames lost: three timeouts of 100 ms, the loop goes on; every received frame is answered in
// its own cycle or (a deferred send) the next.
TEST(Lockstep, WaitsAreNotMissesAndEveryAnswerIsInTheSameOrNextCycle) {
  Bench b(true, 5'000'000);
  b.rack.lost = {10, 11, 150};
  b.rack.deferred = {20, 40, 90};
  Executive& e = b.start();
  EXPECT_EQ(b.rack.period_ns_, 1'000'000);  // the loop told the adapter its period
  EXPECT_EQ(e.run_loop(), StopReason::kDuration);
  const CycleFrameStats& cf = e.cycle_frames();
  std::printf(
      "lockstep: %llu cycles, %llu waits (max %.1f ms), %llu timeouts, %llu frames received, "
      "answered %llu same / %llu next / %llu later, misses %llu, lateness max %lld ns\n",
      static_cast<unsigned long long>(e.cycles()),
      static_cast<unsigned long long>(cf.lockstep_waits),
      static_cast<double>(cf.lockstep_wait_max_ns) * 1e-6,
      static_cast<unsigned long long>(cf.lockstep_timeouts),
      static_cast<unsigned long long>(cf.received),
      static_cast<unsigned long long>(cf.answered_same_cycle),
      static_cast<unsigned long long>(cf.answered_next_cycle),
      static_cast<unsigned long long>(cf.answered_later),
      static_cast<unsigned long long>(e.deadline_misses()),
      static_cast<long long>(e.lateness().max()));
  EXPECT_EQ(e.cycles(), 200u);  // duration counts simulated periods, not the bench's waits
  EXPECT_EQ(cf.lockstep_waits, 200u);
  EXPECT_EQ(cf.lockstep_timeouts, 3u);
  EXPECT_EQ(cf.lockstep_wait_max_ns, 100'000'000u);
  EXPECT_EQ(e.deadline_misses(), 0u);
  EXPECT_EQ(e.lateness().max(), 0);
  EXPECT_EQ(cf.received, 197u);
  // the frames of cycles 20, 40 and 90 are answered in the next cycle, by the send that also
  // answers that cycle's own frame (counted once)
  EXPECT_EQ(cf.answered_next_cycle, 3u);
  EXPECT_EQ(cf.answered_later, 0u);
  EXPECT_EQ(cf.answered_same_cycle + cf.answered_next_cycle, 197u - 3u);
  EXPECT_EQ(cf.last_rx_cycle, 199);
  EXPECT_EQ(cf.last_tx_cycle, 199);
}

// The same bench without --lockstep: the loop does not wait (no timeouts, no waits).
TEST(Lockstep, WithoutTheFlagNothingWaits) {
  Bench b(false, 5'000'000);
  Executive& e = b.start();
  EXPECT_EQ(e.run_loop(), StopReason::kDuration);
  EXPECT_EQ(e.cycle_frames().lockstep_waits, 0u);
  EXPECT_EQ(e.cycle_frames().received, 0u);  // the scripted bench only answers a waiting rig
  EXPECT_EQ(e.deadline_misses(), 0u);
}

// A rig that sends its cycle frame only every third cycle answers two cycles late: counted and
// logged as such (the check can fail).
TEST(Lockstep, AnAnswerTwoCyclesLateIsCounted) {
  Bench b(true, 100'000);
  for (std::uint64_t k = 0; k < 200; ++k)
    if (k % 3 != 0) b.rack.deferred.insert(k);
  Executive& e = b.start();
  EXPECT_EQ(e.run_loop(), StopReason::kDuration);
  std::printf("every third cycle: answered %llu same / %llu next / %llu later\n",
              static_cast<unsigned long long>(e.cycle_frames().answered_same_cycle),
              static_cast<unsigned long long>(e.cycle_frames().answered_next_cycle),
              static_cast<unsigned long long>(e.cycle_frames().answered_later));
  EXPECT_GT(e.cycle_frames().answered_later, 0u);
}

}  // namespace
}  // namespace rig
