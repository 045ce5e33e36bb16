/// rig/rt: the real-time building blocks on their own (they depend on nothing of the project):
/// log histogram, SPSC ring, event count, thread set-up.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <string>
#include <thread>
#include <vector>

#include "rig/rt/clock.h"
#include "rig/rt/event_count.h"
#include "rig/rt/log_histogram.h"
#include "rig/rt/spsc_ring.h"
#include "rig/rt/thread_setup.h"

namespace rig::rt {
namespace {

/// Longer than any test may take: a lost wake-up shows as a ctest timeout, not a flaky time.
constexpr std::int64_t kNeverNs = 600'000'000'000;

// ---- LogHistogram ----
TEST(LogHistogram, BucketsAreContiguousAndOrdered) {
  for (int b = 0; b + 1 < LogHistogram::kBuckets; ++b) {
    EXPECT_EQ(LogHistogram::bucket_high(b) + 1, LogHistogram::bucket_low(b + 1)) << b;
    EXPECT_EQ(LogHistogram::bucket_of(LogHistogram::bucket_low(b)), b);
    EXPECT_EQ(LogHistogram::bucket_of(LogHistogram::bucket_high(b)), b);
  }
  // 16 sub-buckets per octave: 1000 ns lies in [992, 1023] (octave 512..1023, width 32).
  EXPECT_EQ(LogHistogram::bucket_low(LogHistogram::bucket_of(1000)), 992);
  EXPECT_EQ(LogHistogram::bucket_high(LogHistogram::bucket_of(1000)), 1023);
}

TEST(LogHistogram, QuantilesOfHandMadeData) {
  LogHistogram h;
  EXPECT_EQ(h.quantile(0.5), 0);
  // 990 values of 10 ns (exact buckets below 16 ns), 9 of 1000 ns, 1 of 5'000'000 ns.
  for (int i = 0; i < 990; ++i) h.add(10);
  for (int i = 0; i < 9; ++i) h.add(1000);
  h.add(5'000'000);
  EXPECT_EQ(h.count(), 1000u);
  EXPECT_EQ(h.quantile(0.5), 10);
  EXPECT_EQ(h.quantile(0.99), 10);        // rank 990 is still a 10
  EXPECT_EQ(h.quantile(0.999), 1023);     // rank 999: bucket [992, 1023]
  EXPECT_EQ(h.quantile(1.0), 5'000'000);  // capped at the exact max
  EXPECT_EQ(h.max(), 5'000'000);
  h.add(-5);  // negative lateness counts as 0
  EXPECT_EQ(h.bucket_count(0), 1u);
}

// ---- SpscRing ----
TEST(SpscRing, FullRingRefusesAndOrderIsKept) {
  SpscRing<int> ring(4);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(ring.push(i));
  EXPECT_FALSE(ring.push(99));
  for (int i = 0; i < 4; ++i) {
    ASSERT_NE(ring.front(), nullptr);
    EXPECT_EQ(*ring.front(), i);
    ring.release();
  }
  EXPECT_EQ(ring.front(), nullptr);
}

TEST(SpscRing, SizeCountsCommittedUntilReleased) {
  SpscRing<int> ring(4);
  EXPECT_EQ(ring.size(), 0u);
  int* slot = ring.claim();
  ASSERT_NE(slot, nullptr);
  *slot = 7;
  EXPECT_EQ(ring.size(), 0u);  // claimed, not yet committed
  ring.commit();
  EXPECT_TRUE(ring.push(8));
  EXPECT_EQ(ring.size(), 2u);
  ring.release();
  EXPECT_EQ(ring.size(), 1u);
  EXPECT_EQ(*ring.front(), 8);
}

TEST(SpscRing, TwoThreadsKeepEveryValueInOrder) {
  SpscRing<std::uint64_t> ring(8);
  constexpr std::uint64_t kCount = 200'000;
  std::thread producer([&] {
    for (std::uint64_t i = 0; i < kCount;) {
      if (ring.push(i)) ++i;
    }
  });
  std::uint64_t expected = 0;
  while (expected < kCount) {
    if (const std::uint64_t* v = ring.front()) {
      ASSERT_EQ(*v, expected);
      ring.release();
      ++expected;
    }
  }
  producer.join();
  EXPECT_EQ(ring.front(), nullptr);
}

// ---- EventCount ----
TEST(EventCount, NotifyAfterPrepareWaitIsNeverLost) {
  EventCount ec;
  std::atomic<bool> ready{true};
  const std::uint32_t key = ec.prepare_wait();
  ASSERT_TRUE(ready.load());
  ec.cancel_wait();
  ec.notify();  // nobody waits: no wake-up needed
  // A notify() after prepare_wait() makes wait() return at once (the epoch moved).
  const std::uint32_t key2 = ec.prepare_wait();
  EXPECT_EQ(key2, key);
  std::thread t([&] { ec.notify(); });
  t.join();
  ec.wait(key2, kNeverNs);
  EXPECT_NE(ec.prepare_wait(), key2);
  ec.cancel_wait();
}

TEST(EventCount, PingPongNeverLosesAWakeUp) {
  // Two threads hand a counter back and forth 20,000 times, each sleeping until the other moved
  // it: one lost wake-up would hang the test (caught by the ctest timeout).
  EventCount to_b, to_a;
  std::atomic<int> turn{0};
  constexpr int kRounds = 20'000;
  auto wait_for = [](EventCount& ec, std::atomic<int>& v, int value) {
    while (v.load(std::memory_order_acquire) != value) {
      const std::uint32_t key = ec.prepare_wait();
      if (v.load(std::memory_order_acquire) == value) {
        ec.cancel_wait();
        break;
      }
      ec.wait(key, kNeverNs);
    }
  };
  std::thread b([&] {
    for (int i = 0; i < kRounds; ++i) {
      wait_for(to_b, turn, 2 * i + 1);
      turn.store(2 * i + 2, std::memory_order_release);
      to_a.notify();
    }
  });
  for (int i = 0; i < kRounds; ++i) {
    turn.store(2 * i + 1, std::memory_order_release);
    to_b.notify();
    wait_for(to_a, turn, 2 * i + 2);
  }
  b.join();
  EXPECT_EQ(turn.load(), 2 * kRounds);
}

TEST(EventCount, WaitEndsAtItsTimeout) {
  EventCount ec;
  MonotonicClock clock;
  const std::int64_t before_ns = clock.now_ns();
  const std::uint32_t key = ec.prepare_wait();
  ec.wait(key, 2'000'000);  // nobody notifies: returns after (at least) the timeout
  EXPECT_GE(clock.now_ns() - before_ns, 2'000'000);
}

// ---- thread set-up: {ok, message} ----
TEST(ThreadSetup, FailuresSayWhichCallAndWhy) {
  const SetupResult bad_cpu = set_cpu_affinity(-1);
  EXPECT_FALSE(bad_cpu.ok);
  EXPECT_EQ(bad_cpu.message, "pthread_setaffinity_np: Invalid argument");
  const SetupResult slack = set_timer_slack(1);  // always permitted for the own thread
  EXPECT_TRUE(slack.ok) << slack.message;
  EXPECT_TRUE(slack.message.empty());
  // SCHED_FIFO and mlockall depend on the privileges: either granted, or a reason is given.
  std::thread t([] {
    const SetupResult fifo = set_sched_fifo(10);
    EXPECT_EQ(fifo.ok, fifo.message.empty()) << fifo.message;
    if (!fifo.ok) {
      EXPECT_EQ(fifo.message.rfind("pthread_setschedparam(SCHED_FIFO): ", 0), 0u);
    }
  });
  t.join();
  CpuDmaLatency dma;
  const SetupResult held = dma.hold();
  EXPECT_EQ(held.ok, dma.held());
  if (!held.ok) {
    EXPECT_NE(held.message.find("/dev/cpu_dma_latency"), std::string::npos);
  }
}

// ---- VirtualClock ----
TEST(VirtualClock, JumpsToEachDeadlineAndNeverBack) {
  VirtualClock clock;
  EXPECT_EQ(clock.now_ns(), 0);
  clock.sleep_until(1'000'000);
  EXPECT_EQ(clock.now_ns(), 1'000'000);
  clock.sleep_until(500);
  EXPECT_EQ(clock.now_ns(), 1'000'000);
  EXPECT_EQ(clock.realtime_ns(), 1'000'000);
}

}  // namespace
}  // namespace rig::rt
